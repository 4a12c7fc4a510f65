#!/usr/bin/python3
"""Mixed control under stress (interlock-history, docs/history-output.md "Bounds"): the hardest
cells of the law run through the point-history program and every case must either complete or
stop with a stated reason, within the documented per-step bounds, without a NaN.

usage: test_history_stress.py PROGRAM OUTDIR

Cells: Table 1 (base); H_N = 1e-6 mm; eta = 0.99999; zeta0 = 1e-6 N/mm (theta 45 -> 5 deg);
all three at once. For each: substepping off and on (substep_tol = 1e-3); the slip (or tangential
traction) history in 1, 2 or 40 steps per segment; two loadings:
  slip:     sigma_N = -0.2 MPa held (traction-driven), s_T 0 -> 0.6 -> -0.6 mm imposed;
  traction: both components traction-driven, sigma_N = -0.2 MPa, sigma_T 0 -> 0.3 -> 0 MPa;
  overload_n, overload_t: sigma_N = 5 MPa (tension above sigma0_n = 3) with slip, or
            sigma_T = 50 MPa at sigma_N = -0.2 MPa: no solution exists, every case must stop;
and both schemes (&sweep over scheme). All decks run in one call of the program.

Checks per case (from the HDF5 file): status is 'completed' (n_rows = n_steps) or
'stopped at step K of N (segment S of M, its step J of L; time T): <reason>' with
K = n_rows + 1 = (steps of the segments before S) + J and a reason of some words; the
datasets iterations and substeps exist with one value per row and
  0 <= iterations <= newton_max_iterations * A,  1 <= substeps <= 100000 * A,
  A = 4 (max_cuts + 1) (max_cuts + 2)  (the attempt limit of one step);
every real dataset is finite; each traction-driven component meets its prescribed value at
every row within newton_tol * max(|target|, sigma0) (an independent check of the solve).
The worst counts are printed.
"""
import os
import re
import subprocess
import sys

import h5py
import numpy as np

NEWTON_MAX_ITERATIONS = 50
MAX_CUTS = 30
ATTEMPTS = 4 * (MAX_CUTS + 1) * (MAX_CUTS + 2)
MAX_LIBRARY_SUBSTEPS = 100000
NEWTON_TOL = 1e-12

CELLS = {
    "base": dict(h_n="1.0", eta="0.9", micro="theta0_deg = 45.0"),
    "hn1e-6": dict(h_n="1e-6", eta="0.9", micro="theta0_deg = 45.0"),
    "eta0.99999": dict(h_n="1.0", eta="0.99999", micro="theta0_deg = 45.0"),
    "zeta1e-6": dict(h_n="1.0", eta="0.9", micro="theta0_deg = 45.0, thetaf_deg = 5.0, zeta0 = 1e-6"),
    "all": dict(h_n="1e-6", eta="0.99999",
                micro="theta0_deg = 45.0, thetaf_deg = 5.0, zeta0 = 1e-6"),
}
LOADINGS = {
    "slip": ("'traction'", "'separation'", [0.0, 1.0, 2.0, 4.0], [0.0, -0.2, -0.2, -0.2],
             [0.0, 0.0, 0.6, -0.6]),
    "traction": ("'traction'", "'traction'", [0.0, 1.0, 2.0, 3.0], [0.0, -0.2, -0.2, -0.2],
                 [0.0, 0.0, 0.3, 0.0]),
    # beyond the strength: sigma_N = 5 MPa > sigma0_n in tension, or sigma_T = 50 MPa: must stop
    "overload_n": ("'traction'", "'separation'", [0.0, 1.0, 2.0], [0.0, 5.0, 5.0], [0.0, 0.0, 0.1]),
    "overload_t": ("'traction'", "'traction'", [0.0, 1.0, 2.0], [0.0, -0.2, -0.2], [0.0, 0.0, 50.0]),
}
SUBSTEP_TOLS = {"nosub": 0.0, "sub": 1e-3}
STEPS = [1, 2, 40]
STATUS_STOPPED = re.compile(r"^stopped at step (\d+) of (\d+) \(segment (\d+) of (\d+), its step "
                            r"(\d+) of (\d+); time ([^)]+)\): (?P<reason>.+)$")


def fmt(values):
    return ", ".join(repr(float(v)) for v in values)


def write_decks(outdir):
    decks = []
    for cell, c in CELLS.items():
        for load, (nc, tc, times, normal, tangential) in LOADINGS.items():
            for sub, tol in SUBSTEP_TOLS.items():
                if load.startswith("overload") and tol > 0:
                    continue   # keep the test fast: the stops are the same with substepping
                for n in STEPS:
                    name = f"stress_{cell}_{load}_{sub}_{n}"
                    steps = [1] + [n] * (len(times) - 2)
                    text = f"""! {name}: written by test_history_stress.py
&interface
  sigma0_n = 3.0, sigma0_t = 3.0, gc = 0.3, eta = {c['eta']}, mu = 0.5, h_n = {c['h_n']}
/
&microplanes
  {c['micro']}
/
&loading
  normal_control = {nc}, tangential_control = {tc}
  times = {fmt(times)}
  normal = {fmt(normal)}
  tangential = {fmt(tangential)}
  steps = {", ".join(str(s) for s in steps)}
/
&solver
  substep_tol = {tol!r}, newton_tol = {NEWTON_TOL!r}
  newton_max_iterations = {NEWTON_MAX_ITERATIONS}, max_cuts = {MAX_CUTS}
/
&sweep
  parameter = 'scheme', values = 1, 2
/
"""
                    path = os.path.join(outdir, name + ".nml")
                    with open(path, "w") as f:
                        f.write(text)
                    decks.append((path, times, normal, tangential, nc, tc))
    return decks


def targets(time, times, values):
    return np.interp(time, times, values)


def check_case(label, g, times, normal, tangential, controls, problems, worst):
    status = str(g.attrs["status"])
    n_rows = int(g.attrs["n_rows"])
    n_steps = int(g.attrs["n_steps"])
    if status == "completed" and "overload" in label:
        problems.append(f"{label}: completed, but no traction history of this loading exists")
    if status == "completed":
        if n_rows != n_steps:
            problems.append(f"{label}: completed with {n_rows} rows for {n_steps} steps")
    else:
        m = STATUS_STOPPED.match(status)
        if not m:
            problems.append(f"{label}: status '{status}' is neither completed nor a stated stop")
        else:
            if int(m.group(1)) != n_rows + 1:
                problems.append(f"{label}: stopped at step {m.group(1)} but {n_rows} rows")
            # The decks' segments: 1 step (the preload), then n steps each.
            seg, j, n = int(m.group(3)), int(m.group(5)), int(m.group(6))
            if int(m.group(1)) != j + (0 if seg == 1 else 1 + (seg - 2) * n):
                problems.append(f"{label}: step {m.group(1)} is not segment {m.group(3)}'s step "
                                f"{m.group(5)}")
            if int(m.group(2)) != n_steps:
                problems.append(f"{label}: stopped at step {m.group(1)} of {m.group(2)}, but "
                                f"n_steps = {n_steps}")
            reason = m.group("reason")
            if len(reason.split()) < 4 or "nan" in reason.lower():
                problems.append(f"{label}: reason '{reason}' is not a stated reason")
            worst["stopped"].append(f"{label}: {status}")
    for name in ("iterations", "substeps"):
        if name not in g:
            problems.append(f"{label}: dataset {name} missing")
            return
        if g[name].shape != (n_rows,):
            problems.append(f"{label}: {name} has shape {g[name].shape}, expected ({n_rows},)")
            return
    it = g["iterations"][()]
    sub = g["substeps"][()]
    if n_rows:
        if it.min() < 0 or it.max() > NEWTON_MAX_ITERATIONS * ATTEMPTS:
            problems.append(f"{label}: iterations {it.min()}..{it.max()} outside "
                            f"0..{NEWTON_MAX_ITERATIONS * ATTEMPTS}")
        if sub.min() < 1 or sub.max() > MAX_LIBRARY_SUBSTEPS * ATTEMPTS:
            problems.append(f"{label}: substeps {sub.min()}..{sub.max()} outside "
                            f"1..{MAX_LIBRARY_SUBSTEPS * ATTEMPTS}")
        for key, arr in (("iterations", it), ("substeps", sub)):
            k = int(np.argmax(arr))
            if arr[k] > worst[key][0]:
                worst[key] = (int(arr[k]), f"{label} row {k}")
    for name, ds in g.items():
        if ds.dtype.kind == "f" and not np.all(np.isfinite(ds[()])):
            problems.append(f"{label}: {name} holds NaN or Inf")
    if n_rows:
        time = g["time"][()]
        traction = g["traction"][()]
        sigma0 = (float(g.attrs["sigma0_n"]), float(g.attrs["sigma0_t"]))
        gc, eta = float(g.attrs["gc"]), float(g.attrs["eta"])
        stiffness = sum(s0 ** 2 / (2 * gc * (1 - eta)) for s0 in sigma0)   # K_n + K_t
        separation = g["separation"][()]
        for i, (driven, values) in enumerate(zip(controls, (normal, tangential))):
            if not driven:
                continue
            target = targets(time, times, values)
            # the documented criterion: newton_tol relative, or (a very stiff interface) the
            # residual the floating-point resolution of s allows, |K| 8 eps |s|
            allowed = np.maximum(NEWTON_TOL * np.maximum(np.abs(target), sigma0[i]),
                                 stiffness * 8 * np.finfo(float).eps * np.abs(separation).sum(axis=1))
            err = np.abs(traction[:, i] - target) / allowed
            if err.max() > 1 + 1e-6:
                k = int(np.argmax(err))
                problems.append(f"{label}: traction {i} misses its target at row {k} by "
                                f"{abs(traction[k, i] - target[k]):.3g} MPa, {err[k]:.3g} times "
                                f"the allowed residual")


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 2
    program, outdir = argv
    os.makedirs(outdir, exist_ok=True)
    for f in os.listdir(outdir):
        if f.startswith("stress_"):
            os.remove(os.path.join(outdir, f))
    decks = write_decks(outdir)
    run = subprocess.run([program, "--output-dir", outdir] + [d[0] for d in decks],
                         capture_output=True, text=True, errors="replace", timeout=600)
    problems = []
    if run.returncode not in (0, 2):
        problems.append(f"exit status {run.returncode} (0 or 2 expected): {run.stderr[-2000:]}")
    for marker in ("Fortran runtime error", "Program received signal", "Backtrace"):
        if marker in run.stderr:
            problems.append(f"stderr holds '{marker}': {run.stderr[-2000:]}")
    worst = {"iterations": (-1, ""), "substeps": (-1, ""), "stopped": []}
    n_cases = 0
    for path, times, normal, tangential, nc, tc in decks:
        h5 = os.path.splitext(path)[0] + ".h5"
        if not os.path.exists(h5):
            problems.append(f"{os.path.basename(h5)} was not written")
            continue
        controls = (nc == "'traction'", tc == "'traction'")
        with h5py.File(h5) as f:
            for case in f["cases"]:
                g = f["cases"][case]
                label = f"{os.path.basename(path)} {str(g.attrs['label'])}"
                check_case(label, g, times, normal, tangential, controls, problems, worst)
                n_cases += 1
    print(f"history stress: {len(decks)} decks, {n_cases} cases, "
          f"{n_cases - len(worst['stopped'])} completed, {len(worst['stopped'])} stopped")
    print(f"  worst iterations per step: {worst['iterations'][0]} ({worst['iterations'][1]})")
    print(f"  worst substeps per step:   {worst['substeps'][0]} ({worst['substeps'][1]})")
    print(f"  bounds: iterations <= {NEWTON_MAX_ITERATIONS * ATTEMPTS}, "
          f"substeps <= {MAX_LIBRARY_SUBSTEPS * ATTEMPTS}")
    for s in worst["stopped"]:
        print("  " + s)
    for p in problems:
        print("[FAIL] " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
