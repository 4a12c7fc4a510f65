"""The figure of docs/dealii.md: scene a (the joint between rigid platens) against
interlock-history on the matching deck, and scene block (the joint between elastic blocks) on
several numbers of processes.

usage: /usr/bin/python3 plot_curves.py SHEAR_CURVE.csv HISTORY.h5 OUT.png [NP:BLOCK_CURVE.csv ...]
"""
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read(path):
    return np.genfromtxt(path, delimiter=",", names=True)


def main():
    shear, history, out = sys.argv[1:4]
    blocks = [a.split(":", 1) for a in sys.argv[4:]]
    fe = read(shear)
    with h5py.File(history, "r") as f:
        s = f["cases/0001/separation"][()]
        t = f["cases/0001/traction"][()]
    slip = np.hypot(s[:, 1], s[:, 2])
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    ax[0].plot(slip, t[:, 1], "-", color="C0", label="interlock-history: sigma_T1")
    ax[0].plot(slip, t[:, 2], "-", color="C1", label="interlock-history: sigma_T2")
    fe_slip = np.hypot(fe["s_t1"], fe["s_t2"])
    ax[0].plot(fe_slip, fe["sigma_t1"], "o", color="C0", mfc="none", label="deal.II np 2: sigma_T1")
    ax[0].plot(fe_slip, fe["sigma_t2"], "s", color="C1", mfc="none", label="deal.II np 2: sigma_T2")
    ax[0].set_xlabel("slip |s_T| [mm] (at 45 deg)")
    ax[0].set_ylabel("shear traction [MPa]")
    ax[0].set_title("scene a: the joint between rigid platens")
    ax[0].legend(fontsize=8)
    ax[1].plot(slip, s[:, 0], "-", color="C2", label="interlock-history")
    ax[1].plot(fe_slip, fe["s_n"], "o", color="C2", mfc="none", label="deal.II np 2")
    ax[1].set_xlabel("slip |s_T| [mm]")
    ax[1].set_ylabel("dilation s_N [mm]")
    ax[1].set_title("scene a: dilation under sigma_N = -1.5 MPa")
    ax[1].legend(fontsize=8)
    markers = ["-", "o", "x", "+"]
    for i, (n, path) in enumerate(blocks):
        b = read(path)
        u = np.hypot(b["platen_ux"], b["platen_uy"])
        ax[2].plot(u, np.hypot(b["sigma_t1"], b["sigma_t2"]), markers[i % 4],
                   mfc="none", label=f"np {n}: |sigma_T|, the layer's mean")
    ax[2].set_xlabel("platen slip [mm]")
    ax[2].set_ylabel("mean shear traction [MPa]")
    ax[2].set_title("scene block: elastic blocks, cut-backs")
    ax[2].legend(fontsize=8)
    for a in ax:
        a.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
