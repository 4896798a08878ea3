// `study`: the work-precision study (simcore/study.h) from the command line.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include "cli.h"
#include "output.h"
#include "study.h"

namespace cli {

std::vector<double> numberList(const std::string& option, const std::string& text) {
    std::vector<double> values;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ',')) {
        const auto v = simcore::parseNumber(item);
        if (!v) throw UsageError("--" + option + ": '" + item + "' is not a finite number");
        values.push_back(*v);
    }
    if (values.empty()) throw UsageError("--" + option + " needs a comma-separated list");
    return values;
}

std::vector<std::string> nameList(const std::string& text) {
    std::vector<std::string> names;
    std::stringstream ss(text);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty()) names.push_back(item);
    return names;
}

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

}  // namespace

int commandStudy(const std::vector<std::string>& args) {
    std::vector<std::string> names = {"scene", "set", "integrators", "dts", "tols", "duration", "repeat",
                                      "reference", "csv", "plot", "shard", "samples", "from-csv", "title"};
    Options options(args, names, {"fixed-step", "quiet"});

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
    spec.integrators = nameList(options.valueOr("integrators", "euler,midpoint,rk4"));
    if (options.has("dts")) spec.dts = numberList("dts", options.value("dts"));
    if (options.has("tols")) spec.tolerances = numberList("tols", options.value("tols"));
    spec.duration = options.number("duration", 2.0, 0.0, 1e6, true);
    spec.repeat = static_cast<int>(options.integer("repeat", 1, 1, 1000));
    spec.samples = static_cast<int>(options.integer("samples", 20, 1, 100000));
    spec.reference = options.valueOr("reference", "auto");
    spec.options.fixedStep = options.has("fixed-step");
    std::tie(spec.shardIndex, spec.shardCount) = parseShard(options);
    if (auto error = simcore::validateStudy(spec)) throw UsageError(*error);

    // Open outputs first: an unwritable path is bad input, found before any work.
    std::unique_ptr<simcore::AtomicFile> csv;
    if (options.has("csv")) {
        csv = std::make_unique<simcore::AtomicFile>(options.value("csv"));
        if (!csv->ok()) throw UsageError(csv->error());
    }
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
