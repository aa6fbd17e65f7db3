# Shared setup of the standalone GL tools (not part of the main build or CI): tests/tools/nvidia_compare/CMakeLists.txt and
# tests/tools/lod_gpu_drift/CMakeLists.txt include this after their project(). It sets C++17, Release by default, the main build's
# floating-point flags, libstdc++/libgcc linked statically (the binaries run on a machine without a compiler; only
# libEGL.so.1 from glvnd stays dynamic), builds fftess_base, fftess_tessellator and fftess_compare from
# the tree, finds EGL and GL/glcorearb.h, and
# gives:
#   FFTESS_ROOT                the repository root
#   FFTESS_ORACLE              tests/oracle (gl_oracle.cpp)
#   FFTESS_GL_DIR              gl/, the GL module (fftess_gl in the main build): capture, context, batch parser
#   FFTESS_GL_CONTEXT_SOURCES  the headless EGL context (gl/gl_context.cpp), compiled into each tool
#   fftess_standalone_gl_tool(TARGET)  includes (repository root, gl/, glcorearb) and OpenGL::EGL for TARGET
set(CMAKE_CXX_STANDARD 17)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()
get_filename_component(FFTESS_ROOT ${CMAKE_CURRENT_LIST_DIR}/../.. ABSOLUTE)
set(FFTESS_ORACLE ${FFTESS_ROOT}/tests/oracle)
set(FFTESS_GL_DIR ${FFTESS_ROOT}/gl/)
# The main build's floating-point flags: exactly as written, no contraction into FMA.
add_compile_options(-Wall -Wextra -ffp-contract=off -fno-fast-math)
add_link_options(-static-libstdc++ -static-libgcc)

add_subdirectory(${FFTESS_ROOT}/base base)
add_subdirectory(${FFTESS_ROOT}/tessellator tessellator)
add_subdirectory(${FFTESS_ROOT}/compare compare)
target_include_directories(fftess_base INTERFACE ${FFTESS_ROOT})
target_include_directories(fftess_tessellator PUBLIC ${FFTESS_ROOT})

find_package(OpenGL REQUIRED COMPONENTS EGL)
find_path(FFTESS_GLCOREARB_DIR GL/glcorearb.h REQUIRED)
set(FFTESS_GL_CONTEXT_SOURCES ${FFTESS_GL_DIR}/gl_context.cpp)

function(fftess_standalone_gl_tool target)
  target_include_directories(${target} PRIVATE ${FFTESS_ROOT} ${FFTESS_GL_DIR} ${FFTESS_GLCOREARB_DIR})
  target_link_libraries(${target} PRIVATE OpenGL::EGL)
endfunction()
