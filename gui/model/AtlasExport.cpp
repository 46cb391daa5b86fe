// SPDX-License-Identifier: Apache-2.0
#include "AtlasExport.h"

#include "lut/LutFile.h"
#include "lut/formats/Atlas.h"
#include "lut/formats/Registry.h"

#include <QFileInfo>
#include <QTemporaryDir>

#include <string>
#include <vector>

namespace lut::gui {

AtlasExportResult exportAtlasRow(const Lut3D& table, LutPurpose purpose, const QString& path,
                                 LutLayout layout) {
    formats::registerBuiltinFormats();
    QTemporaryDir dir;
    if (!dir.isValid())
        throw Error("cannot make a temporary folder for the atlas's rows");
    auto writeRow = [&dir](const Lut3D& lut, std::optional<LutPurpose> p, int k) {
        LutFile f;
        f.cube = lut;
        f.purpose = p;
        const std::string file = dir.filePath(QStringLiteral("row%1.cube").arg(k)).toStdString();
        formats::writeLut(file, f, {}, "cube");
        return file;
    };
    const std::string out = path.toStdString();
    std::vector<std::string> inputs;
    formats::AtlasBuildOptions o;
    o.layout = layout;
    const bool exists = QFileInfo::exists(path);
    if (exists) {
        // The rows it holds, as they are stored (8-bit values: they round-trip exactly), then
        // the new one; the atlas's N and layout stay.
        const formats::AtlasReading a = formats::readAtlas(out, layout);
        o.size = a.shape.size;
        formats::forEachAtlasRow(out, a, [&](int k, const Lut3D& row) {
            inputs.push_back(writeRow(row, LutPurpose::Raw, k));
        });
    } else {
        o.neutralFirst = true;
    }
    inputs.push_back(writeRow(table, purpose, static_cast<int>(inputs.size())));
    formats::AtlasBuildReport report;
    try {
        report = formats::buildAtlas(inputs, out, o);
    } catch (const Error& e) {
        // The rows' temporary files named as what they are: the export, or the atlas's rows.
        std::string m = e.what();
        for (std::size_t k = 0; k < inputs.size(); ++k) {
            const std::string by = k + 1 == inputs.size() ? "the export" : out;
            for (std::size_t at; (at = m.find(inputs[k])) != std::string::npos;)
                m.replace(at, inputs[k].size(), by);
        }
        throw Error(out + ": " + m);
    }
    AtlasExportResult r;
    r.rows = report.shape.rows;
    r.row = r.rows - 1;
    r.size = report.shape.size;
    // What the library said of the new row, its temporary file named as the export.
    const formats::AtlasRowReport& last = report.rows.back();
    for (Diagnostic d : last.diagnostics) {
        d.path = out;
        r.diagnostics.push_back(std::move(d));
    }
    std::string what = "row " + std::to_string(r.row) + " of " + std::to_string(r.rows) + " (" +
                       std::to_string(r.size) + "^3, " + toString(layout) + " layout)";
    if (last.resample)
        what += ", resampled to " + std::to_string(r.size) + "^3: " + last.resample->str() +
                (last.resample->bounded ? " (" + last.resample->coverage() + ")" : std::string());
    what += "; 8-bit storage: " + last.storage.str();
    r.diagnostics.push_back({Diagnostic::Severity::Info, out, 0, 0, "the LUT added as " + what});
    return r;
}

} // namespace lut::gui
