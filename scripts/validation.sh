#!/usr/bin/env bash
# Runs tests with the Vulkan validation layers on (VISSWEEP_VALIDATION=1; package
# vulkan-validationlayers) and fails if any test printed a validation message. Every VisSweep
# context then installs a debug messenger that counts warnings and errors and prints each as
# "VisSweep Vulkan validation: ..." (Module/vulkan/vsContext.cxx); this script collects them
# from ctest's log of the tests' output. Usage: scripts/validation.sh [CTEST_LABEL_REGEX]
# (default unit|render|tool). Uses the normal build (build/, or VISSWEEP_BUILD_DIR).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VISSWEEP_BUILD_DIR:-$root/build}"
labels="${1:-unit|render|tool}"
"$root/scripts/setup-debian.sh"
"$root/scripts/build.sh"
export LP_NUM_THREADS=1 VISSWEEP_VALIDATION=1
if ! "$build/bin/vissweep" info | grep -q 'validation layers: *on'; then
  echo "validation.sh: the validation layers did not load (is vulkan-validationlayers installed?)" >&2
  exit 1
fi
cd "$build"
status=0
xvfb-run -n "${VISSWEEP_XVFB_SERVER:-96}" -s "-screen 0 1280x1024x24 -noreset" \
  ctest -L "$labels" --output-on-failure --timeout 1500 || status=$?
log="$build/Testing/Temporary/LastTest.log"
messages=$(grep -c -E 'VisSweep Vulkan validation:|Validation (Error|Warning):' "$log" || true)
echo "validation messages in the tests' output: $messages"
if [ "$messages" != "0" ]; then
  grep -E 'VisSweep Vulkan validation:|Validation (Error|Warning):' "$log" | sort | uniq -c | sort -rn | head -20
  status=1
fi
exit $status
