#!/usr/bin/env bash
# Installs every Debian 12 package Throng's build, tests, benchmarks and tools need.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config git
  libvulkan-dev libvulkan-volk-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-tools glslang-dev spirv-tools
  libglm-dev libglfw3-dev libeigen3-dev libcli11-dev libstb-dev libisal-dev nlohmann-json3-dev
  libimgui-dev doctest-dev
  libopenmpi-dev openmpi-bin
  xvfb xauth gnuplot-nox
  clang libclang-rt-14-dev
  ffmpeg
  libtinygltf-dev
  libpugixml-dev
)
# The Khronos glTF-Validator runs on Node.js: Debian's nodejs/npm only where no node is installed.
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then packages+=(nodejs npm); fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends "${packages[@]}"

# glTF-Validator (npm package gltf-validator) into a project-local folder; the export tests run it.
root="$(cd "$(dirname "$0")/.." && pwd)"
validator="$root/build-tools/gltf-validator"
if [ ! -d "$validator/node_modules/gltf-validator" ]; then
  npm install --prefix "$validator" --no-audit --no-fund --loglevel=error gltf-validator@2.0.0-dev.3.10
fi
