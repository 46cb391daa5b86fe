// SPDX-License-Identifier: Apache-2.0
// The one write of a LUT file; see lut/io/LutWriter.h.
#include "lut/io/LutWriter.h"

#include "lut/io/FileNames.h"
#include "lut/io/OutputFile.h"

namespace lut {

namespace {

// What is lost when the file cannot say what its LUT is for (Format::keepsPurpose), and the flag
// that reads it back right: never compensated twice in silence (docs/roundtrip.md, "What the
// file says it is for").
void warnPurposeLost(const Format& format, const std::string& path, const LutFile& lut,
                     Diagnostics& d) {
    if (!lut.purpose || format.keepsPurpose(path, *lut.purpose))
        return;
    const std::string ext = extensionOf(path);
    const std::string kind = (ext.empty() ? format.name() : ext) + " file";
    std::string message;
    if (*lut.purpose == LutPurpose::Smash)
        message = "a " + kind +
                  " cannot say that this is the game's LUT (LUTKIT_PURPOSE smash): read back, it "
                  "would be taken as an edit and compensated for the brighten pass a second "
                  "time; read it with --in-target smash (apply, preview, the editor: "
                  "--lut-target smash), or write a format that keeps it (.cube, .3dl, .itx, "
                  ".clf, .ctf, .csp, a PNG/TIFF/EXR strip, .nutexb)";
    else if (format.keepsPurpose(path, LutPurpose::Smash))
        message = "a " + kind +
                  " is always the game's LUT: this edit (LUTKIT_PURPOSE raw) would be read back "
                  "as the game's, not compensated for the brighten pass; write it with --target "
                  "smash to make the game show the edit, or read it back with --in-target raw";
    else if (lut.cube && !lut.shaper && gameLutEvidence(*lut.cube))
        message = "a " + kind +
                  " cannot say that this is an edit (LUTKIT_PURPOSE raw), and its content looks "
                  "like the game's LUT (lut/LutFile.h): read back, it would be taken as the "
                  "game's; read it with --in-target raw (apply, preview, the editor: "
                  "--lut-target raw)";
    else
        return; // an edit is what a file that does not say is taken for
    d.push_back({Diagnostic::Severity::Warning, path, 0, 0, message});
}

} // namespace

Diagnostics writeLutFile(const Format& format, const std::string& path, const LutFile& lut,
                         const FormatOptions& options, std::string* writtenBytes) {
    const OutputTarget target = checkOutput(path, ExistingOutput::Replace);
    Diagnostics d;
    if (!target.inPlace()) {
        d = format.write(target.writePath, lut, options);
    } else {
        std::string bytes = format.writeMemory(lut, path, options, &d);
        writeOutputBytes(target, bytes);
        if (writtenBytes)
            *writtenBytes = std::move(bytes);
    }
    warnPurposeLost(format, path, lut, d);
    return d;
}

} // namespace lut
