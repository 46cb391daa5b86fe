# Warnings for our own targets only (third-party headers are included as SYSTEM).
function(lutkit_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wno-unused-parameter -Wno-restrict)
endfunction()
