// SPDX-License-Identifier: Apache-2.0
// Entry point of lutkit_imageio.so: OpenImageIO sources and sinks (OiioImage.cpp,
// OiioSink.cpp) behind a
// C-callable table (ImageIOModuleApi.h says why this is a separate module).
#include "imageio/ImageIOModuleApi.h"
#include "imageio/OiioImage.h"
#include "imageio/OiioSink.h"

#include "lut/Error.h"
#include "lut/io/TempFiles.h"

#include <new>

namespace lut::formats::module {
namespace {

template <class Fn> int guarded(std::string& error, Fn&& fn) {
    try {
        fn();
        return kOk;
    } catch (const InterruptedError& e) {
        error = e.what();
        return kInterrupted;
    } catch (const LimitError& e) {
        error = e.what();
        return kLimitError;
    } catch (const std::bad_alloc&) {
        error = "out of memory";
        return kOutOfMemory;
    } catch (const std::exception& e) {
        error = e.what();
        return kError;
    } catch (...) {
        error = "unknown error in the image module";
        return kError;
    }
}

int openSource(const SourceOpen& req, void** handle, int& parts, std::string& error) {
    return guarded(error, [&] {
        auto src = std::make_unique<OiioSource>(req);
        parts = src->parts();
        *handle = src.release();
    });
}
int selectPart(void* h, int index, ImageInfo& info, ImageMetadata& meta, int& granularity,
               std::string& error) {
    return guarded(error,
                   [&] { static_cast<OiioSource*>(h)->select(index, info, meta, granularity); });
}
int readRows(void* h, int y0, int y1, void* dst, std::string& error) {
    return guarded(error, [&] { static_cast<OiioSource*>(h)->readRows(y0, y1, dst); });
}
void closeSource(void* h) {
    delete static_cast<OiioSource*>(h);
}
int openSink(const SinkSpec* specs, int count, const std::string& name, ByteCallbacks bytes,
             void** handle, int& granularity, std::string& error) {
    return guarded(error, [&] {
        auto sink = std::make_unique<OiioSink>(specs, count, name, bytes);
        granularity = sink->granularity();
        *handle = sink.release();
    });
}
int nextPart(void* h, int& granularity, std::string& error) {
    return guarded(error, [&] {
        auto* sink = static_cast<OiioSink*>(h);
        sink->nextPart();
        granularity = sink->granularity();
    });
}
int writeRows(void* h, int y0, int y1, const void* src, std::string& error) {
    return guarded(error, [&] { static_cast<OiioSink*>(h)->writeRows(y0, y1, src); });
}
int finishSink(void* h, std::string& error) {
    return guarded(error, [&] { static_cast<OiioSink*>(h)->finish(); });
}
void closeSink(void* h) {
    delete static_cast<OiioSink*>(h);
}

const ImageIOApi kApi = {kImageIOApiVersion, &openSource, &selectPart, &readRows,   &closeSource,
                         &openSink,          &nextPart,   &writeRows,  &finishSink, &closeSink};

} // namespace
} // namespace lut::formats::module

extern "C" __attribute__((visibility("default"))) const lut::formats::module::ImageIOApi*
lutkit_imageio_api() {
    return &lut::formats::module::kApi;
}

// The module links its own copy of lutlib: its temporary files must be listed in the program's
// registry so an interrupt removes them too (lut/io/TempFiles.h). Called by the loader once.
extern "C" __attribute__((visibility("default"))) void
lutkit_imageio_use_temp_registry(void* registry) {
    lut::useTempFileRegistry(registry);
}
