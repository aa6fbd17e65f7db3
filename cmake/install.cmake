# cmake --install BUILD [--prefix PREFIX]: the fftess binary (bin/) and the libraries as components of one CMake
# package (docs/architecture.md, "Install"):
#   find_package(fftess CONFIG REQUIRED COMPONENTS tessellator compare lod verify)
#     -> fftess::tessellator (+ fftess::base), fftess::compare, fftess::lod, fftess::verify
# Each library installs its own static library, headers (under include/fftess/<module>/) and export
# (fftess-<component>-targets.cmake) in its CMakeLists.txt; this file adds the binary and the package's config, which
# loads the requested components with what they need and finds their dependencies (cmake/fftessConfig.cmake.in).
# The GPU modules (gl/, gpu_lod/, vk/) are not installed: only the cli links them.
include(CMakePackageConfigHelpers)
install(TARGETS fftess RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli)
if(TARGET fftess_bench) # beside the binary, where `fftess bench --micro` runs it; OPTIONAL: a build without it installs
  install(TARGETS fftess_bench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT cli OPTIONAL)
endif()
set(FFTESS_CONFIG_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/fftess)
configure_file(${CMAKE_CURRENT_LIST_DIR}/fftessConfig.cmake.in ${CMAKE_BINARY_DIR}/fftessConfig.cmake @ONLY)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/fftessConfigVersion.cmake VERSION ${PROJECT_VERSION}
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/fftessConfig.cmake ${CMAKE_BINARY_DIR}/fftessConfigVersion.cmake
        DESTINATION ${FFTESS_CONFIG_DIR} COMPONENT tessellator)
