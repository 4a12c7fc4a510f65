#!/usr/bin/python3
"""Export one case of an interlock-history HDF5 file as the text the C API's tests read
(tests/api/c_api/c_api_history.h): the material by its property names, then one row per step with
the separation, the traction and the state the UMAT's STATEV layout holds after that step,
assembled here from the named datasets (docs/history-output.md; the layout of
`interlock-query --statev`), so that the test checks the layout too.

usage: export_history.py FILE.h5 CASE OUT.txt

Format (whitespace-separated, reals with 17 significant digits):
    material M            then M lines `name value`
    rows R dim D statev S then R lines of D separations, D tractions, S STATEV values
"""
import sys

import h5py
import numpy as np

CODES = {"scheme": {"explicit": 1, "implicit": 2, "trapezoidal": 3},
         "ria": {"paper": 0, "azimuthal": 1}}
# deck attribute -> property name (interlock-query --props)
PROPERTIES = ["sigma0_n", "sigma0_t", "gc", "eta", "mu", "h_n", "theta0_deg", "thetaf_deg",
              "zeta0", "prefractured", "scheme", "substep_tol"]
EFFECTS = ["damage", "friction", "interlocking", "finite_depth", "wear"]


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    with h5py.File(sys.argv[1], "r") as f:
        case = f["cases"][sys.argv[2]]
        attrs = case.attrs
        dim = case["separation"].shape[1]
        material = []
        # (the RIA's per-plane values: theta_0, theta_f and zeta_0 of its steepest plane; the
        # angles are stored in radians and written back in degrees: the deck's decimal degrees
        # are recovered by rounding to 10 decimals)
        steepest = int(np.argmax(np.atleast_1d(attrs["theta0_deg"])))
        for name in PROPERTIES:
            value = attrs[name]
            if np.ndim(value) == 1:
                value = value[steepest]
                if name.endswith("_deg"):
                    value = round(float(value), 10)
            if isinstance(value, (bytes, str)):
                value = CODES[name][value.decode() if isinstance(value, bytes) else value]
            material.append((name, float(value)))
        for name in EFFECTS:
            material.append((name, float(attrs["effect_" + name])))
        if dim == 3:
            ria = attrs["ria"]
            ria = ria.decode() if isinstance(ria, bytes) else ria
            material.append(("ria", float(CODES["ria"][ria])))
            if ria == "azimuthal":
                material.append(("n_azimuths", float(attrs["n_azimuths"])))
        per_plane = ["damage", "beta", "frictional_slip", "zeta", "theta", "friction_traction"]
        rows = case["separation"].shape[0]
        # STATEV: the per-plane variables by variable, then plane; work, the two dissipations,
        # the flag; in 3D the strike components by variable, then plane.
        columns = [case[name][:] for name in per_plane]
        columns += [case[name][:].reshape(rows, 1) for name in
                    ("work", "damage_dissipation", "friction_dissipation")]
        columns.append(np.ones((rows, 1)))
        if dim == 3:
            columns += [case["sf_strike"][:], case["tauf_strike"][:]]
        statev = np.hstack(columns)
        table = np.hstack([case["separation"][:], case["traction"][:], statev])
    with open(sys.argv[3], "w") as out:
        out.write(f"material {len(material)}\n")
        for name, value in material:
            out.write(f"{name} {value!r}\n")
        out.write(f"rows {rows} dim {dim} statev {statev.shape[1]}\n")
        for row in table:
            out.write(" ".join(repr(float(x)) for x in row) + "\n")


if __name__ == "__main__":
    main()
