#include "lut/pipeline/SceneKind.h"

#include "lut/Error.h"

#include <string>

namespace lut {

SceneKind detectSceneKind(bool storedIsFloat) {
    return storedIsFloat ? SceneKind::Scene : SceneKind::Screenshot;
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
