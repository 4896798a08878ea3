#include "simlab/request.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "simcore/body.h"
#include "simcore/float_path.h"
#include "simcore/integrator_table.h"
#include "simcore/scenes.h"
#include "simcore/world.h"
#include "simlab/conservation.h"
#include "simlab/output.h"
#include "simlab/refinement.h"
#include "simlab/stability.h"
#include "simlab/study.h"
#include "simlab/sweep.h"

namespace simlab {

std::string quoted(std::string_view value, std::size_t limit) { return simcore::quoteShort(value, limit); }

std::string number(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    // 1e+09 -> 1e9, 1e-05 -> 1e-5: as people write them.
    std::string out = text;
    for (const auto& [from, to] : {std::pair{"e+0", "e"}, {"e+", "e"}, {"e-0", "e-"}})
        if (const auto at = out.find(from); at != std::string::npos) out.replace(at, std::string_view(from).size(), to);
    return out;
}

namespace {

[[noreturn]] void refuse(const std::string& message) { throw RequestError(message); }
void refuseIf(const std::optional<std::string>& error) {
    if (error) refuse(*error);
}

std::string gib(double bytes) { return number(bytes / (1024.0 * 1024.0 * 1024.0)) + " GiB"; }

void checkHeld(double bytes, const std::string& what, const std::string& remedy) {
    if (bytes > kMaxHeldBytes)
        refuse(what + " would hold " + gib(bytes) + " in memory; at most " + gib(kMaxHeldBytes) + " (" + remedy + ")");
}

void checkSteps(double steps, const std::string& what, const std::string& remedy, double limit = kMaxSteps) {
    if (!(steps <= limit))
        refuse(what + " would take " + number(steps) + " steps; at most " + number(limit) + " per run (" + remedy + ")");
}

}  // namespace

// --- the scene -------------------------------------------------------------------------------------

std::string sceneFileOf(const std::string& scene) {
    // A scene file: named *.json, or an existing file by any name (a file manager hands one over).
    struct stat st {};
    const bool file = (scene.size() > 5 && scene.ends_with(".json")) || (::stat(scene.c_str(), &st) == 0 && S_ISREG(st.st_mode));
    return !simcore::findScene(scene) && file ? scene : std::string();
}

namespace {

std::optional<std::string> prefixed(const std::string& prefix, std::optional<std::string> error) {
    if (error) return prefix + *error;
    return error;
}

std::string severalBodiesMessage(const std::string& scene) {
    return quoted(scene, 200) + " is a scene of several bodies: `run`, `params`, `stability`, `study` (work-precision "
                                "and --refine), the window and elasticlab.World take it; this command studies one body (" +
           simcore::sceneNames() + ")";
}

// Each assignment key=value, each key once (a key given twice is a mistake, as in a scene file:
// neither value is picked silently), dt given once; returns the keys given.
std::set<std::string> checkAssignments(const SceneRequest& request) {
    std::set<std::string> given;
    for (const std::string& assignment : request.set) {
        const auto eq = assignment.find('=');
        if (eq == std::string::npos || eq == 0) refuse("--set: expected key=value, got " + quoted(assignment));
        const std::string key = assignment.substr(0, eq);
        if (!given.insert(key).second) refuse("--set " + quoted(key) + " is given twice; give each parameter once");
    }
    if (request.dt && given.contains("dt")) refuse("--dt and --set dt both give the step; give it once");
    return given;
}

}  // namespace

SceneSetup resolveWorld(simcore::WorldSpec spec, const SceneRequest& request, SceneSetup setup) {
    checkAssignments(request);
    // bodyN.key=value sets body N, key=value every body (so one-body settings read as before).
    for (const std::string& assignment : request.set) refuseIf(prefixed("--set ", simcore::assignWorld(spec, assignment)));
    if (request.dt) refuseIf(prefixed("--", simcore::assignWorld(spec, "dt=" + *request.dt)));
    refuseIf(simcore::validateWorld(spec));
    const std::string fileIntegrator = setup.file ? setup.file->integrator : std::string();
    setup.integrator = request.integrator.value_or(fileIntegrator.empty() ? "rk4" : fileIntegrator);
    refuseIf(simcore::unknownIntegrator(setup.integrator));
    if (setup.sceneName.empty() || !setup.file) setup.sceneName = spec.name;
    setup.params = spec.bodies.front().params;  // the world's shared values (dt, gravity, box) as body 1 has them
    setup.world = std::move(spec);
    return setup;
}

SceneSetup resolveScene(const SceneRequest& request) {
    SceneSetup setup;
    setup.sceneName = request.scene;
    std::string fileIntegrator;
    setup.sceneFile = sceneFileOf(request.scene);
    if (!setup.sceneFile.empty()) {
        // A scene file wherever a scene name is taken; the assignments, dt and the integrator
        // override what it holds.
        simlab::SceneFileResult read = simlab::readSceneFile(setup.sceneFile);
        if (!read.file) refuse(read.error);
        setup.sceneName = read.file->sceneName;
        setup.params = read.file->params;
        fileIntegrator = read.file->integrator;
        setup.state = read.file->state;
        std::optional<simcore::WorldSpec> world = read.file->world;
        setup.file = std::move(read.file);
        if (world) {
            if (!request.severalBodies) refuse(severalBodiesMessage(request.scene));
            return resolveWorld(std::move(*world), request, std::move(setup));
        }
    } else if (const simcore::SceneInfo* scene = simcore::findScene(request.scene)) {
        setup.params = request.base && request.base->kind() == scene->kind ? *request.base : simcore::ParameterSet(scene->kind);
    } else if (auto world = request.baseWorld ? request.baseWorld : simcore::worldScene(request.scene)) {
        if (!request.severalBodies) refuse(severalBodiesMessage(request.scene));
        return resolveWorld(std::move(*world), request, std::move(setup));
    } else {
        refuse(simcore::unknownSceneMessage(request.scene) + ", or a scene file (.json)");
    }
    const std::set<std::string> given = checkAssignments(request);
    for (const std::string& assignment : request.set)
        if (auto error = setup.params.assign(assignment)) refuse("--set " + *error);
    if (request.dt)
        if (auto error = setup.params.setFromText("dt", *request.dt)) refuse("--" + *error);
    setup.integrator = request.integrator.value_or(fileIntegrator.empty() ? "rk4" : fileIntegrator);
    refuseIf(simcore::unknownIntegrator(setup.integrator));
    refuseIf(simcore::validateShape(setup.params, setup.integrator));
    if (setup.state && simcore::bodySize(setup.params).particles != setup.state->positions.cols())
        refuse("--set changes the shape of the body in " + quoted(setup.sceneFile, 200) +
               ", so its saved state no longer fits");
    return setup;
}

namespace {
void checkLaneCount(const std::vector<std::string>& integrators) {
    checkIntegrators(integrators);
    if (integrators.size() > 3)
        refuse("--compare takes one to three integrators, got " + std::to_string(integrators.size()));
}
}  // namespace

void checkLanes(const simcore::ParameterSet& params, const std::vector<std::string>& integrators) {
    checkLaneCount(integrators);
    for (const std::string& name : integrators) refuseIf(simcore::validateShape(params, name));
}

void checkLanes(const simcore::WorldSpec& world, const std::vector<std::string>& integrators) {
    checkLaneCount(integrators);
    checkWorldIntegrators(world, integrators);
}

// --- files -------------------------------------------------------------------------------------------

void checkOutputNamed(const std::string& option, const std::optional<std::string>& path) {
    if (path && path->empty()) refuse("--" + option + ": an empty file name; give a file name or leave --" + option + " out");
}

void checkFiles(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
    std::vector<NamedPath> all;
    for (const NamedPath& in : inputs)
        if (!in.second.empty()) all.push_back(in);
    for (const NamedPath& out : outputs) {
        if (out.second.empty()) continue;
        // What an existing output is: a FIFO would block the tool (or a reader) for ever, a
        // folder or socket cannot hold a table.
        // A standard stream already open (--csv - or /dev/stdout into a pipe) never blocks.
        struct stat st {};
        if (!simlab::standardStream(out.second) && ::stat(out.second.c_str(), &st) == 0 && !S_ISREG(st.st_mode) &&
            !S_ISCHR(st.st_mode))
            refuse("--" + out.first + " " + quoted(out.second, 200) + " is " +
                   (S_ISDIR(st.st_mode) ? "a folder" : S_ISFIFO(st.st_mode) ? "a FIFO" : "not a regular file") +
                   "; an output is a regular file, a terminal or another character device");
        all.push_back(out);
    }
    refuseIf(simlab::fileClash(all));
}

// --- the work ----------------------------------------------------------------------------------------

std::optional<std::string> precisionProblem(const std::string& precision, const std::string& integrator) {
    if (precision != "double" && precision != "float")
        return "unknown precision " + quoted(precision) + "; allowed: double, float";
    if (precision != "float") return std::nullopt;
    if (std::string refusal = simcore::floatPathIntegratorRefusal(integrator); !refusal.empty()) return refusal;
    return std::nullopt;
}

void checkPrecision(const std::string& precision, const std::string& integrator) {
    refuseIf(precisionProblem(precision, integrator));
}

void checkPrecision(const SceneSetup& scene, const std::string& precision, const std::string& integrator) {
    checkPrecision(precision, integrator);
    if (scene.world && precision == "float")
        refuse("precision float takes scenes of one body (the float path is built for one); " + quoted(scene.sceneName) +
               " has " + std::to_string(scene.world->bodies.size()) + " bodies");
}

void checkRun(const SceneSetup& scene, const RunRequest& run) {
    checkPrecision(scene, run.precision, scene.integrator);
    // The range the message states (the CLI's and Python's own checks say the same; the front
    // door must not rely on them: fuzz_request found an adaptive run of 1e300 s accepted here).
    if (!(run.duration > 0.0) || !(run.duration <= 1e7))
        refuse("duration " + number(run.duration) + " s is not allowed; allowed (0, 1e+07] s");
    // A fixed-step run takes duration / dt steps: bounded, so that a typo (dt 1e-300) is
    // refused at once instead of running for ever. An adaptive one stops at the bound (exit 3).
    const double dt = scene.params.get(simcore::Param::Dt);
    const bool fixed = !simcore::makeIntegrator(scene.integrator)->adaptive() || run.options.fixedStep;
    const double steps = std::ceil(run.duration / dt - 1e-9);
    if (fixed)
        checkSteps(steps, "duration " + number(run.duration) + " s at dt " + number(dt) + " s",
                   "use a larger dt, a shorter duration or an adaptive integrator", run.maxSteps);
    if (run.rowsEvery > 0) {
        // Rows kept in memory: one every rowsEvery steps (an adaptive run: at most maxSteps).
        const double rows = std::min(fixed ? steps : run.maxSteps, run.maxSteps) / double(run.rowsEvery) + 2.0;
        checkHeld(rows * std::max(1, run.rowColumns) * 8.0,
                  "a row every " + std::to_string(run.rowsEvery) + " steps over " + number(fixed ? steps : run.maxSteps) +
                      " steps",
                  "a larger every, or a shorter duration");
    }
    if (run.sampleEvery > 0.0) {
        const double rows = std::floor(run.duration / run.sampleEvery + 1e-9) + 2.0;
        checkHeld(rows * std::max(1, run.rowColumns) * 8.0,
                  "a row every " + number(run.sampleEvery) + " s over " + number(run.duration) + " s",
                  "a larger every, or a shorter duration");
    }
}

void checkIntegrators(const std::vector<std::string>& names) {
    if (names.empty()) refuse("no integrators given; allowed: " + simcore::integratorNames());
    std::set<std::string> seen;
    for (const std::string& name : names) {
        refuseIf(simcore::unknownIntegrator(name));
        if (!seen.insert(name).second) refuse("integrator " + quoted(name) + " is listed twice");
    }
}

void checkStudy(const simlab::StudySpec& spec) {
    checkIntegrators(spec.integrators);
    refuseIf(simlab::validateStudy(spec));
    if (spec.world) checkWorldIntegrators(*spec.world, spec.integrators);
    else
        for (const std::string& name : spec.integrators) refuseIf(simcore::validateShape(spec.params, name));
    // Every run, the reference (16x below the smallest step) and its check run bounded.
    const double T = spec.duration;
    for (double dt : spec.dts)
        checkSteps(T / dt, "a run at dt " + number(dt) + " s over duration " + number(T) + " s",
                   "larger steps or a shorter duration");
    if (const double h = simlab::studyReferenceStep(spec); h > 0.0)
        checkSteps(T / h,
                   "the rk4 reference at dt " + number(h) + " s (16x below the smallest step) over duration " + number(T) + " s",
                   spec.dts.empty() ? "give larger steps with dts, a shorter duration, or reference rk45 or cvode-bdf"
                                    : "larger steps or a shorter duration");
    // Held: the reference's positions on the grid, a run's and the reference's check run.
    double particles = 0.0;
    if (spec.world)
        for (const simcore::WorldBodySpec& body : spec.world->bodies)
            particles += static_cast<double>(simcore::bodySize(body.params).particles);
    else
        particles = static_cast<double>(simcore::bodySize(spec.params).particles);
    const double samples = static_cast<double>(simlab::studyGrid(spec).size());
    checkHeld(3.0 * samples * particles * 3.0 * 8.0,
              "the study's trajectories (" + number(samples) + " samples of " + number(particles) + " particles)",
              "fewer samples or a smaller body");
}

void checkRefinement(const simlab::RefinementSpec& spec) {
    refuseIf(simlab::validateRefinement(spec));
    const double T = spec.duration;
    const double points = std::round(T / spec.interval) + 1.0;
    const double runs = static_cast<double>(spec.values.size()) + spec.temporalRuns + 1.0;
    const double bodies = spec.world ? static_cast<double>(spec.world->bodies.size()) : 1.0;
    checkHeld(points * runs * 64.0 * bodies, "the refinement's output grid (" + number(points) + " times, " + number(runs) + " runs)",
              "a longer interval or a shorter duration");
    for (int value : spec.values)
        if (spec.world) checkWorldIntegrators(simlab::refinementWorld(spec, value), {spec.integrator});
        else refuseIf(simcore::validateShape(simlab::refinementLevel(spec, value), spec.integrator));
    const auto [dt, rule] = simlab::refinementStep(spec);
    if (dt > 0.0 && !(spec.integrator == "rk45" && !spec.options.fixedStep))
        checkSteps(T / dt, "each level at dt " + number(dt) + " s over duration " + number(T) + " s",
                   "a larger dt or a shorter duration");
}

void checkWorldIntegrators(const simcore::WorldSpec& world, const std::vector<std::string>& names) {
    for (const std::string& name : names) {
        for (std::size_t k = 0; k < world.bodies.size(); ++k)
            refuseIf(prefixed("body" + std::to_string(k + 1) + ": ", simcore::validateShape(world.bodies[k].params, name)));
        // What only the built world knows (xpbd's one set of springs for every body).
        try {
            const simcore::World probe(world, name);
        } catch (const std::invalid_argument& e) {
            refuse(e.what());
        }
    }
}

void checkStability(const simlab::StabilitySpec& spec) {
    checkIntegrators(spec.integrators);
    // The ranges the CLI's and Python's options state, held here too (fuzz_request found
    // hmin = -1 with hmax = inf accepted: a negative trial count passed the step bound).
    if (!(spec.duration > 0.0 && spec.duration <= 1e5))
        refuse("duration = " + number(spec.duration) + " is out of range; allowed (0, 1e+05] s");
    if (!(spec.hMin > 0.0 && spec.hMin <= 1.0)) refuse("hmin = " + number(spec.hMin) + " is out of range; allowed (0, 1] s");
    if (!(spec.hMax > 0.0 && spec.hMax <= 1.0)) refuse("hmax = " + number(spec.hMax) + " is out of range; allowed (0, 1] s");
    if (spec.hMax < spec.hMin) refuse("hmax " + number(spec.hMax) + " s is below hmin " + number(spec.hMin) + " s");
    // A trial at the smallest step takes duration / hmin steps.
    checkSteps(spec.duration / spec.hMin,
               "a trial of duration " + number(spec.duration) + " s at hmin " + number(spec.hMin) + " s",
               "raise hmin or shorten the duration");
    // A trial too short to grow shows nothing: a duration of 1e-300 s called every method
    // stable up to hmax.
    if (spec.duration < kMinTrialSteps * spec.hMin)
        refuse("duration " + number(spec.duration) + " s is too short to judge a step: a trial at hmin " + number(spec.hMin) +
               " s must take at least " + number(kMinTrialSteps) + " steps (lengthen the duration to " +
               number(kMinTrialSteps * spec.hMin) + " s or more, or lower hmin)");
    if (spec.world) return checkWorldIntegrators(*spec.world, spec.integrators);
    for (const std::string& name : spec.integrators) refuseIf(simcore::validateShape(spec.params, name));
}

void checkConservation(const simlab::ConservationSpec& spec) {
    if (spec.world) refuse(severalBodiesMessage(spec.world->name));
    checkIntegrators(spec.integrators);
    refuseIf(simlab::validateConservation(spec));
    for (const std::string& name : spec.integrators) refuseIf(simcore::validateShape(spec.params, name));
}

void checkSweep(simlab::SweepSpec& spec) { refuseIf(simlab::validateSweep(spec)); }

void checkRestitution(const simcore::ParameterSet& params, const std::vector<double>& speeds) {
    for (double speed : speeds) {
        if (!(speed > 0.0 && speed <= 1e4))
            refuse("speeds: every speed must be in (0, 10000] m/s, got " + number(speed));
        const double dt = std::min(params.get(simcore::Param::Dt), 3e-4 / speed);
        checkSteps(10.0 / dt, "the impact at " + number(speed) + " m/s (10 s at dt " + number(dt) + " s)",
                   "a larger dt or lower speeds");
        const double particles = static_cast<double>(simcore::bodySize(params).particles);
        if (10.0 / dt * particles > kMaxParticleSteps)
            refuse("the impact at " + number(speed) + " m/s (10 s at dt " + number(dt) + " s) would take " +
                   number(10.0 / dt) + " steps of " + number(particles) + " particles; at most " +
                   number(kMaxParticleSteps) + " particle-steps per speed (a larger dt, lower speeds or a smaller body)");
    }
}

}  // namespace simlab
