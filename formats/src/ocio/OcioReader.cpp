// SPDX-License-Identifier: Apache-2.0
// The OpenColorIO reader: every LUT file OpenColorIO 2.1 reads (but .cube, ours).
//
// OCIO builds a processor from a FileTransform on the file (it detects the format by extension and
// content; a .ccc/.cdl correction is picked by the "ocio:cccid" attribute, lut/formats/
// OcioFiles.h). When the processor is exactly a 3D table, a 1D shaper then a 3D table, or
// per-channel 1D tables, behind scale-and-offset ops that set their input range
// (ocio/OcioStructure.h), the LutFile holds exactly that: lattice points and shaper entries are
// what OCIO computes there, over the file's own input range. Any other chain (CDLs, logs, several
// tables, ICC profiles) is sampled through the WHOLE processor, never on an inner table's lattice:
// at the size asked for, else 33 (or the largest 3D grid in the file if larger), or, for a chain
// without channel crosstalk, as a 4096-entry 1D table; the error that costs against the processor
// is measured between the lattice points and reported (ocio/OcioSampling.h). The path is checked
// to be a regular file before OCIO opens it (a FIFO would block it), and any failure inside OCIO
// becomes one line naming the file and what OCIO was doing.
#include "Formats.h"
#include "ocio/OcioFacts.h"
#include "ocio/OcioInputChecks.h"
#include "ocio/OcioSampling.h"
#include "ocio/OcioSession.h"
#include "ocio/OcioStructure.h"
#include "ocio/OcioTemporaryFile.h"

#include "lut/formats/OcioFiles.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/Parallel.h"
#include "lut/io/FileNames.h"
#include "lut/io/InputFile.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace lut::formats {

namespace {

// A Cinespace file's METADATA block (OpenColorIO reads no metadata from it): the tag lutkit
// writes there (CspWriter.cpp), if any. Only the file's head is read: the block comes first.
std::optional<LutPurpose> cspMetadataPurpose(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(16384, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    const std::size_t begin = head.find("BEGIN METADATA");
    const std::size_t end = head.find("END METADATA");
    if (begin == std::string::npos || end == std::string::npos || end < begin)
        return std::nullopt;
    return purposeInText(std::string_view(head).substr(begin, end - begin), path);
}

// A "#" comment line holding the tag (lutkit writes one at the top of a .3dl and an .itx:
// OcioWriters.cpp; OpenColorIO skips it). Only the file's head is read.
std::optional<LutPurpose> commentPurpose(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(16384, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    if (head.find('\0') != std::string::npos)
        return std::nullopt; // binary (an ICC profile)
    std::optional<LutPurpose> found;
    std::size_t start = 0;
    while (start < head.size()) {
        std::size_t end = head.find('\n', start);
        if (end == std::string::npos)
            end = head.size();
        const std::string_view line = std::string_view(head).substr(start, end - start);
        const std::size_t first = line.find_first_not_of(" \t");
        if (first != std::string_view::npos && line[first] == '#')
            if (const auto p = purposeInText(line.substr(first + 1), path)) {
                if (found && *found != *p)
                    throw Error(path + ": two LUTKIT_PURPOSE tags that disagree (raw and smash)");
                found = p;
            }
        start = end + 1;
    }
    return found;
}

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
    // Text formats, and ICC profiles (binary: their header's size field, "acsp" at byte 36).
    std::uint64_t maxStreamBytes(std::string_view head) const override {
        if (head.find('\0') == std::string_view::npos)
            return limits::kMaxLutFileBytes;
        if (head.size() < 40 || head.substr(36, 4) != "acsp")
            return 0;
        std::uint64_t size = 0;
        for (int i = 0; i < 4; ++i)
            size = size << 8 | static_cast<unsigned char>(head[static_cast<std::size_t>(i)]);
        return std::min<std::uint64_t>(size, limits::kMaxLutFileBytes);
    }

    LutFile read(const std::string& path, const FormatOptions& options) const override {
        // OCIO opens the file itself: a FIFO, a directory or a device is refused first.
        checkRegularInput(path);
        std::error_code ec;
        const auto fileSize = std::filesystem::file_size(path, ec);
        if (ec)
            throw IoError(path + ": cannot open: " + ec.message());
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
        std::string doing = "loading the file"; // for messages: what OCIO was doing
        try {
            // OCIO caches files by path; a file rewritten in place must be read afresh.
            OCIO::ClearAllCaches();
            auto config = OCIO::Config::CreateRaw();
            auto ft = OCIO::FileTransform::Create();
            ft->setSrc(std::filesystem::absolute(path).string().c_str());
            ft->setInterpolation(OCIO::INTERP_BEST);
            if (const auto id = options.attribute(kOcioCccIdAttribute))
                ft->setCCCId(id->c_str());
            const auto processor = config->getProcessor(ft);
            doing = "inspecting the processor";
            const ProcessorFacts facts = inspectProcessor(processor);
            out.dialect = ocioFormatNamesFor(extensionOf(path));
            out.sourceBitDepth = facts.bitDepth;
            const OcioStructure structure = analyseProcessor(config, processor);
            doing = "sampling the processor";
            sampleProcessor(path, processor, structure, facts, options.size, out);
            // What the LUT is for: a LUTKIT_PURPOSE description (.clf, .ctf: lut/LutPurpose.h).
            std::vector<std::string> described = facts.comments;
            out.purpose = takePurposeTag(described, path);
            if (!out.purpose && extensionOf(path) == ".csp")
                out.purpose = cspMetadataPurpose(path);
            if (!out.purpose)
                out.purpose = commentPurpose(path);
            if (out.cube)
                (void)takePurposeTag(out.cube->comments(), path);
        } catch (const Error&) {
            throw;
        } catch (const std::exception& e) {
            // OCIO::Exception, and C++ library errors from inside OCIO (std::length_error's
            // "vector::reserve" when a reader believes a size in the file, std::bad_alloc).
            std::string msg = ocioFailure(path, doing, e.what());
            if ((msg.find("CCC") != std::string::npos || msg.find("cccid") != std::string::npos) &&
                !options.attribute(kOcioCccIdAttribute))
                msg += " (name the correction with --cccid)";
            throw Error(msg);
        }
        replaceNonFinite(path, out);
        session.appendDiagnostics(out.diagnostics);
        return out;
    }

    // OpenColorIO opens files by path only: bytes in memory go through a temporary file.
    LutFile readMemory(std::string_view bytes, const std::string& name,
                       const FormatOptions& options) const override {
        return readThroughTemporaryFile(
            bytes, name, [&](const std::string& path) { return read(path, options); });
    }
    std::string writeMemory(const LutFile&, const std::string& name, const FormatOptions&,
                            Diagnostics*) const override {
        throw Error(name + ": the 'ocio' reader does not write; pick a format with --format");
    }
};

} // namespace

std::unique_ptr<Format> makeOcioReadFormat() {
    return std::make_unique<OcioReadFormat>();
}

} // namespace lut::formats
