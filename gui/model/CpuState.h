// SPDX-License-Identifier: Apache-2.0
#pragma once
// Clears the upper halves of the calling thread's AVX registers (vzeroupper) when the CPU has AVX;
// nothing elsewhere. Every worker of the editor calls it before its work.
//
// Why: creating the QApplication leaves the window thread's upper YMM state dirty (measured with
// Qt 6.4 on Debian 12, offscreen and xcb), and a Linux thread starts with a copy of its creator's
// registers, so every worker (and every thread lut::parallelFor starts from one) ran with it.
// Then each return from libm's VEX-encoded powf to lutlib's SSE code paid an AVX-SSE transition
// penalty: lut::srgbDecode of a 3840x2160 frame took 4.5-5.5 s of CPU in the editor against
// 0.21-0.30 s in the same thread after vzeroupper (or in lutkit, which has no Qt): a 4K
// screenshot's first preview took seconds. QtCore only (no Qt at all).
namespace lut::gui {

void clearUpperVectorState();

} // namespace lut::gui
