#!/usr/bin/python3
"""Writes the CalculiX input of the paper's pull-out test (section 4.2, Shima et al. 1987).

Axisymmetric CAX4 model (x = radius, y = bar axis, the loaded end at the top, y = L):

    bar        0 <= r <= D/2                  steel, von Mises, isotropic hardening (Table 4)
    layer      D/2 <= r <= D/2 + h            interlock thin-layer UMAT (Table 5): clay-bar over
                                              the top 10 D, concrete-bar below
    concrete   D/2 + h <= r <= R              linear elastic (Table 3)

The bar's top face is pulled to --top-displacement (displacement control, all its nodes
together: the grip); the concrete's top face bears on the reaction plate (u_y = 0); the axis has
u_r = 0. The mesh is structured: --element mm along the bar and radially up to
--uniform-radius, then radial sizes growing geometrically (ratio <= 1.15) to the block's radius.

    /usr/bin/python3 make_mesh.py --output DIR/pullout.inp [--element 5] [--radius 500] ...

The layer material is the interlock UMAT (--layer umat, needs ccx linked with it) or an
isotropic elastic stand-in of the same initial stiffness (--layer elastic, for Debian's stock
ccx, which cannot load a user material).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "scripts"))
import python_with  # noqa: E402  (the python3 that has the modules below)

python_with.modules("numpy")
import numpy as np  # noqa: E402

BAR_DIAMETER = 19.5           # mm (paper 4.2.1)
SLEEVE_LENGTH = 10.0 * BAR_DIAMETER   # clay sleeve at the loaded end, mm

# Table 3
E_CONCRETE, NU_CONCRETE = 2621.0, 0.2
E_STEEL, NU_STEEL = 190000.0, 0.3
# Table 4: hardened yield strength [MPa] vs equivalent plastic strain
HARDENING = [(350.0, 0.0), (350.0, 0.0146), (360.0, 0.0164), (390.0, 0.0206), (400.0, 0.0224),
             (410.0, 0.0242), (415.0, 0.026), (427.0, 0.0278), (433.0, 0.0292),
             (444.0, 0.0314), (450.0, 0.0352), (460.0, 0.038)]
# Table 5: sigma0_n = sigma0_t, Gc_bar, eta, mu, theta0 [deg], thetaf [deg], H_N [mm], zeta0
INTERFACES = {
    "CONCBAR": (1.0, 0.1, 0.995, 0.7, 45.0, 0.0, 1.5, 33.3),
    "CLAYBAR": (0.5, 0.05, 0.995, 0.6, 1.75, 0.0, 0.5, 33.3),
}


def write_text(path, text):
    """Writes a whole file under a temporary name and renames it: never half-written."""
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--output", required=True, help="the .inp file to write")
    p.add_argument("--element", type=float, default=5.0, help="element length [mm] (5)")
    p.add_argument("--embedment", type=float, default=50.0 * BAR_DIAMETER,
                   help="embedded length [mm] (50 D = 975)")
    p.add_argument("--radius", type=float, default=500.0, help="block radius [mm] (500)")
    p.add_argument("--concrete-modulus", type=float, default=E_CONCRETE,
                   help=f"E_c [MPa] ({E_CONCRETE}: Table 3 as printed)")
    p.add_argument("--uniform-radius", type=float, default=60.0,
                   help="radius [mm] up to which the radial size is --element (60)")
    p.add_argument("--bar-element", choices=("CAX4R", "CAX4"), default="CAX4R",
                   help="the steel's element (CAX4R; CAX4 converges worse past yield)")
    p.add_argument("--layer-thickness", type=float, default=0.01, help="h [mm] (0.01)")
    p.add_argument("--layer-e-other", type=float, default=0.01,
                   help="layer PROPS 2, modulus [MPa] of its non-interface components (0.01)")
    p.add_argument("--layer", choices=("umat", "elastic"), default="umat")
    p.add_argument("--steel", choices=("plastic", "elastic"), default="plastic",
                   help="plastic: Table 4's von Mises hardening; elastic: the steel elastic "
                        "(the deal.II example's 3D pull-out compares against it)")
    p.add_argument("--tangent", type=int, choices=(0, 1, 2), default=2,
                   help="interlock PROPS 20: 1 exact (ccx averages it), 2 symmetric for hosts "
                        "that symmetrize (2); 0: PROPS 20 not given (the law's default)")
    p.add_argument("--scheme", type=int, choices=(1, 2), default=2,
                   help="interlock PROPS 11: 1 explicit, 2 implicit (2)")
    # The UMAT's accuracy bounds off by default: in ccx every positive PNEWDT is a cutback, and
    # here they add increments without changing the forces (docs/calculix_pullout.md).
    p.add_argument("--max-damage-increment", type=float, default=1.0,
                   help="interlock PROPS 13 (1: off)")
    p.add_argument("--max-angle-increment", type=float, default=90.0,
                   help="interlock PROPS 14 [deg] (90: off)")
    p.add_argument("--plateau-hardening", type=float, default=0.0,
                   help="slope [MPa] given to Table 4's plateau (0: as the paper)")
    p.add_argument("--top-displacement", type=float, default=5.2, help="mm (5.2)")
    p.add_argument("--initial-increment", type=float, default=0.01, help="fraction (0.01)")
    p.add_argument("--max-increment", type=float, default=0.01, help="fraction (0.01)")
    p.add_argument("--min-increment", type=float, default=1e-6, help="fraction (1e-6)")
    p.add_argument("--controls", default="",
                   help="a *CONTROLS, PARAMETERS=TIME INCREMENTATION data line (default: none)")
    a = p.parse_args(argv)
    if a.element <= 0 or a.radius <= BAR_DIAMETER or a.layer_thickness <= 0:
        p.error("--element, --layer-thickness > 0 and --radius > D are required")
    if a.embedment <= SLEEVE_LENGTH + a.element:
        p.error(f"--embedment {a.embedment} must exceed the sleeve, {SLEEVE_LENGTH} mm")
    return a


def radial_coordinates(a):
    """Node radii: bar, layer, concrete (uniform to --uniform-radius, then graded)."""
    rb = BAR_DIAMETER / 2.0
    nbar = max(1, round(rb / a.element))
    r = list(np.linspace(0.0, rb, nbar + 1))
    r.append(rb + a.layer_thickness)
    while r[-1] < min(a.uniform_radius, a.radius) - 1e-9:
        r.append(min(r[-1] + a.element, a.radius))
    size = a.element
    while r[-1] < a.radius - 1e-9:
        size *= 1.15
        if r[-1] + 1.5 * size >= a.radius:
            r.append(a.radius)
        else:
            r.append(r[-1] + size)
    return np.array(r), nbar


def axial_coordinates(a):
    """Node heights: 0 (far end) .. L (loaded end); the sleeve end is a node row."""
    lower = a.embedment - SLEEVE_LENGTH
    n_sleeve = max(1, round(SLEEVE_LENGTH / a.element))
    n_lower = max(1, round(lower / a.element))
    return np.concatenate([np.linspace(0.0, lower, n_lower + 1),
                           np.linspace(lower, a.embedment, n_sleeve + 1)[1:]])


def lines8(values):
    """ccx data lines: at most 8 values per line."""
    out = []
    for i in range(0, len(values), 8):
        out.append(", ".join(f"{v:.10g}" for v in values[i:i + 8]))
    return "\n".join(out)


def id_lines(ids):
    return "\n".join(", ".join(str(i) for i in ids[k:k + 16]) for k in range(0, len(ids), 16))


def main(argv):
    a = parse_args(argv)
    r, nbar = radial_coordinates(a)
    y = axial_coordinates(a)
    nr, ny = len(r), len(y)
    node = lambda i, j: j * nr + i + 1                         # noqa: E731
    elem = lambda i, j: j * (nr - 1) + i + 1                   # noqa: E731
    layer_col = nbar                                           # element column of the layer
    sleeve_start = a.embedment - SLEEVE_LENGTH

    bar, clay, conc_layer, concrete = [], [], [], []
    for j in range(ny - 1):
        ymid = 0.5 * (y[j] + y[j + 1])
        for i in range(nr - 1):
            e = elem(i, j)
            if i < layer_col:
                bar.append(e)
            elif i == layer_col:
                (clay if ymid > sleeve_start else conc_layer).append(e)
            else:
                concrete.append(e)

    out = []
    w = out.append
    w("** Pull-out test of a ribbed bar from a concrete block (paper section 4.2), written by")
    w("** examples/calculix/pullout/make_mesh.py " + " ".join(argv))
    w(f"** element {a.element} mm, embedment {a.embedment} mm, block radius {a.radius} mm, "
      f"layer h {a.layer_thickness} mm, {len(bar) + len(clay) + len(conc_layer) + len(concrete)}"
      " CAX4")
    w("*NODE, NSET=NALL")
    for j in range(ny):
        for i in range(nr):
            w(f"{node(i, j)}, {r[i]:.8g}, {y[j]:.8g}")
    # The steel's element: CAX4R (one point, hourglass control). ccx's CAX4 is fully
    # integrated without a B-bar treatment, prone to locking in incompressible plastic flow;
    # here it gives forces 0.45 % lower but needs more increments and up to 15 iterations
    # against 6 (docs/calculix_pullout.md). Layer and concrete: CAX4.
    for etype, first_col, last_col in ((a.bar_element, 0, layer_col), ("CAX4", layer_col, nr - 1)):
        w(f"*ELEMENT, TYPE={etype}, ELSET=EALL")
        for j in range(ny - 1):
            for i in range(first_col, last_col):
                w(f"{elem(i, j)}, {node(i, j)}, {node(i + 1, j)}, {node(i + 1, j + 1)}, "
                  f"{node(i, j + 1)}")
    for name, ids in (("BAR", bar), ("LAYERCLAY", clay), ("LAYERCONC", conc_layer),
                      ("CONCRETE", concrete)):
        w(f"*ELSET, ELSET={name}")
        w(id_lines(ids))
    w("*ELSET, ELSET=BAROUTER")
    w(id_lines([e for e in bar if (e - 1) % (nr - 1) == layer_col - 1]))
    w("*ELSET, ELSET=LAYER")
    w("LAYERCLAY, LAYERCONC")
    nsets = {
        "TOP": [node(i, ny - 1) for i in range(nbar + 1)],
        "AXIS": [node(0, j) for j in range(ny)],
        "CONCTOP": [node(i, ny - 1) for i in range(nbar + 1, nr)],
        "BARSURF": [node(nbar, j) for j in range(ny)],
        "CONCSURF": [node(nbar + 1, j) for j in range(ny)],
    }
    for name, ids in nsets.items():
        w(f"*NSET, NSET={name}")
        w(id_lines(ids))

    w("*ORIENTATION, NAME=CYL, SYSTEM=CYLINDRICAL")
    w("0., 0., 0., 0., 1., 0.")
    w("*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL")
    w("*SOLID SECTION, ELSET=CONCRETE, MATERIAL=CONCRETE")
    w("*MATERIAL, NAME=CONCRETE")
    w("*ELASTIC")
    w(f"{a.concrete_modulus}, {NU_CONCRETE}")
    w("*MATERIAL, NAME=STEEL")
    w("*ELASTIC")
    w(f"{E_STEEL}, {NU_STEEL}")
    if a.steel == "plastic":
        w("*PLASTIC")
        eps_plateau_end = HARDENING[1][1]
        for stress, eps in HARDENING:
            if a.plateau_hardening > 0 and 0 < eps <= eps_plateau_end:
                stress += a.plateau_hardening * eps
            w(f"{stress}, {eps}")
    for set_name, mat in (("LAYERCLAY", "CLAYBAR"), ("LAYERCONC", "CONCBAR")):
        s0, gc, eta, mu, th0, thf, hn, z0 = INTERFACES[mat]
        if a.layer == "umat":
            w(f"*SOLID SECTION, ELSET={set_name}, MATERIAL=ABAQUS{mat}, ORIENTATION=CYL")
            w(f"*MATERIAL, NAME=ABAQUS{mat}")
            props = [a.layer_thickness, a.layer_e_other, 1, 3,
                     s0, s0, gc, eta, mu, hn, th0, thf, z0,
                     0, a.scheme, 0.0, a.max_damage_increment, a.max_angle_increment,
                     1, 1, 1, 1, 1] + ([a.tangent] if a.tangent else [])
            w(f"*USER MATERIAL, CONSTANTS={len(props)}")
            w("** h, e_other, normal axis (radial), slip axis (bar axis), then interlock PROPS")
            w(lines8(props))
            if len(props) % 8 == 0:
                w("0.")          # ccx reads a temperature after the constants
            w("*DEPVAR")
            w("34")            # the 3D law's 28, then separations and tractions
        else:
            # Stand-in: isotropic elastic of the interface's initial stiffness K h.
            k = s0 / ((1.0 - eta) * 2.0 * gc / s0)
            w(f"*SOLID SECTION, ELSET={set_name}, MATERIAL=STANDIN{mat}, ORIENTATION=CYL")
            w(f"*MATERIAL, NAME=STANDIN{mat}")
            w("*ELASTIC")
            w(f"{k * a.layer_thickness:.8g}, 0.0")

    w("*BOUNDARY")
    w("AXIS, 1, 1")
    w("CONCTOP, 2, 2")
    w("*STEP, INC=100000")
    w("*STATIC")
    w(f"{a.initial_increment}, 1.0, {a.min_increment}, {a.max_increment}")
    if a.controls:
        w("*CONTROLS, PARAMETERS=TIME INCREMENTATION")
        w(a.controls)
    w("*BOUNDARY")
    w(f"TOP, 2, 2, {a.top_displacement}")
    # ccx shares one print frequency between all print requests: every increment. Forces of
    # CAX4 models are printed for ccx's 2-degree wedge (x 180 for the whole circumference).
    w("*NODE PRINT, NSET=TOP, TOTALS=ONLY")
    w("RF")
    w("*NODE PRINT, NSET=BARSURF")
    w("U")
    w("*NODE PRINT, NSET=CONCSURF")
    w("U")
    w("*EL PRINT, ELSET=LAYER")
    w("SDV")
    w("*EL PRINT, ELSET=BAROUTER")
    w("PEEQ")
    w("*END STEP")

    os.makedirs(os.path.dirname(os.path.abspath(a.output)), exist_ok=True)
    write_text(a.output, "\n".join(out) + "\n")
    print(f"{a.output}: {nr * ny} nodes, {(nr - 1) * (ny - 1)} CAX4 "
          f"({len(bar)} bar, {len(clay)} clay-bar layer, {len(conc_layer)} concrete-bar layer, "
          f"{len(concrete)} concrete)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
