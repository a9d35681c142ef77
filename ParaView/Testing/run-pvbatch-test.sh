#!/usr/bin/env bash
# The VisSweep plugin's pvbatch test: renders Examples/Scenes/tiny.json's volume under the white
# sky with the vissweep tool (seeds 1 and 2) and in pvbatch with the plugin, and compares
# (pvbatch_vissweep.py says how); checks that a missing environment file is reported on stderr.
# Needs a display (run under xvfb-run).
#   run-pvbatch-test.sh ROOT PV_BUILD PV_ROOT PLUGIN OUTDIR
set -euo pipefail
root="$1"; pvbuild="$2"; pvroot="$3"; plugin="$4"; out="$5"
rm -rf "$out"; mkdir -p "$out"

# tiny.json without its sun (the white sky, the representation's default), the volume by full path.
/usr/bin/python3 - "$root/Examples/Scenes/tiny.json" "$out/tiny-white-sky.json" <<'PY'
import json, os, sys
scene = json.load(open(sys.argv[1]))
scene["volume"]["file"] = os.path.join(os.path.dirname(sys.argv[1]), scene["volume"]["file"])
del scene["environment"]
json.dump(scene, open(sys.argv[2], "w"), indent=1)
PY
for seed in 1 2; do
  sed "s/\"seed\": 1/\"seed\": $seed/" "$out/tiny-white-sky.json" > "$out/tiny-seed$seed.json"
  "$pvbuild/bin/vissweep" render "$out/tiny-seed$seed.json" -o "$out/tool-seed$seed.png" > /dev/null
done

status=0
# build-pv/vissweep: the Python package built against ParaView's VTK (the script imports it).
PYTHONPATH="$pvroot/usr/lib/python3/dist-packages:$pvbuild${PYTHONPATH:+:$PYTHONPATH}" \
  pvbatch "$root/ParaView/Testing/pvbatch_vissweep.py" "$plugin" "$root/Examples/Scenes/tiny_sphere.vti" \
  "$out" "$out/tool-seed1.png" "$out/tool-seed2.png" 2> "$out/pvbatch.stderr" || status=$?
cat "$out/pvbatch.stderr" >&2
if [ "$status" != 0 ]; then echo "FAIL pvbatch exited with status $status"; fi
if [ "$(cat "$out/result.txt" 2>/dev/null)" != "0 failure(s)" ]; then
  echo "FAIL the pvbatch script's checks: $(cat "$out/result.txt" 2>/dev/null || echo 'no result (it did not finish)')"; status=1
fi
if ! grep -q 'missing-sky.exr' "$out/pvbatch.stderr"; then
  echo "FAIL a missing environment file was not reported on stderr"; status=1
else
  echo "ok   a missing environment file is reported: $(grep -m1 'missing-sky.exr' "$out/pvbatch.stderr" | cut -c1-200)"
fi
for message in 'SamplesPerFrame 0 is outside \[1, 65536\]: the mapper uses 1' 'Exposure nan is refused' \
    'has no grid named "no-such-grid"' 'TimeBudget -1 is not a number of seconds >= 0: 0 (no budget) is used' \
    'ScatteringAnisotropy 1.5 is outside (-1, 1)' 'ScatteringAnisotropy (the Henyey-Greenstein anisotropy g) must be in (-1, 1), got 1.5'; do
  if grep -q "$message" "$out/pvbatch.stderr"; then
    echo "ok   an out-of-range setting is reported: $(grep -m1 "$message" "$out/pvbatch.stderr" | sed 's/.*| //' | cut -c1-160)"
  else
    echo "FAIL no message matching '$message' on stderr"; status=1
  fi
done

# The README's pvbatch snippet (its "### ParaView" section), exactly as written, from a folder laid
# out as the repository's root (its relative paths: the plugin build and Examples/).
readme="$out/readme"; mkdir -p "$readme"
ln -s "$(cd "$(dirname "$plugin")/../../../.." && pwd)" "$readme/build-pv-plugin"
ln -s "$root/Examples" "$readme/Examples"
/usr/bin/python3 - "$root/README.md" "$readme/snippet.py" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
at = text.index("\n### ParaView\n")
open(sys.argv[2], "w").write(re.compile(r"\n```python\n(.*?)\n```\n", re.S).search(text, at).group(1) + "\n")
PY
snippet_status=0
(cd "$readme" && PYTHONPATH="$pvroot/usr/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}" \
  timeout 600 pvbatch snippet.py > snippet.out 2> snippet.err) || snippet_status=$?
if grep -qx '32 spp' "$readme/snippet.out" && [ -s "$readme/sphere.png" ] && [ "$snippet_status" = 0 ]; then
  echo "ok   the README's ParaView snippet runs as written (32 spp, sphere.png)"
else
  echo "FAIL the README's ParaView snippet (status $snippet_status):"; cat "$readme/snippet.out" "$readme/snippet.err"; status=1
fi
exit $status
