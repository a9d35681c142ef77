# vissweep render as its users expect it (issue 37, item 6):
#  - the EXR's header says what made it: spp, time, mode, strategy, scene file, seed, camera,
#    version and device, as "vissweep.*" attributes (vsCheckExr --header prints them);
#  - --camera-position, --focal-point and --view-up set the camera (the header holds them; a camera
#    pointed away from the volume is refused as a scene's would be; bad values exit 2 naming the option);
#  - -o OUT.jpg writes a JPEG;
#  - the progress display writes whole lines when stderr is not a terminal (no '\r').
#   -DVISSWEEP=<exe> -DCHECK_EXR=<exe> -DSCENE=<tiny.json> -DVERSION=<x.y.z> -DOUT_DIR=<dir>
cmake_minimum_required(VERSION 3.19)
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
# tiny.json looks from -Y; this camera looks from +Y, with its own up.
execute_process(COMMAND "${VISSWEEP}" render "${SCENE}" -o "${OUT_DIR}/out.exr" -o "${OUT_DIR}/out.jpg"
    --width 32 --height 32 --spp 2 --samples-per-frame 1 --seed 7
    --camera-position 7.5,40,12 --focal-point 7.5,7.5,7.5 --view-up 0,0,1
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "vissweep render failed (${rc}): ${out}${err}")
endif ()

# Progress on a pipe: whole lines, nothing redrawn in place.
string(FIND "${err}" "\r" cr)
if (NOT cr EQUAL -1)
  message(FATAL_ERROR "the progress display wrote '\\r' into a pipe: '${err}'")
endif ()
if (NOT err MATCHES "\\] +2 / 2 spp +[0-9.]+ s\n")
  message(FATAL_ERROR "no whole progress line '... 2 / 2 spp ... s' on stderr: '${err}'")
endif ()

# JPEG.
file(READ "${OUT_DIR}/out.jpg" magic LIMIT 3 HEX)
if (NOT magic STREQUAL "ffd8ff")
  message(FATAL_ERROR "out.jpg is not a JPEG (starts with ${magic})")
endif ()

# The EXR's header.
execute_process(COMMAND "${CHECK_EXR}" --header "${OUT_DIR}/out.exr" RESULT_VARIABLE rc OUTPUT_VARIABLE header
  ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "vsCheckExr --header failed (${rc}): ${err}")
endif ()
message(STATUS "${header}")
get_filename_component(scene_abs "${SCENE}" ABSOLUTE)
foreach (line IN ITEMS "vissweep.spp=2" "vissweep.seed=7" "vissweep.mode=monte-carlo" "vissweep.strategy=two-step"
    "vissweep.scene=${scene_abs}" "vissweep.version=${VERSION}" "vissweep.cameraPosition=7.5,40,12"
    "vissweep.focalPoint=7.5,7.5,7.5" "vissweep.viewAngle=30")
  string(FIND "${header}" "${line}\n" at)
  if (at EQUAL -1)
    message(FATAL_ERROR "the EXR's header lacks '${line}'")
  endif ()
endforeach ()
if (NOT header MATCHES "vissweep.seconds=[0-9.e+-]+\n" OR header MATCHES "vissweep.seconds=0\n")
  message(FATAL_ERROR "the EXR's header has no render time")
endif ()
if (NOT header MATCHES "vissweep.effectiveStrategy=[A-Za-z]+\n" OR NOT header MATCHES "vissweep.device=[^\n]+\n"
    OR NOT header MATCHES "vissweep.viewUp=[0-9.e,+-]+\n")
  message(FATAL_ERROR "the EXR's header has no effective strategy or device")
endif ()
if (header MATCHES "vissweep.timeStep")
  message(FATAL_ERROR "a single render's header has a time step")
endif ()

# A camera pointed away from the volume is refused before the render, as a scene's camera is.
execute_process(COMMAND "${VISSWEEP}" render "${SCENE}" -o "${OUT_DIR}/away.png"
    --camera-position=-100,7.5,7.5 --focal-point=-200,7.5,7.5
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 2 OR NOT err MATCHES "sees none of the volume" OR EXISTS "${OUT_DIR}/away.png")
  message(FATAL_ERROR "a camera looking away: exit ${rc}, expected 2 and 'sees none of the volume': ${err}")
endif ()
# Bad values: exit 2 naming the option, nothing written.
# (tiny.json's camera looks along (0, 47.5, -4.5).)
foreach (case IN ITEMS "--view-up|0,0,0|--view-up" "--view-up|0,47.5,-4.5|--view-up"
    "--camera-position|7.5,7.5,7.5|--camera-position" "--camera-position|1,2|--camera-position"
    "--focal-point|1,nan,2|--focal-point")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 option)
  list(GET parts 1 value)
  list(GET parts 2 named)
  execute_process(COMMAND "${VISSWEEP}" render "${SCENE}" -o "${OUT_DIR}/bad.png" ${option} ${value}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 2 OR NOT err MATCHES "${named}" OR EXISTS "${OUT_DIR}/bad.png")
    message(FATAL_ERROR "${option} ${value}: exit ${rc}, expected 2 naming ${named} and no output: ${err}")
  endif ()
endforeach ()
message(STATUS "EXR header, camera options, JPEG and whole progress lines as expected")
