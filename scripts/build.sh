#!/bin/bash
# Configure (Release) and build the library and `archdam` with its commands in
# build/ (the benchmarks: `cmake --build build --target benchmarks`).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 || { cat build.log; exit 1; }
cmake --build build -j"$(nproc)"
