/* SPDX-License-Identifier: Apache-2.0 */
/* musl's internal headers include <features.h>, which MinGW-w64 does not have: nothing of it is
   needed by the libm sources lutkit compiles. */
#pragma once
