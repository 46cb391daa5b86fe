// The OpenColorIO reader: every LUT file OpenColorIO 2.1 reads (but .cube, ours).
//
// OCIO builds a processor from a FileTransform on the file (it detects the format by extension and
// content); we sample that processor on a lattice over [0,1]^3 of the size the user asked for,
// else the file's own 3D grid size (the largest Lut3DTransform in the processor), else 33. So
// anything OCIO can express (1D shapers + cubes, CDLs, matrices, ICC profiles) comes out as one
// Lut3D; the lattice points hold exactly what OCIO computes there. A file of 1D tables only stays
// a 1D table. The path is checked to be a regular file before OCIO opens it (a FIFO would block
// it), and any failure inside OCIO becomes one line naming the file and what OCIO was doing.
#include "Formats.h"
#include "ocio/OcioInputChecks.h"
#include "ocio/OcioSession.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/Parallel.h"
#include "lut/io/FileNames.h"
#include "lut/io/InputFile.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace lut::formats {

namespace {

std::string lowered(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

// OCIO's format names for an extension ("flame/lustre" for .3dl).
std::string ocioFormatNamesFor(const std::string& ext) {
    std::string names;
    for (int i = 0; i < OCIO::FileTransform::GetNumFormats(); ++i) {
        if ("." + lowered(OCIO::FileTransform::GetFormatExtensionByIndex(i)) != ext)
            continue;
        names +=
            (names.empty() ? "" : "/") + std::string(OCIO::FileTransform::GetFormatNameByIndex(i));
    }
    return names;
}

int bitDepthBits(OCIO::BitDepth d) {
    switch (d) {
    case OCIO::BIT_DEPTH_UINT8:
        return 8;
    case OCIO::BIT_DEPTH_UINT10:
        return 10;
    case OCIO::BIT_DEPTH_UINT12:
        return 12;
    case OCIO::BIT_DEPTH_UINT14:
        return 14;
    case OCIO::BIT_DEPTH_UINT16:
        return 16;
    default:
        return 0;
    }
}

struct ProcessorFacts {
    unsigned long gridSize = 0; // largest 3D grid in the processor (0 = none)
    unsigned long length1d = 0; // longest 1D table (0 = none)
    bool halfDomain = false;    // a 1D table indexed by half floats (not a ramp over [0,1])
    int lut1dCount = 0;
    int lut3dCount = 0;
    int otherCount = 0;
    int bitDepth = 0;
    std::string title;
    std::vector<std::string> comments;
};

void collectMetadata(const OCIO::FormatMetadata& md, ProcessorFacts& facts) {
    if (facts.title.empty()) {
        const char* name = md.getName();
        if (name && *name)
            facts.title = name;
    }
    for (int i = 0; i < md.getNumChildrenElements(); ++i) {
        const auto& child = md.getChildElement(i);
        const char* v = child.getElementValue();
        if (v && *v && facts.comments.size() < 1000)
            facts.comments.emplace_back(v);
    }
}

ProcessorFacts inspect(const OCIO::ConstProcessorRcPtr& processor) {
    ProcessorFacts facts;
    collectMetadata(processor->getFormatMetadata(), facts);
    const auto group = processor->createGroupTransform();
    for (int i = 0; i < group->getNumTransforms(); ++i) {
        const auto t = group->getTransform(i);
        if (auto l3 = OCIO::DynamicPtrCast<const OCIO::Lut3DTransform>(t)) {
            ++facts.lut3dCount;
            facts.gridSize = std::max(facts.gridSize, l3->getGridSize());
            facts.bitDepth = std::max(facts.bitDepth, bitDepthBits(l3->getFileOutputBitDepth()));
            collectMetadata(l3->getFormatMetadata(), facts);
        } else if (auto l1 = OCIO::DynamicPtrCast<const OCIO::Lut1DTransform>(t)) {
            ++facts.lut1dCount;
            facts.length1d = std::max(facts.length1d, l1->getLength());
            facts.halfDomain = facts.halfDomain || l1->getInputHalfDomain();
            facts.bitDepth = std::max(facts.bitDepth, bitDepthBits(l1->getFileOutputBitDepth()));
            collectMetadata(l1->getFormatMetadata(), facts);
        } else {
            ++facts.otherCount;
        }
    }
    return facts;
}

// Every extension OpenColorIO 2.1 reads, except .cube (ours). tests/formats/test_ocio_format.cpp
// checks this list against FileTransform::GetFormatExtensionByIndex so it cannot drift; it is
// spelled out here so that looking a format up never has to load OCIO's format registry.
const std::vector<std::string> kOcioReadExtensions = {
    ".3dl", ".cc",  ".ccc",  ".cdl", ".clf", ".ctf",   ".csp",   ".lut",    ".icc", ".icm",
    ".pf",  ".itx", ".look", ".mga", ".m3d", ".spi1d", ".spi3d", ".spimtx", ".cub", ".vf"};

class OcioReadFormat final : public Format {
public:
    std::string name() const override { return "ocio"; }
    std::string description() const override {
        return "any LUT file OpenColorIO reads (.3dl .csp .spi1d .spi3d .clf .ctf .cub .cc .ccc "
               ".cdl "
               ".look .itx .mga .m3d .vf .lut .icc), sampled on a lattice";
    }
    std::vector<std::string> extensions() const override { return kOcioReadExtensions; }
    bool canWrite() const override { return false; }

    LutFile read(const std::string& path, const FormatOptions& options) const override {
        // OCIO opens the file itself: a FIFO, a directory or a device is refused first.
        checkRegularInput(path);
        std::error_code ec;
        const auto fileSize = std::filesystem::file_size(path, ec);
        if (ec)
            throw Error(path + ": cannot open: " + ec.message());
        if (fileSize > limits::kMaxLutFileBytes)
            throw LimitError(path + ": file is " + std::to_string(fileSize) +
                             " bytes, over the limit of " +
                             std::to_string(limits::kMaxLutFileBytes));
        if (options.size != 0 &&
            (options.size < limits::kMin3DSize || options.size > limits::kMax3DSize))
            throw Error(path + ": lattice size " + std::to_string(options.size) + " is outside " +
                        std::to_string(limits::kMin3DSize) + ".." +
                        std::to_string(limits::kMax3DSize));

        checkOcioInput(path); // what OCIO 2.1 would loop on
        OcioSession session(path);
        LutFile out;
        out.format = name();
        Lut3D lut;
        std::string doing = "loading the file"; // for messages: what OCIO was doing
        try {
            // OCIO caches files by path; a file rewritten in place must be read afresh.
            OCIO::ClearAllCaches();
            auto config = OCIO::Config::CreateRaw();
            auto ft = OCIO::FileTransform::Create();
            ft->setSrc(std::filesystem::absolute(path).string().c_str());
            ft->setInterpolation(OCIO::INTERP_BEST);
            const auto processor = config->getProcessor(ft);
            doing = "inspecting the processor";
            const ProcessorFacts facts = inspect(processor);
            out.dialect = ocioFormatNamesFor(extensionOf(path));
            out.sourceBitDepth = facts.bitDepth;

            doing = "building the CPU processor";
            const auto cpu = processor->getOptimizedCPUProcessor(
                OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_NONE);
            // A file of 1D tables only (.spi1d, a 1D .csp, a Discreet .lut) stays a per-channel
            // table: sampled on its own length along the grey ramp, which for per-channel tables
            // is the whole function. Asking for --size makes it a 3D lattice like everything else.
            if (options.size == 0 && facts.lut1dCount > 0 && facts.lut3dCount == 0 &&
                facts.otherCount == 0 && !facts.halfDomain &&
                facts.length1d >= static_cast<unsigned long>(limits::kMin1DSize) &&
                facts.length1d <= static_cast<unsigned long>(limits::kMax1DSize)) {
                doing = "sampling the processor";
                Lut1D shaper = Lut1D::identity(static_cast<int>(facts.length1d));
                shaper.setTitle(facts.title);
                OCIO::PackedImageDesc desc(&shaper.entries()[0].x, shaper.size(), 1, 3);
                cpu->apply(desc);
                for (auto& v : shaper.entries())
                    for (int c = 0; c < 3; ++c)
                        if (!std::isfinite(v[c]))
                            v[c] = 0.0f;
                out.shaper = std::move(shaper);
                session.appendDiagnostics(out.diagnostics);
                return out;
            }

            int size = options.size;
            if (size == 0)
                size = facts.gridSize >= static_cast<unsigned long>(limits::kMin3DSize) &&
                               facts.gridSize <= static_cast<unsigned long>(limits::kMax3DSize)
                           ? static_cast<int>(facts.gridSize)
                           : 33;
            doing = "sampling the processor";
            const std::uint64_t bytes = static_cast<std::uint64_t>(size) * size * size * 12;
            lut = allocating(path, "the " + std::to_string(size) + "^3 lattice", bytes,
                             [&] { return Lut3D::identity(size); });
            lut.setTitle(facts.title);
            lut.comments() = facts.comments;
            // The identity lattice is already in our order (red fastest): OCIO maps it in place,
            // so no index order has to be translated. Rows of one (g,b) line each, in parallel.
            float* data = lut.data();
            parallelFor(size * size, 0, [&](int l0, int l1) {
                OCIO::PackedImageDesc desc(data + static_cast<std::size_t>(l0) * size * 3, size,
                                           l1 - l0, 3);
                cpu->apply(desc);
            });
            if (facts.lut3dCount == 0 || facts.lut1dCount > 0 || facts.otherCount > 0 ||
                facts.gridSize != static_cast<unsigned long>(size))
                out.diagnostics.push_back(ocioDiagnostic(
                    path, "sampled OpenColorIO's processor (" + std::to_string(facts.lut1dCount) +
                              " 1D LUT, " + std::to_string(facts.lut3dCount) + " 3D LUT, " +
                              std::to_string(facts.otherCount) + " other ops) on a " +
                              std::to_string(size) + "^3 lattice over [0,1]"));
        } catch (const Error&) {
            throw;
        } catch (const std::exception& e) {
            // OCIO::Exception, and C++ library errors from inside OCIO (std::length_error's
            // "vector::reserve" when a reader believes a size in the file, std::bad_alloc).
            throw Error(ocioFailure(path, doing, e.what()));
        }
        std::size_t nonFinite = 0;
        for (auto& v : lut.entries())
            for (int c = 0; c < 3; ++c)
                if (!std::isfinite(v[c])) {
                    v[c] = 0.0f;
                    ++nonFinite;
                }
        if (nonFinite)
            out.diagnostics.push_back(
                ocioDiagnostic(path, std::to_string(nonFinite) + " NaN/Inf values replaced by 0",
                               Diagnostic::Severity::Warning));
        session.appendDiagnostics(out.diagnostics);
        out.cube = std::move(lut);
        return out;
    }

    Diagnostics write(const std::string& path, const LutFile&,
                      const FormatOptions&) const override {
        throw Error(path + ": the 'ocio' reader does not write; pick a format with --format");
    }
};

} // namespace

std::unique_ptr<Format> makeOcioReadFormat() {
    return std::make_unique<OcioReadFormat>();
}

} // namespace lut::formats
