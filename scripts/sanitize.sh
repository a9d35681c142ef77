#!/usr/bin/env bash
# Builds VisSweep with AddressSanitizer + UndefinedBehaviorSanitizer on its own code
# (-DVISSWEEP_SANITIZE="address;undefined", RelWithDebInfo, gcc) into build-asan/ and runs
#   - the unit tests (ctest label "unit": sampling math, the Vulkan core on lavapipe, sweeps,
#     the renderer's passes, environment maps, the OpenVDB reader), and
#   - the scene-file parser tests (Tool.SceneFile.*),
# under them. Usage: scripts/sanitize.sh [CTEST_REGEX]  (a regex runs only matching unit tests).
# Leak checking is on. Reports inside third-party code (Mesa/lavapipe, the Vulkan loader, VTK)
# are suppressed only through scripts/sanitizers/*.supp, each entry documented there; VisSweep's
# own code is never suppressed.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VISSWEEP_ASAN_BUILD_DIR:-$root/build-asan}"
jobs="${VISSWEEP_JOBS:-$(nproc)}"
regex="${1:-}"
"$root/scripts/setup-debian.sh"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DVISSWEEP_SANITIZE="address;undefined" -DVISSWEEP_WRAP_PYTHON=OFF
fi
cmake --build "$build" -j "$jobs" --target vissweep_unit_tests vissweep_tool_tests
supp="$root/scripts/sanitizers"
export LP_NUM_THREADS=1
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:halt_on_error=1:strict_init_order=1${VISSWEEP_ASAN_EXTRA:+:$VISSWEEP_ASAN_EXTRA}"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd "$build"
status=0
if [ -n "$regex" ]; then
  ctest -L unit -R "$regex" --output-on-failure --timeout 3000 || status=$?
else
  ctest -L unit --output-on-failure --timeout 3000 || status=$?
  ctest -R '^Tool\.SceneFile\.' --output-on-failure --timeout 600 || status=$?
fi
exit $status
