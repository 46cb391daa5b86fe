// SPDX-License-Identifier: Apache-2.0
#pragma once
// lutkit-editor's command line (gui/main.cpp), read and checked before any QApplication exists:
// --help, --version and bad usage need no display. Its options speak lutkit's vocabulary
// (-V/--version, -v/--verbose, --interp); a bad value is bad usage (one line, exit 2).
//   lutkit-editor [IMAGE [LUT]]
//   lutkit-editor --screenshot OUT.png [IMAGE [LUT]]   render the window offscreen, save, exit
//   lutkit-editor --save-preview OUT.png IMAGE [LUT]   write the preview image like lutkit preview
//   lutkit-editor --script FILE [IMAGE [LUT]]          drive the window (ScriptRunner.h), exit
#include "AdjustParam.h"
#include "ExportTarget.h"
#include "PreviewController.h"

#include "lut/LutPurpose.h"

#include <QSize>
#include <QString>
#include <QStringList>

#include <optional>
#include <variant>
#include <vector>

namespace lut::gui {

struct EditorOptions {
    PreviewOptions preview;
    ExportTarget target = ExportTarget::Smash; // the document's
    std::optional<SceneKind> input;            // --input / --from-screenshot
    std::optional<LutPurpose> lutAnswer;       // --lut-target
    QSize windowSize;                          // invalid: the default
    QString view = QStringLiteral("split");    // split, after or before
    double zoomPercent = 0;                    // 0 = fit
    struct Adjust {
        const AdjustParamInfo* info;
        double value; // clamped to the parameter's range
    };
    std::vector<Adjust> adjusts; // --adjust, in order
    // IMAGE and LUT, a LUT named alone or first taken as the LUT (a file manager's Open with).
    QString imagePath, lutPath;
    // The modes, when asked: --screenshot FILE, --save-preview FILE, --script FILE.
    std::optional<QString> screenshotPath, savePreviewPath, scriptPath;
    bool verbose = false;

    // --screenshot or --save-preview: no window is shown to a user.
    bool headless() const { return screenshotPath || savePreviewPath; }
    bool scripted() const { return scriptPath.has_value(); }
};

// The options of `arguments` (argv, the program's name first), or the exit code the run ends with
// now: 0 after --help or --version (printed on stdout), 2 after bad usage (said on stderr).
std::variant<EditorOptions, int> readEditorOptions(const QStringList& arguments);

} // namespace lut::gui
