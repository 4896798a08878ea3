// The world's description before it is built (world_spec.h): the built-in scenes of several
// bodies, the bodyN.key=value settings and the checks before anything runs.
#include "simcore/world_spec.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "simcore/scenes.h"

namespace simcore {

namespace {

// clang-format off
constexpr std::array kWorldScenes = {
    WorldSceneInfo{"collide2d", "2D: two two-layer rings thrown at each other head-on (offset: their centres apart "
                                "across the line of approach)"},
    WorldSceneInfo{"collide3d", "3D: two two-layer spheres thrown at each other head-on (offset: their centres "
                                "apart across the line of approach)"},
    WorldSceneInfo{"stack3d", "3D: three spheres dropped one above the other onto the floor"},
};
// clang-format on

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

std::string bodyName(std::size_t k) { return "body" + std::to_string(k + 1); }

void setAll(WorldSpec& spec, Param id, double value) {
    for (auto& b : spec.bodies) (void)b.params.set(id, value);
}

// The start vector keys: (which vector, axis).
std::optional<std::pair<int, int>> startVector(std::string_view key) {
    constexpr std::array<std::string_view, 6> keys = {"position_x", "position_y", "position_z",
                                                      "velocity_x", "velocity_y", "velocity_z"};
    for (std::size_t k = 0; k < keys.size(); ++k)
        if (keys[k] == key) return std::pair<int, int>{static_cast<int>(k / 3), static_cast<int>(k % 3)};
    return std::nullopt;
}

int dimensionOf(SceneKind kind) {
    switch (kind) {
        case SceneKind::Spring1d: return 1;
        case SceneKind::Ring2d: return 2;
        default: return 3;
    }
}

}  // namespace

std::span<const WorldSceneInfo> worldSceneTable() { return kWorldScenes; }

std::optional<WorldSpec> worldScene(std::string_view name) {
    WorldSpec spec;
    spec.name = std::string(name);
    if (name == "collide2d" || name == "collide3d") {
        const SceneKind kind = name == "collide2d" ? SceneKind::Ring2d : SceneKind::Sphere3d;
        for (int k = 0; k < 2; ++k) {
            WorldBodySpec b;
            b.params = ParameterSet(kind);
            const double side = k == 0 ? -1.0 : 1.0;
            b.position = Eigen::Vector3d(3.0 * side, 0.0, 0.0);
            b.velocity = Eigen::Vector3d(-2.0 * side, 0.0, 0.0);
            spec.bodies.push_back(b);
        }
        // Weightless bodies at 2 m/s stay clear of the walls for well over 2 s.
        setAll(spec, Param::Box, 10.0);
        return spec;
    }
    if (name == "stack3d") {
        for (int k = 0; k < 3; ++k) {
            WorldBodySpec b;
            b.params = ParameterSet(SceneKind::Sphere3d);
            b.position = Eigen::Vector3d(0.0, -4.8 + 4.3 * k, 0.0);
            spec.bodies.push_back(b);
        }
        setAll(spec, Param::Box, 7.0);
        return spec;
    }
    return std::nullopt;
}

bool isWorldParameter(Param id) {
    switch (paramSpec(id).group) {
        case ParamGroup::Environment:
        case ParamGroup::Contact:
        case ParamGroup::Pointer:
        case ParamGroup::Time: return true;
        default: return false;
    }
}

bool isStartVectorKey(std::string_view key) { return startVector(key).has_value(); }

std::optional<std::string> assignWorld(WorldSpec& spec, std::string_view assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string_view::npos)
        return "expected bodyN.key=value or key=value, got " + quoteShort(assignment);
    std::string_view lhs = assignment.substr(0, eq);
    const std::string_view text = assignment.substr(eq + 1);
    const std::size_t count = spec.bodies.size();
    // bodyN. prefix: one body, numbered from 1.
    std::optional<std::size_t> only;
    if (lhs.starts_with("body")) {
        const auto dot = lhs.find('.');
        const std::string_view digits = lhs.substr(4, dot == std::string_view::npos ? std::string_view::npos : dot - 4);
        const bool numeric = !digits.empty() && digits.size() <= 6 &&
                             std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (numeric && dot != std::string_view::npos) {
            const auto n = static_cast<std::size_t>(std::stoul(std::string(digits)));
            lhs = lhs.substr(dot + 1);
            if (n < 1 || n > count)
                return "body" + std::to_string(n) + "." + std::string(lhs.substr(0, 40)) + ": the scene has " +
                       std::to_string(count) + " bodies (body1 to body" + std::to_string(count) + ")";
            only = n - 1;
        }
    }
    // The key as typed when it is a plain name, else quoted (and cut) for the message.
    const bool plain = lhs.size() <= 40 && std::all_of(lhs.begin(), lhs.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
    const std::string key = plain ? std::string(lhs) : quoteShort(lhs);
    const std::string where = only ? bodyName(*only) + "." + key : key;
    if (lhs == "offset") {
        if (only) return where + ": offset belongs to the scene, not to one body; set it without a prefix";
        if (count != 2 || !(spec.name == "collide2d" || spec.name == "collide3d"))
            return "offset: only collide2d and collide3d have it (their centres apart across the line of approach)";
        const auto value = parseNumber(text);
        if (!value || std::abs(*value) > 1e3) return "offset: " + quoteShort(text) + " is not a number in [-1000, 1000] m";
        spec.bodies[0].position.y() = -0.5 * *value;
        spec.bodies[1].position.y() = 0.5 * *value;
        return std::nullopt;
    }
    if (const auto vector = startVector(lhs)) {
        const auto value = parseNumber(text);
        if (!value || std::abs(*value) > 1e6)
            return where + ": " + quoteShort(text) + " is not a number in [-1e6, 1e6] " +
                   (vector->first == 0 ? "m" : "m/s");
        for (std::size_t k = 0; k < count; ++k) {
            if (only && k != *only) continue;
            if (vector->second == 2 && dimensionOf(spec.bodies[k].params.kind()) < 3 && *value != 0.0)
                return bodyName(k) + "." + std::string(lhs) + ": a 2D body moves in the xy plane (z stays 0)";
            Eigen::Vector3d& v = vector->first == 0 ? spec.bodies[k].position : spec.bodies[k].velocity;
            v[vector->second] = *value;
        }
        return std::nullopt;
    }
    const ParamSpec* param = findParam(lhs);
    if (!param) {
        const std::string message = *ParameterSet(spec.bodies.front().params.kind()).set(lhs, 0.0);
        return (only ? bodyName(*only) + ": " : std::string()) + message +
               " position_x position_y position_z velocity_x velocity_y velocity_z";
    }
    if (only && isWorldParameter(param->id))
        return where + ": " + std::string(param->key) +
               " is a world parameter, shared by every body; set it without a body prefix";
    bool any = false;
    for (std::size_t k = 0; k < count; ++k) {
        if (only && k != *only) continue;
        ParameterSet& set = spec.bodies[k].params;
        if (!set.has(param->id)) {
            if (only) return bodyName(k) + ": " + *set.setFromText(lhs, text);
            continue;
        }
        if (auto error = set.setFromText(lhs, text)) return (count > 1 ? bodyName(k) + ": " : std::string()) + *error;
        any = true;
    }
    if (!any) return std::string(lhs) + ": no body of this scene has it";
    return std::nullopt;
}

std::optional<std::string> validateWorld(const WorldSpec& spec) {
    const std::size_t count = spec.bodies.size();
    if (count < 1) return std::string("a world needs at least one body");
    if (count > static_cast<std::size_t>(kMaxBodies))
        return "the scene has " + std::to_string(count) + " bodies; at most " + std::to_string(kMaxBodies);
    const int dimension = dimensionOf(spec.bodies.front().params.kind());
    for (std::size_t k = 0; k < count; ++k) {
        const ParameterSet& set = spec.bodies[k].params;
        if (dimensionOf(set.kind()) == 1)
            return bodyName(k) + ": a spring1d body cannot share a world (bodies are two-layer rings or spheres)";
        if (dimensionOf(set.kind()) != dimension)
            return bodyName(k) + ": a " + std::to_string(dimensionOf(set.kind())) + "D body in a " +
                   std::to_string(dimension) + "D world (every body of a world lives in the same space)";
        if (auto error = validateShape(set)) return bodyName(k) + ": " + *error;
        if (resolve(set).world.contact == ContactModel::Projection)
            return bodyName(k) +
                   ": contact = projection is the one-body thesis program; a world of several bodies takes "
                   "contact = force (bodies meet through a force in the ODE)";
    }
    const double box = resolve(spec.bodies.front().params).world.box;
    auto radius = [&](std::size_t k) { return resolve(spec.bodies[k].params).shape.radiusOuter; };
    for (std::size_t k = 0; k < count; ++k) {
        const Eigen::Vector3d& p = spec.bodies[k].position;
        for (int axis = 0; axis < dimension; ++axis)
            if (std::abs(p[axis]) + radius(k) > box)
                return bodyName(k) + " sticks out of the box at the start: outer radius " + number(radius(k)) +
                       " m around " + "xyz"[axis] + " = " + number(p[axis]) + " m, walls at +-" + number(box) + " m";
    }
    // The contact skin is at most 0.1 m (World): bodies closer than that at the start would
    // start inside each other's barrier.
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = i + 1; j < count; ++j) {
            const double apart = (spec.bodies[i].position - spec.bodies[j].position).norm();
            if (apart < radius(i) + radius(j) + 0.1)
                return "bodies " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                       " overlap at the start: centres " + number(apart) + " m apart, outer radii " +
                       number(radius(i)) + " m and " + number(radius(j)) + " m (at least 0.1 m between them)";
        }
    return std::nullopt;
}

}  // namespace simcore
