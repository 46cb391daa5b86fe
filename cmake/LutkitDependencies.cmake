# SPDX-License-Identifier: Apache-2.0
# Finds the Debian-packaged dependencies and papers over their known quirks on Debian 12.
if(LUTKIT_PORTABLE)
  include(LutkitPortableDependencies)
  return()
endif()
include(LutkitLibraryDependencies) # Threads, GLM, OpenColorIO

# Debian 12's libopenimageio-dev exports OIIO's command-line tools (iconvert, oiiotool, iv, ...)
# with the library, and its CMake config stops with an error when they are not installed: they are
# in openimageio-tools, which pulls Qt 5 and GTK 3 in. ./run.sh installs only the library, so when
# a tool the config names is missing (or LUTKIT_OIIO_PKGCONFIG is ON, as the fuzz build sets to keep
# this path tested) the library is taken from its pkg-config file instead.
option(LUTKIT_OIIO_PKGCONFIG "Find OpenImageIO through pkg-config, not its CMake config" OFF)
set(_oiio_from_pc ${LUTKIT_OIIO_PKGCONFIG})
find_path(LUTKIT_OIIO_CONFIG_DIR OpenImageIOTargets.cmake PATHS ${CMAKE_SYSTEM_PREFIX_PATH}
          PATH_SUFFIXES lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenImageIO lib/cmake/OpenImageIO)
if(NOT _oiio_from_pc AND LUTKIT_OIIO_CONFIG_DIR)
  get_filename_component(_oiio_prefix "${LUTKIT_OIIO_CONFIG_DIR}/../../../.." ABSOLUTE)
  file(STRINGS "${LUTKIT_OIIO_CONFIG_DIR}/OpenImageIOTargets.cmake" _oiio_tools
       REGEX "^add_executable\\(OpenImageIO::")
  foreach(_line ${_oiio_tools})
    string(REGEX REPLACE "^add_executable\\(OpenImageIO::([A-Za-z0-9_]+).*" "\\1" _tool "${_line}")
    if(NOT EXISTS "${_oiio_prefix}/bin/${_tool}")
      message(STATUS "OpenImageIO's tool ${_tool} is not installed: OpenImageIO found through pkg-config")
      set(_oiio_from_pc ON)
      break()
    endif()
  endforeach()
endif()
if(_oiio_from_pc)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(LUTKIT_OIIO REQUIRED IMPORTED_TARGET OpenImageIO)
  find_package(Imath CONFIG REQUIRED)
  add_library(OpenImageIO::OpenImageIO INTERFACE IMPORTED)
  target_link_libraries(OpenImageIO::OpenImageIO INTERFACE PkgConfig::LUTKIT_OIIO Imath::Imath)
else()
  find_package(OpenImageIO CONFIG REQUIRED)
endif()
# OpenImageIO's exported target lists /usr/include/opencv4, which need not exist: filter it.
foreach(tgt OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
  if(TARGET ${tgt})
    get_target_property(_inc ${tgt} INTERFACE_INCLUDE_DIRECTORIES)
    if(_inc)
      set(_kept "")
      foreach(d ${_inc})
        if(EXISTS "${d}" OR d MATCHES "^\\$<")
          list(APPEND _kept "${d}")
        endif()
      endforeach()
      set_target_properties(${tgt} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_kept}")
    endif()
  endif()
endforeach()

find_package(CLI11 CONFIG QUIET)
if(NOT TARGET CLI11::CLI11)
  find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp REQUIRED)
  add_library(CLI11::CLI11 INTERFACE IMPORTED)
  set_target_properties(CLI11::CLI11 PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${CLI11_INCLUDE_DIR})
endif()

if(LUTKIT_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()

find_package(benchmark CONFIG QUIET)
set(LUTKIT_HAVE_BENCHMARK ${benchmark_FOUND})

set(LUTKIT_HAVE_QT OFF)
if(LUTKIT_BUILD_GUI)
  find_package(Qt6 COMPONENTS Widgets Test Concurrent QUIET)
  if(Qt6_FOUND AND Qt6Widgets_FOUND)
    set(LUTKIT_HAVE_QT ON)
  else()
    message(STATUS "Qt 6 not found: the editor (gui/) is not built")
  endif()
endif()
