// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a picture opened for preview holds, and the rule that tells it from the file (issue 14:
// "an 8-bit sRGB image is an in-game screenshot by default, a linear EXR a scene"):
//   Screenshot  integer files (8/16-bit PNG, TIFF, JPEG...): display-encoded colours as a game
//               showed them, its grading, bloom and display encoding already applied;
//   Scene       float files (EXR, float TIFF, HDR), and integer files their metadata calls
//               linear: linear scene values before post-processing.
// The rule is only a default: `lutkit preview` and the editor print or show the choice and let
// the user override it (a screenshot saved as EXR, a linear render saved as 16-bit TIFF). One
// rule for both: decideSceneKind.
#include <optional>
#include <string>
#include <string_view>

namespace lut {

enum class SceneKind { Screenshot, Scene };

// The default for a stored pixel type: float = Scene, integer = Screenshot.
SceneKind detectSceneKind(bool storedIsFloat);

// What the file says (lut::formats::ImageInfo has these).
struct SceneEvidence {
    bool storedIsFloat = false;
    int bitDepth = 8;       // 8, 16, 32 (float)
    std::string colorSpace; // the file's colour-space metadata ("sRGB", "Linear", ...), or ""
    std::string format;     // the file format's name ("png", "openexr", ...), for the reason
};

// The decision and how to prepare the frame for the pipeline (lut/pipeline/PreviewPlan.h:
// planPreview, preparePreviewFrame).
struct SceneDecision {
    SceneKind kind = SceneKind::Screenshot;
    bool forced = false;         // the user chose it (--from-screenshot / --scene)
    bool storedIsLinear = false; // the stored values are linear (else sRGB-decode them first)
    bool undoGrading = false;    // a screenshot: undo the game's grading before the new LUT
    // One line for the user, e.g. "an in-game screenshot (an 8-bit png file; --scene reads it
    // as a linear scene)".
    std::string reason;
};

// The rule: a float file is a scene; an integer file is a screenshot unless its colour-space
// metadata says linear (a linear render stored as 16-bit TIFF). `forced` overrides it: a forced
// screenshot stored as float is taken as display-encoded values; a forced scene stored as
// integers is sRGB-decoded unless its metadata says linear.
SceneDecision decideSceneKind(const SceneEvidence& evidence,
                              std::optional<SceneKind> forced = std::nullopt);

// "screenshot" / "scene", and back (throws lut::Error naming the accepted words).
const char* toString(SceneKind kind);
SceneKind parseSceneKind(std::string_view name);

} // namespace lut
