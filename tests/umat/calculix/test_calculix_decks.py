#!/usr/bin/python3
"""CTest (label calculix): one ccx deck of tests/data/calculix with the interlock thin layer.

    test_calculix_decks.py CCX DECK.inp WORK_DIR [--complete | --stops]
                           [--count REGEX N ...] [--normal-traction MPA] [--threads N]

Copies the deck into WORK_DIR, runs ccx (on --threads threads, default 1) and checks:
  --complete            ccx ends with "Job finished" and the last step reaches step time 1;
  --stops               ccx stops before the end (bad input must stop the host);
  --count REGEX N       exactly N lines of ccx's output match REGEX (the UMAT's messages:
                        one per material and kind of message);
  --normal-traction T   the layer's normal traction (STATEV 31, *DEPVAR 34) equals -T at
                        every printed point of the last step to 1e-3 relative (the applied
                        pressure: equilibrium of the block, a closed form).
Prints per step the increments, the failed attempts (cutbacks) and the iterations of the
converged attempts (ccx's .sta), and the iterations of every attempt (.cvg).
"""
import argparse
import pathlib
import re
import shutil
import subprocess
import sys


def read_sta(job):
    """Per step: converged increments (iterations), failed attempts, last step time."""
    steps = {}
    for line in job.with_suffix(".sta").read_text().splitlines():
        parts = line.split()
        if len(parts) != 7 or not parts[0].isdigit() or not parts[1].isdigit():
            continue
        st = steps.setdefault(int(parts[0]), {"iterations": [], "failed": 0, "time": 0.0})
        if parts[2].isdigit():
            st["iterations"].append(int(parts[3]))
            st["time"] = float(parts[5])
        else:
            st["failed"] += 1
    return steps


def read_cvg(job):
    """Per step: the iterations of every attempt."""
    total = {}
    path = job.with_suffix(".cvg")
    if not path.is_file():
        return total
    for line in path.read_text().splitlines():
        parts = line.split()
        if len(parts) >= 9 and parts[0].isdigit():
            total[int(parts[0])] = total.get(int(parts[0]), 0) + 1
    return total


def layer_normal_tractions(job):
    """STATEV 31 of every printed layer point in the last step (*EL PRINT SDV; the decks are
    C3D8: the 3D law's 28 STATEV, then the layer's separation and traction (normal, slip))."""
    blocks, current = [], None
    for line in job.with_suffix(".dat").read_text().splitlines():
        if "internal state variables" in line:
            current = []
            blocks.append(current)
            continue
        parts = line.split()
        if current is not None and len(parts) >= 2 + 34 and parts[0].isdigit():
            current.append(float(parts[2 + 30]))
        elif current is not None and parts and not parts[0].isdigit():
            current = None
    return blocks


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("ccx")
    p.add_argument("deck")
    p.add_argument("work")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--complete", action="store_true")
    g.add_argument("--stops", action="store_true")
    p.add_argument("--count", nargs=2, action="append", default=[], metavar=("REGEX", "N"))
    p.add_argument("--normal-traction", type=float)
    p.add_argument("--threads", type=int, default=1)
    a = p.parse_args(argv)
    work = pathlib.Path(a.work)
    work.mkdir(parents=True, exist_ok=True)
    deck = pathlib.Path(a.deck)
    job = work / deck.stem
    shutil.copyfile(deck, job.with_suffix(".inp"))
    for suffix in (".dat", ".cvg", ".sta", ".frd"):
        job.with_suffix(suffix).unlink(missing_ok=True)
    proc = subprocess.run([a.ccx, "-i", job.name], cwd=work, capture_output=True, text=True,
                          env={"OMP_NUM_THREADS": str(a.threads),
                               "CCX_NPROC_STIFFNESS": str(a.threads), "PATH": "/usr/bin:/bin"},
                          timeout=600)
    out = proc.stdout + proc.stderr
    job.with_suffix(".log").write_text(out)
    failures = []

    def check(ok, text):
        print(("ok   " if ok else "FAIL ") + text)
        if not ok:
            failures.append(text)

    steps = read_sta(job) if job.with_suffix(".sta").is_file() else {}
    cvg = read_cvg(job)
    for number, st in sorted(steps.items()):
        its = sorted(st["iterations"])
        median = its[len(its) // 2] if its else 0
        print(f"step {number}: {len(its)} increments, {st['failed']} failed attempts (cutbacks), "
              f"iterations median {median} max {max(its, default=0)}, "
              f"{cvg.get(number, 0)} iterations in all, step time reached {st['time']:.6g}")
    finished = "Job finished" in out
    if a.complete:
        last = steps[max(steps)] if steps else None
        check(finished and last is not None and abs(last["time"] - 1.0) < 1e-9,
              f"{deck.name}: ccx reaches the end of its last step")
    else:
        check(not finished, f"{deck.name}: ccx stops (bad input)")
    for regex, n in a.count:
        found = [line for line in out.splitlines() if re.search(regex, line)]
        for line in found:
            print("  | " + line[:300])
        check(len(found) == int(n), f"{len(found)} line(s) match '{regex}' (expected {n})")
    if a.normal_traction is not None:
        blocks = layer_normal_tractions(job)
        worst = max((abs(t + a.normal_traction) for b in blocks[-10:] for t in b), default=None)
        check(worst is not None and worst <= 1e-3 * a.normal_traction,
              f"the layer's normal traction is -{a.normal_traction} MPa (the applied pressure) "
              f"in the last printed increments: largest difference {worst}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
