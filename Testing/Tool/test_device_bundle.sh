#!/usr/bin/env bash
# Tool.DeviceBundle (issue 37): scripts/device-bundle.sh makes the device bundle from this build and
# its run.sh runs on lavapipe in a clean environment (env -i: only the bundle's libraries on the
# library path, no DISPLAY), so that it cannot rot between the sessions that have a GPU.
#   test_device_bundle.sh SOURCE_DIR BUILD_DIR
# Checks: the bundle is at most 64 MiB; every library its programs load beyond glibc and the Vulkan
# loader is the bundle's own; run.sh --quick exits 0 and writes the JSON and the summary; without a
# Vulkan driver run.sh exits 2 and says so.
set -euo pipefail
root=$1
build=$2
out="$build/Testing/Temporary/DeviceBundle"
rm -rf "$out"
mkdir -p "$out"
bundle="$out/bundle"
fail() {
  echo "FAILED: $*" >&2
  exit 1
}

VISSWEEP_BUILD_DIR="$build" "$root/scripts/device-bundle.sh" "$bundle"
size=$(du -sb "$bundle" | cut -f1)
[ "$size" -le $((64 * 1024 * 1024)) ] || fail "the bundle is $size bytes"


# The quick run, in a clean environment: HOME only for Mesa's shader cache (compiles take minutes).
rc=0
env -i PATH=/usr/bin:/bin HOME="${HOME:-/root}" LP_NUM_THREADS=1 "$bundle/run.sh" --quick "$out/results" \
  > "$out/run.log" 2>&1 || rc=$?
cat "$out/run.log"
[ "$rc" = 0 ] || fail "run.sh --quick exited $rc"
# Every library resolved from outside the bundle is glibc's or the Vulkan loader.
outside=$(env -i LD_LIBRARY_PATH="$bundle/programs/lib" ldd "$bundle/programs/bin/vissweep" \
  "$bundle/programs/bin/vissweep_unit_tests" | awk '/=> \// { print $3 }' | grep -v "^$bundle/programs/lib/" |
  grep -v -E '/(libc|libm|libpthread|libdl|librt|libresolv|libutil|ld-linux-x86-64|libvulkan)\.so' || true)
[ -z "$outside" ] || fail "libraries loaded from outside the bundle: $outside"
for f in info.txt tests.json overhead.json sweeps.json convergence.json summary.txt; do
  [ -s "$out/results/$f" ] || fail "run.sh wrote no $f"
done
grep -q "Unit tests (.*): [1-9][0-9]* passed, exit 0" "$out/results/summary.txt" || fail "the summary lacks the tests' count"
grep -q "bench convergence: exit 0" "$out/results/summary.txt" || fail "the summary lacks bench convergence"

# No Vulkan driver: the loader finds no ICD; run.sh exits 2 naming it.
rc=0
env -i PATH=/usr/bin:/bin HOME="${HOME:-/root}" VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json \
  "$bundle/run.sh" --quick "$out/no_driver" > "$out/no_driver.log" 2>&1 || rc=$?
cat "$out/no_driver.log"
[ "$rc" = 2 ] || fail "without a driver run.sh exited $rc, expected 2"
grep -q "run.sh: error: no usable Vulkan device: .*driver" "$out/no_driver.log" || fail "without a driver the message does not say so"
echo "device bundle: $((size / 1048576)) MiB; run.sh --quick passed; without a driver it exits 2"
