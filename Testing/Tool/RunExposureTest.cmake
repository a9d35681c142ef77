# vissweep render --exposure (issue 37): it changes the PNG (the display transform) and not the EXR
# (the radiance); a negative or non-finite exposure is refused with exit status 2.
#   -DVISSWEEP=<exe> -DCHECK_EXR=<exe> -DSCENE=<json> -DOUT_DIR=<dir>
cmake_minimum_required(VERSION 3.19)
file(REMOVE_RECURSE "${OUT_DIR}")
file(MAKE_DIRECTORY "${OUT_DIR}")
foreach (run IN ITEMS plain exposed)
  set(extra "")
  if (run STREQUAL "exposed")
    set(extra --exposure 4)
  endif ()
  execute_process(COMMAND "${VISSWEEP}" render "${SCENE}" -o "${OUT_DIR}/${run}.exr" -o "${OUT_DIR}/${run}.png"
      --width 32 --height 32 --spp 2 --seed 3 ${extra}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "vissweep render ${extra} failed (${rc}): ${err}")
  endif ()
  file(SHA256 "${OUT_DIR}/${run}.png" png_${run})
endforeach ()
# The EXRs' pixels (their headers differ: the render time is in them).
execute_process(COMMAND "${CHECK_EXR}" --same "${OUT_DIR}/plain.exr" "${OUT_DIR}/exposed.exr"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "--exposure changed the EXR (the radiance): ${out}${err}")
endif ()
if (png_plain STREQUAL png_exposed)
  message(FATAL_ERROR "--exposure 4 did not change the PNG")
endif ()
foreach (bad IN ITEMS -1 nan)
  execute_process(COMMAND "${VISSWEEP}" render "${SCENE}" -o "${OUT_DIR}/bad.png" --exposure ${bad}
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 2 OR NOT err MATCHES "--exposure" OR EXISTS "${OUT_DIR}/bad.png")
    message(FATAL_ERROR "--exposure ${bad}: exit ${rc}, expected 2 naming the option and no output: ${err}")
  endif ()
endforeach ()
message(STATUS "--exposure 4 changes the PNG, not the EXR; -1 and nan are refused")
