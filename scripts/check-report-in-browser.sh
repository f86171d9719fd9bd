#!/bin/bash
# Open a run report (report.html, scripts/run_report.py) in headless Chromium
# (Debian's `chromium` package: apt-get install chromium) as a reader's
# browser does, from the file alone:
#   check-report-in-browser.sh REPORT.html [SCREENSHOT.png]
# Prints the messages the page wrote to the browser's console (an error is a
# line with "CONSOLE" and "Uncaught" or "error"), how many of its figures the
# browser decoded (the page counts them once loaded), and writes a screenshot
# of its first screen (1400 x 1000) if asked. Exit 1 if a figure did not
# load or the console shows an error.
set -u
report=$(realpath "${1:?usage: check-report-in-browser.sh REPORT.html [SCREENSHOT.png]}")
browser=$(command -v chromium || command -v chromium-browser) ||
  { echo "check-report-in-browser: no chromium (apt-get install chromium)"; exit 2; }
flags=(--headless=new --no-sandbox --disable-gpu --hide-scrollbars --window-size=1400,1000)
log=$(mktemp)
dom=$("$browser" "${flags[@]}" --enable-logging=stderr --v=0 --virtual-time-budget=10000 \
  --dump-dom "file://$report" 2> "$log")
console=$(grep "CONSOLE" "$log")
rm -f "$log"
counted=$(echo "$dom" | sed -n 's/.*data-figures-loaded="\([0-9]*\) of \([0-9]*\)".*/\1 \2/p' | awk 'NR == 1')
echo "console messages: ${console:-none}"
if [ -n "$counted" ]; then
  echo "figures the browser decoded: ${counted% *} of ${counted#* }"
else
  echo "figures: not counted (the page's script did not run)"
fi
if [ $# -ge 2 ]; then
  "$browser" "${flags[@]}" --screenshot="$(realpath -m "$2")" "file://$report" > /dev/null 2>&1 &&
    echo "screenshot: $2"
fi
status=0
echo "$console" | grep -qiE "uncaught|error" && status=1
{ [ -n "$counted" ] && [ "${counted% *}" = "${counted#* }" ]; } || status=1
exit $status
