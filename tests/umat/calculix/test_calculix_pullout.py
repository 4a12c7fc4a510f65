#!/usr/bin/python3
"""CTest (label calculix): the coarse pull-out (10 mm elements) in ccx with the interlock UMAT.

    test_calculix_pullout.py CCX_BINARY RUN_DIR

Runs examples/calculix/pullout/run.py (mesh, ccx, post-processing) and asserts what the paper's
section 4.2 says about the test, from closed forms and the paper's text, not from a previous
run of this code:
  - the analysis reaches the prescribed top displacement, 5.2 mm;
  - the force when the bar first yields at the loaded end is within 3 % of the bar's yield force
    350 MPa x pi D^2 / 4 (the clay sleeve carries almost nothing: the force at the grip is the
    force in the bar's top section);
  - the slip along the clay sleeve is at least 10 times the slip below it (the paper: "one
    order of magnitude larger") at every profile level from s = 1 mm on;
  - the yielded length of the bar grows monotonically from the loaded end (never shrinks), and
    reaches beyond the first element.
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
RUN = os.path.join(HERE, "..", "..", "..", "examples", "calculix", "pullout", "run.py")


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 1
    ccx, run_dir = argv
    rc = subprocess.run([sys.executable, RUN, "--ccx", ccx, "--dir", run_dir, "--threads", "2",
                         "--element", "10", "--title", "coarse (CTest)"]).returncode
    summary_path = os.path.join(run_dir, "summary.json")
    if rc == 1 or not os.path.isfile(summary_path):
        print("FAIL: the coarse pull-out did not run")
        return 1
    with open(summary_path) as f:
        s = json.load(f)
    failures = []

    def check(ok, text):
        print(("ok   " if ok else "FAIL ") + text)
        if not ok:
            failures.append(text)

    check(s["completed"], f"reaches {s['top_displacement_target_mm']} mm "
          f"(reached {s['top_displacement_reached_mm']:.4f} mm)")
    fy, f1 = s["bar_yield_force_N"], s["force_at_first_yield_N"]
    check(f1 is not None and abs(f1 / fy - 1.0) <= 0.03,
          f"force at first yield {f1} N within 3 % of the bar's yield force {fy:.1f} N")
    for p in s["profiles"]:
        if p["top_displacement_mm"] >= 1.0:
            r = p["slip_ratio"]
            check(r is not None and r >= 10.0,
                  f"s = {p['top_displacement_mm']} mm: mean slip along the clay sleeve "
                  f"{p['mean_slip_clay_mm']:.4g} mm >= 10 x the slip below "
                  f"{p['mean_slip_below_mm']:.4g} mm (ratio {r})")
    check(s["yield_spreads_monotonically"], "the yielded length never shrinks")
    check(max(s["yielded_length_mm"]) > 15.0,
          f"yielding spreads down from the loaded end (to {max(s['yielded_length_mm'])} mm)")
    print(f"increments {s['increments']}, failed attempts {s['attempts_failed']}, iterations "
          f"median {s['iterations_per_increment_median']} max "
          f"{s['iterations_per_increment_max']}, wall {s['wall_time_s']} s")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
