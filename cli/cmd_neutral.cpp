// lutkit neutral: the identity LUT in any writable format.
#include "cmd_neutral.h"

#include "Commands.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/formats/Nutexb.h"
#include "lut/formats/Registry.h"
#include "lut/io/FileNames.h"

#include <algorithm>
#include <iostream>

namespace lut::cli {

int defaultNeutralSize(const std::string& path, int formatFixedSize) {
    if (formatFixedSize > 0)
        return formatFixedSize;
    static const char* const kImageExtensions[] = {
        ".png", ".tif", ".tiff", ".exr", ".jpg", ".jpeg", ".bmp", ".tga", ".dpx", ".webp", ".hdr"};
    const std::string ext = extensionOf(path);
    for (const char* e : kImageExtensions)
        if (ext == e)
            return 16;
    return 33;
}

int runNeutral(const NeutralOptions& o) {
    formats::registerBuiltinFormats();
    const auto& registry = FormatRegistry::instance();
    const Format* writer = nullptr;
    if (!o.format.empty()) {
        writer = registry.byName(o.format);
        if (!writer) {
            std::cerr << "lutkit neutral: unknown format '" << o.format << "'\n";
            return kExitUsage;
        }
    } else {
        writer = registry.writerForPath(o.output);
    }
    if (!writer || !writer->canWrite())
        throw Error(o.output + ": no format writes '" + extensionOf(o.output) +
                    "' files (use --format)");

    const int size = o.size ? o.size : defaultNeutralSize(o.output, writer->fixedSize());
    if (size < limits::kMin3DSize || size > limits::kMax3DSize) {
        std::cerr << "lutkit neutral: --size " << size << " is outside " << limits::kMin3DSize
                  << ".." << limits::kMax3DSize << "\n";
        return kExitUsage;
    }
    LutFile file;
    file.cube = Lut3D::identity(size);
    file.cube->setTitle(o.title.empty() ? "neutral " + std::to_string(size) : o.title);
    FormatOptions options;
    options.layout = layoutOption("--layout", o.layout);
    options.size = size;
    options.bitDepth = o.bitDepth;
    if (!o.name.empty())
        options.setAttribute(formats::nutexb::kNameAttribute, o.name);
    const Diagnostics diags = writer->write(o.output, file, options);
    std::cout << "wrote " << o.output << ": " << writer->name() << ", neutral " << size << "^3";
    if (!o.layout.empty())
        std::cout << ", layout " << o.layout;
    if (o.bitDepth)
        std::cout << ", " << o.bitDepth << "-bit";
    std::cout << "\n";
    for (const auto& d : diags)
        std::cout << "  " << d.str() << "\n";
    return kExitOk;
}

} // namespace lut::cli
