#!/usr/bin/env bash
# Sets everything up on Debian 12, builds VisSweep and renders the demo:
# the Colin27 brain MRI to build/demo/brain.png.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VISSWEEP_BUILD_DIR:-$root/build}"
ms() { echo $(( $(date +%s%N) / 1000000 )); }
secs() { printf "%d.%01d" $(( $1 / 1000 )) $(( ($1 % 1000) / 100 )); }
t0=$(ms)
# The demo installs and builds only what it needs (issue 39, item 2): no fuzzing toolchain or
# validation layers (setup-debian.sh --demo), no tests, benchmarks or tool (the vissweep_demo target:
# the libraries and the Python package). scripts/test.sh adds the rest to the same build/.
# The image is shown (and written) through the display's filter guided by the preview (--denoise:
# 11-33x lower error than the estimate alone at 2-8 s on ch2, docs/benchmarks.md).
"$root/scripts/setup-debian.sh" --demo
t1=$(ms)
"$root/scripts/build.sh" vissweep_demo
t2=$(ms)
mkdir -p "$build/demo"
export LP_NUM_THREADS="${LP_NUM_THREADS:-$(nproc)}"
PYTHONPATH="$build${PYTHONPATH:+:$PYTHONPATH}" xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  /usr/bin/python3 "$root/Examples/Python/render_brain.py" \
  --volume /usr/share/mricron/templates/ch2.nii.gz --output "$build/demo/brain.png" --size 384 \
  --rotation 110 --strategy Auto --spp 1024 --seconds 10 --preview-first --denoise
t3=$(ms)
echo "stages: setup $(secs $((t1 - t0))) s, build $(secs $((t2 - t1))) s, render $(secs $((t3 - t2))) s"
echo "demo image: $build/demo/brain.png"
