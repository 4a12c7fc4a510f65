#!/usr/bin/env python3
"""The layer check: every Fortran module of src/ and umat/ uses only modules of its own folder
or of a lower layer (docs/architecture.md), a program never uses another program's modules,
the general update path never uses the specialised kernels, and every source file under src/
and umat/ is named by a CMakeLists.txt of its folder or of src/ (a file nobody builds is an
error, not a silently missing feature).

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
# Modules of the general update path, which the kernels' agreement test holds the kernels to:
# they must not be built on the kernels.
GENERAL_PATH = {"interlock_microplane", "interlock_schemes", "interlock_ria"}
KERNEL_MODULES = {"interlock_kernels"}

MODULE_RE = re.compile(r"^\s*module\s+(?!procedure\b|subroutine\b|function\b)(\w+)\s*(!.*)?$",
                       re.IGNORECASE)
SUBMODULE_RE = re.compile(r"^\s*submodule\s*\(\s*(\w+)", re.IGNORECASE)
USE_RE = re.compile(r"^\s*use\s*(,\s*non_intrinsic\s*)?(::)?\s*(\w+)", re.IGNORECASE)
INTRINSIC_RE = re.compile(r"^\s*use\s*,\s*intrinsic", re.IGNORECASE)


def sources(root):
    for top in ("src", "umat"):
        for path in sorted((root / top).rglob("*")):
            if path.is_file() and (path.suffix in (".f90", ".c") or path.name.endswith(".f90.in")):
                yield path


def folder_of(root, path):
    return path.parent.relative_to(root).as_posix()


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
                            "(tests/check_layers.py LAYERS, docs/architecture.md)")
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
    for line in problems:
        print(line)
    if problems:
        print(f"layer check: {len(problems)} problem(s)")
        return 1
    print(f"layer check: {len(files)} files, {len(provider)} modules, {len(uses)} uses: every "
          "use goes down the layers")
    return 0


if __name__ == "__main__":
    sys.exit(main())
