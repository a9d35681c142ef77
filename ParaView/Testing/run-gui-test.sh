#!/usr/bin/env bash
# The plugin's GUI test: ParaView's GUI (under the display given, e.g. xvfb-run) runs
# gui_refinement.py, which renders a VisSweep volume once at 4 of 12 samples per pixel; the plugin's
# refinement timer (ParaView/Plugin/Client/pqVisSweepRefinement.h) must then render the still view
# until it logs "converged at 12 samples per pixel", within 120 s. Run as root: the GUI runs in
# scripts/paraview-check.sh's mount namespace, where ParaView's Python modules lie over Debian's
# VTK 9.1 ones.
#   run-gui-test.sh ROOT PLUGIN OUTDIR
set -euo pipefail
root="$1"; plugin="$2"; out="$3"
rm -rf "$out"; mkdir -p "$out"
export VS_PLUGIN="$plugin" VS_VOLUME="$root/Examples/Scenes/tiny_sphere.vti"
unshare -m "$root/scripts/paraview-check.sh" --inside \
  paraview --verbosity=INFO --script="$root/ParaView/Testing/gui_refinement.py" > "$out/gui.log" 2>&1 &
pid=$!
status=1
for _ in $(seq 120); do
  if grep -q 'VisSweep: the view is converged at 12 samples per pixel' "$out/gui.log"; then status=0; break; fi
  if ! kill -0 $pid 2>/dev/null; then break; fi
  sleep 1
done
kill $pid 2>/dev/null || true
wait $pid 2>/dev/null || true
grep -E "after the script's one render|VisSweep: the view" "$out/gui.log" || true
if [ $status = 0 ]; then
  echo "ok   the GUI refined the still view to MaximumSamples (12) by itself"
else
  echo "FAIL the GUI did not refine the still view to 12 samples per pixel within 120 s:"; tail -20 "$out/gui.log"
fi
exit $status
