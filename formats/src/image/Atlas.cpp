// SPDX-License-Identifier: Apache-2.0
// lutkit atlas: LUTs as the rows of one picture and back (lut/formats/Atlas.h).
#include "lut/formats/Atlas.h"

#include "LutPrep.h"
#include "image/LayoutScore.h"

#include "lut/Error.h"
#include "lut/Quantize.h"
#include "lut/formats/ImageIO.h"
#include "lut/formats/Registry.h"
#include "lut/io/InputFile.h"
#include "lut/io/ProtectInputs.h"
#include "lut/ops/Resample.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace lut::formats {

namespace {

using S = Diagnostic::Severity;

std::string rowName(int k, const std::string& source) {
    return "row " + std::to_string(k) + " (" + (source.empty() ? "neutral" : source) + ")";
}

// The 8-bit values a row stores (what the picture holds), and the storage error.
std::vector<std::uint8_t> stored8(const Lut3D& row, AtlasRowReport& report) {
    std::vector<std::uint8_t> out;
    out.reserve(row.entryCount() * 3);
    ErrorAccumulator acc;
    for (const glm::vec3& v : row.entries())
        for (int c = 0; c < 3; ++c) {
            const std::uint8_t q = toUnorm8(v[c]);
            if (!(v[c] >= 0.0f && v[c] <= 1.0f))
                ++report.clamped;
            acc.add(v[c] == v[c] ? v[c] : 0.0f, q / 255.0);
            out.push_back(q);
        }
    report.storage = acc.result();
    return out;
}

bool storesNeutral(const std::vector<std::uint8_t>& values, int n) {
    std::size_t i = 0;
    for (int b = 0; b < n; ++b)
        for (int g = 0; g < n; ++g)
            for (int r = 0; r < n; ++r)
                for (const int x : {r, g, b})
                    if (values[i++] != toUnorm8(static_cast<float>(x) / static_cast<float>(n - 1)))
                        return false;
    return true;
}

LutLayout defaultRowLayout(int n) {
    return n == layoutFixedSize(LutLayout::Reshade) ? LutLayout::Reshade : LutLayout::Pilot;
}

// buildAtlas over LUTs named `inputs` (files, or what stands for them), the k-th read by read(k)
// when its turn comes: a bad file is reported after the rows before it were checked.
AtlasBuildReport buildRows(const std::vector<std::string>& inputs,
                           const std::function<LutFile(std::size_t k)>& read,
                           const std::string& output, const AtlasBuildOptions& options) {
    // Every row as a table over 0..1 at its own size, then at the atlas's N.
    struct Row {
        Lut3D lut;
        AtlasRowReport report;
    };
    std::vector<Row> rows;
    const int first = options.neutralFirst ? 1 : 0; // the row of the first file
    int n = options.size ? options.size : layoutFixedSize(options.layout);
    for (const std::string& path : inputs) {
        Row r;
        r.report.source = path;
        const int k = first + static_cast<int>(rows.size());
        const LutFile file = read(rows.size());
        r.report.diagnostics = file.diagnostics;
        // An atlas row is applied by an engine to its picture as it is: the game's LUT (made
        // for Smash Ultimate's brighten pass) would show brighter than its edit there.
        if (const PurposeDecision d = decidePurpose(file, std::nullopt);
            d.purpose == LutPurpose::Smash)
            r.report.diagnostics.push_back(
                {Diagnostic::Severity::Warning, path, 0, 0,
                 "what it is for: " + d.text("") +
                     ", made for Smash Ultimate's brighten pass; the row stores it as it is "
                     "and an engine applying it shows it brighter (`lutkit convert " +
                     path + " edit.cube --target raw` gives the edit it makes)"});
        Lut3D table = prepareUnitLut(file, 0, path, r.report.diagnostics);
        r.report.sourceSize = table.size();
        if (n == 0)
            n = table.size(); // the first file's size, when nothing asked for one
        if (table.size() != n) {
            if (!options.size && !layoutFixedSize(options.layout))
                throw Error(rowName(k, path) + " is " + std::to_string(table.size()) +
                            "^3, the atlas's rows are " + std::to_string(n) + "^3 as " +
                            rowName(first, inputs.front()) +
                            ": give --size N to resample every row to N^3");
            ResampleResult rs = resampleWithError(table, n, options.interp);
            r.report.resample = rs.error;
            table = std::move(rs.lut);
        }
        r.lut = std::move(table);
        rows.push_back(std::move(r));
    }
    if (options.neutralFirst) {
        Row r;
        r.lut = Lut3D::identity(n);
        r.report.sourceSize = n;
        rows.insert(rows.begin(), std::move(r));
    }
    if (const std::string problem = layoutSizeProblem(options.layout, n); !problem.empty())
        throw Error(problem);

    // What each row stores; the same values twice is one LUT twice.
    std::vector<std::vector<std::uint8_t>> stored;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        stored.push_back(stored8(rows[k].lut, rows[k].report));
        rows[k].report.neutral = storesNeutral(stored.back(), n);
        for (std::size_t j = 0; j < k; ++j)
            if (stored[j] == stored[k])
                throw Error(rowName(static_cast<int>(k), rows[k].report.source) +
                            " stores the same LUT as " +
                            rowName(static_cast<int>(j), rows[j].report.source) +
                            " (every 8-bit value equal): an atlas holds each LUT once");
    }

    std::vector<Lut3D> tables;
    AtlasBuildReport report;
    for (Row& r : rows) {
        tables.push_back(std::move(r.lut));
        report.rows.push_back(std::move(r.report));
    }
    const Image picture = atlasImage(tables, options.layout);
    ImageWriteOptions wo(8, false, true);
    wo.format = "png"; // standard output ("-") and devices: a PNG, what MultiLUT reads
    writeImage(output, picture, wo);
    report.shape = {options.layout, n, static_cast<int>(tables.size())};
    return report;
}

void checkAtlasRequest(std::size_t count, const AtlasBuildOptions& options) {
    if (count == 0)
        throw Error("an atlas needs at least one LUT");
    if (options.layout == LutLayout::Hald)
        (void)atlasShape(1024, 32, options.layout); // the same refusal as every atlas
}

} // namespace

AtlasBuildReport buildAtlas(const std::vector<std::string>& inputs, const std::string& output,
                            const AtlasBuildOptions& options) {
    checkAtlasRequest(inputs.size(), options);
    checkNotOverwritingInputs(output, inputs);
    registerBuiltinFormats();
    return buildRows(
        inputs, [&](std::size_t k) { return readLut(inputs[k], options.read); }, output, options);
}

AtlasBuildReport buildAtlas(const std::vector<AtlasInput>& luts, const std::string& output,
                            const AtlasBuildOptions& options) {
    checkAtlasRequest(luts.size(), options);
    registerBuiltinFormats();
    std::vector<std::string> names;
    for (const AtlasInput& in : luts)
        names.push_back(in.name);
    return buildRows(
        names, [&](std::size_t k) { return luts[k].lut; }, output, options);
}

namespace {

// The picture's atlas rows in order, each an n-row band of float RGBA (the codec's chunks of
// rows gathered), to `band`: the memory of one row of the atlas, not of the picture.
void forEachBand(const std::string& path, const AtlasShape& shape,
                 const std::function<void(int k, const ImageView& band)>& band) {
    const int n = shape.size;
    Image rows(n * n, n);
    int filled = 0, k = 0;
    (void)readImageRows(path, [&](const ImageView& chunk, int) {
        for (int y = 0; y < chunk.height; ++y) {
            if (chunk.width != rows.width())
                throw Error(path + ": the picture changed while it was read");
            std::copy_n(chunk.row(y), 4 * static_cast<std::size_t>(chunk.width),
                        rows.pixel(0, filled));
            if (++filled == n) {
                band(k++, rows.view());
                filled = 0;
            }
        }
    });
    if (k != shape.rows || filled != 0)
        throw Error(path + ": the picture changed while it was read");
}

// Two 64-bit FNV-1a hashes (different offsets) of a row's stored bytes.
std::pair<std::uint64_t, std::uint64_t> rowHash(const std::vector<std::uint8_t>& bytes) {
    std::uint64_t a = 14695981039346656037ull, b = 0x9e3779b97f4a7c15ull;
    for (const std::uint8_t v : bytes) {
        a = (a ^ v) * 1099511628211ull;
        b = (b ^ (v + 0x5bu)) * 0x100000001b3ull;
        b ^= b >> 29;
    }
    return {a, b};
}

} // namespace

AtlasReading readAtlas(const std::string& path, std::optional<LutLayout> layout) {
    checkRegularInput(path);
    const ImageInfo header = readImageInfo(path);
    AtlasReading out;
    out.width = header.width;
    out.height = header.height;
    try {
        out.shape = atlasShape(header.width, header.height, layout.value_or(LutLayout::Pilot));
    } catch (const Error& e) {
        throw Error(path + ": " + e.what());
    }
    const int n = out.shape.size, rows = out.shape.rows;
    if (layout) {
        out.layoutReason = "given";
    } else {
        // The placements an N^2 x N strip can have; the rows vote.
        std::vector<LayoutFit> fits;
        for (const LayoutFit& f : layoutsForImageSize(n * n, n))
            if (f.layout != LutLayout::Hald)
                fits.push_back(f);
        std::vector<int> votes(fits.size(), 0);
        forEachBand(path, out.shape, [&](int, const ImageView& band) {
            for (std::size_t i = 0; i < fits.size(); ++i)
                if (axisScore(atlasRow(band, {fits[i].layout, n, 1}, 0)).followsAxes())
                    ++votes[i];
        });
        std::string table;
        for (std::size_t i = 0; i < fits.size(); ++i)
            table += (table.empty() ? "" : ", ") + std::string(toString(fits[i].layout)) + " " +
                     std::to_string(votes[i]);
        const int best = *std::max_element(votes.begin(), votes.end());
        const long winners = std::count(votes.begin(), votes.end(), best);
        const std::string counted = "rows whose output channels follow their own inputs, of " +
                                    std::to_string(rows) + ": " + table;
        LutLayout chosen = defaultRowLayout(n);
        if (best > 0 && winners == 1) {
            chosen = fits[static_cast<std::size_t>(std::find(votes.begin(), votes.end(), best) -
                                                   votes.begin())]
                         .layout;
            out.layoutReason = "detected: " + counted;
        } else {
            const auto def = std::find_if(fits.begin(), fits.end(),
                                          [&](const LayoutFit& f) { return f.layout == chosen; });
            if (best > 0 && votes[static_cast<std::size_t>(def - fits.begin())] != best)
                throw Error(path + ": the atlas's layout is not clear (" + counted +
                            "); name it with --in-layout");
            out.layoutReason = "the default, not detectable: " + counted;
            out.diagnostics.push_back(makeDiagnostic(
                S::Warning, path,
                std::string("layout not detectable (") + counted + "); read as " +
                    toString(chosen) + "; name it with --in-layout if it is another"));
        }
        out.shape.layout = chosen;
    }
    // Each row's stored values by their hash, and the first row that held them.
    std::map<std::pair<std::uint64_t, std::uint64_t>, int> seen;
    forEachAtlasRow(path, out, [&](int k, const Lut3D& row) {
        AtlasRowReport scratch;
        const auto [first, fresh] = seen.emplace(rowHash(stored8(row, scratch)), k);
        if (!fresh)
            out.duplicates.emplace_back(k, first->second);
        out.neutral.push_back(row.maxDeviationFromIdentity() <= 0.5f / 255.0f + 1e-6f);
    });
    return out;
}

void forEachAtlasRow(const std::string& path, const AtlasReading& atlas,
                     const std::function<void(int index, const Lut3D& row)>& row) {
    const AtlasShape one{atlas.shape.layout, atlas.shape.size, 1};
    forEachBand(path, atlas.shape,
                [&](int k, const ImageView& band) { row(k, atlasRow(band, one, 0)); });
}

} // namespace lut::formats
