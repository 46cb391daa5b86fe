#pragma once
// What a picture opened for preview holds, and the rule that tells it from the file (issue 14:
// "an 8-bit sRGB image is an in-game screenshot by default, a linear EXR a scene"):
//   Screenshot  integer files (8/16-bit PNG, TIFF, JPEG...): display-encoded colours as a game
//               showed them, its grading, bloom and display encoding already applied;
//   Scene       float files (EXR, float TIFF, HDR): linear scene values before post-processing.
// The rule is only a default: `lutkit preview` and the editor print or show the choice and let
// the user override it (a screenshot saved as EXR, a linear render saved as 16-bit TIFF).
#include <string_view>

namespace lut {

enum class SceneKind { Screenshot, Scene };

// The default for a stored pixel type: float = Scene, integer = Screenshot.
SceneKind detectSceneKind(bool storedIsFloat);

// "screenshot" / "scene", and back (throws lut::Error naming the accepted words).
const char* toString(SceneKind kind);
SceneKind parseSceneKind(std::string_view name);

} // namespace lut
