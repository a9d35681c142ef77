#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, -fsanitize=fuzzer,address,undefined) into build-fuzz/ and
# runs each for SECONDS (default 20) on its growing corpus (build-fuzz/Testing/Fuzz/corpus/),
# starting from the seeds and the checked-in regression inputs. Crashes are saved under
# build-fuzz/Testing/Fuzz/artifacts/. Usage: scripts/fuzz.sh [SECONDS] [TARGET...]
#   TARGET: scene_file, environment_map, openvdb, volume_file (default: all four).
# The same runs are ctest tests labelled "fuzz" in build-fuzz (ctest -L fuzz).
#
# scripts/fuzz.sh --ctest: builds, then runs `ctest -L fuzz` in build-fuzz (what scripts/test.sh
# does): each target over its seeds and regression inputs, then a short run of
# VISSWEEP_FUZZ_SECONDS (a CMake cache variable, 20 s) each. Fails on any crash, sanitizer
# report, leak, timeout or out-of-memory; ctest prints libFuzzer's output and the saved input.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VISSWEEP_FUZZ_BUILD_DIR:-$root/build-fuzz}"
jobs="${VISSWEEP_JOBS:-$(nproc)}"
ctest_mode=0
if [ "${1:-}" = "--ctest" ]; then
  ctest_mode=1
  shift
fi
seconds="${1:-20}"
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene_file environment_map openvdb volume_file)
"$root/scripts/setup-debian.sh"
if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DVISSWEEP_FUZZ=ON -DVISSWEEP_BUILD_TESTING=OFF -DVISSWEEP_WRAP_PYTHON=OFF
fi
cmake --build "$build" -j "$jobs" --target vissweep_fuzz
fuzz="$build/Testing/Fuzz"
if [ $ctest_mode = 1 ]; then
  status=0
  (cd "$build" && ctest -L fuzz --output-on-failure) || status=$?
  # Executions and speed of each short run (ctest shows libFuzzer's output only on failure).
  awk '/^[0-9]+\/[0-9]+ Test: /{t=$3} /^stat::(number_of_executed_units|average_exec_per_sec):/{print t, $0}' \
    "$build/Testing/Temporary/LastTest.log" 2>/dev/null || true
  exit $status
fi
status=0
for t in "${targets[@]}"; do
  case "$t" in
    scene_file) exe=fuzz_scene_file ;;
    environment_map) exe=fuzz_environment_map_reader ;;
    openvdb) exe=fuzz_openvdb_reader ;;
    volume_file) exe=fuzz_volume_file ;;
    *) echo "fuzz.sh: unknown target '$t' (expected scene_file, environment_map, openvdb, volume_file)" >&2; exit 2 ;;
  esac
  dirs=("$fuzz/seeds/$t")
  [ -d "$root/Testing/Fuzz/regressions/$t" ] && dirs+=("$root/Testing/Fuzz/regressions/$t")
  mkdir -p "$fuzz/corpus/$t" "$fuzz/artifacts"
  echo "== $t: $seconds s"
  log="$fuzz/artifacts/$t.log"
  if ! "$build/bin/$exe" -rss_limit_mb=2048 -timeout=30 -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix="$fuzz/artifacts/$t-" "$fuzz/corpus/$t" "${dirs[@]}" > "$log" 2>&1; then
    status=1
    echo "FAILED: $t found a crash (log: $log)"
  fi
  grep -E '^(stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)|SUMMARY|artifact_prefix|fuzz invariant)' "$log" || true
done
exit $status
