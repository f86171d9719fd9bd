#!/bin/bash
# Check that every documentation page the project cites can be opened: each
# `<name>.md` or `<name>.md §N` (also `§N and §M`, `§N, §M`, `§N–§M`) in the
# sources, tests, benchmarks, scripts, cases and documentation must name a
# file of this repository, and each cited section must be a heading of that
# file (`## §N ...`, or `## N. ...`). A bare name is looked up beside the
# citing file, then in doc/ and doc/theory/; a path is taken from the
# repository root or from the citing file's folder. Any mention of the
# design folder outside the repository fails too. Prints file:line for each
# citation that does not resolve; exit code 1 if there is one.
# Usage: bash scripts/check-citations.sh   (doc/style.md §5)
set -uo pipefail
set -f # no globbing of the path parts below
cd "$(dirname "$0")/.." || exit 1
export LC_ALL=C

paths=(source include app tests bench scripts prm doc README.md CMakeLists.txt)
existing=()
for p in "${paths[@]}"; do
  [ -e "$p" ] && existing+=("$p")
done

failures=0
fail() {
  echo "$1" >&2
  failures=$((failures + 1))
}

# REPLY = $1 with "." and ".." removed; fails if it leaves the repository.
normalize() {
  local IFS=/ part
  local parts=()
  for part in $1; do
    case $part in
      '' | .) ;;
      ..)
        [ ${#parts[@]} -gt 0 ] || return 1
        unset 'parts[${#parts[@]}-1]'
        parts=("${parts[@]}")
        ;;
      *) parts+=("$part") ;;
    esac
  done
  REPLY="${parts[*]}"
}

# REPLY = the repository path of the page cited as $2 in file $1, or fail.
resolve() {
  local file=$1 name=$2 dir candidate
  dir=${file%/*}
  [ "$dir" = "$file" ] && dir=.
  local candidates=()
  if [[ $name == /* ]]; then
    candidates=("$dir$name") # e.g. SOURCE_DIR "/../doc/<page>.md" in tests/
  elif [[ $name == */* ]]; then
    candidates=("$name" "$dir/$name")
  else
    candidates=("$dir/$name" "doc/$name" "doc/theory/$name")
  fi
  for candidate in "${candidates[@]}"; do
    normalize "$candidate" && [ -f "$REPLY" ] && return 0
  done
  return 1
}

# The section numbers of the headings of each page read so far.
declare -A headings
has_section() {
  local page=$1 section=$2 line list=" "
  if [ -z "${headings[$page]+set}" ]; then
    while IFS= read -r line; do
      # (§)? as a group: in the C locale § is two bytes, and §? would make
      # only the second optional
      [[ $line =~ ^#+[[:space:]]+(§)?([0-9]+(\.[0-9]+)*)\.?([[:space:]]|$) ]] &&
        list+="${BASH_REMATCH[2]} "
    done <"$page"
    headings[$page]=$list
  fi
  [[ ${headings[$page]} == *" $section "* ]]
}

number='[0-9]+(?:\.[0-9]+)*'
citation="(?:(?<=\\\\n)|(?<![A-Za-z0-9_./\\\\-]))[A-Za-z0-9_./-]*[A-Za-z0-9_-]\\.md(?![A-Za-z0-9_])(?: §$number(?:(?:–|-|, | and |, and | or )§$number)*)?"

while IFS= read -r hit; do
  file=${hit%%:*}
  rest=${hit#*:}
  line=${rest%%:*}
  text=${rest#*:}
  name=${text%% §*}
  [[ $name == //* ]] && continue # a web address
  if ! resolve "$file" "$name"; then
    fail "$file:$line: cites $name, which is not a file of this repository"
    continue
  fi
  page=$REPLY
  sections=${text#"$name"}
  while [[ $sections =~ §([0-9]+(\.[0-9]+)*) ]]; do
    section=${BASH_REMATCH[1]}
    sections=${sections#*"§$section"}
    has_section "$page" "$section" ||
      fail "$file:$line: cites $name §$section, but $page has no heading §$section"
  done
done < <(grep -rnoIP "$citation" "${existing[@]}")

# The design folder is not part of the repository: nothing may point there.
design='shared/[d]esign'
while IFS= read -r hit; do
  fail "$hit: mentions the design folder outside the repository; cite doc/ instead"
done < <(grep -rnIE "$design" "${existing[@]}" | cut -d: -f1,2)

if [ "$failures" -gt 0 ]; then
  echo "check-citations: $failures citation(s) do not resolve" >&2
  exit 1
fi
echo "check-citations: every cited page and section exists"
