// SPDX-License-Identifier: Apache-2.0
// The screenshot/scene rule; see lut/pipeline/SceneKind.h.
#include "lut/pipeline/SceneKind.h"

#include "lut/Error.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace lut {

namespace {

bool saysLinear(const std::string& colorSpace) {
    std::string s = colorSpace;
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s.find("linear") != std::string::npos || s.rfind("lin_", 0) == 0 ||
           s.find("scene") != std::string::npos || s == "acescg" || s == "aces2065-1";
}

std::string fileText(const SceneEvidence& e) {
    std::string s = e.storedIsFloat ? "a float" : "an " + std::to_string(e.bitDepth) + "-bit";
    if (!e.storedIsFloat && e.bitDepth != 8)
        s = "a " + std::to_string(e.bitDepth) + "-bit";
    s += e.format.empty() ? std::string(" file") : " " + e.format + " file";
    if (!e.colorSpace.empty())
        s += " tagged " + e.colorSpace;
    return s;
}

} // namespace

SceneKind detectSceneKind(bool storedIsFloat) {
    return storedIsFloat ? SceneKind::Scene : SceneKind::Screenshot;
}

SceneDecision decideSceneKind(const SceneEvidence& e, std::optional<SceneKind> forced) {
    SceneDecision d;
    const bool linearTag = saysLinear(e.colorSpace);
    const SceneKind byRule =
        e.storedIsFloat || linearTag ? SceneKind::Scene : SceneKind::Screenshot;
    d.kind = forced ? *forced : byRule;
    d.forced = forced.has_value();
    if (d.kind == SceneKind::Screenshot) {
        d.storedIsLinear = false; // display-encoded values, whatever the type
        d.undoGrading = true;
        d.reason = "an in-game screenshot (" + fileText(e) +
                   (d.forced ? "; as asked" : "; --scene reads it as a linear scene") +
                   "): the game's grading is undone before the new LUT";
    } else {
        d.storedIsLinear = e.storedIsFloat || linearTag;
        d.undoGrading = false;
        d.reason =
            "a linear scene (" + fileText(e) +
            (d.forced ? "; as asked" : "; --from-screenshot reads it as an in-game screenshot") +
            (d.storedIsLinear ? ")" : "): its values are sRGB-decoded first");
    }
    return d;
}

const char* toString(SceneKind kind) {
    return kind == SceneKind::Scene ? "scene" : "screenshot";
}

SceneKind parseSceneKind(std::string_view name) {
    if (name == "screenshot")
        return SceneKind::Screenshot;
    if (name == "scene")
        return SceneKind::Scene;
    throw Error("unknown input kind '" + std::string(name) + "' (expected screenshot or scene)");
}

} // namespace lut
