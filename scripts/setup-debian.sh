#!/usr/bin/env bash
# Installs VisSweep's build and test dependencies from Debian 12 packages.
# scripts/setup-debian.sh [--demo]: with --demo only what the demo needs (below).
# Idempotent: runs `apt-get update` and `apt-get install` only when a package is missing.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libvtk9-dev python3-vtk9 python3-numpy python3-matplotlib
  libvulkan-dev mesa-vulkan-drivers vulkan-tools vulkan-validationlayers
  glslang-tools spirv-tools libglm-dev
  libopenexr-dev libopenvdb-dev libtbb-dev libblosc-dev libboost-iostreams-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev
  xvfb xauth
  clang libclang-rt-14-dev
  mricron-data
)
# `--demo` (scripts/demo.sh): what configuring, building and running the demo needs. Left out:
# clang and its runtimes (the fuzz targets, scripts/fuzz.sh), the validation layers
# (scripts/validation.sh), matplotlib (the benchmarks' plots) and vulkan-tools: about 40 MB of
# downloads and 200 MB installed (apt-cache show). scripts/test.sh installs them all.
DEMO_LEAVES_OUT=(clang libclang-rt-14-dev vulkan-validationlayers python3-matplotlib vulkan-tools)
if [ "${1:-}" = "--demo" ]; then
  kept=()
  for p in "${PACKAGES[@]}"; do
    case " ${DEMO_LEAVES_OUT[*]} " in
      *" $p "*) ;;
      *) kept+=("$p") ;;
    esac
  done
  PACKAGES=("${kept[@]}")
fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} missing package(s): ${missing[*]}"
  SUDO=""
  if [ "$(id -u)" != "0" ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "setup: all ${#PACKAGES[@]} packages present"
fi
