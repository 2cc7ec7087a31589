#!/usr/bin/env bash
# Re-renders the golden images the tests compare against (run after an intended visual change,
# then look at the new PNGs before committing them).
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
LP_NUM_THREADS=2 build/bin/throng render --characters 50 --size 320x180 --seed 7 --frames 4 --camera closeup \
  --eye 6,3.5,-9 --out "$tmp" >/dev/null 2>&1
cp "$tmp/frame_0003.png" tests/render/golden/small_scene.png
rm -rf "$tmp"
echo "updated tests/render/golden/small_scene.png"
