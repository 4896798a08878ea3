// `bench`: how fast one scene steps, per size, integrator and thread count.
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "app/cli/cli.h"
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

struct BenchArgs {
    SceneArgs scene;
    long steps = 200, warmup = 10, threads = simcore::availableThreads();
    std::string kernels;
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
}

int runBench(const BenchArgs& args) {
    const SceneSetup& setup = args.setup;
    const long steps = args.steps, warmup = args.warmup, threads = args.threads;
    // The force kernels to time (default: the widest this CPU runs); the row names the set
    // actually used, which is narrower when the CPU lacks the one asked for.
    namespace kernels = simcore::kernels;
    for (auto set : {kernels::KernelSet::Portable, kernels::KernelSet::Avx2, kernels::KernelSet::Avx512})
        if (args.kernels == kernels::kernelSetName(set)) kernels::useKernels(set);

    const auto buildStart = std::chrono::steady_clock::now();
    simcore::Simulation sim(setup.params, setup.integrator);
    const double buildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count();
    sim.setThreads(static_cast<int>(threads));
    for (long i = 0; i < warmup; ++i) sim.step();
    // With --stages the timed steps time their stages too (two clock reads per stage, which
    // us_per_step then includes).
    sim.setProfiling(args.stages);
    const std::uint64_t evalsBefore = sim.diagnostics().forceEvaluations;
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < steps && !sim.failed(); ++i) sim.step();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (sim.failed()) {
        std::fprintf(stderr, "bench: the simulation failed: %s\n", sim.failure()->reason.c_str());
        return kExitFailed;
    }
    const double evals = static_cast<double>(sim.diagnostics().forceEvaluations - evalsBefore);
    const simcore::Topology& topo = sim.topology();
    std::size_t faces = 0;
    for (const simcore::Surface& s : topo.surfaces) faces += topo.dimension == 2 ? s.edges.size() : s.triangles.size();
    const double usPerStep = 1e6 * seconds / static_cast<double>(steps);
    const double nsPerSpring = 1e9 * seconds / (evals * static_cast<double>(topo.springCount()));
    const double realTime = sim.dt() / (seconds / static_cast<double>(steps));
    if (args.header) {
        std::printf("scene,integrator,threads,particles,springs,faces,steps,us_per_step,ns_per_spring_eval,"
                    "steps_per_second,real_time_factor,build_seconds,peak_rss_mib,kernels");
        // One column per stage of the step (simulation.h), in its order: us per step.
        if (args.stages)
            for (int s = 0; s < simcore::kStageCount; ++s)
                std::printf(",us_%s", std::string(simcore::stageName(static_cast<simcore::Stage>(s))).c_str());
        std::printf("\n");
    }
    std::printf("%s,%s,%d,%d,%zu,%zu,%ld,%.2f,%.3f,%.1f,%.3f,%.3f,%.1f,%s", setup.sceneName.c_str(),
                setup.integrator.c_str(), sim.threads(), topo.particleCount(), topo.springCount(), faces,
                steps, usPerStep, nsPerSpring, 1e6 / usPerStep, realTime, buildSeconds,
                static_cast<double>(peakResidentKiB()) / 1024.0, kernels::kernelSetName(kernels::kernelsInUse()));
    if (args.stages) {
        const simcore::StepProfile& profile = sim.profile();
        for (int s = 0; s < simcore::kStageCount; ++s)
            std::printf(",%.3f", 1e6 * profile[static_cast<simcore::Stage>(s)] / static_cast<double>(profile.steps));
    }
    std::printf("\n");
    return kExitOk;
}

}  // namespace

Command addBenchCommand(CLI::App& app) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* sub = app.add_subcommand("bench", "time N steps: us/step, ns per spring evaluation, real-time factor, "
                                                "memory, and the force kernels used");
    addSceneOptions(*sub, args->scene);
    sub->add_option("--steps", args->steps, "steps timed")->type_name("N")->check(wholeIn(1, 100000000L))->capture_default_str();
    sub->add_option("--warmup", args->warmup, "steps run before timing")->type_name("N")->check(wholeIn(0, 1000000L))->capture_default_str();
    sub->add_option("--threads", args->threads, "threads (default: all CPUs this process may use: its affinity mask and cgroup CPU quota)")
        ->type_name("K")
        ->check(wholeIn(1, 256))
        ->capture_default_str();
    sub->add_option("--kernels", args->kernels, "force kernels (default: the widest this CPU runs; a narrower set is "
                                                "used and named when the CPU lacks the one asked for)")
        ->type_name("SET")
        ->check(CLI::IsMember({"portable", "avx2", "avx512"}));
    sub->add_flag("--header", args->header, "print the CSV header line first");
    sub->add_flag("--stages", args->stages,
                  "also time each stage of the step (save, size, integrate, scan, collide, measure, constrain, "
                  "check, commit): one column of us per step each, after the others");
    return {sub, [args] { checkBench(*args); }, [args] { return runBench(*args); }};
}

}  // namespace cli
