#!/usr/bin/python3
"""Bad decks must be rejected: interlock-history exits with status 1, its error output holds
every fragment of NAME.expected (one per line; whitespace runs compare as one space), and no
result file and no temporary file is left behind.

usage: test_history_bad_decks.py PROGRAM DECK.nml [DECK.nml ...]
Each DECK.nml sits beside its DECK.expected (tests/data/bad_decks/): adding a bad deck needs no code.
"""
import os
import re
import subprocess
import sys
import tempfile


def squash(s):
    return re.sub(r"\s+", " ", s)


def main(argv):
    if len(argv) < 2:
        print(__doc__)
        return 2
    program, decks = argv[0], argv[1:]
    failures = 0
    for deck in decks:
        expected_path = os.path.splitext(deck)[0] + ".expected"
        with open(expected_path) as f:
            fragments = [line.strip() for line in f if line.strip()]
        problems = []
        if not fragments:
            problems.append(f"{expected_path} holds no fragment")
        with tempfile.TemporaryDirectory() as work:
            run = subprocess.run([program, "--output-dir", work, os.path.abspath(deck)], cwd=work,
                                 capture_output=True, text=True, errors="replace", timeout=60)
            left = os.listdir(work)
        if run.returncode != 1:
            problems.append(f"exit status {run.returncode}, expected 1")
        message = squash(run.stderr)
        for fragment in fragments:
            if squash(fragment) not in message:
                problems.append(f"message lacks '{fragment}'")
        if os.path.basename(deck) not in message:
            problems.append("message does not name the deck file")
        if left:
            problems.append(f"files left behind: {left}")
        name = os.path.basename(deck)
        if problems:
            failures += 1
            print(f"[FAIL] {name}: " + "; ".join(problems))
            print("       stderr: " + run.stderr.strip()[:2000])
        else:
            print(f"[ ok ] {name}: {run.stderr.strip()[:300]}")
    print(f"history_bad_decks: {len(decks)} decks, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
