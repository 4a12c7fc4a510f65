#!/usr/bin/python3
"""Work-precision diagram of interlock-bench: error against CPU time (log-log), one line per
scheme/tolerance, one panel per scene.

usage: /usr/bin/python3 scripts/plot_work_precision.py DIR [-o docs/work_precision.png]
       [--target 1e-4]
       /usr/bin/python3 scripts/plot_work_precision.py DIR --markdown
DIR holds work_precision.csv (and reference.csv, cost.csv, wp_summary.csv, cost3d.csv,
work_precision_3d.csv) written by
`interlock-bench --out DIR`. --markdown prints the tables of docs/bench.md from those files
instead of plotting (so that every number in the document comes from one run).
"""
import argparse
import csv
import os
import sys

import python_with  # the python3 that has the modules below

python_with.modules("matplotlib")
import matplotlib  # noqa: E402

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


def fmt_err(x):
    return f"{float(x):.1e}"


def markdown(d):
    """The tables of docs/bench.md from one run's CSV files."""
    cost = read_csv(os.path.join(d, "cost.csv"))
    print("| effect set | scheme | substep tol | ns/call (median) | min..max | x bilinear "
          "| sub-increments |")
    print("|---|---|---|---:|---:|---:|---:|")
    for r in cost:
        print(f"| {r['effect_set']} | {r['scheme']} | {r['substep_tol']} | "
              f"{float(r['ns_per_call']):.1f} | {float(r['ns_min']):.1f}.."
              f"{float(r['ns_max']):.1f} | {float(r['ratio_to_bilinear']):.2f} | "
              f"{float(r['mean_substeps']):.2f} |")
    umat = os.path.join(d, "umat_cost.csv")
    if os.path.exists(umat):
        print("\n| effect set | scheme | UMAT ns | update ns | overhead ns | x bilinear "
              "| UMAT / update | floor ns | floor x bilinear | PNEWDT < 1 |")
        print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
        for r in read_csv(umat):
            print(f"| {r['effect_set']} | {r['scheme']} | {float(r['umat_ns']):.1f} | "
                  f"{float(r['update_ns']):.1f} | {float(r['overhead_ns']):.1f} | "
                  f"{float(r['overhead_bilinear_calls']):.2f} | "
                  f"{float(r['umat_over_update']):.2f} | {float(r['floor_ns']):.1f} | "
                  f"{float(r['floor_bilinear_calls']):.2f} | {r['pnewdt_cuts']} |")
    rows = read_csv(os.path.join(d, "work_precision.csv"))
    summ = read_csv(os.path.join(d, "wp_summary.csv"))
    scenes = []
    for r in rows:
        if r["scene"] not in scenes:
            scenes.append(r["scene"])
    for scene in scenes:
        srows = [r for r in rows if r["scene"] == scene]
        counts = sorted({int(r["n_steps"]) for r in srows})
        cols = counts[4::2]          # j = 4, 6, 8, 10
        configs = []
        for r in srows:
            if r["config"] not in configs:
                configs.append(r["config"])
        # uniform first, then Richardson, then substepping (as in the document)
        def key(c):
            sch, rest = c.split(" ", 1)
            kind = 0 if rest == "none" else 1 if rest == "Richardson" else 2
            return (["explicit", "implicit", "trapezoidal"].index(sch)
                    if sch in ("explicit", "implicit", "trapezoidal") else 3, kind, rest)
        configs.sort(key=key)
        print(f"\n*{scene}* — error (CPU ms per run) at n steps:\n")
        print("| configuration | " + " | ".join(f"n = {n}" for n in cols) + " |")
        print("|---|" + "---:|" * len(cols))
        for cfg in configs:
            sch, rest = cfg.split(" ", 1)
            name = sch + ", " + ("uniform" if rest == "none" else "Richardson (n, 2n)"
                                 if rest == "Richardson" else "substep " + rest.replace(".E", "e"))
            cells = []
            for n in cols:
                m = [r for r in srows if r["config"] == cfg and int(r["n_steps"]) == n]
                if not m or m[0]["ok"] != "T":
                    cells.append("-" if not m else "failed")
                else:
                    cells.append(f"{fmt_err(m[0]['error'])} ({1e3 * float(m[0]['cpu_s']):.1f})")
            print(f"| {name} | " + " | ".join(cells) + " |")
    print("\nObserved order (finer half of the levels) per configuration:\n")
    print("| configuration | " + " | ".join(scenes) + " |")
    print("|---|" + "---:|" * len(scenes))
    cfgs = []
    for r in summ:
        if r["config"] not in cfgs:
            cfgs.append(r["config"])
    for cfg in cfgs:
        vals = []
        for scene in scenes:
            m = [r for r in summ if r["scene"] == scene and r["config"] == cfg]
            vals.append(f"{float(m[0]['observed_order']):.2f}" if m else "-")
        print(f"| {cfg} | " + " | ".join(vals) + " |")
    print("\nCPU time to reach the target error (s; x = extrapolated at the observed order; "
          "n = runs below the target from this step count on):\n")
    print("| scene | configuration | CPU s | explicit uniform / this | n |")
    print("|---|---|---:|---:|---:|")
    for r in summ:
        if r["cpu_s_at_target"].strip() == "not reached":
            continue
        ratio = float(r["explicit_uniform_over_this"]) if r["explicit_uniform_over_this"] else -1
        print(f"| {r['scene']} | {r['config']} | {float(r['cpu_s_at_target']):.3g}"
              f"{' (x)' if r['extrapolated'] == 'T' else ''} | "
              f"{ratio:.1f} | {r['n_steps_first_below'] if r['n_steps_first_below'] != '-1' else '-'} |")
    markdown_3d(d)
    ref = os.path.join(d, "reference.csv")
    if os.path.exists(ref):
        print("\n| scene | reference steps | uncertainty | plain implicit error at those steps |")
        print("|---|---:|---:|---:|")
        for r in read_csv(ref):
            print(f"| {r['scene']} | {r['n_reference']} | {float(r['uncertainty']):.1e} | "
                  f"{float(r['plain_error_at_n_reference']):.1e} |")


def markdown_3d(d):
    """Parts 1b and 3b: the 3D update's cost against the 2D one, and the 3D work-precision."""
    cost3d = os.path.join(d, "cost3d.csv")
    if os.path.exists(cost3d):
        print("\nCost per call in three dimensions (part 1b):\n")
        print("| scheme | update | ns/call | x 2D update |")
        print("|---|---|---:|---:|")
        for r in read_csv(cost3d):
            print(f"| {r['scheme']} | {r['update']} | {float(r['ns_per_call']):.1f} | "
                  f"{float(r['ratio_to_2d']):.2f} |")
    wp3d = os.path.join(d, "work_precision_3d.csv")
    if not os.path.exists(wp3d):
        return
    rows = read_csv(wp3d)
    for scene in dict.fromkeys(r["scene"] for r in rows):
        srows = [r for r in rows if r["scene"] == scene]
        counts = sorted({int(r["n_steps_per_segment"]) for r in srows})
        cols = counts[2::2]
        print(f"\n*{scene}* (part 3b) — error (CPU ms per run) at n steps per segment:\n")
        print("| configuration | " + " | ".join(f"n = {n}" for n in cols) + " |")
        print("|---|" + "---:|" * len(cols))
        for cfg in dict.fromkeys(r["config"] for r in srows):
            cells = []
            for n in cols:
                m = [r for r in srows if r["config"] == cfg and int(r["n_steps_per_segment"]) == n]
                cells.append(f"{fmt_err(m[0]['error'])} ({1e3 * float(m[0]['cpu_s']):.1f})"
                             if m else "-")
            print(f"| {cfg} | " + " | ".join(cells) + " |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("dir", help="folder with work_precision.csv")
    ap.add_argument("-o", "--output", default="work_precision.png")
    ap.add_argument("--target", type=float, default=1e-4, help="error level drawn as a line")
    ap.add_argument("--markdown", action="store_true",
                    help="print the tables of docs/bench.md instead of plotting")
    args = ap.parse_args()
    if args.markdown:
        markdown(args.dir)
        return

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

    fig, axes = plt.subplots(1, len(scenes), figsize=(5.2 * len(scenes), 5.3), squeeze=False)
    colours = {"explicit": plt.cm.Reds, "implicit": plt.cm.Blues, "trapezoidal": plt.cm.Greens}
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
    # one legend for all panels, below them (inside a panel it hides points)
    handles, labels = axes[0][-1].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=7.5, loc="lower center", ncol=4, frameon=False)
    fig.suptitle("interlock: error vs CPU time (constant sigma_N; step counts base x 2^j)",
                 fontsize=11)
    fig.tight_layout(rect=(0, 0.1, 1, 1))
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
