#pragma once
// The built-in scenes: a name, the body kind it builds and the force terms it has.

#include <span>
#include <string_view>

#include "simcore/forces.h"
#include "simcore/params.h"

namespace simcore {

struct SceneInfo {
    std::string_view name;
    SceneKind kind;
    std::string_view description;
};

std::span<const SceneInfo> sceneTable();
const SceneInfo* findScene(std::string_view name);
const SceneInfo& sceneInfo(SceneKind kind);
std::string sceneNames();  // "spring1d, ring2d, ..." for messages
// The one message for a name that is not a built-in scene (CLI, GUI, Python).
std::string unknownSceneMessage(std::string_view name);

// Whether a scene has layers with gas (volume, pressure) at all.
bool hasGas(SceneKind kind);
// The force terms a scene declares: a 1D spring has no gas and no layer constraint.
TermSet sceneTerms(SceneKind kind);

}  // namespace simcore
