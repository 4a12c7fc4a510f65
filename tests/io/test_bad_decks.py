#!/usr/bin/python3
"""Bad decks must be rejected (by interlock-history, or interlock-fit given as PROGRAM): the
program exits with status 1, its error output names the deck file and holds every fragment of
NAME.expected (whitespace runs compare as one space), it prints no Fortran runtime error, it
finishes within the time limit, it prints no runtime warning and no byte that is not printable
text (a control character or bytes that are not UTF-8: a binary deck or curve file is never
echoed), and it leaves no result file and no temporary file behind (the output folder holds
nothing new afterwards).

usage: test_bad_decks.py PROGRAM NAME.expected|NAME.nml [...]
       test_bad_decks.py --generate DIR     write the generated decks into DIR
       test_bad_decks.py --crlf PROGRAM DECK.nml
                                  a copy of DECK with Windows (CR LF) line ends gives the same
                                  HDF5 datasets as DECK itself (CR LF decks are accepted)
       test_bad_decks.py --bom PROGRAM DECK.nml
                                  the same with a UTF-8 byte order mark before the text (the
                                  deck attribute is the text without it)

NAME.expected (beside NAME.nml, in tests/data/bad_decks/ or the generated folder) holds one line
per fragment; blank lines and lines starting with '#' are ignored; directives:
  @no-output-dir   run without --output-dir (in an empty working folder), so that the deck's
                   &output file is used as given
  @runtime-warning-known
                   a Fortran runtime warning before the message is a known defect of the
                   deck reader (the comment says which): not counted here
A NAME.expected without NAME.nml runs the program on a deck that does not exist.
Adding a bad deck needs no code: add the pair and re-run cmake.
"""
import os
import random
import re
import subprocess
import sys
import tempfile

TIMEOUT = 60
RUNTIME_ERRORS = ("Fortran runtime error", "Fortran runtime warning", "Error termination", "Backtrace",
                  "Program received signal", "Segmentation fault", "HDF5-DIAG")
RUNTIME_WARNING = "Fortran runtime warning"

BASE = """&interface
  sigma0_n = 3.0, sigma0_t = 3.0, gc = 0.3, eta = 0.9, mu = 0.5, h_n = 1.0
/
&microplanes
  theta0_deg = 45.0
/
&loading
  normal_control = 'traction', tangential_control = 'separation'
  times = 0.0, 1.0, 1.6
  normal = 0.0, -0.2, -0.2
  tangential = 0.0, 0.0, 0.6
  steps = 1, 6
/
"""


def squash(s):
    return re.sub(r"\s+", " ", s)


def listing(folder):
    found = []
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            found.append(os.path.relpath(os.path.join(root, name), folder))
    return sorted(found)


def read_expected(path):
    fragments, directives = [], set()
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if line.startswith("@"):
                directives.add(line)
            else:
                fragments.append(line)
    return fragments, directives


def check_deck(program, given):
    stem = os.path.splitext(given)[0]
    deck, expected_path = stem + ".nml", stem + ".expected"
    name = os.path.basename(deck)
    fragments, directives = read_expected(expected_path)
    unknown = directives - {"@no-output-dir", "@runtime-warning-known"}
    problems = []
    if not fragments:
        problems.append(f"{expected_path} holds no fragment")
    if unknown:
        problems.append(f"unknown directives {sorted(unknown)}")
    stderr, stdout = "", ""
    with tempfile.TemporaryDirectory() as work:
        command = [program, os.path.abspath(deck)]
        if "@no-output-dir" not in directives:
            command[1:1] = ["--output-dir", work]
        try:
            run = subprocess.run(command, cwd=work, capture_output=True, text=True, errors="replace",
                                 timeout=TIMEOUT)
            stderr, stdout, rc = run.stderr, run.stdout, run.returncode
        except subprocess.TimeoutExpired:
            rc = None
            problems.append(f"no answer within {TIMEOUT} s (a hang)")
        left = listing(work)
    if rc is not None and rc != 1:
        problems.append(f"exit status {rc}, expected 1")
    message = squash(stderr)
    for fragment in fragments:
        if squash(fragment) not in message:
            problems.append(f"message lacks '{fragment}'")
    if name not in message:
        problems.append("message does not name the deck file")
    for marker in RUNTIME_ERRORS:
        if marker == RUNTIME_WARNING and "@runtime-warning-known" in directives:
            continue
        if marker in stderr or marker in stdout:
            problems.append(f"output holds '{marker}' (not our message)")
    shown = [c for c in stderr + stdout if c == "\ufffd" or (ord(c) < 32 and c not in "\n\t")]
    if shown:
        problems.append(f"output echoes bytes that are not printable text: {sorted(set(map(ord, shown)))}")
    if " -> " in stdout:
        problems.append("the program says it wrote a file")
    if left:
        problems.append(f"files left behind: {left}")
    if problems:
        print(f"[FAIL] {name}: " + "; ".join(problems))
        print("       stderr: " + stderr.strip()[:2000])
        return False
    print(f"[ ok ] {name}: {stderr.strip()[:400]}")
    return True


def write_pair(folder, name, deck_bytes, fragments, comment, directives=()):
    with open(os.path.join(folder, name + ".nml"), "wb") as f:
        f.write(deck_bytes)
    with open(os.path.join(folder, name + ".expected"), "w") as f:
        f.write(f"# {comment} (written by test_bad_decks.py --generate)\n")
        for directive in directives:
            f.write(directive + "\n")
        f.write("\n".join(fragments) + "\n")


def generate(folder):
    """Decks too big or too binary to keep in the source tree."""
    os.makedirs(folder, exist_ok=True)
    base = BASE.encode()
    title = b"&output\n  title = '" + b"x" * (100 * 1024) + b"'\n/\n"
    # gfortran's namelist read warns "Namelist object 'title' truncated on read" (Debug) before
    # the deck reader's message: a known defect of the deck reader
    write_pair(folder, "title_100k", base + title,
               ["&output:", "title is longer than 1024 characters", "at most 1024"], "a title of 100 kB",
               ["@runtime-warning-known"])
    line = b"! a 10 MB line\n" + base + b"! " + b"y" * (10 * 1024 * 1024) + b"\n"
    write_pair(folder, "line_10mb", line, ["bytes", "at most 4194304 bytes"],
               "a 10 MB line (a deck larger than 4 MiB)")
    values = b"0.0, " * (700 * 1000)
    huge_line = base.replace(b"  times = 0.0, 1.0, 1.6\n", b"  times = " + values + b"1.0\n")
    write_pair(folder, "line_3mb_values", huge_line, ["&loading:", "times", "at most 10001"],
               "700001 values of times on one 3.5 MB line")
    rng = random.Random(20240611)
    garbage = bytes(rng.randrange(256) for _ in range(4096))
    write_pair(folder, "random_bytes", garbage, ["control character", "text file"],
               "4 kB of random bytes")
    write_pair(folder, "nul_in_comment", base.replace(b"/\n&loading", b"/\n! \x00\n&loading", 1),
               ["line 7", "control character (code 0)"], "a NUL byte in a comment")
    write_pair(folder, "utf16", b"\xff\xfe" + BASE.encode("utf-16-le"),
               ["UTF-16", "ASCII or UTF-8"], "the deck saved as UTF-16 (Windows 'Unicode')")
    os.makedirs(os.path.join(folder, "folder_deck.nml"), exist_ok=True)
    with open(os.path.join(folder, "folder_deck.expected"), "w") as f:
        f.write("# folder_deck.nml is a folder (written by --generate)\nthe deck is a folder\n")
    # Not regular files: a FIFO (reading it would block) and the endless /dev/zero.
    for name, make in (("fifo_deck", lambda p: os.mkfifo(p)),
                       ("dev_zero_deck", lambda p: os.symlink("/dev/zero", p))):
        target = os.path.join(folder, name + ".nml")
        if os.path.lexists(target):
            os.remove(target)
        make(target)
        with open(os.path.join(folder, name + ".expected"), "w") as f:
            f.write(f"# {name}.nml is not a regular file (written by --generate)\n"
                    "the deck is not a regular file\n")
    write_pair(folder, "bom_only", b"\xef\xbb\xbf", ["the deck is empty"],
               "a UTF-8 byte order mark and nothing else")
    write_pair(folder, "lone_cr", BASE.replace("\n", "\r").encode(),
               ["line ends", "carriage return"], "old Mac line ends (CR alone)")


def crlf(program, deck, bom=False):
    import h5py
    import numpy as np
    with open(deck, "rb") as f:
        text = f.read()
    problems = []
    with tempfile.TemporaryDirectory() as work:
        lf_deck = os.path.join(work, "lf.nml")
        crlf_deck = os.path.join(work, "crlf.nml")
        with open(lf_deck, "wb") as f:
            f.write(text.replace(b"\r\n", b"\n"))
        # The variant: CR LF line ends, or (bom) a UTF-8 byte order mark before LF text.
        want = text.replace(b"\r\n", b"\n")
        variant = b"\xef\xbb\xbf" + want if bom else want.replace(b"\n", b"\r\n")
        if not bom:
            want = variant
        with open(crlf_deck, "wb") as f:
            f.write(variant)
        for d in (lf_deck, crlf_deck):
            run = subprocess.run([program, "--output-dir", work, d], cwd=work, capture_output=True,
                                 text=True, errors="replace", timeout=TIMEOUT)
            if run.returncode != 0:
                problems.append(f"{os.path.basename(d)}: exit status {run.returncode}: {run.stderr}")
        if not problems:
            with h5py.File(os.path.join(work, "lf.h5")) as a, \
                 h5py.File(os.path.join(work, "crlf.h5")) as b:
                if a.attrs["n_cases"] != b.attrs["n_cases"]:
                    problems.append("n_cases differ")
                for case in a["cases"]:
                    for k in ("status", "label"):
                        if a["cases"][case].attrs[k] != b["cases"][case].attrs[k]:
                            problems.append(f"{case}: attribute {k} differs")
                    for name, ds in a["cases"][case].items():
                        if not np.array_equal(ds[()], b["cases"][case][name][()]):
                            problems.append(f"{case}/{name} differs")
                deck_attr = b.attrs["deck"]
                if not isinstance(deck_attr, bytes):
                    deck_attr = deck_attr.encode("utf-8", "surrogateescape")
                if deck_attr != want:
                    problems.append("the deck attribute is not the " +
                                    ("text without its byte order mark" if bom else "CR LF text") +
                                    " byte for byte")
    for p in problems:
        print("[FAIL] " + p)
    print(f"history {'UTF-8 BOM' if bom else 'CR LF'} deck {os.path.basename(deck)}: "
          + ("FAILED" if problems else "same results"))
    return 1 if problems else 0


def main(argv):
    if len(argv) == 2 and argv[0] == "--generate":
        generate(argv[1])
        return 0
    if len(argv) == 3 and argv[0] in ("--crlf", "--bom"):
        return crlf(argv[1], argv[2], bom=argv[0] == "--bom")
    if len(argv) < 2:
        print(__doc__)
        return 2
    program, decks = argv[0], argv[1:]
    failures = sum(0 if check_deck(program, d) else 1 for d in decks)
    print(f"history_bad_decks: {len(decks)} decks, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
