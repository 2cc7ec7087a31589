#!/usr/bin/env bash
# Configures and builds the release tree (build/, binary at build/bin/throng).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
cmake --preset release
cmake --build --preset release -j"$jobs"
