#!/usr/bin/env python3
"""The layer check: every Fortran module of src/ and umat/ uses only modules of its own folder
or of a lower layer (docs/architecture.md), a program never uses another program's modules,
the general update path never uses the specialised kernels, and every source file under src/
and umat/ is named by a CMakeLists.txt of its folder or of src/ (a file nobody builds is an
error, not a silently missing feature); a Fortran include file (.inc) is built where a source
file of its folder that is so named includes it, and the general path includes none of the
kernels' (its code is the kernels' own). The tests mirror the layers (docs/tests.md): a Fortran
test source under tests/<folder> of a layer uses no module above that layer (nor one of
another folder of the same layer), and one directly in the folder that names its modules (not
the library's public module `interlock`, which re-exports every layer below the API) lives in
the folder of the highest of them.

    check_layers.py SOURCE_DIR

Exit 0 and one summary line when every rule holds; else exit 1 and one line per violation.
Standard library only.
"""
import pathlib
import re
import sys

# Folder (relative to the source tree) -> layer; lower layers never use higher ones. Folders
# of one layer are independent of each other (umat/ and src/driver/ both stand on the library).
LAYERS = {
    "src/base": 0,
    "src/material": 1,
    "src/laws": 2,
    "src/update": 3,
    "src/api": 4,
    "umat": 5,
    "umat/calculix": 6,
    "src/driver": 5,
    "src/io": 6,
    "src/programs/history": 7,
    "src/programs/fit": 7,
    "src/programs/query": 7,
}
# The folders of tests/ that mirror a layer: tests/<x> holds the tests of src/<x> (umat/<x>).
TEST_LAYERS = {
    "tests/base": "src/base",
    "tests/material": "src/material",
    "tests/laws": "src/laws",
    "tests/update": "src/update",
    "tests/api": "src/api",
    "tests/umat": "umat",
    "tests/umat/calculix": "umat/calculix",
    "tests/driver": "src/driver",
    "tests/io": "src/io",
    "tests/programs/history": "src/programs/history",
    "tests/programs/fit": "src/programs/fit",
    "tests/programs/query": "src/programs/query",
}
# The folders of tests/ beside the layers (their subfolders too).
TEST_ELSEWHERE = {
    "tests/support": "the suites' shared helpers",
    "tests/stability": "the whole library and the UMAT under hard cases",
    "tests/mpi": "the deal.II example",
    "tests/tree": "checks of the source tree",
    "tests/data": "reference data and decks",
}
# The library's public module: `use interlock` says nothing of the layer a test exercises.
FACADE = "interlock"
# Helper modules of tests/support that stand for a layer: a suite that uses the UMAT's
# interface calls the UMAT.
SUPPORT_LAYER = {"test_umat_interface": "umat"}
TEST_SUFFIXES = (".pf", ".f90", ".F90", ".f")
# Modules of the general update path, which the kernels' agreement test holds the kernels to:
# they must not be built on the kernels.
GENERAL_PATH = {"interlock_general_path", "interlock_step_3d", "interlock_plane_law_3d"}
KERNEL_MODULES = {"interlock_kernels", "interlock_kernels_3d", "interlock_kernels_3d_coupled"}

MODULE_RE = re.compile(r"^\s*module\s+(?!procedure\b|subroutine\b|function\b)(\w+)\s*(!.*)?$",
                       re.IGNORECASE)
SUBMODULE_RE = re.compile(r"^\s*submodule\s*\(\s*(\w+)", re.IGNORECASE)
USE_RE = re.compile(r"^\s*use\s*(,\s*non_intrinsic\s*)?(::)?\s*(\w+)", re.IGNORECASE)
INTRINSIC_RE = re.compile(r"^\s*use\s*,\s*intrinsic", re.IGNORECASE)
INCLUDE_RE = re.compile(r"""^\s*include\s*['"]([^'"]+)['"]""", re.IGNORECASE)


def sources(root):
    for top in ("src", "umat"):
        for path in sorted((root / top).rglob("*")):
            if path.is_file() and (path.suffix in (".f90", ".c") or path.name.endswith(".f90.in")):
                yield path


def include_files(root):
    for top in ("src", "umat"):
        yield from sorted(path for path in (root / top).rglob("*.inc") if path.is_file())


def folder_of(root, path):
    return path.parent.relative_to(root).as_posix()


def test_folder(root, path):
    """The folder of TEST_LAYERS or TEST_ELSEWHERE that holds path (its nearest), or None."""
    folder = folder_of(root, path)
    while folder not in TEST_LAYERS and folder not in TEST_ELSEWHERE:
        if "/" not in folder:
            return None
        folder = folder.rsplit("/", 1)[0]
    return folder


def check_tests(root, provider, problems):
    """The tests' folders mirror the layers. Returns the number of test sources checked."""
    test_folder_of = {layer_folder: folder for folder, layer_folder in TEST_LAYERS.items()}
    checked = 0
    for path in sorted((root / "tests").rglob("*")):
        if not path.is_file() or path.suffix not in TEST_SUFFIXES:
            continue
        rel = path.relative_to(root)
        folder = test_folder(root, path)
        if folder is None:
            problems.append(f"{rel}: folder {folder_of(root, path)} mirrors no layer "
                            "(tests/tree/check_layers.py TEST_LAYERS, docs/tests.md)")
            continue
        if folder in TEST_ELSEWHERE:
            continue
        checked += 1
        own = TEST_LAYERS[folder]
        used = {}          # module -> its folder
        facade = False
        for line in path.read_text(errors="replace").splitlines():
            if INTRINSIC_RE.match(line):
                continue
            match = USE_RE.match(line)
            if not match:
                continue
            module = match.group(3).lower()
            if module == FACADE:
                facade = True
            elif module in SUPPORT_LAYER:
                used[module] = SUPPORT_LAYER[module]
            elif module in provider:
                used[module] = provider[module]
        for module, where in sorted(used.items()):
            if where != own and LAYERS[where] >= LAYERS[own]:
                problems.append(f"{rel}: uses {module} of {where} (layer {LAYERS[where]}): a "
                                f"test of {folder} may use {own} (layer {LAYERS[own]}) and "
                                "lower layers; it belongs in "
                                f"{test_folder_of.get(where, 'a folder of ' + where)}")
        # (a subfolder holds a helper of its folder's suites, such as an oracle, whose parts go
        # together)
        if used and not facade and own not in used.values() and folder == folder_of(root, path):
            top = max(used.values(), key=lambda where: LAYERS[where])
            problems.append(f"{rel}: the highest layer it uses is {top}, not {own}: it belongs "
                            f"in {test_folder_of.get(top, 'a folder of ' + top)}")
    return checked


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_layers.py SOURCE_DIR")
    root = pathlib.Path(sys.argv[1]).resolve()
    problems = []
    provider = {}   # module -> folder
    uses = []       # (path, line number, module used)
    files = list(sources(root))
    for path in files:
        folder = folder_of(root, path)
        if folder not in LAYERS:
            problems.append(f"{path.relative_to(root)}: folder {folder} has no layer "
                            "(tests/tree/check_layers.py LAYERS, docs/architecture.md)")
            continue
        if path.suffix == ".c":
            continue
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = MODULE_RE.match(line)
            if match:
                provider[match.group(1).lower()] = folder
                continue
            match = SUBMODULE_RE.match(line)
            if match:
                uses.append((path, number, match.group(1).lower()))
                continue
            if INTRINSIC_RE.match(line):
                continue
            match = USE_RE.match(line)
            if match:
                uses.append((path, number, match.group(3).lower()))
    for path, number, used in uses:
        if used not in provider:
            continue   # a module from outside the project (hdf5, pfunit, ...)
        user_folder = folder_of(root, path)
        used_folder = provider[used]
        where = f"{path.relative_to(root)}:{number}"
        if used_folder != user_folder and LAYERS[used_folder] >= LAYERS[user_folder]:
            problems.append(f"{where}: uses {used} of {used_folder} (layer "
                            f"{LAYERS[used_folder]}) from {user_folder} (layer "
                            f"{LAYERS[user_folder]})")
        text = path.read_text()
        defined = {m.group(1).lower() for m in map(MODULE_RE.match, text.splitlines()) if m}
        if defined & GENERAL_PATH and used in KERNEL_MODULES:
            problems.append(f"{where}: the general update path uses the kernels ({used})")
    # Every source file is built: named in its folder's CMakeLists.txt or in src/'s.
    built = set()
    for path in files:
        rel = path.relative_to(root)
        listed = False
        for cmake in (path.parent / "CMakeLists.txt", root / "src" / "CMakeLists.txt"):
            if cmake.is_file() and cmake.parent in path.parents:
                relative = path.relative_to(cmake.parent).as_posix()
                if re.search(r"(^|[\s/(])" + re.escape(relative) + r"(\s|\)|$)",
                             cmake.read_text(), re.MULTILINE):
                    listed = True
        if path.parent.name == "calculix":
            listed = True   # CalculiX's entry: bundled by scripts/build_calculix.sh
        if not listed:
            problems.append(f"{rel}: not named in any CMakeLists.txt (not built)")
        else:
            built.add(path)
    # An include file is built where a built source of its folder includes it; the general
    # path's sources include none that a kernel includes.
    included_by = {}   # include file -> the sources that include it
    for path in files:
        if path.suffix == ".c":
            continue
        for line in path.read_text().splitlines():
            match = INCLUDE_RE.match(line)
            if match:
                included_by.setdefault(path.parent / match.group(1), []).append(path)
    for inc in include_files(root):
        rel = inc.relative_to(root)
        users = included_by.get(inc, [])
        if not any(user in built for user in users):
            problems.append(f"{rel}: included by no source named in a CMakeLists.txt (not built)")
        defined = set()
        for user in users:
            defined |= {m.group(1).lower() for m in map(MODULE_RE.match,
                                                        user.read_text().splitlines()) if m}
        if defined & GENERAL_PATH and defined & KERNEL_MODULES:
            problems.append(f"{rel}: included by the general update path and by a kernel")
    n_tests = check_tests(root, provider, problems)
    for line in problems:
        print(line)
    if problems:
        print(f"layer check: {len(problems)} problem(s)")
        return 1
    print(f"layer check: {len(files)} files, {len(provider)} modules, {len(uses)} uses: every "
          f"use goes down the layers; {n_tests} test sources in the folders of their layers")
    return 0


if __name__ == "__main__":
    sys.exit(main())
