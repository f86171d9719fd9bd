#!/bin/bash
# Install, build, and run the whole test suite (serial and mpirun -np 2 tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh
# OpenMPI refuses to run as root unless told that it is intended.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Build every test executable first (deal.II's test macros would otherwise
# build them inside ctest, where a test and its MPI variant race).
cmake --build build -j"$(nproc)" --target test_executables
cd build
ctest --output-on-failure -j"$(nproc)"
