#!/usr/bin/python3
"""Check the layout of HDF5 files written by interlock-history (docs/history-output.md).

usage: check_history_h5.py [--allow-stopped] FILE.h5 [...]
Exit status 0 when every file follows the contract; the failures are printed otherwise.
The datasets checked are those the case's `stored` attribute lists (&output store; it must list
exactly the datasets of the case, time, separation and traction always); a completed case holds
the rows that `every` keeps of its n_steps (0, every, 2 every, ... and the last). Every text
attribute is a variable-length UTF-8 string (h5py returns str, not bytes).
"""
import sys

import h5py
import numpy as np

FILE_ATTRS = ["program", "version", "command_line", "deck", "deck_file", "title", "n_cases",
              "sweep_parameter"]
CASE_TEXT_ATTRS = ["status", "label", "sweep_parameter", "effects", "scheme", "normal_control",
                   "tangential_control", "extrapolation", "stored"]
PROPERTIES = {"sigma0_n": "MPa", "sigma0_t": "MPa", "gc": "N/mm", "eta": "-", "mu": "-",
              "h_n": "mm", "theta0_deg": "deg", "thetaf_deg": "deg", "zeta0": "N/mm",
              "prefractured": "-", "substep_tol": "-", "gamma_hat": "-"}
EFFECTS = ["damage", "friction", "interlocking", "finite_depth", "wear"]
# name -> (columns: None = (n), 2 = (n, 2), 'planes' = (n, n_planes), unit, integer?)
DATASETS = {
    "time": (None, "-", False), "separation": (2, "mm", False), "traction": (2, "MPa", False),
    "damage": ("planes", "-", False), "beta": ("planes", "-", False),
    "theta": ("planes", "rad", False), "zeta": ("planes", "N/mm", False),
    "frictional_slip": ("planes", "mm", False), "friction_traction": ("planes", "MPa", False),
    "work": (None, "N/mm", False), "stored_energy": (None, "N/mm", False),
    "damage_dissipation": (None, "N/mm", False), "friction_dissipation": (None, "N/mm", False),
    "iterations": (None, "-", True), "substeps": (None, "-", True),
    "sf_strike": ("planes", "mm", False), "tauf_strike": ("planes", "MPa", False),
}
THREE_D_DATASETS = ["sf_strike", "tauf_strike"]  # in 3D cases only
THREE_D_ATTRS = ["frame", "components", "t2_control", "ria", "n_azimuths", "phi_deg", "path"]
ALWAYS = ["time", "separation", "traction"]          # written whatever &output store says


def kept_rows(n_computed, every):
    """The 0-based rows written with &output every: 0, every, 2 every, ... and the last."""
    rows = list(range(0, n_computed, every))
    if n_computed > 0 and rows[-1] != n_computed - 1:
        rows.append(n_computed - 1)
    return rows


def text(value):
    return value.decode() if isinstance(value, (bytes, np.bytes_)) else str(value)


def byte_strings(f):
    """Every text attribute is a variable-length UTF-8 string, which h5py returns as str: the
    names of the attributes that come back as bytes (fixed-length byte strings) instead."""
    found = []

    def visit(name, obj):
        for a, v in obj.attrs.items():
            if isinstance(v, (bytes, np.bytes_)) or (isinstance(v, np.ndarray) and v.dtype.kind == "S"):
                found.append(f"{name or '/'}:{a}")
    visit("", f)
    f.visititems(visit)
    return found


def check_file(path, allow_stopped):
    errors = []
    with h5py.File(path, "r") as f:
        wrong = byte_strings(f)
        if wrong:
            errors.append(f"{len(wrong)} text attributes are byte strings, not UTF-8 strings "
                          f"(h5py returns bytes), e.g. {wrong[:3]}")
        for a in FILE_ATTRS:
            if a not in f.attrs:
                errors.append(f"file attribute '{a}' missing")
        if text(f.attrs.get("program", "")) != "interlock-history":
            errors.append("attribute program is not 'interlock-history'")
        if len(text(f.attrs.get("deck", ""))) == 0:
            errors.append("the deck's text is empty")
        if "cases" not in f:
            return errors + ["group /cases missing"]
        names = sorted(f["cases"])
        n_cases = int(f.attrs.get("n_cases", -1))
        if names != [f"{i:04d}" for i in range(1, n_cases + 1)]:
            errors.append(f"/cases holds {names}, expected 0001..{n_cases:04d}")
        for name in names:
            g = f["cases"][name]
            where = f"/cases/{name}"
            for a in CASE_TEXT_ATTRS:
                if a not in g.attrs:
                    errors.append(f"{where}: attribute '{a}' missing")
            status = text(g.attrs.get("status", ""))
            if status != "completed" and not allow_stopped:
                errors.append(f"{where}: status is '{status}', not 'completed'")
            for p, unit in PROPERTIES.items():
                if p not in g.attrs:
                    errors.append(f"{where}: property attribute '{p}' missing")
                elif text(g.attrs.get(p + "_unit", "")) != unit:
                    errors.append(f"{where}: '{p}_unit' is not '{unit}'")
            for e in EFFECTS:
                if "effect_" + e not in g.attrs:
                    errors.append(f"{where}: attribute 'effect_{e}' missing")
            extrapolated = g.attrs.get("extrapolated", None)
            if extrapolated is None:
                errors.append(f"{where}: attribute 'extrapolated' missing")
            elif int(extrapolated) not in (0, 1):
                errors.append(f"{where}: extrapolated = {extrapolated}, not 0 or 1")
            elif (int(extrapolated) == 1) != (len(text(g.attrs.get("extrapolation", ""))) > 0):
                errors.append(f"{where}: extrapolated = {int(extrapolated)} but the 'extrapolation' "
                              "description is " + ("empty" if int(extrapolated) else "not empty"))
            if text(g.attrs.get("sweep_parameter", "")) and "sweep_value" not in g.attrs:
                errors.append(f"{where}: a sweep without 'sweep_value'")
            n_planes = int(g.attrs.get("n_planes", 0))
            if not 1 <= n_planes <= 13:
                errors.append(f"{where}: n_planes = {n_planes}")
            # A 3D case (SPEC section 9) says so: the frame, N, T1, T2 columns; a 2D case has
            # none of its attributes and datasets.
            three_d = "components" in g.attrs
            if three_d:
                for a in THREE_D_ATTRS:
                    if a not in g.attrs:
                        errors.append(f"{where}: 3D case without attribute '{a}'")
                if text(g.attrs.get("components", "")) != "N, T1, T2":
                    errors.append(f"{where}: components = '{text(g.attrs.get('components', ''))}'")
            else:
                for a in THREE_D_ATTRS:
                    if a in g.attrs:
                        errors.append(f"{where}: 2D case with the 3D attribute '{a}'")
                for d in THREE_D_DATASETS:
                    if d in g:
                        errors.append(f"{where}: 2D case with the 3D dataset '{d}'")
            # &output store and every: the `stored` attribute lists exactly the datasets of the
            # case (in the order of DATASETS), `every` the thinning of the rows.
            stored = [s for s in text(g.attrs.get("stored", "")).split(",") if s]
            unknown = [s for s in stored if s not in DATASETS]
            if unknown:
                errors.append(f"{where}: 'stored' names unknown datasets {unknown}")
            if three_d and text(g.attrs.get("stored", "")) and not all(
                    d in stored for d in THREE_D_DATASETS if d in g):
                errors.append(f"{where}: 'stored' lacks a 3D dataset it holds")
            if stored != [d for d in DATASETS if d in stored]:
                errors.append(f"{where}: 'stored' = {stored} is not in the documented order")
            if not all(d in stored for d in ALWAYS):
                errors.append(f"{where}: 'stored' = {stored} lacks one of {ALWAYS}")
            if sorted(g) != sorted(stored):
                errors.append(f"{where}: holds the datasets {sorted(g)}, 'stored' says {sorted(stored)}")
            every = int(g.attrs.get("every", 0))
            if every < 1:
                errors.append(f"{where}: every = {every} (missing or < 1)")
                every = 1
            n = int(g.attrs.get("n_rows", -1))
            n_steps = int(g.attrs.get("n_steps", -2))
            if status == "completed" and n != len(kept_rows(n_steps, every)):
                errors.append(f"{where}: completed with {n} rows for {n_steps} steps and every = {every}")
            for d, (cols, unit, integer) in DATASETS.items():
                if d not in g:
                    if d in stored:
                        errors.append(f"{where}: dataset '{d}' missing")
                    continue
                ds = g[d]
                pair = 3 if three_d else 2
                shape = (n,) if cols is None else (n, pair if cols == 2 else n_planes)
                if ds.shape != shape:
                    errors.append(f"{where}/{d}: shape {ds.shape}, expected {shape}")
                if text(ds.attrs.get("unit", "")) != unit:
                    errors.append(f"{where}/{d}: unit '{text(ds.attrs.get('unit', ''))}', expected '{unit}'")
                if len(text(ds.attrs.get("description", ""))) < 10:
                    errors.append(f"{where}/{d}: no description")
                x = ds[()]
                if integer != np.issubdtype(x.dtype, np.integer):
                    errors.append(f"{where}/{d}: dtype {x.dtype}")
                if not integer and not np.all(np.isfinite(x)):
                    errors.append(f"{where}/{d}: holds NaN or Inf")
            if errors:
                continue
            if n > 1 and not np.all(np.diff(g["time"][()]) > 0):
                errors.append(f"{where}/time: not strictly increasing")
            if n > 0 and "substeps" in g and g["substeps"][()].min() < 1:
                errors.append(f"{where}: substeps < 1")
            if n > 0 and "iterations" in g and g["iterations"][()].min() < 0:
                errors.append(f"{where}: iterations < 0")
            if n > 0 and "damage" in g and (g["damage"][()].min() < 0 or g["damage"][()].max() > 1):
                errors.append(f"{where}/damage: outside [0, 1]")
    return errors


def main(argv):
    allow = "--allow-stopped" in argv
    files = [a for a in argv if a != "--allow-stopped"]
    if not files:
        print(__doc__)
        return 2
    failed = 0
    for path in files:
        try:
            errors = check_file(path, allow)
        except (OSError, KeyError) as exc:
            errors = [f"cannot read: {exc}"]
        for e in errors:
            print(f"{path}: {e}")
        print(f"{path}: {'ok' if not errors else 'FAILED'}")
        failed += bool(errors)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
