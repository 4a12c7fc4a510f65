#!/usr/bin/env bash
# The README's main command: from the repository root on a fresh Debian 12 machine (as root),
#   bash scripts/main.sh [DECK.nml]        (default: inputs/fig11.nml)
# installs what is missing, builds Release into build/, runs interlock-history on the deck
# writing out/<deck>.h5, plots out/<deck>.png and prints where the PNG is. Idempotent.
set -euo pipefail
cd "$(dirname "$0")/.."

deck="${1:-inputs/fig11.nml}"
if [[ ! -f "$deck" ]]; then
  echo "main.sh: no such deck: $deck" >&2
  exit 1
fi

# Debian packages, only those missing.
bash scripts/ensure_packages.sh

# Configure once, build Release (incremental).
if [[ ! -f build/build.ninja ]]; then
  # (no tests: the main job needs no pFUnit, which a firewalled machine may not have)
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DINTERLOCK_BUILD_TESTS=OFF
fi
cmake --build build -j 2 --target interlock-history

mkdir -p out
name="$(basename "${deck%.*}")"
status=0
./build/bin/interlock-history --output-dir out "$deck" || status=$?
if (( status == 1 )); then
  echo "main.sh: interlock-history rejected $deck" >&2
  exit 1
fi
/usr/bin/python3 scripts/plot_history.py "out/${name}.h5" -o "out/${name}.png" > /dev/null
if (( status == 2 )); then
  echo "main.sh: some case of $deck stopped early (see its status attribute)" >&2
fi
echo "PNG: $(pwd)/out/${name}.png"
