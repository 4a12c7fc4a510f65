"""Writes the 3D reference data of tests/data/reference3d from interlock3d_ref.py.

    /usr/bin/python3 tests/update/reference3d/make_reference3d.py [--out DIR] [--only NAME...]
                     [--halving]

(a) steps_<material>_<scheme>.csv: single random 3D steps from given old states (for update and
    tangent tests); (b) <scene>_<scheme>.csv: histories under constant sigma_N (mixed control,
    SPEC D8: sigma_N applied first at zero slip in one step, then the slip path).
--halving also runs every history at half the step count and prints the largest difference
(relative to each column's largest magnitude), the step-halving study of the README.
"""

import argparse
import math
import os
import random
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import interlock3d_ref as R  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_OUT = os.path.normpath(os.path.join(HERE, "..", "..", "data", "reference3d"))


# ----------------------------------------------------------------------------------------------
# Scenes
# ----------------------------------------------------------------------------------------------
MATERIALS = {
    "granite_paper": ("granite (SPEC parameter sets: sigma0 = 0.025 MPa, Gc = 0.0005 N/mm, "
                      "eta = 0.99, mu = tan(34.6 deg), theta_0 = 30, theta_f = 9 deg, "
                      "H_N = 4 mm, zeta_0 = 6.666 N/mm), RIA paper",
                      lambda: R.granite("paper")),
    "granite_az3": ("granite (as granite_paper), RIA azimuthal N_a = 3",
                    lambda: R.granite("azimuthal", 3)),
    "table1_paper": ("Table 1 (sigma0 = 3 MPa, Gc = 0.3 N/mm, eta = 0.9, mu = 0.5), "
                     "theta_0 = 25 deg, no wear, H_N = 0.5 mm, RIA paper",
                     lambda: R.table1(25.0, 0.5)),
}


class Scene:
    """A history: material key, path kind and its parameters, sigma_N, step count."""

    def __init__(self, name, material, kind, sigma_N, n_steps, store_every, **geo):
        self.name, self.material, self.kind = name, material, kind
        self.sigma_N, self.n_steps, self.store_every, self.geo = sigma_N, n_steps, store_every, geo

    def path(self, n_steps=None):
        n = n_steps or self.n_steps
        g = self.geo
        if self.kind == "straight":
            return R.straight_path(g["length"], math.radians(g["angle_deg"]), n)
        if self.kind == "square":
            return R.square_path(g["side"], n // 4)
        if self.kind == "circle":
            n_rad = n // (1 + 4 * int(round(g["turns"])))
            return R.circle_path(g["radius"], n_rad, n - n_rad, g["turns"])
        raise ValueError(self.kind)

    def describe(self):
        g = self.geo
        if self.kind == "straight":
            p = "straight, %g mm at %g deg from t1" % (g["length"], g["angle_deg"])
        elif self.kind == "square":
            p = ("square 0 -> (a,0) -> (a,a) -> (0,a) -> 0, a = %g mm, equal steps per side"
                 % g["side"])
        else:
            p = ("out to (r,0) then %g counter-clockwise turns of the circle of radius r = %g mm "
                 "about the origin (n / (1 + 4 turns) steps out, the rest around)"
                 % (g["turns"], g["radius"]))
        return p


# Step counts: see the README (step halving).
HISTORY_SCENES = []
for _mat in ("granite_paper", "granite_az3"):
    for _ang in (0, 30, 45, 90):
        HISTORY_SCENES.append(Scene("%s_straight%02d" % (_mat, _ang), _mat, "straight", -1.5,
                                    2000, 10, length=5.0, angle_deg=float(_ang)))
    HISTORY_SCENES.append(Scene("%s_square" % _mat, _mat, "square", -1.5, 2000, 10, side=2.0))
    HISTORY_SCENES.append(Scene("%s_circle" % _mat, _mat, "circle", -1.5, 2250, 10,
                                radius=2.0, turns=2.0))
HISTORY_SCENES.append(Scene("table1_paper_straight45", "table1_paper", "straight", -0.2, 1500,
                            10, length=1.5, angle_deg=45.0))

HISTORY_SCHEMES = ("implicit", "trapezoidal")


def history_columns(n_planes):
    cols = ["step", "s_N", "s_T1", "s_T2", "sigma_N", "sigma_T1", "sigma_T2"]
    for k in range(1, n_planes + 1):
        cols += ["D_%d" % k, "theta_%d_deg" % k, "zeta_%d" % k]
    return cols


def history_table(scene, scheme, n_steps=None, max_steps=None):
    """Rows (numpy array) of a scene run with the scheme; n_steps overrides the step count
    (the rows are then every (store_every * n / n_steps)-th step: the same slip points);
    max_steps runs only the first steps of the path (the first rows of the full run)."""
    mat = MATERIALS[scene.material][1]()
    n = n_steps or scene.n_steps
    every = max(1, scene.store_every * n // scene.n_steps)
    path = scene.path(n)
    if max_steps is not None:
        path = path[:max_steps + 1]
    last = len(path) - 1
    rows = R.run_history(mat, path, scheme, sigma_N=scene.sigma_N, store_every=every)
    out = []
    steps = list(range(0, last + 1, every))
    if steps[-1] != last:
        steps.append(last)
    for i, r in zip(steps, rows):
        v = [float(i), r.s[0], r.s[1], r.s[2], r.sigma[0], r.sigma[1], r.sigma[2]]
        for st in r.states:
            v += [st.D, math.degrees(st.theta), st.zeta]
        out.append(v)
    return np.array(out)


def history_header(scene, scheme):
    return ("# scene %s; material: %s; scheme: %s; steps: %d after the preload step (row step 0:"
            " sigma_N = %g MPa applied in one step at zero slip, SPEC D8), rows every %d steps;"
            " path of (s_T1, s_T2): %s; sigma_N = %g MPa held at every step (mixed control,"
            " solved to round-off); units mm, MPa, N/mm, theta in degrees"
            % (scene.name, MATERIALS[scene.material][0], scheme, scene.n_steps, scene.sigma_N,
               scene.store_every, scene.describe(), scene.sigma_N))


# ----------------------------------------------------------------------------------------------
# Single steps
# ----------------------------------------------------------------------------------------------
STEP_MATERIALS = ("granite_paper", "granite_az3", "table1_paper")
N_STEP_POINTS = 40


def random_point(mat, scheme, rng):
    """A consistent old state: a random 3D walk of 1-6 steps from the virgin (or, one time in
    four, the pre-fractured) state, then one more random step: the recorded point."""
    scale = max(mat.s_0n, mat.s_0t)
    big = rng.choice([3.0, 30.0, 300.0])
    states = R.prefractured_state(mat) if rng.random() < 0.25 else R.virgin_state(mat)
    s = np.zeros(3)
    for _ in range(rng.randint(1, 6)):
        s_new = s + np.array([rng.uniform(-1.5, 0.5), rng.uniform(-1, 1), rng.uniform(-1, 1)]) \
            * scale * big
        s_new[0] = min(s_new[0], 0.9 * mat.H_N if mat.H_N != R.INF else s_new[0])
        _, states, _ = R.step(mat, s, s_new, states, scheme)
        s = s_new
    s_new = s + np.array([rng.uniform(-1.0, 0.6), rng.uniform(-1, 1), rng.uniform(-1, 1)]) \
        * scale * big * rng.choice([0.01, 0.1, 1.0])
    return s, s_new, states


def step_columns(n_planes):
    cols = ["point"] + ["s_old_%s" % c for c in ("N", "T1", "T2")] + \
        ["s_%s" % c for c in ("N", "T1", "T2")]
    names = ("D", "beta", "sf1", "sf2", "zeta", "theta", "tauf1", "tauf2")
    for k in range(1, n_planes + 1):
        cols += ["old_%s_%d" % (n, k) for n in names]
    cols += ["sigma_%s" % c for c in ("N", "T1", "T2")]
    for k in range(1, n_planes + 1):
        cols += ["%s_%d" % (n, k) for n in names]
    cols += ["K_%s_%s" % (a, b) for a in ("N", "T1", "T2") for b in ("N", "T1", "T2")]
    return cols


def state_values(st):
    return [st.D, st.beta, st.sf1, st.sf2, st.zeta, st.theta, st.tauf1, st.tauf2]


def step_table(material, scheme, n_points=N_STEP_POINTS):
    mat = MATERIALS[material][1]()
    rng = random.Random("%s/%s" % (material, scheme))
    out = []
    for i in range(n_points):
        s_old, s_new, old = random_point(mat, scheme, rng)
        sig, new, _ = R.step(mat, s_old, s_new, old, scheme)
        K = R.tangent_fd(mat, s_old, s_new, old, scheme)
        v = [float(i)] + list(s_old) + list(s_new)
        for st in old:
            v += state_values(st)
        v += list(sig)
        for st in new:
            v += state_values(st)
        v += list(K.ravel())
        out.append(v)
    return np.array(out)


def step_header(material, scheme):
    return ("# single steps; material: %s; scheme: %s; each row: one step from s_old and the old"
            " per-plane state (D, beta, sf1, sf2, zeta, theta [rad], tauf1, tauf2; reached by a"
            " random walk of 1-6 steps of the same scheme from the virgin or pre-fractured"
            " state) to s; sigma and the new state; K = d sigma / d s by central differences"
            " (relative step 1e-7: about 1e-7 accurate away from kinks, meaningless on one);"
            " trapezoidal steps need s_old; units mm, MPa, N/mm"
            % (MATERIALS[material][0], scheme))


# ----------------------------------------------------------------------------------------------
# Writing and reading
# ----------------------------------------------------------------------------------------------
def write_csv(path, header, columns, table):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(header + "\n")
        f.write(",".join(columns) + "\n")
        for row in table:
            f.write(",".join("%.15g" % x for x in row) + "\n")
    os.replace(tmp, path)


def read_csv(path):
    with open(path) as f:
        header = f.readline().rstrip("\n")
        columns = f.readline().strip().split(",")
        table = np.array([[float(x) for x in line.split(",")] for line in f if line.strip()])
    return header, columns, table


def halving_summary(table, half):
    """Largest differences of two runs at the same slip points: traction relative to the
    largest traction magnitude, s_N relative to its largest magnitude, D absolute, theta in
    degrees, zeta relative to the largest zeta."""
    d = np.abs(half - table)
    sig = np.abs(table[:, 4:7]).max()
    sn = np.abs(table[:, 1]).max()
    D, th, z = d[:, 7::3], d[:, 8::3], d[:, 9::3]
    zmax = max(np.abs(table[:, 9::3]).max(), 1e-300)
    return "traction %.1e, s_N %.1e, D %.1e, theta %.1e deg, zeta %.1e" % (
        d[:, 4:7].max() / sig, d[:, 1].max() / sn, D.max(), th.max(), z.max() / zmax)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=DEFAULT_OUT)
    ap.add_argument("--only", nargs="*", help="file stems to (re)write")
    ap.add_argument("--halving", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)

    def wanted(stem):
        return not args.only or stem in args.only

    for material in STEP_MATERIALS:
        n_planes = len(MATERIALS[material][1]().planes)
        for scheme in R.SCHEMES:
            stem = "steps_%s_%s" % (material, scheme)
            if wanted(stem):
                t0 = time.time()
                write_csv(os.path.join(args.out, stem + ".csv"), step_header(material, scheme),
                          step_columns(n_planes), step_table(material, scheme))
                print("%s %.0f s" % (stem, time.time() - t0), flush=True)
    for scene in HISTORY_SCENES:
        n_planes = len(MATERIALS[scene.material][1]().planes)
        for scheme in HISTORY_SCHEMES:
            stem = "%s_%s" % (scene.name, scheme)
            if not wanted(stem):
                continue
            t0 = time.time()
            table = history_table(scene, scheme)
            write_csv(os.path.join(args.out, stem + ".csv"), history_header(scene, scheme),
                      history_columns(n_planes), table)
            msg = "%s %.0f s" % (stem, time.time() - t0)
            if args.halving:
                half = history_table(scene, scheme, scene.n_steps // 2)
                msg += "; halving: %s" % halving_summary(table, half)
            print(msg, flush=True)


if __name__ == "__main__":
    main()
