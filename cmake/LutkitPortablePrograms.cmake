# SPDX-License-Identifier: Apache-2.0
# The portable CLI as the browser edition (lutkit.mjs + lutkit.wasm, docs/web.md) or the Windows
# edition (lutkit.exe, one self-contained file: docs/windows.md). Included from cli/CMakeLists.txt
# when LUTKIT_PORTABLE is on.
if(EMSCRIPTEN)
  # An ES module exporting createLutkit() (web/lutkit-api.js, appended after Emscripten's factory):
  # every run() is a fresh instance of the compiled module, so each command runs as in a new
  # process, over an in-memory file system. C++ exceptions are WebAssembly's own (no setjmp is
  # left in lutkit or what it links: PngCodec.cpp, JpegCodec.cpp).
  set_target_properties(lutkit PROPERTIES SUFFIX ".mjs")
  target_link_options(lutkit PRIVATE
    -fwasm-exceptions
    -sMODULARIZE=1 -sEXPORT_ES6=1 -sEXPORT_NAME=createLutkitModule
    -sINVOKE_RUN=0 -sEXIT_RUNTIME=1
    -sALLOW_MEMORY_GROWTH=1 -sMAXIMUM_MEMORY=4GB -sINITIAL_MEMORY=64MB
    -sTOTAL_STACK=8MB
    -sFORCE_FILESYSTEM=1 "-sEXPORTED_RUNTIME_METHODS=['callMain','FS']"
    -sENVIRONMENT=web,worker,node
    -sSUPPORT_LONGJMP=0
    "SHELL:--extern-post-js ${PROJECT_SOURCE_DIR}/web/lutkit-api.js")
  set_property(TARGET lutkit APPEND PROPERTY LINK_DEPENDS ${PROJECT_SOURCE_DIR}/web/lutkit-api.js)
  # The WebAssembly SIMD sampler kernels against their definition, bit for bit (run under Node by
  # tests/web/run.sh; not part of the site).
  add_executable(lutkit_wasm_kernels_check EXCLUDE_FROM_ALL
                 ${PROJECT_SOURCE_DIR}/tests/web/wasm_kernels_check.cpp)
  target_link_libraries(lutkit_wasm_kernels_check PRIVATE lutkit::lutlib_internal)
  target_compile_options(lutkit_wasm_kernels_check PRIVATE -ffp-contract=off)
  target_link_options(lutkit_wasm_kernels_check PRIVATE -sALLOW_MEMORY_GROWTH=1)
  lutkit_warnings(lutkit_wasm_kernels_check)
elseif(WIN32)
  # One self-contained lutkit.exe: the C and C++ runtimes and winpthreads linked in, nothing to
  # install beside it. Unicode arguments and paths come through the wide API (cli/main.cpp).
  target_link_options(lutkit PRIVATE -static -static-libgcc -static-libstdc++)
endif()
