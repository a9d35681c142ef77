#!/usr/bin/env bash
# Sets everything up on Debian 12 and runs the whole test suite:
# unit tests (GoogleTest), image regression tests, Python tests, stress tests.
# Rendering tests need a display: the suite runs under xvfb-run.
# Then the fuzz targets (scripts/fuzz.sh --ctest): a clang build of their own in build-fuzz/,
# each target over its seeds and regression inputs, then fuzzed for 20 s; a crash fails the suite.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VISSWEEP_BUILD_DIR:-$root/build}"
t0=$(date +%s)
"$root/scripts/setup-debian.sh"
t1=$(date +%s)
"$root/scripts/build.sh"
t2=$(date +%s)
# One test at a time, one lavapipe worker thread: with more CPU-bound threads than cores,
# lavapipe's dispatch-and-wait slowed dispatch-heavy tests 10-100x (measured here).
export LP_NUM_THREADS=1
cd "$build"
status=0
# -noreset: by default Xvfb resets when its last client disconnects, i.e. after every test
# process, and a test connecting during the reset aborts with VTK's "bad X server connection"
# (measured here under load: 2 of 4 back-to-back runs of one render test without it, 0 of 6 with).
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure --timeout 1500 || status=$?
t3=$(date +%s)
"$root/scripts/fuzz.sh" --ctest || status=$?
t4=$(date +%s)
echo "setup $((t1 - t0)) s, build $((t2 - t1)) s, tests $((t3 - t2)) s, fuzz build + runs $((t4 - t3)) s"
exit $status
