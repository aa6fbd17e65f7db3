# Reports that the GPU oracle could not be built: a failure in CI (environment variable CI set), a skip elsewhere.
if(DEFINED ENV{CI})
  message(FATAL_ERROR "GPU oracle unavailable in CI: ${REASON}")
endif()
message("ORACLE-SKIPPED: GPU oracle unavailable: ${REASON}")
