#!/bin/bash
# Install, build, and run the main job: the default case on its default mesh.
# Results go to ./results (see the case file's Output section).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-dependencies.sh
bash scripts/build.sh
./build/archdam prm/box_dam_on_rock.prm
