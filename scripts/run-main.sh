#!/bin/bash
# Install, build, and run the main job: the reference case (the paper's 235 m
# arch dam, prm/paper_235m_dam.prm, every stage and output), then draw its
# figures. It runs on the coarse mesh of scripts/compare-paper-variants.py:
# the case's default (production) mesh runs every stage too, but its 4,000
# steps take hours on machines of this kind (README, "The main job"). Results go to ./results/paper_235m_dam_coarse, figures to
# ./results/figures_coarse.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh
/usr/bin/python3 scripts/compare-paper-variants.py --mesh coarse --run reference --rerun
