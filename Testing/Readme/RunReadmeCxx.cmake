# The README's C++ snippets, exactly as written, as a consumer of VisSweep: writes the
# CMakeLists.txt and app.cxx of "### C++", configures them against the build tree
# (VisSweep_DIR=<build>/, MODE=build) or an install prefix (CMAKE_PREFIX_PATH, MODE=install),
# builds the app and runs it in a fresh folder holding only a link to Data/; its image must land
# beside the app (WORK/build/brain.png).
# Arguments: README, MODE, PACKAGE (the build dir or the prefix), WORK, DATA, CH2, GENERATOR, and
# optionally EXTRA_CONFIGURE (one more -D for the app's configure: scripts/paraview-check.sh gives
# the VTK_DIR of ParaView's VTK).
include("${CMAKE_CURRENT_LIST_DIR}/ReadmeSnippet.cmake")
readme_snippet("${README}" "C++" "cmake" cmakelists)
readme_snippet("${README}" "C++" "cpp" app)
file(REMOVE_RECURSE "${WORK}")
file(WRITE "${WORK}/src/CMakeLists.txt" "${cmakelists}")
file(WRITE "${WORK}/src/app.cxx" "${app}")
if (MODE STREQUAL "build")
  set(where "-DVisSweep_DIR=${PACKAGE}")
else ()
  set(where "-DCMAKE_PREFIX_PATH=${PACKAGE}")
endif ()
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${WORK}/src" -B "${WORK}/build" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=Release ${where} ${EXTRA_CONFIGURE}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the README's C++ app (${where}) failed: ${out}\n${err}")
endif ()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${WORK}/build"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "building the README's C++ app failed: ${out}\n${err}")
endif ()
if (MODE STREQUAL "install")
  # Against an install, the app must not reach into the build tree for VisSweep.
  file(READ "${WORK}/build/CMakeCache.txt" cache)
  string(REGEX MATCH "VisSweep_DIR:PATH=[^\n]*" dir "${cache}")
  if (NOT dir MATCHES "^VisSweep_DIR:PATH=${PACKAGE}")
    message(FATAL_ERROR "the app found VisSweep outside the prefix ${PACKAGE}: ${dir}")
  endif ()
endif ()
file(MAKE_DIRECTORY "${WORK}/run")
file(CREATE_LINK "${DATA}" "${WORK}/run/Data" SYMBOLIC)
execute_process(COMMAND "${WORK}/build/app" "${CH2}" "Data/envmaps/sunrise.exr" 48 2
  WORKING_DIRECTORY "${WORK}/run" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(FIND "${out}" "wrote ${WORK}/build/brain.png (2 spp)" wrote)
if (NOT rc EQUAL 0 OR wrote EQUAL -1)
  message(FATAL_ERROR "the README's C++ app failed (${rc}): ${out}\n${err}")
endif ()
# The image lands beside the program, not in the folder it was run from (issue 37).
if (EXISTS "${WORK}/run/brain.png" OR NOT EXISTS "${WORK}/build/brain.png")
  message(FATAL_ERROR "the README's C++ app wrote its image into the folder it was run from, not beside itself")
endif ()
file(SIZE "${WORK}/build/brain.png" bytes)
if (bytes LESS 1000)
  message(FATAL_ERROR "brain.png has only ${bytes} bytes")
endif ()
message(STATUS "README C++ app (${MODE}): ${out}")
