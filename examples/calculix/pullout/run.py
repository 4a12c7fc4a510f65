#!/usr/bin/python3
"""Meshes, runs and post-processes one pull-out analysis with CalculiX.

    /usr/bin/python3 run.py --ccx PATH/ccx_interlock --dir OUT [--threads 2] [--figures DIR]
                            [--title TEXT] [make_mesh.py options, e.g. --element 10]

Writes OUT/pullout.inp (make_mesh.py), runs ccx in OUT (its log in OUT/ccx.log), then
post.py: OUT/summary.json (with the wall time of the ccx run added) and the figures (in
--figures, default OUT). Exit status 0 when the analysis reached the prescribed top
displacement, 2 when it stopped before, 1 when something could not run.
"""
import argparse
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "scripts"))
import python_with  # noqa: E402  (the python3 that has the modules below)

python_with.modules("numpy", "matplotlib")
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import post  # noqa: E402


def umat_share(run_dir):
    """Shares of ccx's CPU samples (perf report, by symbol): interlock's code (the bundle's
    module procedures and its umat), ccx's UMAT interface (umat_main, umat_abaqus: rotation
    into the local axes and the tangent's averaging), the linear solver (libspooles) and the
    rest (mostly ccx's element routines and assembly);
    of interlock's share, the part spent reading and checking PROPS (every call)."""
    out = subprocess.run(["perf", "report", "-i", "perf.data", "--stdio", "--sort", "dso,sym",
                          "--percent-limit", "0"], cwd=run_dir, capture_output=True,
                         text=True).stdout
    shares = {"interlock": 0.0, "interlock_props_and_prepare": 0.0, "ccx_umat_interface": 0.0,
              "spooles": 0.0, "other": 0.0}
    samples = 0
    for line in out.splitlines():
        if line.startswith("# Samples:"):
            text = line.split()[2]                 # e.g. 33K
            scale = {"K": 1e3, "M": 1e6}.get(text[-1], 1.0)
            samples = int(float(text.rstrip("KM")) * scale)
        fields = line.split()
        if len(fields) < 3 or not fields[0].endswith("%"):
            continue
        pct, sym = float(fields[0][:-1]), fields[-1]
        if "interlock" in sym or sym in ("umat_", "umat"):
            shares["interlock"] += pct           # all of it (the next key is a part)
            if any(k in sym for k in ("material_table", "material_prepare", "props_to")):
                shares["interlock_props_and_prepare"] += pct
        elif sym.startswith("umat_main") or sym.startswith("umat_abaqus"):
            shares["ccx_umat_interface"] += pct
        elif "spooles" in fields[1]:
            shares["spooles"] += pct
        else:
            shares["other"] += pct
    return {"samples": samples, "percent": {k: round(v, 2) for k, v in shares.items()}}


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--ccx", required=True, help="the ccx binary (linked with interlock)")
    p.add_argument("--dir", required=True, help="run directory")
    p.add_argument("--threads", type=int, default=2, help="OMP_NUM_THREADS for ccx (2)")
    p.add_argument("--figures", help="directory for the PNG files (default: --dir)")
    p.add_argument("--title", default="", help="text added to the figure titles")
    p.add_argument("--no-figures", action="store_true", help="summary only")
    p.add_argument("--profile", action="store_true",
                   help="run ccx under `perf record` (Debian's linux-perf) and add the share of "
                        "CPU samples spent in the UMAT to the summary")
    a, mesh_args = p.parse_known_args(argv)
    os.makedirs(a.dir, exist_ok=True)
    inp = os.path.join(a.dir, "pullout.inp")
    mesh = subprocess.run([sys.executable, os.path.join(HERE, "make_mesh.py"), "--output", inp]
                          + mesh_args)
    if mesh.returncode != 0:
        return 1
    for ext in (".dat", ".sta", ".cvg", ".frd"):
        path = os.path.join(a.dir, "pullout" + ext)
        if os.path.exists(path):
            os.remove(path)
    env = dict(os.environ, OMP_NUM_THREADS=str(a.threads),
               CCX_NPROC_EQUATION_SOLVER=str(a.threads))
    start = time.monotonic()
    with open(os.path.join(a.dir, "ccx.log"), "w") as log:
        try:
            prefix = (["perf", "record", "-q", "-F", "499", "-o", "perf.data", "--"]
                      if a.profile else [])
            rc = subprocess.run(prefix + [a.ccx, "-i", "pullout"], cwd=a.dir, stdout=log,
                                stderr=subprocess.STDOUT, env=env).returncode
        except OSError as e:
            print(f"run.py: cannot run {a.ccx}: {e}", file=sys.stderr)
            return 1
    wall = time.monotonic() - start
    job = os.path.join(a.dir, "pullout")
    for ext in (".dat", ".sta", ".cvg"):
        if not os.path.isfile(job + ext):
            print(f"run.py: ccx wrote no {job + ext} (exit {rc}); see {a.dir}/ccx.log",
                  file=sys.stderr)
            return 1
    summary, data = post.analyse(job)
    summary["ccx_exit_status"] = rc
    summary["wall_time_s"] = round(wall, 2)
    summary["threads"] = a.threads
    summary["mesh_options"] = " ".join(mesh_args)
    if a.profile:
        summary["profile"] = umat_share(a.dir)
    if not a.no_figures:
        post.plot(data, summary, a.figures or a.dir, a.title or " ".join(mesh_args) or "full")
    post.write_text(os.path.join(a.dir, "summary.json"), json.dumps(summary, indent=1) + "\n")
    s = summary
    print(f"pull-out {' '.join(mesh_args) or '(full)'}: reached {s['top_displacement_reached_mm']:.3f}"
          f" of {s['top_displacement_target_mm']} mm, {s['increments']} increments "
          f"({s['attempts_failed']} failed attempts), iterations median "
          f"{s['iterations_per_increment_median']} max {s['iterations_per_increment_max']}, "
          f"final force {s['final_force_N'] / 1000:.2f} kN, wall {wall:.1f} s")
    return 0 if s["completed"] else 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
