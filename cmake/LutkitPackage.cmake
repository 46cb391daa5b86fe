# SPDX-License-Identifier: Apache-2.0
# `cpack -G DEB` in a build tree (scripts/package.sh does the build and this): a .deb for Debian
# 12 / Ubuntu with what a user runs -- the CLI, the editor with its desktop entry, icons and MIME
# types, the OpenImageIO module, the man page, the shell completions, lutkit's OCIO config and
# the docs -- installed under /usr. The headers, static libraries and CMake package (component
# `dev`, cmake/LutkitInstall.cmake) stay out. Runtime dependencies are read from the binaries by
# dpkg-shlibdeps (OpenImageIO, OpenColorIO, Qt 6 ...), plus Qt's platform plugins, which no
# binary links but the editor needs to open a window. tests/install/PackageTest.cmake extracts
# the package into a fresh root and runs the README's quick starts from it.
# cpack installs the tree as it is: without this, its install step first builds every target
# (tests and benchmarks too); scripts/package.sh builds what the package holds.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
set(CPACK_PACKAGE_NAME lutkit)
set(CPACK_PACKAGE_VENDOR "lutkit")
# The Maintainer field (lintian: bogus-mail-host for @localhost): the project's own identity by
# default; a distributor building the package sets theirs.
set(LUTKIT_DEB_MAINTAINER
    "lutkit maintainers <maintainers@users.noreply.h-seed-9a43a60b.example>"
    CACHE STRING "The .deb's Maintainer field: Name <address>")
set(CPACK_PACKAGE_CONTACT "${LUTKIT_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${LUTKIT_DEB_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "author, convert and preview colour grading LUTs for games and engines")
# Lines under 80 columns (lintian: extended-description-line-too-long).
set(CPACK_PACKAGE_DESCRIPTION
    "lutkit converts 3D LUTs between .cube, LUT images in every engine's layout
(Unreal, Unity, ReShade strips and MultiLUT atlases, Hald), Smash Ultimate's
color_grading_lut.nutexb and every format OpenColorIO reads, reporting the
error each step costs; previews a grade on a screenshot as the game shows it;
and takes a LUT out of a screenshot graded in an image editor. lutkit-editor
is its Qt 6 editor.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# Apache-2.0 (LICENSE); the package carries it and /usr/share/doc/lutkit/copyright (Debian's
# machine-readable form, share/debian/copyright), installed by cmake/LutkitInstall.cmake.
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
# Only the default component (install() rules without a COMPONENT): not `dev`.
set(CPACK_INSTALL_CMAKE_PROJECTS "${PROJECT_BINARY_DIR};lutkit;Unspecified;/")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # lutkit_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS OFF)
if(TARGET lutkit-editor)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "shared-mime-info, desktop-file-utils")
# lintian-clean (docs/packaging.md): binaries stripped, man pages gzip -9n and a Debian
# changelog (LutkitDebStage.cmake, run on the staged tree).
set(CPACK_STRIP_FILES ON)
set(CPACK_PRE_BUILD_SCRIPTS ${PROJECT_SOURCE_DIR}/cmake/LutkitDebStage.cmake)
set(CPACK_LUTKIT_CHANGELOG_IN ${PROJECT_SOURCE_DIR}/share/debian/changelog.in)
set(CPACK_GENERATOR DEB)
include(CPack)
