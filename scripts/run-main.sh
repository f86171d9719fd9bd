#!/bin/bash
# Install, build, and run the main job: the reference case (the paper's 235 m
# arch dam, prm/paper_235m_dam.prm, every stage and output) on its own
# converged mesh (doc/convergence.md), its progress streamed, then draw its
# figures. About half an hour and 6 GB on a 2-core machine (README, "The
# main job"). Results go to ./results/paper_235m_dam, figures to
# ./results/figures. The coarse mesh, a quick look that is not converged:
#   /usr/bin/python3 scripts/compare-paper-variants.py --mesh coarse --run reference
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh
/usr/bin/python3 scripts/compare-paper-variants.py --run reference --rerun
