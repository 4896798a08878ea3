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
    long interleave = 0;  // steps per turn (0: the runs one after the other)
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

// One run with `threads` threads from the scene's start, timed in one or more turns.
class BenchRun {
public:
    BenchRun(const BenchArgs& args, long threads) : m_args(args) {
        const auto buildStart = std::chrono::steady_clock::now();
        m_sim = std::make_unique<simcore::Simulation>(args.setup.params, args.setup.integrator);
        // --precision float: the float path, started from the same state (float_path.h).
        if (args.precision == "float") m_single = std::make_unique<simcore::FloatSimulation>(*m_sim);
        m_buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - buildStart).count();
        if (m_single) m_single->setThreads(static_cast<int>(threads));
        else m_sim->setThreads(static_cast<int>(threads));
    }
    const std::optional<simcore::Failure>& failure() const { return m_single ? m_single->failure() : m_sim->failure(); }
    // The warm-up, untimed; then, with --stages, the timed steps time their stages too (two
    // clock reads per stage, which us_per_step then includes).
    void warmUp() {
        for (long i = 0; i < m_args.warmup && !failure(); ++i) step();
        m_sim->setProfiling(m_args.stages);
        m_evalsBefore = evaluations();
    }
    // `steps` more timed steps; false when the simulation failed (reported on stderr).
    bool timeSteps(long steps) {
        const auto start = std::chrono::steady_clock::now();
        for (long i = 0; i < steps && !failure(); ++i) step();
        m_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        m_steps += steps;
        if (!failure()) return true;
        std::fprintf(stderr, "bench: the simulation failed: %s\n", failure()->reason.c_str());
        return false;
    }
    void printRow(bool header) const;

private:
    void step() {
        if (m_single) m_single->step();
        else m_sim->step();
    }
    std::uint64_t evaluations() const {
        return m_single ? m_single->diagnostics().forceEvaluations : m_sim->diagnostics().forceEvaluations;
    }
    const BenchArgs& m_args;
    std::unique_ptr<simcore::Simulation> m_sim;
    std::unique_ptr<simcore::FloatSimulation> m_single;
    double m_buildSeconds = 0.0, m_seconds = 0.0;
    long m_steps = 0;
    std::uint64_t m_evalsBefore = 0;
};

// The run's CSV row (and the header line first when asked).
void BenchRun::printRow(bool header) const {
    namespace kernels = simcore::kernels;
    const SceneSetup& setup = m_args.setup;
    const double evals = static_cast<double>(evaluations() - m_evalsBefore);
    const simcore::Topology& topo = m_sim->topology();
    std::size_t faces = 0;
    for (const simcore::Surface& s : topo.surfaces) faces += topo.dimension == 2 ? s.edges.size() : s.triangles.size();
    const double steps = static_cast<double>(m_steps);
    const double usPerStep = 1e6 * m_seconds / steps;
    const double nsPerSpring = 1e9 * m_seconds / (evals * static_cast<double>(topo.springCount()));
    const double realTime = m_sim->dt() / (m_seconds / steps);
    const Eigen::VectorXd& state = m_sim->state();
    const std::uint64_t hash = m_single ? m_single->stateHash()
                                        : fnv1a(state.data(), sizeof(double) * static_cast<std::size_t>(state.size()));
    if (header) {
        std::printf("scene,integrator,precision,threads,particles,springs,faces,steps,us_per_step,ns_per_spring_eval,"
                    "steps_per_second,real_time_factor,build_seconds,peak_rss_mib,state_hash,kernels");
        // One column per stage of the step (simulation.h), in its order: us per step.
        if (m_args.stages)
            for (int s = 0; s < simcore::kStageCount; ++s)
                std::printf(",us_%s", std::string(simcore::stageName(static_cast<simcore::Stage>(s))).c_str());
        std::printf("\n");
    }
    std::printf("%s,%s,%s,%d,%d,%zu,%zu,%ld,%.2f,%.3f,%.1f,%.3f,%.3f,%.1f,%016llx,%s", setup.sceneName.c_str(),
                setup.integrator.c_str(), m_args.precision.c_str(), m_single ? m_single->threads() : m_sim->threads(),
                topo.particleCount(), topo.springCount(), faces, m_steps, usPerStep, nsPerSpring, 1e6 / usPerStep, realTime,
                m_buildSeconds, static_cast<double>(peakResidentKiB()) / 1024.0, static_cast<unsigned long long>(hash),
                kernels::kernelSetName(kernels::kernelsInUse()));
    if (m_args.stages) {
        const simcore::StepProfile& profile = m_sim->profile();
        for (int s = 0; s < simcore::kStageCount; ++s)
            std::printf(",%.3f", 1e6 * profile[static_cast<simcore::Stage>(s)] / static_cast<double>(profile.steps));
    }
    std::printf("\n");
    std::fflush(stdout);
}

int runBench(const BenchArgs& args) {
    // The force kernels to time (default: the widest this CPU runs); the row names the set
    // actually used, which is narrower when the CPU lacks the one asked for.
    namespace kernels = simcore::kernels;
    for (auto set : {kernels::KernelSet::Portable, kernels::KernelSet::Avx2, kernels::KernelSet::Avx512})
        if (args.kernels == kernels::kernelSetName(set)) kernels::useKernels(set);
    // One row per thread count, each a fresh run from the same start (the same hash means the
    // same trajectory, whatever the thread count): one after the other, or all made first and
    // timed in turns (--interleave).
    bool header = args.header;
    if (args.interleave == 0) {
        for (long threads : args.threads) {
            BenchRun run(args, threads);
            run.warmUp();
            if (!run.timeSteps(args.steps)) return kExitFailed;
            run.printRow(header);
            header = false;
        }
        return kExitOk;
    }
    std::vector<std::unique_ptr<BenchRun>> runs;
    for (long threads : args.threads) {
        runs.push_back(std::make_unique<BenchRun>(args, threads));
        runs.back()->warmUp();
    }
    for (const BenchTurn& turn : benchTurns(args.steps, args.interleave, static_cast<int>(runs.size())))
        if (!runs[static_cast<std::size_t>(turn.run)]->timeSteps(turn.steps)) return kExitFailed;
    for (const auto& run : runs) {
        run->printRow(header);
        header = false;
    }
    return kExitOk;
}

}  // namespace

std::vector<BenchTurn> benchTurns(long steps, long interleave, int runs) {
    std::vector<BenchTurn> turns;
    for (long done = 0; done < steps; done += interleave)
        for (int run = 0; run < runs; ++run) turns.push_back({run, std::min(interleave, steps - done)});
    return turns;
}

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
    sub->add_option("--interleave", args->interleave,
                    "make the runs of every thread count first, then time them in turns of N steps each (1, 2, 1, "
                    "2, ...) in one process: a load beside them that drifts counts for all alike (paired timing); "
                    "peak_rss_mib is then that of all the runs together")
        ->type_name("N")
        ->check(wholeIn(1, 100000000L));
    sub->add_flag("--header", args->header, "print the CSV header line first");
    sub->add_flag("--stages", args->stages,
                  "also time each stage of the step (save, size, integrate, scan, collide, measure, constrain, "
                  "check, commit): one column of us per step each, after the others");
    return {sub, [args] { checkBench(*args); }, [args] { return runBench(*args); }};
}

}  // namespace cli
