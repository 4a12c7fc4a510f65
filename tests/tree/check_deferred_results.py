#!/usr/bin/python3
"""No function in the given source folders returns a deferred-length character result
(`character(len=:), allocatable` as the result): at every call of such a function gfortran 12
keeps the result's length in a static variable of the caller, which threads calling at once
overwrite. The folders are those a UMAT call runs (the host calls it on many threads);
interlock_numbers:format_real says how their text functions are written instead.

usage: check_deferred_results.py FOLDER...   exit 0: none found, 1: found (each printed)
"""
import glob
import os
import re
import sys

FUNCTION = re.compile(r"^\s*(?:(?:pure|elemental|recursive|impure|module)\s+)*"
                      r"(?:[\w()=,:* ]*\s)?function\s+(\w+)\s*\([^)]*\)\s*"
                      r"(?:result\s*\(\s*(\w+)\s*\))?", re.I)
END = re.compile(r"^\s*end\s+function\b", re.I)
DEFERRED = re.compile(r"character\s*\(\s*len\s*=\s*:\s*\)\s*,\s*allocatable\s*::(.*)", re.I)


def deferred_results(path):
    found, stack = [], []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            code = line.split("!")[0]
            if END.match(code):
                if stack:
                    stack.pop()
                continue
            m = FUNCTION.match(code)
            if m:
                stack.append((m.group(1), (m.group(2) or m.group(1)).lower(), number))
                continue
            d = DEFERRED.search(code)
            if d and stack:
                names = [n.strip().split("(")[0].lower() for n in d.group(1).split(",")]
                if stack[-1][1] in names:
                    found.append(f"{path}:{stack[-1][2]}: function {stack[-1][0]}")
    return found


def main(folders):
    if not folders:
        print(__doc__)
        return 2
    found, files = [], 0
    for folder in folders:
        for path in sorted(glob.glob(os.path.join(folder, "*.f90"))):
            files += 1
            found += deferred_results(path)
    for line in found:
        print(line + ": a deferred-length character result (a race under threads)")
    print(f"{files} files, {len(found)} functions with a deferred-length result")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
