#!/bin/bash
# Every shipped case file (prm/*.prm) runs from a copy of prm/ in a temporary
# folder, started from another working directory, for a few time steps:
#   tests/shipped_examples.sh ARCHDAM SOURCE_DIR
# Only prm/ is copied, not data/: the ground-motion records the cases name as
# ground_motions/... must be found through the data folder (here the built-in
# one, data/ of the source tree; doc/user-guide.md, "Where input files are
# found"), and gmsh_blocks.prm's mesh next to the copied case file. Each case
# must exit with 0 and write its results into the temporary folder. Then:
# the data folder taken from ARCHDAM_DATA_DIR, and a case copied out alone
# with ARCHDAM_DATA_DIR pointing at an empty folder, which must stop with the
# message naming the file and both folders searched.
# Prints one line per case and "N passed, M failed"; exits 1 on any failure.
set -u
archdam=$(realpath "$1")
source_dir=$(realpath "$2")
tmp=$(mktemp -d "${TMPDIR:-/tmp}/archdam_shipped_examples.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cp -r "$source_dir/prm" "$tmp/prm"
mkdir "$tmp/run"
cd "$tmp/run" # not the folder of the case files
unset ARCHDAM_DATA_DIR
# The dense algebra's threads would wait for cores other jobs hold.
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1}

# 3 steps of 5 ms (the smallest time step of the cases, which the massed
# foundation's transmitting boundary needs) after the static stage.
short=(--set "Time integration/Time step=0.005" --set "Time integration/End time=0.015"
       --set "Output/Progress=false" --set "Output/Timer summary=false")
# The arch dams on their default (production) meshes take minutes and
# gigabytes even for 3 steps (arch_dam_massed_foundation: 307,884 DOFs, 160 s
# and 9.8 GB here; the paper's dam: README.md, "The main job"): they run on
# the coarse linear mesh of scripts/compare-paper-variants.py, which keeps
# every model part, stage and input file of the case (the Pacoima variant
# still reads its record through the data folder), 3-6 s each.
coarse=(--set "Finite element/Degree=1" --set "Mesh/Arch dam/Cells across each block=1"
        --set "Mesh/Arch dam/Cells through thickness=1" --set "Mesh/Arch dam/Cells over height=9")

passed=0
failed=0
report() { # report NAME STATUS(0 = pass) DETAIL LOG
  if [ "$2" -eq 0 ]; then
    passed=$((passed + 1))
    echo "PASS $1 ($3)"
  else
    failed=$((failed + 1))
    echo "FAIL $1: $3"
    [ -n "${4:-}" ] && [ -f "$4" ] && sed 's/^/    /' "$4" | tail -n 15
  fi
}

# run_case NAME CASE_FILE [extra arguments]: run, check exit code and outputs.
run_case() {
  local name=$1 case_file=$2
  shift 2
  local out="$tmp/run/out_$name" log="$tmp/run/$name.log" start=$SECONDS
  "$archdam" "$case_file" "${short[@]}" --set "Output/Directory=$out" "$@" > "$log" 2>&1
  local code=$?
  local seconds=$((SECONDS - start))
  if [ $code -ne 0 ]; then
    report "$name" 1 "exit code $code after ${seconds} s" "$log"
  elif [ -s "$out/suite.csv" ]; then # a record suite: one run per record
    local runs=0 record
    for record in "$out"/*/summary.json; do [ -s "$record" ] && runs=$((runs + 1)); done
    report "$name" $((runs < 3)) "a record suite, $runs runs, ${seconds} s" "$log"
  elif [ ! -s "$out/summary.json" ] || [ ! -s "$out/histories.csv" ]; then
    report "$name" 1 "no summary.json or histories.csv in $out" "$log"
  else
    report "$name" 0 "${seconds} s"
  fi
}

for case_file in "$tmp"/prm/*.prm; do
  name=$(basename "$case_file" .prm)
  case $name in
    paper_235m_dam* | arch_dam_massed_foundation) run_case "$name" "$case_file" "${coarse[@]}" ;;
    *) run_case "$name" "$case_file" ;;
  esac
done

# The data folder from ARCHDAM_DATA_DIR (a folder of the user's own).
mkdir -p "$tmp/my_data"
cp -r "$source_dir/data/ground_motions" "$tmp/my_data/"
ARCHDAM_DATA_DIR="$tmp/my_data" run_case "box_dam_on_rock, ARCHDAM_DATA_DIR" \
  "$tmp/prm/box_dam_on_rock.prm"

# A case copied out alone, its records in neither its folder nor the data
# folder: one message naming the parameter, the file and both folders.
mkdir -p "$tmp/alone" "$tmp/empty_data"
cp "$tmp/prm/box_dam_on_rock.prm" "$tmp/alone/"
log="$tmp/run/missing_record.log"
ARCHDAM_DATA_DIR="$tmp/empty_data" "$archdam" "$tmp/alone/box_dam_on_rock.prm" "${short[@]}" \
  --set "Output/Directory=$tmp/run/out_missing_record" > "$log" 2>&1
code=$?
expected="archdam: error: Ground motion/Component x/File: cannot find 'ground_motions/RSN6_IMPVALL.I_I-ELC180.AT2': it is neither in '$tmp/alone' (the case file's folder) nor in '$tmp/empty_data' (the data folder, from ARCHDAM_DATA_DIR)."
if [ $code -eq 1 ] && grep -qxF "$expected" "$log"; then
  report "a record missing from the data folder" 0 "exit code 1, the message names the file and the folders searched"
else
  report "a record missing from the data folder" 1 "exit code $code; expected exit code 1 and: $expected" "$log"
fi

echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
