#!/usr/bin/env python3
"""The docs cite only what exists.

Reads README.md and docs/*.md and checks every
- CTest name (a code span `area_stem...` of a test area, or one after the word "CTest"), against
  the tests registered in the build tree (`ctest --show-only=json-v1`; a `*` in a cited name is a
  wildcard); names of an area this configuration does not register (calculix without
  -DINTERLOCK_CCX, mpi without deal.II: given on the command line) are listed as not checked;
- repository path (a code span or a relative link starting with a top-level folder of the
  repository), against the tree (wildcards allowed);
- name `INTERLOCK_*`, against the CMake files that define it (an option), the C header (a
  macro) and the test scripts (an environment variable);
- program `interlock-*`, against the executables the CMake files build;
- command-line option `--x` of a program or script in a code span that names it, against that
  program's or script's sources.

Usage: check_docs.py SOURCE_DIR BUILD_DIR CTEST [UNCONFIGURED_AREA...]
(the areas whose tests this configuration does not register: their names are not checked).
Prints one line per stale citation (file:line, what, why) and exits 1 if there is any.
"""
import fnmatch
import glob
import json
import os
import re
import subprocess
import sys

AREAS = ("core", "umat", "stability", "history", "fit", "calculix", "mpi")
TOP = ("src", "tests", "umat", "scripts", "inputs", "docs", "bench", "examples", "cmake",
       "include", ".ci")
# Code spans that look like test names and are not.
NOT_TESTS = {
    "history_x": "a dataset of the fit's HDF5 output",
    "history_y": "a dataset of the fit's HDF5 output",
    "umat_abaqus": "a function of CalculiX",
    "calculix_linear_iteration": "a function of the thin layer (umat/interlock_umat_layer.f90)",
}
# A program's sources: where its options are spelled.
PROGRAM_SOURCES = {
    "interlock-history": ["src/programs/history", "src/io", "src/driver"],
    "interlock-fit": ["src/programs/fit", "src/io"],
    "interlock-query": ["src/programs/query"],
    "interlock-bench": ["bench"],
    "interlock-fuzz": ["tests/stability/fuzz"],
}


def registered_tests(build_dir, ctest):
    out = subprocess.run([ctest, "--show-only=json-v1"], cwd=build_dir, check=True,
                         capture_output=True, text=True).stdout
    return {t["name"] for t in json.loads(out)["tests"]}


def cmake_texts(root):
    files = [os.path.join(root, "CMakeLists.txt")]
    for pattern in ("cmake/*.cmake", "*/CMakeLists.txt", "*/*/CMakeLists.txt",
                    "*/*/*/CMakeLists.txt", "tests/**/*.cmake", "examples/*/CMakeLists.txt"):
        files += glob.glob(os.path.join(root, pattern), recursive=True)
    texts = []
    for f in sorted(set(files)):
        with open(f, encoding="utf-8") as fh:
            texts.append(fh.read())
    return "\n".join(texts)


def source_text(root, folders):
    parts = []
    for folder in folders:
        path = os.path.join(root, folder)
        files = [path] if os.path.isfile(path) else \
            [os.path.join(d, f) for d, _, fs in os.walk(path) for f in fs]
        for f in files:
            if f.endswith((".f90", ".F90", ".c", ".h", ".py", ".sh", ".cc", ".cpp")):
                with open(f, encoding="utf-8", errors="replace") as fh:
                    parts.append(fh.read())
    return "\n".join(parts)


def code_spans(line):
    return re.findall(r"`([^`]+)`", line)


def main():
    if len(sys.argv) < 4:
        print(__doc__)
        return 2
    root, build_dir, ctest = sys.argv[1:4]
    tests = registered_tests(build_dir, ctest)
    areas_here = set(AREAS) - set(sys.argv[4:])
    cmake = cmake_texts(root)
    programs = set(re.findall(r"add_executable\(\s*(interlock-[a-z0-9-]+)", cmake))
    programs |= set(re.findall(r"OUTPUT_NAME\s+(interlock-[a-z0-9-]+)", cmake))
    sources = {}
    test_scripts = source_text(root, ["tests", "scripts", "include"])

    docs = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    problems, counts, unchecked = [], {"test": 0, "path": 0, "option": 0, "program": 0,
                                       "flag": 0}, set()

    def problem(where, what, why):
        problems.append(f"{where}: {what}: {why}")

    in_block = False
    for doc in docs:
        rel = os.path.relpath(doc, root)
        with open(doc, encoding="utf-8") as fh:
            lines = fh.read().splitlines()
        for number, line in enumerate(lines, 1):
            where = f"{rel}:{number}"
            if line.lstrip().startswith("```"):
                in_block = not in_block
                continue
            spans = [line] if in_block else code_spans(line)
            # CTest names.
            # In a code block only a ctest command line names tests.
            names = set()
            for span in spans if not in_block or "ctest" in line else []:
                for token in re.findall(r"[A-Za-z0-9_*]+", span) if in_block else [span.strip()]:
                    if (re.fullmatch(r"(%s)_[a-z0-9_*]+" % "|".join(AREAS), token)
                            and token not in NOT_TESTS):
                        names.add(token)
            if not in_block:
                names |= set(re.findall(r"CTests? `([^`]+)`", line))
            for name in names:
                if in_block and not name.startswith(tuple(a + "_" for a in AREAS)):
                    continue
                area = name.split("_")[0]
                if area in AREAS and area not in areas_here:
                    unchecked.add(name)
                    continue
                counts["test"] += 1
                # A test registered only in another configuration (mpi_dealii_absent) is
                # named literally in its add_test.
                if (not any(fnmatch.fnmatchcase(t, name) for t in tests)
                        and f"add_test(NAME {name} " not in cmake
                        and f"add_test(NAME {name}\n" not in cmake):
                    problem(where, f"CTest `{name}`", "no such test in this build tree")
            # Paths: code spans and relative links.
            candidates = [] if in_block else list(spans)
            candidates += re.findall(r"\]\(([^)#\s]+)", line)
            for cand in candidates:
                token = cand.strip().split()[0] if cand.strip() else ""
                token = re.sub(r"[:,;.]+$", "", token)
                token = re.sub(r":\d+(-\d+)?$", "", token)
                if token.startswith(("http:", "https:", "mailto:")):
                    continue
                top_level = token.startswith(tuple(t + "/" for t in TOP))
                base = root if top_level else os.path.dirname(doc)
                if not (top_level
                        or (cand in re.findall(r"\]\(([^)#\s]+)", line) and "/" not in token
                            and token.endswith((".md", ".png", ".csv", ".nml")))):
                    continue
                if "<" in token or "{" in token or "NAME" in token or "DECK" in token:
                    continue
                counts["path"] += 1
                path = os.path.normpath(os.path.join(base, token))
                if not glob.glob(path) and not glob.glob(os.path.join(root, token)):
                    problem(where, f"path `{token}`", "does not exist")
            # CMake options, the C header's macros, the environment variables tests read.
            for option in set(re.findall(r"\b(INTERLOCK_[A-Z0-9_]+)\b", line)):
                counts["option"] += 1
                if option not in cmake and option not in test_scripts:
                    problem(where, f"option `{option}`", "no CMake file, C header or test script has it")
            # Programs and their options.
            for span in spans:
                for prog in set(re.findall(r"\b(interlock-[a-z0-9]+(?:-[a-z0-9]+)*)(?![\w.-])", span)):
                    if prog.endswith("-"):
                        continue
                    counts["program"] += 1
                    if prog not in programs:
                        problem(where, f"program `{prog}`", "no CMake target builds it")
                        continue
                    flags = re.findall(r"(?<![\w-])(--[a-z][a-z0-9-]*)", span.split(prog, 1)[1])
                    if flags and prog in PROGRAM_SOURCES:
                        if prog not in sources:
                            sources[prog] = source_text(root, PROGRAM_SOURCES[prog])
                        for flag in flags:
                            counts["flag"] += 1
                            if f"'{flag}" not in sources[prog] and f'"{flag}' not in sources[prog]:
                                problem(where, f"option `{prog} {flag}`",
                                        "not in the program's sources")
                for script in set(re.findall(r"([\w./-]+\.(?:py|sh))\b", span)):
                    hits = [p for p in glob.glob(os.path.join(root, "**", os.path.basename(script)),
                                                 recursive=True) if "/build" not in p]
                    flags = re.findall(r"(?<![\w-])(--[a-z][a-z0-9-]*)", span.split(script, 1)[1])
                    if not hits or not flags:
                        continue
                    text = source_text(root, [os.path.relpath(h, root) for h in hits])
                    for flag in flags:
                        counts["flag"] += 1
                        if flag not in text and flag != "--help":   # argparse's own
                            problem(where, f"option `{os.path.basename(script)} {flag}`",
                                    "not in the script")
    for p in problems:
        print(p)
    print("checked: " + ", ".join(f"{n} {k}s" for k, n in counts.items()))
    if unchecked:
        print("not checked (no test of their area in this build tree): " +
              " ".join(sorted(unchecked)))
    if problems:
        print(f"{len(problems)} stale citations")
        return 1
    print("the docs cite only what exists")
    return 0


if __name__ == "__main__":
    sys.exit(main())
