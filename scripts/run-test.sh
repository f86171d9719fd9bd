#!/bin/bash
# Run one test of tests/ and compare what it prints with its expected output
# (tests/CMakeLists.txt; doc/theory/conventions.md §9):
#   run-test.sh COMPARISON_FILE COMMAND [ARGUMENTS...]
# in the current directory (the test's own folder in the build tree). The
# command's standard output and error become `output`, normalized as deal.II's
# tests normalize theirs (its normalize.pl: "-0.00" printed as "0.00", dates),
# and compared with COMPARISON_FILE by numdiff with deal.II's test tolerances
# (absolute 1e-6, relative 1e-8). A failing run keeps `failing_output`, a
# failing comparison `output` and `failing_diff`, both printed.
set -u
comparison=$1
shift
export LC_ALL=C OMP_NUM_THREADS=2 OMPI_MCA_rmaps_base_oversubscribe=1
rm -f output failing_output failing_diff
"$@" > output 2>&1
status=$?
if [ $status -ne 0 ]; then
  mv output failing_output
  echo "RUN failed with exit code $status: $PWD/failing_output"
  cat failing_output
  exit 1
fi
perl -pi "${ARCHDAM_NORMALIZE:?}" output
if ! numdiff -a 1e-6 -r 1e-8 -s ' \t\r\n=,:;<>[](){}^' "$comparison" output > failing_diff; then
  echo "DIFF failed: $PWD/output against $comparison"
  head -n 40 failing_diff
  exit 1
fi
rm -f failing_diff
