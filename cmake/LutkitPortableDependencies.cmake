# SPDX-License-Identifier: Apache-2.0
# The portable build's dependencies (LUTKIT_PORTABLE: the browser edition through Emscripten, the
# Windows edition through MinGW-w64; docs/portable.md). Nothing is linked from the build machine:
# GLM, CLI11 and fast_float are header-only (Debian's headers), zlib, libpng,
# libjpeg-turbo and ISA-L are compiled from Debian's sources (LutkitThirdParty.cmake), and
# OpenColorIO, OpenImageIO, OpenEXR, Qt, GoogleTest and Google Benchmark are not used.

# Header-only libraries from Debian's /usr/include, outside the cross toolchain's root: each
# linked into a folder of its own, so no other system header comes with it.
set(_hdr "${PROJECT_BINARY_DIR}/third-party/include/headers")
foreach(lib glm CLI fast_float fmt)
  find_path(LUTKIT_${lib}_PARENT ${lib} PATHS /usr/include NO_DEFAULT_PATH NO_CMAKE_FIND_ROOT_PATH)
  if(NOT LUTKIT_${lib}_PARENT)
    message(FATAL_ERROR "${lib} headers not found in /usr/include (scripts/install-deps.sh)")
  endif()
  file(MAKE_DIRECTORY "${_hdr}")
  file(CREATE_LINK "${LUTKIT_${lib}_PARENT}/${lib}" "${_hdr}/${lib}" SYMBOLIC)
endforeach()
add_library(glm::glm INTERFACE IMPORTED)
set_target_properties(glm::glm PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_hdr}")
add_library(CLI11::CLI11 INTERFACE IMPORTED)
set_target_properties(CLI11::CLI11 PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_hdr}")

# Threads: the Windows edition has them (MinGW-w64's winpthreads, linked statically). The browser
# edition has none: WebAssembly threads need a page served with cross-origin isolation headers,
# which static hosts such as GitHub Pages do not send; lut::threadsAvailable() says so and
# everything runs on the calling thread, with the same results.
if(EMSCRIPTEN)
  add_library(Threads::Threads INTERFACE IMPORTED)
  add_compile_definitions(LUTKIT_NO_THREADS=1)
else()
  set(THREADS_PREFER_PTHREAD_FLAG ON)
  find_package(Threads REQUIRED)
endif()

set(LUTKIT_HAVE_QT OFF)
set(LUTKIT_HAVE_BENCHMARK OFF)
