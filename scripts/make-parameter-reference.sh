#!/bin/bash
# Regenerate doc/parameters.prm, the parameter reference, from the program.
# The test parameter_reference fails when it is out of date.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build}
{
  "$build"/archdam --print-parameters text
} > doc/parameters.prm
echo "wrote doc/parameters.prm"
