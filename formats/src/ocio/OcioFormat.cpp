// The OpenColorIO bridge: every LUT file OpenColorIO 2.1 reads, and every format its Baker writes.
//
// Reading: OCIO builds a processor from a FileTransform on the file (it detects the format by
// extension and content); we sample that processor on a lattice over [0,1]^3 of the size the user
// asked for, else the file's own 3D grid size (the largest Lut3DTransform in the processor), else
// 33. So anything OCIO can express (1D shapers + cubes, CDLs, matrices, ICC profiles) comes out as
// one Lut3D; the lattice points hold exactly what OCIO computes there.
//
// Writing (.spi3d, which OCIO 2.1 reads but cannot bake, is written here directly):
// a raw in-memory Config with an input space and an output space whose transform is our
// table (a Lut3DTransform, preceded by a range fit when the domain is not [0,1]), baked by OCIO's
// Baker with cube size = our size (so the baker samples exactly our lattice points), and written
// atomically. Formats that store integers (.3dl: 12-bit, 0..4095) quantise; the quantisation
// is reported by callers that read the file back (lutkit convert).
//
// .cube is deliberately not claimed: our own reader handles both .cube dialects.
// OCIO is touched only inside read()/write(): nothing here runs at start-up (no static OCIO
// objects), which keeps `lutkit info small.cube` fast.
#include "Formats.h"
#include "LutPrep.h"

#include "lut/Error.h"
#include "lut/Limits.h"
#include "lut/Parallel.h"
#include "lut/io/AtomicFile.h"
#include "lut/io/FileNames.h"
#include "lut/ops/Resample.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <sstream>

namespace lut::formats {

namespace OCIO = OCIO_NAMESPACE;

namespace {

// OCIO's messages span several lines; ours are one line each.
std::string oneLine(const char* message) {
    std::string out;
    bool space = false;
    for (const char* p = message; p && *p; ++p) {
        const bool ws = *p == '\n' || *p == '\r' || *p == '\t' || *p == ' ';
        if (ws) {
            space = !out.empty();
            continue;
        }
        if (space)
            out += ' ';
        space = false;
        out += *p;
    }
    return out;
}

// OCIO reports warnings through a global logging callback; the library must not print, so we
// collect them and hand them back as diagnostics of the read/write that produced them.
std::mutex g_logMutex;
std::vector<std::string>* g_logSink = nullptr;

void initOcio() {
    static std::once_flag once;
    std::call_once(once, [] {
        OCIO::SetLoggingFunction([](const char* message) {
            std::lock_guard lock(g_logMutex);
            if (g_logSink && message) {
                g_logSink->push_back(oneLine(message));
            }
        });
    });
}

// Serialises OCIO use (its caches and our log sink are global) and gathers its log lines.
class OcioSession {
public:
    explicit OcioSession(const std::string& path) : m_path(path) {
        initOcio();
        m_lock = std::unique_lock(s_mutex);
        std::lock_guard lock(g_logMutex);
        g_logSink = &m_log;
    }
    ~OcioSession() {
        std::lock_guard lock(g_logMutex);
        g_logSink = nullptr;
    }
    void appendDiagnostics(Diagnostics& out) {
        std::lock_guard lock(g_logMutex);
        for (const auto& m : m_log) {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Info;
            d.path = m_path;
            d.message = "OpenColorIO: " + m;
            out.push_back(std::move(d));
        }
        m_log.clear();
    }

private:
    static inline std::mutex s_mutex;
    std::unique_lock<std::mutex> m_lock;
    std::string m_path;
    std::vector<std::string> m_log;
};

Diagnostic info(const std::string& path, std::string message,
                Diagnostic::Severity severity = Diagnostic::Severity::Info) {
    Diagnostic d;
    d.severity = severity;
    d.path = path;
    d.message = std::move(message);
    return d;
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

        OcioSession session(path);
        LutFile out;
        out.format = name();
        Lut3D lut;
        try {
            // OCIO caches files by path; a file rewritten in place must be read afresh.
            OCIO::ClearAllCaches();
            auto config = OCIO::Config::CreateRaw();
            auto ft = OCIO::FileTransform::Create();
            ft->setSrc(std::filesystem::absolute(path).string().c_str());
            ft->setInterpolation(OCIO::INTERP_BEST);
            const auto processor = config->getProcessor(ft);
            const ProcessorFacts facts = inspect(processor);
            out.dialect = ocioFormatNamesFor(extensionOf(path));
            out.sourceBitDepth = facts.bitDepth;

            const auto cpu = processor->getOptimizedCPUProcessor(
                OCIO::BIT_DEPTH_F32, OCIO::BIT_DEPTH_F32, OCIO::OPTIMIZATION_NONE);
            // A file of 1D tables only (.spi1d, a 1D .csp, a Discreet .lut) stays a per-channel
            // table: sampled on its own length along the grey ramp, which for per-channel tables
            // is the whole function. Asking for --size makes it a 3D lattice like everything else.
            if (options.size == 0 && facts.lut1dCount > 0 && facts.lut3dCount == 0 &&
                facts.otherCount == 0 && !facts.halfDomain &&
                facts.length1d >= static_cast<unsigned long>(limits::kMin1DSize) &&
                facts.length1d <= static_cast<unsigned long>(limits::kMax1DSize)) {
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
            lut = Lut3D::identity(size);
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
                out.diagnostics.push_back(info(
                    path, "sampled OpenColorIO's processor (" + std::to_string(facts.lut1dCount) +
                              " 1D LUT, " + std::to_string(facts.lut3dCount) + " 3D LUT, " +
                              std::to_string(facts.otherCount) + " other ops) on a " +
                              std::to_string(size) + "^3 lattice over [0,1]"));
        } catch (const OCIO::Exception& e) {
            throw Error(path + ": OpenColorIO cannot read it: " + oneLine(e.what()));
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
                info(path, std::to_string(nonFinite) + " NaN/Inf values replaced by 0",
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

// Largest grid a Lut3DTransform accepts in OCIO 2.1.
constexpr int kOcioMaxGrid = 129;

class OcioBakeFormat final : public Format {
public:
    OcioBakeFormat(std::string name, std::string ocioName, std::string ext, std::string description,
                   int storedBits, int minSize = 2)
        : m_name(std::move(name)), m_ocioName(std::move(ocioName)), m_ext(std::move(ext)),
          m_description(std::move(description)), m_storedBits(storedBits), m_minSize(minSize) {}

    std::string name() const override { return m_name; }
    std::string description() const override { return m_description; }
    std::vector<std::string> extensions() const override { return {m_ext}; }
    // Reading goes through the one "ocio" reader, which detects the variant itself.
    bool canRead() const override { return false; }
    LutFile read(const std::string& path, const FormatOptions&) const override {
        throw Error(path + ": read it with the 'ocio' format");
    }

    Diagnostics write(const std::string& path, const LutFile& file,
                      const FormatOptions& options) const override {
        Diagnostics diags;
        if (file.shaper)
            diags.push_back(info(path, "the 1D shaper was baked into the 3D table",
                                 Diagnostic::Severity::Warning));
        Lut3D lut = file.toLut3D(options.size);
        if (lut.size() < m_minSize) {
            // A .3dl's first line lists the input lattice; with fewer than 4 entries OCIO takes it
            // for a row of values and cannot read the file back. Upsampling is exact here: the
            // finer tetrahedral lattice interpolates the coarse one's tetrahedra unchanged.
            diags.push_back(
                info(path, "a " + std::to_string(lut.size()) + "^3 table is written as " +
                               std::to_string(m_minSize) + "^3 (" + m_name + " needs at least " +
                               std::to_string(m_minSize) + " lattice points per axis)"));
            lut = resample(lut, m_minSize, Interpolation::Tetrahedral);
        }
        if (lut.size() > kOcioMaxGrid)
            throw Error(path + ": OpenColorIO writes tables up to " + std::to_string(kOcioMaxGrid) +
                        "^3; this one is " + std::to_string(lut.size()) + "^3 (use --size)");
        if (!lut.hasDefaultDomain())
            diags.push_back(info(path,
                                 "domain is not [0,1]: the table was re-sampled over [0,1] inputs",
                                 Diagnostic::Severity::Warning));
        if (m_storedBits) {
            const auto [lo, hi] = lut.valueRange();
            if (lo < 0.0f || hi > 1.0f)
                diags.push_back(info(path,
                                     "values outside [0,1] (" + std::to_string(lo) + ".." +
                                         std::to_string(hi) + ") are clipped: " + m_name +
                                         " stores " + std::to_string(m_storedBits) +
                                         "-bit integers",
                                     Diagnostic::Severity::Warning));
            else
                diags.push_back(info(path, m_name + " stores " + std::to_string(m_storedBits) +
                                               "-bit integers"));
        }

        OcioSession session(path);
        std::ostringstream os;
        try {
            const int n = lut.size();
            auto l3 = OCIO::Lut3DTransform::Create(static_cast<unsigned long>(n));
            for (int b = 0; b < n; ++b)
                for (int g = 0; g < n; ++g)
                    for (int r = 0; r < n; ++r) {
                        const glm::vec3 v = lut.at(r, g, b);
                        l3->setValue(static_cast<unsigned long>(r), static_cast<unsigned long>(g),
                                     static_cast<unsigned long>(b), v.x, v.y, v.z);
                    }
            l3->setInterpolation(OCIO::INTERP_TETRAHEDRAL);
            auto group = OCIO::GroupTransform::Create();
            if (!lut.hasDefaultDomain()) {
                // Map [0,1] inputs to the table's own lattice coordinates.
                const glm::vec3 lo = lut.domainMin(), hi = lut.domainMax();
                double oldMin[4] = {lo.x, lo.y, lo.z, 0.0}, oldMax[4] = {hi.x, hi.y, hi.z, 1.0};
                double newMin[4] = {0, 0, 0, 0}, newMax[4] = {1, 1, 1, 1};
                double m44[16], offset4[4];
                OCIO::MatrixTransform::Fit(m44, offset4, oldMin, oldMax, newMin, newMax);
                auto mt = OCIO::MatrixTransform::Create();
                mt->setMatrix(m44);
                mt->setOffset(offset4);
                group->appendTransform(mt);
            }
            group->appendTransform(l3);

            auto config = OCIO::Config::CreateRaw()->createEditableCopy();
            auto in = OCIO::ColorSpace::Create();
            in->setName("lutkit_in");
            config->addColorSpace(in);
            auto outCs = OCIO::ColorSpace::Create();
            outCs->setName("lutkit_out");
            outCs->setTransform(group, OCIO::COLORSPACE_DIR_FROM_REFERENCE);
            config->addColorSpace(outCs);

            auto baker = OCIO::Baker::Create();
            baker->setConfig(config);
            baker->setFormat(m_ocioName.c_str());
            baker->setInputSpace("lutkit_in");
            baker->setTargetSpace("lutkit_out");
            baker->setCubeSize(n);
            auto& md = baker->getFormatMetadata();
            if (!lut.title().empty()) {
                md.addAttribute(OCIO::METADATA_NAME, lut.title().c_str());
                md.addChildElement(OCIO::METADATA_DESCRIPTION, lut.title().c_str());
            }
            for (const auto& c : lut.comments())
                if (!c.empty())
                    md.addChildElement(OCIO::METADATA_DESCRIPTION, c.c_str());
            baker->bake(os);
        } catch (const OCIO::Exception& e) {
            throw Error(path + ": OpenColorIO cannot write " + m_name + ": " + oneLine(e.what()));
        }
        writeFileAtomically(path, os.str());
        session.appendDiagnostics(diags);
        return diags;
    }

    int storedBitDepth() const override { return m_storedBits; }

private:
    std::string m_name, m_ocioName, m_ext, m_description;
    int m_storedBits;
    int m_minSize;
};

// Sony Pictures Imageworks .spi3d: OCIO 2.1 reads it but its Baker cannot write it, so we
// write it ourselves ("SPILUT 1.0", "3 3", "N N N", then one "r g b  R G B" line per lattice
// point with its indices; no domain, no shaper) and read it back through OCIO like the rest.
class Spi3dFormat final : public Format {
public:
    std::string name() const override { return "spi3d"; }
    std::string description() const override {
        return "Sony Imageworks .spi3d (written here, read via OpenColorIO)";
    }
    std::vector<std::string> extensions() const override { return {".spi3d"}; }
    bool canRead() const override { return false; }
    LutFile read(const std::string& path, const FormatOptions&) const override {
        throw Error(path + ": read it with the 'ocio' format");
    }
    Diagnostics write(const std::string& path, const LutFile& file,
                      const FormatOptions& options) const override {
        Diagnostics diags;
        const Lut3D lut = prepareUnitLut(file, options.size, path, diags);
        const int n = lut.size();
        std::string text = "SPILUT 1.0\n3 3\n" + std::to_string(n) + " " + std::to_string(n) + " " +
                           std::to_string(n) + "\n";
        text.reserve(text.size() + static_cast<std::size_t>(n) * n * n * 48);
        char buf[160];
        for (int r = 0; r < n; ++r)
            for (int g = 0; g < n; ++g)
                for (int b = 0; b < n; ++b) {
                    const glm::vec3 v = lut.at(r, g, b);
                    // %.9g: every float reads back as itself.
                    std::snprintf(buf, sizeof buf, "%d %d %d %.9g %.9g %.9g\n", r, g, b,
                                  double(v.x), double(v.y), double(v.z));
                    text += buf;
                }
        writeFileAtomically(path, text);
        return diags;
    }
};

} // namespace

std::unique_ptr<Format> makeOcioReadFormat() {
    return std::make_unique<OcioReadFormat>();
}

std::vector<std::unique_ptr<Format>> makeOcioBakeFormats() {
    std::vector<std::unique_ptr<Format>> v;
    // Order matters where two share an extension: the first is the default writer (.3dl -> flame).
    v.push_back(std::make_unique<OcioBakeFormat>(
        "flame", "flame", ".3dl", "Autodesk Flame .3dl (12-bit integers), via OpenColorIO", 12, 4));
    v.push_back(std::make_unique<OcioBakeFormat>(
        "lustre", "lustre", ".3dl", "Autodesk Lustre .3dl (12-bit integers), via OpenColorIO", 12,
        4));
    v.push_back(std::make_unique<OcioBakeFormat>("csp", "cinespace", ".csp",
                                                 "Cinespace .csp, via OpenColorIO", 0));
    v.push_back(
        std::make_unique<OcioBakeFormat>("clf", "Academy/ASC Common LUT Format", ".clf",
                                         "Academy/ASC Common LUT Format .clf, via OpenColorIO", 0));
    v.push_back(std::make_unique<OcioBakeFormat>(
        "ctf", "Color Transform Format", ".ctf",
        "Autodesk Color Transform Format .ctf, via OpenColorIO", 0));
    v.push_back(std::make_unique<OcioBakeFormat>("cub", "truelight", ".cub",
                                                 "Truelight .cub, via OpenColorIO", 0));
    v.push_back(std::make_unique<OcioBakeFormat>("itx", "iridas_itx", ".itx",
                                                 "Iridas .itx, via OpenColorIO", 0));
    v.push_back(std::make_unique<Spi3dFormat>());
    v.push_back(std::make_unique<OcioBakeFormat>("houdini", "houdini", ".lut",
                                                 "Houdini .lut, via OpenColorIO", 0));
    return v;
}

} // namespace lut::formats
