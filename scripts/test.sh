#!/usr/bin/env bash
# The whole test suite, as README.md gives it: installs what is missing, builds the Release and
# the Debug (-fcheck=all -ffpe-trap=invalid,zero,overflow) configurations and runs every CTest
# suite in both. CalculiX (scripts/build_calculix.sh: Debian's ccx with interlock's umat, built
# once, relinked when our sources change) runs in the Release build only (label `calculix`).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure_packages.sh
jobs=$(nproc 2>/dev/null || echo 2)
echo "=== CalculiX with interlock's umat"
ccx="$(bash scripts/build_calculix.sh | tail -n 1)"
status=0
for config in Release Debug; do
  dir="build-test-$(echo "$config" | tr '[:upper:]' '[:lower:]')"
  echo "=== $config build in $dir"
  mkdir -p "$dir"
  ccx_option="-DINTERLOCK_CCX="
  [ "$config" = Release ] && ccx_option="-DINTERLOCK_CCX=$ccx"
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="$config" "$ccx_option" > "$dir/configure.log" 2>&1 || {
    cat "$dir/configure.log"; exit 1; }
  cmake --build "$dir" -j "$jobs"
  echo "=== $config tests"
  (cd "$dir" && ctest --output-on-failure -j "$jobs" --timeout 1500) || status=1
done
exit $status
