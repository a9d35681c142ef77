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
# The ParaView plugin (issue 36) for the ParaView.Pvbatch test, built against Debian's ParaView 5.11
# by scripts/paraview-plugin.sh (as root: it installs paraview-dev without recommends, which leaves
# Debian's VTK 9.1 packages in place). VISSWEEP_TEST_PARAVIEW=0 leaves it out (the test is then skipped).
pv_status=0
if [ "${VISSWEEP_TEST_PARAVIEW:-1}" != 0 ]; then
  if [ "$(id -u)" = 0 ]; then
    "$root/scripts/paraview-plugin.sh" || pv_status=$?
  else
    echo "test: the ParaView plugin is built as root only (scripts/paraview-plugin.sh); ParaView.Pvbatch will be skipped"
  fi
fi
t2=$(date +%s)
# One test at a time, one lavapipe worker thread: with more CPU-bound threads than cores,
# lavapipe's dispatch-and-wait slowed dispatch-heavy tests 10-100x (measured here).
export LP_NUM_THREADS=1
cd "$build"
status=$pv_status
# -noreset: by default Xvfb resets when its last client disconnects, i.e. after every test
# process, and a test connecting during the reset aborts with VTK's "bad X server connection"
# (measured here under load: 2 of 4 back-to-back runs of one render test without it, 0 of 6 with).
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" ctest --output-on-failure --timeout 1500 || status=$?
t3=$(date +%s)
"$root/scripts/fuzz.sh" --ctest || status=$?
t4=$(date +%s)
echo "setup $((t1 - t0)) s, build $((t2 - t1)) s, tests $((t3 - t2)) s, fuzz build + runs $((t4 - t3)) s"
exit $status
