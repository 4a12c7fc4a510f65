#!/usr/bin/python3
"""interlock-history in three dimensions (SPEC section 9, docs/deck-format.md).

usage: test_history_3d.py PROGRAM DATA_DIR WORK_DIR MODE

MODE
  reference    the histories of tests/data/reference3d (granite, `paper` and `azimuthal`
               N_a = 3, sigma_N = -1.5 MPa after the preload step: straight 5 mm at 0, 30, 45
               and 90 deg, the square of side 2 mm, two turns of the circle of radius 2 mm; the
               implicit and trapezoidal schemes, the stored step counts) are reproduced by decks
               with the same protocol: every column within 1e-10 of the largest value of its
               quantity (separation, traction, and D, theta, zeta over all planes; the files
               carry 12 digits; the reference's README: the same scheme and steps agree to
               round-off). mu = tan(34.6 deg) to all digits, as the reference computes it.
  circle       constant sigma_N = -1.5 MPa on two turns of a circle of radius 2 mm (paper and
               azimuthal RIA, both schemes): the case completes, ends at (r, 0) on the circle
               and sigma_N equals -1.5 MPa at every step within the solver's tolerance
               (newton_tol 1e-12 times 1.5 MPa).
  reduction    a 3D deck with every azimuth 0 (phi_deg = 0) and T2 separation-driven at 0
               (or, with both in-plane components traction-driven, T2 traction-driven at 0:
               Newton on all three components) reproduces the 2D deck's history (separation,
               traction, every per-plane dataset) within 1e-14 of each dataset's largest value,
               with sigma_T2, sf_strike and tauf_strike exactly 0; paper RIA with wear, a
               general RIA, the implicit and trapezoidal schemes.
  sweep        the shipped direction sweeps (inputs/granite_3d_sweep_{paper,az2,az3,az6}.nml)
               against the figures of SPEC section 9's independent implementation (granite,
               sigma_N = -1.5 MPa): paper peak shear 2.89 MPa along t1 and 1.13 MPa along t2
               (+-0.01 MPa: 3 digits quoted), a traction across the slip up to 0.75 MPa at 45 deg
               (+-0.01), and the spread of the peak over the directions, (max - min) / max,
               about 4 %, 7 % and 1.6 % at N_a = 2, 3, 6 (+-0.5, +-0.5 and +-0.2 points: the
               quoted digits); the spread falls from N_a = 3 to 6.
  scenes       the figures docs/three-dimensions.md quotes from the shipped decks, around the
               physics they show: on the second turn of granite_3d_circle the traction lags the
               slip direction (> 0) by 17 to 26 deg (16.5..26.5; the range SPEC section 9
               quotes); as a regression guard of the page (our own numbers), after
               granite_3d_anisotropy's
               3 mm along t1 and back the peak along t2 is lower than the virgin joint's
               (granite_3d_anisotropy_virgin) by more than 10 %: 2.11 against 2.47 MPa (+-0.005).
  restart      a 3D history restarted from one of its rows (&initial_state with every per-plane
               dataset, the strike components sf_strike and tauf_strike, and the three
               separations and tractions, as a replay deck gives them) continues it: the rows
               after agree within 1e-12 of each dataset's largest value (the restart's path
               points are rounded differently); restarted without the strike components it
               does not (> 1e-3): they are read and they matter.
  ria_sweep    a &sweep over `ria` (0, 1) and one over `n_azimuths` (1, 2, 6) give each case
               the history (every dataset, bitwise) and the attributes ria, n_azimuths and
               n_planes of the deck that names that RIA in &microplanes (granite, straight
               slip under -1.5 MPa): the cases differ from each other.
  layout       a 2D deck's HDF5 layout (datasets, shapes, dtypes, chunks, attributes with their
               values) is the stored one (tests/data/layout, written by the program before it
               knew three dimensions).
"""
import math
import os
import subprocess
import sys

import h5py
import numpy as np

MU = repr(math.tan(math.radians(34.6)))
GRANITE = (f"&interface\n  sigma0_n = 0.025, sigma0_t = 0.025, gc = 0.0005, eta = 0.99, "
           f"mu = {MU}, h_n = 4.0\n/\n")


def microplanes(ria):
    extra = "" if ria == "paper" else ", n_azimuths = 3"
    return f"&microplanes\n  theta0_deg = 30.0, thetaf_deg = 9.0, zeta0 = 6.666{extra}\n/\n"


def run(program, deck_path, text, work):
    with open(deck_path, "w") as f:
        f.write(text)
    out = subprocess.run([program, "--output-dir", work, deck_path], capture_output=True,
                         text=True, timeout=600)
    if out.returncode != 0:
        raise RuntimeError(f"{deck_path}: exit {out.returncode}: {out.stderr}{out.stdout}")
    return os.path.join(work, os.path.splitext(os.path.basename(deck_path))[0] + ".h5")


def read_csv(path):
    with open(path) as f:
        f.readline()
        header = f.readline().strip().split(",")
    return header, np.loadtxt(path, delimiter=",", skiprows=2, ndmin=2)


def history_columns(g, steps):
    """The reference's columns from a case: step, s (3), sigma (3), then D, theta [deg], zeta
    per plane."""
    cols = [steps.astype(float)]
    sep, tr = g["separation"][()], g["traction"][()]
    cols += [sep[steps, j] for j in range(3)] + [tr[steps, j] for j in range(3)]
    d, th, ze = g["damage"][()], g["theta"][()], g["zeta"][()]
    for k in range(d.shape[1]):
        cols += [d[steps, k], np.degrees(th[steps, k]), ze[steps, k]]
    return np.column_stack(cols)


def group_scales(header, ref):
    """The scale of each column: the largest absolute value of its quantity (separation,
    traction, and each per-plane quantity over all planes), so that a component that is zero by
    symmetry (sigma_T1 on slip along t2) is measured against the traction, not its round-off."""
    def quantity(name):
        if name.startswith("sigma_"):
            return "sigma"
        if name.startswith("s_"):
            return "s"
        return name.split("_")[0]
    groups = [quantity(h) for h in header]
    scales = []
    for j, q in enumerate(groups):
        cols = [i for i, g in enumerate(groups) if g == q]
        scales.append(max(np.max(np.abs(ref[:, cols])), 1e-300))
    return scales


def mode_reference(program, data, work):
    failures = 0
    scenes = [("straight", "path = 'straight', length = 5.0", "1, 2000", (0, 30, 45, 90)),
              ("square", "path = 'square', side = 2.0", "1, 500, 500, 500, 500", None),
              ("circle", "path = 'circle', radius = 2.0, turns = 2", "1, 250, 2000", None)]
    for ria, tag in (("paper", "paper"), ("azimuthal", "az3")):
        for scheme in ("implicit", "trapezoidal"):
            for kind, path, steps, angles in scenes:
                deck = (GRANITE + microplanes(ria) +
                        f"&loading\n  normal_control = 'traction', normal = -1.5\n  {path}\n"
                        f"  steps = {steps}\n/\n&solver\n  scheme = '{scheme}'\n/\n")
                if angles:
                    deck += ("&sweep\n  parameter = 'angle_deg', values = " +
                             ", ".join(str(a) for a in angles) + "\n/\n")
                h5 = run(program, os.path.join(work, f"granite_{tag}_{kind}_{scheme}.nml"), deck, work)
                with h5py.File(h5, "r") as f:
                    for icase, angle in enumerate(angles or (None,), start=1):
                        name = f"granite_{tag}_{kind}" + (f"{angle:02d}" if angle is not None else "")
                        header, ref = read_csv(os.path.join(data, "reference3d", f"{name}_{scheme}.csv"))
                        g = f["cases"][f"{icase:04d}"]
                        steps_ref = ref[:, 0].astype(int)
                        got = history_columns(g, steps_ref)
                        if got.shape != ref.shape:
                            print(f"FAIL {name} {scheme}: columns {got.shape} against {ref.shape}")
                            failures += 1
                            continue
                        worst, where = 0.0, ""
                        scales = group_scales(header, ref)
                        for j in range(1, ref.shape[1]):
                            err = np.max(np.abs(got[:, j] - ref[:, j])) / scales[j]
                            if err > worst:
                                worst, where = err, header[j]
                        ok = worst <= 1.0e-10
                        failures += not ok
                        print(f"{'ok  ' if ok else 'FAIL'} {name} {scheme}: largest difference "
                              f"{worst:.2e} of its quantity's largest value ({where}); "
                              f"{g['separation'].shape[0]} rows")
    return failures


def mode_circle(program, work):
    failures = 0
    for ria in ("paper", "azimuthal"):
        for scheme in ("implicit", "trapezoidal"):
            deck = (GRANITE + microplanes(ria) +
                    "&loading\n  normal_control = 'traction', normal = -1.5\n"
                    "  path = 'circle', radius = 2.0, turns = 2\n  steps = 1, 100, 800\n/\n"
                    f"&solver\n  scheme = '{scheme}', newton_tol = 1e-12\n/\n")
            h5 = run(program, os.path.join(work, f"circle_{ria}_{scheme}.nml"), deck, work)
            with h5py.File(h5, "r") as f:
                g = f["cases"]["0001"]
                status = g.attrs["status"]
                sep, tr = g["separation"][()], g["traction"][()]
                n = sep.shape[0]
                off = np.max(np.abs(tr[:, 0] + 1.5))
                end = math.hypot(sep[-1, 1] - 2.0, sep[-1, 2])
                radius = np.max(np.abs(np.hypot(sep[101:, 1], sep[101:, 2]) - 2.0))
                ok = (status == "completed" and n == 901 and off <= 1.0e-12 * 1.5 and
                      end <= 1e-12 and radius <= 1e-12 and sep.shape[1] == 3)
                failures += not ok
                print(f"{'ok  ' if ok else 'FAIL'} circle {ria} {scheme}: {status}, {n} rows, "
                      f"max |sigma_N + 1.5| = {off:.1e} MPa, end point off (2, 0) by {end:.1e} mm, "
                      f"off the circle by at most {radius:.1e} mm; sigma_T2 up to "
                      f"{np.max(np.abs(tr[:, 2])):.3f} MPa")
    return failures


def mode_reduction(program, work):
    failures = 0
    loadings = {
        "mixed": ("normal_control = 'traction', tangential_control = 'separation'\n"
                  "  times = 0, 1, 3, 4\n  normal = 0, -1.5, -1.5, -1.0\n"
                  "  tangential = 0, 0, 2.0, 0.5\n  steps = 1, 400, 200"),
        "traction": ("normal_control = 'traction', tangential_control = 'traction'\n"
                     "  times = 0, 1, 2\n  normal = 0, -1.5, -1.5\n  tangential = 0, 0, 0.5\n"
                     "  steps = 1, 100"),
    }
    # T2 separation-driven at 0, and (all three components driven) traction-driven at 0
    t2_controls = {"mixed": "separation", "traction": "traction"}
    rias = {
        "paper": ("theta0_deg = 30.0, thetaf_deg = 9.0, zeta0 = 6.666",
                  "n_planes = 3, gamma_hat = 0.3333333333333333, 0.3333333333333333, "
                  "0.3333333333333334, theta0_deg = -30, 0, 30, thetaf_deg = -9, 0, 9, "
                  "zeta0 = 6.666, 1e30, 6.666"),
        "general": ("n_planes = 2, gamma_hat = 0.4, 0.6, theta0_deg = -20, 35, "
                    "thetaf_deg = -5, 10, zeta0 = 3, 8",) * 2,
    }
    for ria, (plain, general) in rias.items():
        for lname, loading in loadings.items():
            for scheme in ("implicit", "trapezoidal"):
                d2 = (GRANITE + f"&microplanes\n  {general}\n/\n&loading\n  {loading}\n/\n"
                      f"&solver\n  scheme = '{scheme}'\n/\n")
                n_planes = general.split("n_planes = ")[1].split(",")[0]
                zeros = ", ".join(["0"] * int(n_planes))
                n_points = loading.split("times = ")[1].split("\n")[0].count(",") + 1
                t2 = ", ".join(["0"] * n_points)
                d3 = (GRANITE + f"&microplanes\n  {general}, phi_deg = {zeros}\n/\n"
                      f"&loading\n  {loading}\n  t2_control = '{t2_controls[lname]}', t2 = {t2}\n/\n"
                      f"&solver\n  scheme = '{scheme}'\n/\n")
                tag = f"{ria}_{lname}_{scheme}"
                h2 = run(program, os.path.join(work, f"red2d_{tag}.nml"), d2, work)
                h3 = run(program, os.path.join(work, f"red3d_{tag}.nml"), d3, work)
                worst, where, exact = 0.0, "", True
                with h5py.File(h2, "r") as f2, h5py.File(h3, "r") as f3:
                    g2, g3 = f2["cases"]["0001"], f3["cases"]["0001"]
                    if g3["separation"].shape[1] != 3 or g2["separation"].shape[1] != 2:
                        print(f"FAIL {tag}: separation columns {g2['separation'].shape}, "
                              f"{g3['separation'].shape}")
                        failures += 1
                        continue
                    for name in g2:
                        a = g2[name][()]
                        b = g3[name][()]
                        if name in ("separation", "traction"):
                            exact = exact and np.all(b[:, 2] == 0.0)
                            b = b[:, :2]
                        if name in ("iterations", "substeps"):
                            continue
                        scale = max(np.max(np.abs(a)), 1e-300)
                        err = np.max(np.abs(a - b)) / scale if a.shape == b.shape else np.inf
                        if err > worst:
                            worst, where = err, name
                    exact = exact and np.all(g3["sf_strike"][()] == 0.0) and \
                        np.all(g3["tauf_strike"][()] == 0.0)
                ok = worst <= 1.0e-14 and exact
                failures += not ok
                print(f"{'ok  ' if ok else 'FAIL'} {tag}: 3D against 2D, largest difference "
                      f"{worst:.1e} of the dataset's largest value ({where or '-'}); sigma_T2, "
                      f"sf_strike, tauf_strike exactly 0: {exact}")
    return failures


def sweep_peaks(h5):
    """[(angle_deg, peak |sigma_T|, peak |traction across the slip|)] of a direction sweep."""
    rows = []
    with h5py.File(h5, "r") as f:
        for name in sorted(f["cases"]):
            g = f["cases"][name]
            a = float(g.attrs["sweep_value"])
            tr = g["traction"][()]
            across = -math.sin(math.radians(a)) * tr[:, 1] + math.cos(math.radians(a)) * tr[:, 2]
            rows.append((a, float(np.max(np.hypot(tr[:, 1], tr[:, 2]))),
                         float(np.max(np.abs(across)))))
    return rows


def mode_sweep(program, work):
    inputs = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "inputs")
    failures = 0

    def check(ok, text):
        nonlocal failures
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {text}")

    spreads = {}
    for ria, quoted, tol in (("paper", None, None), ("az2", 4.0, 0.5), ("az3", 7.0, 0.5),
                             ("az6", 1.6, 0.2)):
        deck = os.path.join(inputs, f"granite_3d_sweep_{ria}.nml")
        with open(deck) as f:
            h5 = run(program, os.path.join(work, os.path.basename(deck)), f.read(), work)
        rows = sweep_peaks(h5)
        peaks = [r[1] for r in rows]
        spread = 100.0 * (max(peaks) - min(peaks)) / max(peaks)
        spreads[ria] = spread
        print(f"     {ria}: {len(rows)} directions, peak {min(peaks):.3f}..{max(peaks):.3f} MPa, "
              f"spread {spread:.2f} %")
        if ria == "paper":
            by_angle = {round(r[0], 6): r for r in rows}
            check(abs(by_angle[0.0][1] - 2.89) <= 0.01,
                  f"paper: peak along t1 {by_angle[0.0][1]:.4f} MPa (2.89)")
            check(abs(by_angle[90.0][1] - 1.13) <= 0.01,
                  f"paper: peak along t2 {by_angle[90.0][1]:.4f} MPa (1.13)")
            check(abs(by_angle[45.0][2] - 0.75) <= 0.01,
                  f"paper: traction across the slip at 45 deg up to {by_angle[45.0][2]:.4f} MPa "
                  f"(0.75)")
        else:
            check(abs(spread - quoted) <= tol,
                  f"{ria}: spread {spread:.2f} % ({quoted} +- {tol})")
    check(spreads["az6"] < spreads["az3"], "the spread falls from N_a = 3 to 6")
    return failures


def mode_scenes(program, work):
    inputs = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "inputs")
    failures = 0

    def shipped(name):
        with open(os.path.join(inputs, name + ".nml")) as f:
            h5 = run(program, os.path.join(work, name + ".nml"), f.read(), work)
        with h5py.File(h5, "r") as f:
            g = f["cases"]["0001"]
            return g["separation"][()], g["traction"][()]

    sep, tr = shipped("granite_3d_circle")
    slip = np.diff(sep[:, 1:3], axis=0)
    lag = np.degrees((np.arctan2(slip[:, 1], slip[:, 0]) - np.arctan2(tr[1:, 2], tr[1:, 1]) +
                      np.pi) % (2 * np.pi) - np.pi)
    second = lag[1 + 250 + 1000 - 1:]   # the deck's steps: preload, the leg out, two turns
    ok = len(second) == 1000 and second.min() > 16.5 and second.max() < 26.5
    failures += not ok
    print(f"{'ok  ' if ok else 'FAIL'} circle, second turn: the traction lags the slip direction "
          f"by {second.min():.1f} to {second.max():.1f} deg (docs: 17 to 26)")
    _, worn = shipped("granite_3d_anisotropy")
    _, virgin = shipped("granite_3d_anisotropy_virgin")
    peak_worn = float(np.max(np.abs(worn[-600:, 2])))   # the last leg: 3 mm along t2
    peak_virgin = float(np.max(np.abs(virgin[:, 2])))
    ok = (peak_worn < 0.9 * peak_virgin and abs(peak_worn - 2.11) <= 0.005 and
          abs(peak_virgin - 2.47) <= 0.005)
    failures += not ok
    print(f"{'ok  ' if ok else 'FAIL'} induced anisotropy: peak along t2 {peak_worn:.4f} MPa "
          f"after 3 mm along t1 and back, {peak_virgin:.4f} MPa virgin (docs: 2.11, 2.47)")
    return failures


RESTART_PLANES = ("damage", "beta", "frictional_slip", "zeta", "theta", "friction_traction",
                  "sf_strike", "tauf_strike")


def mode_restart(program, work):
    granite = ("&interface\n  sigma0_n = 0.025, sigma0_t = 0.025, gc = 0.0005, eta = 0.99, "
               "mu = 0.6898538, h_n = 4.0\n/\n&microplanes\n  theta0_deg = 30.0, "
               "thetaf_deg = 9.0, zeta0 = 6.666, n_azimuths = 3\n/\n&output\n  store = 'all'\n/\n")
    control = ("  normal_control = 'traction', tangential_control = 'separation', "
               "t2_control = 'separation'\n")
    deck = (granite + "&loading\n" + control + "  times = 0.0, 1.0, 2.0\n"
            "  normal = 0.0, -1.5, -1.5\n  tangential = 0.0, 0.0, 0.8\n  t2 = 0.0, 0.0, 0.5\n"
            "  steps = 1, 40\n/\n")
    h5 = run(program, os.path.join(work, "restart_whole.nml"), deck, work)
    with h5py.File(h5, "r") as f:
        g = f["cases"]["0001"]
        whole = {k: g[k][()] for k in RESTART_PLANES + ("separation", "traction")}
    k = 20   # the row after step 21: halfway along the oblique segment
    failures = 0
    for with_strike in (True, False):
        lines = []
        for name in RESTART_PLANES:
            values = whole[name][k] if with_strike or "strike" not in name else 0 * whole[name][k]
            lines.append(f"  {name} = " + ", ".join(repr(float(v)) for v in values))
        for name in ("separation", "traction"):
            lines.append(f"  {name} = " + ", ".join(repr(float(v)) for v in whole[name][k]))
        sep = whole["separation"][k]
        deck = (granite + "&initial_state\n" + "\n".join(lines) + "\n/\n&loading\n" + control +
                "  times = 0.0, 1.0\n  normal = -1.5, -1.5\n"
                f"  tangential = {float(sep[1])!r}, 0.8\n  t2 = {float(sep[2])!r}, 0.5\n"
                "  steps = 20\n/\n")
        name = "restart_part" if with_strike else "restart_part_no_strike"
        h5 = run(program, os.path.join(work, name + ".nml"), deck, work)
        worst = 0.0
        with h5py.File(h5, "r") as f:
            g = f["cases"]["0001"]
            for q in RESTART_PLANES + ("separation", "traction"):
                a, b = g[q][()], whole[q][k + 1:]
                scale = max(np.max(np.abs(whole[q])), 1e-300)
                worst = max(worst, float(np.max(np.abs(a - b))) / scale)
        ok = worst <= 1e-12 if with_strike else worst > 1e-3
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} restart from row {k + 1} "
              f"{'with' if with_strike else 'without'} the strike components: rows after "
              f"within {worst:.1e} of each dataset's largest value "
              f"({'<= 1e-12' if with_strike else '> 1e-3: they matter'})")
    return failures


def mode_layout(program, data, work):
    failures = 0
    folder = os.path.join(data, "layout")
    layout = os.path.join(os.path.dirname(os.path.abspath(__file__)), "h5_layout.py")
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".nml"):
            continue
        deck = os.path.join(folder, name)
        out = subprocess.run([program, "--output-dir", work, deck], capture_output=True,
                             text=True, timeout=600)
        if out.returncode != 0:
            print(f"FAIL {name}: exit {out.returncode}: {out.stderr}")
            failures += 1
            continue
        h5 = os.path.join(work, name[:-4] + ".h5")
        cmp = subprocess.run([sys.executable, layout, h5, "--compare",
                              os.path.join(folder, name[:-4] + ".txt")], capture_output=True,
                             text=True)
        print(("ok   " if cmp.returncode == 0 else "FAIL ") + cmp.stdout.strip())
        failures += cmp.returncode != 0
    return failures


def mode_ria_sweep(program, work):
    failures = 0

    def check(ok, text):
        nonlocal failures
        failures += not ok
        print(f"{'ok  ' if ok else 'FAIL'} {text}")

    loading = ("&loading\n  normal_control = 'traction', normal = -1.5\n  path = 'straight', "
               "length = 1.0\n  steps = 1, 20\n/\n")
    base = GRANITE + "&microplanes\n  theta0_deg = 30.0, thetaf_deg = 9.0, zeta0 = 6.666{}\n/\n"

    def single(n_azimuths):
        extra = "" if n_azimuths == 0 else f", n_azimuths = {n_azimuths}"
        name = os.path.join(work, f"ria_single_{n_azimuths}.nml")
        return run(program, name, base.format(extra) + loading, work)

    sweeps = (("ria", "0, 1", [0, 3]), ("n_azimuths", "1, 2, 6", [1, 2, 6]))
    for parameter, values, azimuths in sweeps:
        text = base.format("") + loading + f"&sweep\n  parameter = '{parameter}', values = {values}\n/\n"
        h5 = run(program, os.path.join(work, f"ria_sweep_{parameter}.nml"), text, work)
        with h5py.File(h5) as f:
            cases = [f["cases"][c] for c in sorted(f["cases"])]
            check(len(cases) == len(azimuths), f"{parameter}: {len(cases)} cases")
            finals = []
            for case, n_azimuths in zip(cases, azimuths):
                with h5py.File(single(n_azimuths)) as r:
                    ref = r["cases"]["0001"]
                    for a in ("ria", "n_azimuths", "n_planes"):
                        check(case.attrs[a] == ref.attrs[a],
                              f"{parameter} case {case.attrs['label']}: {a} = {case.attrs[a]} "
                              f"({ref.attrs[a]})")
                    same = all(np.array_equal(case[k][()], ref[k][()]) for k in ref)
                    check(same and set(case) == set(ref),
                          f"{parameter} case {case.attrs['label']}: every dataset bitwise the "
                          f"deck's with n_azimuths = {n_azimuths}")
                finals.append(case["traction"][-1, 1])
            check(len(set(finals)) == len(finals),
                  f"{parameter}: the cases differ (final sigma_T1 {finals})")
    return failures


def main(argv):
    if len(argv) != 4:
        print(__doc__)
        return 2
    program, data, work, mode = argv
    os.makedirs(work, exist_ok=True)
    if mode == "reference":
        failures = mode_reference(program, data, work)
    elif mode == "circle":
        failures = mode_circle(program, work)
    elif mode == "reduction":
        failures = mode_reduction(program, work)
    elif mode == "layout":
        failures = mode_layout(program, data, work)
    elif mode == "sweep":
        failures = mode_sweep(program, work)
    elif mode == "restart":
        failures = mode_restart(program, work)
    elif mode == "scenes":
        failures = mode_scenes(program, work)
    elif mode == "ria_sweep":
        failures = mode_ria_sweep(program, work)
    else:
        print(__doc__)
        return 2
    print("FAILED" if failures else "passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
