#!/usr/bin/python3
"""The pull-out measurements of docs/calculix_pullout.md: runs variants of the model and
prints one markdown table (convergence, forces, cost) and the force differences between them.

    /usr/bin/python3 measure.py --ccx PATH --out DIR [--set NAME ...] [--threads 2]

Sets (each a list of runs of run.py; every run in DIR/<set>/<variant>):
  tangent   coarse and full mesh, the exact tangent (ccx keeps its symmetric part) against the
            symmetric option (layer PROPS 24 = interlock PROPS 20 = 2)
  bounds    coarse and full mesh, the UMAT's accuracy bounds (PROPS 13, 14 = 0.25, 1 deg) on
            and off; the full mesh with the bounds on also with increments of at most 0.0125
  radius    coarse mesh, block radius 500 mm (the default) against 1000 mm and 250 mm
  layer     coarse mesh, the layer's e_other 0.01 MPa (the default) against 1 and 2621 MPa
  concrete  coarse mesh, Table 3's E_c = 2621 MPa against ten times that
  plateau   full mesh, the steel's perfectly plastic plateau: CAX4R (default) against ccx's
            fully integrated CAX4
  profile   full mesh under perf: the share of CPU time spent in the UMAT
"""
import argparse
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "scripts"))
import python_with  # noqa: E402  (the python3 that has the modules below)

python_with.modules("numpy", "matplotlib")
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import post  # noqa: E402

OFF = ["--max-damage-increment", "1", "--max-angle-increment", "90"]
SETS = {
    "tangent": [
        ("coarse, tangent 1 (exact; ccx symmetrizes)", ["--element", "10", "--tangent", "1"] + OFF),
        ("coarse, tangent 2 (symmetric option)", ["--element", "10", "--tangent", "2"] + OFF),
        ("full, tangent 1 (exact; ccx symmetrizes)", ["--element", "5", "--tangent", "1"] + OFF),
        ("full, tangent 2 (symmetric option)", ["--element", "5", "--tangent", "2"] + OFF),
    ],
    "bounds": [
        ("coarse, bounds on (0.25, 1 deg)", ["--element", "10", "--tangent", "2",
                                             "--max-damage-increment", "0.25",
                                             "--max-angle-increment", "1"]),
        ("coarse, bounds off", ["--element", "10", "--tangent", "2"] + OFF),
        ("full, bounds on (0.25, 1 deg)", ["--element", "5", "--tangent", "2",
                                           "--max-damage-increment", "0.25",
                                           "--max-angle-increment", "1"]),
        # (the run above stops in its last increment, at 5.1974 mm: with increments of at
        # most 0.0125 of the step they end elsewhere, docs/calculix_pullout.md)
        ("full, bounds on, max increment 0.0125", ["--element", "5", "--tangent", "2",
                                                   "--max-damage-increment", "0.25",
                                                   "--max-angle-increment", "1",
                                                   "--max-increment", "0.0125",
                                                   "--initial-increment", "0.0125"]),
        ("full, bounds off", ["--element", "5", "--tangent", "2"] + OFF),
    ],
    "radius": [
        ("coarse, R = 500 mm", ["--element", "10", "--radius", "500"] + OFF),
        ("coarse, R = 1000 mm", ["--element", "10", "--radius", "1000"] + OFF),
        ("coarse, R = 250 mm", ["--element", "10", "--radius", "250"] + OFF),
    ],
    "concrete": [
        ("coarse, E_c = 2621 MPa (Table 3 as printed)", ["--element", "10"] + OFF),
        ("coarse, E_c = 26210 MPa", ["--element", "10", "--concrete-modulus", "26210"] + OFF),
    ],
    "layer": [
        ("coarse, e_other = 0.01 MPa", ["--element", "10"] + OFF),
        ("coarse, e_other = 1 MPa", ["--element", "10", "--layer-e-other", "1"] + OFF),
        ("coarse, e_other = 2621 MPa (= E_c)", ["--element", "10", "--layer-e-other", "2621"]
         + OFF),
    ],
    "plateau": [],          # filled in main() from --plateau-variants
    "profile": [
        ("full, tangent 2, under perf", ["--element", "5", "--tangent", "2", "--profile"] + OFF),
    ],
}


def slug(text):
    return "".join(c if c.isalnum() else "_" for c in text).strip("_")[:60]


def run(ccx, out, threads, name, args, reuse):
    d = os.path.join(out, slug(name))
    if reuse and os.path.isfile(os.path.join(d, "summary.json")):
        with open(os.path.join(d, "summary.json")) as f:
            s = json.load(f)
        return s, post.analyse(os.path.join(d, "pullout"))[1]
    profile = "--profile" in args
    args = [x for x in args if x != "--profile"]
    cmd = [sys.executable, os.path.join(HERE, "run.py"), "--ccx", ccx, "--dir", d,
           "--threads", str(threads), "--title", name] + (["--profile"] if profile else []) + args
    subprocess.run(cmd)
    path = os.path.join(d, "summary.json")
    if not os.path.isfile(path):
        return None, None
    with open(path) as f:
        s = json.load(f)
    _, data = post.analyse(os.path.join(d, "pullout"))
    return s, data


def kn(v):
    return "-" if v is None else f"{v / 1000:.2f}"


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--ccx", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--reuse", action="store_true",
                   help="tabulate the runs already in --out (no ccx run)")
    p.add_argument("--set", action="append", choices=sorted(SETS), required=True)
    p.add_argument("--plateau-variants", default="none,bar:CAX4",
                   help="comma list for the plateau set: none, bar:<CAX4|CAX4R>, "
                        "hardening:<MPa>, controls:<data line> (default: none,bar:CAX4)")
    a = p.parse_args(argv)
    for v in a.plateau_variants.split(","):
        kind, _, value = v.partition(":")
        base = ["--element", "5", "--tangent", "2"] + OFF
        if kind == "none":
            SETS["plateau"].append(("full, Table 4 as given", base))
        elif kind == "hardening":
            SETS["plateau"].append((f"full, plateau slope {value} MPa",
                                    base + ["--plateau-hardening", value]))
        elif kind == "bar":
            SETS["plateau"].append((f"full, steel in {value}", base + ["--bar-element", value]))
        elif kind == "controls":
            SETS["plateau"].append((f"full, *CONTROLS {value}", base + ["--controls", value]))
    rows, curves = [], []
    for set_name in a.set:
        for name, args in SETS[set_name]:
            s, data = run(a.ccx, os.path.join(a.out, set_name), a.threads, name, args, a.reuse)
            if s is None:
                rows.append(f"| {name} | did not run | | | | | | | |")
                continue
            curves.append((name, data["s_top"], data["force"]))
            prof = s.get("profile")
            share = "" if not prof else f", UMAT {prof['percent']['interlock']} % of CPU"
            rows.append(
                f"| {name} | {s['top_displacement_reached_mm']:.3f} | {s['increments']} | "
                f"{s['attempts_failed']} | {s['iterations_per_increment_median']:g} / "
                f"{s['iterations_per_increment_max']} | "
                f"{s['iterations_total_with_failed_attempts']} | "
                f"{kn(s['force_at_first_yield_N'])} | {kn(s['force_at_2.6mm_N'])} | "
                f"{kn(s['final_force_N'])} | {s['wall_time_s']:.0f}{share} |")
    print("| run | reached [mm] | increments | failed attempts | iterations median / max | "
          "iterations in all | F at first yield [kN] | F at 2.6 mm [kN] | F at end [kN] | "
          "wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    print("\n".join(rows))
    if len(curves) > 1:
        print()
    for i, (ref_name, ref_s, ref_f) in enumerate(curves):
        for name, s_top, force in curves[i + 1:]:
            # At the top displacements both runs converged at (interpolating across the kink
            # at yield would compare different points of the curve), else interpolated.
            common = sorted(set(np.round(s_top, 7)) & set(np.round(ref_s, 7)))
            how = "at the common increments"
            if len(common) < 10:
                # at the increments of the run with fewer, the other one interpolated
                coarser = s_top if len(s_top) < len(ref_s) else ref_s
                common = coarser[coarser <= min(s_top[-1], ref_s[-1]) + 1e-12]
                how = "at the increments of the run with fewer, the other interpolated"
            grid = np.array(common)
            diff = np.interp(grid, s_top, force) - np.interp(grid, ref_s, ref_f)
            k = int(np.argmax(np.abs(diff)))
            print(f"- {name} against {ref_name}: largest force difference over 0..{grid[-1]:.2f}"
                  f" mm ({how}) {diff[k] / 1000:+.3f} kN at {grid[k]:.2f} mm "
                  f"({diff[k] / max(np.interp(grid[k], ref_s, ref_f), 1.0) * 100:+.3f} %)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
