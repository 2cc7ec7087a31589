#!/bin/sh
# Installs the build into a fresh prefix and runs the installed throng from another folder:
# `--version`, a one-frame render and `throng view --help` (throng-view found beside throng).
# Usage: install_check.sh BUILD_DIR WORK_DIR
set -eu
build=$1
work=$2
rm -rf "$work"
mkdir -p "$work/prefix" "$work/elsewhere"
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
bin="$work/prefix/bin/throng"
test -x "$bin" || { echo "error: $bin was not installed"; exit 1; }
test -x "$work/prefix/bin/throng-view" || { echo "error: throng-view was not installed"; exit 1; }
test -f "$work/prefix/share/throng/storyboards/plaza_small.png" ||
  { echo "error: share/throng/storyboards/plaza_small.png was not installed"; exit 1; }
cd "$work/elsewhere"
"$bin" --version
"$bin" render -n 20 --frames 1 --size 64x48 --out frames
test -f frames/frame_0000.png || { echo "error: the installed throng wrote no frame"; exit 1; }
"$bin" view --help > /dev/null
echo "installed throng ran from $work/elsewhere"
