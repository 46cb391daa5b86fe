# SPDX-License-Identifier: Apache-2.0
# What lutkit's two libraries need wherever they are linked: lutkit::lutlib needs GLM and
# Threads, lutkit::formats OpenColorIO and the native image codecs' libpng, zlib, libjpeg, ISA-L
# and OpenEXR. Included by LutkitDependencies.cmake when lutkit itself is built and, installed next
# to lutkitConfig.cmake, by that config when another project links the installed libraries, so
# both find these the same way (with the same Debian 12 quirks).
find_package(Threads REQUIRED)

# GLM: header-only; Debian ships a config package, fall back to the header.
find_package(glm CONFIG QUIET)
if(NOT TARGET glm::glm)
  find_path(GLM_INCLUDE_DIR glm/glm.hpp REQUIRED)
  add_library(glm::glm INTERFACE IMPORTED)
  set_target_properties(glm::glm PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${GLM_INCLUDE_DIR})
endif()

# OpenColorIO's CMake config is broken on Debian 12: use pkg-config. The installed
# lutkit::formats names the pkg-config target (PkgConfig::OCIO); lutkit's own CMake files use the
# alias OpenColorIO::OpenColorIO.
if(NOT TARGET PkgConfig::OCIO)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(OCIO REQUIRED IMPORTED_TARGET OpenColorIO)
endif()
if(NOT TARGET OpenColorIO::OpenColorIO)
  add_library(OpenColorIO::OpenColorIO ALIAS PkgConfig::OCIO)
endif()

# The native image codecs (formats/src/imageio): PNG, JPEG, OpenEXR scanline files. ISA-L's
# assembly inflates the PNG reader's common files as their rows are asked for (Debian's
# libisal-dev has a pkg-config file only); its deflate is compiled from source
# (cmake/LutkitThirdParty.cmake) so that a PNG is written the same on every platform.
find_package(PNG REQUIRED)
find_package(ZLIB REQUIRED)
find_package(JPEG REQUIRED)
find_package(OpenEXR CONFIG REQUIRED)
if(NOT TARGET PkgConfig::ISAL)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(ISAL REQUIRED IMPORTED_TARGET libisal)
endif()
