// SPDX-License-Identifier: Apache-2.0
#pragma once
// The OpenImageIO sink, inside lutkit_imageio.so only (OiioSink.cpp): rows in, a file of any
// format OpenImageIO writes out, its bytes through the caller's checked callbacks, or written by
// name where a writer must read back what it wrote (OiioSink.cpp says which).
#include "imageio/ImageIOModuleApi.h"

#include "lut/Error.h"
#include "lut/io/TempFiles.h"

#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>
#include <vector>

namespace lut::formats::module {

class CallbackProxy;

class OiioSink {
public:
    OiioSink(const SinkSpec* specs, int count, const std::string& name, ByteCallbacks bytes);
    ~OiioSink();
    int granularity() const;
    void nextPart();
    void writeRows(int y0, int y1, const void* src);
    void finish();

private:
    OIIO_NAMESPACE::ImageSpec makeSpec(const SinkSpec& s) const;
    bool proxyFailed() const;
    std::string userText(std::string text) const;
    [[noreturn]] void failWrite(const std::string& reason) const;
    std::string failure(int err) const;
    void checkReadsBack() const;
    void copyScratch();
    void removeScratch() noexcept;

    std::string m_path;     // the name the caller gave: messages name it
    std::string m_openName; // what the writer opens: m_path, the caller's file or the scratch
    std::string m_format;   // the writer's format name ("tiff")
    std::vector<SinkSpec> m_parts;
    std::vector<OIIO_NAMESPACE::ImageSpec> m_specs;
    std::size_t m_index = 0;
    bool m_byName = false;       // the writer writes m_openName itself
    bool m_mipsAsImages = false; // MIP levels written as subimages (TIFF)
    ByteCallbacks m_bytes;
    std::string m_scratch; // a private file written by name, copied through m_bytes at finish()
    TempPathRegistration m_scratchRegistration;
    std::unique_ptr<CallbackProxy> m_proxy;
    std::unique_ptr<OIIO_NAMESPACE::ImageOutput> m_out;
};

} // namespace lut::formats::module
