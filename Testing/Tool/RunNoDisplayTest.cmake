# The tool without an X display (cmake -P; DISPLAY is unset by the test's environment):
#   -DVISSWEEP=<exe> -DSCENE=<json>
# `vissweep info` runs; `vissweep bench frames`, which measures
# VTK's OpenGL window, exits 2 saying that it needs an X display (VTK would abort the process).
cmake_minimum_required(VERSION 3.19)
if (DEFINED ENV{DISPLAY})
  message(FATAL_ERROR "DISPLAY is set ('$ENV{DISPLAY}'): this test needs it unset")
endif ()
execute_process(COMMAND "${VISSWEEP}" info RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "VisSweep computes on")
  message(FATAL_ERROR "vissweep info without a display failed (${rc}): ${out}${err}")
endif ()
execute_process(COMMAND "${VISSWEEP}" bench frames "${SCENE}" --size 16 --frames 1
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 2)
  message(FATAL_ERROR "bench frames without a display: exit ${rc}, expected 2: ${out}${err}")
endif ()
foreach (text "vissweep bench frames: error: DISPLAY is not set" "needs an X display" "xvfb-run")
  string(FIND "${err}" "${text}" at)
  if (at LESS 0)
    message(FATAL_ERROR "bench frames without a display: the message lacks '${text}': ${err}")
  endif ()
endforeach ()
message(STATUS "info runs without a display; bench frames says: ${err}")
