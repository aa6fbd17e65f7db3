# ctest "oracle:driver-check port bug": driver-check --port-bug runs llvmpipe as a port with the bug (compare.h
# portBugInput before the driver, portBugOutput after it); the comparison must name the bug for every differing
# patch. The per-point arithmetic bugs, unknown names and bad forms are refused with exit 2 naming --port-bug.
function(refused value expect)
  execute_process(COMMAND ${FFTESS} driver-check --random 3 --port-bug ${value} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${expect}" OR NOT out STREQUAL "")
    message(FATAL_ERROR "--port-bug ${value}: exit ${rc} (expected 2), stderr:\n${err}\n(expected /${expect}/)")
  endif()
endfunction()
refused(float_division
        "--port-bug float_division: float division .* per-point arithmetic bug.*accepted: denormals_flushed, ")
refused(lerp_not_rounded "cannot be simulated around a driver; accepted: .*uv_swapped")
refused(uv_swap "--port-bug 'uv_swap': not a port bug; accepted: ")
refused(uv_swapped:2 "FORM after ':' must be a number from 1 to 1")
refused(outer_factors_rotated:x "FORM after ':' must be a number from 1 to 3")

# Text: the header names the simulated bug; the summary line "typical port bug NAME reproduces N of M" has N = M.
foreach(bug uv_swapped outer_factors_rotated:2 domain_v_flipped tri_barycentrics_permuted:3 inside_factors_swapped)
  execute_process(COMMAND ${FFTESS} driver-check --random 300 --seed 5 --flush-denormals --port-bug ${bug} --show 0
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc EQUAL 3 AND NOT DEFINED ENV{CI})
    message("ORACLE-SKIPPED: no OpenGL context: ${err}")
    return()
  endif()
  string(REGEX REPLACE ":.*" "" name "${bug}")
  string(REGEX MATCH "summary: [0-9]+ patches, [0-9]+ same, ([0-9]+) differ" summary "${out}")
  set(differing "${CMAKE_MATCH_1}")
  string(REGEX MATCH "typical port bug ${name} reproduces ([0-9]+) of" named "${out}")
  set(reproduced "${CMAKE_MATCH_1}")
  if(NOT rc EQUAL 1 OR NOT out MATCHES "\nsimulated port bug: ${name} " OR differing LESS 50
     OR NOT reproduced EQUAL differing)
    message(FATAL_ERROR "--port-bug ${bug}: exit ${rc} (expected 1), ${name} reproduces '${reproduced}' of "
                        "'${differing}' differing patches (expected all, at least 50):\n${out}${err}")
  endif()
  message(STATUS "--port-bug ${bug}: ${name} reproduces ${reproduced} of ${differing} differing patches")
endforeach()

# JSON: the simulated bug is a key; the listed patches name it.
execute_process(COMMAND ${FFTESS} driver-check --random 40 --seed 5 --flush-denormals --port-bug uv_swapped --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(JSON simulated GET "${out}" port_bug name)
string(JSON form GET "${out}" port_bug form)
string(JSON differing GET "${out}" differing)
string(JSON reproduced GET "${out}" bugs uv_swapped)
string(JSON first GET "${out}" listed 0 bugs)
if(NOT rc EQUAL 1 OR NOT simulated STREQUAL "uv_swapped" OR NOT form EQUAL 1 OR NOT reproduced EQUAL differing
   OR NOT first MATCHES "\"uv_swapped\"")
  message(FATAL_ERROR "--port-bug uv_swapped --json: exit ${rc}, port_bug ${simulated} form ${form}, "
                      "${reproduced} of ${differing}, first listed bugs ${first}")
endif()
