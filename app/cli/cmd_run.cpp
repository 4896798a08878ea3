// `run`: one headless simulation, with a CSV time series and the final state.
#include <array>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <cmath>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/cli.h"
#include "simcore/integrator_table.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/output.h"

namespace cli {

namespace {

void printSummary(const simcore::Simulation& sim, const SceneSetup& setup, double wallSeconds) {
    const simcore::Diagnostics& d = sim.diagnostics();
    const simcore::Topology& topo = sim.topology();
    std::printf("scene        %s (%d particles, %zu springs, %zu surfaces)\n", setup.sceneName.c_str(),
                topo.particleCount(), topo.springCount(), topo.surfaces.size());
    std::printf("integrator   %s, dt %g s, %ld steps, t = %g s\n",
                std::string(sim.integrator().name()).c_str(), sim.dt(), d.step, d.time);
    std::printf("energy       kinetic %.6g J, spring %.6g J, gravity %.6g J", d.kinetic,
                d.springTotal(), d.gravity);
    if (d.hasGas) std::printf(", gas %.6g J", d.gas);
    if (!sim.contactProjection()) std::printf(", contact %.6g J", d.contact);
    std::printf(", total %.6g J\n", d.total());
    if (sim.contactProjection())
        std::printf("removed      damping %.6g J, collisions (projection) %.6g J; balance drift %.3g J\n",
                    d.removedDamping, d.removedCollisions, d.energyDrift());
    else
        std::printf("removed      damping %.6g J, contact %.6g J; balance drift %.3g J\n", d.removedDamping,
                    d.removedContact, d.energyDrift());
    if (d.hasGas)
        std::printf("layers       volume inner %.6g, outer %.6g; pressure inner %.6g, outer %.6g\n",
                    d.volume[0], d.volume[1], d.pressure[0], d.pressure[1]);
    std::printf("cost         %llu force evaluations, %.3f s wall, %.0f steps/s\n",
                static_cast<unsigned long long>(d.forceEvaluations), wallSeconds,
                wallSeconds > 0 ? static_cast<double>(d.step) / wallSeconds : 0.0);
    if (d.hasSolverCounters) {
        const simcore::SolverCounters& c = d.solver;
        std::printf("solver       %ld steps, %ld RHS evaluations, %ld Jacobian-vector products, %ld linear "
                    "iterations (+%ld CG in the preconditioner), %ld nonlinear iterations\n",
                    c.steps, c.rhsEvaluations, c.jacobianProducts, c.linearIterations, c.preconditionerIterations,
                    c.nonlinearIterations);
        std::printf("             %ld error-test failures, %ld convergence failures, %ld re-initialisations; "
                    "order %d, step %g s\n",
                    c.errorTestFailures, c.convergenceFailures, c.reinitialisations, c.order, c.step);
    }
}

// --json: the summary as one JSON object (SI units, as the text's), whatever the run's end:
// "status" is ok, failed (with "failure": reason, step, time) or stopped (--max-steps).
void printSummaryJson(const simcore::Simulation& sim, const SceneSetup& setup, double wallSeconds, const std::string& status) {
    const simcore::Diagnostics& d = sim.diagnostics();
    const simcore::Topology& topo = sim.topology();
    nlohmann::ordered_json j = {
        {"scene", setup.sceneName},
        {"particles", topo.particleCount()},
        {"springs", topo.springCount()},
        {"surfaces", topo.surfaces.size()},
        {"integrator", sim.integrator().name()},
        {"dt", sim.dt()},
        {"steps", d.step},
        {"t", d.time},
        {"status", status},
    };
    if (sim.failure())
        j["failure"] = {{"reason", sim.failure()->reason}, {"step", sim.failure()->step}, {"time", sim.failure()->time}};
    nlohmann::ordered_json energy = {{"kinetic", d.kinetic}, {"spring", d.springTotal()}, {"gravity", d.gravity}};
    if (d.hasGas) energy["gas"] = d.gas;
    if (!sim.contactProjection()) energy["contact"] = d.contact;
    energy["total"] = d.total();
    j["energy"] = energy;
    j["removed"] = sim.contactProjection()
                       ? nlohmann::ordered_json{{"damping", d.removedDamping}, {"collisions", d.removedCollisions}}
                       : nlohmann::ordered_json{{"damping", d.removedDamping}, {"contact", d.removedContact}};
    j["energy_drift"] = d.energyDrift();
    if (d.hasGas)
        j["layers"] = {{"volume_inner", d.volume[0]}, {"volume_outer", d.volume[1]},
                       {"pressure_inner", d.pressure[0]}, {"pressure_outer", d.pressure[1]}};
    j["cost"] = {{"force_evaluations", d.forceEvaluations}, {"wall_seconds", wallSeconds},
                 {"steps_per_second", wallSeconds > 0 ? static_cast<double>(d.step) / wallSeconds : 0.0}};
    if (d.hasSolverCounters) {
        const simcore::SolverCounters& c = d.solver;
        j["solver"] = {{"steps", c.steps}, {"rhs_evaluations", c.rhsEvaluations}, {"jacobian_products", c.jacobianProducts},
                       {"linear_iterations", c.linearIterations}, {"preconditioner_iterations", c.preconditionerIterations},
                       {"nonlinear_iterations", c.nonlinearIterations}, {"error_test_failures", c.errorTestFailures},
                       {"convergence_failures", c.convergenceFailures}, {"reinitialisations", c.reinitialisations},
                       {"order", c.order}, {"step", c.step}};
    }
    printJson(j);
}

struct RunArgs {
    SceneArgs scene;
    double duration = 5.0;
    long every = 1;
    double maxSteps = kMaxSteps;
    std::string csv, state, saveScene;
    bool quiet = false, json = false;
    simcore::IntegratorOptions integrator;
    SceneSetup setup;  // after check()
    // A scene of several bodies (collide2d, collide3d, stack3d, or a scene file of several), after
    // check(), and the state a scene file saved with it.
    std::optional<simcore::WorldSpec> world;
    std::optional<simlab::SceneFile::State> worldState;
};

// The run's fixed-step bound: a fixed-step run takes duration / dt steps, refused at once when
// that is more than --max-steps (a typo such as --dt 1e-300 would otherwise run for ever).
void checkStepBound(const RunArgs& args, std::string_view integrator, double dt) {
    if (simcore::makeIntegrator(integrator)->adaptive() && !args.integrator.fixedStep) return;
    const double steps = std::ceil(args.duration / dt - 1e-9);
    if (steps > args.maxSteps) {
        char text[300];
        std::snprintf(text, sizeof text,
                      "--duration %g s at dt %g s would take %.3g steps; at most %.0f per run (use a larger --dt, "
                      "a shorter --duration, or an adaptive integrator; --max-steps raises the limit)",
                      args.duration, dt, steps, args.maxSteps);
        throw UsageError(text);
    }
}

// A scene of several bodies: its description with every --set applied (bodyN.key=value for
// one body, key=value for all), checked as a whole (simcore::validateWorld).
void checkWorld(RunArgs& args, simcore::WorldSpec spec, const std::string& fileIntegrator = "rk4") {
    for (const std::string& assignment : args.scene.set)
        if (auto error = simcore::assignWorld(spec, assignment)) throw UsageError("--set " + *error);
    if (args.scene.dt)
        if (auto error = simcore::assignWorld(spec, "dt=" + *args.scene.dt)) throw UsageError("--" + *error);
    args.setup.sceneName = spec.name;
    args.setup.integrator = args.scene.integrator.value_or(fileIntegrator);
    if (auto error = simcore::unknownIntegrator(args.setup.integrator)) throw UsageError(*error);
    if (auto error = simcore::validateWorld(spec)) throw UsageError(*error);
    checkStepBound(args, args.setup.integrator, simcore::resolve(spec.bodies.front().params).time.dt);
    args.world = std::move(spec);
}

void checkRun(RunArgs& args) {
    checkDistinctFiles({{"scene", sceneFileOf(args.scene)}, {"csv", args.csv}, {"state", args.state},
                        {"save-scene", args.saveScene}});
    if (auto world = simcore::worldScene(args.scene.scene)) {
        checkWorld(args, std::move(*world));
        return;
    }
    if (const std::string path = sceneFileOf(args.scene); !path.empty()) {
        simlab::SceneFileResult read = simlab::readSceneFile(path);
        if (!read.file) throw UsageError(read.error);
        if (read.file->world) {  // a scene file of several bodies, perhaps with its state
            args.worldState = read.file->state;
            checkWorld(args, std::move(*read.file->world), read.file->integrator);
            return;
        }
    }
    args.setup = sceneSetup(args.scene);
    checkStepBound(args, args.setup.integrator, args.setup.params.get(simcore::Param::Dt));
}

// Steps until the end of the run, handing each step's state to `row` every --every steps and
// at the last; returns whether the run stopped at --max-steps.
template <class Sim, class Row>
bool stepThrough(Sim& sim, const RunArgs& args, double tEnd, Row&& row) {
    // An adaptive method chooses its own steps: the same bound holds while it runs (a
    // tolerance it cannot meet ends the run, exit 3, instead of creeping on for ever).
    const long firstStep = sim.stepCount();
    while (sim.time() < tEnd - 1e-9 * sim.dt()) {
        if (!sim.step(tEnd)) break;
        const bool last = sim.time() >= tEnd - 1e-9 * sim.dt();
        if (sim.stepCount() % args.every == 0 || last) row();
        if (static_cast<double>(sim.stepCount() - firstStep) >= args.maxSteps && !last) return true;
    }
    return false;
}

// Opens every output before running: an unwritable path is bad input, found at once.
using Outputs = std::array<std::unique_ptr<simlab::AtomicFile>, 3>;  // csv, state, scene
Outputs openOutputs(const RunArgs& args) {
    Outputs files;
    const std::array<const std::string*, 3> paths = {&args.csv, &args.state, &args.saveScene};
    for (std::size_t k = 0; k < paths.size(); ++k) {
        if (paths[k]->empty()) continue;
        files[k] = std::make_unique<simlab::AtomicFile>(*paths[k]);
        if (!files[k]->ok()) throw UsageError(files[k]->error());
    }
    return files;
}

// Commits the outputs; false (reported) when one cannot be written.
bool commitOutputs(const Outputs& files) {
    for (const auto& file : files)
        if (file && !file->commit()) {
            std::fprintf(stderr, "error: %s\n", file->error().c_str());
            return false;
        }
    return true;
}

void printWorldSummary(const simcore::World& world, double wallSeconds) {
    const simcore::WorldDiagnostics& d = world.diagnostics();
    std::printf("scene        %s (%d bodies, %d particles)\n", world.spec().name.c_str(), world.bodyCount(),
                world.particleCount());
    std::printf("integrator   %s, dt %g s, %ld steps, t = %g s\n", std::string(world.integrator().name()).c_str(),
                world.dt(), d.step, d.time);
    std::printf("energy       kinetic %.6g J, spring %.6g J, gravity %.6g J, gas %.6g J, contact %.6g J (between "
                "bodies %.6g J), total %.6g J\n",
                d.kinetic, d.springTotal(), d.gravity, d.gas, d.contact, d.contactPairs, d.total());
    std::printf("removed      damping %.6g J, contact %.6g J; balance drift %.3g J\n", d.removedDamping,
                d.removedContact, d.energyDrift());
    for (int k = 0; k < world.bodyCount(); ++k) {
        const simcore::BodyDiagnostics& b = d.bodies[static_cast<std::size_t>(k)];
        std::printf("body %-7d mass %.6g kg, centre (%.6g, %.6g, %.6g) m, velocity (%.6g, %.6g, %.6g) m/s, volume "
                    "inner %.6g, outer %.6g\n",
                    k + 1, b.mass, b.com.x(), b.com.y(), b.com.z(), b.velocity.x(), b.velocity.y(), b.velocity.z(),
                    b.volume[0], b.volume[1]);
    }
    std::printf("momentum     (%.9g, %.9g, %.9g) kg m/s; min gap %.6g m\n", d.momentum.x(), d.momentum.y(),
                d.momentum.z(), d.minGap);
    std::printf("cost         %llu force evaluations, %.3f s wall, %.0f steps/s\n",
                static_cast<unsigned long long>(d.forceEvaluations), wallSeconds,
                wallSeconds > 0 ? static_cast<double>(d.step) / wallSeconds : 0.0);
}

// --json for a scene of several bodies: the world's totals, then each body's.
void printWorldSummaryJson(const simcore::World& world, double wallSeconds, const std::string& status) {
    const simcore::WorldDiagnostics& d = world.diagnostics();
    const auto vec = [](const Eigen::Vector3d& v) { return nlohmann::ordered_json{v.x(), v.y(), v.z()}; };
    nlohmann::ordered_json j = {{"scene", world.spec().name}, {"bodies_count", world.bodyCount()},
                                {"particles", world.particleCount()}, {"integrator", world.integrator().name()},
                                {"dt", world.dt()}, {"steps", d.step}, {"t", d.time}, {"status", status}};
    if (world.failed())
        j["failure"] = {{"reason", *world.failure()}, {"step", world.failedStep()}, {"time", world.failedTime()}};
    j["energy"] = {{"kinetic", d.kinetic}, {"spring", d.springTotal()}, {"gravity", d.gravity}, {"gas", d.gas},
                   {"contact", d.contact}, {"contact_bodies", d.contactPairs}, {"total", d.total()}};
    j["removed"] = {{"damping", d.removedDamping}, {"contact", d.removedContact}};
    j["energy_drift"] = d.energyDrift();
    j["momentum"] = vec(d.momentum);
    j["angular_momentum"] = vec(d.angularMomentum);
    j["min_gap"] = d.minGap;
    nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
    for (const simcore::BodyDiagnostics& b : d.bodies)
        bodies.push_back({{"mass", b.mass}, {"com", vec(b.com)}, {"velocity", vec(b.velocity)},
                          {"volume_inner", b.volume[0]}, {"volume_outer", b.volume[1]},
                          {"pressure_inner", b.pressure[0]}, {"pressure_outer", b.pressure[1]}});
    j["bodies"] = bodies;
    j["cost"] = {{"force_evaluations", d.forceEvaluations}, {"wall_seconds", wallSeconds},
                 {"steps_per_second", wallSeconds > 0 ? static_cast<double>(d.step) / wallSeconds : 0.0}};
    printJson(j);
}

int runWorld(const RunArgs& args) {
    const Outputs files = openOutputs(args);
    std::optional<simcore::World> built;
    try {
        built.emplace(*args.world, args.setup.integrator);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    simcore::World& world = *built;
    world.setIntegratorOptions(args.integrator);
    if (args.worldState)  // resume a saved experiment
        if (auto error = simlab::applyState(world, *args.worldState)) throw UsageError(*error);
    const auto columns = simlab::worldColumns(world);
    auto& csv = files[0];
    if (csv) {
        csv->write(simlab::csvHeader(columns));
        csv->write(simlab::csvRow(columns, world.diagnostics()));
    }
    const auto start = std::chrono::steady_clock::now();
    const double tEnd = world.time() + args.duration;  // a resumed run continues from its saved time
    const bool tooManySteps = stepThrough(world, args, tEnd, [&] {
        if (csv) csv->write(simlab::csvRow(columns, world.diagnostics()));
    });
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (files[1]) files[1]->write(simlab::stateTable(world));
    if (files[2]) files[2]->write(simlab::sceneFileText(world, true));
    if (!commitOutputs(files)) return kExitBadInput;
    if (args.json)
        printWorldSummaryJson(world, wall, world.failed() ? "failed" : tooManySteps ? "stopped" : "ok");
    else if (!args.quiet)
        printWorldSummary(world, wall);
    if (tooManySteps) {
        std::fprintf(stderr, "run stopped at step %ld, t = %g s: %.0f steps taken, the most one run may take "
                             "(--max-steps); the files hold the run so far\n",
                     world.stepCount(), world.time(), args.maxSteps);
        return kExitFailed;
    }
    if (world.failed()) {
        std::fprintf(stderr, "simulation failed at step %ld, t = %g s: %s\n", world.failedStep(), world.failedTime(),
                     world.failure()->c_str());
        return kExitFailed;
    }
    return kExitOk;
}

int run(const RunArgs& args) {
    if (args.world) return runWorld(args);
    const SceneSetup& setup = args.setup;
    const double duration = args.duration;
    const Outputs files = openOutputs(args);
    auto& csv = files[0];
    auto& state = files[1];
    auto& sceneOut = files[2];

    simcore::Simulation sim(setup.params, setup.integrator);
    sim.setIntegratorOptions(args.integrator);
    if (setup.state)  // resume a saved experiment
        if (auto error = simlab::applyState(sim, *setup.state)) throw UsageError(*error);
    if (const std::string warning = stabilityWarning(setup.params, setup.integrator); !warning.empty())
        std::fprintf(stderr, "%s\n", warning.c_str());

    const auto columns = simlab::timeSeriesColumns(setup.params.kind(), sim.diagnostics().hasSolverCounters);
    if (csv) {
        csv->write(simlab::csvHeader(columns));
        csv->write(simlab::csvRow(columns, sim.diagnostics()));
    }
    const auto start = std::chrono::steady_clock::now();
    const double tEnd = sim.time() + duration;  // a resumed run continues from its saved time
    const bool tooManySteps = stepThrough(sim, args, tEnd, [&] {
        if (csv) csv->write(simlab::csvRow(columns, sim.diagnostics()));
    });
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (state) state->write(simlab::stateTable(sim));
    if (sceneOut) sceneOut->write(simlab::sceneFileText(sim, setup.sceneName, true));
    if (!commitOutputs(files)) return kExitBadInput;
    if (args.json)
        printSummaryJson(sim, setup, wall, sim.failed() ? "failed" : tooManySteps ? "stopped" : "ok");
    else if (!args.quiet)
        printSummary(sim, setup, wall);
    // The rule for the last step: a fixed-step run takes whole steps until t >= the end, so a
    // duration that is not a multiple of dt ends past it; it is said, never silent.
    if (!sim.failed() && sim.time() > tEnd + 1e-9 * sim.dt())
        std::fprintf(stderr,
                     "note: --duration %g s is not a multiple of dt %g s: the run took whole steps and ended at "
                     "t = %g s, %g s past the end asked for\n",
                     duration, sim.dt(), sim.time(), sim.time() - tEnd);
    if (tooManySteps) {
        std::fprintf(stderr, "run stopped at step %ld, t = %g s: %.0f steps taken, the most one run may take (--max-steps; "
                             "loosen --rtol/--atol or shorten --duration); the files hold the run so far\n",
                     sim.stepCount(), sim.time(), args.maxSteps);
        return kExitFailed;
    }
    if (sim.failed()) {
        const simcore::Failure& f = *sim.failure();
        std::fprintf(stderr, "simulation failed at step %ld, t = %g s: %s\n", f.step, f.time,
                     f.reason.c_str());
        return kExitFailed;
    }
    return kExitOk;
}

}  // namespace

Command addRunCommand(CLI::App& app) {
    auto args = std::make_shared<RunArgs>();
    CLI::App* sub = app.add_subcommand("run", "run one scene headless: a CSV row every N steps, the final state table, "
                                              "a summary of energy, volume and cost. Scenes of several bodies "
                                              "(collide2d, collide3d, stack3d) take --set bodyN.key=value for body N "
                                              "(from 1; key=value sets every body) and position_x/y/z, velocity_x/y/z");
    addSceneOptions(*sub, args->scene);
    sub->add_option("--duration", args->duration, "simulated time to run [s] (a resumed scene file runs on from its time)")
        ->type_name("T")
        ->check(finiteIn(0.0, 1e7, true))
        ->capture_default_str();
    addCsvOption(*sub, args->csv, "write the time series (one row per --every steps and the last)");
    sub->add_option("--every", args->every, "CSV row every N steps")->type_name("N")->check(wholeIn(1, 1000000000L))->capture_default_str();
    sub->add_option("--state", args->state, "write the final state: index, layer, position, velocity")->type_name("FILE");
    sub->add_option("--save-scene", args->saveScene, "save the experiment with its final state as a scene file")
        ->type_name("FILE.json");
    sub->add_option("--max-steps", args->maxSteps, "the most steps the run may take: a fixed-step run that needs more is "
                                                   "refused before it starts, an adaptive one stops there (exit 3)")
        ->type_name("N")
        ->check(finiteIn(1.0, 1e12, false))
        ->default_str("1e9");
    sub->add_flag("--quiet", args->quiet, "no summary on standard output");
    addJsonFlag(*sub, args->json);
    addIntegratorOptions(*sub, args->integrator);
    return {sub, [args] { checkRun(*args); }, [args] { return run(*args); }};
}

}  // namespace cli
