// Benchmarks (Google Benchmark). Speed goals live here, never in timed tests.
//
//   build/release/bench/elastic-lab-bench --benchmark_filter=Sphere
//
// Counters: us per step, ns per spring evaluation, real-time factor at the scene's DT.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>

#include "simcore/forces.h"
#include "simcore/simulation.h"
#include "simcore/world.h"

namespace {

using namespace simcore;

void reportCounters(benchmark::State& state, const Simulation& sim, std::uint64_t evals) {
    const double steps = static_cast<double>(state.iterations());
    const BodySize size = bodySize(sim.parameters());
    state.counters["particles"] = static_cast<double>(size.particles);
    state.counters["springs"] = static_cast<double>(size.springs);
    state.counters["faces"] = static_cast<double>(size.faces);
    // The stated upper bound of the simulation's heap (tested to hold); the measured peak
    // per run is elastic-lab-cli bench's last column but one (one process per run).
    state.counters["memory_bound_mib"] = memoryBoundBytes(size) / (1024.0 * 1024.0);
    state.counters["us_per_step"] = benchmark::Counter(steps * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["ns_per_spring"] = benchmark::Counter(
        static_cast<double>(evals) * static_cast<double>(sim.topology().springCount()) * 1e-9,
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["realtime_x"] = benchmark::Counter(steps * sim.dt(), benchmark::Counter::kIsRate);
}

void stepScene(benchmark::State& state, ParameterSet params, const char* integrator, int threads) {
    // As bench/run-benchmarks.sh: gravity off and the start perturbed, so that the body wobbles
    // in place for as many steps as the benchmark takes (with 1 kg per particle, fine spheres
    // are heavy and soft and collapse on the floor in long runs); every term is still evaluated.
    params.set(simcore::Param::Gravity, 0.0);
    params.set(simcore::Param::Perturb, 0.01);
    Simulation sim(params, integrator);
    sim.setThreads(threads);
    const std::uint64_t before = sim.diagnostics().forceEvaluations;
    for (auto _ : state) {
        if (!sim.step()) {
            state.SkipWithError(sim.failure()->reason.c_str());
            break;
        }
    }
    reportCounters(state, sim, sim.diagnostics().forceEvaluations - before);
}

void BM_Sphere3d(benchmark::State& state) {
    ParameterSet p(SceneKind::Sphere3d);
    p.set(simcore::Param::Subdivisions, static_cast<double>(state.range(0)));
    stepScene(state, p, "rk4", static_cast<int>(state.range(1)));
}
BENCHMARK(BM_Sphere3d)->ArgsProduct({{1, 2, 3, 4, 5, 6, 7}, {1, 2}})->Unit(benchmark::kMicrosecond)->UseRealTime();

void BM_Ring2d(benchmark::State& state) {
    ParameterSet p(SceneKind::Ring2d);
    p.set(simcore::Param::Particles, static_cast<double>(state.range(0)));
    // Large rings need a finer step: their edges are short and stiff in proportion.
    stepScene(state, p, "rk4", 2);
}
BENCHMARK(BM_Ring2d)->Arg(10)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond)->UseRealTime();

void BM_Integrators(benchmark::State& state, const char* integrator) {
    ParameterSet p(SceneKind::Sphere3d);
    p.set(simcore::Param::Subdivisions, 4);
    stepScene(state, p, integrator, 2);
}
BENCHMARK_CAPTURE(BM_Integrators, euler, "euler")->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Integrators, midpoint, "midpoint")->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Integrators, rk4, "rk4")->Unit(benchmark::kMicrosecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_Integrators, verlet, "verlet")->Unit(benchmark::kMicrosecond)->UseRealTime();

// One force evaluation: 0 = the one-pass reference kernels, 1 = the fast path with the
// portable kernels, 2 = with the AVX2 kernels, 3 = with the AVX-512 kernels (where the CPU
// has them).
void BM_Forces(benchmark::State& state) {
    const bool fast = state.range(1) != 0;
    const auto set = static_cast<kernels::KernelSet>(std::max<std::int64_t>(0, state.range(1) - 1));
    if (set > kernels::widestKernels()) {
        state.SkipWithError("this CPU lacks these kernels");
        return;
    }
    kernels::useKernels(set);
    ParameterSet p(SceneKind::Sphere3d);
    p.set(simcore::Param::Subdivisions, static_cast<double>(state.range(0)));
    Body body = buildBody(p);
    ForceModel model(&body.topology, &body.mass, sceneTerms(SceneKind::Sphere3d));
    model.params.stiffness = {800, 700, 700};
    model.params.damping = {15, 50, 50};
    model.params.gasConstant = {20, 20};
    const Eigen::Index n3 = 3 * body.topology.particleCount();
    Eigen::VectorXd x = Eigen::Map<Eigen::VectorXd>(body.positions.data(), n3) * 1.01;
    Eigen::VectorXd v = Eigen::VectorXd::Constant(n3, 0.1), f(n3);
    ForceExtras extras;
    for (auto _ : state) {
        if (fast)
            model.evaluate(x.data(), v.data(), f.data(), extras);
        else
            model.evaluateReference(x.data(), v.data(), f.data(), extras);
        benchmark::DoNotOptimize(f.data());
    }
    state.counters["ns_per_spring"] = benchmark::Counter(
        static_cast<double>(state.iterations()) * static_cast<double>(body.topology.springCount()) * 1e-9,
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    kernels::useKernels(kernels::widestKernels());
}
BENCHMARK(BM_Forces)->ArgsProduct({{4, 6}, {0, 1, 2, 3}})->Unit(benchmark::kMicrosecond)->UseRealTime();

// The GUI path: copying the positions out for a snapshot, against one step.
void BM_SnapshotCopy(benchmark::State& state) {
    ParameterSet p(SceneKind::Sphere3d);
    p.set(simcore::Param::Subdivisions, static_cast<double>(state.range(0)));
    Simulation sim(p, "rk4");
    std::vector<float> snapshot(static_cast<std::size_t>(3 * sim.particleCount()));
    for (auto _ : state) {
        const auto x = sim.positions();
        for (Eigen::Index k = 0; k < x.size(); ++k) snapshot[static_cast<std::size_t>(k)] = static_cast<float>(x.data()[k]);
        benchmark::DoNotOptimize(snapshot.data());
    }
}
BENCHMARK(BM_SnapshotCopy)->Arg(4)->Arg(6)->Unit(benchmark::kMicrosecond);

// Two level-4 spheres (1026 particles each, dt 0.001), weightless: pressed into
// each other's contact skin (contact = 1: every step evaluates the pairs within the skin) or
// moving apart (contact = 0: the broad phase finds nothing to do). Issue 26's goal: in contact
// at most 1.5 x apart, per step.
void BM_TwoSpheres(benchmark::State& state) {
    const bool contact = state.range(0) == 1;
    WorldSpec spec = *worldScene("collide3d");
    for (const char* s : {"gravity=0", "subdivisions=4", "dt=0.001", "body1.position_x=-2.06", "body2.position_x=2.06",
                          "body1.velocity_x=0.4", "body2.velocity_x=-0.4"})
        (void)assignWorld(spec, s);
    if (!contact) {
        (void)assignWorld(spec, "body1.velocity_x=-0.4");
        (void)assignWorld(spec, "body2.velocity_x=0.4");
    }
    World world(spec, "rk4");
    // Into contact first (about 0.1 s at 0.8 m/s closing speed).
    while (contact && world.diagnostics().contactPairsActive == 0 && world.time() < 1.0) world.step();
    int touching = 0;
    for (auto _ : state) {
        if (!world.step()) {
            state.SkipWithError(world.failure()->c_str());
            break;
        }
        touching += world.diagnostics().contactPairsActive > 0 ? 1 : 0;
    }
    const double steps = static_cast<double>(state.iterations());
    state.counters["particles"] = world.particleCount();
    state.counters["steps_in_contact"] = touching;
    state.counters["us_per_step"] = benchmark::Counter(steps * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_TwoSpheres)->Arg(0)->Arg(1)->Iterations(30)->Unit(benchmark::kMicrosecond)->UseRealTime();

}  // namespace


BENCHMARK_MAIN();
