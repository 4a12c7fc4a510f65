#!/usr/bin/env python3
"""Write the single-file UMAT bundle: every library module the UMAT needs, in dependency
order, followed by the UMAT itself, as ONE free-form Fortran file that compiles on its own
(`gfortran -c interlock_umat_bundle.f90`).

Modules are found by reading `module` and `use` statements of the library's folders
(LIBRARY_FOLDERS below: src/base, material, laws, update, api; .f90 and .f90.in files);
the version module comes from its .in template with @PROJECT_VERSION@ substituted; a Fortran
`include` line of a module (a file of its folder) is replaced by that file's text.
Standard library only.

    python3 scripts/make_bundle.py [--source-dir DIR] [--version X.Y.Z] [--output FILE]
                                   [--entry umat/calculix/interlock_ccx_umat.f90]

--entry names another external entry than the 2D UMAT (umat/interlock_umat.f90), e.g.
CalculiX's `umat` over the thin-layer entry; the bundle then holds that entry instead (both
define the external `umat`, so they never go into one bundle).
"""
import argparse
import pathlib
import re
import sys

MODULE_RE = re.compile(r"^\s*module\s+(?!procedure\b|subroutine\b|function\b)(\w+)\s*(!.*)?$",
                       re.IGNORECASE)
USE_RE = re.compile(r"^\s*use\s*(?:,\s*non_intrinsic\s*)?(?:::)?\s*(\w+)", re.IGNORECASE)
INTRINSIC_USE_RE = re.compile(r"^\s*use\s*,\s*intrinsic", re.IGNORECASE)
PLACEHOLDER_RE = re.compile(r"@[A-Za-z_][A-Za-z0-9_]*@")
INCLUDE_RE = re.compile(r"""^\s*include\s*['"]([^'"]+)['"]\s*(!.*)?$""", re.IGNORECASE)
# The library's layers (docs/architecture.md); the programs' I/O above them is not bundled.
LIBRARY_FOLDERS = ("base", "material", "laws", "update", "api")


def project_version(source_dir):
    text = (source_dir / "CMakeLists.txt").read_text()
    m = re.search(r"project\s*\(\s*interlock\s+VERSION\s+([0-9][0-9.]*)", text, re.IGNORECASE)
    if not m:
        sys.exit("make_bundle: cannot find the project version in CMakeLists.txt; pass --version")
    return m.group(1)


def expand_includes(path, text):
    """text with each `include 'file'` line replaced by that file's text (its folder's)."""
    lines = []
    for line in text.splitlines():
        m = INCLUDE_RE.match(line)
        if not m:
            lines.append(line)
            continue
        included = path.parent / m.group(1)
        if not included.is_file():
            sys.exit(f"make_bundle: {path} includes {m.group(1)}, not found in {path.parent}")
        lines.append(f"! (included: {m.group(1)})")
        lines.extend(expand_includes(included, included.read_text()).splitlines())
    return "\n".join(lines) + "\n"


def scan(path, text):
    """Modules defined in a file and the non-intrinsic modules it uses."""
    defined, used = [], []
    for line in text.splitlines():
        m = MODULE_RE.match(line)
        if m:
            defined.append(m.group(1).lower())
            continue
        if INTRINSIC_USE_RE.match(line):
            continue
        m = USE_RE.match(line)
        if m:
            used.append(m.group(1).lower())
    if len(defined) > 1:
        sys.exit(f"make_bundle: {path} defines several modules; one module per file expected")
    return defined, used


def main():
    here = pathlib.Path(__file__).resolve().parent
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--source-dir", type=pathlib.Path, default=here.parent,
                        help="the project's source tree (default: this script's parent)")
    parser.add_argument("--version", help="PROJECT_VERSION (default: from CMakeLists.txt)")
    parser.add_argument("--output", type=pathlib.Path,
                        default=pathlib.Path("interlock_umat_bundle.f90"))
    parser.add_argument("--entry", default="umat/interlock_umat.f90",
                        help="the external entry, relative to the source tree "
                             "(default: umat/interlock_umat.f90, the 2D UMAT)")
    args = parser.parse_args()
    src = args.source_dir / "src"
    umat = args.source_dir / args.entry
    if not umat.is_file():
        sys.exit(f"make_bundle: the entry {umat} does not exist")
    version = args.version or project_version(args.source_dir)

    providers = {}   # module name -> (path, text, used modules)
    # The library's modules (src/) and the UMAT's own (umat/*.f90 but the UMAT itself).
    umat_modules = [p for p in sorted((args.source_dir / "umat").glob("*.f90"))
                    if p.name != "interlock_umat.f90" and p != umat]
    library = [p for folder in LIBRARY_FOLDERS for p in sorted((src / folder).iterdir())
               if p.suffix == ".f90" or p.name.endswith(".f90.in")]
    for path in library + umat_modules:
        text = expand_includes(path, path.read_text())
        if path.suffix == ".in":
            text = text.replace("@PROJECT_VERSION@", version)
            left = PLACEHOLDER_RE.findall(text)
            if left:
                sys.exit(f"make_bundle: {path} has unsubstituted placeholders {left}")
        defined, used = scan(path, text)
        for name in defined:
            if name in providers:
                sys.exit(f"make_bundle: module {name} defined in {providers[name][0]} and {path}")
            providers[name] = (path, text, used)

    umat_text = umat.read_text()
    _, roots = scan(umat, umat_text)

    order, state = [], {}

    def visit(name, chain):
        if name not in providers:
            sys.exit(f"make_bundle: module {name} (needed by {' <- '.join(chain)}) not found in {src} or umat/")
        if state.get(name) == "done":
            return
        if state.get(name) == "active":
            sys.exit(f"make_bundle: circular module dependency {' -> '.join(chain + [name])}")
        state[name] = "active"
        for dep in providers[name][2]:
            visit(dep, chain + [name])
        state[name] = "done"
        order.append(name)

    for root in roots:
        visit(root, ["UMAT"])

    parts = [
        "! interlock " + version + ": single-file UMAT bundle, GENERATED by scripts/make_bundle.py.\n"
        "! Do not edit: change src/ and umat/ and regenerate. Compile on its own, e.g.\n"
        "!   gfortran -O2 -c interlock_umat_bundle.f90\n"
        "! (free form, Fortran 2008; the reals are real64 whatever the default real kind).\n"
        "! PROPS / STATEV layout: interlock-query --props / --statev, or docs/material.md.\n"
        "! Modules, in dependency order: " + ", ".join(order) + "\n"]
    for name in order:
        path, text, _ = providers[name]
        rel = path.relative_to(args.source_dir).as_posix()
        parts.append(f"\n! {'=' * 20} {rel} {'=' * 20}\n" + text.rstrip("\n") + "\n")
    entry = umat.relative_to(args.source_dir).as_posix()
    parts.append(f"\n! {'=' * 20} {entry} {'=' * 20}\n" + umat_text.rstrip("\n") + "\n")

    args.output.parent.mkdir(parents=True, exist_ok=True)
    tmp = args.output.with_name(args.output.name + ".tmp")
    tmp.write_text("".join(parts))
    tmp.replace(args.output)
    print(f"make_bundle: wrote {args.output} ({len(order)} modules + UMAT, version {version})")


if __name__ == "__main__":
    main()
