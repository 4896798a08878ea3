#include "simcore/scenes.h"

#include <array>
#include <stdexcept>

#include "simcore/params.h"

namespace simcore {

namespace {
// clang-format off
constexpr std::array kScenes = {
    SceneInfo{"spring1d", SceneKind::Spring1d,
              "1D: two masses on one spring hanging along -y, the top one fixed (thesis fig. 7)"},
    SceneInfo{"ring2d", SceneKind::Ring2d,
              "2D: two concentric gas-filled rings joined by radius and shear springs (thesis 3.4)"},
    SceneInfo{"sphere3d", SceneKind::Sphere3d,
              "3D: two concentric gas-filled spheres, subdivided octahedron (thesis 3.5.2)"},
    SceneInfo{"sphere3d-latlong", SceneKind::Sphere3dLatLong,
              "3D: two concentric gas-filled lat/long spheres, the non-uniform sphere (thesis 3.5.1)"},
};
// clang-format on
}  // namespace

std::span<const SceneInfo> sceneTable() { return kScenes; }

const SceneInfo* findScene(std::string_view name) {
    for (const SceneInfo& s : kScenes)
        if (s.name == name) return &s;
    return nullptr;
}

const SceneInfo& sceneInfo(SceneKind kind) {
    for (const SceneInfo& s : kScenes)
        if (s.kind == kind) return s;
    throw std::invalid_argument("unknown scene kind");
}

std::string unknownSceneMessage(std::string_view name) {
    return "unknown scene " + quoteShort(name) + "; allowed: " + sceneNames();
}

std::string sceneNames() {
    std::string names;
    for (const SceneInfo& s : kScenes) {
        if (!names.empty()) names += ", ";
        names += s.name;
    }
    return names;
}

bool hasGas(SceneKind kind) { return kind != SceneKind::Spring1d; }

TermSet sceneTerms(SceneKind kind) {
    TermSet terms;
    terms.set(Term::Gravity, true);
    terms.set(Term::Springs, true);
    terms.set(Term::Pointer, true);
    terms.set(Term::Collisions, true);
    terms.set(Term::Gas, hasGas(kind));
    terms.set(Term::LayerConstraint, hasGas(kind));
    return terms;
}

}  // namespace simcore
