#!/bin/bash
# Install, build, and run the main job: the reference case (the paper's 235 m
# arch dam, prm/paper_235m_dam.prm) on its default mesh, then draw its figures.
# Results go to ./results/paper_235m_dam, figures to ./results/figures.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh
./build/archdam prm/paper_235m_dam.prm
/usr/bin/python3 scripts/compare-paper-variants.py --run none
