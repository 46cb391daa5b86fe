// SPDX-License-Identifier: Apache-2.0
#pragma once
// The libraries behind the formats print nothing of their own: what they log is folded into the
// one line or the diagnostics of the read or write that caused it. OpenColorIO logs through a
// global function: captureLibraryMessages() points it at the OCIO session in progress (its lines
// become Info diagnostics of that read or write) and drops what is logged outside one. Programs
// call it once at start (lutkit, lutkit-editor); the formats' own OCIO calls install it too.
namespace lut::formats {

void captureLibraryMessages();

} // namespace lut::formats
