#!/usr/bin/env bash
# The whole test suite, as README.md gives it: installs what is missing, builds the Release and
# the Debug (-fcheck=all -ffpe-trap=invalid,zero,overflow) configurations and runs every CTest
# suite in both. CalculiX (scripts/build_calculix.sh: Debian's ccx with interlock's umat, built
# once, relinked when our sources change) runs in the Release build only (label `calculix`).
# The unit suites are pFUnit tests: without network, pFUnit is built from the pinned archive in
# ../shared/vendor/ when it is there (once, in the Release tree; the Debug tree finds that
# install), else from an installed pFUnit (CMAKE_PREFIX_PATH) or the pinned download.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/ensure_packages.sh
jobs=$(nproc 2>/dev/null || echo 2)
echo "=== CalculiX with interlock's umat"
ccx="$(bash scripts/build_calculix.sh | tail -n 1)"
pfunit_archive=../shared/vendor/pFUnit-4.14.0-with-submodules.tar.gz
pfunit_options=(-DPython_EXECUTABLE=/usr/bin/python3)
if [ -f "$pfunit_archive" ]; then
  pfunit_options+=("-DINTERLOCK_PFUNIT_SOURCE=$(cd "$(dirname "$pfunit_archive")" && pwd)/$(basename "$pfunit_archive")"
    -DINTERLOCK_PFUNIT_SHA256=070200f8018c61d70198edfac73e5460b5407339f062af9832123aada516fada)
  echo "=== pFUnit from $pfunit_archive"
else
  echo "=== no $pfunit_archive: pFUnit must be installed (CMAKE_PREFIX_PATH) or downloadable"
fi
status=0
for config in Release Debug; do
  dir="build-test-$(echo "$config" | tr '[:upper:]' '[:lower:]')"
  echo "=== $config build in $dir"
  mkdir -p "$dir"
  ccx_option="-DINTERLOCK_CCX="
  [ "$config" = Release ] && ccx_option="-DINTERLOCK_CCX=$ccx"
  # One pFUnit for both configurations (its flags are its own): the Release tree's.
  prefix_option="-DCMAKE_PREFIX_PATH="
  [ "$config" = Debug ] && prefix_option="-DCMAKE_PREFIX_PATH=$PWD/build-test-release/_deps/pfunit-install"
  cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="$config" "$ccx_option" "$prefix_option" \
    "${pfunit_options[@]}" > "$dir/configure.log" 2>&1 || { cat "$dir/configure.log"; exit 1; }
  grep '^-- pFUnit' "$dir/configure.log" || true
  cmake --build "$dir" -j "$jobs"
  echo "=== $config tests"
  (cd "$dir" && ctest --output-on-failure -j "$jobs" --timeout 1500) || status=1
done
exit $status
