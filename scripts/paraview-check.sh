#!/usr/bin/env bash
# Builds VisSweep's libraries and the vissweep tool against ParaView 5.11's own VTK 9.2 (Debian
# 12's paraview-dev, libvtk*-pv5.11) into build-pv/, checks that they link ParaView's VTK only,
# renders a scene with that tool (VTK 9.2's OpenGL window, lavapipe's Vulkan) and builds and runs
# the README's C++ app against that build. docs/paraview.md says what it found. Not part of
# scripts/test.sh (it installs about 560 MB). Run as root on Debian 12.
#
#   scripts/paraview-check.sh               # install (once), configure, build, render
#   scripts/paraview-check.sh --build-only  # install (once), configure, build
#
# Three Debian packaging facts shape it:
#  - paraview Recommends python3-paraview, which Conflicts with python3-vtk9, on which Debian's
#    libvtk9-dev depends: `apt-get install paraview-dev` with recommends REMOVES the VTK 9.1
#    development package the normal build needs. So paraview-dev is installed without recommends.
#  - ParaView's VTK CMake package (VTKPython-targets.cmake) refuses to load unless python3-paraview's
#    modules exist under /usr/lib/python3/dist-packages/vtkmodules. So python3-paraview is only
#    downloaded and unpacked into build-pv-root/, and laid over dist-packages in a private mount
#    namespace (unshare -m) that only this script's configure and build see.
#  - paraview-dev ships no VTK wrapping hierarchy files (lib/vtk/hierarchy/ParaView/*-hierarchy.txt),
#    which vtk_module_wrap_python needs for every VTK module VisSweep's classes use; python3-paraview
#    does (unpacked in build-pv-root/): the plugin's wrapping and the Python package's read them
#    there (VISSWEEP_PV_HIERARCHY_DIR), so build-pv/vissweep is `import vissweep` for pvpython.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${VISSWEEP_PV_BUILD_DIR:-$root/build-pv}"
pvroot="${VISSWEEP_PV_ROOT:-$root/build-pv-root}"
jobs="${VISSWEEP_JOBS:-$(nproc)}"
site=/usr/lib/python3/dist-packages

if [ "${1:-}" = "--inside" ]; then
  # In the private mount namespace: ParaView's Python modules over Debian's (this namespace only).
  shift
  mount -t overlay overlay -o "lowerdir=$pvroot$site:$site" "$site"
  mount --bind "$pvroot$site/vtkmodules" "$site/vtkmodules"
  # ParaView's own CMake package (ParaViewTools-targets.cmake, for plugins) also names pvpython,
  # python3-paraview's too.
  mount -t overlay overlay -o "lowerdir=$pvroot/usr/bin:/usr/bin" /usr/bin
  exec "$@"
fi
inside() { unshare -m "$root/scripts/paraview-check.sh" --inside "$@"; }
build_only=0
if [ "${1:-}" = "--build-only" ]; then build_only=1; fi   # for scripts/paraview-plugin.sh

"$root/scripts/setup-debian.sh"   # the normal build's packages (VTK 9.1 among them)
if ! dpkg -s paraview-dev >/dev/null 2>&1; then
  apt-get install -y --no-install-recommends paraview-dev
fi
dpkg -s libvtk9-dev >/dev/null   # still there (see above)
if [ ! -f "$pvroot$site/vtkmodules/vtkCommonCore.so" ]; then
  mkdir -p "$pvroot/debs"
  (cd "$pvroot/debs" && apt-get download python3-paraview)
  dpkg -x "$pvroot"/debs/python3-paraview_*.deb "$pvroot"
fi

vtk_dir="$(dirname "$(dpkg -L paraview-dev | grep '/vtk/vtk-config.cmake$')")"
echo "== ParaView's VTK: $vtk_dir ($(grep -o 'PACKAGE_VERSION "[^"]*"' "$vtk_dir/vtk-config-version.cmake" | head -1))"
# The Python package against ParaView's VTK (for `import vissweep` in pvpython and pvbatch): its
# wrapping reads the VTK modules' hierarchy files, which paraview-dev lacks and python3-paraview
# (unpacked above) ships. VISSWEEP_PV_WRAP_PYTHON=OFF leaves it out.
wrap="${VISSWEEP_PV_WRAP_PYTHON:-ON}"
echo "== configure (tests off: they need VTK::RenderingImage, which ParaView's VTK does not ship;"
echo "   Python package $wrap, with python3-paraview's wrapping hierarchy files)"
inside cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DVISSWEEP_BUILD_TESTING=OFF \
  -DVISSWEEP_WRAP_PYTHON="$wrap" -DVISSWEEP_PV_HIERARCHY_DIR="$pvroot/usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView" \
  -DVTK_DIR="$vtk_dir"
echo "== build"
inside nice -n 10 cmake --build "$build" -j "$jobs"
if [ "$build_only" = 1 ]; then exit 0; fi
echo "== libraries link ParaView's VTK only"
for lib in "$build"/lib/libvissweep*.so "$build/bin/vissweep"; do
  if ldd "$lib" | grep -q 'libvtk[A-Za-z]*-9\.1\.so'; then
    echo "$lib links Debian's VTK 9.1:"; ldd "$lib" | grep 'libvtk.*-9\.1'; exit 1
  fi
done
ldd "$build"/lib/libvissweepRendering.so | grep -c 'pv5\.11' | sed 's/^/  ParaView libraries linked by libvissweepRendering: /'
echo "== the tool, linked against ParaView's VTK: info and a render"
LP_NUM_THREADS="${LP_NUM_THREADS:-1}" "$build/bin/vissweep" info | head -3
rm -f "$build/check/tiny.png"; mkdir -p "$build/check"
LP_NUM_THREADS="${LP_NUM_THREADS:-1}" xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  "$build/bin/vissweep" render "$root/Examples/Scenes/tiny.json" -o "$build/check/tiny.png" --width 64 --height 64 \
  --spp 4 --json "$build/check/tiny.json"
test -s "$build/check/tiny.png"
echo "== the README's C++ app against this build (VisSweep_DIR=$build, ParaView's VTK)"
inside env LP_NUM_THREADS="${LP_NUM_THREADS:-1}" xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \
  cmake -DREADME="$root/README.md" -DMODE=build -DPACKAGE="$build" -DWORK="$build/check/readme-cxx" \
    -DDATA="$root/Data" -DCH2=/usr/share/mricron/templates/ch2.nii.gz -DGENERATOR=Ninja \
    -DEXTRA_CONFIGURE="-DVTK_DIR=$vtk_dir" -P "$root/Testing/Readme/RunReadmeCxx.cmake"
echo "== ParaView check passed"
