#!/bin/bash
# Install what ArchDam needs from Debian 12's packages, and nothing else.
# Idempotent: packages already present are not touched, and apt-get is not
# called at all when everything is there.
set -euo pipefail

packages=(
  cmake make g++ perl             # build; perl: the tests' output normalization
  lld                             # LLVM's linker: links the test executables faster than gold
  libdeal.ii-dev                  # deal.II 9.4 with PETSc/MUMPS, Trilinos, HDF5, MPI
  libmumps-dev                    # MUMPS directly: the factorization condensed on the joints
  libscotch-dev                   # SCOTCH's nested dissection, an order of that factorization
  openmpi-bin                     # mpirun for the MPI tests
  libopenblas0-pthread            # 3-5x faster factorization than reference BLAS
  numdiff                         # test output comparison
  python3-matplotlib              # plots (/usr/bin/python3)
  python3-vtk9                    # VTK's readers: the vtk_output test opens the results as ParaView does
  python3-h5py                    # HDF5 for Python: the vtk_output test reads the XDMF output
  clang libclang-rt-14-dev        # fuzz targets (libFuzzer, sanitizers) in the test suite
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
