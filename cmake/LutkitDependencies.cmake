# SPDX-License-Identifier: Apache-2.0
# Finds the Debian-packaged dependencies and papers over their known quirks on Debian 12.
include(LutkitLibraryDependencies) # Threads, GLM, OpenColorIO

# OpenImageIO's exported target lists /usr/include/opencv4, which need not exist: filter it.
find_package(OpenImageIO CONFIG REQUIRED)
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
