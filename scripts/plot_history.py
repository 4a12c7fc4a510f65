#!/usr/bin/python3
"""Plot interlock-history results laid out like the paper's figures.

usage: plot_history.py FILE.h5 [FILE.h5 ...] [-o PNG] [--compare FILE]

One PNG per HDF5 file: (a) shear traction sigma_T vs slip s_T and (b) dilation s_N vs slip s_T,
side by side, one curve per case, the legend from the swept value. -o names the PNG (one input
file only; default: the input's name with .png). --compare overlays another HDF5 file written by
interlock-history (dashed, every case) or a reference CSV with the columns
time, s_N, s_T, sigma_N, sigma_T, ... (dashed black). Needs h5py and matplotlib.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def text(value):
    return value.decode() if isinstance(value, (bytes, np.bytes_)) else str(value)


def read_h5(path):
    """[(label, s (n, 2), sigma (n, 2), status)], title."""
    curves = []
    with h5py.File(path, "r") as f:
        title = text(f.attrs.get("title", "")) or os.path.basename(path)
        for name in sorted(f["cases"]):
            g = f["cases"][name]
            label = text(g.attrs.get("label", "")) or os.path.splitext(os.path.basename(path))[0]
            status = text(g.attrs.get("status", ""))
            if status != "completed":
                label += " (stopped)"
            curves.append((label, g["separation"][()], g["traction"][()], status))
    return curves, title


def read_csv(path):
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return [(os.path.basename(path), data[:, 1:3], data[:, 3:5], "completed")]


def plot(path, png, compare):
    curves, title = read_h5(path)
    fig, (ax_t, ax_n) = plt.subplots(1, 2, figsize=(12, 4.8))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, (label, s, sigma, _) in enumerate(curves):
        c = colors[i % len(colors)]
        ax_t.plot(s[:, 1], sigma[:, 1], color=c, lw=1.4, label=label)
        ax_n.plot(s[:, 1], s[:, 0], color=c, lw=1.4, label=label)
    if compare:
        if compare.lower().endswith(".csv"):
            extra = read_csv(compare)
        else:
            extra = [(f"{lab} [{os.path.basename(compare)}]", s, sg, st)
                     for lab, s, sg, st in read_h5(compare)[0]]
        for i, (label, s, sigma, _) in enumerate(extra):
            c = "k" if len(extra) == 1 else colors[i % len(colors)]
            ax_t.plot(s[:, 1], sigma[:, 1], "--", color=c, lw=1.0, label=label)
            ax_n.plot(s[:, 1], s[:, 0], "--", color=c, lw=1.0, label=label)
    ax_t.set_xlabel("slip $s_T$ [mm]")
    ax_t.set_ylabel(r"shear traction $\sigma_T$ [MPa]")
    ax_t.set_title("(a) shear traction vs slip")
    ax_n.set_xlabel("slip $s_T$ [mm]")
    ax_n.set_ylabel("dilation $s_N$ [mm]")
    ax_n.set_title("(b) dilation vs slip")
    for ax in (ax_t, ax_n):
        ax.grid(True, lw=0.3)
    ax_n.legend(fontsize=8, loc="best")
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)
    print(png)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("files", nargs="+", help="HDF5 files written by interlock-history")
    parser.add_argument("-o", dest="output", help="PNG to write (one input file only)")
    parser.add_argument("--compare", help="HDF5 file or reference CSV to overlay")
    args = parser.parse_args(argv)
    if args.output and len(args.files) > 1:
        parser.error("-o needs exactly one input file")
    for path in args.files:
        png = args.output or os.path.splitext(path)[0] + ".png"
        plot(path, png, args.compare)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
