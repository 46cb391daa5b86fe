# SPDX-License-Identifier: Apache-2.0
# CPack's pre-build script for the .deb (CPACK_PRE_BUILD_SCRIPTS, cmake/LutkitPackage.cmake): run
# on the staged tree before it is packed, so the package is what Debian's policy and lintian ask
# for while `cmake --install` stays plain:
#  - man pages compressed with gzip -9n (no name, no time stamp: the same bytes every build);
#  - /usr/share/doc/lutkit/changelog.gz, a Debian changelog of this version (share/debian/
#    changelog.in; a native package's changelog is changelog.gz, not changelog.Debian.gz).
# The binaries are stripped by CPack itself (CPACK_STRIP_FILES).
set(stage "${CPACK_TEMPORARY_INSTALL_DIRECTORY}${CPACK_PACKAGING_INSTALL_PREFIX}")
if(NOT IS_DIRECTORY "${stage}/bin")
  message(FATAL_ERROR "LutkitDebStage.cmake: no staged tree at ${stage}")
endif()
find_program(LUTKIT_GZIP gzip REQUIRED)

function(gzip_n9 file)
  execute_process(COMMAND ${LUTKIT_GZIP} -9 -n -f "${file}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "gzip -9n ${file} failed")
  endif()
endfunction()

file(GLOB pages "${stage}/share/man/man*/*.[0-9]")
foreach(page ${pages})
  gzip_n9("${page}")
endforeach()

set(VERSION "${CPACK_PACKAGE_VERSION}")
set(MAINTAINER "${CPACK_DEBIAN_PACKAGE_MAINTAINER}")
configure_file("${CPACK_LUTKIT_CHANGELOG_IN}" "${stage}/share/doc/lutkit/changelog" @ONLY)
gzip_n9("${stage}/share/doc/lutkit/changelog")
