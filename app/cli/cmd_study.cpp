// `study`: the work-precision study (simlab/study.h) from the command line, and with
// --refine the refinement study (simlab/refinement.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "app/cli/cli.h"
#include "simcore/integrator_table.h"
#include "simcore/scaling.h"
#include "simlab/output.h"
#include "simlab/refinement.h"
#include "simlab/scenefile.h"
#include "simlab/study.h"

namespace cli {

namespace {

struct StudyArgs {
    SceneArgs scene;
    std::optional<std::string> integrators, dts, tols, reference, shard, refine, title, precision;
    std::optional<double> duration;
    int repeat = 1, samples = 20, temporalRuns = 4;
    double interval = 0.01, timeBudget = 0.0;
    std::string csv, plot, fromCsv, timings;
    bool fixedStep = false, quiet = false, compensated = false;
    // After check():
    SceneSetup setup;
    simlab::StudySpec study;
    simlab::RefinementSpec refinement;
};

void printOrders(const std::vector<simlab::StudyRow>& rows, double referenceError) {
    std::printf("fitted convergence order (slope of log error against log dt over the 3 smallest resolved steps),\n"
                "per error measure:\n");
    std::printf("  %-24s %10s %10s %10s  %s\n", "curve", "error_max", "error_fin", "error_rms", "nominal");
    auto cell = [](double order, int points) {
        char text[32];
        if (std::isfinite(order)) std::snprintf(text, sizeof text, "%.2f (%d)", order, points);
        else std::snprintf(text, sizeof text, "- (%d)", points);
        return std::string(text);
    };
    for (const simlab::OrderFit& fit : simlab::fitOrders(rows, referenceError)) {
        auto method = simcore::makeIntegrator(fit.integrator.substr(0, fit.integrator.find(' ')));
        const int nominal = method ? method->order() : 0;
        std::printf("  %-24s %10s %10s %10s  %d\n", fit.integrator.c_str(), cell(fit.order, fit.points).c_str(),
                    cell(fit.orderFinal, fit.pointsFinal).c_str(), cell(fit.orderRms, fit.pointsRms).c_str(), nominal);
    }
}

void printFastest(const std::vector<simlab::StudyRow>& rows) {
    const auto best = simlab::fastestByFamily(rows);
    if (best.empty()) return;
    std::printf("\nfastest of each family at each accuracy (error_max reached; median wall time, log-log interpolated):\n");
    double level = -1.0;
    for (const simlab::FamilyBest& b : best) {
        if (b.error != level) std::printf("  error %-8.0e", b.error), level = b.error;
        else std::printf("  %-14s", "");
        std::printf(" %-12s %-22s %10.3g s %12.4g evals\n", b.family.c_str(), b.integrator.c_str(), b.wallSeconds,
                    b.forceEvaluations);
    }
}

bool writeFile(const std::string& path, const std::string& text) {
    simlab::AtomicFile file(path);
    if (!file.ok() || !file.write(text) || !file.commit()) {
        std::fprintf(stderr, "error: %s\n", file.error().c_str());
        return false;
    }
    return true;
}

// Opens --csv before any work: an unwritable path is bad input, found first.
std::unique_ptr<simlab::AtomicFile> openCsv(const std::string& path) {
    if (path.empty()) return nullptr;
    auto csv = std::make_unique<simlab::AtomicFile>(path);
    if (!csv->ok()) throw UsageError(csv->error());
    return csv;
}

// --refine KEY=v1,v2,...: the same body at several resolutions against the finest.
void checkRefinement(StudyArgs& args) {
    args.setup = sceneSetup(args.scene);
    simlab::RefinementSpec& spec = args.refinement;
    spec.params = args.setup.params;
    spec.world = args.setup.world;  // a world: every body's resolution raised together
    const std::string& refine = *args.refine;
    const auto eq = refine.find('=');
    if (eq == std::string::npos) throw UsageError("--refine: expected KEY=v1,v2,..., got " + simcore::quoteShort(refine));
    spec.key = refine.substr(0, eq);
    for (double v : numberList("refine", refine.substr(eq + 1))) {
        if (v != std::floor(v) || v < 0 || v > 1e6) throw UsageError("--refine: levels are whole numbers, got " + simlab::formatDouble(v));
        spec.values.push_back(static_cast<int>(v));
    }
    const std::vector<std::string> integrators = nameList("integrators", args.integrators.value_or("rk4"));
    if (integrators.size() != 1) throw UsageError("--refine takes one integrator (--integrators NAME)");
    spec.integrator = integrators.front();
    if (args.scene.dt) spec.dt = args.setup.params.get(simcore::Param::Dt);
    if (args.tols) {
        const std::vector<double> tols = numberList("tols", *args.tols);
        if (tols.size() != 1) throw UsageError("--refine takes one tolerance (--tols T)");
        spec.tolerance = tols.front();
    }
    spec.duration = args.duration.value_or(1.0);
    spec.interval = args.interval;
    spec.temporalRuns = args.temporalRuns;
    spec.options.fixedStep = args.fixedStep;
    simlab::checkRefinement(spec);
}

int runRefinement(const StudyArgs& args) {
    const simlab::RefinementSpec& spec = args.refinement;
    const SceneSetup& setup = args.setup;
    std::unique_ptr<simlab::AtomicFile> csv = openCsv(args.csv);

    const bool quiet = args.quiet;
    auto progress = [&](const simlab::StudyProgress& p) {
        if (!quiet && p.done < p.total) std::fprintf(stderr, "[%d/%d] %s\n", p.done + 1, p.total, p.what.c_str());
    };
    simlab::RefinementResult result;
    try {
        result = simlab::runRefinement(spec, progress);
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return kExitFailed;
    }
    if (!quiet) {
        std::printf("refinement   %s, %s at %zu levels against the finest, T = %g s, grid every %g s, scaling = %s\n",
                    setup.sceneName.c_str(), spec.key.c_str(), result.rows.size(), spec.duration, spec.interval,
                    simcore::scalingOf(spec.params) == simcore::Scaling::Physical ? "physical" : "thesis");
        std::printf("step         %s\n", result.stepRule.c_str());
        if (spec.params.get(simcore::Param::Perturb) > 0.0)
            std::printf("note         perturb = %g m is a random displacement per particle: each level starts from a\n"
                        "             different shape, and that difference does not shrink like the mesh error\n",
                        spec.params.get(simcore::Param::Perturb));
        std::printf("errors       volume: largest relative error of a layer's enclosed volume; com: largest distance\n"
                    "             of the mass-weighted centre of mass [m]; both over the grid, against the finest level\n\n");
        std::printf("%-14s %9s %8s %11s %10s %8s %10s %12s %12s  %s\n", "level", "particles", "springs", "h [m]", "dt [s]",
                    "steps", "wall_s", "error_volume", "error_com", "status");
        for (const simlab::RefinementRow& row : result.rows) {
            const std::string level = spec.key + "=" + std::to_string(row.value);
            std::printf("%-14s %9d %8d %11.4g %10.4g %8ld %10.4g ", level.c_str(), row.particles, row.springs, row.h, row.dt,
                        row.steps, row.wallSeconds);
            if (row.reference)
                std::printf("%12s %12s  reference\n", "0", "0");
            else if (row.ok)
                std::printf("%12.4g %12.4g  ok\n", row.errorVolume, row.errorCom);
            else
                std::printf("%12s %12s  %s\n", "-", "-", row.status().c_str());
        }
        if (!result.temporal.empty()) {
            std::printf("\ntemporal     %s=%d at coarser steps against itself at the study's step (the plot's step curve):\n",
                        spec.key.c_str(), result.temporalValue);
            for (const simlab::TemporalPoint& p : result.temporal) {
                std::printf("  %-3s %-10.4g %8ld steps %10.4g s ", p.tolerance > 0 ? "tol" : "dt",
                            p.tolerance > 0 ? p.tolerance : p.dt, p.steps, p.wallSeconds);
                if (p.ok) std::printf("%12.4g %12.4g\n", p.errorVolume, p.errorCom);
                else std::printf("failed (%s)\n", p.failure.c_str());
            }
            std::printf("time error   of the study's step, estimated: volume %.3g, com %.3g m (spatial errors below 10x\n"
                        "             this are not resolved and are left out of the fit)\n",
                        result.timeErrorVolume, result.timeErrorCom);
        }
        std::printf("\nfitted spatial order (slope of log error against log h, h = mean structural rest length,\n"
                    "over the 3 finest resolved levels; measured against the finest, which steepens it slightly):\n");
        for (const simlab::SpatialOrder& fit : simlab::fitSpatialOrders(result)) {
            if (std::isfinite(fit.order))
                std::printf("  %-8s %5.2f  (%d points)\n", fit.observable.c_str(), fit.order, fit.points);
            else
                std::printf("  %-8s   -    (%d usable points)\n", fit.observable.c_str(), fit.points);
        }
    }
    if (csv) {
        csv->write(simlab::refinementCsvHeader());
        for (const simlab::RefinementRow& row : result.rows) csv->write(simlab::refinementCsvRow(spec.key, row));
        if (!csv->commit()) {
            std::fprintf(stderr, "error: %s\n", csv->error().c_str());
            return kExitBadInput;
        }
    }
    if (!args.plot.empty()) {
        const std::string title = args.title.value_or(
            setup.sceneName + ": mesh error and step error against run time, T = " + simlab::formatDouble(spec.duration) + " s");
        if (!writeFile(args.plot, simlab::refinementSvg(spec, result, title))) return kExitBadInput;
    }
    return kExitOk;
}

// Merge mode: fit and plot rows written earlier (e.g. the shards, concatenated).
int runFromCsv(const StudyArgs& args) {
    const simlab::InputFile input = simlab::readInputFile(args.fromCsv, "a study CSV");
    if (!input.error.empty()) throw UsageError(input.error);
    std::string error;
    const auto rows = simlab::parseStudyCsv(input.text, &error);
    if (!rows) throw UsageError(simcore::quoteShort(args.fromCsv, 200) + ": " + error);
    printOrders(*rows, 0.0);
    printFastest(*rows);
    if (!args.plot.empty() && !writeFile(args.plot, simlab::studySvg(*rows, args.title.value_or("work-precision"))))
        return kExitBadInput;
    return kExitOk;
}

void checkStudy(StudyArgs& args) {
    checkFiles({{"scene", sceneFileOf(args.scene)}, {"from-csv", args.fromCsv}},
               {{"csv", args.csv}, {"plot", args.plot}, {"timings", args.timings}});
    if (args.refine) return checkRefinement(args);
    if (!args.fromCsv.empty()) return;
    args.setup = sceneSetup(args.scene);
    simlab::StudySpec& spec = args.study;
    spec.params = args.setup.params;
    spec.world = args.setup.world;  // a world: every run and the reference run the whole world
    spec.integrators = nameList("integrators", args.integrators.value_or("euler,midpoint,rk4"));
    if (args.dts) spec.dts = numberList("dts", *args.dts);
    if (args.tols) spec.tolerances = numberList("tols", *args.tols);
    spec.duration = args.duration.value_or(2.0);
    spec.repeat = args.repeat;
    spec.timeBudget = args.timeBudget;
    if (args.precision) spec.precisions = nameList("precision", *args.precision);
    spec.compensated = args.compensated;
    spec.samples = args.samples;
    spec.reference = args.reference.value_or("auto");
    spec.options.fixedStep = args.fixedStep;
    std::tie(spec.shardIndex, spec.shardCount) = parseShard(args.shard.value_or(""));
    simlab::checkStudy(spec);
}

// The table's head: the scene, the runs (this shard's), the budget and the float build.
void printStudyHeader(const simlab::StudySpec& spec, const SceneSetup& setup, std::size_t runs) {
    std::printf("study        %s, T = %g s, %zu runs%s, timing: %d run%s of each point (median, quartiles)\n",
                setup.sceneName.c_str(), spec.duration, runs,
                spec.shardCount > 1 ? (" (shard " + std::to_string(spec.shardIndex + 1) + "/" +
                                       std::to_string(spec.shardCount) + ")").c_str()
                                    : "",
                spec.repeat, spec.repeat == 1 ? "" : "s");
    if (spec.timeBudget > 0)
        std::printf("budget       a run longer than %g s is not reached, nor any costlier point of its curve\n",
                    spec.timeBudget);
    if (std::find(spec.precisions.begin(), spec.precisions.end(), "float") != spec.precisions.end())
        std::printf("float        %s%s\n",
                    simlab::floatOnReferenceProblem(spec) ? "the float build of the reference problem (spring1d)"
                                                          : "the float32 path (state and forces in float), one thread",
                    spec.compensated ? ", compensated (Kahan) state update" : "");
}

// One line of the table, printed as soon as its point has run.
void printStudyRow(const simlab::StudyRow& row, const simlab::StudyItem& item) {
    std::printf("%-24s %-11.4g %8ld %11llu ", row.label().c_str(), row.dt, row.steps,
                static_cast<unsigned long long>(row.forceEvaluations));
    if (row.walls.empty()) std::printf("%10s %10s %10s ", "-", "-", "-");
    else std::printf("%10.4g %10.4g %10.4g ", row.wallQ1, row.wallSeconds, row.wallQ3);
    if (row.ok)
        std::printf("%11.4g %11.4g %11.4g %11.4g  ok", row.errorFinal, row.errorMax, row.errorRms, row.errorEnergy);
    else
        std::printf("%11s %11s %11s %11s  %s (%s)", "-", "-", "-", "-", row.status().c_str(), row.failure.c_str());
    if (item.tolerance > 0) std::printf("  [tol %g]", item.tolerance);
    std::printf("\n");
    std::fflush(stdout);
}

int runStudy(const StudyArgs& args) {
    if (args.refine) return runRefinement(args);
    if (!args.fromCsv.empty()) return runFromCsv(args);
    const simlab::StudySpec& spec = args.study;
    const SceneSetup& setup = args.setup;
    std::unique_ptr<simlab::AtomicFile> csv = openCsv(args.csv);
    std::unique_ptr<simlab::AtomicFile> timings = openCsv(args.timings);
    const bool quiet = args.quiet;
    const auto items = simlab::shardItems(simlab::studyItems(spec), spec.shardIndex, spec.shardCount);
    if (!quiet) printStudyHeader(spec, setup, items.size());
    simlab::StudyReference reference;
    try {
        reference = simlab::computeReference(spec);
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return kExitFailed;
    }
    if (!quiet) {
        std::printf("reference    %s; its estimated error at T: %.3g m (errors below ~10x this are not resolved)\n",
                    reference.description.c_str(), reference.estimatedError);
        std::printf("grid         %zu output times for error_max\n\n", reference.times.size());
        std::printf("%-24s %-11s %8s %11s %10s %10s %10s %11s %11s %11s %11s  %s\n", "integrator", "dt", "steps",
                    "force_evals", "wall_q1", "wall_med", "wall_q3", "error_final", "error_max", "error_rms",
                    "err_energy", "status");
    }
    std::vector<simlab::StudyRow> rows;
    for (const simlab::StudyItem& item : items) {
        simlab::StudyRow row = simlab::runStudyPoint(spec, item, reference, rows);
        if (!quiet) printStudyRow(row, item);
        rows.push_back(std::move(row));
    }
    if (!quiet) {
        std::printf("\n");
        printOrders(rows, reference.estimatedError);
        printFastest(rows);
    }
    if (csv) {
        if (spec.shardIndex == 0) csv->write(simlab::studyCsvHeader());  // shards after the first append rows only
        for (const auto& row : rows) csv->write(simlab::studyCsvRow(row));
        if (!csv->commit()) {
            std::fprintf(stderr, "error: %s\n", csv->error().c_str());
            return kExitBadInput;
        }
    }
    if (timings) {
        if (spec.shardIndex == 0) timings->write(simlab::studyTimingsCsvHeader());
        for (const auto& row : rows) timings->write(simlab::studyTimingsCsvRows(row));
        if (!timings->commit()) {
            std::fprintf(stderr, "error: %s\n", timings->error().c_str());
            return kExitBadInput;
        }
    }
    if (!args.plot.empty()) {
        const std::string title =
            args.title.value_or(setup.sceneName + ": error against cost, T = " + simlab::formatDouble(spec.duration) + " s");
        if (!writeFile(args.plot, simlab::studySvg(rows, title, simlab::referenceScale(reference), spec.duration)))
            return kExitBadInput;
    }
    return kExitOk;
}

}  // namespace

// Kept whole: the table of the study command's options, one after another, then which exclude
// which (a split would part an option from the rule that names it).
Command addStudyCommand(CLI::App& app) {
    auto args = std::make_shared<StudyArgs>();
    CLI::App* sub = app.add_subcommand(
        "study", "work-precision study: error against wall time, force evaluations and dt for each integrator and "
                 "step (or tolerance), fitted orders; with --refine, the refinement study (the same body at each "
                 "resolution against the finest); with --from-csv, fit and plot rows written before (shards)");
    addSceneOptions(*sub, args->scene, true, false);
    args->scene.severalBodies = true;  // work-precision and refinement of a whole world
    CLI::Option* refine = sub->add_option("--refine", args->refine,
                                          "refinement study over KEY (particles, subdivisions or slices) at these levels")
                              ->type_name("KEY=v1,v2,...");
    CLI::Option* fromCsv = sub->add_option("--from-csv", args->fromCsv, "fit and plot the rows of an earlier study's CSV "
                                                                        "(e.g. the shards, concatenated)")
                               ->type_name("FILE")
                               ->excludes(refine);
    CLI::Option* integrators =
        sub->add_option("--integrators", args->integrators, "comma-separated integrators (one with --refine)")
            ->type_name("a,b,...")
            ->default_str("euler,midpoint,rk4; rk4 with --refine");
    CLI::Option* dts = sub->add_option("--dts", args->dts, "comma-separated fixed steps [s]")->type_name("h1,h2,...");
    CLI::Option* tols = sub->add_option("--tols", args->tols, "comma-separated tolerances of the adaptive methods "
                                                              "(one with --refine)")
                            ->type_name("t1,t2,...");
    CLI::Option* duration = sub->add_option("--duration", args->duration, "simulated time of every run [s]")
                                ->type_name("T")
                                ->check(finiteIn(0.0, 1e6, true))
                                ->default_str("2; 1 with --refine");
    CLI::Option* repeat = sub->add_option("--repeat", args->repeat, "time each run R times: every wall time is kept "
                                                                    "(--timings), each point reports min, quartiles, median")
                              ->type_name("R")
                              ->check(wholeIn(1, 1000))
                              ->capture_default_str();
    CLI::Option* reference = sub->add_option("--reference", args->reference, "what the error is measured against: auto "
                                                                              "(closed form where one exists), exact, rk4, rk45, "
                                                                              "cvode-bdf (at a tight tolerance)")
                                  ->type_name("NAME")
                                  ->default_str("auto");
    CLI::Option* samples = sub->add_option("--samples", args->samples, "output times on which error_max is taken")
                               ->type_name("G")
                               ->check(wholeIn(1, 100000))
                               ->capture_default_str();
    CLI::Option* shard = sub->add_option("--shard", args->shard, "run the K-th of N equal parts of the sweep (1-based); "
                                                                 "the parts' CSVs concatenate into the whole")
                             ->type_name("K/N");
    CLI::Option* budget = sub->add_option("--time-budget", args->timeBudget,
                                          "a run that takes longer is recorded as 'not reached' (no error), and so is "
                                          "every costlier point of its curve [s]; 0 = none")
                              ->type_name("SECONDS")
                              ->check(finiteIn(0.0, 1e6, false))
                              ->capture_default_str();
    CLI::Option* precision = sub->add_option("--precision", args->precision,
                                             "double (the simulation), float (the float32 path: euler, midpoint, rk4, "
                                             "symplectic-euler, verlet; for spring1d its float build, also the Yoshida "
                                             "methods), or both: double,float (the round-off floor of each)")
                                 ->type_name("P[,P]")
                                 ->default_str("double");
    CLI::Option* compensated = sub->add_flag("--compensated", args->compensated,
                                             "float: compensated (Kahan) summation of the state update");
    CLI::Option* timingsOption =
        sub->add_option("--timings", args->timings, "write every raw wall time, one row per run and repeat")
            ->type_name("FILE");
    CLI::Option* csv = addCsvOption(*sub, args->csv, "write one row per point");
    sub->add_option("--plot", args->plot, "draw the diagram as SVG")->type_name("FILE.svg");
    sub->add_option("--title", args->title, "the plot's title")->type_name("TEXT");
    sub->add_option("--interval", args->interval, "with --refine: compare the levels every I s [s]")
                                ->type_name("I")
                                ->check(finiteIn(0.0, 1e6, true))
                                ->capture_default_str()
                                ->needs(refine);
    sub->add_option("--temporal-runs", args->temporalRuns,
                                            "with --refine: coarser steps run on the finest level, to set its step error beside the mesh error")
                                ->type_name("K")
                                ->check(wholeIn(0, 10))
                                ->capture_default_str()
                                ->needs(refine);
    CLI::Option* fixed = sub->add_flag("--fixed-step", args->fixedStep, "run the adaptive methods at the fixed steps --dts");
    sub->add_flag("--quiet", args->quiet, "no table on standard output (the CSV and plot are still written)");
    sub->get_option("--dt")->description("with --refine: the time step of every level [s] (default: the stable "
                                         "step each level needs)")->needs(refine);
    for (CLI::Option* temporalOnly : {dts, repeat, reference, samples, shard, budget, precision, compensated, timingsOption})
        temporalOnly->excludes(refine);
    // Merge mode runs nothing: an option that would change a run is a mistake, not ignored.
    for (CLI::Option* notMerged : {integrators, dts, tols, duration, repeat, reference, samples, shard, csv, fixed, budget,
                                   precision, compensated, timingsOption, sub->get_option("--scene"), sub->get_option("--set")})
        notMerged->excludes(fromCsv);
    return {sub, [args] { checkStudy(*args); }, [args] { return runStudy(*args); }};
}

}  // namespace cli
