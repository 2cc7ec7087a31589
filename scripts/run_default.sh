#!/usr/bin/env bash
# Fresh machine → pictures: installs the packages, builds, and renders the built-in default
# scene (a few thousand characters running) into crowd.mp4 and ./frames/frame_0000.png ...
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install_deps.sh
./scripts/build.sh
LP_NUM_THREADS=${LP_NUM_THREADS:-$(nproc)} build/bin/throng render --out frames --video crowd.mp4 --overwrite "$@"
