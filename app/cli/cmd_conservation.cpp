// `conservation`: long-time energy (simlab/conservation.h) from the command line.
#include <cmath>
#include <cstdio>
#include <memory>

#include "app/cli/cli.h"
#include "simlab/conservation.h"
#include "simlab/output.h"

namespace cli {

namespace {

struct ConservationArgs {
    SceneArgs scene;
    std::optional<std::string> integrators, title;
    double periods = 1000.0;
    int samples = 120;
    std::string precision = "double", csv, curves, plot;
    bool quiet = false;
    // After check():
    SceneSetup setup;
    simlab::ConservationSpec spec;
};

void check(ConservationArgs& args) {
    checkDistinctFiles({{"scene", sceneFileOf(args.scene)}, {"csv", args.csv}, {"curves", args.curves}, {"plot", args.plot}});
    args.setup = sceneSetup(args.scene);
    simlab::ConservationSpec& spec = args.spec;
    spec.params = args.setup.params;
    spec.integrators = nameList("integrators", args.integrators.value_or("verlet,yoshida4,rk4"));
    spec.periods = args.periods;
    spec.dt = spec.params.get(simcore::Param::Dt);
    spec.samples = args.samples;
    spec.precision = args.precision;
    if (auto error = simlab::validateConservation(spec)) throw UsageError(*error);
}

bool writeOutput(const std::string& path, const std::string& text) {
    simlab::AtomicFile file(path);
    if (!file.ok() || !file.write(text) || !file.commit()) {
        std::fprintf(stderr, "error: %s\n", file.error().c_str());
        return false;
    }
    return true;
}

int run(const ConservationArgs& args) {
    const simlab::ConservationSpec& spec = args.spec;
    // Outputs opened before any work: an unwritable path is bad input, found first.
    for (const std::string& path : {args.csv, args.curves, args.plot})
        if (!path.empty()) {
            simlab::AtomicFile probe(path);
            if (!probe.ok()) throw UsageError(probe.error());
        }
    const bool quiet = args.quiet;
    auto progress = [&](int done, int total, const std::string& what) {
        if (!quiet && done < total) std::fprintf(stderr, "[%d/%d] %s\n", done + 1, total, what.c_str());
    };
    simlab::ConservationResult result;
    try {
        result = simlab::runConservation(spec, progress);
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return kExitFailed;
    }
    if (!quiet) {
        std::printf("conservation %s, undamped (%s), %s\n", args.setup.sceneName.c_str(), result.undamped.c_str(),
                    spec.precision == "float" ? "float build of spring1d" : "double");
        std::printf("fastest mode omega_max = %.6g rad/s, period %.6g s; dt = %g s (h omega = %.3g); %g periods = %.6g s\n",
                    result.omegaMax, result.period, spec.dt, spec.dt * result.omegaMax, spec.periods, result.duration);
        std::printf("energy scale (largest kinetic energy) %.4g J; alpha: slope of log |dE| envelope against log t from\n"
                    "10 periods on, 95 %% interval; bounded < 0.25 <= random-walk < 0.75 <= drift\n\n",
                    result.energyScale);
        std::printf("%-17s %7s %17s  %-12s %12s %12s %10s %9s  %s\n", "integrator", "alpha", "95% interval", "class",
                    "final |dE| J", "relative", "steps", "wall_s", "status");
        for (const simlab::ConservationRow& row : result.rows) {
            if (row.ok)
                std::printf("%-17s %7.3f  [%6.3f, %6.3f]  %-12s %12.4g %12.4g %10ld %9.3g  ok\n", row.integrator.c_str(),
                            row.alpha, row.alphaLo, row.alphaHi, row.growth.c_str(), row.finalError, row.relativeError,
                            row.steps, row.wallSeconds);
            else
                std::printf("%-17s %7s %17s  %-12s %12s %12s %10ld %9.3g  %s (%s)\n", row.integrator.c_str(), "-", "-", "-",
                            "-", "-", row.steps, row.wallSeconds, row.status().c_str(), row.failure.c_str());
        }
    }
    if (!args.csv.empty()) {
        std::string text = simlab::conservationCsvHeader();
        for (const simlab::ConservationRow& row : result.rows) text += simlab::conservationCsvRow(row);
        if (!writeOutput(args.csv, text)) return kExitBadInput;
    }
    if (!args.curves.empty() && !writeOutput(args.curves, simlab::conservationCurvesCsv(result))) return kExitBadInput;
    if (!args.plot.empty()) {
        char title[300];
        std::snprintf(title, sizeof title, "%s: |energy error| over %g periods, dt = %g s (h omega = %.3g)%s",
                      args.setup.sceneName.c_str(), spec.periods, spec.dt, spec.dt * result.omegaMax,
                      spec.precision == "float" ? ", float" : "");
        if (!writeOutput(args.plot, simlab::conservationSvg(result, args.title.value_or(title)))) return kExitBadInput;
    }
    return result.cancelled ? kExitFailed : kExitOk;
}

}  // namespace

Command addConservationCommand(CLI::App& app) {
    auto args = std::make_shared<ConservationArgs>();
    CLI::App* sub = app.add_subcommand(
        "conservation", "long-time energy: run the undamped scene for --periods periods of its fastest mode at --dt, fit "
                        "the growth exponent alpha of |energy error| against time, and classify it (bounded, "
                        "random-walk, drift)");
    addSceneOptions(*sub, args->scene, true, false);
    sub->add_option("--integrators", args->integrators, "comma-separated fixed-step integrators")
        ->type_name("a,b,...")
        ->default_str("verlet,yoshida4,rk4");
    sub->add_option("--periods", args->periods, "run length in periods of the fastest mode")
        ->type_name("P")
        ->check(finiteIn(20.0, 1e7, false))
        ->capture_default_str();
    sub->add_option("--samples", args->samples, "log-spaced times at which the energy error is recorded")
        ->type_name("N")
        ->check(wholeIn(10, 100000))
        ->capture_default_str();
    sub->add_option("--precision", args->precision, "double (the simulation) or float (the float build of spring1d)")
        ->type_name("P")
        ->check(CLI::IsMember({"double", "float"}))
        ->capture_default_str();
    sub->add_option("--csv", args->csv, "write one row per integrator")->type_name("FILE");
    sub->add_option("--curves", args->curves, "write the |energy error| envelopes, one row per sample")->type_name("FILE");
    sub->add_option("--plot", args->plot, "draw |energy error| against t (log-log) as SVG")->type_name("FILE.svg");
    sub->add_option("--title", args->title, "the plot's title")->type_name("TEXT");
    sub->add_flag("--quiet", args->quiet, "no table on standard output (the files are still written)");
    return {sub, [args] { check(*args); }, [args] { return run(*args); }};
}

}  // namespace cli
