// The float32 path (float_path.h).
//
// One force evaluation, as the double path's ForceModel does it: the body's particles are
// owned by fixed chunks (ForceModel::chunksFor; vertex k of each layer by chunk k * chunks / n),
// each chunk's springs and faces join only its own particles, and the few joining two chunks
// are shared:
//  1. each chunk (a task) clears its rows of the force and gradient buffers and adds its
//     springs' forces F = [stiffness (L - L0) + damping (dv.u)] u (+F to the first end, -F to the second,
//     spring by spring) and its faces' rows (b - a) x (c - a) (3D; (dy, -dx) in 2D) to each
//     corner; its damping power damping * (dv.u)^2 and volume terms x_a.((b - a) x (c - a))
//     (= x_a.(x_b x x_c); 2D: the shoelace term) are summed in double lanes. Chunks go in
//     pairs (0, 1), (2, 3): the second of a pair to finish adds the shared springs and faces
//     that join only that pair's particles, in the same task (the two pairs' rows are apart,
//     so with four chunks both pairs' shared elements run at once); with four chunks, the
//     shared elements joining only 0 and 2 and only 1 and 3 then go as a second run of two
//     tasks (their rows are apart too);
//  2. (the caller) the other shared springs and faces, then volumes and pressures from the
//     sums, in chunk order (the chunks, the pairs' shared sets, the cross pairs', the rest);
//  3. particles: (weight + F + P/6 g) / m (P/2 in 2D), handed with v to the integrator's
//     update of the particle's own rows; each chunk runs it on its own particles at the start
//     of the next evaluation's pass 1, the step's last one with the state check, also chunk by
//     chunk (finish).
// Positions, velocities and forces are padded rows (x, y, z, 0) of 16 bytes, so that a
// particle is one 128-bit load. With AVX2 springs, faces and face pairs go eight at a time
// (two edge quads), with AVX-512 sixteen (four quads): the rows are transposed to columns in
// registers, the arithmetic runs eight or sixteen wide, operation for operation as the scalar
// code (no fused multiply-add: simcore builds with -ffp-contract=off), and the results are
// added to the rows one spring or face at a time in order, so that every set gives the same
// bits, and so do 1 and 2 threads (the split depends on the body only). The wide kernels are
// one body for both widths (simcore/internal/float_kernels_body.h).
#include "simcore/float_path.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <unordered_map>

#include "simcore/failure_texts.h"
#include "simcore/force_kernels.h"
#include "simcore/forces.h"
#include "simcore/internal/compensated_time.h"
#include "simcore/parallel.h"

// The AVX2 passes on x86-64 with GCC, unless the build asks for portable kernels only
// (ELASTIC_LAB_PORTABLE_KERNELS: no x86 intrinsics, as for another architecture).
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(ELASTIC_LAB_PORTABLE_KERNELS)
#define SIMCORE_FLOAT_AVX2 1
// GCC 12 warns inside its own AVX-512 intrinsics (_mm512_undefined_ps, GCC bug 105593), as in
// force_kernels.cpp.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#endif

namespace simcore {

namespace {

constexpr std::array<std::string_view, 5> kFloatIntegrators{"euler", "midpoint", "rk4", "symplectic-euler", "verlet"};
constexpr int kParticleTask = 2048;        // particles per task
// Springs and faces are taken in blocks of kStridedBlock with a stride of kStride (see the
// constructor).
constexpr std::size_t kStridedBlock = 128, kStride = 16;

using F4 = float __attribute__((vector_size(16)));

// Rows are read and written as float vectors (a vector of float may alias float; not through
// memcpy, whose accesses may alias anything and make the compiler reload every pointer after
// each store in the update loops).
using F4Unaligned = float __attribute__((vector_size(16), aligned(4)));
inline F4 row(const float* p, int i) { return *reinterpret_cast<const F4Unaligned*>(p + 4 * static_cast<std::ptrdiff_t>(i)); }
inline void setRow(float* p, int i, F4 r) { *reinterpret_cast<F4Unaligned*>(p + 4 * static_cast<std::ptrdiff_t>(i)) = r; }
inline F4 splat(float s) { return F4{s, s, s, s}; }

// Eight lanes of double sums, added lane by lane (lane k % 8 for element k of a task) and
// combined in lane order: the same order for the scalar and the eight-wide code.
struct LaneSums {
    std::array<double, 8> lane{};
    double total() const {
        double s = 0.0;
        for (double l : lane) s += l;
        return s;
    }
};

struct SpringArrays {
    std::vector<int> a, b;
    std::vector<float> rest;
    std::size_t size() const { return a.size(); }
};

inline void addRow(float* f4, int i, F4 r) { setRow(f4, i, row(f4, i) + r); }
inline void subRow(float* f4, int i, F4 r) { setRow(f4, i, row(f4, i) - r); }

// One spring's force F = [stiffness (L - L0) + damping (dv.u)] u from its end differences d
// (positions) and dv (velocities), and its damping power damping (dv.u)^2 in `power`; 0 for
// both when degenerate (L below kDegenerateLength). The reference the eight- and sixteen-wide
// code follows operation by operation. 1/L is L (1/L^2), and dv.u is (dv.d)/L, F is
// (magnitude/L) d: the square root and the division run side by side, and (dv.d) beside both,
// which shortens the chain each spring waits on (the kernels were bound by its latency).
inline F4 springForce(F4 d, F4 dv, float stiffness, float damping, float rest, float& power) {
    const float len2 = (d[0] * d[0] + d[1] * d[1]) + d[2] * d[2];
    const float len = std::sqrt(len2);
    const float inv = len * (1.0f / len2);
    const float dvu = ((dv[0] * d[0] + dv[1] * d[1]) + dv[2] * d[2]) * inv;
    const float scale = (stiffness * (len - rest) + damping * dvu) * inv;
    const bool ok = len >= static_cast<float>(kDegenerateLength);
    power = ok ? damping * dvu * dvu : 0.0f;
    return ok ? F4{scale * d[0], scale * d[1], scale * d[2], 0.0f} : F4{};
}

// Edge quads of a two-layer body, as ForceModel's (force_kernels.h, QuadSet): for a mesh edge
// (a, b) of the inner layer and its outer copy (A, B) = (a + n, b + n), the four springs over
// the same four particles, one per lane: structural (a, b), structural (A, B), shear (A, b)
// and shear (B, a). Evaluated together they update 4 particle rows instead of 8 (the wide code
// reads each of the 4 particles' rows twice, as a first and as a second end, since stop 45:
// the second read comes from the L1 cache, cheaper than the column permutations it replaced).
struct QuadArrays {
    std::vector<int> a, b;
    std::vector<float> rest;  // 4 per quad, in lane order
    std::size_t size() const { return a.size(); }
};

// One quad, scalar: lane l's spring as springScalar, its power to lane ((q - base) % 2) * 4 + l;
// the rows then updated in a fixed order: a += F0 - F3, b -= F0 + F2, A += F1 + F2,
// B += F3 - F1.
inline void quadScalar(const QuadArrays& quads, std::size_t base, std::size_t q, int n, const std::array<float, 4>& stiffness,
                       const std::array<float, 4>& damping, const float* x, const float* v, float* f4, LaneSums& power) {
    const int a = quads.a[q], b = quads.b[q], A = a + n, B = b + n;
    const std::array<int, 4> first{a, A, A, B}, second{b, B, b, a};
    std::array<F4, 4> force;
    for (std::size_t l = 0; l < 4; ++l) {
        const F4 d = row(x, second[l]) - row(x, first[l]), dv = row(v, second[l]) - row(v, first[l]);
        float p;
        force[l] = springForce(d, dv, stiffness[l], damping[l], quads.rest[4 * q + l], p);
        power.lane[((q - base) % 2) * 4 + l] += static_cast<double>(p);
    }
    addRow(f4, a, force[0] - force[3]);
    subRow(f4, b, force[0] + force[2]);
    addRow(f4, A, force[1] + force[2]);
    addRow(f4, B, force[3] - force[1]);
}

// One spring, scalar: the reference the eight-wide code follows operation by operation. Its
// power goes to lane (k - base) % 8.
inline void springScalar(const SpringArrays& s, std::size_t base, std::size_t k, float stiffness, float damping, const float* x,
                         const float* v, float* f4, LaneSums& power) {
    const F4 xa = row(x, s.a[k]), xb = row(x, s.b[k]), va = row(v, s.a[k]), vb = row(v, s.b[k]);
    float p;
    const F4 force = springForce(xb - xa, vb - va, stiffness, damping, s.rest[k], p);
    addRow(f4, s.a[k], force);
    subRow(f4, s.b[k], force);
    power.lane[(k - base) % 8] += static_cast<double>(p);
}

// One face, scalar: its row added to its corners, its volume term to lane (k - base) % 8.
inline void faceScalar(const std::vector<std::array<int, 3>>& faces, int dimension, std::size_t base, std::size_t k,
                       const float* x, float* g4, LaneSums& volume) {
    const auto& f = faces[k];
    const F4 xa = row(x, f[0]), xb = row(x, f[1]);
    float term;
    if (dimension == 2) {
        const F4 d = xb - xa;
        const F4 g{d[1], 0.0f - d[0], 0.0f, 0.0f};
        term = xa[0] * xb[1] - xb[0] * xa[1];
        addRow(g4, f[0], g);
        addRow(g4, f[1], g);
    } else {
        const F4 xc = row(x, f[2]);
        const F4 e = xb - xa, h = xc - xa;
        const F4 g{e[1] * h[2] - e[2] * h[1], e[2] * h[0] - e[0] * h[2], e[0] * h[1] - e[1] * h[0], 0.0f};
        term = (xa[0] * g[0] + xa[1] * g[1]) + xa[2] * g[2];
        addRow(g4, f[0], g);
        addRow(g4, f[1], g);
        addRow(g4, f[2], g);
    }
    volume.lane[(k - base) % 8] += static_cast<double>(term);
}

// A pair of faces sharing an edge, (a, b, c) and (b, a, d) (3D): their rows g1 = (b - a) x
// (c - a) and g2 = (a - b) x (d - b) as faceScalar's, g1 + g2 added to a and b, g1 to c, g2 to
// d (4 rows loaded and 4 updated for two faces, instead of 6 and 6); the volume terms
// a.g1 then b.g2 to lane (k - base) % 8. The reference of the wide code.
inline void facePairScalar(const int* corners, std::size_t stride, std::size_t base, std::size_t k, const float* x, float* g4,
                           LaneSums& volume) {
    const int a = corners[k], b = corners[stride + k], c = corners[2 * stride + k], d = corners[3 * stride + k];
    const F4 xa = row(x, a), xb = row(x, b), xc = row(x, c), xd = row(x, d);
    auto cross = [](F4 e, F4 h) {
        return F4{e[1] * h[2] - e[2] * h[1], e[2] * h[0] - e[0] * h[2], e[0] * h[1] - e[1] * h[0], 0.0f};
    };
    const F4 g1 = cross(xb - xa, xc - xa), g2 = cross(xa - xb, xd - xb);
    const F4 both = g1 + g2;
    addRow(g4, a, both);
    addRow(g4, b, both);
    addRow(g4, c, g1);
    addRow(g4, d, g2);
    volume.lane[(k - base) % 8] += static_cast<double>((xa[0] * g1[0] + xa[1] * g1[1]) + xa[2] * g1[2]);
    volume.lane[(k - base) % 8] += static_cast<double>((xb[0] * g2[0] + xb[1] * g2[1]) + xb[2] * g2[2]);
}

#ifdef SIMCORE_FLOAT_AVX2
// The wide kernels, one body for both widths (simcore/internal/float_kernels_body.h).
#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
#define SIMCORE_FLOAT_WIDTH 8
#include "simcore/internal/float_kernels_body.h"
#undef SIMCORE_FLOAT_WIDTH
}  // namespace avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx2")
namespace avx512 {
#define SIMCORE_FLOAT_WIDTH 16
#include "simcore/internal/float_kernels_body.h"
#undef SIMCORE_FLOAT_WIDTH
}  // namespace avx512
#pragma GCC pop_options

bool haveAvx2() { return __builtin_cpu_supports("avx2"); }
#endif

// The springs and faces of one chunk (or the shared ones), and what they sum.
struct Chunk {
    QuadArrays quads;
    SpringArrays springs;
    std::array<std::size_t, kSpringFamilyCount + 1> familyStart{};  // families in order
    std::vector<std::array<int, 3>> faces;                          // slot 0's first
    std::size_t slotStart = 0;                                      // the first face of slot 1
    std::vector<int> faceCorners;                                   // three columns
    std::array<std::vector<int>, 2> pairCorners;                    // per slot: face pairs, four columns
    std::vector<std::pair<int, int>> owned;                         // particle ranges [begin, end)
    LaneSums power;
    std::array<LaneSums, 2> volume;
};

// Faces sharing an edge in pairs (a, b, c) and (b, a, d), found greedily within each slot of a
// chunk (on the level-6 sphere 95 % of the faces): their corners go to the chunk's pairCorners
// (four columns, in strided blocks as the faces), the rest stay in its faces.
void pairFaces(Chunk& c) {
    std::vector<std::array<int, 3>> single;
    std::size_t singleSlotStart = 0;
    const std::array<std::size_t, 3> cut{0, c.slotStart, c.faces.size()};
    for (std::size_t slot = 0; slot < 2; ++slot) {
        if (slot == 1) singleSlotStart = single.size();
        std::unordered_map<std::uint64_t, std::size_t> byEdge;  // directed edge -> face
        auto edgeKey = [](int u, int w) {
            return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(u)) << 32) | static_cast<std::uint32_t>(w);
        };
        for (std::size_t f = cut[slot]; f < cut[slot + 1]; ++f)
            for (std::size_t e = 0; e < 3; ++e) byEdge.emplace(edgeKey(c.faces[f][e], c.faces[f][(e + 1) % 3]), f);
        std::vector<bool> matched(c.faces.size(), false);
        std::vector<std::array<int, 4>> pairs;
        for (std::size_t f = cut[slot]; f < cut[slot + 1]; ++f) {
            if (matched[f]) continue;
            for (std::size_t e = 0; e < 3 && !matched[f]; ++e) {
                const int u = c.faces[f][e], w = c.faces[f][(e + 1) % 3];
                const auto other = byEdge.find(edgeKey(w, u));
                if (other == byEdge.end() || other->second == f || matched[other->second]) continue;
                const auto& g = c.faces[other->second];
                int d = g[0];
                for (int corner : g)
                    if (corner != u && corner != w) d = corner;
                pairs.push_back({u, w, c.faces[f][(e + 2) % 3], d});
                matched[f] = matched[other->second] = true;
            }
            if (!matched[f]) single.push_back(c.faces[f]);
        }
        // In strided blocks, as the faces and springs (see the constructor).
        std::vector<std::array<int, 4>> order;
        std::size_t block = 0;
        for (; block + kStridedBlock <= pairs.size(); block += kStridedBlock)
            for (std::size_t r = 0; r < kStride; ++r)
                for (std::size_t q = 0; q < kStridedBlock / kStride; ++q) order.push_back(pairs[block + q * kStride + r]);
        for (; block < pairs.size(); ++block) order.push_back(pairs[block]);
        c.pairCorners[slot].resize(4 * order.size());
        for (std::size_t k = 0; k < order.size(); ++k)
            for (std::size_t corner = 0; corner < 4; ++corner) c.pairCorners[slot][corner * order.size() + k] = order[k][corner];
    }
    c.faces = std::move(single);
    c.slotStart = singleSlotStart;
}

}  // namespace

bool floatPathSupports(std::string_view integrator) {
    return std::find(kFloatIntegrators.begin(), kFloatIntegrators.end(), integrator) != kFloatIntegrators.end();
}

std::string floatPathIntegrators() {
    std::string s;
    for (std::string_view name : kFloatIntegrators) s += (s.empty() ? "" : ", ") + std::string(name);
    return s;
}

std::string floatPathIntegratorRefusal(std::string_view integrator) {
    if (floatPathSupports(integrator)) return "";
    return "precision float is built for the explicit integrators " + floatPathIntegrators() + ", not " +
           quoteShort(integrator);
}

std::string floatPathRefusal(const Simulation& start) {
    if (std::string refusal = floatPathIntegratorRefusal(start.integrator().name()); !refusal.empty()) return refusal;
    if (start.pointer().active) return "precision float has no pointer (mouse spring)";
    return "";
}

struct FloatSimulation::Impl {
    // The body.
    const Topology* topo = nullptr;
    int n = 0;
    int dimension = 3;
    Eigen::VectorXd mass;
    std::vector<float> invMass;   // per particle (0 on fixed particles)
    std::vector<float> weightY;   // the weight's y component per particle
    F4 axes{};                    // 1 on the body's axes, 0 on the others (and the pad)
    // The owners; each pair's shared springs and faces; with four owners each cross pair's
    // (0, 2), (1, 3); the other shared ones.
    std::vector<Chunk> chunks;
    int owners = 1;  // chunks that own particles (ForceModel::chunksFor)
    int crosses() const { return owners >= 4 ? owners / 2 : 0; }
    Chunk& pairShared(int pair) { return chunks[static_cast<std::size_t>(owners + pair)]; }
    Chunk& crossShared(int cross) { return chunks[static_cast<std::size_t>(owners + owners / 2 + cross)]; }
    std::array<std::atomic<int>, ForceModel::kChunks / 2> pairArrivals{};  // per pair: its chunks done in this pass
    std::array<float, kSpringFamilyCount> stiffness{}, damping{};
    int perLayer = 0;  // particles per layer (the quads' outer offset)
    std::vector<std::uint8_t> particleSlot;
    ForceParams params;
    bool gas = false;
    std::array<double, 3> low{}, high{};

    // State and scratch (4 floats per particle).
    std::vector<float> x, v, xt, vt, xa, va;
    std::vector<float> force4, gradient4;
    std::array<float, 2> pressureScaled{};  // P / 6 (P / 2 in 2D) per slot
    double stagePower = 0.0;                // the last evaluation's damping power [W]
    bool stateSound = true;                 // finish found every particle finite and inside
    std::uint64_t evaluations = 0;

    std::unique_ptr<ThreadPool> pool;
    int threads = 1;
    kernels::KernelSet simd = kernels::KernelSet::Portable;  // the passes: portable, AVX2 or AVX-512

    mutable Diagnostics diag;
    mutable bool measured = false;
    double removed = 0.0;
    double initialEnergy = 0.0;

    int particleTasks() const { return (n + kParticleTask - 1) / kParticleTask; }

    void run(int count, TaskRef task) {
        if (pool) {
            pool->run(count, task);
        } else {
            for (int t = 0; t < count; ++t) task(t);
        }
    }

    // A chunk's springs and faces at (px, pv), added to the force and gradient rows.
    void accumulate(Chunk& c, const float* px, const float* pv) {
        c.power = {};
        c.volume = {};
        float* f4 = force4.data();
        const std::array<float, 4> quadStiffness{stiffness[0], stiffness[0], stiffness[2], stiffness[2]}, quadDamping{damping[0], damping[0], damping[2], damping[2]};
#ifdef SIMCORE_FLOAT_AVX2
        if (simd == kernels::KernelSet::Avx512)
            avx512::quads(c.quads, 0, c.quads.size(), perLayer, quadStiffness, quadDamping, px, pv, f4, c.power);
        else if (simd == kernels::KernelSet::Avx2)
            avx2::quads(c.quads, 0, c.quads.size(), perLayer, quadStiffness, quadDamping, px, pv, f4, c.power);
        else
#endif
            for (std::size_t q = 0; q < c.quads.size(); ++q)
                quadScalar(c.quads, 0, q, perLayer, quadStiffness, quadDamping, px, pv, f4, c.power);
        for (std::size_t f = 0; f < static_cast<std::size_t>(kSpringFamilyCount); ++f) {
            const std::size_t begin = c.familyStart[f], end = c.familyStart[f + 1];
#ifdef SIMCORE_FLOAT_AVX2
            if (simd == kernels::KernelSet::Avx512) {
                avx512::springs(c.springs, begin, end, stiffness[f], damping[f], px, pv, f4, c.power);
                continue;
            }
            if (simd == kernels::KernelSet::Avx2) {
                avx2::springs(c.springs, begin, end, stiffness[f], damping[f], px, pv, f4, c.power);
                continue;
            }
#endif
            for (std::size_t k = begin; k < end; ++k) springScalar(c.springs, begin, k, stiffness[f], damping[f], px, pv, f4, c.power);
        }
        if (!gas) return;
        float* g4 = gradient4.data();
        const std::array<std::size_t, 3> cut{0, c.slotStart, c.faces.size()};
        for (std::size_t slot = 0; slot < 2; ++slot) {
            const std::vector<int>& pairs = c.pairCorners[slot];
            const std::size_t pairCount = pairs.size() / 4;
#ifdef SIMCORE_FLOAT_AVX2
            if (simd == kernels::KernelSet::Avx512)
                avx512::facePairs(pairs.data(), pairCount, 0, pairCount, px, g4, c.volume[slot]);
            else if (simd == kernels::KernelSet::Avx2)
                avx2::facePairs(pairs.data(), pairCount, 0, pairCount, px, g4, c.volume[slot]);
            else
#endif
                for (std::size_t k = 0; k < pairCount; ++k) facePairScalar(pairs.data(), pairCount, 0, k, px, g4, c.volume[slot]);
#ifdef SIMCORE_FLOAT_AVX2
            if (simd == kernels::KernelSet::Avx512 && dimension == 3) {
                avx512::faces(c.faces, c.faceCorners.data(), c.faces.size(), cut[slot], cut[slot + 1], px, g4, c.volume[slot]);
                continue;
            }
            if (simd == kernels::KernelSet::Avx2 && dimension == 3) {
                avx2::faces(c.faces, c.faceCorners.data(), c.faces.size(), cut[slot], cut[slot + 1], px, g4, c.volume[slot]);
                continue;
            }
#endif
            for (std::size_t k = cut[slot]; k < cut[slot + 1]; ++k)
                faceScalar(c.faces, dimension, cut[slot], k, px, g4, c.volume[slot]);
        }
    }

    // Passes 1 and 2 at (px, pv): forces and gradients, damping power and pressures. Each
    // chunk first runs `pending` (the previous evaluation's stage update, which writes the rows
    // px and pv of this one) on its own particles and clears their force and gradient rows
    // (the update has read them), then adds its springs and faces: a chunk's springs and faces
    // read only its own particles, and the shared ones run after every chunk is done, so no
    // separate update pass (and no pool run for it) is needed.
    template <class Pending>
    void springsAndFaces(const float* px, const float* pv, Pending&& pending) {
        const int pairs = owners / 2;
        for (int p = 0; p < pairs; ++p) pairArrivals[static_cast<std::size_t>(p)].store(0, std::memory_order_relaxed);
        auto task = [&](int t) {
            Chunk& c = chunks[static_cast<std::size_t>(t)];
            for (auto [begin, end] : c.owned) pending(begin, end);
            accumulate(c, px, pv);
            // The second of the pair to finish adds the pair's shared springs and faces (the
            // acquire sees the other's rows; the release hands its own to the second).
            if (pairs > 0 && pairArrivals[static_cast<std::size_t>(t / 2)].fetch_add(1, std::memory_order_acq_rel) == 1)
                accumulate(pairShared(t / 2), px, pv);
        };
        run(owners, task);
        // The cross pairs' shared elements (after both pairs': they add to the same rows), at
        // once, then the rest.
        if (crosses() > 0)
            run(crosses(), [&](int t) { accumulate(crossShared(t), px, pv); });
        accumulate(chunks.back(), px, pv);
        double power = 0.0;
        for (const Chunk& c : chunks) power += c.power.total();
        stagePower = power;
        if (gas)
            for (std::size_t slot = 0; slot < 2; ++slot) {
                double sum = 0.0;
                for (const Chunk& c : chunks) sum += c.volume[slot].total();
                const double volume = dimension == 2 ? 0.5 * sum : sum / 6.0;
                const double pressure = volume > 0.0 ? params.gasConstant[slot] / volume : 0.0;
                pressureScaled[slot] = static_cast<float>(dimension == 2 ? 0.5 * pressure : pressure / 6.0);
            }
        ++evaluations;
    }

    // Pass 3: the force on particle i (its weight, its springs, its gas), times its inverse mass.
    // The accelerations of the last evaluation, with what they need in locals (the update
    // loops then keep them in registers: a store to a row could otherwise alias any of them);
    // each particle's force and gradient rows are cleared once read, so they are zero between
    // evaluations and between steps.
    struct Accelerations {
        float* f4;
        float* g4;
        const float* weightY;
        const float* invMass;
        const std::uint8_t* slot;
        std::array<float, 2> pressure;
        bool gas;
        F4 axes;
        F4 take(int i) const {
            const auto k = static_cast<std::size_t>(i);
            F4 f = F4{0.0f, weightY[k], 0.0f, 0.0f} + row(f4, i);
            setRow(f4, i, F4{});
            if (gas) {
                f += splat(pressure[slot[k]]) * row(g4, i);
                setRow(g4, i, F4{});
            }
            // (f * m^-1) * 1 is f * m^-1, and (f * m^-1) * 0 the signed zero f * 0 gives: the
            // same bits as a row of m^-1 with 0 on the absent axes.
            return (f * splat(invMass[k])) * axes;
        }
    };
    Accelerations accelerations() {
        return {force4.data(), gradient4.data(), weightY.data(), invMass.data(), particleSlot.data(), pressureScaled, gas, axes};
    }

    // The evaluation's stage update as a pending update of particles [begin, end):
    // update(i, v_i, a_i), with v_i the row of the evaluation's velocities pv and a_i from its
    // forces. The update (a lambda capturing by value) is copied to a local for the loop.
    template <class Update>
    auto stage(const float* pv, const Update& update) {
        return [this, pv, &update](int begin, int end) {
            const Accelerations acc = accelerations();
            const Update local = update;
            for (int i = begin; i < end; ++i) local(i, row(pv, i), acc.take(i));
        };
    }

    // One evaluation at (px, pv) whose stage update runs with the next pass (the next
    // evaluation's chunk pass, or finish): returns that update.
    template <class Pending, class Update>
    auto evaluate(const float* px, const float* pv, Pending&& pending, const Update& update) {
        springsAndFaces(px, pv, pending);
        return stage(pv, update);
    }

    // The step's last update and the check of the state (finite, inside the walls) in one
    // pool run; sets stateSound. With several chunks each task is a chunk's own particles, as
    // in the chunk passes, so a thread updates the rows it wrote and will read next (pieces
    // across the chunks sent half the rows from one core's cache to the other's every step);
    // one chunk's body goes in pieces of kParticleTask. Checked a block at a time, after its
    // update.
    template <class Pending>
    void finish(Pending&& pending) {
        std::array<std::uint8_t, 64> pieceOk{};
        auto updateAndCheck = [&](int begin, int end) {
            bool ok = true;
            for (int block = begin; block < end; block += kParticleTask) {
                const int blockEnd = std::min(end, block + kParticleTask);
                pending(block, blockEnd);
                ok = sound(block, blockEnd) && ok;
            }
            return ok;
        };
        int tasks = 0;
        if (owners > 1) {
            tasks = owners;
            run(tasks, [&](int t) {
                bool ok = true;
                for (auto [begin, end] : chunks[static_cast<std::size_t>(t)].owned) ok = updateAndCheck(begin, end) && ok;
                pieceOk[static_cast<std::size_t>(t)] = ok ? 1 : 0;
            });
        } else {
            tasks = std::min<int>(particleTasks(), static_cast<int>(pieceOk.size()));
            const int per = (n + tasks - 1) / tasks;
            run(tasks, [&](int t) {
                const int begin = t * per, end = std::min(n, begin + per);
                pieceOk[static_cast<std::size_t>(t)] = updateAndCheck(begin, end) ? 1 : 0;
            });
        }
        stateSound = true;
        for (int t = 0; t < tasks; ++t) stateSound = stateSound && pieceOk[static_cast<std::size_t>(t)] != 0;
    }

    void step(std::string_view integrator, float h, double hd) {
        float* X = x.data();
        float* V = v.data();
        const auto none = [](int, int) {};  // the rows are clear at the start of a step
        if (integrator == "euler") {
            auto update = [=](int i, F4 vi, F4 ai) {
                setRow(X, i, row(X, i) + splat(h) * vi);
                setRow(V, i, vi + splat(h) * ai);
            };
            finish(evaluate(X, V, none, update));
            removed += hd * stagePower;
        } else if (integrator == "symplectic-euler") {
            auto update = [=](int i, F4 vi, F4 ai) {
                const F4 vn = vi + splat(h) * ai;
                setRow(V, i, vn);
                setRow(X, i, row(X, i) + splat(h) * vn);
            };
            finish(evaluate(X, V, none, update));
            removed += hd * stagePower;
        } else if (integrator == "verlet") {
            const float half = 0.5f * h, hh = 0.5f * h * h;
            auto first = [=](int i, F4 vi, F4 ai) {
                setRow(X, i, row(X, i) + splat(h) * vi + splat(hh) * ai);
                setRow(V, i, vi + splat(half) * ai);
            };
            auto second = [=](int i, F4 vi, F4 ai) { setRow(V, i, vi + splat(half) * ai); };
            auto pending = evaluate(X, V, none, first);
            const double p1 = stagePower;
            finish(evaluate(X, V, pending, second));
            removed += 0.5 * hd * (p1 + stagePower);
        } else if (integrator == "midpoint") {
            float* XT = xt.data();
            float* VT = vt.data();
            const float half = 0.5f * h;
            auto first = [=](int i, F4 vi, F4 ai) {
                setRow(XT, i, row(X, i) + splat(half) * vi);
                setRow(VT, i, vi + splat(half) * ai);
            };
            auto second = [=](int i, F4 vi, F4 ai) {
                setRow(X, i, row(X, i) + splat(h) * vi);
                setRow(V, i, row(V, i) + splat(h) * ai);
            };
            auto pending = evaluate(X, V, none, first);
            finish(evaluate(XT, VT, pending, second));
            removed += hd * stagePower;
        } else {
            rk4(h, hd);
        }
    }

    // One RK4 step: four evaluations, each stage's update run with the next pass.
    void rk4(float h, double hd) {
        float* X = x.data();
        float* V = v.data();
        const auto none = [](int, int) {};  // the rows are clear at the start of a step
        float* XT = xt.data();
        float* VT = vt.data();
        float* XA = xa.data();
        float* VA = va.data();
        const float sixth = h / 6.0f, third = h / 3.0f, half = 0.5f * h;
        auto first = [=](int i, F4 vi, F4 ai) {
            const F4 xi = row(X, i);
            setRow(XA, i, xi + splat(sixth) * vi);
            setRow(VA, i, vi + splat(sixth) * ai);
            setRow(XT, i, xi + splat(half) * vi);
            setRow(VT, i, vi + splat(half) * ai);
        };
        auto middle = [&](float c) {
            return [=](int i, F4 vi, F4 ai) {
                setRow(XA, i, row(XA, i) + splat(third) * vi);
                setRow(VA, i, row(VA, i) + splat(third) * ai);
                setRow(XT, i, row(X, i) + splat(c) * vi);
                setRow(VT, i, row(V, i) + splat(c) * ai);
            };
        };
        auto second = middle(half), thirdUpdate = middle(h);
        auto last = [=](int i, F4 vi, F4 ai) {
            setRow(X, i, row(XA, i) + splat(sixth) * vi);
            setRow(V, i, row(VA, i) + splat(sixth) * ai);
        };
        auto pending1 = evaluate(X, V, none, first);
        double power = stagePower;
        auto pending2 = evaluate(XT, VT, pending1, second);
        power += 2.0 * stagePower;
        auto pending3 = evaluate(XT, VT, pending2, thirdUpdate);
        power += 2.0 * stagePower;
        finish(evaluate(XT, VT, pending3, last));
        power += stagePower;
        removed += hd / 6.0 * power;
    }

    // Whether particles [begin, end) are finite and inside the walls (branch-free: the step's
    // common case is that they are).
    bool sound(int begin, int end) const {
        const F4 lo{static_cast<float>(std::max(low[0], -3e38)), static_cast<float>(std::max(low[1], -3e38)),
                    static_cast<float>(std::max(low[2], -3e38)), -1.0f};
        const F4 hi{static_cast<float>(std::min(high[0], 3e38)), static_cast<float>(std::min(high[1], 3e38)),
                    static_cast<float>(std::min(high[2], 3e38)), 1.0f};
        const F4 big = splat(3e38f);
        auto bad = F4{} < F4{};  // all lanes false
        for (int i = begin; i < end; ++i) {
            const F4 xi = row(x.data(), i), vi = row(v.data(), i);
            // NaN fails every comparison, so "not (inside)" catches it; infinities are outside.
            bad |= !((xi >= lo) & (xi <= hi) & (vi >= (F4{} - big)) & (vi <= big));
        }
        return !(bad[0] | bad[1] | bad[2] | bad[3]);
    }

    // The reason the state is unusable, or "": checked in parallel pieces, the first bad
    // particle found again serially for the message.
    // The reason the state is unusable, or "": finish checked it in parallel pieces; the first
    // bad particle is found again serially for the message.
    std::string check() {
        if (stateSound) return "";
        for (int i = 0; i < n; ++i) {
            const F4 xi = row(x.data(), i), vi = row(v.data(), i);
            for (int axis = 0; axis < 3; ++axis) {
                if (!std::isfinite(xi[axis]) || !std::isfinite(vi[axis]))
                    return failure_text::floatNotFinite(static_cast<std::size_t>(i));
                const double c = xi[axis];
                if (c < low[static_cast<std::size_t>(axis)] || c > high[static_cast<std::size_t>(axis)])
                    return failure_text::floatReachedWall(static_cast<std::size_t>(i));
            }
        }
        return "";
    }

    void toDouble(Eigen::VectorXd& out) const {
        out.resize(6 * static_cast<Eigen::Index>(n));
        for (int i = 0; i < n; ++i)
            for (int axis = 0; axis < 3; ++axis) {
                out[3 * i + axis] = static_cast<double>(x[4 * static_cast<std::size_t>(i) + static_cast<std::size_t>(axis)]);
                out[3 * (n + i) + axis] =
                    static_cast<double>(v[4 * static_cast<std::size_t>(i) + static_cast<std::size_t>(axis)]);
            }
    }

    // Energies, volumes and pressures in double from the float state (the double path's
    // functions).
    void measure(Diagnostics& d) const {
        Eigen::VectorXd y;
        toDouble(y);
        const double* px = y.data();
        const double* pv = y.data() + 3 * n;
        d.kinetic = 0.0;
        d.gravity = 0.0;
        for (int i = 0; i < n; ++i) {
            const double m = mass[i];
            d.kinetic += 0.5 * m * ((pv[3 * i] * pv[3 * i] + pv[3 * i + 1] * pv[3 * i + 1]) + pv[3 * i + 2] * pv[3 * i + 2]);
            d.gravity += m * params.gravity * px[3 * i + 1];
        }
        for (int f = 0; f < kSpringFamilyCount; ++f)
            d.spring[static_cast<std::size_t>(f)] =
                springEnergy(topo->springs[static_cast<std::size_t>(f)], params.stiffness[static_cast<std::size_t>(f)], px);
        d.gas = 0.0;
        d.volume = {};
        d.pressure = {};
        if (gas)
            for (const Surface& s : topo->surfaces) {
                const std::size_t count = dimension == 2 ? s.edges.size() : s.triangles.size();
                const double sum = partialVolume(s, dimension, px, 0, count);
                const double volume = dimension == 2 ? 0.5 * sum : sum / 6.0;
                const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
                d.volume[slot] = volume;
                d.pressure[slot] = volume > 0.0 ? params.gasConstant[slot] / volume : 0.0;
                d.gas += gasEnergy(params.gasConstant[slot], volume);
            }
    }
};

// Kept whole: the float layout built in one pass, each stage over what the one before decided
// (chunk ownership, then the edge quads taken out of the families, the families, the faces,
// the state), sharing its locals; read top to bottom it is docs/performance.md's description.
FloatSimulation::FloatSimulation(const Simulation& start) : m_impl(std::make_unique<Impl>()) {
    if (std::string refusal = floatPathRefusal(start); !refusal.empty()) throw std::invalid_argument(refusal);
    Impl& s = *m_impl;
    const Topology& topo = start.topology();
    m_topology = &topo;
    m_integrator = std::string(start.integrator().name());
    m_dt = start.dt();
    m_time = start.time();
    m_step = start.stepCount();
    s.topo = &topo;
    s.n = topo.particleCount();
    s.dimension = topo.dimension;
    s.mass = start.body().mass;
    const ForceModel& model = start.forces();
    s.params = model.params;
    if (!model.terms().has(Term::Gravity)) s.params.gravity = 0.0;
    s.gas = model.terms().has(Term::Gas);
    s.low = model.contact.low;
    s.high = model.contact.high;
    const auto n = static_cast<std::size_t>(s.n);
    s.invMass.assign(n, 0.0f);
    s.weightY.assign(n, 0.0f);
    for (std::size_t i = 0; i < n; ++i) {
        const bool fixed = i < start.body().fixed.size() && start.body().fixed[i];
        s.invMass[i] = fixed ? 0.0f : static_cast<float>(1.0 / s.mass[static_cast<Eigen::Index>(i)]);
        s.weightY[i] = static_cast<float>(0.0 - s.mass[static_cast<Eigen::Index>(i)] * s.params.gravity);
    }
    s.axes = F4{s.dimension >= 2 ? 1.0f : 0.0f, 1.0f, s.dimension == 3 ? 1.0f : 0.0f, 0.0f};
    // Chunks by particle ownership (as many as ForceModel::chunksFor gives; vertex k of each
    // layer in chunk k * chunks / n); a spring or face whose particles are not all one chunk's
    // is shared.
    const int owners = ForceModel::chunksFor(topo.springCount());
    s.owners = owners;
    const bool layered = !topo.layerPairs.empty() && 2 * topo.layerPairs.size() == n;
    const int perLayer = layered ? s.n / 2 : s.n;
    auto owner = [&](int i) { return owners == 1 ? 0 : ((i % perLayer) * owners) / perLayer; };
    // The owners, then per pair of owners (0, 1), (2, 3) the shared elements joining only
    // that pair, then (four owners) per cross pair (0, 2), (1, 3), then the other shared ones.
    s.chunks.resize(static_cast<std::size_t>(owners + owners / 2 + s.crosses()) + 1);
    auto chunkOf = [&](std::initializer_list<int> particles) {
        unsigned touched = 0;
        for (int p : particles) touched |= 1u << owner(p);
        for (int c = 0; c < owners; ++c)
            if (touched == 1u << c) return &s.chunks[static_cast<std::size_t>(c)];
        for (int pair = 0; pair < owners / 2; ++pair)
            if ((touched & ~(3u << (2 * pair))) == 0) return &s.pairShared(pair);
        for (int cross = 0; cross < s.crosses(); ++cross)
            if ((touched & ~((1u << cross) | (1u << (cross + owners / 2)))) == 0) return &s.crossShared(cross);
        return &s.chunks.back();
    };
    for (int i = 0; i < s.n; ++i) {
        auto& owned = s.chunks[static_cast<std::size_t>(owner(i))].owned;
        if (!owned.empty() && owned.back().second == i) ++owned.back().second;
        else owned.emplace_back(i, i + 1);
    }
    s.perLayer = perLayer;
    // Edge quads (two-layer bodies): each inner structural spring (a, b) whose outer copy
    // (A, B) and shear springs (A, b), (B, a) exist (in either orientation), all four in one
    // chunk; their springs leave the families.
    std::array<std::vector<bool>, kSpringFamilyCount> inQuad;
    for (std::size_t f = 0; f < static_cast<std::size_t>(kSpringFamilyCount); ++f)
        inQuad[f].assign(topo.springs[f].size(), false);
    if (layered) {
        const auto structural = static_cast<std::size_t>(SpringFamily::Structural),
                   shear = static_cast<std::size_t>(SpringFamily::Shear);
        auto key = [](int i, int j) {
            return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(i, j))) << 32) |
                   static_cast<std::uint32_t>(std::max(i, j));
        };
        std::unordered_map<std::uint64_t, std::size_t> structuralAt, shearAt;
        for (std::size_t k = 0; k < topo.springs[structural].size(); ++k)
            structuralAt.emplace(key(topo.springs[structural].a[k], topo.springs[structural].b[k]), k);
        for (std::size_t k = 0; k < topo.springs[shear].size(); ++k)
            shearAt.emplace(key(topo.springs[shear].a[k], topo.springs[shear].b[k]), k);
        const SpringSet& st = topo.springs[structural];
        const SpringSet& sh = topo.springs[shear];
        for (std::size_t k = 0; k < st.size(); ++k) {
            const int a = st.a[k], b = st.b[k];
            if (a >= perLayer || b >= perLayer || inQuad[structural][k]) continue;
            const int A = a + perLayer, B = b + perLayer;
            const auto outer = structuralAt.find(key(A, B)), s1 = shearAt.find(key(A, b)), s2 = shearAt.find(key(B, a));
            if (outer == structuralAt.end() || s1 == shearAt.end() || s2 == shearAt.end()) continue;
            if (inQuad[structural][outer->second] || inQuad[shear][s1->second] || inQuad[shear][s2->second]) continue;
            Chunk* c = chunkOf({a, b, A, B});  // the shared ones too: fewer loads on the serial stretch
            inQuad[structural][k] = inQuad[structural][outer->second] = true;
            inQuad[shear][s1->second] = inQuad[shear][s2->second] = true;
            c->quads.a.push_back(a);
            c->quads.b.push_back(b);
            for (double rest : {st.rest[k], st.rest[outer->second], sh.rest[s1->second], sh.rest[s2->second]})
                c->quads.rest.push_back(static_cast<float>(rest));
        }
        for (Chunk& c : s.chunks) {  // strided blocks, as the springs below
            QuadArrays order;
            std::size_t block = 0;
            auto take = [&](std::size_t q) {
                order.a.push_back(c.quads.a[q]);
                order.b.push_back(c.quads.b[q]);
                for (std::size_t l = 0; l < 4; ++l) order.rest.push_back(c.quads.rest[4 * q + l]);
            };
            for (; block + kStridedBlock <= c.quads.size(); block += kStridedBlock)
                for (std::size_t r = 0; r < kStride; ++r)
                    for (std::size_t q = 0; q < kStridedBlock / kStride; ++q) take(block + q * kStride + r);
            for (; block < c.quads.size(); ++block) take(block);
            c.quads = std::move(order);
        }
    }
    for (std::size_t f = 0; f < static_cast<std::size_t>(kSpringFamilyCount); ++f) {
        s.stiffness[f] = static_cast<float>(s.params.stiffness[f]);
        s.damping[f] = static_cast<float>(s.params.damping[f]);
        for (Chunk& c : s.chunks) c.familyStart[f] = c.springs.size();
        const SpringSet& set = topo.springs[f];
        for (std::size_t k = 0; k < set.size(); ++k) {
            if (inQuad[f][k]) continue;
            Chunk* c = chunkOf({set.a[k], set.b[k]});
            c->springs.a.push_back(set.a[k]);
            c->springs.b.push_back(set.b[k]);
            c->springs.rest.push_back(static_cast<float>(set.rest[k]));
        }
    }
    for (Chunk& c : s.chunks) {
        c.familyStart[kSpringFamilyCount] = c.springs.size();
        // Within each family, blocks of 128 springs taken with a stride of 16 (k, k + 16, ...,
        // then k + 1, ...): the mesh's springs come edge after edge, so neighbours in the list
        // share a particle, and adding their forces one after the other would wait on the
        // previous store to the same row; 16 apart they rarely do (nearby still: the block is
        // small).
        SpringArrays order;
        for (std::size_t f = 0; f < static_cast<std::size_t>(kSpringFamilyCount); ++f) {
            const std::size_t begin = c.familyStart[f], end = c.familyStart[f + 1];
            auto take = [&](std::size_t k) {
                order.a.push_back(c.springs.a[k]);
                order.b.push_back(c.springs.b[k]);
                order.rest.push_back(c.springs.rest[k]);
            };
            std::size_t block = begin;
            for (; block + kStridedBlock <= end; block += kStridedBlock)
                for (std::size_t r = 0; r < kStride; ++r)
                    for (std::size_t q = 0; q < kStridedBlock / kStride; ++q) take(block + q * kStride + r);
            for (; block < end; ++block) take(block);
        }
        c.springs = std::move(order);
    }
    // Faces: each chunk's inner layer's first (slot 0), then the outer's.
    if (s.gas) {
        for (std::size_t slot = 0; slot < 2; ++slot) {
            for (Chunk& c : s.chunks)
                if (slot == 1) c.slotStart = c.faces.size();
            for (const Surface& surface : topo.surfaces) {
                if (static_cast<std::size_t>(layerSlot(surface.layer)) != slot) continue;
                if (s.dimension == 2) {
                    for (auto [a, b] : surface.edges) chunkOf({a, b})->faces.push_back({a, b, a});
                } else {
                    for (const auto& t : surface.triangles) chunkOf({t[0], t[1], t[2]})->faces.push_back(t);
                }
            }
        }
        // 3D: faces sharing an edge go in pairs (pairFaces).
        if (s.dimension == 3)
            for (Chunk& c : s.chunks) pairFaces(c);
        for (Chunk& c : s.chunks) {
            // The faces of each slot in strided blocks, as the springs below (consecutive faces
            // share corners).
            std::vector<std::array<int, 3>> order;
            const std::array<std::size_t, 3> cut{0, c.slotStart, c.faces.size()};
            for (std::size_t slot = 0; slot < 2; ++slot) {
                std::size_t block = cut[slot];
                for (; block + kStridedBlock <= cut[slot + 1]; block += kStridedBlock)
                    for (std::size_t r = 0; r < kStride; ++r)
                        for (std::size_t q = 0; q < kStridedBlock / kStride; ++q) order.push_back(c.faces[block + q * kStride + r]);
                for (; block < cut[slot + 1]; ++block) order.push_back(c.faces[block]);
            }
            c.faces = std::move(order);
            c.faceCorners.resize(3 * c.faces.size());
            for (std::size_t f = 0; f < c.faces.size(); ++f)
                for (std::size_t k = 0; k < 3; ++k) c.faceCorners[k * c.faces.size() + f] = c.faces[f][k];
        }
    }
    s.particleSlot.resize(n);
    for (std::size_t i = 0; i < n; ++i) s.particleSlot[i] = static_cast<std::uint8_t>(layerSlot(topo.layer[i]));
    // State, rounded to float.
    const Eigen::VectorXd& y = start.state();
    for (auto* buffer : {&s.x, &s.v, &s.xt, &s.vt, &s.xa, &s.va}) buffer->assign(4 * n, 0.0f);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t axis = 0; axis < 3; ++axis) {
            s.x[4 * i + axis] = static_cast<float>(y[static_cast<Eigen::Index>(3 * i + axis)]);
            s.v[4 * i + axis] = static_cast<float>(y[static_cast<Eigen::Index>(3 * (n + i) + axis)]);
        }
    s.force4.assign(4 * n, 0.0f);
    s.gradient4.assign(4 * n, 0.0f);
#ifdef SIMCORE_FLOAT_AVX2
    // The kernel set in use (kernels::useKernels never picks one the CPU lacks: AVX-512 means
    // avx512f, which has AVX2 with it).
    s.simd = haveAvx2() ? kernels::kernelsInUse() : kernels::KernelSet::Portable;
#endif
    s.measure(s.diag);
    s.diag.hasGas = s.gas;
    s.diag.dt = m_dt;
    s.diag.time = m_time;
    s.diag.step = m_step;
    for (const Surface& surface : topo.surfaces)
        s.diag.restVolume[static_cast<std::size_t>(layerSlot(surface.layer))] = surface.restVolume;
    s.initialEnergy = s.diag.total();
    s.diag.initialEnergy = s.initialEnergy;
    s.measured = true;
    setThreads(start.threads());
}

FloatSimulation::~FloatSimulation() = default;

void FloatSimulation::setThreads(int threads) {
    threads = std::max(1, threads);
    m_impl->pool = threads > 1 ? std::make_unique<ThreadPool>(threads) : nullptr;
    m_impl->threads = threads;
}

int FloatSimulation::threads() const { return m_impl->threads; }

bool FloatSimulation::step() {
    if (failed()) return false;
    m_impl->step(m_integrator, static_cast<float>(m_dt), m_dt);
    ++m_step;
    const double started = m_time;
    m_time = advanceTime(started, m_dt, m_timeCarry);
    m_impl->measured = false;
    if (std::string reason = m_impl->check(); !reason.empty()) {
        m_failure = Failure{reason, m_step, started};
        return false;
    }
    return true;
}

const Diagnostics& FloatSimulation::diagnostics() const {
    Impl& s = *m_impl;
    if (!s.measured) {
        s.measure(s.diag);
        s.measured = true;
    }
    s.diag.step = m_step;
    s.diag.time = m_time;
    s.diag.removedDamping = s.removed;
    s.diag.forceEvaluations = s.evaluations;
    return s.diag;
}

Eigen::VectorXd FloatSimulation::state() const {
    Eigen::VectorXd y;
    m_impl->toDouble(y);
    return y;
}

void FloatSimulation::writeStateTo(Simulation& sim) const {
    const Eigen::VectorXd y = state();
    const auto n = static_cast<Eigen::Index>(m_topology->particleCount());
    sim.setState(Eigen::Map<const Eigen::Matrix3Xd>(y.data(), 3, n), Eigen::Map<const Eigen::Matrix3Xd>(y.data() + 3 * n, 3, n),
                 m_step, m_time);
}

std::uint64_t FloatSimulation::stateHash() const {
    std::uint64_t h = 14695981039346656037ULL;
    for (const std::vector<float>* buffer : {&m_impl->x, &m_impl->v}) {
        const auto* p = reinterpret_cast<const unsigned char*>(buffer->data());
        for (std::size_t i = 0; i < buffer->size() * sizeof(float); ++i) h = (h ^ p[i]) * 1099511628211ULL;
    }
    return h;
}

}  // namespace simcore
