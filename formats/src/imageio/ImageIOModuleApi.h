// SPDX-License-Identifier: Apache-2.0
#pragma once
// The seam between the formats library and the OpenImageIO module (lutkit_imageio.so).
//
// Why: Debian's OpenImageIO pulls in ~260 shared libraries (OpenCV's video I/O, GStreamer, GDAL,
// DCMTK ...) whose loading, symbol lookup and static initialisers cost ~190 ms of CPU (0.4 s of
// wall time on a busy machine) before the first pixel, at every start. So the formats OpenImageIO
// is needed for are behind this module, which ImageIOLoader.cpp dlopen()s on first use; PNG,
// OpenEXR scanline files and PNM have native codecs in lutkit_formats, BMP and TGA native
// readers, and never load it.
// Exceptions do not cross the seam: every entry returns a status and a message, and the loader
// rethrows them as the caller's own types. Images are streamed: a source hands out rows in the
// file's type, a sink takes rows and writes its bytes through the caller's callbacks (checked
// writes: a codec never sees a failed write it could answer with exit()).
#include "imageio/ImageCodec.h"

#include <cstdint>
#include <string>

namespace lut::formats::module {

// 3: ImageInfo has colorSpace and chromaSubsampling; 4: parts (subimages and MIP levels) read
// and written one after the other, tiles, windows; 5: ByteCallbacks::file.
constexpr int kImageIOApiVersion = 5;
constexpr const char* kImageIOModuleName = "lutkit_imageio.so";
constexpr const char* kImageIOEntryPoint = "lutkit_imageio_api";

enum Status : int { kOk = 0, kError = 1, kLimitError = 2, kOutOfMemory = 3, kInterrupted = 4 };

// Where a sink's bytes go (the caller's lut::OutputFile, in memory when it cannot seek).
struct ByteCallbacks {
    void* context = nullptr;
    // Writes n bytes at offset; returns false with a reason on failure.
    bool (*pwrite)(void* context, const void* data, std::size_t n, std::uint64_t offset,
                   std::string& error) = nullptr;
    // The output's own temporary file (a regular file, renamed into place by the caller after
    // the sink finishes), or "" (standard output, a device, memory). A writer that must read back
    // what it wrote writes this file by name instead of through pwrite (without one: a private
    // scratch file, copied through pwrite at the end). See OiioSink.
    std::string file;
};

struct SourceOpen {
    std::string path;
    const std::string* memory = nullptr; // the bytes (standard input's, or in memory), or null
    std::string format;                  // for memory: the format's name, "" = by content
};

struct ImageIOApi {
    int version;
    // Opens the file and lists its parts (every subimage, and each one's MIP levels, in order);
    // part 0 is selected.
    int (*openSource)(const SourceOpen& request, void** handle, int& parts, std::string& error);
    // Makes part `index` the one readRows reads (from row 0) and describes it.
    int (*selectPart)(void* handle, int index, ImageInfo& info, ImageMetadata& metadata,
                      int& granularity, std::string& error);
    int (*readRows)(void* handle, int y0, int y1, void* dst, std::string& error);
    void (*closeSource)(void* handle);
    // `name` is a file name whose extension picks the writer ("x.tif"). specs[0..count) are the
    // parts to write in order (SinkSpec::mipLevel > 0: a MIP level of the part before).
    int (*openSink)(const SinkSpec* specs, int count, const std::string& name, ByteCallbacks bytes,
                    void** handle, int& granularity, std::string& error);
    // Ends the current part and starts the next one.
    int (*nextPart)(void* handle, int& granularity, std::string& error);
    int (*writeRows)(void* handle, int y0, int y1, const void* src, std::string& error);
    int (*finishSink)(void* handle, std::string& error);
    void (*closeSink)(void* handle);
};

using ImageIOEntryPoint = const ImageIOApi* (*)();

} // namespace lut::formats::module
