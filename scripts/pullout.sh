#!/usr/bin/env bash
# The paper's pull-out test (section 4.2) in CalculiX with the interlock thin-layer UMAT, in one
# command, from the repository root on a fresh Debian 12 machine (as root, or with sudo):
#
#     bash scripts/pullout.sh [--coarse] [--out DIR] [make_mesh.py options]
#
#  1. installs what is missing (scripts/ensure_packages.sh: python3-numpy, -matplotlib, ...);
#  2. builds ccx 2.20 with interlock's UMAT (scripts/build_calculix.sh; cached: a second run
#     only relinks when src/ or umat/ changed);
#  3. meshes the model (examples/calculix/pullout/make_mesh.py; 5 mm elements, --coarse: 10 mm),
#     runs ccx on 2 threads, post-processes (examples/calculix/pullout/post.py).
#
# Writes DIR (default out/pullout, or out/pullout-coarse) with the ccx files, summary.json and
# fig16_pullout_stress.png (pull-out stress vs s/D, the paper's Fig. 16), fig17_bar_strain.png
# (the bar's axial strain along its length, Fig. 17), interfaces.png (slip, damage, wear along
# the bar) and convergence.png. Exit status: 0 when the bar's top reached 5.2 mm, else 2
# (or 1 when something could not run). The model and its choices: docs/calculix_pullout.md.
set -euo pipefail
cd "$(dirname "$0")/.."

out=""
mesh_args=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --coarse) mesh_args+=(--element 10); coarse=1; shift ;;
    --out) out="$2"; shift 2 ;;
    *) mesh_args+=("$1"); shift ;;
  esac
done
if [[ -z "$out" ]]; then
  out="out/pullout${coarse:+-coarse}"
fi

bash scripts/ensure_packages.sh
ccx="$(bash scripts/build_calculix.sh | tail -n 1)"
if [[ ! -x "$ccx" ]]; then
  echo "pullout.sh: scripts/build_calculix.sh gave no ccx binary" >&2
  exit 1
fi
status=0
/usr/bin/python3 examples/calculix/pullout/run.py --ccx "$ccx" --dir "$out" --threads 2 \
  "${mesh_args[@]}" || status=$?
echo "pullout.sh: figures and summary.json in $(pwd)/$out"
exit "$status"
