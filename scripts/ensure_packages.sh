#!/usr/bin/env bash
# Installs the Debian packages interlock needs, only those that are missing (Debian 12).
# Sourced or run by scripts/main.sh, scripts/test.sh and .ci/run.
set -euo pipefail
# m4 and python3: pFUnit's build (gFTL's templates, the .pf preprocessor), when it is built
# from source for the tests. g++, libdeal.ii-dev (deal.II 9.4 with MPI, p4est, PETSc with
# MUMPS and hypre), openmpi-bin and libopenmpi-dev: the deal.II example (examples/dealii) and
# its tests (label mpi; about 250 packages, 1.6 GB, the first time).
needed=(gfortran cmake ninja-build libhdf5-dev liblapack-dev libblas-dev
        python3-h5py python3-matplotlib python3-numpy python3 m4
        g++ libdeal.ii-dev openmpi-bin libopenmpi-dev)
missing=()
for p in "${needed[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "interlock: installing missing Debian packages: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
