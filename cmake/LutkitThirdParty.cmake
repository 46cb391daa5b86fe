# SPDX-License-Identifier: Apache-2.0
# The C libraries lutkit compiles from their sources, fetched from Debian 12's archive: the same
# upstream releases Debian 12 ships as packages, each tarball checked against its SHA-256, with
# Debian's own patches where they fix the library (libpng's security fixes, committed in
# third_party/debian/) and lutkit's (third_party/lutkit/). docs/portable.md says why each is here.
#
#   ISA-L's igzip deflate (every build): ISA-L's x86 assembly deflates to other bytes than its
#     portable C, so a PNG written on an x86 Linux machine would differ from the same PNG written
#     in the browser, on Windows or on ARM. lutkit compiles igzip's portable C and deflates with
#     it everywhere, so a written PNG is the same file on every platform (formats/src/imageio/
#     PngWriter.cpp). In the native build its symbols are renamed (lutkit_isal_*) so that
#     Debian's libisal (its assembly inflate, 3.4x faster on a noisy screenshot) links beside it.
#   zlib, libpng, libjpeg-turbo (the portable builds, LUTKIT_PORTABLE): no system library is
#     linked into the browser or Windows edition, and these are the versions the native build
#     links from Debian's packages, so both decode and encode the same bytes.
#
# Tarballs are cached in LUTKIT_SOURCE_CACHE (default ~/.cache/lutkit/sources) and unpacked into
# the build tree (<build>/third-party/); an offline build needs them there (scripts/fetch-sources.sh
# fills the cache).

set(LUTKIT_SOURCE_CACHE "$ENV{HOME}/.cache/lutkit/sources" CACHE PATH
    "Where the third-party source tarballs are kept (downloaded once)")
set(LUTKIT_DEBIAN_MIRROR "http://deb.debian.org/debian" CACHE STRING
    "Debian archive the third-party sources come from")

# lutkit_debian_source(VAR POOL_DIR FILE SHA256 TOPDIR [PATCHES dir])
# Downloads POOL_DIR/FILE from the Debian archive into the cache (once), checks its SHA-256,
# unpacks it into <build>/third-party/ and applies the patches listed in `dir/series`. Sets VAR
# to the unpacked source folder.
function(lutkit_debian_source var pool file sha256 topdir)
  cmake_parse_arguments(arg "" "PATCHES" "" ${ARGN})
  set(archive "${LUTKIT_SOURCE_CACHE}/${file}")
  if(EXISTS "${archive}")
    file(SHA256 "${archive}" have)
    if(NOT have STREQUAL sha256)
      message(STATUS "${archive}: checksum differs, downloading it again")
      file(REMOVE "${archive}")
    endif()
  endif()
  if(NOT EXISTS "${archive}")
    set(url "${LUTKIT_DEBIAN_MIRROR}/pool/main/${pool}/${file}")
    message(STATUS "Downloading ${url}")
    file(MAKE_DIRECTORY "${LUTKIT_SOURCE_CACHE}")
    file(DOWNLOAD "${url}" "${archive}.part" EXPECTED_HASH SHA256=${sha256} STATUS st TLS_VERIFY ON)
    list(GET st 0 code)
    if(NOT code EQUAL 0)
      list(GET st 1 why)
      file(REMOVE "${archive}.part")
      message(FATAL_ERROR "Cannot download ${url}: ${why}. Put ${file} (SHA-256 ${sha256}) into "
                          "${LUTKIT_SOURCE_CACHE} by hand, or run scripts/fetch-sources.sh where the "
                          "Debian archive is reachable.")
    endif()
    file(RENAME "${archive}.part" "${archive}")
  endif()
  set(root "${PROJECT_BINARY_DIR}/third-party")
  set(dir "${root}/${topdir}")
  set(stamp "${dir}/.lutkit-unpacked-${sha256}")
  if(NOT EXISTS "${stamp}")
    file(REMOVE_RECURSE "${dir}")
    file(MAKE_DIRECTORY "${root}")
    file(ARCHIVE_EXTRACT INPUT "${archive}" DESTINATION "${root}")
    if(NOT EXISTS "${dir}")
      message(FATAL_ERROR "${archive} did not unpack into ${dir}")
    endif()
    if(arg_PATCHES)
      file(STRINGS "${arg_PATCHES}/series" series REGEX "^[^#]")
      foreach(p ${series})
        execute_process(COMMAND patch -p1 -s -N -i "${arg_PATCHES}/${p}" WORKING_DIRECTORY "${dir}"
                        RESULT_VARIABLE rc)
        if(NOT rc EQUAL 0)
          message(FATAL_ERROR "Cannot apply ${arg_PATCHES}/${p} to ${dir}")
        endif()
      endforeach()
    endif()
    file(TOUCH "${stamp}")
  endif()
  set(${var} "${dir}" PARENT_SCOPE)
endfunction()

# Third-party code is compiled with its own warnings off and as C, optimised as the build asks.
function(lutkit_third_party_target tgt)
  set_target_properties(${tgt} PROPERTIES POSITION_INDEPENDENT_CODE ON C_VISIBILITY_PRESET hidden)
  target_compile_options(${tgt} PRIVATE -w)
endfunction()

# --- ISA-L's igzip, portable C (every build) -------------------------------------------------
lutkit_debian_source(LUTKIT_ISAL_SRC libi/libisal libisal_2.30.0.orig.tar.xz
  f363f1be3d657d5676cef5253ee2233e60116e2fa9c9de86881185bf81e0e4b8 libisal-2.30.0
  PATCHES "${PROJECT_SOURCE_DIR}/third_party/lutkit/libisal")
set(_isal_files igzip/igzip.c igzip/hufftables_c.c igzip/igzip_base.c igzip/igzip_icf_base.c
  igzip/adler32_base.c igzip/flatten_ll.c igzip/encode_df.c igzip/igzip_icf_body.c
  igzip/igzip_base_aliases.c igzip/proc_heap_base.c igzip/huff_codes.c igzip/igzip_inflate.c
  crc/crc_base.c crc/crc_base_aliases.c crc/crc64_base.c)
list(TRANSFORM _isal_files PREPEND "${LUTKIT_ISAL_SRC}/")
# lutkit_isal_level_state_bytes: the level buffer's state size, so a 32-bit build (WebAssembly)
# compresses in the 64-bit build's blocks (PngWriter.cpp).
add_library(lutkit_igzip STATIC ${_isal_files} "${PROJECT_SOURCE_DIR}/third_party/isal/lutkit_isal_level.c")
lutkit_third_party_target(lutkit_igzip)
target_include_directories(lutkit_igzip PRIVATE ${LUTKIT_ISAL_SRC}/include ${LUTKIT_ISAL_SRC}/igzip ${LUTKIT_ISAL_SRC})
# The header lutkit includes, <isa-l/igzip_lib.h>, from these sources (not the system's).
file(MAKE_DIRECTORY "${PROJECT_BINARY_DIR}/third-party/include/isa-l")
foreach(h igzip_lib.h crc.h types.h)
  configure_file("${LUTKIT_ISAL_SRC}/include/${h}" "${PROJECT_BINARY_DIR}/third-party/include/isa-l/${h}" COPYONLY)
endforeach()
# The hash is ISA-L's multiply hash on every machine: with SSE 4.2 enabled it would be the crc32
# instruction's, and a -march=native build would write other bytes.
target_compile_options(lutkit_igzip PRIVATE -U__SSE4_2__)
if(NOT LUTKIT_PORTABLE)
  # Renamed (lutkit_isal_deflate, ...) so that Debian's libisal links beside it: formats' sources
  # name these through formats/src/imageio/Igzip.h.
  target_compile_options(lutkit_igzip PRIVATE -include "${PROJECT_SOURCE_DIR}/third_party/isal/lutkit_prefix.h")
endif()
target_include_directories(lutkit_igzip INTERFACE "$<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/third-party/include>")
# The Windows edition inflates with ISA-L's x86-64 assembly, as the Linux build does through
# Debian's libisal (its portable C inflate is 3.4x slower, as measured above). Inflating gives the same bytes whichever code does it; deflating
# stays the portable C above. nasm assembles the decoder (SSE and AVX2/BMI2 variants, chosen at
# run time by ISA-L's own dispatcher); without nasm the portable C inflate is used.
if(LUTKIT_PORTABLE AND WIN32 AND CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
  find_program(LUTKIT_NASM nasm)
  if(LUTKIT_NASM)
    set(_isal_asm_objects "")
    foreach(a igzip_inflate_multibinary igzip_decode_block_stateless_01 igzip_decode_block_stateless_04
              rfc1951_lookup)
      set(_obj "${PROJECT_BINARY_DIR}/third-party/isal-asm/${a}.obj")
      add_custom_command(OUTPUT "${_obj}"
        COMMAND "${CMAKE_COMMAND}" -E make_directory "${PROJECT_BINARY_DIR}/third-party/isal-asm"
        COMMAND "${LUTKIT_NASM}" -f win64 -DWIN64 -I${LUTKIT_ISAL_SRC}/include/ -I${LUTKIT_ISAL_SRC}/igzip/
                "${LUTKIT_ISAL_SRC}/igzip/${a}.asm" -o "${_obj}"
        DEPENDS "${LUTKIT_ISAL_SRC}/igzip/${a}.asm" VERBATIM)
      list(APPEND _isal_asm_objects "${_obj}")
    endforeach()
    set_source_files_properties(${_isal_asm_objects} PROPERTIES EXTERNAL_OBJECT ON GENERATED ON)
    target_sources(lutkit_igzip PRIVATE ${_isal_asm_objects})
    # The C alias that would call the portable decoder is renamed out of the way: the assembly's
    # dispatcher defines decode_huffman_code_block_stateless.
    set_source_files_properties("${LUTKIT_ISAL_SRC}/igzip/igzip_base_aliases.c" PROPERTIES
      COMPILE_DEFINITIONS "decode_huffman_code_block_stateless=lutkit_isal_decode_c_alias_unused")
  else()
    message(STATUS "nasm not found: lutkit.exe inflates PNGs with ISA-L's portable C (slower)")
  endif()
endif()

# --- musl's libm functions (every build): lut/Math.h ----------------------------------------
# The same pow, exp, log, cbrt, sin, cos, atan2, hypot (double and float) on every platform:
# glibc, Emscripten's musl and MinGW-w64 round some results differently (glibc picks FMA code on
# CPUs that have it), so a LUT or a picture computed with the system's libm would differ in a
# few values between the Linux, Windows and browser editions. musl's are portable C (ARM's
# optimized routines for exp/log/pow, fdlibm for the others), compiled without FMA contraction,
# under lutkit_ names beside the system's libm.
lutkit_debian_source(LUTKIT_MUSL_SRC m/musl musl_1.2.3.orig.tar.gz
  7d5b0b6062521e4627e099e4c9dc8248d32a30285e959b7eecaa780cf8cfd4a4 musl-1.2.3)
set(_math_files pow exp exp2 log log2 log10 cbrt sin cos atan atan2 hypot powf expf exp2f logf
  log2f cbrtf sinf cosf atanf atan2f hypotf __sin __cos __rem_pio2 __rem_pio2_large __sindf
  __cosdf __rem_pio2f __math_oflow __math_uflow __math_invalid __math_divzero __math_xflow
  __math_oflowf __math_uflowf __math_invalidf __math_divzerof __math_xflowf exp_data pow_data
  log_data log2_data exp2f_data powf_data logf_data log2f_data)
list(TRANSFORM _math_files PREPEND "${LUTKIT_MUSL_SRC}/src/math/")
list(TRANSFORM _math_files APPEND ".c")
add_library(lutkit_math STATIC ${_math_files})
lutkit_third_party_target(lutkit_math)
# Our <math.h> (third_party/musl/include: what the sources use, from compiler builtins), then
# musl's internal headers; MinGW-w64 lacks <endian.h> and <features.h> (third_party/musl/shim-win).
target_include_directories(lutkit_math BEFORE PRIVATE ${PROJECT_SOURCE_DIR}/third_party/musl/include
  ${LUTKIT_MUSL_SRC}/src/internal ${LUTKIT_MUSL_SRC}/arch/generic)
if(WIN32)
  target_include_directories(lutkit_math PRIVATE ${PROJECT_SOURCE_DIR}/third_party/musl/shim-win)
endif()
target_compile_options(lutkit_math PRIVATE -ffp-contract=off -fno-builtin -fno-math-errno
  -include "${PROJECT_SOURCE_DIR}/third_party/musl/lutkit_math_prefix.h")

if(NOT LUTKIT_PORTABLE)
  return()
endif()

# --- zlib ---------------------------------------------------------------------------------------
lutkit_debian_source(LUTKIT_ZLIB_SRC z/zlib zlib_1.2.13.dfsg.orig.tar.bz2
  71feb7947e3c00ef125f83b79a4e529bde31171e5babe48b391f06758d1ab0a1 zlib-1.2.13.dfsg)
set(_zlib_files adler32.c compress.c crc32.c deflate.c infback.c inffast.c inflate.c inftrees.c
  trees.c uncompr.c zutil.c)
list(TRANSFORM _zlib_files PREPEND "${LUTKIT_ZLIB_SRC}/")
add_library(lutkit_zlib STATIC ${_zlib_files})
lutkit_third_party_target(lutkit_zlib)
# No HAVE_UNISTD_H: z_off_t is long for zlib and for every file that includes zlib.h alike.
target_include_directories(lutkit_zlib PUBLIC "$<BUILD_INTERFACE:${LUTKIT_ZLIB_SRC}>")
add_library(ZLIB::ZLIB ALIAS lutkit_zlib)

# --- libpng (with Debian 12's security fixes) ---------------------------------------------------
lutkit_debian_source(LUTKIT_PNG_SRC libp/libpng1.6 libpng1.6_1.6.39.orig.tar.gz
  a00e9d2f2f664186e4202db9299397f851aea71b36a35e74910b8820e380d441 libpng-1.6.39
  PATCHES "${PROJECT_SOURCE_DIR}/third_party/debian/libpng1.6")
set(_png_files png.c pngerror.c pngget.c pngmem.c pngpread.c pngread.c pngrio.c pngrtran.c
  pngrutil.c pngset.c pngtrans.c pngwio.c pngwrite.c pngwtran.c pngwutil.c)
list(TRANSFORM _png_files PREPEND "${LUTKIT_PNG_SRC}/")
# libpng's default configuration without setjmp (lutkit's error handler throws (PngCodec.cpp), and
# the browser edition's WebAssembly exceptions do not mix with setjmp)
file(READ "${LUTKIT_PNG_SRC}/scripts/pnglibconf.h.prebuilt" _pngconf)
string(REPLACE "#define PNG_SETJMP_SUPPORTED\n" "" _pngconf "${_pngconf}")
# ... and without its simplified API (png_image_*), which needs setjmp and which lutkit does not use.
string(REGEX REPLACE "#define PNG_SIMPLIFIED_[A-Z_]*SUPPORTED\n" "" _pngconf "${_pngconf}")
file(WRITE "${PROJECT_BINARY_DIR}/third-party/include/libpng/pnglibconf.h.new" "${_pngconf}")
configure_file("${PROJECT_BINARY_DIR}/third-party/include/libpng/pnglibconf.h.new"
               "${PROJECT_BINARY_DIR}/third-party/include/libpng/pnglibconf.h" COPYONLY)
add_library(lutkit_png STATIC ${_png_files})
lutkit_third_party_target(lutkit_png)
# No hardware-specific filters: the C ones everywhere (the same samples either way).
target_compile_definitions(lutkit_png PRIVATE PNG_ARM_NEON_OPT=0 PNG_INTEL_SSE_OPT=0
                                             PNG_POWERPC_VSX_OPT=0 PNG_MIPS_MSA_OPT=0)
target_include_directories(lutkit_png PUBLIC "$<BUILD_INTERFACE:${LUTKIT_PNG_SRC}>"
                                             "$<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/third-party/include/libpng>")
target_link_libraries(lutkit_png PUBLIC lutkit_zlib)
add_library(PNG::PNG ALIAS lutkit_png)

# --- libjpeg-turbo (the C decoder and encoder; its SIMD code is x86/ARM assembly) ---------------
lutkit_debian_source(LUTKIT_JPEG_SRC libj/libjpeg-turbo libjpeg-turbo_2.1.5.orig.tar.gz
  254f3642b04e309fee775123133c6464181addc150499561020312ec61c1bf7c libjpeg-turbo-2.1.5)
set(_jpeg_files jcapimin.c jcapistd.c jccoefct.c jccolor.c jcdctmgr.c jchuff.c jcicc.c jcinit.c
  jcmainct.c jcmarker.c jcmaster.c jcomapi.c jcparam.c jcphuff.c jcprepct.c jcsample.c jctrans.c
  jdapimin.c jdapistd.c jdatadst.c jdatasrc.c jdcoefct.c jdcolor.c jddctmgr.c jdhuff.c jdicc.c
  jdinput.c jdmainct.c jdmarker.c jdmaster.c jdmerge.c jdphuff.c jdpostct.c jdsample.c jdtrans.c
  jerror.c jfdctflt.c jfdctfst.c jfdctint.c jidctflt.c jidctfst.c jidctint.c jidctred.c
  jquant1.c jquant2.c jutils.c jmemmgr.c jmemnobs.c jaricom.c jcarith.c jdarith.c jsimd_none.c)
list(TRANSFORM _jpeg_files PREPEND "${LUTKIT_JPEG_SRC}/")
# The three headers its CMake generates, as Debian's build makes them (JPEG_LIB_VERSION 62,
# arithmetic coding both ways, in-memory source and destination).
set(_jgen "${PROJECT_BINARY_DIR}/third-party/include/libjpeg")
file(WRITE "${_jgen}/jconfig.h.new" "#define JPEG_LIB_VERSION 62
#define LIBJPEG_TURBO_VERSION 2.1.5
#define LIBJPEG_TURBO_VERSION_NUMBER 2001005
#define C_ARITH_CODING_SUPPORTED 1
#define D_ARITH_CODING_SUPPORTED 1
#define MEM_SRCDST_SUPPORTED 1
#define BITS_IN_JSAMPLE 8
")
file(WRITE "${_jgen}/jconfigint.h.new" "#define BUILD \"lutkit\"
#undef inline
#define INLINE __inline__ __attribute__((always_inline))
#define THREAD_LOCAL __thread
#define PACKAGE_NAME \"libjpeg-turbo\"
#define VERSION \"2.1.5\"
#define SIZEOF_SIZE_T ${CMAKE_SIZEOF_VOID_P}
#if defined(__has_attribute)
#if __has_attribute(fallthrough)
#define FALLTHROUGH __attribute__((fallthrough));
#else
#define FALLTHROUGH
#endif
#else
#define FALLTHROUGH
#endif
")
file(WRITE "${_jgen}/jversion.h.new" "#define JVERSION \"6b  27-Mar-1998\"
#define JCOPYRIGHT \"Copyright (C) 2009-2023 D. R. Commander, Copyright (C) 1991-2020 Thomas G. Lane, Guido Vollbeding\"
#define JCOPYRIGHT_SHORT \"Copyright (C) 1991-2023 The libjpeg-turbo Project and many others\"
")
foreach(h jconfig.h jconfigint.h jversion.h)
  configure_file("${_jgen}/${h}.new" "${_jgen}/${h}" COPYONLY)
endforeach()
add_library(lutkit_jpeg STATIC ${_jpeg_files})
lutkit_third_party_target(lutkit_jpeg)
target_include_directories(lutkit_jpeg PUBLIC "$<BUILD_INTERFACE:${LUTKIT_JPEG_SRC}>"
                                              "$<BUILD_INTERFACE:${_jgen}>")
add_library(JPEG::JPEG ALIAS lutkit_jpeg)
