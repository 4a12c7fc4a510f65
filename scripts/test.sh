#!/usr/bin/env bash
# The whole test suite, as README.md gives it: installs what is missing, builds the Release and
# the Debug (-fcheck=all -ffpe-trap=invalid,zero,overflow) configurations and runs every CTest
# suite in both.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure_packages.sh
jobs=$(nproc 2>/dev/null || echo 2)
status=0
for config in Release Debug; do
  dir="build-test-$(echo "$config" | tr '[:upper:]' '[:lower:]')"
  echo "=== $config build in $dir"
  mkdir -p "$dir"
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="$config" > "$dir/configure.log" 2>&1 || {
    cat "$dir/configure.log"; exit 1; }
  cmake --build "$dir" -j "$jobs"
  echo "=== $config tests"
  (cd "$dir" && ctest --output-on-failure -j "$jobs" --timeout 1500) || status=1
done
exit $status
