#!/usr/bin/env bash
# Configures (once) and builds VisSweep (Release) into build/. Used by demo.sh and test.sh.
# scripts/build.sh [TARGET...]: those targets only (demo.sh: vissweep_demo, the libraries and the
# Python package); without targets everything (`all`: tests, benchmarks, the tool, examples).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VISSWEEP_BUILD_DIR:-$root/build}"
jobs="${VISSWEEP_JOBS:-$(nproc)}"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
fi
if [ $# -gt 0 ]; then
  cmake --build "$build" -j "$jobs" --target "$@"
else
  cmake --build "$build" -j "$jobs"
fi
