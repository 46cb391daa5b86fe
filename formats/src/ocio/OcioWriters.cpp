// SPDX-License-Identifier: Apache-2.0
// The OpenColorIO writers: every format OCIO's Baker writes.
//
// A raw in-memory Config with an input space and an output space whose transform is our table (a
// Lut3DTransform, preceded by a range fit when the domain is not [0,1]), baked by OCIO's Baker
// with cube size = our size (so the baker samples exactly our lattice points), and written
// atomically. Formats that store integers (.3dl: 12-bit, 0..4095) quantise; the quantisation is
// reported by callers that read the file back (lutkit convert). Reading goes through the one
// "ocio" reader (OcioReader.cpp). .spi3d, which OCIO 2.1 reads but cannot bake, is written and
// read by lutkit (spi3d/Spi3dFormat.cpp).
//
// Formats that hold a shaper keep it, and keep an input range other than [0,1]: .clf and .ctf are
// written as the transforms themselves (range Matrix, Lut1D, Lut3D) by OCIO's GroupTransform
// writer (OCIO's Baker would resample them); .csp gets a prelut written by hand (CspWriter.cpp),
// since the Baker derives its prelut from a colour space, never from a table it is given. Each
// format also answers to OCIO's own name for it (ociobakelut --format cinespace, truelight ...).
#include "Formats.h"
#include "ocio/CspWriter.h"
#include "ocio/OcioLut3D.h"
#include "ocio/OcioSession.h"

#include "lut/Error.h"
#include "lut/ErrorStats.h"
#include "lut/io/Format.h"
#include "lut/ops/Resample.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace lut::formats {

namespace {

// Largest grid a Lut3DTransform accepts in OCIO 2.1.
constexpr int kOcioMaxGrid = 129;

// A Matrix that maps [lo, hi] onto [0,1] per channel.
OCIO::MatrixTransformRcPtr rangeMatrix(glm::vec3 lo, glm::vec3 hi) {
    double oldMin[4] = {lo.x, lo.y, lo.z, 0.0}, oldMax[4] = {hi.x, hi.y, hi.z, 1.0};
    double newMin[4] = {0, 0, 0, 0}, newMax[4] = {1, 1, 1, 1};
    double m44[16], offset4[4];
    OCIO::MatrixTransform::Fit(m44, offset4, oldMin, oldMax, newMin, newMax);
    auto mt = OCIO::MatrixTransform::Create();
    mt->setMatrix(m44);
    mt->setOffset(offset4);
    return mt;
}

class OcioBakeFormat final : public Format {
public:
    enum class Shaper { None, Transforms, Csp };
    // Where the file says what its LUT is for (lut/LutPurpose.h): OCIO's metadata (.clf, .ctf:
    // a Description; .csp: its METADATA block), a "#" comment line lutkit adds before the baked
    // bytes (.3dl, .itx: comments their readers skip, OpenColorIO's too), or nowhere (.cub's
    // "#" lines are its keywords, Houdini's .lut has no comments).
    enum class PurposePlace { None, Metadata, Comment };
    OcioBakeFormat(std::string name, std::string ocioName, std::string ext, std::string description,
                   int storedBits, int minSize = 2, std::vector<FormatAlias> aliases = {},
                   Shaper shaper = Shaper::None, PurposePlace purposePlace = PurposePlace::None)
        : m_name(std::move(name)), m_ocioName(std::move(ocioName)), m_ext(std::move(ext)),
          m_description(std::move(description)), m_storedBits(storedBits), m_minSize(minSize),
          m_aliases(std::move(aliases)), m_shaper(shaper), m_purposePlace(purposePlace) {}

    std::string name() const override { return m_name; }
    std::vector<FormatAlias> aliases() const override { return m_aliases; }
    bool holdsShaper() const override { return m_shaper != Shaper::None; }
    bool keepsPurpose(const std::string&, LutPurpose) const override {
        return m_purposePlace != PurposePlace::None;
    }
    std::string description() const override { return m_description; }
    std::vector<std::string> extensions() const override { return {m_ext}; }
    // Reading goes through the one "ocio" reader, which detects the variant itself.
    bool canRead() const override { return false; }
    // Refused before the file is opened, as from bytes.
    LutFile read(const std::string& path, const FormatOptions& options) const override {
        return readMemory({}, path, options);
    }
    LutFile readMemory(std::string_view, const std::string& name,
                       const FormatOptions&) const override {
        throw Error(name + ": read it with the 'ocio' format");
    }

    // Every writer makes its bytes in memory (OCIO's Baker and GroupTransform write to a
    // stream); write() puts them on disk atomically.
    std::string writeMemory(const LutFile& file, const std::string& path,
                            const FormatOptions& options, Diagnostics* diagnostics) const override {
        Diagnostics diags;
        std::string bytes = encode(file, path, options, diags);
        if (file.purpose && m_purposePlace == PurposePlace::Comment)
            bytes = "# " + purposeTag(*file.purpose) + "\n" + bytes;
        if (diagnostics)
            *diagnostics = std::move(diags);
        return bytes;
    }

    int storedBitDepth() const override { return m_storedBits; }

private:
    std::string encode(const LutFile& file, const std::string& path, const FormatOptions& options,
                       Diagnostics& diags) const {
        const bool plain = !file.shaper && file.cube && file.cube->hasDefaultDomain();
        if (m_shaper == Shaper::Transforms && !plain)
            return transformsBytes(path, file, options, diags);
        if (m_shaper == Shaper::Csp && !plain)
            return cspWithShaperBytes(path, file, options.size, diags);
        if (file.shaper)
            diags.push_back(ocioDiagnostic(path, "the 1D shaper was baked into the 3D table",
                                           Diagnostic::Severity::Warning));
        Lut3D lut = file.toLut3D(options.size);
        if (lut.size() < m_minSize) {
            // A .3dl's first line lists the input lattice; with fewer than 4 entries OCIO takes it
            // for a row of values and cannot read the file back. Upsampling is exact here: the
            // finer tetrahedral lattice interpolates the coarse one's tetrahedra unchanged.
            diags.push_back(ocioDiagnostic(
                path, "a " + std::to_string(lut.size()) + "^3 table is written as " +
                          std::to_string(m_minSize) + "^3 (" + m_name + " needs at least " +
                          std::to_string(m_minSize) + " lattice points per axis)"));
            lut = resample(lut, m_minSize, Interpolation::Tetrahedral);
        }
        if (lut.size() > kOcioMaxGrid)
            throw Error(path + ": OpenColorIO writes tables up to " + std::to_string(kOcioMaxGrid) +
                        "^3; this one is " + std::to_string(lut.size()) + "^3 (use --size)");
        if (!lut.hasDefaultDomain())
            diags.push_back(ocioDiagnostic(
                path, "domain is not [0,1]: the table was re-sampled over [0,1] inputs",
                Diagnostic::Severity::Warning));
        if (m_storedBits) {
            const auto [lo, hi] = lut.valueRange();
            if (lo < 0.0f || hi > 1.0f)
                diags.push_back(ocioDiagnostic(path,
                                               "values outside [0,1] (" + std::to_string(lo) +
                                                   ".." + std::to_string(hi) +
                                                   ") are clipped: " + m_name + " stores " +
                                                   std::to_string(m_storedBits) + "-bit integers",
                                               Diagnostic::Severity::Warning));
            // What storing integers costs: every entry against its stored code (the clip
            // included), exact over every input (interpolation blends entries).
            const double scale = std::ldexp(1.0, m_storedBits) - 1.0;
            ErrorAccumulator acc;
            for (const glm::vec3& v : lut.entries())
                for (int c = 0; c < 3; ++c)
                    if (std::isfinite(v[c]))
                        acc.add(std::round(std::clamp(double(v[c]), 0.0, 1.0) * scale) / scale,
                                v[c]);
            diags.push_back(ocioDiagnostic(path, m_name + " stores " +
                                                     std::to_string(m_storedBits) +
                                                     "-bit integers: " + acc.result().str()));
        }

        OcioSession session(path);
        std::ostringstream os;
        try {
            const int n = lut.size();
            auto l3 = makeLut3DTransform(lut, OCIO::INTERP_TETRAHEDRAL);
            auto group = OCIO::GroupTransform::Create();
            if (!lut.hasDefaultDomain()) {
                // Map [0,1] inputs to the table's own lattice coordinates.
                group->appendTransform(rangeMatrix(lut.domainMin(), lut.domainMax()));
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
            if (file.purpose)
                md.addChildElement(OCIO::METADATA_DESCRIPTION, purposeTag(*file.purpose).c_str());
            for (const auto& c : lut.comments())
                if (!c.empty())
                    md.addChildElement(OCIO::METADATA_DESCRIPTION, c.c_str());
            baker->bake(os);
        } catch (const Error&) {
            throw;
        } catch (const std::exception& e) {
            // OCIO::Exception, and C++ library errors from inside OCIO (std::bad_alloc...).
            throw Error(path + ": OpenColorIO cannot write " + m_name + ": " +
                        ocioMessage(e.what()));
        }
        session.appendDiagnostics(diags);
        return os.str();
    }

    // .clf/.ctf: [range Matrix] [Lut1D] [range Matrix] Lut3D, exactly the LutFile.
    std::string transformsBytes(const std::string& path, const LutFile& file,
                                const FormatOptions& options, Diagnostics& diags) const;

    std::string m_name, m_ocioName, m_ext, m_description;
    int m_storedBits;
    int m_minSize;
    std::vector<FormatAlias> m_aliases;
    Shaper m_shaper;
    PurposePlace m_purposePlace;
};

std::string OcioBakeFormat::transformsBytes(const std::string& path, const LutFile& file,
                                            const FormatOptions& options,
                                            Diagnostics& diags) const {
    std::optional<Lut3D> cube = file.cube;
    if (cube && options.size != 0 && options.size != cube->size()) {
        diags.push_back(
            ocioDiagnostic(path, "3D table resampled from " + std::to_string(cube->size()) +
                                     "^3 to " + std::to_string(options.size) + "^3 (tetrahedral)"));
        Lut3D r = resample(*cube, options.size, Interpolation::Tetrahedral);
        r.setDomain(cube->domainMin(), cube->domainMax());
        cube = std::move(r);
    }
    if (cube && cube->size() > kOcioMaxGrid)
        throw Error(path + ": OpenColorIO writes tables up to " + std::to_string(kOcioMaxGrid) +
                    "^3; this one is " + std::to_string(cube->size()) + "^3 (use --size)");
    OcioSession session(path);
    std::ostringstream os;
    try {
        auto group = OCIO::GroupTransform::Create();
        const std::string title = cube ? cube->title() : file.shaper->title();
        auto& md = group->getFormatMetadata();
        md.addAttribute(OCIO::METADATA_ID, "lutkit");
        if (!title.empty()) {
            md.addAttribute(OCIO::METADATA_NAME, title.c_str());
            md.addChildElement(OCIO::METADATA_DESCRIPTION, title.c_str());
        }
        if (file.purpose)
            md.addChildElement(OCIO::METADATA_DESCRIPTION, purposeTag(*file.purpose).c_str());
        if (cube)
            for (const auto& c : cube->comments())
                if (!c.empty())
                    md.addChildElement(OCIO::METADATA_DESCRIPTION, c.c_str());
        if (file.shaper) {
            const Lut1D& sh = *file.shaper;
            if (sh.domainMin() != glm::vec3(0.0f) || sh.domainMax() != glm::vec3(1.0f))
                group->appendTransform(rangeMatrix(sh.domainMin(), sh.domainMax()));
            auto l1 = OCIO::Lut1DTransform::Create(static_cast<unsigned long>(sh.size()), false);
            for (int i = 0; i < sh.size(); ++i)
                l1->setValue(static_cast<unsigned long>(i), sh[i].x, sh[i].y, sh[i].z);
            l1->setInterpolation(OCIO::INTERP_LINEAR);
            group->appendTransform(l1);
        }
        if (cube) {
            if (!cube->hasDefaultDomain())
                group->appendTransform(rangeMatrix(cube->domainMin(), cube->domainMax()));
            group->appendTransform(makeLut3DTransform(*cube, OCIO::INTERP_TETRAHEDRAL));
        }
        group->write(OCIO::Config::CreateRaw(), m_ocioName.c_str(), os);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        throw Error(path + ": OpenColorIO cannot write " + m_name + ": " + ocioMessage(e.what()));
    }
    session.appendDiagnostics(diags);
    return os.str();
}

} // namespace

std::vector<std::unique_ptr<Format>> makeOcioBakeFormats() {
    std::vector<std::unique_ptr<Format>> v;
    // Order matters where two share an extension: the first is the default writer (.3dl -> flame).
    using S = OcioBakeFormat::Shaper;
    using P = OcioBakeFormat::PurposePlace;
    v.push_back(std::make_unique<OcioBakeFormat>(
        "flame", "flame", ".3dl", "Autodesk Flame .3dl (12-bit integers), via OpenColorIO", 12, 4,
        std::vector<FormatAlias>{{"3dl", "", ""}}, S::None, P::Comment));
    v.push_back(std::make_unique<OcioBakeFormat>(
        "lustre", "lustre", ".3dl", "Autodesk Lustre .3dl (12-bit integers), via OpenColorIO", 12,
        4, std::vector<FormatAlias>{}, S::None, P::Comment));
    v.push_back(std::make_unique<OcioBakeFormat>(
        "csp", "cinespace", ".csp", "Cinespace .csp (with its prelut), via OpenColorIO", 0, 2,
        std::vector<FormatAlias>{{"cinespace", "", ""}}, S::Csp, P::Metadata));
    v.push_back(std::make_unique<OcioBakeFormat>(
        "clf", "Academy/ASC Common LUT Format", ".clf",
        "Academy/ASC Common LUT Format .clf (shaper kept), via OpenColorIO", 0, 2,
        std::vector<FormatAlias>{{"Academy/ASC Common LUT Format", "", ""}}, S::Transforms,
        P::Metadata));
    v.push_back(std::make_unique<OcioBakeFormat>(
        "ctf", "Color Transform Format", ".ctf",
        "Autodesk Color Transform Format .ctf (shaper kept), via OpenColorIO", 0, 2,
        std::vector<FormatAlias>{{"Color Transform Format", "", ""}}, S::Transforms, P::Metadata));
    v.push_back(std::make_unique<OcioBakeFormat>("cub", "truelight", ".cub",
                                                 "Truelight .cub, via OpenColorIO", 0, 2,
                                                 std::vector<FormatAlias>{{"truelight", "", ""}}));
    v.push_back(std::make_unique<OcioBakeFormat>(
        "itx", "iridas_itx", ".itx", "Iridas .itx, via OpenColorIO", 0, 2,
        std::vector<FormatAlias>{{"iridas_itx", "", ""}}, S::None, P::Comment));
    v.push_back(std::make_unique<OcioBakeFormat>("houdini", "houdini", ".lut",
                                                 "Houdini .lut, via OpenColorIO", 0));
    return v;
}

} // namespace lut::formats
