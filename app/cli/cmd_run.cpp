// `run`: one headless simulation, with a CSV time series and the final state.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "app/cli/cli.h"
#include "simcore/float_path.h"
#include "simcore/integrator_table.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/output.h"
#include "simlab/timeseries.h"

namespace cli {

namespace {

// What the summary reads of a finished run, in double or on the float path.
struct RunView {
    const simcore::Diagnostics& d;
    const simcore::Topology& topology;
    std::string integrator;
    double dt;
    bool contactProjection;
    const std::optional<simcore::Failure>& failure;
    std::string precision;
};

RunView viewOf(const simcore::Simulation& sim) {
    return {sim.diagnostics(), sim.topology(), std::string(sim.integrator().name()), sim.dt(),
            sim.contactProjection(), sim.failure(), "double"};
}
RunView viewOf(const simcore::FloatSimulation& single) {
    return {single.diagnostics(), single.topology(), std::string(single.integrator()), single.dt(), false,
            single.failure(), "float"};
}

void printSummary(const RunView& sim, const SceneSetup& setup, double wallSeconds) {
    const simcore::Diagnostics& d = sim.d;
    const simcore::Topology& topo = sim.topology;
    std::printf("scene        %s (%d particles, %zu springs, %zu surfaces)\n", setup.sceneName.c_str(),
                topo.particleCount(), topo.springCount(), topo.surfaces.size());
    std::printf("integrator   %s, dt %g s, %ld steps, t = %g s%s\n", sim.integrator.c_str(), sim.dt, d.step, d.time,
                sim.precision == "float" ? ", precision float" : "");
    std::printf("energy       kinetic %.6g J, spring %.6g J, gravity %.6g J", d.kinetic,
                d.springTotal(), d.gravity);
    if (d.hasGas) std::printf(", gas %.6g J", d.gas);
    if (!sim.contactProjection) std::printf(", contact %.6g J", d.contact);
    std::printf(", total %.6g J\n", d.total());
    if (sim.contactProjection)
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
void printSummaryJson(const RunView& sim, const SceneSetup& setup, double wallSeconds, const std::string& status) {
    const simcore::Diagnostics& d = sim.d;
    const simcore::Topology& topo = sim.topology;
    nlohmann::ordered_json j = {
        {"scene", setup.sceneName},
        {"particles", topo.particleCount()},
        {"springs", topo.springCount()},
        {"surfaces", topo.surfaces.size()},
        {"integrator", sim.integrator},
        {"precision", sim.precision},
        {"dt", sim.dt},
        {"steps", d.step},
        {"t", d.time},
        {"status", status},
    };
    if (sim.failure)
        j["failure"] = {{"reason", sim.failure->reason}, {"step", sim.failure->step}, {"time", sim.failure->time}};
    nlohmann::ordered_json energy = {{"kinetic", d.kinetic}, {"spring", d.springTotal()}, {"gravity", d.gravity}};
    if (d.hasGas) energy["gas"] = d.gas;
    if (!sim.contactProjection) energy["contact"] = d.contact;
    energy["total"] = d.total();
    j["energy"] = energy;
    j["removed"] = sim.contactProjection
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
    std::string csv, state, saveScene, xlsx;
    std::string dialectName = "plain";
    simlab::CsvDialect dialect = simlab::CsvDialect::Plain;  // after check()
    std::string precision = "double";
    bool quiet = false, json = false;
    simcore::IntegratorOptions integrator;
    SceneSetup setup;  // after check(); setup.world for a scene of several bodies
};

void checkRun(RunArgs& args) {
    checkFiles({{"scene", sceneFileOf(args.scene)}},
               {{"csv", args.csv}, {"xlsx", args.xlsx}, {"state", args.state}, {"save-scene", args.saveScene}});
    const auto dialect = simlab::csvDialectNamed(args.dialectName);
    if (!dialect) throw UsageError("--csv-dialect: " + simlab::unknownCsvDialectMessage(args.dialectName));
    args.dialect = *dialect;
    args.setup = sceneSetup(args.scene);
    if (args.setup.world) {
        // A world's CSV has per-body columns (simlab::worldColumns); the workbook and the
        // spreadsheet dialect are built for one body (the float path too: simlab::checkRun).
        for (const auto& [given, option] : {std::pair{!args.xlsx.empty(), "--xlsx"},
                                            {args.dialect != simlab::CsvDialect::Plain, "--csv-dialect excel-semicolon"}})
            if (given) throw UsageError(std::string(option) + " takes scenes of one body; " + args.setup.sceneName +
                                        " has " + std::to_string(args.setup.world->bodies.size()) + " bodies");
    }
    simlab::RunRequest request;  // the front door: steps, duration, precision
    request.precision = args.precision;
    request.duration = args.duration;
    request.maxSteps = args.maxSteps;
    request.options = args.integrator;
    simlab::checkRun(args.setup, request);
    if (!simcore::makeIntegrator(args.setup.integrator)->adaptive() || args.integrator.fixedStep) {
        const double dt = args.setup.params.get(simcore::Param::Dt);
        const double steps = std::ceil(args.duration / dt - 1e-9);
        // A workbook's sheet has room for 1048575 rows of data: the start, every N-th step and
        // the last must fit, or the run is refused before it starts (an adaptive run that
        // outgrows the sheet is told at the end, its CSV still written).
        const double rows = std::floor(steps / static_cast<double>(args.every)) + 2;
        if (!args.xlsx.empty() && rows > static_cast<double>(simlab::kXlsxMaxDataRows)) {
            char text[300];
            std::snprintf(text, sizeof text,
                          "--xlsx: %.0f rows (%.0f steps, a row every %ld) do not fit a sheet of %ld rows; use "
                          "--every %.0f or more",
                          rows, steps, args.every, simlab::kXlsxMaxDataRows,
                          std::ceil(steps / static_cast<double>(simlab::kXlsxMaxDataRows - 2)));
            throw UsageError(text);
        }
    }
}

// Steps `sim` until `tEnd`, handing each step to `row` every --every steps and at the last.
// Ctrl+C and SIGTERM (`signals`) stop it after a whole step; an adaptive method chooses its own
// steps, so the same bound holds while it runs (a tolerance it cannot meet ends the run, exit 3,
// instead of creeping on for ever).
struct Stepped {
    bool tooManySteps = false;
    int stoppedBy = 0;  // the signal that stopped the run, or 0
};
template <class Sim, class Row>
Stepped stepThrough(Sim& sim, const RunArgs& args, double tEnd, const StopSignals& signals, Row&& row) {
    Stepped out;
    const double tStart = sim.time();
    const long firstStep = sim.stepCount();
    ProgressLine progress(args.quiet || args.json);
    while (sim.time() < tEnd - 1e-9 * sim.dt()) {
        if (signals.caught()) break;
        if (!sim.step(tEnd)) break;
        const bool last = sim.time() >= tEnd - 1e-9 * sim.dt();
        if (sim.stepCount() % args.every == 0 || last) row();
        if (static_cast<double>(sim.stepCount() - firstStep) >= args.maxSteps && !last) {
            out.tooManySteps = true;
            break;
        }
        progress.update(sim.time() - tStart, tEnd - tStart, "s", sim.stepCount() - firstStep);
    }
    progress.clear();
    out.stoppedBy = signals.caught();
    return out;
}

// One body's run on the double path or on the float path (--precision float), as stepThrough
// steps it.
struct BodyStepper {
    simcore::Simulation& sim;
    simcore::FloatSimulation* single;  // null: the double path
    double time() const { return single ? single->time() : sim.time(); }
    long stepCount() const { return single ? single->stepCount() : sim.stepCount(); }
    double dt() const { return sim.dt(); }
    bool step(double tEnd) { return single ? single->step() : sim.step(tEnd); }
};

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

// Opens an output before running (an unwritable path is bad input, found at once); null when
// the option was not given.
std::unique_ptr<simlab::AtomicFile> openOutput(const std::string& path) {
    if (path.empty()) return nullptr;
    auto file = std::make_unique<simlab::AtomicFile>(path);
    if (!file->ok()) throw UsageError(file->error());
    return file;
}

// A scene of several bodies: its CSV with the per-body columns, the state with a body column,
// the scene file of every body; the same signals, bounds and all-or-none outputs as one body's.
int runWorld(const RunArgs& args) {
    const SceneSetup& setup = args.setup;
    const std::unique_ptr<simlab::AtomicFile> csv = openOutput(args.csv), state = openOutput(args.state),
                                              sceneOut = openOutput(args.saveScene);
    std::optional<simcore::World> built;
    try {
        built.emplace(*setup.world, setup.integrator);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    simcore::World& world = *built;
    world.setIntegratorOptions(args.integrator);
    if (setup.state)  // resume a saved experiment
        if (auto error = simlab::applyState(world, *setup.state)) throw UsageError(*error);
    const auto columns = simlab::worldColumns(world);
    if (csv) {
        csv->write(simlab::csvHeader(columns));
        csv->write(simlab::csvRow(columns, world.diagnostics()));
    }
    const auto start = std::chrono::steady_clock::now();
    const double tEnd = world.time() + args.duration;  // a resumed run continues from its saved time
    const StopSignals signals;  // Ctrl+C, SIGTERM: stop after a whole step, write the run so far
    const Stepped stepped = stepThrough(world, args, tEnd, signals, [&] {
        if (csv) csv->write(simlab::csvRow(columns, world.diagnostics()));
    });
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (state) state->write(simlab::stateTable(world));
    if (sceneOut) sceneOut->write(simlab::sceneFileText(world, true));
    if (auto error = simlab::commitAll({csv.get(), state.get(), sceneOut.get()})) {
        std::fprintf(stderr, "error: %s\n", error->c_str());
        return kExitBadInput;
    }
    const char* status = stepped.stoppedBy || stepped.tooManySteps ? "stopped" : world.failed() ? "failed" : "ok";
    if (args.json)
        printWorldSummaryJson(world, wall, status);
    else if (!args.quiet)
        printWorldSummary(world, wall);
    if (stepped.stoppedBy) {
        std::fprintf(stderr, "run stopped by %s at step %ld, t = %g s; the files hold the run so far\n",
                     StopSignals::name(stepped.stoppedBy), world.stepCount(), world.time());
        return 128 + stepped.stoppedBy;
    }
    if (stepped.tooManySteps) {
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

// All or none: every output (CSV, workbook, then `others`: state, scene) complete before the
// first replaces its file. The error, or nothing when every file is in place.
std::optional<std::string> commitOutputs(simlab::TimeSeriesWriter& series, std::vector<simlab::AtomicFile*> others) {
    if (!series.finish()) return series.error();
    std::vector<simlab::AtomicFile*> outputs = series.files();
    outputs.insert(outputs.end(), others.begin(), others.end());
    return simlab::commitAll(outputs);
}

int run(const RunArgs& args) {
    if (args.setup.world) return runWorld(args);
    const SceneSetup& setup = args.setup;
    const double duration = args.duration;
    const std::unique_ptr<simlab::AtomicFile> state = openOutput(args.state), sceneOut = openOutput(args.saveScene);

    simcore::Simulation sim(setup.params, setup.integrator);
    sim.setIntegratorOptions(args.integrator);
    if (setup.state)  // resume a saved experiment
        if (auto error = simlab::applyState(sim, *setup.state)) throw UsageError(*error);
    if (const std::string warning = stabilityWarning(setup.params, setup.integrator); !warning.empty())
        std::fprintf(stderr, "%s\n", warning.c_str());

    // --precision float: the float path from this state (float_path.h), stepped instead.
    std::unique_ptr<simcore::FloatSimulation> single;
    if (args.precision == "float") single = std::make_unique<simcore::FloatSimulation>(sim);
    auto diagnostics = [&]() -> const simcore::Diagnostics& { return single ? single->diagnostics() : sim.diagnostics(); };
    auto time = [&] { return single ? single->time() : sim.time(); };
    auto stepCount = [&] { return single ? single->stepCount() : sim.stepCount(); };
    auto failed = [&] { return single ? single->failed() : sim.failed(); };

    simlab::TimeSeriesWriter series(setup.params.kind(),
                                     simlab::timeSeriesColumns(setup.params.kind(), diagnostics().hasSolverCounters),
                                     {args.csv, args.dialect, args.xlsx});
    if (!series.ok()) throw UsageError(series.error());
    const bool recording = !args.csv.empty() || !args.xlsx.empty();
    if (recording) series.add(diagnostics());
    const auto start = std::chrono::steady_clock::now();
    const double tEnd = time() + duration;  // a resumed run continues from its saved time
    const StopSignals signals;  // Ctrl+C, SIGTERM: stop after a whole step, write the run so far
    BodyStepper stepper{sim, single.get()};
    const auto [tooManySteps, stoppedBy] = stepThrough(stepper, args, tEnd, signals, [&] {
        if (recording) series.add(diagnostics());
    });
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    // The state table and the scene file from the float state, in double (a saved scene
    // resumes on the double path unless run again with --precision float).
    if (single) single->writeStateTo(sim);
    if (state) state->write(simlab::inDialect(simlab::stateTable(sim), args.dialect, true));
    if (sceneOut) sceneOut->write(simlab::sceneFileText(sim, setup.sceneName, true));

    if (const std::optional<std::string> error = commitOutputs(series, {state.get(), sceneOut.get()})) {
        std::fprintf(stderr, "error: %s\n", error->c_str());
        return kExitBadInput;
    }
    const RunView view = single ? viewOf(*single) : viewOf(sim);
    if (stoppedBy) {
        if (args.json) printSummaryJson(view, setup, wall, "stopped");
        std::fprintf(stderr, "run stopped by %s at step %ld, t = %g s; the files hold the run so far\n",
                     StopSignals::name(stoppedBy), stepCount(), time());
        return 128 + stoppedBy;
    }
    if (args.json)
        printSummaryJson(view, setup, wall, failed() ? "failed" : tooManySteps ? "stopped" : "ok");
    else if (!args.quiet)
        printSummary(view, setup, wall);
    // The rule for the last step: a fixed-step run takes whole steps until t >= the end, so a
    // duration that is not a multiple of dt ends past it; it is said, never silent.
    if (!args.quiet && !failed() && time() > tEnd + 1e-9 * sim.dt())
        std::fprintf(stderr,
                     "note: --duration %g s is not a multiple of dt %g s: the run took whole steps and ended at "
                     "t = %g s, %g s past the end asked for\n",
                     duration, sim.dt(), time(), time() - tEnd);
    if (tooManySteps) {
        std::fprintf(stderr, "run stopped at step %ld, t = %g s: %.0f steps taken, the most one run may take (--max-steps; "
                             "loosen --rtol/--atol or shorten --duration); the files hold the run so far\n",
                     stepCount(), time(), args.maxSteps);
        return kExitFailed;
    }
    if (failed()) {
        const simcore::Failure& f = *view.failure;
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
    args->scene.severalBodies = true;  // scenes of several bodies run here (bodyN.key=value)
    sub->add_option("--duration", args->duration, "simulated time to run [s] (a resumed scene file runs on from its time)")
        ->type_name("T")
        ->check(finiteIn(0.0, 1e7, true))
        ->capture_default_str();
    addCsvOption(*sub, args->csv, "write the time series (one row per --every steps and the last)");
    sub->add_option("--xlsx", args->xlsx, "write the time series as an .xlsx workbook: the table with units on one "
                                          "sheet, charts of energy, volume and pressure against t on another")
        ->type_name("FILE.xlsx");
    sub->add_option("--csv-dialect", args->dialectName, "how --csv and --state are spelled: plain (comma, decimal point) "
                                                        "or excel-semicolon (semicolon, decimal comma, CRLF, UTF-8 "
                                                        "byte-order mark, for spreadsheets in decimal-comma locales)")
        ->type_name("NAME")
        ->capture_default_str();
    sub->add_option("--every", args->every, "CSV and .xlsx row every N steps")->type_name("N")->check(wholeIn(1, 1000000000L))->capture_default_str();
    sub->add_option("--state", args->state, "write the final state: index, layer, position, velocity")->type_name("FILE");
    sub->add_option("--save-scene", args->saveScene, "save the experiment with its final state as a scene file")
        ->type_name("FILE.json");
    sub->add_option("--max-steps", args->maxSteps, "the most steps the run may take: a fixed-step run that needs more is "
                                                   "refused before it starts, an adaptive one stops there (exit 3)")
        ->type_name("N")
        ->check(finiteIn(1.0, 1e12, false))
        ->default_str("1e9");
    sub->add_option("--precision", args->precision,
                    "double, or float: the float32 path (state and forces in float, diagnostics in double; euler, "
                    "midpoint, rk4, symplectic-euler, verlet; no contact: the run stops where a particle reaches a wall)")
        ->type_name("P")
        ->capture_default_str();
    sub->add_flag("--quiet", args->quiet, "no summary on standard output, no progress line and no notes on standard error");
    addJsonFlag(*sub, args->json);
    addIntegratorOptions(*sub, args->integrator);
    return {sub, [args] { checkRun(*args); }, [args] { return run(*args); }};
}

}  // namespace cli
