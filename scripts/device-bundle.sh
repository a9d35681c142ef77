#!/usr/bin/env bash
# Makes the device bundle (issue 37): a folder of at most 64 MiB that runs VisSweep's device checks
# and benchmarks in one command on any Linux x86-64 machine with a Vulkan loader and driver (a GPU
# machine with nothing but NVIDIA's driver on it: no Debian packages, no network, no X server):
#   programs.tar.gz  bin/: the headless tool (vissweep) and the unit tests (vissweep_unit_tests),
#            stripped; lib/: every shared library they need beyond glibc and the Vulkan loader
#            (found by ldd); run.sh unpacks it beside itself (or in $TMPDIR) on its first run
#   data/    Colin27 (ch2, ch2better from mricron-data), the sunrise HDRI, the test data (Data/)
#   scenes/  the benchmark scenes with their paths into data/: mri_sunrise, brain_sunrise, tiny
#   run.sh   info, the device tests, bench overhead, bench sweeps, bench convergence: JSON + summary
#
#   scripts/device-bundle.sh [OUT]      # from a build (scripts/build.sh); OUT default build/device-bundle
#   OUT/run.sh [--quick] [RESULTS]      # RESULTS default OUT/results; --quick: seconds, for tests
#
# run.sh exits 2, naming what is missing, where the bundle cannot run (no Vulkan loader, no
# driver, a device without what the kernels need, a library or glibc too old), 1 when a test or a
# benchmark failed, 0 otherwise. scripts/test.sh runs it on lavapipe in a clean environment
# (Tool.DeviceBundle: env -i, only the bundle's libraries).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VISSWEEP_BUILD_DIR:-$root/build}"
out="${1:-$build/device-bundle}"
limit=$((64 * 1024 * 1024))
ch2="${VISSWEEP_CH2:-/usr/share/mricron/templates/ch2.nii.gz}"
ch2better="$(dirname "$ch2")/ch2better.nii.gz"

for f in "$build/bin/vissweep" "$build/bin/vissweep_unit_tests" "$ch2" "$ch2better"; do
  if [ ! -f "$f" ]; then
    echo "device-bundle.sh: $f is missing (build first: scripts/build.sh; Colin27: apt-get install mricron-data)" >&2
    exit 2
  fi
done

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/data" "$out/scenes"
for exe in vissweep vissweep_unit_tests; do
  strip --strip-unneeded -o "$out/bin/$exe" "$build/bin/$exe"
done

# The libraries beyond glibc (the target's own) and the Vulkan loader (the target's own: it finds
# the target's driver). libstdc++ and libgcc_s are bundled: an older system's may lack GCC 12's symbols.
ldd "$out/bin/vissweep" "$out/bin/vissweep_unit_tests" | awk '/=> \// { print $3 }' | sort -u |
  while read -r lib; do
    case "$(basename "$lib")" in
      libc.so.* | libm.so.* | libpthread.so.* | libdl.so.* | librt.so.* | libresolv.so.* | libutil.so.* | \
        ld-linux-x86-64.so.* | libvulkan.so.*) ;;
      *) cp -L "$lib" "$out/lib/" ;;
    esac
  done
strip --strip-unneeded "$out"/lib/*.so* 2>/dev/null || true

# Data: the volumes and environment maps the scenes use; the unit tests' Data/ (envmaps, smoke).
cp "$ch2" "$ch2better" "$out/data/"
cp -r "$root/Data/envmaps" "$root/Data/smoke" "$out/data/"
cp "$root/Examples/Scenes/tiny_sphere.vti" "$out/data/"
# The scenes, their files pointing into data/ (relative paths resolve against the scene's folder).
/usr/bin/python3 - "$root" "$out" <<'EOF'
import json, sys
root, out = sys.argv[1], sys.argv[2]
scenes = {
    "mri_sunrise.json": (root + "/Benchmarks/scenes/mri_sunrise.json", "../data/ch2.nii.gz"),
    "brain_sunrise.json": (root + "/Examples/Scenes/brain_sunrise.json", "../data/ch2.nii.gz"),
    "tiny.json": (root + "/Examples/Scenes/tiny.json", "../data/tiny_sphere.vti"),
}
for name, (source, volume) in scenes.items():
    scene = json.load(open(source))
    scene["volume"]["file"] = volume
    env = scene.get("environment", {})
    if "file" in env:
        env["file"] = "../data/envmaps/" + env["file"].split("/")[-1]
    json.dump(scene, open(out + "/scenes/" + name, "w"), indent=2)
EOF
# The programs and libraries packed (gzip: OpenVDB alone is 57 MB, the libraries 135 MB unpacked);
# run.sh unpacks them at its first run. tar and gzip are on any Linux.
tar -C "$out" -czf "$out/programs.tar.gz" bin lib
rm -rf "$out/bin" "$out/lib"
cp "$root/scripts/device-run.sh" "$out/run.sh"
chmod +x "$out/run.sh"

size=$(du -sb "$out" | cut -f1)
if [ "$size" -gt "$limit" ]; then
  echo "device-bundle.sh: $out is $((size / 1048576)) MiB, more than 64 MiB:" >&2
  du -sb "$out"/* "$out"/data/* | sort -n | tail -8 >&2
  exit 1
fi
echo "device bundle: $out ($((size / 1048576)) MiB, $(tar -tzf "$out/programs.tar.gz" | grep -c '^lib/.') libraries); run: $out/run.sh"
