#!/usr/bin/python3
"""Plot the curves of an interlock-fit result: measured points against the fitted history.

usage: plot_fit.py FIT.h5 [-o FOLDER] [--combined PNG]

One PNG per curve, FOLDER/STEM_NAME.png (default FOLDER: the file's folder): the data in the
window (dots), the fitted history along the same abscissa (line), with the fitted values and
standard errors in the title; each loading cycle in its own colour (a cycle: from the first
point until the abscissa, after turning twice, passes its first value again in its first
direction). --combined also writes all curves side by side in one PNG, in the deck's order.
Needs h5py and matplotlib (/usr/bin/python3).
"""
import argparse
import os

import python_with  # the python3 that has the modules below

python_with.modules("h5py", "matplotlib", "numpy")
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

LABELS = {"time": "time", "separation_n": "dilation s_N [mm]", "separation_t": "slip s_T [mm]",
          "traction_n": "sigma_N [MPa]", "traction_t": "shear sigma_T [MPa]", "work": "work [N/mm]",
          "stored_energy": "stored energy [N/mm]", "damage_dissipation": "damage dissipation [N/mm]",
          "friction_dissipation": "friction dissipation [N/mm]",
          "separation_t1": "slip s_T1 [mm]", "separation_t2": "slip s_T2 [mm]",
          "traction_t1": "shear sigma_T1 [MPa]", "traction_t2": "shear sigma_T2 [MPa]",
          "traction_t_magnitude": "shear |sigma_T| [MPa]", "slip_length": "slip length [mm]"}


def text(value):
    return value.decode() if isinstance(value, (bytes, np.bytes_)) else str(value)


def cycles(x):
    """The cycle of each point of a path x (0, 1, ...): a new cycle starts where x, after
    turning twice, passes its first value again in its first direction."""
    x = np.asarray(x, dtype=float)
    cycle = np.zeros(x.size, dtype=int)
    if x.size < 3:
        return cycle
    tol = 1e-6 * (x.max() - x.min() or 1.0)
    x0, k, turns, direction, first, extreme = x[0], 0, 0, 0, 0, x[0]
    for i in range(1, x.size):
        step = x[i] - extreme
        if direction == 0:
            if abs(step) > tol:
                direction = first = 1 if step > 0 else -1
                extreme = x[i]
        elif step * direction >= 0:
            extreme = x[i]
        elif abs(step) > tol:
            turns += 1
            direction = -direction
            extreme = x[i]
        if turns >= 2 and direction == first and (x[i] - x0) * first > tol >= (x[i - 1] - x0) * first:
            k += 1
            turns = 0
        cycle[i] = k
    return cycle


def draw(ax, name, g):
    x, y = g["x"][()], g["y"][()]
    hx, hy = g["history_x"][()], g["history_y"][()]
    cx, ch = cycles(x), cycles(hx)
    step = max(1, x.size // 400)
    for k in range(max(cx.max(), ch.max()) + 1):
        colour = f"C{k % 10}"
        tag = f" cycle {k + 1}" if max(cx.max(), ch.max()) > 0 else ""
        on = np.flatnonzero(cx == k)[::step]
        if on.size:
            ax.plot(x[on], y[on], ".", ms=3, color=colour, alpha=0.45,
                    label=f"data{tag} ({np.count_nonzero(cx == k)} points)")
        rows = np.flatnonzero(ch == k)
        if rows.size:
            if k > 0 and rows[0] > 0:       # join the line to the previous cycle's end
                rows = np.concatenate([[rows[0] - 1], rows])
            ax.plot(hx[rows], hy[rows], "-", lw=1.2, color=colour, label=f"fit{tag}")
    ax.set_xlabel(LABELS.get(text(g.attrs["along"]), text(g.attrs["along"])))
    ax.set_ylabel(LABELS.get(text(g.attrs["against"]), text(g.attrs["against"])))
    ax.set_title(f"{name}: rms {float(g.attrs['rms']):.3g}", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("file")
    ap.add_argument("-o", "--output-dir")
    ap.add_argument("--combined")
    a = ap.parse_args()
    folder = a.output_dir or os.path.dirname(os.path.abspath(a.file))
    stem = os.path.splitext(os.path.basename(a.file))[0]
    with h5py.File(a.file, "r") as f:
        names = [text(s) for s in f.attrs["parameters"]]
        values, se = f.attrs["values"], f.attrs["std_error"]
        fitted = ", ".join(f"{n} = {v:.5g}" + (f" ± {s:.2g}" if s < 1e300 else "")
                           for n, v, s in zip(names, values, se))
        # the deck's order (HDF5 lists groups alphabetically)
        curves = [text(c) for c in f.attrs["curve_names"]]
        written = []
        for name in curves:
            fig, ax = plt.subplots(figsize=(6, 4.2))
            draw(ax, name, f["curves"][name])
            fig.suptitle(fitted, fontsize=8)
            fig.tight_layout()
            out = os.path.join(folder, f"{stem}_{name}.png")
            fig.savefig(out, dpi=110)
            plt.close(fig)
            written.append(out)
        if a.combined:
            fig, axes = plt.subplots(1, len(curves), figsize=(3.6 * len(curves), 3.4), squeeze=False)
            for ax, name in zip(axes[0], curves):
                draw(ax, name, f["curves"][name])
            fig.suptitle(fitted, fontsize=8)
            fig.tight_layout()
            fig.savefig(a.combined, dpi=90)
            plt.close(fig)
            written.append(a.combined)
    for out in written:
        print(out)


if __name__ == "__main__":
    main()
