#include "ExportTarget.h"

#include "lut/Error.h"
#include "lut/formats/Registry.h"
#include "lut/io/FormatRegistry.h"
#include "lut/pipeline/SmashDisplayEdit.h"
#include "lut/pipeline/SmashGrading.h"

namespace lut::gui {

const std::vector<ExportTargetInfo>& exportTargets() {
    static const std::vector<ExportTargetInfo> targets = {
        {ExportTarget::Smash, "smash", "Smash Ultimate (.nutexb)", "nutexb", std::nullopt,
         ".nutexb", kSmashLutSize, 0},
        {ExportTarget::Engine, "engine", "Game engine strip (.png)", "strip", LutLayout::Pilot,
         ".png", 16, 8},
        {ExportTarget::Grading, "cube", "Grading app (.cube)", "cube", std::nullopt, ".cube", 0, 0},
    };
    return targets;
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

Lut3D exportTable(const LutSource& source, ExportTarget target, const StrengthOptions& strength) {
    static const Lut3D neutral = Lut3D::identity(33);
    const bool full = isFullStrength(strength);
    const Lut3D& effective = source.effective ? *source.effective : neutral;
    if (target != ExportTarget::Smash)
        return full ? effective : applyStrength(effective, strength);
    // The edit is a LUT on display colours, sampled tetrahedrally (exact for affine edits, the
    // neutral one included).
    if (source.gameBase) {
        const bool neutralEdit = !source.adjustments || source.adjustments->isNeutral();
        const Lut3D edit = neutralEdit ? neutral : applyAdjustments(neutral, *source.adjustments);
        return smashLutForDisplayEdit(full ? edit : applyStrength(edit, strength),
                                      source.gameBase.get(), Interpolation::Tetrahedral);
    }
    return smashLutForDisplayEdit(full ? effective : applyStrength(effective, strength), nullptr,
                                  Interpolation::Tetrahedral);
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
    out.table = exportTable(source, target);
    out.clip = countOutOfRange(out.table);
    const Format* format = FormatRegistry::instance().byName(info.format);
    if (!format)
        throw Error("the " + info.format + " format is not available");
    const FormatOptions options = targetFormatOptions(target);
    LutFile file;
    file.cube = out.table;
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
