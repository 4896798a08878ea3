// `study`: the work-precision study (simcore/study.h) from the command line, and with
// --refine the refinement study (simcore/refinement.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "cli.h"
#include "output.h"
#include "refinement.h"
#include "scaling.h"
#include "study.h"

namespace cli {

// Comma-separated lists: every item present (no "a,,b", no trailing comma), no item twice.
std::vector<std::string> listItems(const std::string& option, const std::string& text) {
    std::vector<std::string> items;
    std::string item;
    std::stringstream ss(text);
    while (std::getline(ss, item, ',')) items.push_back(item);
    if (!text.empty() && text.back() == ',') items.emplace_back();
    if (items.empty()) throw UsageError("--" + option + " needs a comma-separated list, got nothing");
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items[i].empty())
            throw UsageError("--" + option + " " + simcore::quoteShort(text) + ": item " + std::to_string(i + 1) +
                             " is empty");
        for (std::size_t j = 0; j < i; ++j)
            if (items[j] == items[i])
                throw UsageError("--" + option + ": " + simcore::quoteShort(items[i]) + " is listed twice");
    }
    return items;
}

std::vector<double> numberList(const std::string& option, const std::string& text) {
    std::vector<double> values;
    for (const std::string& item : listItems(option, text)) {
        const auto v = simcore::parseNumber(item);
        if (!v) throw UsageError("--" + option + ": " + simcore::quoteShort(item) + " is not a finite number");
        for (double earlier : values)
            if (earlier == *v) throw UsageError("--" + option + ": " + simcore::quoteShort(item) + " is listed twice");
        values.push_back(*v);
    }
    return values;
}

std::vector<std::string> nameList(const std::string& option, const std::string& text) { return listItems(option, text); }

std::pair<int, int> parseShard(const Options& options) {
    if (!options.has("shard")) return {0, 1};
    const std::string text = options.value("shard");
    const auto slash = text.find('/');
    const auto k = simcore::parseNumber(text.substr(0, slash == std::string::npos ? 0 : slash));
    const auto n = slash == std::string::npos ? std::nullopt : simcore::parseNumber(text.substr(slash + 1));
    if (!k || !n || *k != std::floor(*k) || *n != std::floor(*n) || *n < 1 || *k < 1 || *k > *n || *n > 100000)
        throw UsageError("--shard: '" + text + "' is not allowed; allowed K/N with 1 <= K <= N, e.g. 2/4");
    return {static_cast<int>(*k) - 1, static_cast<int>(*n)};
}

namespace {

void printOrders(const std::vector<simcore::StudyRow>& rows, double referenceError) {
    std::printf("fitted convergence order (slope of log error_max against log dt over the 3 smallest resolved steps):\n");
    for (const simcore::OrderFit& fit : simcore::fitOrders(rows, referenceError)) {
        auto method = simcore::makeIntegrator(fit.integrator);
        const int nominal = method ? method->order() : 0;
        if (std::isfinite(fit.order))
            std::printf("  %-17s %5.2f  (%d points; nominal %d)\n", fit.integrator.c_str(), fit.order, fit.points, nominal);
        else
            std::printf("  %-17s   -    (%d usable points; nominal %d)\n", fit.integrator.c_str(), fit.points, nominal);
    }
}

bool writeFile(const std::string& path, const std::string& text) {
    simcore::AtomicFile file(path);
    if (!file.ok() || !file.write(text) || !file.commit()) {
        std::fprintf(stderr, "error: %s\n", file.error().c_str());
        return false;
    }
    return true;
}

// Opens --csv before any work: an unwritable path is bad input, found first.
std::unique_ptr<simcore::AtomicFile> openCsv(const Options& options) {
    if (!options.has("csv")) return nullptr;
    auto csv = std::make_unique<simcore::AtomicFile>(options.value("csv"));
    if (!csv->ok()) throw UsageError(csv->error());
    return csv;
}

// --refine KEY=v1,v2,...: the same body at several resolutions against the finest.
int commandRefinement(const Options& options) {
    for (const char* temporalOnly : {"dts", "repeat", "reference", "shard", "samples", "from-csv"})
        if (options.has(temporalOnly))
            throw UsageError(std::string("--") + temporalOnly + " belongs to the temporal study, not to --refine");
    SceneSetup setup = sceneSetup(options);
    simcore::RefinementSpec spec;
    spec.params = setup.params;
    const std::string refine = options.value("refine");
    const auto eq = refine.find('=');
    if (eq == std::string::npos) throw UsageError("--refine: expected KEY=v1,v2,..., got '" + refine + "'");
    spec.key = refine.substr(0, eq);
    for (double v : numberList("refine", refine.substr(eq + 1))) {
        if (v != std::floor(v) || v < 0 || v > 1e6) throw UsageError("--refine: levels are whole numbers, got " + simcore::formatDouble(v));
        spec.values.push_back(static_cast<int>(v));
    }
    const std::vector<std::string> integrators = nameList("integrators", options.valueOr("integrators", "rk4"));
    if (integrators.size() != 1) throw UsageError("--refine takes one integrator (--integrators NAME)");
    spec.integrator = integrators.front();
    if (options.has("dt")) spec.dt = setup.params.get("dt");
    if (options.has("tols")) {
        const std::vector<double> tols = numberList("tols", options.value("tols"));
        if (tols.size() != 1) throw UsageError("--refine takes one tolerance (--tols T)");
        spec.tolerance = tols.front();
    }
    spec.duration = options.number("duration", 1.0, 0.0, 1e6, true);
    spec.interval = options.number("interval", 0.01, 0.0, 1e6, true);
    spec.temporalRuns = static_cast<int>(options.integer("temporal-runs", 4, 0, 10));
    spec.options.fixedStep = options.has("fixed-step");
    if (auto error = simcore::validateRefinement(spec)) throw UsageError(*error);
    std::unique_ptr<simcore::AtomicFile> csv = openCsv(options);

    const bool quiet = options.has("quiet");
    auto progress = [&](const simcore::StudyProgress& p) {
        if (!quiet && p.done < p.total) std::fprintf(stderr, "[%d/%d] %s\n", p.done + 1, p.total, p.what.c_str());
    };
    simcore::RefinementResult result;
    try {
        result = simcore::runRefinement(spec, progress);
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return kExitFailed;
    }
    if (!quiet) {
        std::printf("refinement   %s, %s at %zu levels against the finest, T = %g s, grid every %g s, scaling = %s\n",
                    setup.sceneName.c_str(), spec.key.c_str(), result.rows.size(), spec.duration, spec.interval,
                    simcore::scalingOf(spec.params) == simcore::Scaling::Physical ? "physical" : "thesis");
        std::printf("step         %s\n", result.stepRule.c_str());
        if (spec.params.get("perturb") > 0.0)
            std::printf("note         perturb = %g m is a random displacement per particle: each level starts from a\n"
                        "             different shape, and that difference does not shrink like the mesh error\n",
                        spec.params.get("perturb"));
        std::printf("errors       volume: largest relative error of a layer's enclosed volume; com: largest distance\n"
                    "             of the mass-weighted centre of mass [m]; both over the grid, against the finest level\n\n");
        std::printf("%-14s %9s %8s %11s %10s %8s %10s %12s %12s  %s\n", "level", "particles", "springs", "h [m]", "dt [s]",
                    "steps", "wall_s", "error_volume", "error_com", "status");
        for (const simcore::RefinementRow& row : result.rows) {
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
            for (const simcore::TemporalPoint& p : result.temporal) {
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
        for (const simcore::SpatialOrder& fit : simcore::fitSpatialOrders(result)) {
            if (std::isfinite(fit.order))
                std::printf("  %-8s %5.2f  (%d points)\n", fit.observable.c_str(), fit.order, fit.points);
            else
                std::printf("  %-8s   -    (%d usable points)\n", fit.observable.c_str(), fit.points);
        }
    }
    if (csv) {
        csv->write(simcore::refinementCsvHeader());
        for (const simcore::RefinementRow& row : result.rows) csv->write(simcore::refinementCsvRow(spec.key, row));
        if (!csv->commit()) {
            std::fprintf(stderr, "error: %s\n", csv->error().c_str());
            return kExitBadInput;
        }
    }
    if (options.has("plot")) {
        const std::string title = options.valueOr(
            "title", setup.sceneName + ": mesh error and step error against run time, T = " + simcore::formatDouble(spec.duration) + " s");
        if (!writeFile(options.value("plot"), simcore::refinementSvg(spec, result, title))) return kExitBadInput;
    }
    return kExitOk;
}

}  // namespace

int commandStudy(const std::vector<std::string>& args) {
    std::vector<std::string> names = {"scene", "set", "integrators", "dts", "tols", "duration", "repeat",
                                      "reference", "csv", "plot", "shard", "samples", "from-csv", "title",
                                      "refine", "dt", "interval", "temporal-runs"};
    Options options(args, names, {"fixed-step", "quiet"});
    checkDistinctFiles(options, {"csv", "plot"});
    if (options.has("refine")) return commandRefinement(options);
    for (const char* refineOnly : {"dt", "interval", "temporal-runs"})
        if (options.has(refineOnly))
            throw UsageError(std::string("--") + refineOnly + " belongs to --refine; the temporal study takes --dts");

    if (options.has("from-csv")) {
        // Merge mode: fit and plot rows written earlier (e.g. the shards, concatenated).
        std::ifstream in(options.value("from-csv"));
        if (!in) throw UsageError("cannot read '" + options.value("from-csv") + "'");
        std::stringstream text;
        text << in.rdbuf();
        std::string error;
        const auto rows = simcore::parseStudyCsv(text.str(), &error);
        if (!rows) throw UsageError(options.value("from-csv") + ": " + error);
        printOrders(*rows, 0.0);
        if (options.has("plot") &&
            !writeFile(options.value("plot"), simcore::studySvg(*rows, options.valueOr("title", "work-precision"))))
            return kExitBadInput;
        return kExitOk;
    }

    SceneSetup setup = sceneSetup(options);
    simcore::StudySpec spec;
    spec.params = setup.params;
    spec.integrators = nameList("integrators", options.valueOr("integrators", "euler,midpoint,rk4"));
    if (options.has("dts")) spec.dts = numberList("dts", options.value("dts"));
    if (options.has("tols")) spec.tolerances = numberList("tols", options.value("tols"));
    spec.duration = options.number("duration", 2.0, 0.0, 1e6, true);
    spec.repeat = static_cast<int>(options.integer("repeat", 1, 1, 1000));
    spec.samples = static_cast<int>(options.integer("samples", 20, 1, 100000));
    spec.reference = options.valueOr("reference", "auto");
    spec.options.fixedStep = options.has("fixed-step");
    std::tie(spec.shardIndex, spec.shardCount) = parseShard(options);
    if (auto error = simcore::validateStudy(spec)) throw UsageError(*error);
    // Bounded work: the smallest step, and the RK4 reference 16x below it, take at most
    // kMaxSteps steps each (--dts 1e-300 is refused, not run for ever or counted as 0 steps).
    if (!spec.dts.empty()) {
        const double smallest = *std::min_element(spec.dts.begin(), spec.dts.end());
        const double steps = spec.duration / smallest * 16.0;
        if (steps > kMaxSteps) {
            char text[300];
            std::snprintf(text, sizeof text,
                          "--dts %g over --duration %g s: its reference (16x smaller steps) would take %.3g steps; "
                          "at most %.0f (use larger steps or a shorter --duration)",
                          smallest, spec.duration, steps, kMaxSteps);
            throw UsageError(text);
        }
    }

    std::unique_ptr<simcore::AtomicFile> csv = openCsv(options);
    const bool quiet = options.has("quiet");
    const auto items = simcore::shardItems(simcore::studyItems(spec), spec.shardIndex, spec.shardCount);
    if (!quiet)
        std::printf("study        %s, T = %g s, %zu runs%s, timing: median of %d\n", setup.sceneName.c_str(),
                    spec.duration, items.size(),
                    spec.shardCount > 1 ? (" (shard " + std::to_string(spec.shardIndex + 1) + "/" +
                                           std::to_string(spec.shardCount) + ")").c_str()
                                        : "",
                    spec.repeat);
    simcore::StudyReference reference;
    try {
        reference = simcore::computeReference(spec);
    } catch (const std::runtime_error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return kExitFailed;
    }
    if (!quiet) {
        std::printf("reference    %s; its estimated error at T: %.3g m (errors below ~10x this are not resolved)\n",
                    reference.description.c_str(), reference.estimatedError);
        std::printf("grid         %zu output times for error_max\n\n", reference.times.size());
        std::printf("%-17s %-11s %8s %11s %11s %11s %11s %11s  %s\n", "integrator", "dt", "steps", "force_evals",
                    "wall_s", "error_final", "error_max", "err_energy", "status");
    }
    std::vector<simcore::StudyRow> rows;
    for (const simcore::StudyItem& item : items) {
        simcore::StudyRow row = simcore::runStudyItem(spec, item, reference);
        if (!quiet) {
            std::printf("%-17s %-11.4g %8ld %11llu %11.4g ", item.integrator.c_str(), row.dt, row.steps,
                        static_cast<unsigned long long>(row.forceEvaluations), row.wallSeconds);
            if (row.ok)
                std::printf("%11.4g %11.4g %11.4g  ok", row.errorFinal, row.errorMax, row.errorEnergy);
            else
                std::printf("%11s %11s %11s  %s (%s)", "-", "-", "-", row.status().c_str(), row.failure.c_str());
            if (item.tolerance > 0) std::printf("  [tol %g]", item.tolerance);
            std::printf("\n");
            std::fflush(stdout);
        }
        rows.push_back(std::move(row));
    }
    if (!quiet) {
        std::printf("\n");
        printOrders(rows, reference.estimatedError);
    }
    if (csv) {
        if (spec.shardIndex == 0) csv->write(simcore::studyCsvHeader());  // shards after the first append rows only
        for (const auto& row : rows) csv->write(simcore::studyCsvRow(row));
        if (!csv->commit()) {
            std::fprintf(stderr, "error: %s\n", csv->error().c_str());
            return kExitBadInput;
        }
    }
    if (options.has("plot")) {
        const std::string title = options.valueOr("title", setup.sceneName + ": error against cost, T = " +
                                                              simcore::formatDouble(spec.duration) + " s");
        if (!writeFile(options.value("plot"), simcore::studySvg(rows, title))) return kExitBadInput;
    }
    return kExitOk;
}

}  // namespace cli
