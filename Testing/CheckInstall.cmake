# Installs the build into PREFIX, then runs the installed `vissweep info` and
# imports the installed Python package with Debian's interpreter.
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
set(ENV{PYTHONPATH} "${PREFIX}/${LIBDIR}/python3/dist-packages")
execute_process(COMMAND /usr/bin/python3 -c
  "import vissweep, vtk; m = vissweep.vtkVisibilitySweepVolumeMapper(); print(vissweep.__file__, m.GetClassName())"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "vtkVisibilitySweepVolumeMapper" OR NOT out MATCHES "${PREFIX}")
  message(FATAL_ERROR "importing the installed package failed (${rc}): ${out} ${err}")
endif ()
message(STATUS "installed layout works: ${out}")
