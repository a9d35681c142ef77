#!/bin/sh
# run.sh of VisSweep's device bundle (made by scripts/device-bundle.sh, which copies this file):
# on a Linux x86-64 machine with a Vulkan loader and driver, runs
#   vissweep info                          -> info.txt
#   the unit tests (the device's and the CPU's, in one process) -> tests.json, tests.txt
#   bench overhead (brain_sunrise, 512^2)  -> overhead.json   (paths/s per strategy)
#   bench sweeps (ch2better, the renderer's default grid, profiled) -> sweeps.json
#   bench convergence (mri_sunrise, 512^2, budgets 0.25-2 s) -> convergence.json
# and writes summary.txt (one page: the device, the tests' counts, each benchmark's table).
#
#   ./run.sh [--quick] [RESULTS]     RESULTS default: results/ beside run.sh
#   --quick: the Vulkan and driver tests only and each benchmark's --quick form (seconds on lavapipe)
#
# Exit status: 2 when the bundle cannot run here (a library, glibc, the Vulkan loader, a driver or
# a feature the kernels need is missing: the message names it), 1 when a test or a benchmark failed,
# 0 otherwise. POSIX sh and coreutils only: the machine needs nothing else.
set -u
here=$(CDPATH= cd -- "$(dirname -- "$0")" && pwd)
quick=0
if [ "${1:-}" = "--quick" ]; then
  quick=1
  shift
fi
results=${1:-$here/results}
if ! mkdir -p "$results"; then
  echo "run.sh: cannot create the results folder $results" >&2
  exit 2
fi
results=$(CDPATH= cd -- "$results" && pwd)
summary="$results/summary.txt"
# The programs and their libraries, packed by device-bundle.sh: unpacked once, beside run.sh when
# its folder is writable, else in $TMPDIR.
programs="$here/programs"
if [ ! -x "$programs/bin/vissweep" ]; then
  if ! mkdir -p "$programs" 2> /dev/null || [ ! -w "$programs" ]; then
    programs=$(mktemp -d "${TMPDIR:-/tmp}/vissweep-bundle.XXXXXX") || { echo "run.sh: error: no folder to unpack into" >&2; exit 2; }
  fi
  if ! gzip -dc "$here/programs.tar.gz" | tar -x -C "$programs"; then
    echo "run.sh: error: cannot unpack $here/programs.tar.gz into $programs (tar and gzip are needed)" >&2
    exit 2
  fi
fi
tool="$programs/bin/vissweep"
tests="$programs/bin/vissweep_unit_tests"
LD_LIBRARY_PATH="$programs/lib"
export LD_LIBRARY_PATH
# Headless: nothing here needs an X display.
unset DISPLAY
status=0

cannot_run() {
  echo "run.sh: error: $*" >&2
  printf 'CANNOT RUN HERE: %s\n' "$*" >> "$summary"
  exit 2
}

# A step with a time limit where coreutils' timeout exists.
limited() {
  seconds=$1
  shift
  if command -v timeout > /dev/null 2>&1; then
    timeout "$seconds" "$@"
  else
    "$@"
  fi
}

{
  echo "VisSweep device bundle: $(date -u '+%Y-%m-%d %H:%M UTC') on $(uname -n) ($(uname -m), $(uname -r))"
  [ "$quick" = 1 ] && echo "QUICK run (--quick): tests and benchmarks in their short forms, not figures to quote"
} > "$summary"

# 1. The bundle's programs start here: every library found (ldd, where there is one) and glibc new enough.
if command -v ldd > /dev/null 2>&1; then
  missing=$(ldd "$tool" "$tests" 2>&1 | awk '/not found/ { print $1 }' | sort -u | tr '\n' ' ')
  if [ -n "$missing" ]; then
    case "$missing" in
      *libvulkan*) cannot_run "no Vulkan loader: libvulkan.so.1 is not installed (install the Vulkan loader and a driver)" ;;
      *) cannot_run "shared libraries not found: $missing" ;;
    esac
  fi
fi
if ! version=$("$tool" --version 2>&1); then
  cannot_run "the bundled tool does not start on this machine: $version"
fi

# 2. The Vulkan device: the loader, a driver, and what the kernels need (vissweep info names what is missing).
if ! limited 120 "$tool" info > "$results/info.txt" 2>&1; then
  cannot_run "no usable Vulkan device: $(cat "$results/info.txt")"
fi
if grep -q "MISSING for VisSweep" "$results/info.txt"; then
  cannot_run "$(grep "MISSING for VisSweep" "$results/info.txt")"
fi
{
  echo "$version"
  sed -n '/VisSweep computes on/,$p' "$results/info.txt" | grep -v "data in"
  echo
} >> "$summary"

# 3. The unit tests, with the bundle's data, all in one process (several contexts, the validation
# layers' among them: VulkanCore.AllInOneProcess).
filter="*"
[ "$quick" = 1 ] && filter="VulkanCore.*:DriverChoices.*:DriverLoopLimit.*"
VISSWEEP_TEST_DATA_DIR="$here/data" VISSWEEP_TEST_CH2="$here/data/ch2.nii.gz" \
  limited 1200 "$tests" --gtest_filter="$filter" --gtest_output="json:$results/tests.json" > "$results/tests.txt" 2>&1
rc=$?
passed=$(grep -c '^\[       OK \]' "$results/tests.txt")
failed=$(grep '^\[  FAILED  \]' "$results/tests.txt" | grep -v 'listed below\|tests, listed' | sed 's/ (.*//' | sort -u)
{
  echo "Unit tests ($filter): $passed passed, exit $rc"
  [ -n "$failed" ] && echo "$failed"
  echo
} >> "$summary"
[ "$rc" = 0 ] || status=1

# 4. The benchmarks; each prints its table (kept in the summary) and writes its JSON.
bench() {
  name=$1
  shift
  limited 900 "$tool" bench "$@" --json "$results/$name.json" > "$results/$name.txt" 2>&1
  rc=$?
  {
    echo "bench $name: exit $rc  (vissweep bench $*)"
    grep -v '^\[' "$results/$name.txt" | grep -v '^ *$' | tail -n 25
    echo
  } >> "$summary"
  [ "$rc" = 0 ] || status=1
}
if [ "$quick" = 1 ]; then
  bench overhead overhead "$here/scenes/tiny.json" --quick
  bench sweeps sweeps --volume "$here/data/ch2.nii.gz" --quick
  bench convergence convergence "$here/scenes/tiny.json" --quick --strategies environment,two-step \
    --reference-dir "$results/references"
else
  bench overhead overhead "$here/scenes/brain_sunrise.json" --width 512 --height 512
  bench sweeps sweeps --volume "$here/data/ch2better.nii.gz" --profile --repeats 3 --subsets 0 --only renderer
  bench convergence convergence "$here/scenes/mri_sunrise.json" --width 512 --height 512 \
    --budgets 0.25,0.5,1,2 --repeats 1 --reference-spp 4096 --reference-dir "$results/references"
fi

echo "results in $results (summary.txt); exit $status" >> "$summary"
cat "$summary"
exit $status
