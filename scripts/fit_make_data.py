#!/usr/bin/python3
"""Measured-curve CSV files from a history: run interlock-history on a deck and write its rows as
CSV (the columns interlock-fit decks read), optionally with deterministic noise.

usage: fit_make_data.py PROGRAM DECK.nml OUT.csv [--noise FRACTION] [--seed N]
                        [--cycle-start T0 --cycle-period T]

A fit deck (one with &fit) is run without its &fit group: the curves of the values its
&interface and &microplanes give.
Columns: time, cycle, slip (separation_t, mm), dilation (separation_n, mm), shear (traction_t,
MPa), normal (traction_n, MPa). cycle = 1 + floor((time - T0) / T) for time > T0 (the deck's
`cycles` repeat the block of period T = times(n) - times(1) after the preload), 1 without
--cycle-period. --noise f adds independent normal noise of standard deviation f max|column| to
dilation and shear (numpy's default_rng(seed): the same file on every machine and run).
A 3D deck (three components, docs/deck-format.md "Three dimensions") gives the columns time,
cycle, slip_t1, slip_t2 (s_T1, s_T2, mm), slip_length (the length of the slip path in the
(T1, T2) plane, mm: interlock-fit's slip_length), dilation, shear_t1, shear_t2 (sigma_T1,
sigma_T2, MPa), shear (|sigma_T|, MPa), normal; the noise goes to dilation, shear_t1, shear_t2 and
shear.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile

import python_with  # the python3 that has the modules below

python_with.modules("h5py", "numpy")
import h5py  # noqa: E402
import numpy as np  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("program")
    ap.add_argument("deck")
    ap.add_argument("out")
    ap.add_argument("--noise", type=float, default=0.0)
    ap.add_argument("--seed", type=int, default=12)
    ap.add_argument("--cycle-start", type=float, default=0.0)
    ap.add_argument("--cycle-period", type=float, default=0.0)
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as work:
        deck = a.deck
        with open(deck) as f:
            text = f.read()
        if re.search(r"^\s*&fit\b", text, re.M | re.I):
            # a fit deck: its history part, with the values of its &interface and &microplanes
            deck = os.path.join(work, os.path.basename(a.deck))
            with open(deck, "w") as f:
                f.write(re.sub(r"^\s*&fit\b.*?^\s*/\s*$", "", text, flags=re.M | re.S | re.I))
        run = subprocess.run([a.program, "--output-dir", work, deck], capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"fit_make_data: interlock-history failed: {run.stderr}")
        name = os.path.splitext(os.path.basename(a.deck))[0] + ".h5"
        with h5py.File(os.path.join(work, name), "r") as f:
            case = f["cases/0001"]
            time = case["time"][()]
            sep = case["separation"][()]
            trac = case["traction"][()]
    cycle = np.ones_like(time)
    if a.cycle_period > 0:
        cycle = np.maximum(1, 1 + np.floor((time - a.cycle_start) / a.cycle_period - 1e-9))
    if sep.shape[1] == 3:
        steps = np.hypot(np.diff(sep[:, 1]), np.diff(sep[:, 2]))
        names = ["slip_t1", "slip_t2", "slip_length", "dilation", "shear_t1", "shear_t2",
                 "shear", "normal"]
        columns = [sep[:, 1], sep[:, 2], np.concatenate([[0.0], np.cumsum(steps)]),
                   sep[:, 0].copy(), trac[:, 1].copy(), trac[:, 2].copy(),
                   np.hypot(trac[:, 1], trac[:, 2]), trac[:, 0]]
        noisy = [3, 4, 5, 6]
    else:
        names = ["slip", "dilation", "shear", "normal"]
        columns = [sep[:, 1], sep[:, 0].copy(), trac[:, 1].copy(), trac[:, 0]]
        noisy = [1, 2]
    if a.noise > 0:
        rng = np.random.default_rng(a.seed)
        for k in noisy:
            columns[k] = columns[k] + rng.normal(0.0, a.noise * np.abs(columns[k]).max(),
                                                 columns[k].size)
    with open(a.out, "w") as f:
        f.write(",".join(["time", "cycle"] + names) + "\n")
        for row in zip(time, cycle, *columns):
            f.write(",".join(repr(float(v)) for v in row) + "\n")


if __name__ == "__main__":
    main()
