# ctest "oracle:gl_oracle command line": the fftess_gl_oracle command line as docs/oracle.md shows it.
#   1. data/example.batch gives exactly data/example.out (checked once against fftess with flushDenormals; the same
#      bytes the golden .out files use);
#   2. a batch with an hlsl stage is refused: exit 2, the line number in the message, nothing on stdout.
# Exit 3 (no OpenGL context / not llvmpipe) is a skip, or a failure when CI is set.
# Variables: ORACLE (the executable), DATA (tests/oracle/data), OUT (a scratch folder).
execute_process(COMMAND ${ORACLE} ${DATA}/example.batch RESULT_VARIABLE rc OUTPUT_FILE ${OUT}/example.out
                ERROR_VARIABLE err)
if(rc EQUAL 3)
  if(DEFINED ENV{CI})
    message(FATAL_ERROR "oracle_cli: no llvmpipe context (CI is set): ${err}")
  endif()
  message("ORACLE-SKIPPED: ${err}")
  return()
endif()
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "oracle_cli: fftess_gl_oracle example.batch exited ${rc}: ${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/example.out ${DATA}/example.out RESULT_VARIABLE same)
if(NOT same EQUAL 0)
  message(FATAL_ERROR "oracle_cli: output of example.batch differs from data/example.out (see ${OUT}/example.out)")
endif()

execute_process(COMMAND ${ORACLE} ${DATA}/bad_stage.batch RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT out STREQUAL "" OR NOT err MATCHES "line 2: stage 'hlsl-avg'")
  message(FATAL_ERROR "oracle_cli: bad_stage.batch: expected exit 2, empty stdout and 'line 2: stage 'hlsl-avg'...'; "
                      "got exit ${rc}, stdout '${out}', stderr '${err}'")
endif()
message("oracle_cli: example output exact; hlsl stage refused with: ${err}")
