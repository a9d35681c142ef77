#!/usr/bin/env bash
# Builds VisSweep's ParaView plugin (ParaView/) against Debian 12's ParaView 5.11 and, with --test,
# runs its pvbatch test. docs/paraview.md says how it works and why. Run as root on Debian 12.
#
#   scripts/paraview-plugin.sh          # build: build-pv/ (VisSweep on ParaView's VTK), build-pv-plugin/
#   scripts/paraview-plugin.sh --test   # build, then the pvbatch, GUI and MPI tests (under xvfb-run)
#
# The plugin is build-pv-plugin/lib/paraview-5.11/plugins/VisSweep/VisSweep.so: load it with
# Tools > Manage Plugins, `paraview --plugin-search-paths=<that folder's parent>`, PV_PLUGIN_PATH or
# LoadPlugin() in pvpython/pvbatch. Debian's VTK 9.1 packages stay installed: paraview-dev is
# installed without recommends, and python3-paraview (which conflicts with python3-vtk9) is only
# unpacked into build-pv-root/ (scripts/paraview-check.sh), whose Python modules pvbatch finds
# through PYTHONPATH.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
pvbuild="${VISSWEEP_PV_BUILD_DIR:-$root/build-pv}"
pvroot="${VISSWEEP_PV_ROOT:-$root/build-pv-root}"
build="${VISSWEEP_PV_PLUGIN_BUILD_DIR:-$root/build-pv-plugin}"
jobs="${VISSWEEP_JOBS:-$(nproc)}"

# paraview-dev (no recommends), python3-paraview unpacked, VisSweep built on ParaView's VTK.
"$root/scripts/paraview-check.sh" --build-only
inside() { unshare -m "$root/scripts/paraview-check.sh" --inside "$@"; }

# Qt 5's development files, for the plugin's GUI part (refinement while the view is still). Only if
# apt would remove nothing (a guard for Debian's VTK 9.1 packages, which others build against).
gui_packages=(qtbase5-dev libqt5svg5-dev qttools5-dev libqt5opengl5-dev)
missing=()
for p in "${gui_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  if apt-get -s install -y --no-install-recommends "${missing[@]}" | grep -q '^Remv'; then
    echo "paraview-plugin: installing ${missing[*]} would remove packages; building without the GUI part"
  else
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
fi
dpkg -s libvtk9-dev >/dev/null   # still there

pvdir="$(dirname "$(dpkg -L paraview-dev | grep '/paraview-config.cmake$')")"
echo "== configure the plugin ($pvdir)"
# The wrapping hierarchy files: python3-paraview ships them (unpacked in build-pv-root); any that
# are missing are made with ParaView's vtkWrapHierarchy (ParaView/cmake/vissweepParaViewHierarchy.cmake).
inside cmake -S "$root/ParaView" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DParaView_DIR="$pvdir" -DVisSweep_DIR="$pvbuild" \
  -DVISSWEEP_PV_HIERARCHY_DIR="${VISSWEEP_PV_HIERARCHY_DIR-$pvroot/usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView}"
echo "== build the plugin"
inside nice -n 10 cmake --build "$build" -j "$jobs"
plugin="$build/lib/paraview-5.11/plugins/VisSweep/VisSweep.so"
test -f "$plugin"
echo "== plugin: $plugin"

if [ "${1:-}" = "--test" ]; then
  LP_NUM_THREADS="${LP_NUM_THREADS:-1}" xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
    "$root/ParaView/Testing/run-pvbatch-test.sh" "$root" "$pvbuild" "$pvroot" "$plugin" "$build/test"
  LP_NUM_THREADS="${LP_NUM_THREADS:-1}" xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
    "$root/ParaView/Testing/run-gui-test.sh" "$root" "$plugin" "$build/test-gui" "$pvroot"
  LP_NUM_THREADS="${LP_NUM_THREADS:-1}" xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
    "$root/ParaView/Testing/run-mpi-test.sh" "$root" "$pvroot" "$plugin" "$build/test-mpi"
fi
