// SPDX-License-Identifier: Apache-2.0
#include "AtlasExport.h"

#include "lut/LutFile.h"
#include "lut/formats/Atlas.h"
#include "lut/formats/Registry.h"

#include <QFileInfo>

#include <optional>
#include <string>
#include <vector>

namespace lut::gui {

AtlasExportResult exportAtlasRow(const Lut3D& table, LutPurpose purpose, const QString& path,
                                 LutLayout layout) {
    const std::string out = path.toStdString();
    // The rows in memory, each named in messages as what it is: the atlas's file for the rows it
    // holds, "the export" for the new one.
    std::vector<formats::AtlasInput> rows;
    auto addRow = [&rows](const Lut3D& lut, std::optional<LutPurpose> p, std::string name) {
        formats::AtlasInput row;
        row.lut.cube = lut;
        row.lut.purpose = p;
        row.name = std::move(name);
        rows.push_back(std::move(row));
    };
    formats::AtlasBuildOptions o;
    o.layout = layout;
    if (QFileInfo::exists(path)) {
        // The rows it holds, as they are stored (8-bit values), then the new one; the atlas's N
        // and layout stay.
        const formats::AtlasReading a = formats::readAtlas(out, layout);
        o.size = a.shape.size;
        formats::forEachAtlasRow(out, a,
                                 [&](int, const Lut3D& row) { addRow(row, LutPurpose::Raw, out); });
    } else {
        o.neutralFirst = true;
    }
    addRow(table, purpose, "the export");
    formats::AtlasBuildReport report;
    try {
        report = formats::buildAtlas(rows, out, o);
    } catch (const Error& e) {
        throw Error(out + ": " + e.what());
    }
    AtlasExportResult r;
    r.rows = report.shape.rows;
    r.row = r.rows - 1;
    r.size = report.shape.size;
    // What the library said of the new row, said of the export's file.
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
