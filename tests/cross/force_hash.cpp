// force_hash: the force code's results as text, to compare two builds bit for bit (one line per
// quantity: a 64-bit FNV-1a hash of the result's bytes, or one double in hex, %a).
//
// scripts/check-aarch64.sh builds this for x86-64 and for AArch64 (run under an emulator) and
// compares the outputs line by line; on x86-64 it also runs each kernel set (argument:
// portable, avx2 or avx512; the set in use goes to stderr, so the outputs stay comparable).
// Qt-free and without SUNDIALS: it is compiled from the simcore sources it needs alone.
//
// Cases, each built by simcore's own builders from a ParameterSet (buildBody, bodyValues) and
// perturbed by the seeded start recipe of Simulation::reset:
//   - scenes at several resolutions, one- and two-chunk (ForceModel::kChunks), 2D and 3D;
//   - a sphere pushed through the floor with every third inner particle moved outside its
//     outer partner, moving sideways with friction on: wall contact and the layer barrier act;
//   - the mouse spring on one particle.
// Per case: the rest shape and the state (what the builders and the start recipe made), then
// ForceModel::evaluate, evaluateMotion, evaluateReference, the volume gradient, the energies
// and volumes. Then each kernel of the set in use on blocks of length 0..40 at an offset (the
// inputs of tests/test_force_kernels.cpp): every remainder of the four- and eight-lane loops.
// Last, Eigen's reductions over long vectors (see runReductions).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "kernel_inputs.h"
#include "simcore/body.h"
#include "simcore/contact.h"
#include "simcore/force_kernels.h"
#include "simcore/forces.h"
#include "simcore/parallel.h"
#include "simcore/params.h"
#include "simcore/scaling.h"
#include "simcore/scenes.h"

using namespace simcore;
namespace kernels = simcore::kernels;

namespace {

// 64-bit FNV-1a over the bytes of n doubles (both targets are little-endian; -0.0 and 0.0
// differ, as they should).
std::uint64_t fnv1a(const double* data, std::size_t n, std::uint64_t hash = 0xcbf29ce484222325ull) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n * sizeof(double); ++i) {
        hash ^= bytes[i];
        hash *= 0x100000001b3ull;
    }
    return hash;
}
std::uint64_t fnv1a(const Eigen::VectorXd& v) { return fnv1a(v.data(), static_cast<std::size_t>(v.size())); }

void printHash(const std::string& where, const char* what, std::uint64_t hash) {
    std::printf("%s %s %016llx\n", where.c_str(), what, static_cast<unsigned long long>(hash));
}
void printValue(const std::string& where, const char* what, double value) {
    std::printf("%s %s %a\n", where.c_str(), what, value);
}

struct Case {
    std::string name;
    ParameterSet params;
    bool throughFloor = false;  // pushed through the floor, inner layer partly outside the outer
    bool pointer = false;       // the mouse spring on particle 7
};

// The ForceModel's tunables as Simulation::applyForceParams sets them, from the same sources
// (the parameter table resolved, the body's per-spring values for its resolution).
void configure(ForceModel& model, const ParameterSet& set, const Body& body) {
    const Params p = resolve(set);
    const BodyValues values = bodyValues(set, body);
    model.params.stiffness = values.stiffness;
    model.params.damping = values.damping;
    if (set.kind() != SceneKind::Spring1d) model.params.gasConstant = p.forces.gasConstant;
    model.params.gravity = p.world.gravity;
    model.params.mks = p.forces.mks;
    model.params.mkd = p.forces.mkd;
    model.params.mouseRest = p.forces.mouseRest;
    ContactParams& c = model.contact;
    c.walls = c.layerBarrier = p.world.contact == ContactModel::Force;
    c.stiffness = values.contactStiffness;
    c.alpha = dampingForRestitution(p.world.restitution) / p.world.contactSpeed;
    c.friction = p.world.friction;
    c.frictionSpeed = p.world.frictionSpeed;
    const Eigen::Vector3d centre = centroid(body.positions);
    const int dims = body.topology.dimension;
    for (int axis = 0; axis < 3; ++axis) {
        const bool moves = axis == 1 || (axis == 0 && dims >= 2) || (axis == 2 && dims == 3);
        if (!moves) continue;
        c.low[static_cast<std::size_t>(axis)] = centre[axis] - p.world.box;
        c.high[static_cast<std::size_t>(axis)] = centre[axis] + p.world.box;
    }
}

void runCase(const Case& k, ThreadPool& pool) {
    const std::string& at = k.name;
    const Body body = buildBody(k.params);
    const Topology& topo = body.topology;
    const Eigen::Index n3 = 3 * topo.particleCount();
    ForceModel model(&topo, &body.mass, sceneTerms(k.params.kind()));
    configure(model, k.params, body);
    model.prepareContact(body.positions.data(), body.fixed);
    model.setPool(&pool);

    // Which coordinates move (Simulation::build's inverse masses): 2D bodies stay in z = 0.
    Eigen::VectorXd invMass3 = Eigen::VectorXd::Zero(n3);
    for (int i = 0; i < topo.particleCount(); ++i) {
        if (body.fixed[static_cast<std::size_t>(i)]) continue;
        const double inv = 1.0 / body.mass[i];
        invMass3[3 * i + 1] = inv;
        if (topo.dimension >= 2) invMass3[3 * i] = inv;
        if (topo.dimension == 3) invMass3[3 * i + 2] = inv;
    }
    // The start state by Simulation::reset's recipe (seeded uniform displacement on the moving
    // coordinates), and seeded velocities so that damping and friction act.
    const Params p = resolve(k.params);
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(body.positions.data(), n3);
    Eigen::VectorXd v = Eigen::VectorXd::Zero(n3);
    std::mt19937_64 rng(p.start.seed);
    std::uniform_real_distribution<double> uniform(-p.start.perturb, p.start.perturb);
    for (Eigen::Index c = 0; c < n3; ++c)
        if (invMass3[c] != 0.0) x[c] += uniform(rng);
    std::mt19937_64 rngV(p.start.seed + 1);
    std::uniform_real_distribution<double> speed(-0.5, 0.5);
    for (Eigen::Index c = 0; c < n3; ++c)
        if (invMass3[c] != 0.0) v[c] = speed(rngV);
    if (k.throughFloor) {
        // Every third inner particle 1.4 times as far out (past its outer partner: 1.4 * 1.5 m
        // > 2 m), then the body lowered until its lowest particle is 0.15 m below the floor,
        // moving sideways along x at 1 m/s (friction).
        for (const auto& pair : topo.layerPairs)
            if (pair[0] % 3 == 0) x.segment(3 * pair[0], 3) *= 1.4;
        double lowest = x[1];
        for (Eigen::Index i = 0; i < n3 / 3; ++i) lowest = std::min(lowest, x[3 * i + 1]);
        const double drop = lowest - (model.contact.low[1] - 0.15);
        for (Eigen::Index i = 0; i < n3 / 3; ++i) {
            x[3 * i + 1] -= drop;
            v[3 * i] += 1.0;
        }
    }
    if (k.pointer) model.pointer = PointerSpring{true, 7, x.segment<3>(21) + Eigen::Vector3d(0.3, -0.2, 0.1)};

    printHash(at, "rest-shape", fnv1a(body.positions.data(), static_cast<std::size_t>(n3)));
    for (int family = 0; family < kSpringFamilyCount; ++family) {
        const auto f = static_cast<std::size_t>(family);
        const std::string name(springFamilyName(SpringFamily(family)));
        printHash(at, ("rest-lengths-" + name).c_str(), fnv1a(topo.springs[f].rest.data(), topo.springs[f].size()));
        printValue(at, ("stiffness-" + name).c_str(), model.params.stiffness[f]);
        printValue(at, ("damping-" + name).c_str(), model.params.damping[f]);
    }
    printHash(at, "state-x", fnv1a(x));
    printHash(at, "state-v", fnv1a(v));
    printValue(at, "contact-alpha", model.contact.alpha);

    ForceExtras e;
    Eigen::VectorXd f(n3);
    model.evaluate(x.data(), v.data(), f.data(), e);
    printHash(at, "evaluate-f", fnv1a(f));
    printValue(at, "f[3]", f[3]);
    printValue(at, "volume-inner", e.volume[0]);
    printValue(at, "volume-outer", e.volume[1]);
    printValue(at, "pressure-inner", e.pressure[0]);
    printValue(at, "pressure-outer", e.pressure[1]);
    printValue(at, "damping-power", e.dampingPower);
    for (int family = 0; family < kSpringFamilyCount; ++family)
        printValue(at, ("spring-energy-" + std::string(springFamilyName(SpringFamily(family)))).c_str(),
                   e.springEnergy[static_cast<std::size_t>(family)]);
    std::printf("%s degenerate-springs %d\n", at.c_str(), e.degenerateSprings);
    printValue(at, "contact-energy", e.contactEnergy);
    printValue(at, "contact-power", e.contactPower);
    if (k.throughFloor) {
        // Each kind of contact alone (the walls, the layer barrier); the comparison must not
        // pass by either being absent where it is meant to act.
        const ContactParams both = model.contact;
        model.contact.layerBarrier = false;
        const double walls = model.contactEnergy(x.data());
        model.contact = both;
        model.contact.walls = false;
        const double barrier = model.contactEnergy(x.data());
        model.contact = both;
        printValue(at, "contact-energy-walls", walls);
        printValue(at, "contact-energy-barrier", barrier);
        if (walls <= 0.0 || barrier <= 0.0 || e.contactPower <= 0.0) {
            std::fprintf(stderr, "%s: wall contact, layer barrier or friction absent in the case built for them\n",
                         at.c_str());
            std::exit(1);
        }
    }

    Eigen::VectorXd xdot(n3), a(n3);
    ForceExtras m;
    model.evaluateMotion(x.data(), v.data(), invMass3.data(), xdot.data(), a.data(), m);
    printHash(at, "motion-xdot", fnv1a(xdot));
    printHash(at, "motion-a", fnv1a(a));
    printValue(at, "motion-damping-power", m.dampingPower);

    Eigen::VectorXd reference(n3);
    ForceExtras r;
    model.evaluateReference(x.data(), v.data(), reference.data(), r);
    printHash(at, "reference-f", fnv1a(reference));
    printValue(at, "reference-damping-power", r.dampingPower);

    if (const kernels::PaddedRows g = model.computeVolumeGradient(x.data()))
        printHash(at, "volume-gradient", fnv1a(g.data(), static_cast<std::size_t>(4 * topo.particleCount())));
    const auto energies = model.springEnergies(x.data());
    printHash(at, "spring-energies", fnv1a(energies.data(), energies.size()));
    const auto volumes = model.volumes(x.data());
    printHash(at, "volumes", fnv1a(volumes.data(), volumes.size()));
    printValue(at, "contact-energy-pass", model.contactEnergy(x.data()));
    for (int l = 0; l < 2; ++l)
        printValue(at, l == 0 ? "gas-energy-inner" : "gas-energy-outer",
                   gasEnergy(model.params.gasConstant[static_cast<std::size_t>(l)], volumes[static_cast<std::size_t>(l)]));
}

// --- The kernels alone (the inputs of tests/test_force_kernels.cpp) --------------------------

using kernel_inputs::kBegin;
using kernel_inputs::kMaxLength;
using kernel_inputs::kParticles;
using kernel_inputs::kPerLayer;

// Every kernel on blocks [kBegin, kBegin + length): the hash of the rows it leaves and of the
// sums it returns, and its count of degenerate springs.
void runKernels() {
    const kernel_inputs::Inputs in = kernel_inputs::makeInputs();
    const double *x = in.x.data(), *v = in.v.data();
    for (std::size_t length = 0; length <= kMaxLength; ++length) {
        const std::size_t begin = kBegin, end = kBegin + length;
        auto start = [&] {
            kernels::AlignedBuffer f4(4 * kParticles);
            std::copy(in.f4Start.begin(), in.f4Start.end(), f4.data());
            return f4;
        };
        auto report = [&](const char* kernel, const kernels::AlignedBuffer& rows, std::vector<double> sums, int degenerate) {
            const std::string at = std::string("kernel-") + kernel + " length=" + std::to_string(length);
            const std::uint64_t hash = fnv1a(sums.data(), sums.size(), fnv1a(rows.data(), rows.size()));
            std::printf("%s %016llx degenerate=%d\n", at.c_str(), static_cast<unsigned long long>(hash), degenerate);
        };
        {
            kernels::AlignedBuffer f4 = start();
            int degenerate = 0;
            const kernels::SpringSums s = kernels::springBlock(in.springs, begin, end, 30.0, 0.7, x, v, f4.data(), degenerate);
            report("springs", f4, {s.power, s.stretch2}, degenerate);
        }
        {
            kernels::AlignedBuffer f4 = start();
            int degenerate = 0;
            const kernels::SpringSums s =
                kernels::springRunBlock(in.run, begin, end, kPerLayer, 30.0, 0.7, x, v, f4.data(), degenerate);
            report("radius-run", f4, {s.power, s.stretch2}, degenerate);
        }
        {
            kernels::AlignedBuffer f4 = start();
            int degenerate = 0;
            const kernels::QuadSums s =
                kernels::quadBlock(in.quads, begin, end, kPerLayer, {30.0, 20.0}, {0.7, 0.4}, x, v, f4.data(), degenerate);
            report("edge-quads", f4, {s.power, s.stretch2[0], s.stretch2[1]}, degenerate);
        }
        {
            kernels::AlignedBuffer f4 = start();
            const double volume6 = kernels::triangleBlock(in.surface, begin, end, x, f4.data());
            report("triangles", f4, {volume6}, 0);
        }
        {
            kernels::AlignedBuffer f4 = start(), g4(4 * kParticles), out(3 * kParticles);
            for (std::size_t i = 0; i < g4.size(); ++i) g4.data()[i] = in.f4Start[(i * 7) % in.f4Start.size()];
            std::fill(out.data(), out.data() + out.size(), -1.0);
            const int b = static_cast<int>(begin), e = static_cast<int>(end);
            kernels::unpad(f4.data(), g4.data(), 0.3, in.invMass3.data(), b, e, out.data());
            kernels::unpad(f4.data(), nullptr, 0.0, nullptr, b + e, 2 * e, out.data());
            report("unpad", out, {}, 0);
        }
    }
}

// Eigen's reductions over whole-state vectors (VectorXd), as the integrators use them outside
// the force evaluation (error norms, convergence tests, the Jacobian-vector product's dot): on
// random vectors of lengths 1, 8, ..., 2998, one hash per reduction over all lengths. Their
// order of summation is Eigen's and could depend on the target's vectors, as the row-wise mean
// did (simcore's centroid).
void runReductions() {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<double> squaredNorm, norm, dot, sum;
    for (int n = 1; n <= 3000; n += 7) {
        Eigen::VectorXd a(n), b(n);
        for (int i = 0; i < n; ++i) {
            a[i] = unit(rng);
            b[i] = unit(rng);
        }
        squaredNorm.push_back(a.squaredNorm());
        norm.push_back(a.norm());
        dot.push_back(a.dot(b));
        sum.push_back(a.sum());
    }
    const std::string at = "eigen-vectorxd lengths=" + std::to_string(squaredNorm.size());
    printHash(at, "squaredNorm", fnv1a(squaredNorm.data(), squaredNorm.size()));
    printHash(at, "norm", fnv1a(norm.data(), norm.size()));
    printHash(at, "dot", fnv1a(dot.data(), dot.size()));
    printHash(at, "sum", fnv1a(sum.data(), sum.size()));
}

std::vector<Case> cases() {
    std::vector<Case> list;
    auto add = [&](std::string name, SceneKind kind, std::initializer_list<std::pair<Param, double>> values) -> Case& {
        Case c{std::move(name), ParameterSet(kind)};
        for (const auto& [param, value] : values)
            if (auto error = c.params.set(param, value)) {
                std::fprintf(stderr, "%s: %s\n", c.name.c_str(), error->c_str());
                std::exit(2);
            }
        list.push_back(std::move(c));
        return list.back();
    };
    add("sphere3d-L2", SceneKind::Sphere3d, {{Param::Subdivisions, 2}, {Param::Perturb, 0.05}});
    add("sphere3d-L4", SceneKind::Sphere3d, {{Param::Subdivisions, 4}, {Param::Perturb, 0.02}}).pointer = true;
    add("sphere3d-L4-thesis", SceneKind::Sphere3d,
        {{Param::Subdivisions, 4}, {Param::Scaling, 1}, {Param::Perturb, 0.02}, {Param::Seed, 7}});
    add("ring2d-12", SceneKind::Ring2d, {{Param::Perturb, 0.05}});
    add("ring2d-3001", SceneKind::Ring2d, {{Param::Particles, 3001}, {Param::Perturb, 0.002}});
    add("latlong-8x4", SceneKind::Sphere3dLatLong, {{Param::Perturb, 0.05}});
    add("latlong-31x16", SceneKind::Sphere3dLatLong, {{Param::Slices, 31}, {Param::Stacks, 16}, {Param::Perturb, 0.02}});
    add("spring1d", SceneKind::Spring1d, {{Param::Perturb, 0.05}});
    add("sphere3d-L2-floor", SceneKind::Sphere3d,
        {{Param::Subdivisions, 2}, {Param::Perturb, 0.05}, {Param::Friction, 0.3}, {Param::Restitution, 0.5}})
        .throughFloor = true;
    add("sphere3d-L4-floor", SceneKind::Sphere3d,
        {{Param::Subdivisions, 4}, {Param::Perturb, 0.02}, {Param::Friction, 0.3}}).throughFloor = true;
    add("ring2d-48-floor", SceneKind::Ring2d, {{Param::Particles, 48}, {Param::Perturb, 0.02}, {Param::Friction, 0.3}})
        .throughFloor = true;
    add("latlong-16x8-floor", SceneKind::Sphere3dLatLong,
        {{Param::Slices, 16}, {Param::Stacks, 8}, {Param::Perturb, 0.02}, {Param::Friction, 0.3}}).throughFloor = true;
    return list;
}

}  // namespace

int main(int argc, char** argv) {
    const std::string_view wanted = argc > 1 ? argv[1] : "portable";
    kernels::KernelSet set = kernels::KernelSet::Portable;
    if (wanted == "avx2") set = kernels::KernelSet::Avx2;
    else if (wanted == "avx512") set = kernels::KernelSet::Avx512;
    else if (wanted != "portable") {
        std::fprintf(stderr, "usage: force_hash [portable|avx2|avx512]\n");
        return 2;
    }
    // The set in use on stderr (the results on stdout are the same whatever it is); exit 3
    // when this build or CPU lacks the set asked for, so that nothing is compared by mistake.
    const kernels::KernelSet inUse = kernels::useKernels(set);
    std::fprintf(stderr, "kernels: %s\n", kernels::kernelSetName(inUse));
    if (inUse != set) return 3;
    ThreadPool pool(ForceModel::kChunks);
    for (const Case& c : cases()) runCase(c, pool);
    runKernels();
    runReductions();
    return 0;
}
