#!/bin/bash
# AddressSanitizer + UndefinedBehaviorSanitizer build of the library, the
# application and the test executables, and a run of the serial tests with any
# sanitizer report failing the test (doc/sanitizers.md):
#   scripts/run-sanitizers.sh [BUILD_DIR] [TESTS] [JOBS]
# TESTS: a regular expression of test names (without tests/) to build and run
# (default: all; only the serial variants run, never mpirun=2 or the fuzz targets).
# Not part of the test suite: the build alone takes an hour or more.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build=${1:-$root/build-sanitize}
tests=${2:-.*}
jobs=${3:-1}
# Release: deal.II's optimized library and its -O2 (its flags come after
# ours); -g1 keeps the line tables for the reports at little compile cost.
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g1"
log="$build/sanitize-build.log"
mkdir -p "$build"
start=$(date +%s)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
  -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" > "$log" 2>&1 \
  || { cat "$log"; exit 1; }
targets=(archdam)
for source in "$root"/tests/*.cc; do
  name=$(basename "$source" .cc)
  [[ $name =~ ^($tests)$ ]] && targets+=("tests.$name")
done
cmake --build "$build" -j"$jobs" "${targets[@]/#/--target=}" >> "$log" 2>&1 \
  || { tail -40 "$log"; exit 1; }
echo "build: $(( $(date +%s) - start )) s"
# Every report ends the process with an error; leaks are checked against
# scripts/lsan.supp, which lists only third-party libraries (OpenMPI, PETSc,
# ... keep their start-up allocations until exit). The slow unwinder gives
# each leak its whole stack: the fast one stops at the first library built
# without frame pointers (OpenMPI's), and the suppressions cannot match.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:fast_unwind_on_malloc=0:detect_stack_use_after_return=0:check_initialization_order=1"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
start=$(date +%s)
cd "$build"
status=0
ctest -j"$jobs" -R "^tests/($tests)$" --output-on-failure --timeout 3000 || status=$?
echo "tests: $(( $(date +%s) - start )) s"
exit $status
