// Elastic Lab beside Bullet's btSoftBody, in one process, in alternating rounds (issue 27).
//
//   build/release/bench/elastic-lab-bullet-compare [--level 6] [--steps 200] [--rounds 7]
//       [--kernels avx2] [--threads 1,2] [--bullet-bending 2] [--bullet-iterations 1] [--float on]
//
// Ours: the two-layer sphere3d at the level (thesis scaling as `elastic-lab-cli bench`,
// gravity off, the start perturbed by 0.01), RK4, DT 0.003, every diagnostic on.
// Bullet (the build Debian ships: single precision, its default): one btSoftBody made from our
// outer layer's mesh at the same level (the same particles; links along the mesh edges and, with
// --bullet-bending 2, the default, to each node's second ring: as many links as our outer
// layer's structural and shear springs), gas pressure on (kPR), damping on (kDP), one position
// iteration (Bullet's default; --bullet-iterations), in a btSoftRigidDynamicsWorld with gravity
// off, stepped by stepSimulation(0.003, 0) (one step of exactly 0.003 s per call). Bullet's
// soft body runs on one thread; ours with each thread count asked for.
//
// Ours also runs on the float32 path (float_path.h; --float off leaves it out), started from
// the same state, each float lane paired with the double lane of its thread count.
//
// Each round times every lane for the same number of steps, one after the other; a lane's
// ratio is its steps/s over Bullet's in the same round (a paired ratio, so that a machine
// whose speed drifts from minute to minute moves both sides of it), and the summary gives the
// median and the range of those ratios.
#include <BulletSoftBody/btSoftBodyHelpers.h>
#include <BulletSoftBody/btSoftBodyRigidBodyCollisionConfiguration.h>
#include <BulletSoftBody/btSoftRigidDynamicsWorld.h>
#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "simcore/float_path.h"
#include "simcore/force_kernels.h"
#include "simcore/parallel.h"
#include "simcore/simulation.h"

namespace {

std::string cpuName() {
    std::ifstream in("/proc/cpuinfo");
    std::string line, name = "unknown CPU", flags;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0 && name == "unknown CPU") name = line.substr(line.find(':') + 2);
        if (line.rfind("flags", 0) == 0 && flags.empty()) flags = line + " ";
    }
    const bool avx512 = flags.find(" avx512f ") != std::string::npos, avx2 = flags.find(" avx2 ") != std::string::npos;
    return name + (avx512 ? " (AVX-512)" : avx2 ? " (AVX2, no AVX-512)" : " (no AVX2)");
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Bullet's soft body from our outer layer's mesh (its own world, gravity off).
class BulletSphere {
public:
    BulletSphere(const simcore::Simulation& ours, int bending, int iterations) {
        const simcore::Topology& topo = ours.topology();
        const simcore::Surface* outer = topo.surface(simcore::Layer::Outer);
        std::vector<int> local(static_cast<std::size_t>(topo.particleCount()), -1);
        std::vector<btScalar> vertices;
        std::vector<int> triangles;
        for (const auto& t : outer->triangles)
            for (int corner : t) {
                int& id = local[static_cast<std::size_t>(corner)];
                if (id < 0) {
                    id = static_cast<int>(vertices.size() / 3);
                    for (int k = 0; k < 3; ++k) vertices.push_back(static_cast<btScalar>(ours.body().positions(k, corner)));
                }
                triangles.push_back(id);
            }
        m_world = std::make_unique<btSoftRigidDynamicsWorld>(&m_dispatcher, &m_broadphase, &m_solver, &m_config);
        m_world->setGravity(btVector3(0, 0, 0));
        btSoftBodyWorldInfo& info = m_world->getWorldInfo();
        info.m_gravity.setValue(0, 0, 0);
        info.air_density = 0;
        info.water_density = 0;
        info.m_sparsesdf.Initialize();
        m_body = btSoftBodyHelpers::CreateFromTriMesh(info, vertices.data(), triangles.data(),
                                                      static_cast<int>(triangles.size() / 3));
        if (bending > 0) m_body->generateBendingConstraints(bending);
        m_body->m_cfg.piterations = iterations;
        m_body->m_cfg.kPR = 100.0f;  // gas pressure
        m_body->m_cfg.kDP = 0.01f;  // damping
        m_body->setTotalMass(static_cast<btScalar>(vertices.size() / 3));  // 1 kg per particle, as ours
        m_world->addSoftBody(m_body);
    }
    ~BulletSphere() {
        m_world->removeSoftBody(m_body);
        delete m_body;
    }
    void step() { m_world->stepSimulation(0.003f, 0); }
    int nodes() const { return m_body->m_nodes.size(); }
    int links() const { return m_body->m_links.size(); }
    int faces() const { return m_body->m_faces.size(); }
    bool finite() const {
        for (int i = 0; i < m_body->m_nodes.size(); ++i)
            if (!std::isfinite(m_body->m_nodes[i].m_x.x())) return false;
        return true;
    }

private:
    btSoftBodyRigidBodyCollisionConfiguration m_config;
    btCollisionDispatcher m_dispatcher{&m_config};
    btDbvtBroadphase m_broadphase;
    btSequentialImpulseConstraintSolver m_solver;
    std::unique_ptr<btSoftRigidDynamicsWorld> m_world;
    btSoftBody* m_body = nullptr;
};

struct Lane {
    std::string name;
    std::function<void()> step;
    int pairedWith = -1;        // the lane this one is also compared with (float: double's)
    std::vector<double> rate;   // steps/s per round
    std::vector<double> ratio;  // rate / Bullet's in the same round
    std::vector<double> paired; // rate / the paired lane's in the same round
};

// The command line.
struct Options {
    // Bullet's links: the mesh edges and, by default, the bending links to each node's
    // second ring (generateBendingConstraints(2)): 147,432 links at level 6, as many as our
    // outer layer's structural and shear springs (147,456). One position iteration: Bullet's
    // default.
    int level = 6, bending = 2, iterations = 1;
    bool withFloat = true;
    long steps = 200, rounds = 7, warmup = 10;
    std::string kernels;
    std::vector<int> threads{1, 2};
};

// False (after printing the usage or the unknown option) when the command line is not one.
bool parseOptions(int argc, char** argv, Options& o) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : nullptr;
        if (!value) {
            std::fprintf(stderr, "usage: %s [--level L] [--steps N] [--rounds R] [--warmup N] [--kernels SET] [--threads 1,2] [--bullet-bending K] [--bullet-iterations N] [--float on|off]\n", argv[0]);
            return false;
        }
        if (arg == "--level") o.level = std::atoi(value);
        else if (arg == "--steps") o.steps = std::atol(value);
        else if (arg == "--rounds") o.rounds = std::atol(value);
        else if (arg == "--warmup") o.warmup = std::atol(value);
        else if (arg == "--kernels") o.kernels = value;
        else if (arg == "--bullet-bending") o.bending = std::atoi(value);
        else if (arg == "--bullet-iterations") o.iterations = std::atoi(value);
        else if (arg == "--float") o.withFloat = std::string(value) != "off";
        else if (arg == "--threads") {
            o.threads.clear();
            for (const char* p = value; *p;) {
                o.threads.push_back(std::atoi(p));
                p = std::strchr(p, ',');
                if (!p) break;
                ++p;
            }
        } else {
            std::fprintf(stderr, "unknown option %s\n", arg.c_str());
            return false;
        }
        ++i;
    }
    return true;
}

// The warm-up, then the rounds: each lane's steps/s, its ratio to Bullet's (lane 0) and to its
// paired lane's in the same round.
void timeRounds(std::vector<Lane>& lanes, long steps, long rounds, long warmup) {
    for (Lane& lane : lanes)
        for (long i = 0; i < warmup; ++i) lane.step();
    for (long r = 0; r < rounds; ++r) {
        for (Lane& lane : lanes) {
            const auto start = std::chrono::steady_clock::now();
            for (long i = 0; i < steps; ++i) lane.step();
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            lane.rate.push_back(static_cast<double>(steps) / seconds);
            lane.ratio.push_back(lane.rate.back() / lanes.front().rate.back());
        }
        for (Lane& lane : lanes)
            if (lane.pairedWith >= 0)
                lane.paired.push_back(lane.rate.back() / lanes[static_cast<std::size_t>(lane.pairedWith)].rate.back());
    }
}

// The summary: one CSV row per lane, the median and range of its rates and ratios.
void printLanes(const std::vector<Lane>& lanes, long rounds, long steps) {
    std::printf("lane,rounds,steps_per_round,steps_per_second_median,steps_per_second_min,steps_per_second_max,"
                "ratio_to_bullet_median,ratio_min,ratio_max,ratio_to_double_median,ratio_to_double_min,"
                "ratio_to_double_max\n");
    for (const Lane& lane : lanes) {
        std::printf("%s,%ld,%ld,%.1f,%.1f,%.1f,%.3f,%.3f,%.3f", lane.name.c_str(), rounds, steps, median(lane.rate),
                    *std::min_element(lane.rate.begin(), lane.rate.end()),
                    *std::max_element(lane.rate.begin(), lane.rate.end()), median(lane.ratio),
                    *std::min_element(lane.ratio.begin(), lane.ratio.end()),
                    *std::max_element(lane.ratio.begin(), lane.ratio.end()));
        if (lane.paired.empty()) std::printf(",,,\n");
        else
            std::printf(",%.3f,%.3f,%.3f\n", median(lane.paired), *std::min_element(lane.paired.begin(), lane.paired.end()),
                        *std::max_element(lane.paired.begin(), lane.paired.end()));
    }
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    if (!parseOptions(argc, argv, o)) return 2;
    const std::vector<int>& threads = o.threads;
    namespace sk = simcore::kernels;
    for (auto set : {sk::KernelSet::Portable, sk::KernelSet::Avx2, sk::KernelSet::Avx512})
        if (o.kernels == sk::kernelSetName(set)) sk::useKernels(set);

    simcore::ParameterSet params(simcore::SceneKind::Sphere3d);
    params.set(simcore::Param::Subdivisions, o.level);
    params.set(simcore::Param::Scaling, 1.0);  // thesis, as elastic-lab-cli bench
    params.set(simcore::Param::Gravity, 0.0);
    params.set(simcore::Param::Perturb, 0.01);
    params.set(simcore::Param::Dt, 0.003);

    std::vector<std::unique_ptr<simcore::Simulation>> ours;
    std::vector<std::unique_ptr<simcore::FloatSimulation>> floats;
    std::vector<Lane> lanes;
    std::unique_ptr<BulletSphere> bullet;
    auto threadName = [](int t) { return std::to_string(t) + " thread" + (t > 1 ? "s" : ""); };
    // Lanes: Bullet, then ours in double per thread count, then in float (the float32 path,
    // started from the same state) per thread count, each float lane paired with the double
    // lane of its thread count.
    for (int t : threads) {
        ours.push_back(std::make_unique<simcore::Simulation>(params, "rk4"));
        simcore::Simulation* sim = ours.back().get();
        sim->setThreads(t);
        if (!bullet) {
            bullet = std::make_unique<BulletSphere>(*sim, o.bending, o.iterations);
            BulletSphere* b = bullet.get();
            lanes.push_back({"bullet btSoftBody, 1 thread", [b] { b->step(); }, -1, {}, {}, {}});
        }
        lanes.push_back({"elastic-lab double, " + threadName(sim->threads()), [sim] { sim->step(); }, -1, {}, {}, {}});
    }
    if (o.withFloat)
        for (std::size_t k = 0; k < threads.size(); ++k) {
            floats.push_back(std::make_unique<simcore::FloatSimulation>(*ours[k]));
            simcore::FloatSimulation* single = floats.back().get();
            single->setThreads(threads[k]);
            lanes.push_back({"elastic-lab float, " + threadName(single->threads()), [single] { single->step(); },
                             static_cast<int>(k) + 1, {}, {}, {}});
        }
    const simcore::Simulation& first = *ours.front();
    std::printf("# CPU: %s; our kernels: %s; Bullet %d (btScalar: %zu bytes)\n", cpuName().c_str(),
                sk::kernelSetName(sk::kernelsInUse()), btGetVersion(), sizeof(btScalar));
    std::printf("# ours: sphere3d level %d, two layers, %d particles, %zu springs, RK4, DT %.3g\n", o.level,
                first.topology().particleCount(), first.topology().springCount(), first.dt());
    std::printf("# Bullet: one layer, %d nodes, %d links, %d faces, DT 0.003\n", bullet->nodes(), bullet->links(),
                bullet->faces());
    timeRounds(lanes, o.steps, o.rounds, o.warmup);
    for (const auto& sim : ours)
        if (sim->failed()) {
            std::fprintf(stderr, "our simulation failed: %s\n", sim->failure()->reason.c_str());
            return 1;
        }
    for (const auto& single : floats)
        if (single->failed()) {
            std::fprintf(stderr, "our float simulation failed: %s\n", single->failure()->reason.c_str());
            return 1;
        }
    if (!bullet->finite()) {
        std::fprintf(stderr, "Bullet's soft body left the finite numbers\n");
        return 1;
    }
    printLanes(lanes, o.rounds, o.steps);
    return 0;
}
