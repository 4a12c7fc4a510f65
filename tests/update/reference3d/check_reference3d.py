"""Validates the 3D reference implementation (interlock3d_ref.py) and its data.

    /usr/bin/python3 tests/update/reference3d/check_reference3d.py [--full]

1. 2D reduction: phi = 0, s_T2 = 0 reproduces the shipped 2D reference curves
   (tests/data/reference: an independent 2D implementation) with the same scheme and step
   count to the CSV's 12 digits; sigma_T2, sf_2, tauf_2 exactly 0 (pre-fractured and D7 too).
2. Section 9's properties: flat-RIA rotation invariance, pi/N_a symmetry of `azimuthal`, the
   azimuth mapping, energy balance and monotone friction dissipation on a 3D path, the closed
   form of a debonded flat interface, the strike stiffness of a sliding plane.
3. The directional figures quoted for the 3D law (granite, sigma_N = -1.5 MPa), which another
   implementation of section 9 gave.
4. The stored data (tests/data/reference3d): a subset re-generated and compared.
--full runs the long versions (whole 2D curves, the peak spread for N_a = 2, 3, 6, 12, the
circular-path lag at a fine step) and re-generates every stored file.
"""

import json
import math
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import interlock3d_ref as R  # noqa: E402
import make_reference3d as M  # noqa: E402

REF2D = os.path.normpath(os.path.join(HERE, "..", "..", "data", "reference"))
FAILURES = []


def report(name, ok, detail):
    print("%-4s %s: %s" % ("ok" if ok else "FAIL", name, detail), flush=True)
    if not ok:
        FAILURES.append(name)


def rel_max(a, b):
    """Largest difference relative to the largest magnitude of b (per column if 2D)."""
    a, b = np.asarray(a), np.asarray(b)
    scale = np.abs(b).max(axis=0)
    scale = np.where(scale == 0.0, 1.0, scale)
    return np.abs(a - b).max(axis=0) / scale


# ----------------------------------------------------------------------------------------------
# 1. 2D reduction
# ----------------------------------------------------------------------------------------------
def load_2d(fig, case, explicit):
    meta = json.load(open(os.path.join(REF2D, fig, "meta.json")))
    c = [c for c in meta["cases"] if c["case"] == case][0]
    fn = os.path.join(REF2D, fig, case + ("_explicit" if explicit else "") + ".csv")
    with open(fn) as f:
        head = f.readline().strip().split(",")
        data = np.array([[float(x) for x in line.split(",")] for line in f if line.strip()])
    return meta, c, head, data


def material_2d(params):
    def val(v):
        return math.inf if v == "inf" else float(v)
    planes = R.ria_paper(math.radians(params["theta0_deg"]), math.radians(params["thetaf_deg"]),
                         val(params["zeta0"]))
    return R.Material(params["sigma0_n"], params["sigma0_t"], params["Gc_bar"], params["eta"],
                      params["mu"], val(params["H_N"]), planes)


def run_2d(fig, case, scheme, max_steps=None, ref_explicit=None):
    """Run the scene of a 2D reference case through the 3D law; compare with the stored curve
    (the explicit file for the explicit scheme, else the implicit one)."""
    explicit = scheme == "explicit" if ref_explicit is None else ref_explicit
    meta, c, head, data = load_2d(fig, case, explicit)
    mat = material_2d(c["params"])
    n, every, t_end = c["n_steps"], c["rows_in_this_copy_every_n_steps"], meta["load"]["t_end"]
    n_run = n if max_steps is None else min(n, max_steps)
    path = [(t_end * i / n, 0.0) for i in range(n_run + 1)]
    t0 = time.time()
    rows = R.run_history(mat, path, scheme, sigma_N=meta["sigma_N"], store_every=every)
    mine, zero = [], 0.0
    for r in rows:
        v = [r.time, r.s[0], r.s[1], r.sigma[0], r.sigma[1]]
        for st in r.states:
            v += [st.D, math.degrees(st.theta), st.zeta, st.sf1]
            zero = max(zero, abs(st.sf2), abs(st.tauf2))
        zero = max(zero, abs(r.sigma[2]), abs(r.s[2]))
        mine.append(v)
    mine = np.array(mine)
    if n_run % every:
        mine = mine[:-1]
    err = rel_max(mine, data[:len(mine)])
    return err, head, zero, n_run, n, time.time() - t0


def check_2d(full):
    print("== 1. 2D reduction (phi = 0, s_T2 = 0) against tests/data/reference")
    cases = [("fig5", "HN_0.5", "explicit", None), ("fig5", "HN_0.5", "implicit", 1200),
             ("fig9", "theta0_15", "explicit", 2000), ("fig9", "theta0_15", "implicit", 400),
             ("fig11", "zeta0_10000", "explicit", 2000), ("fig11", "zeta0_10000", "implicit", 300)]
    if full:
        cases = [(f, c, s, None) for (f, c, s, _) in cases] + [
            ("fig11", "zeta0_100", "implicit", None), ("fig10", "thetaf_7", "explicit", None),
            ("fig8_long", "eta_0.7", "implicit", None), ("fig7", "theta_0", "implicit", None),
            ("fig6", "HN_inf", "explicit", None)]
    for fig, case, scheme, cap in cases:
        err, head, zero, n_run, n, sec = run_2d(fig, case, scheme, cap)
        worst = int(np.argmax(err))
        report("2D %s %s %s" % (fig, case, scheme), err.max() < 1e-10 and zero == 0.0,
               "%d of %d steps, largest difference %.1e of the column's largest value (%s),"
               " T2 parts %g (%.1f s)" % (n_run, n, err.max(), head[worst], zero, sec))
    # No wear: the trapezoidal scheme's traction and state (zeta aside: its wear driver is
    # another rule) equal the implicit curve's
    err, head, zero, n_run, n, sec = run_2d("fig5", "HN_0.5", "trapezoidal",
                                            None if full else 1200, False)
    keep = [i for i, h in enumerate(head) if not h.startswith("zeta")]
    report("2D fig5 HN_0.5 trapezoidal (no wear)", err[keep].max() < 1e-10 and zero == 0.0,
           "largest difference %.1e (zeta excluded) (%.1f s)" % (err[keep].max(), sec))
    # With wear: the trapezoidal scheme at the reference's step against the implicit curve,
    # whose traction and dilation are converged to ~1e-4 (its per-plane zeta is not: the
    # trailing plane's zeta_3 is 2.3 % below the converged value at 6400 steps, which the
    # trapezoidal scheme reaches to 1e-5 at that step)
    err, head, zero, n_run, n, sec = run_2d("fig9", "theta0_15", "trapezoidal",
                                            None if full else 400, False)
    keep = [head.index(h) for h in ("s_N", "sigma_T", "theta_1", "theta_3")]
    report("2D fig9 theta0_15 trapezoidal vs implicit reference", err[keep].max() < 3e-4,
           "%d of %d steps, s_N, sigma_T, theta: largest difference %.1e; zeta_3 %.1e"
           " (%.1f s)" % (n_run, n, err[keep].max(), err[head.index("zeta_3")], sec))
    # pre-fractured start, D7 separation and the effect switches: T2 parts exactly zero
    zero = 0.0
    path = [(-0.001, 0.0, 0.0), (-0.001, 0.05, 0.0), (0.3, 0.2, 0.0), (0.6, -0.1, 0.0),
            (-0.002, -0.3, 0.0), (-0.002, 0.4, 0.0)]
    for switches in ({}, {"damage": False}, {"friction": False}, {"depth": False},
                     {"wear": False}):
        mat = R.Material(3.0, 3.0, 0.3, 0.9, 0.5, 0.5,
                         R.ria_paper(math.radians(25), math.radians(10), 0.01), **switches)
        for scheme in R.SCHEMES:
            for st0 in (R.virgin_state(mat), R.prefractured_state(mat)):
                for r in R.run_history(mat, path, scheme, state0=st0):
                    zero = max([zero, abs(r.sigma[2])] +
                               [max(abs(s.sf2), abs(s.tauf2)) for s in r.states])
    report("2D reduction T2 parts (pre-fractured, D7, effect switches)", zero == 0.0,
           "largest |sigma_T2|, |sf_2|, |tauf_2|: %g" % zero)


# ----------------------------------------------------------------------------------------------
# 2. Properties of section 9
# ----------------------------------------------------------------------------------------------
def rotate(v, a):
    c, s = math.cos(a), math.sin(a)
    return np.array([v[0], c * v[1] - s * v[2], s * v[1] + c * v[2]])


def random_walk(rng, n, scale_n, scale_t, s_max_n):
    pts, s = [], np.zeros(3)
    for _ in range(n):
        s = s + np.array([rng.uniform(-1.0, 0.7) * scale_n, rng.uniform(-1, 1) * scale_t,
                          rng.uniform(-1, 1) * scale_t])
        s[0] = min(s[0], s_max_n)
        pts.append(s.copy())
    return pts


def history_tractions(mat, pts, scheme, state0=None):
    return np.array([r.sigma for r in R.run_history(mat, pts, scheme, state0=state0)])


def check_properties():
    print("== 2. Properties of SPEC section 9")
    rng = np.random.default_rng(9)
    # flat RIA: rotation invariance (damage, friction, finite depth; D7 visited)
    flat = R.Material(3.0, 3.0, 0.3, 0.9, 0.5, 0.5, [R.Plane(1.0, 0.0, 0.0)])
    pts = random_walk(rng, 80, 0.05, 0.1, 0.7)
    worst = 0.0
    for scheme in R.SCHEMES:
        base = history_tractions(flat, pts, scheme)
        for a in (0.3, 1.0, 2.5, -2.0):
            rot = history_tractions(flat, [rotate(p, a) for p in pts], scheme)
            worst = max(worst, np.abs(rot - np.array([rotate(b, a) for b in base])).max()
                        / np.abs(base).max())
    report("flat RIA rotation invariance", worst < 1e-13,
           "80 random 3D steps, every scheme, 4 angles: %.1e of the largest traction" % worst)

    # azimuthal N_a = 3: rotation by pi/3 is a symmetry (wear on); pi/6 is not
    mat = R.granite("azimuthal", 3)
    pts = random_walk(rng, 40, 0.002, 0.05, 0.5)
    worst, other = 0.0, 0.0
    for scheme in R.SCHEMES:
        base = history_tractions(mat, pts, scheme)
        rot = history_tractions(mat, [rotate(p, math.pi / 3) for p in pts], scheme)
        worst = max(worst, np.abs(rot - np.array([rotate(b, math.pi / 3) for b in base])).max()
                    / np.abs(base).max())
        rot = history_tractions(mat, [rotate(p, math.pi / 6) for p in pts], scheme)
        other = max(other, np.abs(rot - np.array([rotate(b, math.pi / 6) for b in base])).max()
                    / np.abs(base).max())
    report("azimuthal N_a = 3: pi/3 symmetry", worst < 1e-12 and other > 1e-3,
           "40 random 3D steps with wear, every scheme: %.1e (rotation by pi/6: %.1e, not a"
           " symmetry)" % (worst, other))

    # azimuth mapping: a plane given with phi in [pi, 2 pi), computed without the mapping,
    # equals the mapped plane (state: sf, tauf, theta of the opposite sign)
    raw = [R.Plane(0.5, math.radians(20), math.radians(5), 0.01, math.radians(200)),
           R.Plane(0.5, math.radians(-30), math.radians(-9), 0.02, math.radians(300))]
    mapped = R.Material(3.0, 3.0, 0.3, 0.9, 0.5, 0.5, raw)
    unmapped = R.Material(3.0, 3.0, 0.3, 0.9, 0.5, 0.5, [R.Plane(1.0, 0.0, 0.0)])
    unmapped.planes = raw
    pts = random_walk(rng, 30, 0.02, 0.1, 0.4)
    worst = 0.0
    for scheme in R.SCHEMES:
        a = R.run_history(mapped, pts, scheme)
        b = R.run_history(unmapped, pts, scheme, state0=[R.PlaneState(theta=p.theta0)
                                                          for p in raw])
        for ra, rb in zip(a, b):
            worst = max(worst, np.abs(ra.sigma - rb.sigma).max())
            for sa, sb in zip(ra.states, rb.states):
                sb = R.map_state(sb)
                worst = max(worst, abs(sa.sf1 - sb.sf1), abs(sa.sf2 - sb.sf2),
                            abs(sa.theta - sb.theta), abs(sa.zeta - sb.zeta), abs(sa.D - sb.D))
    report("azimuth outside [0, pi) mapped", worst < 1e-12,
           "traction and state of the mapped plane vs the raw one: %.1e" % worst)

    # energy balance (depth and wear off) on a 3D path; friction dissipation monotone
    mat = R.table1(25.0, R.INF, wear=False)
    corners = [(-0.004, 0.0, 0.0), (-0.004, 0.3, 0.0), (-0.01, 0.3, 0.3), (0.02, -0.2, 0.3),
               (-0.006, -0.2, -0.3), (-0.006, 0.1, 0.0)]

    def balance(n_per_leg):
        pts = [corners[0]]
        for p, q in zip(corners[:-1], corners[1:]):
            pts += [tuple(np.array(p) + (np.array(q) - np.array(p)) * i / n_per_leg)
                    for i in range(1, n_per_leg + 1)]
        rows = R.run_history(mat, pts, "implicit", with_energies=True)
        e = rows[-1].energies
        res = e.work - e.stored - e.damage - e.friction
        fr = [r.energies.friction for r in rows]
        return res, e, min(np.diff(fr))
    r1, e1, m1 = balance(100)
    r2, e2, m2 = balance(200)
    report("energy balance, 3D path (depth and wear off)",
           abs(r2) < 5e-5 * e2.work and abs(r1 / r2) > 3.0 and min(m1, m2) >= 0.0,
           "work %.6f N/mm = stored %.6f + damage %.6f + friction %.6f; residual %.2e"
           " (100 steps per leg %.2e: ratio %.1f, second order); smallest friction dissipation"
           " increment %.1e" % (e2.work, e2.stored, e2.damage, e2.friction, r2, r1, r1 / r2,
                                min(m1, m2)))

    # closed form: debonded flat interface, constant p, slip in any direction
    flat = R.Material(3.0, 3.0, 0.3, 0.9, 0.5, R.INF, [R.Plane(1.0, 0.0, 0.0)])
    sN = -0.002
    p = -flat.K_n * sN
    worst = 0.0
    for a in np.linspace(0.0, 2 * math.pi, 13):
        d = np.array([math.cos(a), math.sin(a)])
        pts = [(sN, 0.0, 0.0)] + [(sN, *(d * 0.5 * i / 10)) for i in range(1, 11)]
        for scheme in R.SCHEMES:
            sig = R.run_history(flat, pts, scheme, state0=R.prefractured_state(flat))[-1].sigma
            worst = max(worst, abs(sig[0] + p), abs(np.dot(sig[1:], d) - flat.mu * p),
                        abs(sig[1] * d[1] - sig[2] * d[0]))
    report("closed form: debonded flat interface", worst < 1e-13,
           "sigma_N = -p, shear mu p along the slip, 0 across, 13 directions: %.1e MPa" % worst)

    # tangent: the strike stiffness of a sliding plane (debonded, flat, sliding along t1)
    s_old, s_new = np.array([sN, 0.2, 0.0]), np.array([sN, 0.21, 0.0])
    old = R.run_history(flat, [tuple(s_old)], "implicit",
                        state0=R.prefractured_state(flat))[-1].states
    K = R.tangent_fd(flat, s_old, s_new, old, "implicit")
    tr = flat.K_t * (s_new[1] - old[0].sf1)
    expect = flat.K_t * flat.mu * p / tr
    report("tangent: strike stiffness of a sliding plane",
           abs(K[2, 2] - expect) < 1e-6 * expect and abs(K[1, 1]) < 1e-6 * expect
           and abs(K[1, 0] + flat.mu * flat.K_n) < 1e-6 * flat.K_n,
           "K_T2T2 %.6f = K_t mu p / |tau_tr| %.6f; K_T1T1 %.1e; K_T1N %.6f = -mu K_n"
           % (K[2, 2], expect, K[1, 1], K[1, 0]))
    # tangent in the 2D reduction: the T2 row and column zero except T2-T2
    mat = R.granite("paper")
    pts = [(-0.02, 0.0, 0.0), (-0.021, 0.1, 0.0)]
    worst = 0.0
    for scheme in R.SCHEMES:
        old = R.run_history(mat, pts[:1], scheme)[-1].states
        K = R.tangent_fd(mat, np.array(pts[0]), np.array(pts[1]), old, scheme)
        worst = max(worst, abs(K[0, 2]), abs(K[1, 2]), abs(K[2, 0]), abs(K[2, 1]))
        t22 = K[2, 2]
    report("tangent in the 2D reduction", worst < 1e-9 and t22 != 0.0,
           "T2 row and column off the diagonal %.1e; K_T2T2 = %.4f" % (worst, t22))


# ----------------------------------------------------------------------------------------------
# 3. The directional figures quoted for the 3D law
# ----------------------------------------------------------------------------------------------
def straight_granite(mat, angle_deg, length, n, scheme="trapezoidal"):
    a = math.radians(angle_deg)
    rows = R.run_history(mat, R.straight_path(length, a, n), scheme, sigma_N=-1.5)
    c, s = math.cos(a), math.sin(a)
    along = np.array([r.sigma[1] * c + r.sigma[2] * s for r in rows])
    across = np.array([-r.sigma[1] * s + r.sigma[2] * c for r in rows])
    return along, across, rows


def circle_lag(n_radial, n_per_turn):
    mat = R.granite("azimuthal", 3)
    rows = R.run_history(mat, R.circle_path(2.0, n_radial, 2 * n_per_turn, 2.0), "trapezoidal",
                         sigma_N=-1.5)
    lag = []
    for r in rows[n_radial + n_per_turn + 1:]:        # the second turn
        tangent = math.atan2(r.s[2], r.s[1]) + 0.5 * math.pi
        lag.append(math.degrees((tangent - math.atan2(r.sigma[2], r.sigma[1]) + math.pi)
                                % (2 * math.pi) - math.pi))
    return min(lag), max(lag)


def peak_spread(n_a, n_dir, n_steps):
    mat = R.granite("azimuthal", n_a)
    peaks = [straight_granite(mat, 180.0 / n_a * i / n_dir, 1.0, n_steps)[0].max()
             for i in range(n_dir + 1)]
    return (max(peaks) - min(peaks)) / max(peaks), min(peaks), max(peaks)


def check_figures(full):
    print("== 3. Directional figures (granite, sigma_N = -1.5 MPa applied first at zero slip;"
          " trapezoidal scheme)")
    paper = R.granite("paper")
    along, _, _ = straight_granite(paper, 0.0, 1.0, 800)
    report("paper, slip along t1: peak 2.89 MPa", abs(along.max() - 2.89) < 0.01,
           "%.4f MPa (1 mm in 800 steps)" % along.max())
    along, _, _ = straight_granite(paper, 90.0, 2.0, 200)
    report("paper, slip along t2: peak 1.13 MPa", abs(along.max() - 1.13) < 0.01,
           "%.4f MPa (2 mm in 200 steps)" % along.max())
    _, across, _ = straight_granite(paper, 45.0, 2.0, 400)
    report("paper, slip at 45 deg: transverse traction up to 0.75 MPa",
           abs(np.abs(across).max() - 0.75) < 0.015,
           "%.4f MPa (2 mm in 400 steps)" % np.abs(across).max())
    az3 = R.granite("azimuthal", 3)
    along, _, _ = straight_granite(az3, 0.0, 1.0, 200)
    report("azimuthal N_a = 3, slip along t1: peak 2.30 MPa", abs(along.max() - 2.30) < 0.01,
           "%.4f MPa (1 mm in 200 steps)" % along.max())
    expected = {2: 0.04, 3: 0.07, 6: 0.016, 12: 0.004}
    for n_a in ((2, 3, 6, 12) if full else (3,)):
        n_dir = 12 if full else 2
        spread, lo, hi = peak_spread(n_a, n_dir, 200)
        report("azimuthal N_a = %d: peak spread about %.1f %%" % (n_a, 100 * expected[n_a]),
               abs(spread - expected[n_a]) < 0.25 * expected[n_a],
               "%.2f %% (peaks %.4f..%.4f MPa, %d directions over [0, pi/N_a], 1 mm in 200 steps)"
               % (100 * spread, lo, hi, n_dir + 1))
    lo, hi = circle_lag(100, 720) if full else circle_lag(40, 180)
    report("azimuthal N_a = 3, circle r = 2 mm: lag 17-26 deg",
           abs(lo - 17.0) < 1.5 and abs(hi - 26.0) < 1.5,
           "%.1f..%.1f deg over the second turn (%s)"
           % (lo, hi, "720 steps per turn" if full else "180 steps per turn"))


# ----------------------------------------------------------------------------------------------
# 4. The stored data
# ----------------------------------------------------------------------------------------------
def check_data(full):
    print("== 4. Stored data tests/data/reference3d re-generated (subset)")
    total = sum(os.path.getsize(os.path.join(M.DEFAULT_OUT, f))
                for f in os.listdir(M.DEFAULT_OUT))
    report("data size", total < 5e6, "%.2f MB" % (total / 1e6))
    for material in M.STEP_MATERIALS:
        for scheme in R.SCHEMES:
            stem = "steps_%s_%s" % (material, scheme)
            _, cols, stored = M.read_csv(os.path.join(M.DEFAULT_OUT, stem + ".csv"))
            n = len(stored) if full else 8
            fresh = M.step_table(material, scheme, n)
            k = cols.index("K_N_N")
            err = rel_max(fresh[:, :k], stored[:n, :k]).max()
            report(stem, err < 1e-12, "%d points: %.1e" % (n, err))
    for scene in M.HISTORY_SCENES:
        for scheme in M.HISTORY_SCHEMES:
            if not full and not (scene.name.endswith("straight45") and scheme == "trapezoidal"):
                continue
            stem = "%s_%s" % (scene.name, scheme)
            _, cols, stored = M.read_csv(os.path.join(M.DEFAULT_OUT, stem + ".csv"))
            n = None if full else 100
            fresh = M.history_table(scene, scheme, max_steps=n)
            err = rel_max(fresh, stored[:len(fresh)]).max()
            report(stem, err < 1e-12, "%d rows: %.1e" % (len(fresh), err))


def main():
    full = "--full" in sys.argv[1:]
    t0 = time.time()
    check_2d(full)
    check_properties()
    check_figures(full)
    check_data(full)
    print("%d failure(s), %.0f s" % (len(FAILURES), time.time() - t0))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
