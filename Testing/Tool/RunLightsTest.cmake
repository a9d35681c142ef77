# The scene file's "lights" (issue 38): a scene with lights renders brighter than the same scene with
# --no-lights, and a bad light key is an error naming it (exit status 2, no output).
#   -DVISSWEEP=<exe> -DCHECK_EXR=<exe> -DSCENE=<json with lights> -DOUT_DIR=<dir>
cmake_minimum_required(VERSION 3.19)
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
foreach (run IN ITEMS lit unlit)
  set(extra "")
  if (run STREQUAL "unlit")
    set(extra --no-lights)
  endif ()
  execute_process(COMMAND "${VISSWEEP}" render "${SCENE}" -o "${OUT_DIR}/${run}.exr" -q ${extra}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "vissweep render ${extra} failed (${rc}): ${err}")
  endif ()
endforeach ()
execute_process(COMMAND "${CHECK_EXR}" --brighter "${OUT_DIR}/lit.exr" "${OUT_DIR}/unlit.exr" 1.5
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}")
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "the scene's lights do not brighten the image 1.5 times: ${out}${err}")
endif ()
# A bad light: its key path in the error, nothing written.
file(READ "${SCENE}" text)
string(REPLACE "\"intensity\": 2}" "\"intensity\": -2}" bad "${text}")
get_filename_component(dir "${SCENE}" DIRECTORY)
set(bad_scene "${OUT_DIR}/bad_lights.json")
string(REPLACE "../../../Examples/Scenes/" "${dir}/../../../Examples/Scenes/" bad "${bad}")
file(WRITE "${bad_scene}" "${bad}")
execute_process(COMMAND "${VISSWEEP}" render "${bad_scene}" -o "${OUT_DIR}/bad.exr" -q
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 2 OR NOT err MATCHES "lights\\[0\\]\\.intensity" OR EXISTS "${OUT_DIR}/bad.exr")
  message(FATAL_ERROR "a negative light intensity: exit ${rc}, expected 2 naming lights[0].intensity and no output: ${err}")
endif ()
message(STATUS "the lights brighten the image; a bad light names its key: ${err}")
