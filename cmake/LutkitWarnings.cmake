# SPDX-License-Identifier: Apache-2.0
# Warnings for our own targets only (third-party headers are included as SYSTEM). -Wno-restrict is
# GCC's (a false positive of GCC 12 in std::string); clang (Emscripten, the fuzzers) has no such
# warning.
function(lutkit_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wno-unused-parameter
                                           $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
  if(LUTKIT_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
