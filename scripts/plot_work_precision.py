#!/usr/bin/python3
"""Work-precision diagram of interlock-bench: error against CPU time (log-log), one line per
scheme/tolerance, one panel per scene.

usage: /usr/bin/python3 scripts/plot_work_precision.py DIR [-o docs/work_precision.png]
       [--target 1e-4]
DIR holds work_precision.csv (and reference.csv) written by `interlock-bench --out DIR`.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TITLES = {
    "fig11": "Fig. 11 (H_N = 2, zeta_0 = 1, monotonic 50 mm)",
    "fig12": "Fig. 12 (H_N = 5, zeta_0 = 20, cyclic +/-10 mm)",
    "granite": "granite (H_N = 4, zeta_0 = 6.666, 2 cycles +/-5 mm)",
}


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir", help="folder with work_precision.csv")
    ap.add_argument("-o", "--output", default="work_precision.png")
    ap.add_argument("--target", type=float, default=1e-4, help="error level drawn as a line")
    args = ap.parse_args()

    rows = read_csv(os.path.join(args.dir, "work_precision.csv"))
    refs = {}
    ref_path = os.path.join(args.dir, "reference.csv")
    if os.path.exists(ref_path):
        refs = {r["scene"]: float(r["uncertainty"]) for r in read_csv(ref_path)}
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    if not scenes:
        sys.exit("no rows in work_precision.csv")

    fig, axes = plt.subplots(1, len(scenes), figsize=(5.2 * len(scenes), 4.8), squeeze=False)
    colours = {"explicit": plt.cm.Reds, "implicit": plt.cm.Blues}
    for ax, scene in zip(axes[0], scenes):
        configs = []
        for r in rows:
            if r["scene"] == scene and r["config"] not in configs:
                configs.append(r["config"])
        for cfg in configs:
            pts = [r for r in rows if r["scene"] == scene and r["config"] == cfg and r["ok"] == "T"]
            pts.sort(key=lambda r: int(r["n_steps"]))
            if not pts:
                continue
            scheme, tol = pts[0]["scheme"], pts[0]["substep_tol"]
            tols = ["none", "1.E-02", "1.E-03", "1.E-04", "1.E-05"]
            if tol == "richardson":   # 2 u(2n) - u(n) of the uniform-step runs
                shade, style, marker, lw = 0.95, ":", "s", 2.0
                label = f"{scheme}, uniform, Richardson (n, 2n)"
            else:
                shade = 0.9 - 0.13 * (tols.index(tol) if tol in tols else 0)
                style = "-" if tol == "none" else "--"
                marker = "o" if tol == "none" else "."
                lw = 2.2 if tol == "none" else 1.1
                label = f"{scheme}, " + ("uniform steps" if tol == "none" else f"substep tol {tol}")
            ax.loglog([float(r["cpu_s"]) for r in pts], [float(r["error"]) for r in pts],
                      style, marker=marker, lw=lw, color=colours[scheme](shade), label=label)
            if tol == "none":   # step counts at the ends of the uniform-step lines
                for r in (pts[0], pts[-1]):
                    ax.annotate(r["n_steps"], (float(r["cpu_s"]), float(r["error"])),
                                textcoords="offset points", xytext=(4, 4), fontsize=7,
                                color=colours[scheme](shade))
        ax.axhline(args.target, color="0.5", lw=0.8, ls=":")
        title = TITLES.get(scene, scene)
        if scene in refs:
            title += f"\nreference uncertainty {refs[scene]:.1e}"
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("CPU time per run [s]")
        ax.grid(True, which="major", lw=0.4, alpha=0.6)
    axes[0][0].set_ylabel("max relative error of sigma_T and s_N")
    axes[0][-1].legend(fontsize=7, loc="lower left")
    fig.suptitle("interlock: error vs CPU time (constant sigma_N; step counts base x 2^j)",
                 fontsize=11)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
