#!/usr/bin/python3
"""The verdict of a test by what its program prints: each expectation on its own line.

usage: check_output.py [--status N] [--expect REGEX]... [--absent REGEX]... -- COMMAND [ARG...]

Runs COMMAND, prints its output (standard output, then standard error), then one line per
check: its exit status is N (default 0); each --expect REGEX (Python syntax) matches somewhere
in the output; no --absent REGEX does. A failed check says what it expected and what the
program printed instead: the exit status it returned, or the output lines nearest to the
expected text. Exit status 0 when every check holds, 1 otherwise.

The test suites use it as the launcher of a program whose messages are the verdict
(tests/CMakeLists.txt: interlock_expect_output), instead of one regular expression over all
messages, which on failure says only that it was not found.
"""
import argparse
import difflib
import re
import subprocess
import sys


def literal(regex):
    """The text a regular expression spells, roughly: escapes and wildcards dropped."""
    text = re.sub(r"\\(.)", r"\1", regex)
    return re.sub(r"[\^$*+?]|\.\*|\[[^\]]*\]|\{[0-9,]+\}", "", text)


def nearest(regex, lines, n=3):
    """The n output lines most like what `regex` spells (for a message that was not found):
    the most of its words, then the closest text."""
    want = literal(regex)
    words = set(re.findall(r"\w+", want))
    scored = []
    for line in lines:
        shared = len(words & set(re.findall(r"\w+", line)))
        close = difflib.SequenceMatcher(None, want, line, autojunk=False).ratio()
        scored.append((shared, close, line))
    scored.sort(key=lambda x: (-x[0], -x[1]))
    return [line for shared, close, line in scored[:n] if shared > 0]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--status", type=int, default=0)
    parser.add_argument("--expect", action="append", default=[])
    parser.add_argument("--absent", action="append", default=[])
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args(argv)
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    if not command:
        parser.error("no command")
    run = subprocess.run(command, capture_output=True, text=True, errors="replace")
    sys.stdout.write(run.stdout)
    sys.stdout.write(run.stderr)
    output = run.stdout + run.stderr
    lines = [line for line in output.splitlines() if line.strip()]
    failures = 0

    def verdict(ok, what, got=()):
        nonlocal failures
        failures += not ok
        print(f"[{' ok ' if ok else 'FAIL'}] {what}")
        for line in got:
            print(f"         got: {line}")

    verdict(run.returncode == args.status, f"exit status {args.status}"
            + ("" if run.returncode == args.status else f": got {run.returncode}"))
    for regex in args.expect:
        found = re.search(regex, output) is not None
        unlike = f"(none of the {len(lines)} lines printed shares a word with it)"
        verdict(found, f"expected: {regex}",
                () if found else nearest(regex, lines) or [unlike])
    for regex in args.absent:
        match = re.search(regex, output)
        verdict(match is None, f"absent: {regex}",
                () if match is None else [l for l in lines if re.search(regex, l)][:3])
    print(f"check_output: {failures} of {1 + len(args.expect) + len(args.absent)} checks "
          "missed" if failures else
          f"check_output: all {1 + len(args.expect) + len(args.absent)} checks hold")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
