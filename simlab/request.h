#pragma once
// The one front door: every request from the CLI, the GUI (its command line and its dialogs)
// and Python is checked here before any work starts or any file is opened for writing.
//
// A refusal is a RequestError whose text is the same in every door: the CLI prints it after
// "error: " (exit 2), the GUI after "elastic-lab: " (exit 2) or in its dialog, Python raises
// ValueError with it. Every value a message echoes goes through quoted() (simcore::quoteShort:
// at most 40 bytes, control bytes as \xNN, the length said when cut).
//
// The bounds (docs/reliability.md): a run takes at most kMaxSteps steps, a study's or a
// refinement's runs and references too; what is held in memory (rows, reference trajectories,
// a stability scan's runs) stays under kMaxHeldBytes; a stability trial must last at least
// kMinTrialSteps steps at the largest step scanned.

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "simcore/integrators.h"
#include "simcore/params.h"
#include "simcore/world.h"
#include "simlab/bounds.h"
#include "simlab/scenefile.h"

namespace simlab {

struct StudySpec;
struct RefinementSpec;
struct StabilitySpec;
struct ConservationSpec;
struct SweepSpec;

// Bad input: the message names the problem and what is allowed.
struct RequestError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

// A value in a message: quoted and cut (the one helper every message uses).
std::string quoted(std::string_view value, std::size_t limit = 40);
// A number in a message: its shortest round-trip text (inf and nan as such).
std::string number(double value);

// --- the scene -----------------------------------------------------------------------------------

// A scene as every door takes it: a built-in name or a scene file (.json), then assignments
// key=value (a key given twice is refused, as in a scene file), then dt and the integrator.
struct SceneRequest {
    std::string scene = "ring2d";
    std::vector<std::string> set;           // "key=value", in the order given
    std::optional<std::string> dt;          // same as set dt=...
    std::optional<std::string> integrator;  // default: the scene file's, else rk4
    // The values a built-in scene starts from (the GUI's presets): the scene's defaults if unset.
    std::optional<simcore::ParameterSet> base;
    // The door takes scenes of several bodies (`run`, `params`, the GUI, Python's World); where
    // it does not, such a scene is refused in the words every door uses.
    bool severalBodies = false;
    // The bodies a scene of several bodies starts from (the GUI's world presets), in place of
    // the scene's own.
    std::optional<simcore::WorldSpec> baseWorld;
};

struct SceneSetup {
    simcore::ParameterSet params;
    std::string sceneName;
    std::string sceneFile;  // the file read, or empty for a built-in scene
    std::string integrator = "rk4";
    std::optional<SceneFile::State> state;  // from a scene file that saved one
    std::optional<SceneFile> file;          // the scene file as read (before the overrides)
    // A scene of several bodies (only where the request takes them): every body with the
    // assignments applied; `params` then holds body 1's values (dt, gravity and the box are
    // the world's, the same in every body).
    std::optional<simcore::WorldSpec> world;
};

// The scene file a scene argument names, or empty when it names a built-in scene.
std::string sceneFileOf(const std::string& scene);
// Resolves and checks the scene (table ranges, shape, the integrator and its memory).
SceneSetup resolveScene(const SceneRequest& request);
// A scene of several bodies: `spec` with the request's assignments (bodyN.key=value sets body N,
// key=value every body; each key once), dt and integrator, checked as a whole (bodies apart and
// inside the box, at most kMaxBodies). `setup` carries what resolveScene read of a file.
SceneSetup resolveWorld(simcore::WorldSpec spec, const SceneRequest& request, SceneSetup setup = SceneSetup());

// Side by side (the GUI's --compare): one to three integrators, each known, listed once, and
// each lane's memory with its integrator within the limit.
void checkLanes(const simcore::ParameterSet& params, const std::vector<std::string>& integrators);
// The same for a scene of several bodies: the same count and names, each lane's world with its
// integrator by checkWorldIntegrators (every body's shape and memory, xpbd's one set of springs).
void checkLanes(const simcore::WorldSpec& world, const std::vector<std::string>& integrators);

// --- files ---------------------------------------------------------------------------------------

// (option, path): option without dashes ("csv"), as messages name it ("--csv").
using NamedPath = std::pair<std::string, std::string>;
// Outputs never overwrite an input or each other (the same file by any name: links, "./",
// "..", /dev/std*, /proc/self/fd), an output name is never empty, and an output that exists
// is a regular file, a character device (written in place) or a standard stream, never a
// FIFO, socket or folder. `outputs` are given, empty ones skipped; an empty name is refused
// when `given` (the option was on the command line with '').
void checkFiles(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs);
// An output option given with an empty name.
void checkOutputNamed(const std::string& option, const std::optional<std::string>& path);

// --- the work ------------------------------------------------------------------------------------

// A run of `duration` seconds: a fixed-step method takes at most maxSteps steps; `rowsEvery`
// > 0 keeps a row every so many steps in memory (Python's run(every=)), at most kMaxHeldBytes.
struct RunRequest {
    double duration = 5.0;
    double maxSteps = kMaxSteps;
    long rowsEvery = 0;   // 0: rows are streamed to a file, not held
    double sampleEvery = 0.0;  // > 0: a row held every so many seconds of simulated time
    int rowColumns = 0;   // columns of a held row
    simcore::IntegratorOptions options;
    std::string precision = "double";  // double | float (the float path, simcore/float_path.h)
};
void checkRun(const SceneSetup& scene, const RunRequest& run);

// The precision of a run (run, bench, Python, the GUI's Run dock): double, or float for the
// integrators the float path is built for (simcore::floatPathSupports). The problem, or nothing.
std::optional<std::string> precisionProblem(const std::string& precision, const std::string& integrator);
void checkPrecision(const std::string& precision, const std::string& integrator);
// The same for a run of `scene`: the float path is built for one body, so a scene of several
// bodies takes double only (the CLI's run, the GUI's command line, checkRun).
void checkPrecision(const SceneSetup& scene, const std::string& precision, const std::string& integrator);

// A work-precision study: validateStudy, then its references and runs bounded in steps and
// in memory (the reference trajectory and one run's, samples x particles each).
void checkStudy(const StudySpec& spec);
// A refinement study: validateRefinement, its levels and output grid bounded.
void checkRefinement(const RefinementSpec& spec);
// A stability scan: hmin <= hmax, a trial at hmin within kMaxSteps and at least kMinTrialSteps.
void checkStability(const StabilitySpec& spec);
// Restitution at these impact speeds: each run (10 s at min(dt, 3e-4 s / speed)) bounded.
void checkRestitution(const simcore::ParameterSet& params, const std::vector<double>& speeds);

// Long-time energy (conservation): validateConservation, each integrator's memory. The step
// count needs the scene's fastest mode; runConservation refuses it (a RequestError, before any
// step) when above kMaxSteps.
void checkConservation(const ConservationSpec& spec);
// A sweep: validateSweep (its points, every point's body, max_steps at most kMaxSteps per point).
void checkSweep(SweepSpec& spec);

// The integrators a scan or study names: each known.
void checkIntegrators(const std::vector<std::string>& names);
// A world with each of these integrators: every body's shape and memory, and what only the
// built world refuses (xpbd with bodies whose springs differ).
void checkWorldIntegrators(const simcore::WorldSpec& world, const std::vector<std::string>& names);

}  // namespace simlab
