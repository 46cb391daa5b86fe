// SPDX-License-Identifier: Apache-2.0
// resolveLutDestination: the one place that decides what a LUT output is and is for.
#include "lut/formats/LutDestination.h"

#include "lut/Error.h"
#include "lut/formats/ImageFiles.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"
#include "lut/io/FormatRegistry.h"

namespace lut::formats {

bool LutDestination::gameFormat() const {
    return writer && writer->name() == kGameLutFormat;
}

bool isGameFormatPath(const std::string& path) {
    registerBuiltinFormats();
    const Format* f = FormatRegistry::instance().writerForPath(path);
    return f && f->name() == kGameLutFormat;
}

int LutDestination::newTableSize(int otherwise) const {
    return size ? size : fixedSize ? fixedSize : image ? kLutImageSize : otherwise;
}

const Format& LutDestination::requireWriter() const {
    if (!writer)
        throw Error(path + ": no format writes '" + extensionOf(path) +
                    "' files (name the output format: --format)");
    return *writer;
}

LutDestination resolveLutDestination(const LutDestinationRequest& request) {
    registerBuiltinFormats();
    const FormatRegistry& registry = FormatRegistry::instance();
    LutDestination d;
    d.path = request.path;
    d.format = request.format;
    const Format* writer = request.format.empty() ? registry.writerForPath(request.path)
                                                  : registry.byName(request.format);
    d.writer = writer && writer->canWrite() ? writer : nullptr;

    if (request.purpose) {
        d.purpose = request.purpose;
        d.purposeFrom = DestinationPurpose::Said;
    } else if (d.gameFormat()) {
        d.purpose = LutPurpose::Smash;
        d.purposeFrom = DestinationPurpose::GameFormat;
    }

    d.size = request.size;
    d.layout = request.layout;
    d.image = request.format.empty() ? isImageExtension(request.path)
                                     : request.format == "hald" || request.format == "strip";
    if (request.haldLevel) {
        if (request.layout && *request.layout != LutLayout::Hald)
            throw RequestError(std::string("--level is a Hald level; the layout is ") +
                               toString(*request.layout) + " (use --size)");
        if (!d.image)
            throw RequestError("--level is a Hald level; " + request.path +
                               " is not a LUT image (use --size)");
        d.haldLevel = request.haldLevel;
        d.size = request.haldLevel * request.haldLevel;
        if (request.format != "hald")
            d.layout = LutLayout::Hald;
    }
    d.hald = d.writer && (d.writer->name() == "hald" ||
                          (d.layout == LutLayout::Hald && d.writer->name() == "strip"));
    if (d.writer) {
        FormatOptions sized;
        sized.layout = d.layout;
        d.fixedSize = d.writer->fixedSizeFor(sized);
    }
    return d;
}

} // namespace lut::formats
