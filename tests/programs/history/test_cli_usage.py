#!/usr/bin/python3
"""Usage errors of the command-line programs.

usage: test_cli_usage.py WORK_DIR NAME=PROGRAM...   (NAME: history, fit, query, bench, fuzz)

A usage error (no argument where one is needed, an unknown option, an option without its
value, a value that is not a number, a folder that does not exist) prints a message and the
usage on stderr, nothing on stdout (every option is checked before any work: interlock-query
prints nothing before a bad trailing option), and exits with status 2 (interlock-history and
interlock-fit: 1, their documented status for a wrong option) within seconds, without a
Fortran "ERROR STOP" or a backtrace; --help prints the usage on stdout and --version the version, both with status 0.
interlock-bench without --out writes nothing into the working folder.
Every program runs in an empty folder, which must stay empty.
"""
import os
import shutil
import subprocess
import sys

CASES = {
    "history": [([], 1), (["--bogus"], 1), (["--output-dir"], 1)],
    "fit": [([], 1), (["--bogus"], 1), (["--output-dir"], 1), (["a.nml", "b.nml"], 1),
            (["--quiet", "--output-dir"], 1)],
    "query": [([], 2), (["--bogus"], 2), (["--props", "--bogus"], 2),
              (["--markdown", "--properties", "--bogus"], 2)],
    "bench": [([], 2), (["--bogus"], 2), (["--quick"], 2), (["--out"], 2),
              (["--target", "abc", "--out", "."], 2), (["--history", "fig11"], 2),
              (["--profile", "x", "1", "1"], 2), (["--out", "/nonexistent"], 2),
              (["--quick", "--out", "/nonexistent/folder"], 2)],
    "fuzz": [(["--bogus"], 2), (["--updates"], 2), (["--updates", "abc"], 2),
             (["--seed", "1.5e"], 2), (["--fd-every", "0"], 2),
             (["--deck-dir", "/nonexistent"], 2)],
}


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    work = argv[0]
    programs = dict(a.split("=", 1) for a in argv[1:])
    failures = 0

    def check(ok, what):
        nonlocal failures
        print(f"[{' ok ' if ok else 'FAIL'}] {what}")
        failures += not ok

    for name, program in programs.items():
        folder = os.path.join(work, name)
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        for args, code in CASES[name]:
            r = subprocess.run([program] + args, cwd=folder, capture_output=True, text=True,
                               timeout=20)
            label = f"{name} {' '.join(args) or '(no argument)'}"
            noisy = [w for w in ("ERROR STOP", "Backtrace", "STOP ") if w in r.stderr + r.stdout]
            check(r.returncode == code and "usage" in r.stderr and not noisy and not r.stdout,
                  f"{label}: exit status {r.returncode} ({code}), usage on stderr, nothing on "
                  "stdout" + (f", but {noisy}" if noisy else "")
                  + (f", but stdout: {r.stdout[:100]!r}" if r.stdout else "")
                  + ("" if r.returncode == code else f": {r.stderr.strip()[:200]}"))
        for args, stream in ((["--help"], "usage"), (["--version"], "interlock")):
            r = subprocess.run([program] + args, cwd=folder, capture_output=True, text=True,
                               timeout=60)
            check(r.returncode == 0 and stream in r.stdout and not r.stderr,
                  f"{name} {args[0]}: status {r.returncode} (0), on stdout")
        left = os.listdir(folder)
        check(not left, f"{name}: nothing written into the working folder ({left})")
    print(f"cli_usage: {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
