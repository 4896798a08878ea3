// `stability`: largest stable dt per integrator, measured beside the linearised prediction.
#include <cmath>
#include <cstdio>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/cli.h"
#include "simcore/integrator_table.h"
#include "simlab/output.h"
#include "simlab/stability.h"

namespace cli {

namespace {

std::string stepText(double h) {
    if (std::isinf(h)) return "unlimited";
    if (h <= 0.0) return "none";
    char b[32];
    std::snprintf(b, sizeof b, "%.4g", h);
    return b;
}

struct StabilityArgs {
    SceneArgs scene;
    std::string integrators = "euler,midpoint,rk4,symplectic-euler,verlet,rk45,implicit-euler";
    double duration = 2.0, perturb = 0.01, hMin = 1e-5, hMax = 1.0;
    std::string csv, shard;
    bool quiet = false, json = false;
    simlab::StabilitySpec spec;  // after check()
    SceneSetup setup;
};

void checkStability(StabilityArgs& args) {
    checkFiles({{"scene", sceneFileOf(args.scene)}}, {{"csv", args.csv}});
    args.setup = sceneSetup(args.scene);
    simlab::StabilitySpec& spec = args.spec;
    spec.params = args.setup.params;
    spec.world = args.setup.world;  // a scene of several bodies: the whole world
    spec.integrators = nameList("integrators", args.integrators);
    spec.duration = args.duration;
    spec.perturb = args.perturb;
    spec.hMin = args.hMin;
    spec.hMax = args.hMax;
    std::tie(spec.shardIndex, spec.shardCount) = parseShard(args.shard);
    simlab::checkStability(spec);
}

// --json: {"scene", "bodies" (a world), "free_coordinates", "basis", "omega_max",
// "fastest": [re, im], "rows": [{"integrator", "dt_stable", "dt_unstable", "dt_predicted",
// "reason"}]}: steps in s, null for "unlimited" (stable up to the largest step scanned, or an
// A-stable method).
void printStabilityJson(const SceneSetup& setup, const simlab::StabilitySpec& spec, const simlab::LinearModes& modes,
                        const std::vector<simlab::StabilityRow>& rows) {
    auto step = [](double h) { return std::isinf(h) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(h); };
    const simlab::StabilityVerdict v = simlab::stabilityVerdict(modes, "rk4", 0.0);
    nlohmann::ordered_json j = {{"scene", setup.sceneName}};
    if (spec.world) j["bodies"] = spec.world->bodies.size();
    j["free_coordinates"] = modes.freeCoordinates;
    j["basis"] = v.basis;
    j["omega_max"] = modes.omegaMax;
    j["fastest"] = {v.fastest.real(), v.fastest.imag()};
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const simlab::StabilityRow& row : rows)
        list.push_back({{"integrator", row.integrator}, {"dt_stable", row.stable}, {"dt_unstable", step(row.unstable)},
                        {"dt_predicted", step(row.predicted)}, {"reason", row.reasonAbove}});
    j["rows"] = list;
    printJson(j);
}

// The table's head: the scene, the one linearisation (its modes and spectrum) and each method's
// region on one undamped and one purely damped mode, then the column names.
void printStabilityHead(const simlab::StabilitySpec& spec, const SceneSetup& setup, const simlab::LinearModes& modes,
                        const simcore::ParameterSet& linearised) {
    std::printf("scene        %s, T = %g s, trials start perturbed by %g m (seed %g); the prediction is "
                "linearised at the unperturbed rest shape\n", setup.sceneName.c_str(),
                spec.duration, linearised.get(simcore::Param::Perturb), linearised.get(simcore::Param::Seed));
    std::printf("linearised   %d free coordinates (%s); highest frequency w_max = %.4g rad/s "
                "(period %.4g s), its damping c = %.4g 1/s (zeta = %.3g); fastest modal damping %.4g 1/s",
                modes.freeCoordinates, modes.dense ? "all modes" : "power iteration, highest mode only; Arnoldi spectrum",
                modes.omegaMax, modes.omegaMax > 0 ? 2 * M_PI / modes.omegaMax : 0.0, modes.dampingAtMax,
                modes.omegaMax > 0 ? modes.dampingAtMax / (2 * modes.omegaMax) : 0.0, modes.fastestDamping);
    if (modes.unstableModes) std::printf("; %d physically unstable modes excluded", modes.unstableModes);
    std::printf("\n");
    if (spec.world)
        std::printf("world        %zu bodies linearised as one system (every body's forces, the contact between "
                    "bodies where a pair is within the skin): one spectrum, one verdict per method\n",
                    spec.world->bodies.size());
    {
        // The verdict's spectrum (what every door predicts from).
        const simlab::StabilityVerdict v = simlab::stabilityVerdict(modes, "rk4", 0.0);
        std::printf("eigenvalues  %s of the first-order system (the prediction of every method; the "
                    "partitioned ones use the exact step matrix up to %d coordinates): fastest lambda = %.4g "
                    "%+.4gi 1/s\n",
                    v.basis.c_str(), simlab::kExactStepLimit, v.fastest.real(), std::abs(v.fastest.imag()));
    }
    // Each method's region, summarised by its limit on one undamped mode (w = 1) and on a
    // purely damped one (real axis), computed from the same functions as the prediction.
    std::printf("regions      limit of h*w on an undamped mode / of h*c on a pure decay rate c:");
    for (const std::string& name : spec.integrators) {
        simlab::LinearModes one;
        one.omega2 = {1.0};
        one.damping = {0.0};
        one.omegaMax = 1.0;
        const double undamped = simlab::predictedStableStep(name, one, 100.0);
        // real axis: the overdamped limit c -> infinity has rates c and w^2/c -> a decay rate
        // of 1 alone is the mode w^2 = 0, c = 1.
        simlab::LinearModes decay;
        decay.omega2 = {0.0};
        decay.damping = {1.0};
        const double real = simlab::predictedStableStep(name, decay, 100.0);
        std::printf(" %s %s/%s", name.c_str(), stepText(undamped).c_str(), stepText(real).c_str());
    }
    std::printf("\n             (damping moves the undamped limits; see docs/numerics.md)\n\n");
    std::printf("%-17s %12s %12s %12s %9s %9s  %s\n", "integrator", "measured", "(unstable)", "predicted",
                "h*w meas", "h*w pred", "what happens just above the measured limit");
}

int runStability(const StabilityArgs& args) {
    const simlab::StabilitySpec& spec = args.spec;
    const SceneSetup& setup = args.setup;
    std::unique_ptr<simlab::AtomicFile> csv;
    if (!args.csv.empty()) {
        csv = std::make_unique<simlab::AtomicFile>(args.csv);
        if (!csv->ok()) throw UsageError(csv->error());
    }
    simcore::ParameterSet linearised = spec.params;
    if (!linearised.isExplicit(simcore::Param::Perturb)) linearised.set(simcore::Param::Perturb, spec.perturb);
    // The one verdict's linearisation (at the rest shape, as the GUI's banners and map): the
    // trials below start perturbed, the prediction does not.
    const simlab::LinearModes modes = simlab::stabilityModes(spec);
    const bool quiet = args.quiet || args.json;
    if (!quiet) printStabilityHead(spec, setup, modes, linearised);
    std::vector<simlab::StabilityRow> rows;
    for (const std::string& name : simlab::shardNames(spec.integrators, spec.shardIndex, spec.shardCount)) {
        simlab::StabilityRow row = simlab::scanIntegrator(spec, name, modes);
        if (!quiet) {
            std::string meas = row.stable <= 0.0 ? "< " + stepText(spec.hMin) : stepText(row.stable);
            if (std::isinf(row.unstable)) meas = ">= " + stepText(row.stable);
            std::printf("%-17s %12s %12s %12s %9.3g %9.3g  %s\n", (name == "rk45" ? "rk45 (fixed)" : name.c_str()),
                        meas.c_str(), stepText(row.unstable).c_str(), stepText(row.predicted).c_str(),
                        row.stable * modes.omegaMax, std::isinf(row.predicted) ? INFINITY : row.predicted * modes.omegaMax,
                        std::isinf(row.unstable) ? "(stable up to the largest dt scanned)" : row.reasonAbove.c_str());
            std::fflush(stdout);
        }
        rows.push_back(std::move(row));
    }
    if (args.json) printStabilityJson(setup, spec, modes, rows);
    if (csv) {
        if (spec.shardIndex == 0) csv->write(simlab::stabilityCsvHeader());
        for (const auto& row : rows) csv->write(simlab::stabilityCsvRow(row, modes));
        if (!csv->commit()) {
            std::fprintf(stderr, "error: %s\n", csv->error().c_str());
            return kExitBadInput;
        }
    }
    return kExitOk;
}

}  // namespace

Command addStabilityCommand(CLI::App& app) {
    auto args = std::make_shared<StabilityArgs>();
    CLI::App* sub = app.add_subcommand("stability", "largest stable dt per integrator (bisection) beside the linearised "
                                                    "prediction (highest frequency, damping, stability region)");
    addSceneOptions(*sub, args->scene, false, false);
    args->scene.severalBodies = true;  // a scene of several bodies: the whole world's spectrum and trials
    sub->add_option("--integrators", args->integrators, "comma-separated integrators")->type_name("a,b,...")->capture_default_str();
    sub->add_option("--duration", args->duration, "simulated time a step must survive [s]")
        ->type_name("T")
        ->check(finiteIn(0.0, 1e5, true))
        ->capture_default_str();
    sub->add_option("--perturb", args->perturb, "random start displacement per particle [m] (unless --set perturb=)")
        ->type_name("A")
        ->check(finiteIn(0.0, 1e3, false))
        ->capture_default_str();
    sub->add_option("--hmin", args->hMin, "smallest dt scanned [s]")->type_name("H")->check(finiteIn(0.0, 1.0, true))->capture_default_str();
    sub->add_option("--hmax", args->hMax, "largest dt scanned [s]")->type_name("H")->check(finiteIn(0.0, 1.0, true))->capture_default_str();
    sub->add_option("--shard", args->shard, "scan the K-th of N equal parts of the integrators (1-based)")->type_name("K/N");
    addCsvOption(*sub, args->csv, "write one row per integrator");
    sub->add_flag("--quiet", args->quiet, "no table on standard output");
    addJsonFlag(*sub, args->json);
    return {sub, [args] { checkStability(*args); }, [args] { return runStability(*args); }};
}

}  // namespace cli
