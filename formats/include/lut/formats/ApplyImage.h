// SPDX-License-Identifier: Apache-2.0
#pragma once
// A lut::PixelChain (a LUT and the steps around it) through an image file, streamed: rows are
// read in chunks in the file's own type, converted run by run into float RGBA, run through the
// chain and converted back to the output's type, then written; reading, computing and writing
// overlap on their own threads. Memory is a few chunks, never a frame. The output keeps what the
// input had: its data type (uint8, uint16, half, float; 10-bit DPX stays 10-bit), channels (alpha
// and extra channels pass through untouched), compression (OpenEXR, TIFF) and metadata (EXR
// header attributes, PNG chunks, TIFF/EXIF tags, ICC profile), unless options say otherwise or
// the output format cannot hold it (reported as a diagnostic).
#include "lut/Error.h"
#include "lut/formats/ImageIO.h"
#include "lut/interp/PixelChain.h"
#include "lut/io/OutputPolicy.h"

#include <cstdint>
#include <functional>
#include <string>

namespace lut::formats {

struct ApplyImageOptions {
    int bitDepth = 0;        // 0 = the input's type; 8, 16 (half for OpenEXR), 32 (float)
    std::string compression; // "" = the input's where the output format has it (EXR, TIFF)
    std::string inFormat;    // the input's format when it is "-" ("" = from its first bytes)
    std::string outFormat;   // the output's format for "-"/devices ("" = extension, else input's)
    int threads = 0;         // compute threads (0 = all cores)
    int rowsPerChunk = 0;    // 0 = automatic; the image height = one chunk (whole frame)
    bool overlap = true;     // read, compute and write on threads of their own
    // Which subimage of a file holding several (OpenEXR parts, TIFF pages, GIF frames): -1 =
    // every one (the output format must hold them: OpenEXR, TIFF, GIF; else MultiImageError).
    // MIP levels are kept where the output format has them.
    int subimage = -1;
    // Called once the file's header is read and before any pixel is decoded, with the memory
    // the read will hold at once (chunk buffers, a whole-image decoder's frame): a batch holds
    // its budget here (lutkit's --max-memory). May block; throws to refuse the file.
    std::function<void(std::uint64_t bytes, const std::string& what)> reserveMemory;
};

struct ApplyImageReport {
    ImageInfo input;
    ImageInfo output;
    DomainStats domain; // what the LUT saw outside its domain
    // Output values (R, G, B after the whole chain) that an integer output type (8/16-bit)
    // clamps: outside [0,1] by more than half a step of that type, or NaN; counted only for such
    // outputs (the domain it names is [0,1] widened by that half step).
    DomainStats clamped;
    Diagnostics diagnostics; // what was not kept, and why (warnings, notes)
    bool unchanged = false;  // the chain cannot change these pixels: stored values copied
    int parts = 1;           // images written (subimages and MIP levels)
    double seconds = 0.0;
};

// Reads `input` ("-" = standard input), runs chain on every pixel, writes `output` (from
// lut::checkOutput: the overwrite rule is the caller's). Throws lut::Error naming the file; a
// failed write leaves an existing output as it was.
ApplyImageReport applyToImage(const std::string& input, const OutputTarget& output,
                              const PixelChain& chain, const ApplyImageOptions& options = {});

} // namespace lut::formats
