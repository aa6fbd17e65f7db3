# ctest "oracle:driver-check svg": driver-check --svg on llvmpipe. The denormal batch's two patches are culled by
# llvmpipe (it flushes denormal factors): exit 1 and a picture with both patches' panels, the reference's triangles
# highlighted as only in the reference.
file(REMOVE ${OUT}/driver_check.svg)
execute_process(COMMAND ${FFTESS} driver-check ${DATA}/denormal.batch --svg ${OUT}/driver_check.svg
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 3 AND NOT DEFINED ENV{CI})
  message("ORACLE-SKIPPED: no OpenGL context: ${err}")
  return()
endif()
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "driver-check --svg: exit ${rc} (expected 1):\n${out}${err}")
endif()
file(READ ${OUT}/driver_check.svg svg)
foreach(expect "^<\\?xml" "2 patches, 0 same, 2 differ; the first 2 differing drawn" ">patch 0 \\(line 2\\): culled_in_capture<"
               ">patch 1 \\(line 3\\): culled_in_capture<" "<path class=\"or\" d=\"M" "</svg>\n$")
  if(NOT svg MATCHES "${expect}")
    message(FATAL_ERROR "driver-check --svg: the picture lacks /${expect}/:\n${svg}")
  endif()
endforeach()
message(STATUS "driver-check --svg: ${OUT}/driver_check.svg")
