#!/usr/bin/env bash
# Installs every Debian 12 package Throng's build, tests, benchmarks and tools need.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config git
  libvulkan-dev libvulkan-volk-dev mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  glslang-tools glslang-dev spirv-tools
  libglm-dev libglfw3-dev libeigen3-dev libcli11-dev libstb-dev nlohmann-json3-dev
  libimgui-dev doctest-dev
  libopenmpi-dev openmpi-bin
  xvfb xauth gnuplot-nox
  clang libclang-rt-14-dev
  ffmpeg libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  libpugixml-dev
)
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update
$SUDO apt-get install -y --no-install-recommends "${packages[@]}"
