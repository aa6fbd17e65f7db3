# ctest "python: pip install . builds the module": pip installs the repository into OUT (no build isolation: setuptools
# and wheel from Debian; no dependency downloads), reusing the configured build tree BUILD (FFTESS_CMAKE_BUILD_DIR), and
# the installed package, imported from OUT alone, tessellates one patch.
file(REMOVE_RECURSE ${OUT})
set(ENV{FFTESS_CMAKE_BUILD_DIR} ${BUILD})
execute_process(COMMAND ${PYTHON} -m pip install --no-build-isolation --no-deps --no-cache-dir --quiet --target ${OUT}
                        ${SRC}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pip install failed (${rc}):\n${out}\n${err}")
endif()
file(GLOB modules ${OUT}/fftess/_fftess*.so)
if(NOT modules)
  message(FATAL_ERROR "pip install: no fftess/_fftess*.so under ${OUT}")
endif()
set(ENV{PYTHONPATH} ${OUT})
execute_process(COMMAND ${PYTHON} -c
  "import fftess, numpy as np; t = fftess.tessellate('quad', 'integer', 'triangle_cw', np.full(6, 2, np.float32)); \
assert fftess.__file__.startswith('${OUT}/'), fftess.__file__; assert t.points.shape == (9, 2), t.points.shape; \
print('installed', fftess.__file__)"
  WORKING_DIRECTORY ${OUT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the installed module does not work (${rc}):\n${out}\n${err}")
endif()
message(STATUS "${out}")
