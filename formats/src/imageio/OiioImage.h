#pragma once
// OpenImageIO sources and sinks, inside lutkit_imageio.so only (OiioImage.cpp).
#include "imageio/ImageIOModuleApi.h"

#include "lut/Error.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>

namespace lut::formats::module {

class OiioSource {
public:
    explicit OiioSource(const SourceOpen& request);
    ~OiioSource();
    void describe(ImageInfo& info, ImageMetadata& metadata, int& granularity) const;
    void readRows(int y0, int y1, void* dst);

private:
    std::string m_path;
    std::unique_ptr<OIIO_NAMESPACE::Filesystem::IOMemReader> m_memory;
    std::unique_ptr<OIIO_NAMESPACE::ImageInput> m_in;
    OIIO_NAMESPACE::ImageSpec m_spec;
};

class CallbackProxy;

class OiioSink {
public:
    OiioSink(const SinkSpec& spec, const std::string& name, ByteCallbacks bytes);
    ~OiioSink();
    int granularity() const { return m_tiled ? m_tileHeight : 1; }
    void writeRows(int y0, int y1, const void* src);
    void finish();

private:
    std::string m_path;
    SinkSpec m_spec;
    std::unique_ptr<CallbackProxy> m_proxy;
    std::unique_ptr<OIIO_NAMESPACE::ImageOutput> m_out;
    bool m_tiled = false;
    int m_tileHeight = 0;
};

} // namespace lut::formats::module
