#!/usr/bin/python3
"""`&output every` and `store` of interlock-history (docs/deck-format.md, docs/history-output.md).

usage: test_history_output.py PROGRAM WORK_DIR MODE
  MODE every    A wear scene (Fig. 10 material, theta_f = 7 deg, zeta_0 = 20 N/mm, H_N = 1 mm,
                sigma_N = -2 MPa, 100 slip steps, implicit; two cases: h_n swept), plain and
                extrapolated (&solver extrapolate = .true.), each run with every = 1,
                store = 'all' and with every = 7, store = 'curves': the thinned file holds rows
                0, 7, ..., 98 and 100 (the last), each bitwise equal to the full run's row, no
                per-plane dataset, and its case attributes say every = 7 and which datasets
                were stored; every attribute but every/stored/n_rows equals the full run's.
  list          store = 'Substeps, damage ,zeta' (case and blanks do not matter): exactly time,
                separation, traction, damage, zeta, substeps, bitwise equal to the full run.
  stopped       An overloaded history (tangential traction beyond the capacity; exit status 2)
                with every = 7: the last computed row (the step before the stop) is kept, and
                the rows are the plain run's.
Every file written is also checked with check_history_h5.py (layout contract).
"""
import os
import subprocess
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_history_h5  # noqa: E402

PER_PLANE = ["damage", "beta", "theta", "zeta", "frictional_slip", "friction_traction"]
# The datasets of a 2D case (the decks here are 2D; the strike datasets are 3D only).
ALL = [d for d in check_history_h5.DATASETS if d not in check_history_h5.THREE_D_DATASETS]
CURVES = [d for d in ALL if d not in PER_PLANE]
# Attributes that legitimately differ between a full and a thinned file.
OUTPUT_ATTRS = {"every", "stored", "n_rows"}

WEAR = """&interface
  sigma0_n = 0.025, sigma0_t = 0.025, gc = 0.0005, eta = 0.99, mu = 0.5, h_n = 1.0
/
&microplanes
  theta0_deg = 30.0, thetaf_deg = 7.0, zeta0 = 20.0
/
&loading
  normal_control = 'traction', tangential_control = 'separation'
  times = 0.0, 1.0, 21.0
  normal = 0.0, -2.0, -2.0
  tangential = 0.0, 0.0, 20.0
  steps = 1, 100
/
&solver
  scheme = 'implicit', extrapolate = {extrapolate}
/
&sweep
  parameter = 'h_n'
  values = 1.0, 0.5
/
"""
STOPPED = """&interface
  sigma0_n = 3.0, sigma0_t = 3.0, gc = 0.3, eta = 0.9, mu = 0.5, h_n = 1.0
/
&microplanes
  theta0_deg = 45.0
/
&loading
  normal_control = 'traction', tangential_control = 'traction'
  times = 0.0, 1.0, 2.0
  normal = 0.0, -0.2, -0.2
  tangential = 0.0, 0.0, 6.0
  steps = 1, 20
/
&solver
  scheme = 'implicit'
/
"""

failures = 0


def check(ok, what):
    global failures
    print(f"[{' ok ' if ok else 'FAIL'}] {what}")
    if not ok:
        failures += 1
    return ok


def text(v):
    return v.decode() if isinstance(v, (bytes, np.bytes_)) else str(v)


def run(program, work, name, deck, expect_rc=0):
    """Write the deck, run it, check the layout; the file's cases as dicts (attrs, datasets)."""
    path = os.path.join(work, name + ".nml")
    with open(path, "w") as f:
        f.write(deck)
    h5 = os.path.join(work, name + ".h5")
    if os.path.exists(h5):
        os.remove(h5)
    r = subprocess.run([program, "--output-dir", work, path], capture_output=True, text=True,
                       timeout=120)
    if not check(r.returncode == expect_rc, f"{name}: exit status {r.returncode} "
                 f"(expected {expect_rc}) {r.stderr.strip()[:300]}"):
        return None
    errors = check_history_h5.check_file(h5, allow_stopped=expect_rc == 2)
    check(not errors, f"{name}: layout contract (check_history_h5.py) {errors[:3]}")
    cases = []
    with h5py.File(h5, "r") as f:
        for c in sorted(f["cases"]):
            g = f["cases"][c]
            cases.append(({k: g.attrs[k] for k in g.attrs}, {d: g[d][()] for d in g}))
    return cases


def same_attrs(a, b):
    keys = (set(a) | set(b)) - OUTPUT_ATTRS
    return all(k in a and k in b and np.array_equal(np.asarray(a[k]), np.asarray(b[k])) for k in keys)


def compare(name, full, thin, every, stored):
    """thin = full at the kept rows, bitwise, holding exactly `stored`."""
    for i, ((fa, fd), (ta, td)) in enumerate(zip(full, thin)):
        where = f"{name} case {i + 1}"
        n_full = int(fa["n_rows"])
        rows = check_history_h5.kept_rows(n_full, every)
        check(int(ta["every"]) == every and int(fa["every"]) == 1,
              f"{where}: every = {int(ta['every'])} (full run: {int(fa['every'])})")
        check(text(ta["stored"]).split(",") == stored,
              f"{where}: stored = '{text(ta['stored'])}'")
        check(text(fa["stored"]).split(",") == ALL, f"{where}: the full run stored every dataset")
        check(sorted(td) == sorted(stored), f"{where}: datasets {sorted(td)}")
        check(int(ta["n_rows"]) == len(rows) and rows[-1] == n_full - 1,
              f"{where}: {int(ta['n_rows'])} rows = {rows[:3]} ... {rows[-2:]} of {n_full}")
        check(all(np.array_equal(td[d], fd[d][rows]) for d in stored if d in td),
              f"{where}: every kept row equals the full run's row, bitwise")
        check(same_attrs(fa, ta), f"{where}: every other case attribute is the full run's")
    check(len(full) == len(thin) > 0, f"{name}: {len(thin)} cases")


def mode_every(program, work):
    for extrapolate in (".false.", ".true."):
        base = WEAR.format(extrapolate=extrapolate)
        tag = "x" if extrapolate == ".true." else "p"
        full = run(program, work, f"every1_{tag}", base)
        thin = run(program, work, f"every7_{tag}", base + "&output\n  every = 7, store = 'curves'\n/\n")
        if full and thin:
            compare(f"every = 7, store = 'curves', extrapolate = {extrapolate}", full, thin, 7, CURVES)
            check(not any(d in thin[0][1] for d in PER_PLANE), "no per-plane dataset")
            check(int(full[0][0]["n_rows"]) == 101 and int(thin[0][0]["n_rows"]) == 16,
                  "101 rows computed, 16 written (rows 0, 7, ..., 98 and 100)")


def mode_list(program, work):
    base = WEAR.format(extrapolate=".false.")
    full = run(program, work, "list_full", base)
    thin = run(program, work, "list_some", base + "&output\n  store = 'Substeps, damage ,zeta'\n/\n")
    if full and thin:
        compare("store = 'Substeps, damage ,zeta'", full, thin, 1,
                ["time", "separation", "traction", "damage", "zeta", "substeps"])


def mode_stopped(program, work):
    full = run(program, work, "stopped_full", STOPPED, expect_rc=2)
    thin = run(program, work, "stopped_every7", STOPPED + "&output\n  every = 7\n/\n", expect_rc=2)
    if full and thin:
        n = int(full[0][0]["n_rows"])
        check(n > 1 and (n - 1) % 7 != 0, f"the plain run stops after {n} rows (not a multiple of 7 + 1)")
        check(text(thin[0][0]["status"]) == text(full[0][0]["status"])
              and text(thin[0][0]["status"]).startswith("stopped at step"),
              f"same status: {text(thin[0][0]['status'])[:80]}")
        compare("stopped, every = 7", full, thin, 7, ALL)


def main(argv):
    modes = {"every": mode_every, "list": mode_list, "stopped": mode_stopped}
    if len(argv) != 3 or argv[2] not in modes:
        print(__doc__)
        return 2
    program, work, mode = argv
    os.makedirs(work, exist_ok=True)
    modes[mode](program, work)
    print(f"history_output {mode}: {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
