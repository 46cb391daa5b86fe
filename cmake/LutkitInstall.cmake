# SPDX-License-Identifier: Apache-2.0
# What `cmake --install build --prefix P` puts where. The programs install themselves in their own
# CMakeLists (cli/, gui/); this file installs the package a C++ project links against:
#   P/lib/lutkit/lutkit_imageio.so  the OpenImageIO module (formats/src/imageio/ImageIOLoader.cpp
#                                    looks for it in <executable dir>/../lib/lutkit/)
#   P/include/lut/...                the public headers of lutlib and formats, and the generated
#                                    lut/Version.h
#   P/lib/liblutlib.a, P/lib/liblutkit_formats.a
#   P/lib/cmake/lutkit/              find_package(lutkit) -> lutkit::lutlib, lutkit::formats and
#                                    lutkit::imageio (the module, for $<TARGET_FILE:...>)
#   P/share/lutkit/ocio/config.ocio  lutkit's own OpenColorIO config (found relative to the
#                                    executable, formats/src/ocio/ColorConfig.cpp)
#   P/share/doc/lutkit/              README.md, CONTRIBUTING.md, LICENSE, copyright and docs/
#                                    (the .md files and their pictures)
# tests/install checks the installed tree: the installed lutkit runs, and a one-file project
# builds against it with find_package.
include(CMakePackageConfigHelpers)

set(LUTKIT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/lutkit)
# Not CMAKE_INSTALL_LIBDIR: the loader finds the module relative to the executable (bin/..).
set(LUTKIT_INSTALL_MODULEDIR lib/lutkit)

set_target_properties(lutkit_formats PROPERTIES EXPORT_NAME formats)
set_target_properties(lutkit_imageio PROPERTIES EXPORT_NAME imageio)
# Component `dev` (headers, static libraries, the CMake package): what a project building against
# lutkit needs, left out of the .deb (cmake/LutkitPackage.cmake); everything else is the default
# component, what users run.
install(TARGETS lutlib lutkit_math lutkit_formats lutkit_igzip lutkit_imageio EXPORT lutkitTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT dev
        LIBRARY DESTINATION ${LUTKIT_INSTALL_MODULEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/lutlib/include/ ${PROJECT_SOURCE_DIR}/formats/include/
                  ${PROJECT_BINARY_DIR}/lutlib/generated/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT dev FILES_MATCHING PATTERN "*.h")

# Not CMAKE_INSTALL_DATADIR: found relative to the executable (bin/../share/lutkit).
install(FILES ${PROJECT_SOURCE_DIR}/share/ocio/config.ocio DESTINATION share/lutkit/ocio)

install(EXPORT lutkitTargets NAMESPACE lutkit:: DESTINATION ${LUTKIT_INSTALL_CMAKEDIR} COMPONENT dev)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/lutkitConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/lutkitConfig.cmake
                              INSTALL_DESTINATION ${LUTKIT_INSTALL_CMAKEDIR})
# 0.x: a minor version may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/lutkitConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/lutkitConfig.cmake ${PROJECT_BINARY_DIR}/lutkitConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/LutkitLibraryDependencies.cmake
        DESTINATION ${LUTKIT_INSTALL_CMAKEDIR} COMPONENT dev)

# The docs, where Debian puts a package's: share/doc/lutkit, laid out as in the repo so the
# README's links (docs/colour.md, docs/images/...) work in the installed tree; the pictures the
# docs show; the licence, and Debian's machine-readable copyright file. `--help` and the man page
# cite the installed paths (LUTKIT_DOC_DIR, cli/CMakeLists.txt); tests/install checks that every
# path they and the README cite is installed.
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CONTRIBUTING.md
              ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/share/debian/copyright
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/lutkit)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/lutkit/docs
        FILES_MATCHING PATTERN "*.md" PATTERN "*.png")
# The measurements the README's Numbers cite.
install(FILES ${PROJECT_SOURCE_DIR}/bench/RESULTS.md DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/lutkit/bench)
