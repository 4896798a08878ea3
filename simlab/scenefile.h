#pragma once
// Scene files: a scene, every parameter, the integrator and optionally the exact state, as
// JSON, so that a paused experiment can be saved and resumed exactly.
//
//   {
//     "format": "elastic-lab-scene", "version": 3,
//     "scene": "ring2d", "integrator": "rk4",
//     "parameters": { "ks": 800, "kd": 15, "scaling": "physical", ... every key of the scene ... },
//     "state": { "step": 410, "time": 1.23,                       (optional)
//                "next_step": 0.0021,          (adaptive integrators: the step proposed next)
//                "positions": [[x, y, z], ...], "velocities": [[vx, vy, vz], ...] }
//
// Version 2 added state.next_step (so an rk45 run resumes exactly); version 1 files load.
// Version 3 added "scaling" (physical | thesis) and writes choices by name; a file of an
// earlier version loads as scaling=thesis, the per-particle body it was saved with.
//   }
//
// Version 4 added scenes of several bodies (a world, simcore/world.h); a one-body file is still
// written as version 3, so earlier programs read it:
//
//   { "format": "elastic-lab-scene", "version": 4,
//     "scene": "collide3d", "integrator": "rk4",
//     "parameters": { "gravity": 0, "box": 10, ... },       (every body: world parameters, and
//                                                           body parameters given to all)
//     "bodies": [ { "kind": "sphere3d", "position": [x, y, z], "velocity": [vx, vy, vz],
//                   "parameters": { "mass": 4, ... } },    (this body's own; they override)
//                 ... ],
//     "state": { "step": 410, "time": 1.23, "next_step": 0.0021,   (optional)
//                "bodies": [ { "positions": [[x, y, z], ...], "velocities": [...] }, ... ] } }
//
// Without "bodies" a world scene's name (collide2d, ...) loads that scene as built in. Every
// refusal of a body's entry names the body as people count and the key: "body3.kind: ...",
// "body2.mass: ...", "body1.gravity: a world parameter ...".
//
// Reading validates everything through the parameter table: unknown keys (at any level),
// wrong types, out-of-range values and a newer format version are refused with a message that
// names the key and, for syntax errors, the line.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "simcore/params.h"
#include "simcore/world.h"

namespace simcore {
class Simulation;
}  // namespace simcore

namespace simlab {

inline constexpr int kSceneFormatVersion = 3;       // written for one body
inline constexpr int kWorldSceneFormatVersion = 4;  // written for several; the newest read

struct SceneFile {
    std::string sceneName;
    simcore::ParameterSet params;
    std::string integrator = "rk4";
    struct State {
        long step = 0;
        double time = 0.0;
        std::optional<double> nextStep;  // adaptive integrators: the step they proposed [s]
        Eigen::Matrix3Xd positions;   // a world: every body's particles side by side (world numbering)
        Eigen::Matrix3Xd velocities;
    };
    std::optional<State> state;
    // A scene of several bodies: its bodies, each with its parameters, start position and
    // velocity (then `params` is the first body's, for what only reads the world's values).
    std::optional<simcore::WorldSpec> world;
};

struct SceneFileResult {
    std::optional<SceneFile> file;
    std::string error;  // set when file is empty
};

SceneFileResult parseSceneFile(const std::string& text);
// Every file read as input (scene files, a study's --from-csv): a regular file of at most
// kMaxInputFileBytes; a directory, FIFO, device or socket is refused by what it is, without
// waiting on it or reading it to the end. `what` names the file in messages ("a scene file").
inline constexpr long long kMaxInputFileBytes = 256LL * 1024 * 1024;
inline constexpr long long kMaxSceneFileBytes = kMaxInputFileBytes;
// The reader's other bounds, for any accepted size: nesting depth (the format needs 4), the
// memory of the parsed tree (estimated while parsing; a body at the 1 GiB limit, ~700,000
// particles, takes ~280 MiB), and a saved step count (2^53: exact in any JSON reader, and
// billions of years of steps left before a 64-bit counter overflows).
inline constexpr int kMaxSceneDepth = 16;
inline constexpr long long kMaxSceneParseBytes = 768LL * 1024 * 1024;
inline constexpr std::uint64_t kMaxSavedStep = 1ULL << 53;
struct InputFile {
    std::string text;
    std::string error;  // set when nothing was read
};
InputFile readInputFile(const std::string& path, const std::string& what);
SceneFileResult readSceneFile(const std::string& path);

// The JSON text of a simulation (with its state when withState).
std::string sceneFileText(const simcore::Simulation& sim, const std::string& sceneName, bool withState);
// The JSON text of a scene file as read: only its explicitly set parameters (the rest stay the
// table's, inherited values included), and its state when it has one.
std::string sceneFileText(const SceneFile& file);
// Restores a saved state into a simulation built from the same file; error text or nothing.
std::optional<std::string> applyState(simcore::Simulation& sim, const SceneFile::State& state);

// The JSON text of a world: every parameter (the world's at the top, each body's own under it),
// with its exact state when withState.
std::string sceneFileText(const simcore::World& world, bool withState);
std::optional<std::string> applyState(simcore::World& world, const SceneFile::State& state);

}  // namespace simlab
