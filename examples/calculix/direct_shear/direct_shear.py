#!/usr/bin/python3
"""Direct shear in CalculiX with the interlock thin layer, checked against interlock-history.

A block with one interface layer (h = 0.01 mm) between two elastic blocks: a normal pressure of
0.2 MPa, then displacement-controlled slip of 1.5 mm, with the paper's Table 1 interface and
theta_0 = 25 deg, H_N = 0.5 mm (no wear). Three element types: C3D8 (normal = local 3, slip =
local 1), CPE4 (normal 2, slip 1), CAX4 (a bar in a sleeve: the layer is a tube, normal =
local 1 = radial and slip = local 3 = axial of *ORIENTATION, SYSTEM=CYLINDRICAL).

    direct_shear.py write --element C3D8 [--tangent 1|2] [--out DIR]      (the .inp only)
    direct_shear.py run --ccx CCX --history INTERLOCK_HISTORY --element C3D8
                        [--tangent 1|2] [--out DIR] [--tolerance 1e-5]
                        [--state-tolerance 5e-5] [--angle-deg A]
                        [--path straight|square|circle] [--side A] [--radius R]
                        [--increments N] [--ria paper|azimuthal] [--n-azimuths N]
                        [--prefractured] [--shear-traction TAU]

C3D8 only, the slip in the layer's plane (t1 = x, t2 = y; both shear components through the 3D
law): --angle-deg, the straight slip at A deg from t1 towards t2; --path square (side A, default
0.75 mm: t1, t2, -t1, -t2) or circle (out to radius R, default 0.5 mm, then one
counter-clockwise turn), in --increments fixed increments (default 200) ending on the path's
vertices (ccx amplitudes), turned by --angle-deg; --ria azimuthal: the azimuthal RIA with
--n-azimuths N_a (layer PROPS 25-26; 1 + 2 N_a planes, *DEPVAR 8 (1 + 2 N_a) + 4 + 6).

`run` writes the deck, runs ccx, reads the layer's separations, tractions and state per
increment (*EL PRINT SDV; ccx calls every element's material with NTENS = 6, so the layer runs
the 3D law: its 8 n + 4 STATEV (interlock-query --statev; for the paper's RIA 1-22 mean what the
2D law's do), then the layer's 6: the separation and the traction (normal, t1) and the
separation and traction along t2), replays the separation history (s_N, s_T1, s_T2) of one
layer point through interlock-history (a 3D deck with one step per ccx increment and the same
RIA) and asserts that the tractions and the state agree to the tolerances: tractions relative to
the largest traction of the run; each state variable relative to its largest value over the run
(the friction tractions: at least the largest traction). It also writes convergence.txt: the
global iterations of every increment (mean, median, max) and the residual sequence (ccx's .cvg
and .sta). Exit status 0 when all agree. Standard library plus h5py (for interlock-history's
output): `run` restarts itself under /usr/bin/python3 (or another python3 on PATH with h5py)
when the interpreter running it has no h5py (scripts/python_with.py).
"""
import argparse
import math
import pathlib
import re
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "scripts"))
import python_with  # noqa: E402  (the python3 that has h5py, for `run`)

H = 0.01            # layer thickness [mm]
E_OTHER = 0.01      # modulus of the layer's other components [MPa] (small: see below)
E_BLOCK, NU_BLOCK = 30000.0, 0.2   # the blocks (concrete-like) [MPa]
PRESSURE = 0.2      # normal pressure [MPa]
SLIP = 1.5          # imposed slip [mm]
INCREMENT = 0.01    # slip increment [mm] (fixed: 150 increments)
# Table 1, theta_0 = theta_f = 25 deg (no wear), H_N = 0.5 mm; scheme 2 (implicit); the
# accuracy bounds off (max_damage_increment 1, max_angle_increment_deg 90: ccx acts on a
# PNEWDT request at every iteration, not only at convergence).
INTERLOCK = {"sigma0_n": 3.0, "sigma0_t": 3.0, "gc": 0.3, "eta": 0.9, "mu": 0.5, "h_n": 0.5,
             "theta0_deg": 25.0, "thetaf_deg": 25.0, "zeta0": 1e30, "prefractured": 0,
             "scheme": 2, "substep_tol": 0.0, "max_damage_increment": 1.0,
             "max_angle_increment_deg": 90.0, "damage": 1, "friction": 1, "interlocking": 1,
             "finite_depth": 1, "wear": 1}
AXES = {"C3D8": (3, 1), "CPE4": (2, 1), "CAX4": (1, 3)}   # (normal, slip) local axes
# The 3D law's STATEV (interlock-query --statev), in the order of the history file's datasets:
# per-plane variables by variable, then plane; the point's four; the strike components. The
# layer's six follow: (normal, slip) separation and traction, the separation and traction along
# t2.
LAYER_EXTRA = 6
# The state variables that are tractions [MPa]
TRACTION_STATE = ("friction_traction", "tauf_strike")
# What ccx's printed values support (7 significant digits, relative rounding <= 5e-7): the
# tractions agree to 9.1e-7 of the largest traction; a state variable replayed from printed
# separations carries their rounding times its sensitivity (a friction traction K_t (s - sf):
# K_t x 5e-7 x |s|, 1.7e-5 of the largest traction seen at 45 deg).
TRACTION_TOLERANCE = 1e-5
STATE_TOLERANCE = 5e-5


def n_planes(ria, n_azimuths):
    """The RIA's planes: the paper's three, or 1 + 2 N_a for the azimuthal RIA."""
    return 3 if ria == "paper" else 1 + 2 * n_azimuths


def statev_names(n):
    """(name, count) of the 3D law's STATEV for n planes: 8 n + 4 in all."""
    return [("damage", n), ("beta", n), ("frictional_slip", n), ("zeta", n), ("theta", n),
            ("friction_traction", n), ("work", 1), ("damage_dissipation", 1),
            ("friction_dissipation", 1), ("initialized", 1), ("sf_strike", n),
            ("tauf_strike", n)]


def user_material(element, tangent, interlock, ria="paper", n_azimuths=1):
    """The layer's *USER MATERIAL (24 constants; 26 with the azimuthal RIA: layer PROPS 25-26 =
    the law's 21 `ria` = 1 and 22 `n_azimuths`) and *DEPVAR (the law's 8 n + 4, the layer's 6)."""
    normal, slip = AXES[element]
    values = [H, E_OTHER, normal, slip] + list(interlock.values()) + [float(tangent)]
    if ria == "azimuthal":
        values += [1.0, float(n_azimuths)]
    nstatv = 8 * n_planes(ria, n_azimuths) + 4 + LAYER_EXTRA
    lines = []
    for i in range(0, len(values), 8):
        lines.append(", ".join(f"{v:.12g}" for v in values[i:i + 8]))
    if len(values) % 8 == 0:
        lines.append("0.")     # ccx reads a temperature after the constants: its own line here
    return (f"*MATERIAL, NAME=ABAQUSLAYER\n*USER MATERIAL, CONSTANTS={len(values)}\n"
            + "\n".join(lines) + f"\n*DEPVAR\n{nstatv}\n")


def grid_3d():
    """Nodes and C3D8 elements: 2 x 2 in plane (10 x 10 mm), z: block 5, layer h, block 5."""
    zs = [0.0, 5.0, 5.0 + H, 10.0 + H]
    xs = [0.0, 5.0, 10.0]
    nodes, nid = {}, {}
    n = 0
    for k, z in enumerate(zs):
        for j, y in enumerate(xs):
            for i, x in enumerate(xs):
                n += 1
                nodes[n] = (x, y, z)
                nid[i, j, k] = n
    elements = {"LOWER": [], "LAYER": [], "UPPER": []}
    e = 0
    for k, name in enumerate(["LOWER", "LAYER", "UPPER"]):
        for j in range(2):
            for i in range(2):
                e += 1
                c = [nid[i, j, k], nid[i + 1, j, k], nid[i + 1, j + 1, k], nid[i, j + 1, k]]
                c += [nid[i, j, k + 1], nid[i + 1, j, k + 1], nid[i + 1, j + 1, k + 1],
                      nid[i, j + 1, k + 1]]
                elements[name].append((e, c))
    bottom = [nid[i, j, 0] for i in range(3) for j in range(3)]
    top = [nid[i, j, 3] for i in range(3) for j in range(3)]
    return nodes, elements, bottom, top


def grid_2d(levels, xs):
    """Nodes and 4-node elements on a grid: columns xs, rows `levels`, the element sets by row."""
    nodes, nid = {}, {}
    n = 0
    for k, y in enumerate(levels):
        for i, x in enumerate(xs):
            n += 1
            nodes[n] = (x, y, 0.0)
            nid[i, k] = n
    return nodes, nid


def slip_path(path, increments, angle_deg=0.0, side=None, radius=None):
    """The slip (s_T1, s_T2) [mm] of the loaded face at the end of every increment of the slip
    step, from (0, 0), as the interlock-history deck's paths (docs/deck-format.md): `straight`
    SLIP along t1; `square`
    0 -> (a, 0) -> (a, a) -> (0, a) -> 0, `increments` / 4 per side; `circle` out to radius r,
    then one counter-clockwise turn, the increments shared in proportion to the lengths (r and
    2 pi r), every increment's end on the circle (a polyline of chords); both turned by
    angle_deg."""
    points = [(0.0, 0.0)]
    if path == "straight":
        points += [(SLIP * k / increments, 0.0) for k in range(1, increments + 1)]
    elif path == "square":
        if increments % 4:
            sys.exit(f"direct_shear: --increments {increments} with --path square: a multiple of 4")
        m = increments // 4
        corners = [(0.0, 0.0), (side, 0.0), (side, side), (0.0, side), (0.0, 0.0)]
        for (x0, y0), (x1, y1) in zip(corners, corners[1:]):
            points += [(x0 + (x1 - x0) * k / m, y0 + (y1 - y0) * k / m) for k in range(1, m + 1)]
    else:
        out = max(1, round(increments / (1.0 + 2.0 * math.pi)))
        turn = increments - out
        points += [(radius * k / out, 0.0) for k in range(1, out + 1)]
        points += [(radius * math.cos(2.0 * math.pi * k / turn),
                    radius * math.sin(2.0 * math.pi * k / turn)) for k in range(1, turn + 1)]
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    return [(c * x - s * y, s * x + c * y) for x, y in points]


def amplitude(name, values):
    """A ccx *AMPLITUDE over the step time, one value per increment end (times k / n). ccx
    reads each number from its first 20 characters only (`read(...,'(f20.0)')`: -1.2e-16
    written with 15 digits, 21 characters, is read as -0.122): 12 digits."""
    n = len(values) - 1
    pairs = [f"{k / n:.12g}, {v:.12g}" for k, v in enumerate(values)]
    return [f"*AMPLITUDE, NAME={name}"] + [", ".join(pairs[i:i + 4])
                                           for i in range(0, len(pairs), 4)]


def model(element, tangent, shear_force=None, prefractured=0, angle_deg=0.0, ria="paper",
          n_azimuths=1, path=None):
    """The deck. `path` (C3D8): the slip at every increment end (slip_path), imposed through
    two amplitudes (x, y) in fixed increments, one per vertex; otherwise a straight slip of
    SLIP at angle_deg."""
    out = [f"** Direct shear, {element}, interlock thin layer h = {H} mm (tangent option "
           f"{tangent}); written by examples/calculix/direct_shear/direct_shear.py"]
    if element == "C3D8":
        nodes, elements, bottom, top = grid_3d()
        etype = "C3D8"
        pressure_face = [(e, "P2") for e, _ in elements["UPPER"]]
        fixed = {"BOTTOM": (bottom, (1, 3))}
        held = {"TOPREF": (top[:1], (1, 1)), "TOP": (top, (2, 2))}   # 3 free (pressure)
        slip_set, slip_dof = "TOPREF", 1
        tied = (top, (1, 3))
        orientation = ""
    elif element == "CPE4":
        levels = [0.0, 5.0, 5.0 + H, 10.0 + H]
        xs = [0.0, 5.0, 10.0]
        nodes, nid = grid_2d(levels, xs)
        elements = {"LOWER": [], "LAYER": [], "UPPER": []}
        e = 0
        for k, name in enumerate(["LOWER", "LAYER", "UPPER"]):
            for i in range(2):
                e += 1
                elements[name].append((e, [nid[i, k], nid[i + 1, k], nid[i + 1, k + 1],
                                           nid[i, k + 1]]))
        etype = "CPE4"
        pressure_face = [(e, "P3") for e, _ in elements["UPPER"]]
        fixed = {"BOTTOM": ([nid[i, 0] for i in range(3)], (1, 2))}
        held = {"TOPREF": ([nid[0, 3]], (1, 1))}
        slip_set, slip_dof = "TOPREF", 1
        tied = ([nid[i, 3] for i in range(3)], (1, 2))
        orientation = ""
    else:   # CAX4: a bar (r < 5) in a sleeve, the layer a tube at r = 5; x radial, y axial
        xs = [0.0, 2.5, 5.0, 5.0 + H, 7.5 + H, 10.0 + H]
        levels = [0.0, 5.0, 10.0]
        nodes, nid = grid_2d(levels, xs)
        elements = {"LOWER": [], "LAYER": [], "UPPER": []}   # LOWER = bar, UPPER = sleeve
        e = 0
        for i in range(5):
            name = "LOWER" if i < 2 else ("LAYER" if i == 2 else "UPPER")
            for k in range(2):
                e += 1
                elements[name].append((e, [nid[i, k], nid[i + 1, k], nid[i + 1, k + 1],
                                           nid[i, k + 1]]))
        etype = "CAX4"
        # the confining pressure on the sleeve's outer face (face 2: nodes 2-3)
        pressure_face = [(e, "P2") for e, c in elements["UPPER"] if nodes[c[1]][0] > 10.0]
        fixed = {"SLEEVEBOTTOM": ([nid[i, 0] for i in range(3, 6)], (2, 2)),
                 "AXIS": ([nid[0, k] for k in range(3)], (1, 1))}
        held = {"BARTOP": ([nid[i, 2] for i in range(3)], (2, 2))}
        slip_set, slip_dof = "BARTOP", 2
        tied = None
        orientation = ("*ORIENTATION, NAME=CYL, SYSTEM=CYLINDRICAL\n"
                       "0., 0., 0., 0., 1., 0.\n")
    out.append("*NODE, NSET=NALL")
    out += [f"{n}, {x:.10g}, {y:.10g}, {z:.10g}" for n, (x, y, z) in nodes.items()]
    for name, els in elements.items():
        out.append(f"*ELEMENT, TYPE={etype}, ELSET={name}")
        out += [f"{e}, " + ", ".join(str(c) for c in conn) for e, conn in els]
    for name, (ns, _) in list(fixed.items()) + list(held.items()):
        out.append(f"*NSET, NSET={name}")
        out += [", ".join(str(n) for n in ns[i:i + 8]) for i in range(0, len(ns), 8)]
    out.append("*ELSET, ELSET=BLOCKS\nLOWER, UPPER")
    out.append(f"*MATERIAL, NAME=BLOCK\n*ELASTIC\n{E_BLOCK}, {NU_BLOCK}")
    out.append(user_material(element, tangent, dict(INTERLOCK, prefractured=prefractured),
                             ria, n_azimuths).rstrip("\n"))
    if orientation:
        out.append(orientation.rstrip("\n"))
        out.append("*SOLID SECTION, ELSET=LAYER, MATERIAL=ABAQUSLAYER, ORIENTATION=CYL")
    else:
        out.append("*SOLID SECTION, ELSET=LAYER, MATERIAL=ABAQUSLAYER")
    if element == "CPE4":
        out.append("1.")
    out.append("*SOLID SECTION, ELSET=BLOCKS, MATERIAL=BLOCK")
    if element == "CPE4":
        out.append("1.")
    if tied:
        # The loaded face moves as one, in slip and normal (no rotation of the upper block:
        # the normal traction stays the pressure, as in a direct shear box); its first node
        # carries the slip (displacement or force).
        nodes_tied, dofs = tied
        out.append("*EQUATION")
        for dof in dofs:
            for n in nodes_tied[1:]:
                out.append(f"2\n{n}, {dof}, 1., {nodes_tied[0]}, {dof}, -1.")
    out.append("*BOUNDARY")
    for name, (_, (a, b)) in fixed.items():
        out.append(f"{name}, {a}, {b}")
    if path:
        out += amplitude("SLIPX", [x for x, _ in path])
        out += amplitude("SLIPY", [y for _, y in path])
    # Step 1: the normal pressure, slip held at zero.
    out.append("*STEP, INC=1000\n*STATIC\n0.1, 1.0, 1e-6, 0.1")
    out.append("*BOUNDARY")
    for name, (_, (a, b)) in held.items():
        out.append(f"{name}, {a}, {b}, 0.")
    out.append("*DLOAD")
    out += [f"{e}, {face}, {PRESSURE}" for e, face in pressure_face]
    out.append("*EL PRINT, ELSET=LAYER, FREQUENCY=1\nSDV")
    out.append("*END STEP")
    if path:
        # Step 2: the slip along the path, fixed increments ending on its vertices: the tied
        # face's x and every top node's y (held at 0 in step 1) follow the amplitudes.
        n_inc = len(path) - 1
        out.append(f"*STEP, INC={n_inc + 10}\n*STATIC, DIRECT\n{1.0 / n_inc:.12g}, 1.0")
        out.append(f"*BOUNDARY, AMPLITUDE=SLIPX\n{slip_set}, {slip_dof}, {slip_dof}, 1.")
        out.append("*BOUNDARY, AMPLITUDE=SLIPY\nTOP, 2, 2, 1.")
    elif shear_force is None:
        # Step 2: the slip, displacement controlled, fixed increments.
        n_inc = round(SLIP / INCREMENT)
        out.append(f"*STEP, INC={n_inc + 10}\n*STATIC, DIRECT\n{1.0 / n_inc:.12g}, 1.0")
        out.append("*BOUNDARY")
        if angle_deg:
            # slip along (cos A, sin A) in the layer's plane: the tied face's x and every top
            # node's y (held at 0 in step 1)
            a = math.radians(angle_deg)
            out.append(f"{slip_set}, {slip_dof}, {slip_dof}, {SLIP * math.cos(a):.12g}")
            out.append(f"TOP, 2, 2, {SLIP * math.sin(a):.12g}")
        else:
            out.append(f"{slip_set}, {slip_dof}, {slip_dof}, {SLIP}")
    else:
        # Step 2 (measurement only): the shear force on the tied face, automatic increments.
        out.append("*STEP, INC=1000\n*STATIC\n0.02, 1.0, 1e-5, 0.02")
        out.append("*BOUNDARY, OP=NEW")
        for name, (_, (a, b)) in fixed.items():
            out.append(f"{name}, {a}, {b}")
        for name, (_, (a, b)) in held.items():
            if name != slip_set:
                out.append(f"{name}, {a}, {b}, 0.")
        out.append(f"*CLOAD\n{slip_set}, {slip_dof}, {shear_force:.12g}")
    out.append("*EL PRINT, ELSET=LAYER, FREQUENCY=1\nSDV")
    out.append("*END STEP")
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------- reading ccx's output
def read_dat_sdv(path):
    """{(element, point): [row of SDV per printed increment]} and the step times. ccx prints
    a point's values on one line, wrapped on continuation lines when there are many (over
    100: the 13-plane RIA's 114)."""
    rows, times = {}, []
    block, key = False, None
    for line in path.read_text().splitlines():
        m = re.match(r"\s*internal state variables \(elem, integ\.pnt\.,values\) for set "
                     r"(\S+) and time\s+(\S+)", line)
        if m:
            block, key = True, None
            times.append(float(m.group(2)))
            continue
        if block:
            parts = line.split()
            if not parts:
                continue
            if re.fullmatch(r"\d+", parts[0]) and len(parts) > 1 and re.fullmatch(r"\d+", parts[1]):
                key = (int(parts[0]), int(parts[1]))
                rows.setdefault(key, []).append([float(v) for v in parts[2:]])
                continue
            try:
                values = [float(v) for v in parts]
            except ValueError:
                block, key = False, None
                continue
            if key is None:
                block = False
                continue
            rows[key][-1].extend(values)
    return rows, times


def read_convergence(job):
    """Per increment (step, increment): the iterations and the residual sequence (.cvg)."""
    incs = {}
    cvg = job.with_suffix(".cvg")
    for line in cvg.read_text().splitlines():
        parts = line.split()
        if len(parts) < 9 or not parts[0].isdigit():
            continue
        step, inc, att, it = (int(x) for x in parts[:4])
        # RESID. FORCE (%) and CORR. DISP (%): ccx's largest residual force and correction
        # relative to the average force and displacement increment.
        incs.setdefault((step, inc), []).append((att, it, float(parts[5]), float(parts[6])))
    return incs


def convergence_lines(job):
    """The second step's global iterations per increment and its hardest residual sequence."""
    conv = read_convergence(job)
    step2 = [(inc, v) for (st, inc), v in sorted(conv.items()) if st == 2]
    iters = [len(v) for _, v in step2]
    lines = []
    reached = 0.0
    for line in job.with_suffix(".sta").read_text().splitlines():
        parts = line.split()
        if len(parts) == 7 and parts[0] == "2" and parts[2].isdigit():
            reached = float(parts[5])      # STEP TIME of a converged increment
    lines.append(f"step 2 reached step time {reached:.4g} of 1")
    if iters:
        srt = sorted(iters)
        cutbacks = sum(1 for _, v in step2 if any(a > 1 for a, _, _, _ in v))
        lines.append(f"slip step: {len(iters)} increments ({cutbacks} with cutbacks), "
                     f"global iterations per increment: mean {sum(iters) / len(iters):.2f}, "
                     f"median {srt[len(srt) // 2]}, max {max(iters)}, total {sum(iters)}")
        lines.append("iterations per increment: " + " ".join(str(i) for i in iters))
        worst_inc = max(step2, key=lambda kv: len(kv[1]))
        lines.append(f"residual sequence of increment {worst_inc[0]} (largest residual force): "
                     + " ".join(f"{r:.2e}" for _, _, r, _ in worst_inc[1][:16])
                     + (" ..." if len(worst_inc[1]) > 16 else "")
                     + "  (% of the average force)")
    return lines


def imposed_slip(args):
    """The options checked; the slip at every increment end (C3D8 with imposed slip, else
    None) and the path that the model imposes by amplitudes (None: straight)."""
    three_d = args.angle_deg or args.path != "straight" or args.ria != "paper"
    if three_d and (args.element != "C3D8" or args.shear_traction is not None):
        sys.exit("direct_shear: --angle-deg, --path and --ria azimuthal are for C3D8 with "
                 "imposed slip")
    if args.path == "straight" and args.increments:
        sys.exit("direct_shear: --increments is for --path square or circle (straight: "
                 f"{round(SLIP / INCREMENT)} increments)")
    if args.increments is not None and args.increments < 4:
        sys.exit(f"direct_shear: --increments {args.increments}: at least 4")
    if not (args.side > 0.0 and args.radius > 0.0):
        sys.exit(f"direct_shear: --side {args.side}, --radius {args.radius}: both > 0 mm")
    if args.element != "C3D8" or args.shear_traction is not None:
        return None, None
    if args.path == "straight":
        return slip_path("straight", round(SLIP / INCREMENT), args.angle_deg), None
    vertices = slip_path(args.path, args.increments or 200, args.angle_deg, args.side,
                         args.radius)
    return vertices, vertices


def run(args):
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    job = out / f"direct_shear_{args.element.lower()}_t{args.tangent}"
    # the slip at every increment end, to check the layer's against
    vertices, path = imposed_slip(args)
    if args.ria == "azimuthal":
        job = job.with_name(job.name + f"_azimuthal{args.n_azimuths}")
    if path:
        size = args.side if args.path == "square" else args.radius
        job = job.with_name(job.name + f"_{args.path}{round(size * 1000)}um")
    if args.angle_deg:
        job = job.with_name(job.name + f"_{args.angle_deg:g}deg")
    force = None
    if args.shear_traction is not None:
        if args.element == "CAX4":
            sys.exit("direct_shear: --shear-traction is for C3D8 and CPE4")
        force = args.shear_traction * (100.0 if args.element == "C3D8" else 10.0)
        job = job.with_name(job.name + f"_tau{round(args.shear_traction * 1000)}kPa")
    if args.prefractured:
        job = job.with_name(job.name + "_prefractured")
    job.with_suffix(".inp").write_text(model(args.element, args.tangent, force,
                                             int(args.prefractured), args.angle_deg, args.ria,
                                             args.n_azimuths, path))
    for suffix in (".dat", ".cvg", ".sta"):
        job.with_suffix(suffix).unlink(missing_ok=True)
    proc = subprocess.run([args.ccx, "-i", job.name], cwd=out, capture_output=True, text=True,
                          env={"OMP_NUM_THREADS": "1", "CCX_NPROC_STIFFNESS": "1",
                               "PATH": "/usr/bin:/bin"})
    job.with_suffix(".log").write_text(proc.stdout + proc.stderr)
    if proc.returncode != 0 or "Job finished" not in proc.stdout:
        lines = [f"{job.name}: {args.element}, tangent option {args.tangent}: ccx stopped"]
        lines += convergence_lines(job)
        (out / f"{job.name}_convergence.txt").write_text("\n".join(lines) + "\n")
        print("\n".join(lines))
        sys.exit(f"direct_shear: FAIL, ccx stopped on {job.name}.inp (log: {job}.log)")
    rows, times = read_dat_sdv(job.with_suffix(".dat"))
    point = min(rows)
    sdv = rows[point]
    n = len(sdv)
    names = statev_names(n_planes(args.ria, args.n_azimuths))
    extra = sum(count for _, count in names)
    # (normal, slip, t2) separations and tractions: the layer's STATEV after the law's
    s_ccx = [r[extra:extra + 2] + [r[extra + 4]] for r in sdv]
    t_ccx = [r[extra + 2:extra + 4] + [r[extra + 5]] for r in sdv]
    path_lines, path_failed = [], False
    if vertices:
        # The layer slips along the imposed path, short of it by the blocks' elastic shear
        # (10 mm of block at G = E / (2 (1 + nu)): |tau| 10 / G, at most 2.5e-3 mm here).
        g_block = E_BLOCK / (2.0 * (1.0 + NU_BLOCK))
        slip_rows = s_ccx[len(s_ccx) - (len(vertices) - 1):]
        off = [(math.hypot(s[1] - x, s[2] - y), math.hypot(t[1], t[2]) * 10.0 / g_block)
               for s, t, (x, y) in zip(slip_rows, t_ccx[len(t_ccx) - len(slip_rows):],
                                       vertices[1:])]
        worst_off = max(off)
        path_failed = any(d > 2.0 * b + 1e-4 for d, b in off)
        path_lines.append(f"slip path: the layer's (s_T1, s_T2) within {worst_off[0]:.2e} mm of "
                          f"the imposed path at every increment (blocks' shear there: "
                          f"{worst_off[1]:.2e} mm)")

    # The replay deck: the separations of the point at every ccx increment, one step each.
    deck = out / f"{job.name}_replay.nml"
    h5 = out / f"{job.name}_replay.h5"
    p = INTERLOCK
    tpts = ", ".join(str(i) for i in range(n + 1))
    normal = ", ".join(["0"] + [repr(s[0]) for s in s_ccx])
    tangential = ", ".join(["0"] + [repr(s[1]) for s in s_ccx])
    t2 = ", ".join(["0"] + [repr(s[2]) for s in s_ccx])
    deck.write_text(
        f"! Replay of {job.name}.inp, element {point[0]} point {point[1]}: ccx's separations\n"
        f"&interface\n  sigma0_n = {p['sigma0_n']}, sigma0_t = {p['sigma0_t']}, gc = {p['gc']},"
        f" eta = {p['eta']}, mu = {p['mu']}, h_n = {p['h_n']},"
        f" prefractured = {'.true.' if args.prefractured else '.false.'}\n/\n"
        f"&microplanes\n  theta0_deg = {p['theta0_deg']}, thetaf_deg = {p['thetaf_deg']},"
        f" zeta0 = {p['zeta0']}"
        + (f", n_azimuths = {args.n_azimuths}" if args.ria == "azimuthal" else "") + "\n/\n"
        f"&loading\n  normal_control = 'separation', tangential_control = 'separation',"
        f" t2_control = 'separation'\n"
        f"  times = {tpts}\n  normal = {normal}\n  tangential = {tangential}\n  t2 = {t2}\n"
        f"  steps = {', '.join(['1'] * n)}\n/\n"
        f"&solver\n  scheme = 'implicit'\n/\n"
        f"&output\n  file = '{h5.name}'\n/\n")
    h5.unlink(missing_ok=True)
    proc = subprocess.run([args.history, deck.name], cwd=out, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"direct_shear: interlock-history failed on {deck}:\n{proc.stdout}{proc.stderr}")
    import h5py
    with h5py.File(h5, "r") as f:
        case = f["cases/0001"]
        data = {k: case[k][()] for k in case.keys()}
    worst = {}

    def compare(name, ccx_values, history_values, scale=None):
        scale = scale or max(max(abs(v) for v in ccx_values), 1e-300)
        err = max(abs(a - b) for a, b in zip(ccx_values, history_values)) / scale
        worst[name] = (err, scale)

    # Tractions relative to the largest traction (norm of the vector) of the run.
    trac = data["traction"]
    t_scale = max(math.sqrt(sum(x * x for x in t)) for t in t_ccx)
    for c, label in enumerate(["normal traction", "shear traction", "t2 traction"]):
        compare(label, [t[c] for t in t_ccx], [trac[i][c] for i in range(n)], t_scale)
    col = 0
    for name, count in names:
        hist = data.get(name)
        for k in range(count):
            values = [r[col + k] for r in sdv]
            if hist is not None:
                hv = [hist[i][k] if count > 1 else hist[i] for i in range(n)]
                largest = max(abs(v) for v in values)
                if largest > 0:
                    # A friction traction K_t (s - sf) replayed from printed separations
                    # carries an absolute error (K_t times their rounding): it is measured
                    # against the run's largest traction too, or a plane whose friction stays
                    # near zero (the flat plane's strike friction on a circle, 2e-3 MPa) would
                    # fail on rounding alone.
                    scale = max(largest, t_scale) if name in TRACTION_STATE else None
                    compare(f"{name}[{k + 1}]" if count > 1 else name, values, hv, scale)
        col += count
    traction_names = ("normal traction", "shear traction", "t2 traction")
    state_tolerance = args.state_tolerance
    failed = {k: v for k, v in worst.items()
              if v[0] > (args.tolerance if k in traction_names else state_tolerance)}

    lines = [f"{job.name}: {args.element}, tangent option {args.tangent}, point {point}, "
             f"{n} printed increments",
             "agreement with interlock-history (max |ccx - history| / max |ccx|):"]
    lines += [f"  {k:28s} {v[0]:.2e}  (scale {v[1]:.4g})" for k, v in sorted(worst.items())]
    peak = max(range(n), key=lambda i: math.hypot(t_ccx[i][1], t_ccx[i][2]))
    lines.append(f"peak shear traction |(t_T1, t_T2)| = "
                 f"{math.hypot(t_ccx[peak][1], t_ccx[peak][2]):.4g} MPa "
                 f"(t_T1 {t_ccx[peak][1]:.4g}, t_T2 {t_ccx[peak][2]:.4g}; t_N {t_ccx[peak][0]:.4g})"
                 f" at slip (s_T1, s_T2) = ({s_ccx[peak][1]:.4g}, {s_ccx[peak][2]:.4g}) mm")
    lines += path_lines + convergence_lines(job)
    (out / f"{job.name}_convergence.txt").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
    if path_failed:
        sys.exit("direct_shear: FAIL, the layer's slip left the imposed path by more than "
                 "twice the blocks' elastic shear + 1e-4 mm")
    if failed:
        sys.exit(f"direct_shear: FAIL, disagreement above {args.tolerance} (tractions), "
                 f"{state_tolerance} (state): {sorted(failed)}")
    print(f"direct_shear: {args.element} agrees with interlock-history to {args.tolerance} "
          f"(tractions), {state_tolerance} (state)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("command", choices=["write", "run"],
                        help="write: the .inp file only (DIR/direct_shear_<element>.inp); run: "
                             "write it, run ccx, replay the layer point through "
                             "interlock-history and compare")
    parser.add_argument("--element", choices=sorted(AXES), required=True,
                        help="the elements (layer axes normal, slip): C3D8 (3, 1), CPE4 (2, 1), "
                             "CAX4 (1, 3: a bar in a sleeve, cylindrical orientation)")
    parser.add_argument("--tangent", type=int, choices=[1, 2], default=1,
                        help="interlock PROPS 20 (layer PROPS 24): 1 the exact tangent (ccx "
                             "averages it), 2 the symmetric one for hosts that symmetrize (1)")
    parser.add_argument("--out", default=".",
                        help="folder for the deck, ccx's files, the replay deck and its HDF5 "
                             "file, <job>_convergence.txt (.)")
    parser.add_argument("--ccx", help="run: the ccx binary linked with interlock's umat "
                                      "(scripts/build_calculix.sh prints its path)")
    parser.add_argument("--history", help="run: the interlock-history binary")
    parser.add_argument("--tolerance", type=float, default=TRACTION_TOLERANCE,
                        help="the tractions' tolerance, relative to the run's largest traction "
                             f"({TRACTION_TOLERANCE:g}; seen <= 9.1e-7)")
    parser.add_argument("--state-tolerance", type=float, default=STATE_TOLERANCE,
                        help="the state variables' tolerance, each relative to its largest "
                             f"value ({STATE_TOLERANCE:g}): ccx prints SDV with 7 digits, and a "
                             "friction traction K_t (s - sf) replayed from the printed "
                             "separations carries K_t times their rounding (seen 1.7e-5 with the "
                             "slip at 45 deg)")
    parser.add_argument("--shear-traction", type=float,
                        help="measurement variant: step 2 shears by this mean traction [MPa] "
                             "(a force on the tied top face, automatic increments) instead of "
                             "imposing the slip (default: the slip imposed)")
    parser.add_argument("--angle-deg", type=float, default=0.0,
                        help="C3D8: the slip direction from the slip axis x towards y [deg] (0)")
    parser.add_argument("--path", choices=["straight", "square", "circle"], default="straight",
                        help="C3D8: the slip path in the layer's plane (straight: 1.5 mm along "
                             "--angle-deg in 150 increments; square and circle turned by "
                             "--angle-deg) (straight)")
    parser.add_argument("--side", type=float, default=0.75, help="--path square: side [mm] (0.75)")
    parser.add_argument("--radius", type=float, default=0.5, help="--path circle: radius [mm] (0.5)")
    parser.add_argument("--increments", type=int,
                        help="--path square or circle: the slip step's fixed increments "
                             "(default 200)")
    parser.add_argument("--ria", choices=["paper", "azimuthal"], default="paper",
                        help="C3D8: the RIA (layer PROPS 25 `ria`) (paper)")
    parser.add_argument("--n-azimuths", type=int, default=3, choices=range(1, 7),
                        help="--ria azimuthal: N_a (layer PROPS 26), 1 + 2 N_a planes (3)")
    parser.add_argument("--prefractured", action="store_true",
                        help="the interface fully debonded from the start (D = 1; interlock PROPS 10)")
    args = parser.parse_args()
    if args.command == "write":
        path = pathlib.Path(args.out) / f"direct_shear_{args.element.lower()}.inp"
        path.write_text(model(args.element, args.tangent, angle_deg=args.angle_deg,
                              ria=args.ria, n_azimuths=args.n_azimuths,
                              path=imposed_slip(args)[1]))
        print(path)
        return
    if not (args.ccx and args.history):
        parser.error("run needs --ccx and --history")
    python_with.modules("h5py")     # before anything runs: it may restart this script
    run(args)


if __name__ == "__main__":
    main()
