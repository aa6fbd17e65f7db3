# ctest "vk:driver-check": fftess driver-check --api vulkan on lavapipe (docs/compare.md "Vulkan").
#   1. 3000 seeded random patches with --flush-denormals: exit 0, verdict same (lavapipe runs the reference
#      tessellator and flushes denormal factors, as llvmpipe does);
#   2. the same without --flush-denormals: exit 1, and every difference is reproduced by denormals_flushed;
#   3. --api metal is refused: exit 2, naming --api;
#   4. a loader that finds no driver (VK_ICD_FILENAMES / VK_DRIVER_FILES naming a missing file): exit 3, a message
#      that says there is no Vulkan device, nothing on stdout.
# Exit 3 in case 1 (no Vulkan device) is a skip, or a failure when CI is set.
# Variables: FFTESS (the executable).
set(random --random 3000 --seed 20261202)
execute_process(COMMAND ${FFTESS} driver-check --api vulkan ${random} --flush-denormals RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc EQUAL 3)
  if(DEFINED ENV{CI})
    message(FATAL_ERROR "vk driver-check: no Vulkan device (CI is set): ${err}")
  endif()
  message("VK-SKIPPED: ${err}")
  return()
endif()
if(NOT rc EQUAL 0 OR NOT out MATCHES "verdict: same")
  message(FATAL_ERROR "vk driver-check: --flush-denormals: expected exit 0 and 'verdict: same', got exit ${rc}:\n"
                      "${out}${err}")
endif()
string(REGEX MATCH "driver: [^\n]*" driver "${out}")

execute_process(COMMAND ${FFTESS} driver-check --api vulkan ${random} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT out MATCHES "every difference is reproduced by denormals_flushed")
  message(FATAL_ERROR "vk driver-check: without --flush-denormals: expected exit 1 and only denormals_flushed "
                      "differences, got exit ${rc}:\n${out}${err}")
endif()
string(REGEX MATCH "summary: [^\n]*" summary "${out}")

execute_process(COMMAND ${FFTESS} driver-check --api metal --random 1 RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT err MATCHES "--api")
  message(FATAL_ERROR "vk driver-check: --api metal: expected exit 2 naming --api, got exit ${rc}: ${out}${err}")
endif()

execute_process(COMMAND ${CMAKE_COMMAND} -E env VK_ICD_FILENAMES=/nonexistent/fftess_icd.json
                        VK_DRIVER_FILES=/nonexistent/fftess_icd.json
                        ${FFTESS} driver-check --api vulkan --random 1 RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 3 OR NOT out STREQUAL "" OR NOT err MATCHES "driver-check --api vulkan: no Vulkan device")
  message(FATAL_ERROR "vk driver-check: no driver: expected exit 3, empty stdout and 'no Vulkan device', got exit "
                      "${rc}: ${out}${err}")
endif()
string(STRIP "${err}" err)
message("vk driver-check: ${driver}; same with --flush-denormals; without: ${summary}; no driver: ${err}")
