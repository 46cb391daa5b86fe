# SPDX-License-Identifier: Apache-2.0
# ctest install_what_was_built (tests/install/CMakeLists.txt): `cmake --install BUILD_DIR --prefix
# $(mktemp -d)` installs what this tree built, and only that (issue 43: after ./run.sh, which
# builds the CLI alone, the editor's and the man page's rules wanted files nobody had made, and
# the install failed half-way). Then the installed lutkit runs: --version and neutral.
#  - the man page and completions are installed with lutkit (made after each link of lutkit);
#  - lutkit-editor, its .desktop entry, MIME types and icons are installed together when the
#    editor was built, and none of them when it was not (a test tree without Qt, or with the
#    editor not built yet, takes the second branch).
cmake_minimum_required(VERSION 3.20)
foreach(v BUILD_DIR VERSION)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "InstallBuiltTest.cmake: -D${v}=... is required")
  endif()
endforeach()

execute_process(COMMAND mktemp -d OUTPUT_VARIABLE prefix OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mktemp -d failed")
endif()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT rc EQUAL 0)
    file(REMOVE_RECURSE ${prefix})
    message(FATAL_ERROR "${what} failed (${rc}):\n  ${ARGN}\n${o}\n${e}")
  endif()
  set(out "${o}${e}" PARENT_SCOPE)
endfunction()

run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
run("installed lutkit --version" ${prefix}/bin/lutkit --version)
if(NOT out STREQUAL "lutkit ${VERSION}\n")
  message(FATAL_ERROR "installed lutkit --version said '${out}'")
endif()
run("installed lutkit neutral" ${prefix}/bin/lutkit neutral ${prefix}/neutral.cube --size 5)
file(STRINGS ${prefix}/neutral.cube size REGEX "^LUT_3D_SIZE ")
if(NOT size STREQUAL "LUT_3D_SIZE 5")
  message(FATAL_ERROR "the installed lutkit's neutral.cube says '${size}'")
endif()
foreach(f share/man/man1/lutkit.1 share/bash-completion/completions/lutkit)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed with lutkit: ${f}")
  endif()
endforeach()

# The editor and its desktop files: all or nothing, as built.
set(editor_files bin/lutkit-editor share/applications/lutkit-editor.desktop
                 share/mime/packages/lutkit.xml share/icons/hicolor/scalable/apps/lutkit-editor.svg)
set(present "")
set(absent "")
foreach(f ${editor_files})
  if(EXISTS ${prefix}/${f})
    list(APPEND present ${f})
  else()
    list(APPEND absent ${f})
  endif()
endforeach()
if(present AND absent)
  message(FATAL_ERROR "half the editor installed: ${present} without ${absent}")
endif()
if(EXISTS ${BUILD_DIR}/bin/lutkit-editor AND absent)
  message(FATAL_ERROR "lutkit-editor was built but not installed: ${absent}")
endif()
if(NOT EXISTS ${BUILD_DIR}/bin/lutkit-editor AND present)
  message(FATAL_ERROR "lutkit-editor was not built, yet installed: ${present}")
endif()
file(REMOVE_RECURSE ${prefix})
