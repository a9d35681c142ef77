# Installs the build into PREFIX, then checks the installed layout works where it lands:
#  - the installed `vissweep info` runs and finds its data beside itself (PREFIX/share/vissweep),
#    and `vissweep render` of an installed example scene works;
#  - the Python package sits in the folder Debian's python3 searches for the configured prefix
#    (INSTALL_PREFIX, /usr/local by default), and imports from the scratch prefix.
cmake_minimum_required(VERSION 3.19)
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
  RESULT_VARIABLE rc OUTPUT_QUIET)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif ()
execute_process(COMMAND "${PREFIX}/bin/vissweep" info RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "max 3D image dimension")
  message(FATAL_ERROR "installed vissweep info failed (${rc}): ${out} ${err}")
endif ()
file(REAL_PATH "${PREFIX}/share/vissweep" data)
if (NOT out MATCHES "data in ${data}")
  message(FATAL_ERROR "the installed vissweep does not take its data from ${data}: ${out}")
endif ()
foreach (f IN ITEMS Examples/Scenes/tiny.json Examples/Scenes/tiny_sphere.vti Benchmarks/plot_convergence.py
    Benchmarks/scenes/phantom_forest.json Data/envmaps/sunrise.exr)
  if (NOT EXISTS "${PREFIX}/share/vissweep/${f}")
    message(FATAL_ERROR "not installed: share/vissweep/${f}")
  endif ()
endforeach ()
foreach (f IN ITEMS share/doc/vissweep/reference.md share/licenses/vissweep/LICENSE)
  if (NOT EXISTS "${PREFIX}/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif ()
endforeach ()
execute_process(COMMAND "${PREFIX}/bin/vissweep" render "${PREFIX}/share/vissweep/Examples/Scenes/tiny.json"
    -o "${PREFIX}/tiny.png" --width 16 --height 16 --spp 1 -q
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT EXISTS "${PREFIX}/tiny.png")
  message(FATAL_ERROR "installed vissweep render of the installed tiny.json failed (${rc}): ${out} ${err}")
endif ()

execute_process(COMMAND /usr/bin/python3 -c "import sys; print('\\n'.join(sys.path))" OUTPUT_VARIABLE path)
if (INSTALL_PREFIX MATCHES "^/usr(/local)?$")
  string(FIND "${path}" "${INSTALL_PREFIX}/${SITE}\n" at)
  if (at LESS 0)
    message(FATAL_ERROR "the package installs into ${INSTALL_PREFIX}/${SITE}, which Debian's python3 "
      "does not search: ${path}")
  endif ()
else ()
  message(STATUS "prefix ${INSTALL_PREFIX}: not a prefix Debian's python3 searches, PYTHONPATH is needed")
endif ()
set(ENV{PYTHONPATH} "${PREFIX}/${SITE}")
execute_process(COMMAND /usr/bin/python3 -c
  "import vissweep, vtk; m = vissweep.vtkVisibilitySweepVolumeMapper(); print(vissweep.__file__, m.GetClassName())"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "vtkVisibilitySweepVolumeMapper" OR NOT out MATCHES "${PREFIX}")
  message(FATAL_ERROR "importing the installed package failed (${rc}): ${out} ${err}")
endif ()
message(STATUS "installed layout works: ${out}")
