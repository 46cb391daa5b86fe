// SPDX-License-Identifier: Apache-2.0
#pragma once
// The OpenImageIO source, inside lutkit_imageio.so only (OiioImage.cpp; the sink: OiioSink.h).
#include "imageio/ImageIOModuleApi.h"

#include "lut/Error.h"
#include "lut/io/TempFiles.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <memory>
#include <string>
#include <vector>

namespace lut::formats::module {

class OiioSource {
public:
    explicit OiioSource(const SourceOpen& request);
    ~OiioSource();
    int parts() const { return static_cast<int>(m_parts.size()); }
    // Makes part `index` current (readRows reads it from row 0) and describes it.
    void select(int index, ImageInfo& info, ImageMetadata& metadata, int& granularity);
    void readRows(int y0, int y1, void* dst);

private:
    struct Part {
        int subimage = 0;
        int mipLevel = 0;
    };
    void open(const SourceOpen& request);
    std::string withoutScratch(std::string text) const;
    void removeScratch() noexcept;
    void listParts();
    [[noreturn]] void fail(const std::string& what, bool ok);

    std::string m_path;
    std::unique_ptr<OIIO_NAMESPACE::Filesystem::IOMemReader> m_memory;
    std::string m_scratch; // the bytes in a file, for a reader that reads files only
    TempPathRegistration m_scratchRegistration;
    std::unique_ptr<OIIO_NAMESPACE::ImageInput> m_in;
    OIIO_NAMESPACE::ImageSpec m_spec;
    std::vector<Part> m_parts;
    int m_subimages = 1;
    Part m_current;
};

} // namespace lut::formats::module
