#!/usr/bin/python3
"""Post-processes a CalculiX pull-out run (make_mesh.py's model): figures and a summary.

    /usr/bin/python3 post.py RUN_DIR/pullout [--figures DIR] [--summary FILE.json]

Reads JOB.inp (the geometry), JOB.dat (printed every increment: the grip's total force, the
axial and radial displacements of the bar's surface and of the concrete's face of the layer,
the layer's state variables, the plastic strain of the bar's outer elements), JOB.sta and
JOB.cvg (increments, attempts, iterations, residuals). Writes
  fig16_pullout_stress.png   pull-out stress F / (pi D^2 / 4) vs s / D (the paper's Fig. 16)
  fig17_bar_strain.png       the bar's surface axial strain along its length (Fig. 17)
  interfaces.png             slip, damage and wear of the interfaces along the bar
  convergence.png            global iterations per increment, residual sequences
and a JSON summary (the numbers the docs and the CTest use). Nothing is written if the run
cannot be read; each output is written under a temporary name and renamed when complete.
"""
import argparse
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "scripts"))
import python_with  # noqa: E402  (the python3 that has the modules below)

python_with.modules("numpy", "matplotlib")
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_mesh import BAR_DIAMETER, E_STEEL, HARDENING, SLEEVE_LENGTH, write_text  # noqa: E402

BAR_AREA = math.pi * BAR_DIAMETER ** 2 / 4.0
YIELD_STRESS = HARDENING[0][0]        # Table 3's f_sy = Table 4's first yield strength
WEDGE = 180.0                         # ccx prints CAX4 forces for a 2-degree wedge
PROFILE_LEVELS = (0.5, 1.0, 2.0, 3.0, 4.0, 5.2)   # top displacements [mm] of the profiles

HEADER = re.compile(r"^\s*(.+?)\s*for set\s+(\S+)\s+and time\s+(\S+)")
FORTRAN_EXP = re.compile(r"(\d)([+-]\d{3})$")


def to_float(text):
    """ccx prints 1.0-100 for 1.0E-100."""
    try:
        return float(text)
    except ValueError:
        return float(FORTRAN_EXP.sub(r"\1E\2", text))


def read_inp(path):
    """Node coordinates, node and element sets, top displacement of the grip."""
    nodes, sets, top = {}, {}, None
    mode, name = None, None
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s or s.startswith("**"):
                continue
            if s.startswith("*"):
                key = s.upper()
                mode, name = None, None
                if key.startswith("*NODE,") and "NSET=NALL" in key:
                    mode = "node"
                elif key.startswith("*NSET") or key.startswith("*ELSET"):
                    mode = "set"
                    name = re.search(r"SET=(\w+)", key).group(1)
                    sets[name] = []
                elif key.startswith("*BOUNDARY"):
                    mode = "boundary"
                continue
            fields = [v.strip() for v in s.split(",") if v.strip()]
            if mode == "node":
                nodes[int(fields[0])] = (float(fields[1]), float(fields[2]))
            elif mode == "set":
                sets[name].extend(int(v) if v.isdigit() else v for v in fields)
            elif mode == "boundary" and fields[0] == "TOP" and len(fields) == 4:
                top = float(fields[3])
    return nodes, sets, top


def read_dat(path):
    """{(what, set): [(time, rows)]} with rows a list of lists of numbers."""
    blocks = {}
    current = None
    with open(path) as f:
        for line in f:
            m = HEADER.match(line)
            if m:
                what = m.group(1).split("(")[0].strip()
                current = []
                blocks.setdefault((what, m.group(2)), []).append((to_float(m.group(3)), current))
                continue
            fields = line.split()
            if current is not None and fields:
                try:
                    current.append([to_float(v) for v in fields])
                except ValueError:
                    current = None
    return blocks


def read_sta(path):
    """Converged increments: (inc, attempts, iterations, total time, increment); ccx marks an
    unsuccessful attempt with a U after its number (those rows are skipped)."""
    rows = []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) == 7 and fields[0].isdigit() and fields[2].isdigit():
                rows.append((int(fields[1]), int(fields[2]), int(fields[3]),
                             to_float(fields[4]), to_float(fields[6])))
    return rows


def read_cvg(path):
    """Every iteration: (inc, attempt, iteration, residual force %, correction %)."""
    rows = []
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) == 9 and all(v.isdigit() for v in fields[:5]):
                rows.append((int(fields[1]), int(fields[2]), int(fields[3]),
                             to_float(fields[5]), to_float(fields[6])))
    return rows


def by_node(rows, nodes):
    """Rows (node, ux, uy, uz) sorted by height: y, ux, uy."""
    a = np.array([(nodes[int(r[0])][1], r[1], r[2]) for r in rows])
    return a[np.argsort(a[:, 0])]


def element_means(rows, columns):
    """{element: mean over its integration points of the given value columns}."""
    acc = {}
    for r in rows:
        acc.setdefault(int(r[0]), []).append([r[2 + c] if 2 + c < len(r) else 0.0
                                              for c in columns])   # 0: an elastic stand-in
    return {e: np.mean(np.array(v), axis=0) for e, v in acc.items()}


def element_heights(nodes, elements, inp_path):
    """Mid-height of each listed element, from the .inp connectivity."""
    wanted, heights, reading = set(elements), {}, False
    with open(inp_path) as f:
        for line in f:
            s = line.strip()
            if s.startswith("*"):
                reading = s.upper().startswith("*ELEMENT")
                continue
            if reading and s:
                v = [int(x) for x in s.split(",")]
                if v[0] in wanted:
                    heights[v[0]] = np.mean([nodes[n][1] for n in v[1:]])
    return heights


def analyse(job):
    nodes, sets, top = read_inp(job + ".inp")
    dat = read_dat(job + ".dat")
    sta = read_sta(job + ".sta")
    cvg = read_cvg(job + ".cvg")
    length = max(y for _, y in nodes.values())
    sleeve_start = length - SLEEVE_LENGTH

    forces = dat.get(("total force", "TOP"), [])
    t = np.array([0.0] + [tm for tm, _ in forces])
    force = np.array([0.0] + [rows[0][1] * WEDGE for _, rows in forces])
    s_top = t * top

    bar_u = {tm: by_node(rows, nodes) for tm, rows in dat.get(("displacements", "BARSURF"), [])}
    conc_u = {tm: by_node(rows, nodes) for tm, rows in dat.get(("displacements", "CONCSURF"), [])}
    layer = dat.get(("internal state variables", "LAYER"), [])
    peeq = dat.get(("equivalent plastic strain", "BAROUTER"), [])
    layer_elements = [e for e in sets["LAYERCLAY"] + sets["LAYERCONC"] if isinstance(e, int)]
    heights = element_heights(nodes, layer_elements + sets["BAROUTER"], job + ".inp")

    # Yielded length from the loaded end after each printed increment (PEEQ > 0).
    yielded = [0.0]
    for tm, rows in peeq:
        ys = [heights[e] for e, v in element_means(rows, [0]).items() if v[0] > 0.0]
        yielded.append(length - min(ys) if ys else 0.0)   # to the lowest yielded centre
    if not peeq:                      # an elastic steel (make_mesh.py --steel elastic)
        yielded = [0.0] * len(t)
    yielded = np.array(yielded)
    first_yield = next((k for k in range(1, len(yielded)) if yielded[k] > 0), None)

    profiles = []
    for level in PROFILE_LEVELS:
        if len(t) < 2 or s_top[-1] < level - 1e-9:
            continue
        tm = min(bar_u, key=lambda x: abs(x * top - level))
        b, c = bar_u[tm], conc_u[tm]
        ym = 0.5 * (b[1:, 0] + b[:-1, 0])
        strain = np.diff(b[:, 2]) / np.diff(b[:, 0])
        slip = b[:, 2] - c[:, 2]
        opening = c[:, 1] - b[:, 1]
        state = next(rows for x, rows in layer if x == tm)
        # STATEV 1-3 damage, 10-12 zeta, 13-15 theta of the planes -theta0, 0, +theta0,
        # 29-30 separation, 31-32 traction (normal, slip) in the interface's axes (ccx calls
        # the layer with NTENS = 6: the 3D law's 28 STATEV come first)
        means = element_means(state, list(range(34)))
        es = sorted(means, key=lambda e: heights[e])
        ye = np.array([heights[e] for e in es])
        damage = np.array([means[e][0:3].mean() for e in es])
        theta = np.array([means[e][12:15] for e in es])
        theta0 = np.where(ye > sleeve_start, 1.75, 45.0) * math.pi / 180.0
        wear = 1.0 - np.min(np.abs(theta[:, [0, 2]]), axis=1) / theta0
        zeta = np.array([means[e][9:12].max() for e in es])
        bond = np.array([means[e][31] for e in es])
        profiles.append(dict(level=level, s_top=tm * top, y=b[:, 0], ym=ym, strain=strain,
                             slip=slip, opening=opening, ye=ye, damage=damage, wear=wear,
                             zeta=zeta, bond=bond))

    def slip_ratio(p):
        clay = np.abs(p["slip"][p["y"] >= sleeve_start]).mean()
        below = np.abs(p["slip"][p["y"] < sleeve_start]).mean()
        return clay, below

    iterations = np.array([r[2] for r in sta])
    per_increment = {}
    for inc, att, it, res, corr in cvg:
        per_increment.setdefault(inc, []).append(it)
    total_iterations = len(cvg)
    summary = {
        "job": os.path.basename(job),
        "top_displacement_target_mm": top,
        "top_displacement_reached_mm": float(s_top[-1]) if len(t) else 0.0,
        "completed": bool(len(t) and abs(t[-1] - 1.0) < 1e-9),
        "bar_yield_force_N": YIELD_STRESS * BAR_AREA,
        "force_at_first_yield_N": float(force[first_yield]) if first_yield else None,
        "top_displacement_at_first_yield_mm": float(s_top[first_yield]) if first_yield else None,
        "final_force_N": float(force[-1]),
        "force_at_2.6mm_N": float(np.interp(2.6, s_top, force)) if s_top[-1] >= 2.6 else None,
        "yielded_length_mm": [float(v) for v in yielded],
        "yield_spreads_monotonically": bool(np.all(np.diff(yielded) >= -1e-9)),
        "increments": len(sta),
        "attempts_failed": int(sum(r[1] - 1 for r in sta)),
        "iterations_per_increment_median": float(np.median(iterations)) if len(sta) else None,
        "iterations_per_increment_max": int(iterations.max()) if len(sta) else None,
        "iterations_total_with_failed_attempts": total_iterations,
        "profiles": [],
    }
    for p in profiles:
        clay, below = slip_ratio(p)
        summary["profiles"].append({
            "top_displacement_mm": p["level"], "mean_slip_clay_mm": clay,
            "mean_slip_below_mm": below, "slip_ratio": clay / below if below > 0 else None,
            "yielded_length_mm": float(np.interp(p["s_top"], s_top, yielded)),
            "max_bar_strain": float(p["strain"].max())})
    return summary, dict(t=t, s_top=s_top, force=force, profiles=profiles, cvg=cvg, sta=sta,
                         length=length, sleeve_start=sleeve_start)


def save(fig, path):
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=80)
    os.replace(tmp, path)


def plot(data, summary, outdir, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(outdir, exist_ok=True)
    depth = lambda y: data["length"] - y            # noqa: E731  distance from the loaded end

    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(data["s_top"] / BAR_DIAMETER, data["force"] / BAR_AREA, "k-", lw=1.5,
            label="CalculiX + interlock")
    ax.axhline(YIELD_STRESS, color="0.6", ls=":", lw=1, label="bar yield, 350 MPa")
    ax.set_xlabel("s / D  (top displacement / bar diameter)")
    ax.set_ylabel("pull-out stress  F / (pi D^2/4)  [MPa]")
    ax.set_xlim(0, 0.3)
    ax.set_ylim(0, None)
    ax.set_title(f"Pull-out stress (paper Fig. 16) - {title}", fontsize=9)
    ax.legend(loc="lower right", fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, os.path.join(outdir, "fig16_pullout_stress.png"))
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(6, 4.2))
    for p in data["profiles"]:
        ax.plot(depth(p["ym"]), p["strain"] * 1e6, lw=1.2,
                label=f"s = {p['s_top']:.2f} mm ({p['s_top'] / BAR_DIAMETER:.3f} D)")
    ax.axhline(YIELD_STRESS / E_STEEL * 1e6, color="0.6", ls=":", lw=1, label="yield strain")
    ax.axvline(SLEEVE_LENGTH, color="0.6", ls="--", lw=1)
    ax.set_xlim(0, min(data["length"], 600))
    ax.set_yscale("log")
    ax.set_ylim(10, None)
    ax.set_xlabel("distance from the loaded end [mm]  (dashed: end of the clay sleeve)")
    ax.set_ylabel("bar surface axial strain [1e-6]")
    ax.set_title(f"Bar axial strain (paper Fig. 17) - {title}", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    save(fig, os.path.join(outdir, "fig17_bar_strain.png"))
    plt.close(fig)

    fig, axes = plt.subplots(4, 1, figsize=(6, 9.5), sharex=True)
    for p in data["profiles"]:
        lab = f"s = {p['s_top']:.2f} mm"
        axes[0].semilogy(depth(p["y"]), np.maximum(np.abs(p["slip"]), 1e-6), lw=1.2, label=lab)
        axes[1].plot(depth(p["ye"]), p["damage"], lw=1.2, label=lab)
        axes[2].plot(depth(p["ye"]), np.abs(p["bond"]), lw=1.2, label=lab)
        axes[3].plot(depth(p["ye"]), p["wear"], lw=1.2, label=lab)
    axes[0].set_ylabel("|slip| [mm]")
    axes[1].set_ylabel("damage (mean of planes)")
    axes[2].set_ylabel("|bond stress| [MPa]")
    axes[3].set_ylabel("wear 1 - theta/theta_0")
    axes[3].set_xlabel("distance from the loaded end [mm]  (dashed: end of the clay sleeve)")
    for ax in axes:
        ax.axvline(SLEEVE_LENGTH, color="0.6", ls="--", lw=1)
        ax.grid(alpha=0.3)
        ax.set_xlim(0, min(data["length"], 600))
    axes[0].legend(fontsize=7)
    axes[0].set_title(f"Interfaces along the bar - {title}", fontsize=9)
    fig.tight_layout()
    save(fig, os.path.join(outdir, "interfaces.png"))
    plt.close(fig)

    fig, axes = plt.subplots(1, 2, figsize=(9, 3.6))
    sta = data["sta"]
    axes[0].plot([r[3] * summary["top_displacement_target_mm"] for r in sta],
                 [r[2] for r in sta], "k.-", lw=0.8)
    axes[0].set_xlabel("top displacement [mm]")
    axes[0].set_ylabel("global iterations (converged attempt)")
    seq = {}
    for inc, att, it, res, corr in data["cvg"]:
        seq.setdefault((inc, att), []).append(max(res, 1e-12))
    for key in sorted(seq)[:: max(1, len(seq) // 25)]:
        axes[1].semilogy(range(1, len(seq[key]) + 1), seq[key], lw=0.8)
    axes[1].set_xlabel("iteration")
    axes[1].set_ylabel("residual force [% of average force]")
    axes[1].set_title("residual sequences (every k-th increment)", fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle(f"Convergence - {title}", fontsize=9)
    fig.tight_layout()
    save(fig, os.path.join(outdir, "convergence.png"))
    plt.close(fig)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("job", help="path of the job without extension (RUN_DIR/pullout)")
    p.add_argument("--figures", help="directory for the PNG files")
    p.add_argument("--summary", help="JSON summary file")
    p.add_argument("--title", default="", help="text added to the figure titles")
    a = p.parse_args(argv)
    for ext in (".inp", ".dat", ".sta", ".cvg"):
        if not os.path.isfile(a.job + ext):
            print(f"post.py: no {a.job + ext}", file=sys.stderr)
            return 1
    summary, data = analyse(a.job)
    if a.figures:
        plot(data, summary, a.figures, a.title or os.path.basename(a.job))
    text = json.dumps(summary, indent=1)
    if a.summary:
        write_text(a.summary, text + "\n")
    brief = {k: v for k, v in summary.items() if k not in ("yielded_length_mm",)}
    print(json.dumps(brief, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
