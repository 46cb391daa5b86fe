# SPDX-License-Identifier: Apache-2.0
# Warnings for our own targets only (third-party headers are included as SYSTEM).
function(lutkit_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wno-unused-parameter -Wno-restrict)
  if(LUTKIT_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
