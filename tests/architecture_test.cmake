# ctest architecture:layout: the house rules that a reader of docs/architecture.md relies on, checked on every
# product source file (not on tests/, docs/ or tests/tools/):
#  1. includes point down: a quoted #include "FOLDER/..." names a module the including module may use (the table
#     below, the same as the target links in CMakeLists.txt); any other quoted include must be a file beside the
#     including file (its own module);
#  2. nothing in a product folder includes tests/;
#  3. no product source file is over 600 lines.
# Run: cmake -DSOURCE=<repository root> -P tests/architecture_test.cmake
cmake_minimum_required(VERSION 3.20)
set(modules base tessellator compare lod verify gl gpu_lod vk cli bench)
set(allowed_base base)
set(allowed_tessellator base tessellator)
set(allowed_compare base tessellator compare)
set(allowed_lod base lod)
set(allowed_verify base tessellator lod verify)
set(allowed_gl base gl)
set(allowed_gpu_lod base tessellator lod verify gl gpu_lod)
set(allowed_vk base gl vk)
set(allowed_cli base tessellator compare lod verify gl gpu_lod vk cli)
set(allowed_bench base tessellator compare lod verify bench)
set(max_lines 600)

set(problems "")
set(checked 0)
foreach(module IN LISTS modules)
  file(GLOB_RECURSE files RELATIVE ${SOURCE} ${SOURCE}/${module}/*.h ${SOURCE}/${module}/*.cpp
       ${SOURCE}/${module}/*.glsl ${SOURCE}/${module}/*.hlsl)
  foreach(f IN LISTS files)
    math(EXPR checked "${checked} + 1")
    file(READ ${SOURCE}/${f} text)
    string(REGEX MATCHALL "\n" newlines "${text}")
    list(LENGTH newlines n)
    if(n GREATER max_lines)
      string(APPEND problems "  ${f}: ${n} lines (at most ${max_lines})\n")
    endif()
    file(STRINGS ${SOURCE}/${f} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"[^\"]+\"")
    get_filename_component(dir ${f} DIRECTORY)
    foreach(line IN LISTS includes)
      string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*\"([^\"]+)\".*$" "\\1" path "${line}")
      string(REGEX REPLACE "/.*$" "" first "${path}")
      if(first STREQUAL "tests")
        string(APPEND problems "  ${f}: includes test code \"${path}\"\n")
      elseif(path MATCHES "/" AND first IN_LIST modules AND NOT EXISTS ${SOURCE}/${dir}/${path})
        if(NOT first IN_LIST allowed_${module})
          string(APPEND problems "  ${f}: includes \"${path}\", but ${module}/ may use only: ${allowed_${module}}\n")
        endif()
      elseif(NOT EXISTS ${SOURCE}/${dir}/${path})
        string(APPEND problems "  ${f}: includes \"${path}\", which is neither beside it nor in a module folder\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(checked LESS 50)
  message(FATAL_ERROR "architecture:layout: only ${checked} files found under ${SOURCE}: wrong SOURCE?")
endif()
if(problems)
  message(FATAL_ERROR "architecture:layout: ${checked} product files checked; these break the layout "
                      "(docs/architecture.md):\n${problems}")
endif()
message(STATUS "architecture:layout: ${checked} product files: includes point down, none includes tests/, none over "
               "${max_lines} lines")
