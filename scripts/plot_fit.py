#!/usr/bin/python3
"""Plot the curves of an interlock-fit result: measured points against the fitted history.

usage: plot_fit.py FIT.h5 [-o FOLDER] [--combined PNG]

One PNG per curve, FOLDER/STEM_NAME.png (default FOLDER: the file's folder): the data in the
window (dots), the fitted history along the same abscissa (line), with the fitted values and
standard errors in the title. --combined also writes all curves side by side in one PNG.
Needs h5py and matplotlib (/usr/bin/python3).
"""
import argparse
import os

import matplotlib

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

LABELS = {"time": "time", "separation_n": "dilation s_N [mm]", "separation_t": "slip s_T [mm]",
          "traction_n": "sigma_N [MPa]", "traction_t": "shear sigma_T [MPa]", "work": "work [N/mm]",
          "stored_energy": "stored energy [N/mm]", "damage_dissipation": "damage dissipation [N/mm]",
          "friction_dissipation": "friction dissipation [N/mm]"}


def text(value):
    return value.decode() if isinstance(value, (bytes, np.bytes_)) else str(value)


def draw(ax, name, g):
    x, y = g["x"][()], g["y"][()]
    step = max(1, x.size // 400)
    ax.plot(x[::step], y[::step], ".", ms=3, color="0.45", label=f"data ({x.size} points)")
    ax.plot(g["history_x"][()], g["history_y"][()], "-", lw=1.2, color="C0", label="fit")
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
        names = [s.strip() for s in text(f.attrs["parameters"]).split(",")]
        values, se = f.attrs["values"], f.attrs["std_error"]
        fitted = ", ".join(f"{n} = {v:.5g}" + (f" ± {s:.2g}" if s < 1e300 else "")
                           for n, v, s in zip(names, values, se))
        curves = sorted(f["curves"])
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
