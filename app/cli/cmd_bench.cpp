// `bench`: how fast one scene steps, per size, integrator and thread count.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/cli.h"
#include "simcore/float_path.h"
#include "simcore/force_kernels.h"
#include "simcore/params.h"
#include "simcore/simulation.h"

namespace cli {

namespace {

long peakResidentKiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;  // KiB on Linux
}

// FNV-1a (64 bits) of a byte range: the final state's fingerprint (same hash = same
// trajectory, bit for bit).
std::uint64_t fnv1a(const void* data, std::size_t bytes) {
    std::uint64_t h = 14695981039346656037ULL;
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ULL;
    return h;
}

// The default thread counts: one, and all CPUs this process may use (when more than one), so
// that a bench prints both figures people compare.
std::vector<long> defaultThreadCounts() {
    const long all = simcore::availableThreads();
    return all > 1 ? std::vector<long>{1, all} : std::vector<long>{1};
}

struct BenchArgs {
    SceneArgs scene;
    long steps = 200, warmup = 10;
    std::vector<long> threads = defaultThreadCounts();
    std::string kernels;
    std::string precision = "double";
    bool header = false;
    bool stages = false;
    SceneSetup setup;  // after check()
};

void checkBench(BenchArgs& args) {
    args.setup = sceneSetup(args.scene);
    // The benchmarks time the thesis's per-particle body at every size (docs/performance.md),
    // so that their figures stay comparable; --set scaling=physical times the physical one.
    simcore::ParameterSet& params = args.setup.params;
    if (params.has(simcore::Param::Scaling))
        if (!params.isExplicit(simcore::Param::Scaling)) params.set(simcore::Param::Scaling, 1.0);
    simlab::checkPrecision(args.precision, args.setup.integrator);  // the front door
    if (args.precision == "float") {
        if (args.stages) throw UsageError("--stages times the double path's stages; not with --precision float");
    }
}

// One timed run with `threads` threads from the scene's start: one CSV row.
int benchRow(const BenchArgs& args, long threads, bool header) {
    const SceneSetup& setup = args.setup;
    const long steps = args.steps, warmup = args.warmup;
    namespace kernels = simcore::kernels;

    const auto buildStart = std::chrono::steady_clock::now();
    simcore::Simulation sim(setup.params, setup.integrator);
    // --precision float: the float path, started from the same state (float_path.h).
    std::unique_ptr<simcore::FloatSimulation> single;
    if (args.precision == "float") single = std::make_unique<simcore::FloatSimulation>(sim);
    const double buildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count();
    if (single) single->setThreads(static_cast<int>(threads));
    else sim.setThreads(static_cast<int>(threads));
    auto step = [&] { return single ? single->step() : sim.step(); };
    auto failure = [&]() -> const std::optional<simcore::Failure>& { return single ? single->failure() : sim.failure(); };
    auto evaluations = [&] {
        return single ? single->diagnostics().forceEvaluations : sim.diagnostics().forceEvaluations;
    };
    for (long i = 0; i < warmup; ++i) step();
    // With --stages the timed steps time their stages too (two clock reads per stage, which
    // us_per_step then includes).
    sim.setProfiling(args.stages);
    const std::uint64_t evalsBefore = evaluations();
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < steps && !failure(); ++i) step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (failure()) {
        std::fprintf(stderr, "bench: the simulation failed: %s\n", failure()->reason.c_str());
        return kExitFailed;
    }
    const double evals = static_cast<double>(evaluations() - evalsBefore);
    const simcore::Topology& topo = sim.topology();
    std::size_t faces = 0;
    for (const simcore::Surface& s : topo.surfaces) faces += topo.dimension == 2 ? s.edges.size() : s.triangles.size();
    const double usPerStep = 1e6 * seconds / static_cast<double>(steps);
    const double nsPerSpring = 1e9 * seconds / (evals * static_cast<double>(topo.springCount()));
    const double realTime = sim.dt() / (seconds / static_cast<double>(steps));
    const Eigen::VectorXd& state = sim.state();
    const std::uint64_t hash = single ? single->stateHash()
                                      : fnv1a(state.data(), sizeof(double) * static_cast<std::size_t>(state.size()));
    if (header) {
        std::printf("scene,integrator,precision,threads,particles,springs,faces,steps,us_per_step,ns_per_spring_eval,"
                    "steps_per_second,real_time_factor,build_seconds,peak_rss_mib,state_hash,kernels");
        // One column per stage of the step (simulation.h), in its order: us per step.
        if (args.stages)
            for (int s = 0; s < simcore::kStageCount; ++s)
                std::printf(",us_%s", std::string(simcore::stageName(static_cast<simcore::Stage>(s))).c_str());
        std::printf("\n");
    }
    std::printf("%s,%s,%s,%d,%d,%zu,%zu,%ld,%.2f,%.3f,%.1f,%.3f,%.3f,%.1f,%016llx,%s", setup.sceneName.c_str(),
                setup.integrator.c_str(), args.precision.c_str(), single ? single->threads() : sim.threads(), topo.particleCount(), topo.springCount(), faces,
                steps, usPerStep, nsPerSpring, 1e6 / usPerStep, realTime, buildSeconds,
                static_cast<double>(peakResidentKiB()) / 1024.0, static_cast<unsigned long long>(hash),
                kernels::kernelSetName(kernels::kernelsInUse()));
    if (args.stages) {
        const simcore::StepProfile& profile = sim.profile();
        for (int s = 0; s < simcore::kStageCount; ++s)
            std::printf(",%.3f", 1e6 * profile[static_cast<simcore::Stage>(s)] / static_cast<double>(profile.steps));
    }
    std::printf("\n");
    std::fflush(stdout);
    return kExitOk;
}

int runBench(const BenchArgs& args) {
    // The force kernels to time (default: the widest this CPU runs); the row names the set
    // actually used, which is narrower when the CPU lacks the one asked for.
    namespace kernels = simcore::kernels;
    for (auto set : {kernels::KernelSet::Portable, kernels::KernelSet::Avx2, kernels::KernelSet::Avx512})
        if (args.kernels == kernels::kernelSetName(set)) kernels::useKernels(set);
    // One row per thread count, each a fresh run from the same start (the same hash means the
    // same trajectory, whatever the thread count).
    bool header = args.header;
    for (long threads : args.threads) {
        if (const int code = benchRow(args, threads, header); code != kExitOk) return code;
        header = false;
    }
    return kExitOk;
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* sub = app.add_subcommand("bench", "time N steps: us/step, ns per spring evaluation, real-time factor, "
                                                "memory, the precision and force kernels used, and a hash of the final state");
    addSceneOptions(*sub, args->scene);
    sub->add_option("--steps", args->steps, "steps timed")->type_name("N")->check(wholeIn(1, 100000000L))->capture_default_str();
    sub->add_option("--warmup", args->warmup, "steps run before timing")->type_name("N")->check(wholeIn(0, 1000000L))->capture_default_str();
    // The default is said in words, never as this machine's number: the man page is made from
    // this text at build time and must not carry the build machine's CPU count.
    sub->add_option("--threads", args->threads,
                    "thread counts, one row each, comma-separated (default: 1 and all CPUs this process may use: its "
                    "affinity mask and cgroup CPU quota)")
        ->type_name("K[,K...]")
        ->delimiter(',')
        ->check(wholeIn(1, 256));
    sub->add_option("--kernels", args->kernels, "force kernels (default: the widest this CPU runs; a narrower set is "
                                                "used and named when the CPU lacks the one asked for)")
        ->type_name("SET")
        ->check(CLI::IsMember({"portable", "avx2", "avx512"}));
    sub->add_option("--precision", args->precision,
                     "double, or float: the float32 path (state and forces in float; euler, midpoint, rk4, "
                     "symplectic-euler, verlet; no contact)")
        ->type_name("P")
        ->capture_default_str();
    sub->add_flag("--header", args->header, "print the CSV header line first");
    sub->add_flag("--stages", args->stages,
                  "also time each stage of the step (save, size, integrate, scan, collide, measure, constrain, "
                  "check, commit): one column of us per step each, after the others");
    return {sub, [args] { checkBench(*args); }, [args] { return runBench(*args); }};
}

}  // namespace cli
