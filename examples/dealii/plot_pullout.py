#!/usr/bin/python3
"""Figures and tables of the deal.II example's scene b (the pull-out test, docs/dealii.md).

    /usr/bin/python3 plot_pullout.py compare --dealii LABEL=DIR/curve.csv ... \\
        --ccx LABEL=DIR/pullout ... --out FIGURE.png
    /usr/bin/python3 plot_pullout.py twist --dealii LABEL=DIR/curve.csv ... --out FIGURE.png

compare: the grip's force against its displacement for deal.II runs (curve.csv) and CalculiX
runs of the axisymmetric model (the job's path without extension: its .dat, made by
examples/calculix/pullout/run.py); prints a Markdown table of the forces at 0.52, 1.3 and
2.6 mm and each curve's first peak (a dot in the figure).
twist: pull, then twist: the torque and the grip's axial force against the twist angle, and
the interfaces' mean damage and slip around the bar.
"""
import argparse
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "scripts"))
import python_with  # noqa: E402  (the python3 that has the modules below)

python_with.modules("numpy", "matplotlib")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

LEVELS = (0.52, 1.3, 2.6)  # grip displacements of the table [mm]


def read_curve(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def read_ccx(job):
    """(displacement [mm], force [N]) of the grip of an axisymmetric CalculiX run."""
    sys.path.insert(0, os.path.join(HERE, "..", "calculix", "pullout"))
    import post  # noqa: E402
    _, _, top = post.read_inp(job + ".inp")
    forces = post.read_dat(job + ".dat")[("total force", "TOP")]
    t = np.array([0.0] + [tm for tm, _ in forces])
    return t * top, np.array([0.0] + [rows[0][1] * post.WEDGE for _, rows in forces])


def first_peak(s, f):
    """The first local maximum of the force, (displacement, force), located by the parabola
    through it and its two neighbours (the increments are 0.104 mm apart), or the sample
    itself before a drop of more than 10 %; None without one."""
    for k in range(1, len(f) - 1):
        if f[k] >= f[k - 1] and f[k] > f[k + 1]:
            if f[k + 1] < 0.9 * f[k]:  # a snap (the bond lets go at once): the sample
                return s[k], f[k]
            a, b, c = np.polyfit(s[k - 1:k + 2], f[k - 1:k + 2], 2)
            x = -b / (2 * a)
            return x, np.polyval([a, b, c], x)
    return None


def labelled(items):
    out = []
    for item in items:
        label, _, path = item.partition("=")
        out.append((label, path))
    return out


def finish(fig, axes, titles, xlabel, out):
    for ax, title in zip(axes, titles):
        ax.set_xlabel(xlabel)
        ax.set_title(title)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def compare(args):
    curves = []
    # The k-th deal.II run and the k-th CalculiX run share a colour (give them in the same
    # order of mesh sizes).
    for k, (label, path) in enumerate(labelled(args.dealii)):
        c = read_curve(path)
        curves.append((label, np.concatenate([[0.0], c["pull"]]),
                       np.concatenate([[0.0], c["force"]]), "-", f"C{k}"))
    for k, (label, job) in enumerate(labelled(args.ccx)):
        s, f = read_ccx(job)
        curves.append((label, s, f, "--", f"C{k}"))
    fig, ax = plt.subplots(1, 1, figsize=(7.5, 4.8))
    print("| run | " + " | ".join(f"F at {v} mm [kN]" for v in LEVELS) +
          " | first peak [kN] | at [mm] |")
    print("|---|" + "---|" * (len(LEVELS) + 2))
    for label, s, f, style, colour in curves:
        ax.plot(s, f / 1e3, style, color=colour, label=label)
        peak = first_peak(s, f)
        if peak:
            ax.plot(peak[0], peak[1] / 1e3, "o", color=colour, ms=4)
        cells = [f"{np.interp(v, s, f) / 1e3:.2f}" if v <= s[-1] + 1e-9 else "-"
                 for v in LEVELS]
        cells += [f"{peak[1] / 1e3:.2f}", f"{peak[0]:.3f}"] if peak else ["-", "-"]
        print(f"| {label} | " + " | ".join(cells) + " |")
    ax.set_ylabel("grip force [kN]")
    finish(fig, [ax], ["pull-out, elastic steel: 3D deal.II and axisymmetric CalculiX"],
           "grip displacement [mm]", args.out)


def twist(args):
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    for label, path in labelled(args.dealii):
        c = read_curve(path)
        on = c["twist_deg"] > 0
        first = np.argmax(on) - 1  # the increment before the twist: its start
        sel = np.r_[first, np.nonzero(on)[0]]
        a = c["twist_deg"][sel]
        axes[0].plot(a, c["torque"][sel] / 1e3, label=label)
        axes[1].plot(a, c["force"][sel] / 1e3, label=label)
        for key, style in (("clay", "-"), ("concrete", "--")):
            axes[2].plot(a, c[f"{key}_damage"][sel], style, label=f"{label}: {key}-bar damage")
        print(f"{label}: force {c['force'][sel][0] / 1e3:.2f} kN before the twist, "
              f"{c['force'][sel][-1] / 1e3:.2f} kN at {a[-1]:.1f} deg; largest torque "
              f"{np.max(c['torque']) / 1e3:.1f} N m at "
              f"{a[np.argmax(c['torque'][sel])]:.1f} deg; damage clay-bar "
              f"{c['clay_damage'][sel][-1]:.3f}, concrete-bar {c['concrete_damage'][sel][-1]:.3f}")
    axes[0].set_ylabel("torque on the grip [N m]")
    axes[1].set_ylabel("axial force on the grip [kN]")
    axes[2].set_ylabel("mean damage")
    finish(fig, axes, ("torque", "axial force held by the grip", "interfaces"),
           "twist of the grip [deg]", args.out)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("what", choices=("compare", "twist"))
    p.add_argument("--dealii", action="append", default=[], help="LABEL=curve.csv")
    p.add_argument("--ccx", action="append", default=[], help="LABEL=job path (no extension)")
    p.add_argument("--out", required=True, help="the PNG file")
    args = p.parse_args(argv)
    if args.what == "compare" and not args.ccx:
        p.error("compare needs at least one --ccx run")
    {"compare": compare, "twist": twist}[args.what](args)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
