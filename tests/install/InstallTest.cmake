# SPDX-License-Identifier: Apache-2.0
# ctest install_tree (tests/install/CMakeLists.txt): checks that `cmake --install` gives a tree
# that works on its own.
#  1. cmake --install BUILD_DIR --prefix WORK_DIR/prefix
#  2. the installed lutkit converts the sample grade to a nutexb and to a LUT strip PNG, and bakes
#     with lutkit's own OpenColorIO config, found in the installed share/lutkit/ocio/; the strip
#     needs the image module, which must be loaded from the installed lib/lutkit/ (checked with
#     the dynamic loader's LD_DEBUG=files log, since the build tree's copy would work too);
#     `lutkit info --json` on both outputs reports the sizes the formats store (16 and 33); the
#     installed lutkit-editor (when Qt was found) starts and reports the version, and its .desktop
#     entry, MIME types and icons are in share/ (the entry's Exec is the installed program)
#  3. every doc path cited by `lutkit --help`, each command's --help, lutkit-editor --help, the
#     installed man page and the README exists in the repo and in the installed tree: the
#     installed paths (LUTKIT_DOC_DIR/..., e.g. /usr/share/doc/lutkit/docs/colour.md) and the
#     repo-relative ones (docs/x.md, bench/RESULTS.md); every picture a doc shows is installed
#  4. a one-file project (consumer/) configures with find_package(lutkit VERSION) against the
#     prefix only, builds, and runs (consumer/main.cpp says what it checks)
cmake_minimum_required(VERSION 3.20)
foreach(v BUILD_DIR WORK_DIR SAMPLES_DIR CONSUMER_DIR VERSION CXX_COMPILER SOURCE_DIR DOC_DIR DOC_INSTALL_DIR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "InstallTest.cmake: -D${v}=... is required")
  endif()
endforeach()

# Runs a command; fails the test with its output unless it exits 0. The output is left in `out`.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n  ${ARGN}\n${o}\n${e}")
  endif()
  set(out "${o}${e}" PARENT_SCOPE)
endfunction()

function(expect_match what regex text)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: expected a match for '${regex}' in:\n${text}")
  endif()
endfunction()

set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# 1. Install.
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(f bin/lutkit lib/lutkit/lutkit_imageio.so share/lutkit/ocio/config.ocio
          include/lut/Version.h include/lut/Lut3D.h
          include/lut/formats/Registry.h lib/cmake/lutkit/lutkitConfig.cmake
          lib/cmake/lutkit/lutkitConfigVersion.cmake)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${prefix}/${f}")
  endif()
endforeach()

# 2. The installed program.
set(lutkit ${prefix}/bin/lutkit)
set(cube ${SAMPLES_DIR}/sample_grade.cube)
run("installed lutkit convert to nutexb" ${lutkit} convert ${cube} ${WORK_DIR}/a.nutexb)
run("installed lutkit info on the nutexb" ${lutkit} info --json ${WORK_DIR}/a.nutexb)
expect_match("info a.nutexb" "\"format\": \"nutexb\".*\"size\": 16," "${out}")

# A TIFF strip: PNG, OpenEXR and PNM have native codecs, every other format loads the module.
run("installed lutkit convert to a strip TIFF" ${CMAKE_COMMAND} -E env LD_DEBUG=files
    ${lutkit} convert ${cube} ${WORK_DIR}/strip.tif --layout pilot)
# glibc logs each dlopen as "file=<path> [0];  dynamically loaded by ...".
string(REGEX MATCHALL "file=[^ ]*lutkit_imageio\\.so[^\n]*dynamically loaded" loads "${out}")
string(REGEX REPLACE "([][+.*()^$?|\\])" "\\\\\\1" prefix_regex "${prefix}")
expect_match("the image module loaded from the installed tree"
             "^file=${prefix_regex}/bin/\\.\\./lib/lutkit/lutkit_imageio\\.so" "${loads}")
run("installed lutkit info on the strip" ${lutkit} info --json ${WORK_DIR}/strip.tif)
expect_match("info strip.tif" "\"format\": \"strip\".*\"size\": 33," "${out}")

# lutkit's own OpenColorIO config, found next to the installed program (not the build tree's
# copy) when $OCIO names none.
run("installed lutkit bake with its own config" ${CMAKE_COMMAND} -E env --unset=OCIO
    ${lutkit} bake --inputspace ACEScg --outputspace sRGB --cubesize 9 --json ${WORK_DIR}/acescg.cube)
expect_match("bake's config" "\"config\": \"${prefix_regex}/share/lutkit/ocio/config.ocio \\(lutkit's own\\)\""
             "${out}")

if(EXISTS ${prefix}/bin/lutkit-editor)
  run("installed lutkit-editor --version" ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen
      ${prefix}/bin/lutkit-editor --version)
  expect_match("lutkit-editor --version" "lutkit-editor ${VERSION}" "${out}")
  # The desktop integration (gui/desktop): menu entry, MIME types, icon in every size; the entry's
  # Exec names the program installed next to it.
  set(desktop_files share/applications/lutkit-editor.desktop share/mime/packages/lutkit.xml
                    share/icons/hicolor/scalable/apps/lutkit-editor.svg)
  foreach(s 16 32 48 64 128 256)
    list(APPEND desktop_files share/icons/hicolor/${s}x${s}/apps/lutkit-editor.png)
  endforeach()
  foreach(f ${desktop_files})
    if(NOT EXISTS ${prefix}/${f})
      message(FATAL_ERROR "not installed: ${prefix}/${f}")
    endif()
  endforeach()
  file(STRINGS ${prefix}/share/applications/lutkit-editor.desktop exec REGEX "^Exec=")
  string(REGEX REPLACE "^Exec=([^ ]+).*" "\\1" exec "${exec}")
  if(NOT EXISTS ${prefix}/bin/${exec})
    message(FATAL_ERROR "lutkit-editor.desktop runs '${exec}', not in ${prefix}/bin")
  endif()
endif()

# 3. The paper trail: every doc a help text, the man page or the README cites, in the repo and
# installed. The installed path cited is DOC_DIR (the .deb's /usr/share/doc/lutkit), found here
# under the prefix.
run("installed lutkit --help" ${lutkit} --help)
set(cited_in "${out}")
string(REGEX MATCHALL "\n  [a-z]+ +[A-Z]" commands "${out}")
list(LENGTH commands n_commands)
if(n_commands LESS 20)
  message(FATAL_ERROR "lutkit --help lists ${n_commands} commands (parsing failed?):\n${out}")
endif()
foreach(c ${commands})
  string(REGEX REPLACE "^\n  ([a-z]+) .*" "\\1" c "${c}")
  run("installed lutkit ${c} --help" ${lutkit} ${c} --help)
  string(APPEND cited_in "${out}")
endforeach()
if(EXISTS ${prefix}/bin/lutkit-editor)
  run("installed lutkit-editor --help" ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen
      ${prefix}/bin/lutkit-editor --help)
  string(APPEND cited_in "${out}")
endif()
file(READ ${prefix}/share/man/man1/lutkit.1 man)
string(REPLACE "\\-" "-" man "${man}")
string(REPLACE "\\&" "" man "${man}")
file(READ ${SOURCE_DIR}/README.md readme)
string(APPEND cited_in "\n${man}\n${readme}")
# Brackets and semicolons would split CMake's lists oddly: the paths hold none.
string(REGEX REPLACE "[][;]" " " cited_in "${cited_in}")
string(REGEX REPLACE "([][+.*()^$?|\\])" "\\\\\\1" doc_regex "${DOC_DIR}")
string(REGEX MATCHALL "${doc_regex}/[A-Za-z0-9_./-]*[A-Za-z0-9_]" absolute "${cited_in}")
string(REGEX MATCHALL "(^|[^A-Za-z0-9_./-])(docs|bench)/[A-Za-z0-9_./-]*\\.(md|png)" relative "${cited_in}")
set(cited "")
foreach(p ${absolute})
  string(LENGTH "${DOC_DIR}/" skip)
  string(SUBSTRING "${p}" ${skip} -1 p)
  list(APPEND cited "${p}")
endforeach()
foreach(p ${relative})
  string(REGEX REPLACE "^[^db]" "" p "${p}")
  list(APPEND cited "${p}")
endforeach()
list(REMOVE_DUPLICATES cited)
list(LENGTH absolute n_absolute)
if(NOT cited MATCHES "docs/colour\\.md" OR n_absolute LESS 5)
  message(FATAL_ERROR "found only ${n_absolute} installed doc paths cited: ${cited}")
endif()
set(installed_docs ${prefix}/${DOC_INSTALL_DIR})
foreach(p ${cited})
  if(NOT EXISTS ${SOURCE_DIR}/${p})
    message(FATAL_ERROR "cited by --help, the man page or the README, not in the repo: ${p}")
  endif()
  if(NOT EXISTS ${installed_docs}/${p})
    message(FATAL_ERROR "cited by --help, the man page or the README, not installed: ${installed_docs}/${p}")
  endif()
endforeach()
list(LENGTH cited n_cited)
message(STATUS "install_tree: ${n_cited} cited doc paths in the repo and installed: ${cited}")
# The pictures the installed docs show, next to them.
file(GLOB_RECURSE docs_md ${installed_docs}/*.md)
set(n_pictures 0)
foreach(md ${docs_md})
  file(READ ${md} text)
  get_filename_component(dir ${md} DIRECTORY)
  string(REGEX MATCHALL "!\\[[^]]*\\]\\([^)]+\\)" pictures "${text}")
  foreach(pic ${pictures})
    string(REGEX REPLACE ".*\\(([^)]+)\\)$" "\\1" pic "${pic}")
    if(NOT EXISTS ${dir}/${pic})
      message(FATAL_ERROR "${md} shows ${pic}, not installed")
    endif()
    math(EXPR n_pictures "${n_pictures} + 1")
  endforeach()
endforeach()

if(n_pictures LESS 5)
  message(FATAL_ERROR "found only ${n_pictures} pictures in the installed docs")
endif()

# 4. A project built against the installed package, and nothing else.
set(launcher "")
if(CXX_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
run("configuring the find_package(lutkit) consumer" ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/consumer
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER} ${launcher}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DLUTKIT_EXPECTED_VERSION=${VERSION})
run("building the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
run("running the consumer" ${WORK_DIR}/consumer/consumer ${cube} ${WORK_DIR})
message(STATUS "install_tree: ${out}")
