#pragma once
// The description of a world of several bodies before it is built (world.h builds and steps
// it): its bodies, each a ParameterSet with a start position and velocity; the built-in
// scenes; the bodyN.key=value settings; the checks before anything runs. world_spec.cpp.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "simcore/params.h"

namespace simcore {

// What a world's body is made of before it is built.
struct WorldBodySpec {
    ParameterSet params{SceneKind::Sphere3d};
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // start centre (centroid) [m]
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // start velocity of every particle [m/s]
};

// The most bodies a world may hold (the CLI refuses more before anything is built).
inline constexpr int kMaxBodies = 16;

// A world before it is built: its bodies (world parameters are every body's own copy, kept
// equal by setWorldValue), and the name of the scene it came from.
struct WorldSpec {
    std::string name;
    std::vector<WorldBodySpec> bodies;
};

// The built-in scenes of several bodies: collide2d, collide3d, stack3d.
struct WorldSceneInfo {
    std::string_view name;
    std::string_view description;
};
std::span<const WorldSceneInfo> worldSceneTable();
// The scene's description, or nothing when `name` is not a scene of several bodies.
std::optional<WorldSpec> worldScene(std::string_view name);

// Parameters shared by all bodies: gravity, the box, contact, the pointer, time.
bool isWorldParameter(Param id);
// The per-body start keys besides the parameter table's: position_x/y/z, velocity_x/y/z.
bool isStartVectorKey(std::string_view key);

// One --set assignment, "bodyN.key=value" (N from 1) or "key=value" (every body; a world
// parameter: the world). Returns the one-line message naming the body and the key when it
// is refused (a body the scene does not have, a world parameter given to one body, a key no
// body of the scene has, a value out of range).
std::optional<std::string> assignWorld(WorldSpec& spec, std::string_view assignment);
// What no single assignment can decide, before anything is built: 1..kMaxBodies bodies, of
// one dimension, none of them 1D; every body's shape; bodies that overlap (their outer
// spheres, with the contact skin) or stick out of the box at the start. The message names the
// body or bodies.
std::optional<std::string> validateWorld(const WorldSpec& spec);

}  // namespace simcore
