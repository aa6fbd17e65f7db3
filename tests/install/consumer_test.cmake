# ctest "install:consumer": cmake --install of the build tree into BUILD/install-test, then, from BUILD/consumer-test,
# against that tree only (docs/architecture.md, "Install"):
#  1. the installed bin/fftess runs (--version names this build's version; bench --micro finds the installed
#     fftess_bench when the build has one); no internal header is installed;
#  2. docs/examples/consumer (find_package(fftess COMPONENTS tessellator compare lod verify)) configures, builds and
#     runs: each component used for real, each program's claim checked, tessellate_patch's output and terrain_check's
#     verdict and counts against the installed binary's (below);
#  3. a project that asks for verify alone gets lod, tessellator and base with it, not compare, and every installed
#     header compiles there, as <fftess/...>; compare alone gets tessellator and base; an optional unknown component
#     is reported not found;
#  4. find_package(fftess COMPONENTS nosuch) fails, naming the component and the real ones; from a tree with some
#     components installed, asking for another fails naming the one not installed.
# Same compiler, generator and sanitizers as this build (a sanitized static library needs them at link time).
# Arguments: -DBUILD -DSOURCE -DGENERATOR -DCXX -DSANITIZE -DVERSION -DBENCH (1: the build has fftess_bench).
set(prefix ${BUILD}/install-test)
set(work ${BUILD}/consumer-test)
file(REMOVE_RECURSE ${prefix} ${work})
file(MAKE_DIRECTORY ${work})
file(GLOB example_files ${SOURCE}/docs/examples/consumer/*)
file(COPY ${example_files} DESTINATION ${work}/src)

# step(COMMAND...): runs it, fails the test unless it exits 0; its stdout in last_out.
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_out "${out}" PARENT_SCOPE)
endfunction()
# expect(TEXT REGEX WHAT): fails the test unless TEXT matches REGEX.
function(expect text regex what)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: expected a match of '${regex}', got:\n${text}")
  endif()
endfunction()

# 1. The install: the binary, and the headers (public ones only).
step(${CMAKE_COMMAND} --install ${BUILD} --prefix ${prefix})
step(${prefix}/bin/fftess --version)
expect("${last_out}" "^fftess ${VERSION}\n$" "installed bin/fftess --version")
if(BENCH) # the build has fftess_bench (FFTESS_BENCHMARKS): installed beside the binary, `fftess bench --micro` runs it
  step(${prefix}/bin/fftess bench --micro --benchmark_list_tests=true)
  expect("${last_out}" "^BM_" "installed bin/fftess bench --micro")
endif()
file(GLOB_RECURSE headers RELATIVE ${prefix}/include ${prefix}/include/*.h)
list(LENGTH headers header_count)
foreach(h IN LISTS headers)
  if(h MATCHES "internal|testing\\.h$" OR NOT h MATCHES "^fftess/[a-z_]+/[a-z_0-9]+\\.h$")
    message(FATAL_ERROR "installed ${h}: an internal header (docs/architecture.md) or not under "
                        "include/fftess/<module>/")
  endif()
endforeach()

set(flags)
if(SANITIZE)
  set(flags "-DCMAKE_CXX_FLAGS=-fsanitize=${SANITIZE}" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=${SANITIZE}")
endif()
set(configure -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix}
    ${flags})

# 2. The example consumer, every component.
step(${CMAKE_COMMAND} -S ${work}/src -B ${work}/build ${configure})
step(${CMAKE_COMMAND} --build ${work}/build)
set(line "quad fractional_odd triangle_cw hw 3.5 2 5 4 3 3")
step(${work}/build/tessellate_patch ${line})
set(library_hex "${last_out}")
step(${prefix}/bin/fftess tessellate --format hex -e ${line})
expect("${library_hex}" "^patch 0 points [1-9][0-9]* indices [1-9]" "tessellate_patch (fftess::tessellator)")
if(NOT library_hex STREQUAL last_out)
  message(FATAL_ERROR "tessellate_patch (fftess::tessellator) and the installed `fftess tessellate` differ:\n"
                      "${library_hex}\n---\n${last_out}")
endif()
step(${work}/build/port_tests)
expect("${last_out}" "^patch 0: same [^\n]*\npatch 1: [a-z_]+ \\([0-9]+ primitives\\), reproduced by \
outer_factors_rotated\npatch 2: same "
       "port_tests (fftess::compare)")
message(STATUS "port_tests:\n${last_out}")
step(${work}/build/lod_factor)
expect("${last_out}" "shared edge: same bits\n$" "lod_factor (fftess::lod)")
step(${work}/build/terrain_check ${SOURCE}/docs/examples/terrain.toml)
expect("${last_out}" "terrain.toml: watertight \\([0-9]+ patches, [1-9][0-9]* shared edges checked, 0 cracks, \
0 holes\\)"
       "terrain_check (fftess::verify)")
message(STATUS "terrain_check: ${last_out}")
# The same check by the installed binary: the same verdict and counts.
string(REGEX REPLACE "^.*: ([a-z_]+) \\(([0-9]+) patches, ([0-9]+) shared.*$" "verdict: \\1;\\2;\\3" library
       "${last_out}")
list(GET library 0 verdict)
list(GET library 1 patches)
list(GET library 2 edges)
step(${prefix}/bin/fftess check ${SOURCE}/docs/examples/terrain.toml)
expect("${last_out}" "\n  patches +${patches} [^\n]*\n  edges checked +${edges} .*\n${verdict}\n$"
       "the installed `fftess check` against terrain_check (fftess::verify)")

# 3. One component alone (alone(COMPONENT LOADED NOT_LOADED SOURCE_TEXT)): its find_package defines the targets it
# needs and no others, finds their dependencies itself (Threads, glm, CGAL, toml++), reports an optional unknown
# component not found, and SOURCE_TEXT compiles against fftess::COMPONENT from the install tree.
function(alone component loaded not_loaded text)
  set(dir ${work}/alone-${component})
  file(WRITE ${dir}/source.cpp "${text}")
  file(WRITE ${dir}/CMakeLists.txt "cmake_minimum_required(VERSION 3.20)
project(alone CXX)
find_package(fftess CONFIG REQUIRED COMPONENTS ${component} OPTIONAL_COMPONENTS nosuch)
foreach(t ${loaded})
  if(NOT TARGET fftess::\${t})
    message(FATAL_ERROR \"COMPONENTS ${component}: no fftess::\${t}\")
  endif()
endforeach()
foreach(t ${not_loaded})
  if(TARGET fftess::\${t})
    message(FATAL_ERROR \"COMPONENTS ${component}: fftess::\${t} loaded too\")
  endif()
endforeach()
if(fftess_nosuch_FOUND OR NOT fftess_${component}_FOUND OR NOT fftess_FOUND)
  message(FATAL_ERROR \"COMPONENTS ${component}: the FOUND variables are wrong\")
endif()
add_library(source OBJECT source.cpp)
target_link_libraries(source PRIVATE fftess::${component})
")
  step(${CMAKE_COMMAND} -S ${dir} -B ${dir}/build ${configure})
  step(${CMAKE_COMMAND} --build ${dir}/build)
endfunction()
# verify alone, with every installed header as <fftess/...>; compare alone (the port's suite of docs/compare.md).
set(includes "")
foreach(h IN LISTS headers)
  string(APPEND includes "#include <${h}>\n")
endforeach()
alone(verify "verify lod tessellator base" "compare" "${includes}")
message(STATUS "verify alone: lod, tessellator and base loaded, compare not; ${header_count} installed headers compile")
alone(compare "compare tessellator base" "lod verify" "#include <fftess/compare/compare.h>\n")
message(STATUS "compare alone: tessellator and base loaded, lod and verify not")

# 4. A component that cannot be loaded: find_package(fftess CONFIG REQUIRED COMPONENTS ...) from PREFIX fails and
# says why (refused(PREFIX COMPONENT MESSAGE)). The check comes before any dependency is looked for: no language.
function(refused from component text)
  set(dir ${work}/refused-${component})
  file(WRITE ${dir}/CMakeLists.txt "cmake_minimum_required(VERSION 3.20)\nproject(refused NONE)\n"
                                   "find_package(fftess CONFIG REQUIRED COMPONENTS ${component})\n")
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${dir} -B ${dir}/build -DCMAKE_PREFIX_PATH=${from}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(REGEX REPLACE "[ \t\n]+" " " err "${err}")
  string(FIND "${err}" "${text}" at)
  if(rc EQUAL 0 OR at EQUAL -1)
    message(FATAL_ERROR "find_package(fftess COMPONENTS ${component}): expected a failure saying \"${text}\", got "
                        "${rc}:\n${out}\n${err}")
  endif()
  message(STATUS "COMPONENTS ${component}: refused: ${text}")
endfunction()
refused(${prefix} nosuch "fftess has no component 'nosuch'; its components are: tessellator compare lod verify")
# The tessellator and verify components installed alone (cmake --install --component): verify needs lod.
set(partial ${work}/partial-install)
foreach(c tessellator verify)
  step(${CMAKE_COMMAND} --install ${BUILD} --prefix ${partial} --component ${c})
endforeach()
refused(${partial} compare "fftess: component 'compare' is not installed in ${partial}/")
refused(${partial} verify "fftess: component 'verify' needs 'lod', which is not installed in ${partial}/")
