# SPDX-License-Identifier: Apache-2.0
# ctest desktop_entry, desktop_mime, desktop_icons (tests/desktop/CMakeLists.txt).
#   entry  desktop-file-validate finds nothing to say about lutkit-editor.desktop; Exec runs
#          lutkit-editor; every MimeType it lists is defined in lutkit.xml and every type there is
#          listed; update-desktop-database maps each type to lutkit-editor.desktop
#   mime   lutkit.xml is well-formed (xmllint); update-mime-database compiles it without an error
#          and its globs2 maps *.cube, *.nutexb and *.lut.png to the types, with *.cube and
#          *.lut.png sub-classes of text/plain and image/png (so text and image programs still
#          open them) and the .cube keywords in its magic
#   icons  the hicolor PNGs are exactly the sizes 16..256, each a PNG whose header says the size
#          of its folder; the scalable SVG is well-formed with the 256x256 viewBox
cmake_minimum_required(VERSION 3.20)

function(need tool var)
  if(NOT ${var})
    message(STATUS "SKIPPED: ${tool} not installed (scripts/install-deps.sh installs it)")
    set(skipped TRUE PARENT_SCOPE)
  endif()
endfunction()

# Runs a command; fails unless it exits 0 with nothing on stderr (and, if quiet, on stdout).
function(run_clean what quiet)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  if(NOT rc EQUAL 0 OR NOT e STREQUAL "" OR (quiet AND NOT o STREQUAL ""))
    message(FATAL_ERROR "${what} (exit ${rc}):\n  ${ARGN}\n${o}\n${e}")
  endif()
endfunction()

function(expect_line what file regex)
  file(STRINGS ${file} lines REGEX "${regex}")
  if(NOT lines)
    file(READ ${file} text)
    message(FATAL_ERROR "${what}: no line of ${file} matches '${regex}':\n${text}")
  endif()
endfunction()

set(entry ${DESKTOP_DIR}/lutkit-editor.desktop)
set(mimexml ${DESKTOP_DIR}/lutkit.xml)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

# The types lutkit.xml defines, in file order.
file(STRINGS ${mimexml} type_lines REGEX "<mime-type type=")
set(defined "")
foreach(l ${type_lines})
  string(REGEX REPLACE ".*<mime-type type=\"([^\"]+)\".*" "\\1" t "${l}")
  list(APPEND defined ${t})
endforeach()
if(NOT defined)
  message(FATAL_ERROR "no <mime-type> in ${mimexml}")
endif()

if(CHECK STREQUAL "entry")
  need(desktop-file-validate DESKTOP_FILE_VALIDATE)
  need(update-desktop-database UPDATE_DESKTOP_DATABASE)
  if(skipped)
    return()
  endif()
  run_clean("desktop-file-validate reports" TRUE ${DESKTOP_FILE_VALIDATE} ${entry})
  expect_line("Exec" ${entry} "^Exec=lutkit-editor( |$)")
  expect_line("Icon" ${entry} "^Icon=lutkit-editor$")
  file(READ ${entry} text)
  string(REGEX MATCH "\nMimeType=([^\n]*)" unused "${text}")
  string(REGEX REPLACE ";$" "" listed "${CMAKE_MATCH_1}") # a CMake list: types split at ';'
  list(SORT listed)
  set(sorted_defined ${defined})
  list(SORT sorted_defined)
  if(NOT listed STREQUAL sorted_defined)
    message(FATAL_ERROR "MimeType= lists '${listed}' but lutkit.xml defines '${sorted_defined}'")
  endif()
  file(MAKE_DIRECTORY ${WORK_DIR}/applications)
  file(COPY ${entry} DESTINATION ${WORK_DIR}/applications)
  run_clean("update-desktop-database" FALSE ${UPDATE_DESKTOP_DATABASE} ${WORK_DIR}/applications)
  foreach(t ${defined})
    expect_line("mimeinfo.cache for ${t}" ${WORK_DIR}/applications/mimeinfo.cache
                "^${t}=(.*;)?lutkit-editor\\.desktop;")
  endforeach()

elseif(CHECK STREQUAL "mime")
  need(xmllint XMLLINT)
  need(update-mime-database UPDATE_MIME_DATABASE)
  if(skipped)
    return()
  endif()
  run_clean("xmllint" TRUE ${XMLLINT} --noout ${mimexml})
  file(MAKE_DIRECTORY ${WORK_DIR}/mime/packages)
  file(COPY ${mimexml} DESTINATION ${WORK_DIR}/mime/packages)
  # update-mime-database exits 0 on errors in a package and only prints them; with WORK_DIR on
  # XDG_DATA_DIRS it prints nothing else.
  run_clean("update-mime-database" TRUE ${CMAKE_COMMAND} -E env XDG_DATA_DIRS=${WORK_DIR}
            ${UPDATE_MIME_DATABASE} ${WORK_DIR}/mime)
  set(globs ${WORK_DIR}/mime/globs2)
  expect_line("glob" ${globs} "^[0-9]+:text/x-cube-lut:\\*\\.cube$")
  expect_line("glob" ${globs} "^[0-9]+:application/x-nutexb:\\*\\.nutexb$")
  expect_line("glob" ${globs} "^[0-9]+:image/x-lut-strip:\\*\\.lut\\.png$")
  expect_line("sub-class" ${WORK_DIR}/mime/subclasses "^text/x-cube-lut text/plain$")
  expect_line("sub-class" ${WORK_DIR}/mime/subclasses "^image/x-lut-strip image/png$")
  file(READ ${WORK_DIR}/mime/magic magic)
  foreach(word LUT_3D_SIZE LUT_1D_SIZE)
    string(FIND "${magic}" "${word}" at)
    if(at EQUAL -1)
      message(FATAL_ERROR "the compiled magic has no ${word}")
    endif()
  endforeach()

elseif(CHECK STREQUAL "icons")
  need(xmllint XMLLINT)
  if(skipped)
    return()
  endif()
  set(hicolor ${DESKTOP_DIR}/icons/hicolor)
  file(GLOB pngs RELATIVE ${hicolor} ${hicolor}/*/apps/*.png)
  list(SORT pngs COMPARE NATURAL)
  set(expected "")
  foreach(s 16 32 48 64 128 256)
    list(APPEND expected "${s}x${s}/apps/lutkit-editor.png")
  endforeach()
  if(NOT pngs STREQUAL expected)
    message(FATAL_ERROR "icons: expected ${expected}, found ${pngs}")
  endif()
  foreach(p ${pngs})
    string(REGEX REPLACE "^([0-9]+)x.*" "\\1" size "${p}")
    # PNG: 8-byte signature, then the IHDR chunk (length, "IHDR", width, height big-endian).
    file(READ ${hicolor}/${p} head LIMIT 24 HEX)
    string(SUBSTRING "${head}" 0 16 signature)
    string(SUBSTRING "${head}" 24 8 chunk)
    string(SUBSTRING "${head}" 32 8 w)
    string(SUBSTRING "${head}" 40 8 h)
    math(EXPR w "0x${w}")
    math(EXPR h "0x${h}")
    if(NOT signature STREQUAL "89504e470d0a1a0a" OR NOT chunk STREQUAL "49484452")
      message(FATAL_ERROR "${p} is not a PNG")
    endif()
    if(NOT w EQUAL size OR NOT h EQUAL size)
      message(FATAL_ERROR "${p} is ${w}x${h}, not ${size}x${size}")
    endif()
  endforeach()
  set(svg ${hicolor}/scalable/apps/lutkit-editor.svg)
  run_clean("xmllint" TRUE ${XMLLINT} --noout ${svg})
  expect_line("square viewBox" ${svg} "viewBox=\"0 0 256 256\"")

else()
  message(FATAL_ERROR "DesktopTest.cmake: -DCHECK=entry|mime|icons")
endif()
