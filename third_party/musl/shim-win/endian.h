/* SPDX-License-Identifier: Apache-2.0 */
/* What musl's libm.h asks of <endian.h>, for toolchains without one (MinGW-w64): every target of
   lutkit is little-endian. */
#pragma once
#define __LITTLE_ENDIAN 1234
#define __BIG_ENDIAN 4321
#define __BYTE_ORDER __LITTLE_ENDIAN
