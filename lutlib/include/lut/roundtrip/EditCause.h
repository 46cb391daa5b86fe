// SPDX-License-Identifier: Apache-2.0
#pragma once
// The likely cause extract names when a patch is not what a global colour edit leaves (from the
// block evidence, lut/roundtrip/BlockEvidence.h, and the entries' agreement with their
// neighbours), each with its fix in the message.
namespace lut {

enum class EditCause {
    None,      // the patch looks like a global colour edit
    Blur,      // blur, soften, or a resampling filter over the patch
    Sharpen,   // sharpen, unsharp mask, clarity
    Noise,     // noise or film grain
    LocalEdit, // a brush stroke or a local (masked) adjustment over part of the patch
    Lossy,     // lossy compression (JPEG) only
    Unknown,   // not uniform, pattern not recognised
};
// "none", "blur", "sharpen", "noise", "local-edit", "lossy", "unknown"
const char* toString(EditCause cause);

} // namespace lut
