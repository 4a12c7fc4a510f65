#!/usr/bin/python3
"""Plot interlock-history results laid out like the paper's figures.

usage: plot_history.py FILE.h5 [FILE.h5 ...] [-o PNG] [--compare FILE] [--axis t1|t2]

One PNG per HDF5 file: (a) shear traction sigma_T vs slip s_T and (b) dilation s_N vs slip s_T,
side by side, one curve per case, the legend from the swept value. -o names the PNG (one input
file only; default: the input's name with .png). --compare overlays another HDF5 file written by
interlock-history (dashed, every case) or a reference CSV with the columns
time, s_N, s_T, sigma_N, sigma_T, ... (dashed black). Needs h5py and matplotlib.

A 3D file (cases with the columns N, T1, T2; docs/three-dimensions.md) gives four panels:
(a) the slip path in the (s_T1, s_T2) plane, (b) the shear traction against the slip length
(the length of the path in the (T1, T2) plane): its magnitude |sigma_T| (solid) and, for up to
three cases, sigma_T1 (dashed) and sigma_T2 (dotted), (c) the dilation s_N against the slip
length, and (d) for a sweep over the slip direction (&sweep parameter = 'angle_deg') a polar
plot of the peak and the residual (last row) |sigma_T| against the direction, otherwise the
traction path in the (sigma_T1, sigma_T2) plane. --axis t1 or t2 plots (b) and (c) against
s_T1 or s_T2 instead, each case from its last row where that component was zero (the last leg
along it: the induced-anisotropy scene compared with a virgin joint).
"""
import argparse
import os
import sys

import python_with  # the python3 that has the modules below

python_with.modules("h5py", "matplotlib", "numpy")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def text(value):
    return value.decode() if isinstance(value, (bytes, np.bytes_)) else str(value)


def is_3d(path):
    with h5py.File(path, "r") as f:
        return any("components" in f["cases"][name].attrs for name in f["cases"])


def read_h5(path):
    """[(label, s (n, 2 or 3), sigma (n, 2 or 3), status)], title."""
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


def slip_length(s):
    """The length of the slip path in the (T1, T2) plane at each row (0 at row 0)."""
    steps = np.hypot(np.diff(s[:, 1]), np.diff(s[:, 2]))
    return np.concatenate([[0.0], np.cumsum(steps)])


def last_leg(x):
    """The rows from the last one where x was zero (the last leg along that component)."""
    zero = np.nonzero(x == 0.0)[0]
    return slice(int(zero[-1]) if len(zero) else 0, None)


def direction_sweep(path):
    """[(angle_deg, peak |sigma_T|, residual |sigma_T|)] of a sweep over the slip direction,
    else []."""
    with h5py.File(path, "r") as f:
        if text(f.attrs.get("sweep_parameter", "")) != "angle_deg":
            return []
        rows = []
        for name in sorted(f["cases"]):
            g = f["cases"][name]
            tau = np.hypot(g["traction"][:, 1], g["traction"][:, 2])
            rows.append((float(g.attrs["sweep_value"]), float(tau.max()), float(tau[-1])))
    return rows


def plot_3d(path, png, compare, axis):
    curves, title = read_h5(path)
    fig = plt.figure(figsize=(12, 9.6))
    ax_p = fig.add_subplot(2, 2, 1)
    ax_t = fig.add_subplot(2, 2, 2)
    ax_n = fig.add_subplot(2, 2, 3)
    sweep = direction_sweep(path)
    ax_d = fig.add_subplot(2, 2, 4, projection="polar" if sweep else None)
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    extra = []
    if compare:
        extra = [(f"{lab} [{os.path.basename(compare)}]", s, sg, st)
                 for lab, s, sg, st in read_h5(compare)[0]]
    column = {"t1": 1, "t2": 2}.get(axis)
    for i, (label, s, sigma, _) in enumerate(curves + extra):
        dashed = i >= len(curves)
        c = colors[i % len(colors)]
        tau = np.hypot(sigma[:, 1], sigma[:, 2])
        ax_p.plot(s[:, 1], s[:, 2], "--" if dashed else "-", color=c, lw=1.2, label=label)
        if column:
            keep = last_leg(s[:, column])
            x = s[keep, column]
            ax_t.plot(x, sigma[keep, column], "--" if dashed else "-", color=c, lw=1.4, label=label)
            ax_n.plot(x, s[keep, 0], "--" if dashed else "-", color=c, lw=1.4, label=label)
        else:
            x = slip_length(s)
            ax_t.plot(x, tau, "--" if dashed else "-", color=c, lw=1.4, label=label)
            if len(curves) + len(extra) <= 3:
                ax_t.plot(x, sigma[:, 1], "--", color=c, lw=0.9)
                ax_t.plot(x, sigma[:, 2], ":", color=c, lw=0.9)
            ax_n.plot(x, s[:, 0], "--" if dashed else "-", color=c, lw=1.4, label=label)
        if not sweep:
            ax_d.plot(sigma[:, 1], sigma[:, 2], "--" if dashed else "-", color=c, lw=1.0,
                      label=label)
    ax_p.set_xlabel("slip $s_{T1}$ [mm]")
    ax_p.set_ylabel("slip $s_{T2}$ [mm]")
    ax_p.set_title("(a) slip path in the ($t_1$, $t_2$) plane")
    ax_p.set_aspect("equal", adjustable="datalim")
    if column:
        name = f"T{column}"
        ax_t.set_xlabel(f"slip $s_{{{name}}}$ [mm] (last leg along $t_{column}$)")
        ax_t.set_ylabel(f"shear traction $\\sigma_{{{name}}}$ [MPa]")
        ax_t.set_title(f"(b) shear traction along $t_{column}$")
        ax_n.set_xlabel(f"slip $s_{{{name}}}$ [mm] (last leg along $t_{column}$)")
    else:
        ax_t.set_xlabel("slip length [mm]")
        ax_t.set_ylabel(r"shear traction [MPa]: $|\sigma_T|$ (solid), $\sigma_{T1}$ (dashed), "
                        r"$\sigma_{T2}$ (dotted)", fontsize=8)
        ax_t.set_title("(b) shear traction vs slip length")
        ax_n.set_xlabel("slip length [mm]")
    ax_n.set_ylabel("dilation $s_N$ [mm]")
    ax_n.set_title("(c) dilation")
    if sweep:
        a = np.radians([r[0] for r in sweep])
        ax_d.plot(a, [r[1] for r in sweep], "o-", lw=1.4, label=r"peak $|\sigma_T|$")
        ax_d.plot(a, [r[2] for r in sweep], "s--", lw=1.2, label=r"residual $|\sigma_T|$ (end)")
        ax_d.set_thetamin(min(0.0, np.degrees(a.min())))
        ax_d.set_thetamax(max(90.0, np.degrees(a.max())))
        ax_d.set_title("(d) shear traction [MPa] against the slip direction (deg from $t_1$)",
                       fontsize=10)
        ax_d.legend(fontsize=8, loc="lower left")
    else:
        ax_d.set_xlabel(r"$\sigma_{T1}$ [MPa]")
        ax_d.set_ylabel(r"$\sigma_{T2}$ [MPa]")
        ax_d.set_title("(d) traction path in the ($t_1$, $t_2$) plane")
        ax_d.set_aspect("equal", adjustable="datalim")
        ax_d.grid(True, lw=0.3)
    if len(curves) + len(extra) <= 16:
        ax_n.legend(fontsize=7, loc="best")
    finish(fig, (ax_p, ax_t, ax_n), title, png)


def plot(path, png, compare, axis=None):
    if is_3d(path):
        plot_3d(path, png, compare, axis)
        return
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
    ax_n.legend(fontsize=8, loc="best")
    finish(fig, (ax_t, ax_n), title, png)


def finish(fig, axes, title, png):
    """Grid the axes, title the figure and write the PNG."""
    for ax in axes:
        ax.grid(True, lw=0.3)
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)
    print(png)


def plot_polar(paths, png):
    """One polar figure of the peak (and residual) shear against the slip direction for
    several direction sweeps, one curve per file (labelled by its RIA): how the direction
    dependence of a RIA changes with its azimuths. Mirrored about t1 and t2 (the RIAs are
    symmetric under s_T1 -> -s_T1 and s_T2 -> -s_T2) to a full turn."""
    fig = plt.figure(figsize=(7.5, 7.5))
    ax = fig.add_subplot(1, 1, 1, projection="polar")
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, path in enumerate(paths):
        sweep = direction_sweep(path)
        if not sweep:
            raise SystemExit(f"plot_history.py: {path} is not a sweep over the slip direction")
        with h5py.File(path, "r") as f:
            g = f["cases"][sorted(f["cases"])[0]]
            ria = text(g.attrs.get("ria", ""))
            n_a = g.attrs.get("n_azimuths", None)
        label = ria + (f" N_a = {int(n_a)}" if ria == "azimuthal" and n_a is not None else "")
        deg = np.array([r[0] for r in sweep])
        peak = np.array([r[1] for r in sweep])
        resid = np.array([r[2] for r in sweep])
        full = np.concatenate([deg, 180.0 - deg[::-1], 180.0 + deg, 360.0 - deg[::-1]])
        c = colors[i % len(colors)]
        ax.plot(np.radians(full), np.concatenate([peak, peak[::-1], peak, peak[::-1]]), "-",
                color=c, lw=1.6, label=f"{label}: peak")
        ax.plot(np.radians(full), np.concatenate([resid, resid[::-1], resid, resid[::-1]]), ":",
                color=c, lw=1.0, label=f"{label}: residual")
    ax.set_title("shear traction $|\\sigma_T|$ [MPa] against the slip direction "
                 "(deg from $t_1$)", fontsize=10)
    ax.legend(fontsize=8, loc="lower left", bbox_to_anchor=(-0.1, -0.12))
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)
    print(png)


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("files", nargs="+", help="HDF5 files written by interlock-history")
    parser.add_argument("-o", dest="output", help="PNG to write (one input file only)")
    parser.add_argument("--compare", help="HDF5 file or reference CSV to overlay")
    parser.add_argument("--axis", choices=["t1", "t2"],
                        help="3D files: traction and dilation against s_T1 or s_T2 (last leg)")
    parser.add_argument("--polar", action="store_true",
                        help="direction sweeps: one polar figure of all the files (needs -o)")
    args = parser.parse_args(argv)
    if args.polar:
        if not args.output:
            parser.error("--polar needs -o PNG")
        plot_polar(args.files, args.output)
        return 0
    if args.output and len(args.files) > 1:
        parser.error("-o needs exactly one input file")
    for path in args.files:
        png = args.output or os.path.splitext(path)[0] + ".png"
        plot(path, png, args.compare, args.axis)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
