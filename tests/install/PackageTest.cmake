# SPDX-License-Identifier: Apache-2.0
# The Debian package (cmake/LutkitPackage.cmake), made from this build tree with cpack and
# extracted with dpkg-deb -x into a fresh root (no dpkg database, no root needed):
#   - its control fields: name, version, the runtime dependencies dpkg-shlibdeps found
#     (OpenImageIO, OpenColorIO; Qt 6 and its platform plugins with the editor);
#   - what it holds: the programs, the image module, the man pages (gzip -9n), the changelog,
#     the completions, the editor's
#     desktop entry, MIME types and icon, the OCIO config, the docs with their pictures, the
#     licence and Debian's copyright file, and no headers, static libraries or CMake package
#     (the `dev` component);
#   - the binaries stripped, the Maintainer an address (what lintian checks, docs/packaging.md);
#   - the extracted lutkit and lutkit-editor run (--version), and the README's quick starts run
#     as written with that lutkit first on PATH (docs_tests with LUTKIT_QUICKSTART_BIN).
# Variables: BUILD_DIR, WORK_DIR, VERSION, DOCS_TESTS, EDITOR (ON/OFF).
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(RUN_OUT "${out}" PARENT_SCOPE)
endfunction()

run(cpack -G DEB --config "${BUILD_DIR}/CPackConfig.cmake" -B "${WORK_DIR}/pkg")
file(GLOB debs "${WORK_DIR}/pkg/lutkit_${VERSION}_*.deb")
list(LENGTH debs n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "expected one lutkit_${VERSION}_*.deb in ${WORK_DIR}/pkg, found: ${debs}")
endif()
set(deb "${debs}")

run(dpkg-deb -f "${deb}" Package Version Depends Section Maintainer)
set(control "${RUN_OUT}")
foreach(want "Package: lutkit" "Version: ${VERSION}" "libopenimageio" "libopencolorio"
             "Section: graphics")
  string(FIND "${control}" "${want}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the control fields lack '${want}':\n${control}")
  endif()
endforeach()
if(control MATCHES "Maintainer: [^\n]*@localhost")
  message(FATAL_ERROR "the Maintainer field is not an address (lintian: bogus-mail-host):\n${control}")
endif()
if(EDITOR)
  foreach(want "libqt6widgets6" "qt6-qpa-plugins")
    string(FIND "${control}" "${want}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "the control fields lack '${want}' (the editor):\n${control}")
    endif()
  endforeach()
endif()

set(root "${WORK_DIR}/root")
run(dpkg-deb -x "${deb}" "${root}")
set(files usr/bin/lutkit usr/lib/lutkit/lutkit_imageio.so usr/share/man/man1/lutkit.1.gz
          usr/share/doc/lutkit/changelog.gz
          usr/share/bash-completion/completions/lutkit usr/share/zsh/site-functions/_lutkit
          usr/share/fish/vendor_completions.d/lutkit.fish usr/share/lutkit/ocio/config.ocio
          usr/share/doc/lutkit/README.md usr/share/doc/lutkit/docs/specs/strip-layouts.md
          usr/share/doc/lutkit/docs/colour.md usr/share/doc/lutkit/docs/images/check-report.png
          usr/share/doc/lutkit/LICENSE usr/share/doc/lutkit/copyright)
if(EDITOR)
  list(APPEND files usr/bin/lutkit-editor usr/share/man/man1/lutkit-editor.1.gz
       usr/share/applications/lutkit-editor.desktop
       usr/share/mime/packages/lutkit.xml usr/share/icons/hicolor/scalable/apps/lutkit-editor.svg)
endif()
foreach(f ${files})
  if(NOT EXISTS "${root}/${f}")
    message(FATAL_ERROR "the package lacks /${f}")
  endif()
endforeach()
foreach(dev usr/include usr/lib/cmake usr/lib/liblutlib.a usr/lib/liblutkit_formats.a)
  if(EXISTS "${root}/${dev}")
    message(FATAL_ERROR "the package holds /${dev}: that is the dev component")
  endif()
endforeach()

# What lintian asks of a package (docs/packaging.md): man pages gzip -9n (no name, no time
# stamp: gzip's header flags byte 0, its time 0), binaries stripped (no .symtab).
foreach(f usr/share/man/man1/lutkit.1.gz usr/share/doc/lutkit/changelog.gz)
  file(READ "${root}/${f}" head LIMIT 10 HEX)
  if(NOT head MATCHES "^1f8b08000000000002")
    message(FATAL_ERROR "/${f} is not gzip -9n (header ${head})")
  endif()
endforeach()
find_program(READELF readelf)
if(READELF)
  set(binaries usr/bin/lutkit usr/lib/lutkit/lutkit_imageio.so)
  if(EDITOR)
    list(APPEND binaries usr/bin/lutkit-editor)
  endif()
  foreach(b ${binaries})
    run(${READELF} -S "${root}/${b}")
    if(RUN_OUT MATCHES "\\.symtab|\\.debug_")
      message(FATAL_ERROR "/${b} is not stripped")
    endif()
  endforeach()
endif()

run("${root}/usr/bin/lutkit" --version)
if(NOT RUN_OUT STREQUAL "lutkit ${VERSION}\n")
  message(FATAL_ERROR "the packaged lutkit says '${RUN_OUT}'")
endif()
if(EDITOR)
  run(${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen "${root}/usr/bin/lutkit-editor" --version)
  if(NOT RUN_OUT STREQUAL "lutkit-editor ${VERSION}\n")
    message(FATAL_ERROR "the packaged lutkit-editor says '${RUN_OUT}'")
  endif()
endif()
# The packaged lutkit finds its image module and OCIO config from where it is (bin/..): an image
# read and a conversion through OpenColorIO from the extracted tree.
run("${root}/usr/bin/lutkit" neutral "${WORK_DIR}/n.png")
run("${root}/usr/bin/lutkit" convert "${WORK_DIR}/n.png" "${WORK_DIR}/n.3dl")
run(${CMAKE_COMMAND} -E env "LUTKIT_QUICKSTART_BIN=${root}/usr/bin"
    "LUTKIT_TEST_TMP=${WORK_DIR}/test-tmp" "${DOCS_TESTS}")
message(STATUS "package ${deb}: control, files, --version and the quick starts checked")
