// SPDX-License-Identifier: Apache-2.0
#include "ExportTarget.h"

#include "lut/Error.h"
#include "lut/formats/LutDestination.h"
#include "lut/formats/Registry.h"
#include "lut/io/FormatRegistry.h"
#include "lut/smash/PurposeConversion.h"

namespace lut::gui {

namespace {

// A target's file type is the editor's choice; what the file is for and its lattice are the
// library's one rule for where a LUT goes (lut/formats/LutDestination.h, as lutkit convert and
// neutral resolve them): the game's LUT in the game's format, else an edit (the editor exports
// its document's edit); the size the format fixes (a .nutexb's 16^3), else 16^3 for a LUT image,
// else the document's.
ExportTargetInfo target(ExportTarget id, std::string key, std::string label, std::string format,
                        std::optional<LutLayout> layout, std::string extension, int bitDepth) {
    formats::LutDestinationRequest request;
    request.path = "export" + extension;
    request.format = format;
    request.layout = layout;
    const formats::LutDestination d = formats::resolveLutDestination(request);
    return {id,
            std::move(key),
            std::move(label),
            std::move(format),
            layout,
            std::move(extension),
            d.newTableSize(0),
            bitDepth,
            d.purposeFor(LutPurpose::Raw)};
}

} // namespace

const std::vector<ExportTargetInfo>& exportTargets() {
    static const std::vector<ExportTargetInfo> targets = {
        target(ExportTarget::Smash, "smash", "Smash Ultimate (.nutexb)", formats::kGameLutFormat,
               std::nullopt, ".nutexb", 0),
        target(ExportTarget::Engine, "engine", "Game engine strip (.png)", "strip",
               LutLayout::Pilot, ".png", 8),
        target(ExportTarget::Grading, "cube", "Grading app (.cube)", "cube", std::nullopt, ".cube",
               0),
    };
    return targets;
}

bool isTargetFile(ExportTarget id, const std::string& path, const std::string& format) {
    if (!format.empty())
        return false; // a format named is the user's choice, with its own settings
    const ExportTargetInfo& t = exportTargetInfo(id);
    formats::LutDestinationRequest request;
    request.path = path;
    const formats::LutDestination d = formats::resolveLutDestination(request);
    return d.writer && d.writer == FormatRegistry::instance().byName(t.format);
}

const ExportTargetInfo& exportTargetInfo(ExportTarget target) {
    for (const auto& t : exportTargets())
        if (t.id == target)
            return t;
    throw Error("unknown export target");
}

ExportTarget parseExportTarget(std::string_view key) {
    if (key == "grading")
        return ExportTarget::Grading;
    if (key == "raw")
        return ExportTarget::Engine;
    for (const auto& t : exportTargets())
        if (t.key == key)
            return t.id;
    throw Error("unknown target '" + std::string(key) + "' (expected smash, engine or cube)");
}

Lut3D exportTable(const LutSource& source, ExportTarget target, const StrengthOptions& strength,
                  ClipCount* clip) {
    static const Lut3D neutral = Lut3D::identity(33);
    const LutPurpose to = exportTargetInfo(target).purpose;
    const bool full = isFullStrength(strength);
    // At a partial strength the edit is blended with neutral (lut/ops/Strength.h): before it is
    // made for the game, so the game shows that share of the edit.
    auto blended = [&](const Lut3D& edit) { return full ? edit : applyStrength(edit, strength); };
    // The edit is a LUT on display colours, evaluated tetrahedrally (exact for affine edits, the
    // neutral one included), with lutkit convert's one rule above white (lut/smash/
    // SmashAuthoring.h: a game LUT exported unchanged is itself).
    PurposeOptions o;
    o.editInterpolation = Interpolation::Tetrahedral;
    const bool neutralEdit = !source.adjustments || source.adjustments->isNeutral();
    Lut3D table;
    if (source.gameBase && to == LutPurpose::Smash) {
        // The adjustments edit the picture the game shows with its LUT: that LUT is the stage.
        o.stageLut = source.gameBase.get();
        const Lut3D edit = neutralEdit ? neutral : applyAdjustments(neutral, *source.adjustments);
        const PurposeConversion c = convertPurpose(blended(edit), LutPurpose::Raw, to, o);
        if (clip)
            *clip = countOutOfRange(c.authoring.exact);
        return c.authoring.exact; // the file clamps it, as it clamps convert's
    }
    if (source.gameBase) { // the edit the game's LUT makes, then the adjustments on it
        const Lut3D edit = editOfGameLut(*source.gameBase, 33);
        table = blended(neutralEdit ? edit : applyAdjustments(edit, *source.adjustments));
    } else {
        const Lut3D& effective = source.effective ? *source.effective : neutral;
        if (to == LutPurpose::Smash) {
            const PurposeConversion c = convertPurpose(blended(effective), LutPurpose::Raw, to, o);
            if (clip)
                *clip = countOutOfRange(c.authoring.exact);
            return c.authoring.exact;
        }
        table = blended(effective);
    }
    if (clip)
        *clip = countOutOfRange(table);
    return table;
}

FormatOptions targetFormatOptions(ExportTarget target) {
    const ExportTargetInfo& info = exportTargetInfo(target);
    FormatOptions o;
    o.layout = info.layout;
    o.size = info.size;
    o.bitDepth = info.bitDepth;
    return o;
}

TargetLut makeTargetLut(const LutSource& source, ExportTarget target) {
    formats::registerBuiltinFormats();
    const ExportTargetInfo& info = exportTargetInfo(target);
    TargetLut out;
    out.table = exportTable(source, target, {}, &out.clip);
    const Format* format = FormatRegistry::instance().byName(info.format);
    if (!format)
        throw Error("the " + info.format + " format is not available");
    const FormatOptions options = targetFormatOptions(target);
    LutFile file;
    file.cube = out.table;
    file.purpose = info.purpose;
    const std::string name = "export" + info.extension;
    if (info.format == "cube") {
        // The .cube writer writes every float as the shortest text that reads back as the same
        // float (formats/src/cube): the file holds the table exactly (tested), no round trip.
        out.shown = std::make_shared<const Lut3D>(out.table);
        return out;
    }
    const std::string bytes = format->writeMemory(file, name, options, &out.notes);
    out.shown = std::make_shared<const Lut3D>(format->readMemory(bytes, name, options).toLut3D());
    return out;
}

} // namespace lut::gui
