#include "simcore/force_kernels.h"
#include "simcore/scan_kernels.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>

// The kernels are written once (force_kernels_body.h, and the scans beside them:
// scan_kernels_body.h) over simd.h's width-generic vectors and compiled here once per
// instruction set, each copy in a namespace of its own and under
// `#pragma GCC target`, so that one binary runs on any x86-64 and picks the widest set the CPU
// has at load time:
//   portable  the baseline target (SSE2 on x86-64; whatever the target is elsewhere, e.g. NEON
//             on AArch64), no intrinsics: GCC lowers the vector operations;
//   avx2      four lanes with AVX2 shuffles (x86-64);
//   avx512    the edge quads and radius runs eight lanes wide, the rest the AVX2 copy's
//             (eight-wide triangles and indexed springs measured slower).
// The AVX2 and AVX-512 copies need GCC on x86-64 (no resolvers: the sanitizer builds run them
// too); ELASTIC_LAB_PORTABLE_KERNELS (a CMake option) builds the portable copy alone. Clang 14
// has no `#pragma GCC target`, so a clang build (the fuzz preset) runs the portable kernels;
// results are bit-identical across sets.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(ELASTIC_LAB_PORTABLE_KERNELS)
#define SIMCORE_AVX2_KERNELS 1
#define SIMCORE_AVX512_KERNELS 1
// GCC 12 warns inside its own AVX-512 intrinsics (_mm512_undefined_pd, GCC bug 105593); the
// warning is reported at the header's lines, so it is silenced for the header alone.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#else
#define SIMCORE_AVX2_KERNELS 0
#define SIMCORE_AVX512_KERNELS 0
#endif

namespace simcore::kernels {

namespace {

// A block's quad sums from their accumulators [parity][lane] (see QuadSums).
QuadSums combineQuadLanes(const double (&power)[2][4], const double (&square)[2][4]) {
    double p[4], q[4];
    for (int l = 0; l < 4; ++l) {
        p[l] = power[0][l] + power[1][l];
        q[l] = square[0][l] + square[1][l];
    }
    return {(p[0] + p[1]) + (p[2] + p[3]), {q[0] + q[1], q[2] + q[3]}};
}

}  // namespace

}  // namespace simcore::kernels

#define SIMCORE_SIMD_ISA 0
#define SIMCORE_SIMD_NS portable
#include "simcore/internal/simd.h"
#include "simcore/internal/force_kernels_body.h"
#include "simcore/internal/scan_kernels_body.h"
#undef SIMCORE_SIMD_ISA
#undef SIMCORE_SIMD_NS

#if SIMCORE_AVX2_KERNELS
#pragma GCC push_options
#pragma GCC target("avx2")
#define SIMCORE_SIMD_ISA 2
#define SIMCORE_SIMD_NS avx2
#include "simcore/internal/simd.h"
#include "simcore/internal/force_kernels_body.h"
#include "simcore/internal/scan_kernels_body.h"
#undef SIMCORE_SIMD_ISA
#undef SIMCORE_SIMD_NS
#pragma GCC pop_options
#endif

#if SIMCORE_AVX512_KERNELS
#pragma GCC push_options
#pragma GCC target("avx512f,avx2")
#define SIMCORE_SIMD_ISA 3
#define SIMCORE_SIMD_NS avx512
#include "simcore/internal/simd.h"
#include "simcore/internal/force_kernels_body.h"
#include "simcore/internal/scan_kernels_body.h"
#undef SIMCORE_SIMD_ISA
#undef SIMCORE_SIMD_NS
#pragma GCC pop_options
#endif

namespace simcore::kernels {

namespace {

KernelSet detectWidest() {
#if SIMCORE_AVX512_KERNELS
    // libgcc's check includes the OS saving the registers (XCR0).
    if (__builtin_cpu_supports("avx512f")) return KernelSet::Avx512;
#endif
#if SIMCORE_AVX2_KERNELS
    if (__builtin_cpu_supports("avx2")) return KernelSet::Avx2;
#endif
    return KernelSet::Portable;
}

std::atomic<KernelSet> g_kernels{detectWidest()};

}  // namespace

double sumLanes(const double* v, std::size_t n) {
    // The AVX2 kernels keep the same four lanes in one register.
    double lane[4] = {0.0, 0.0, 0.0, 0.0};
    std::size_t k = 0;
    for (; k + 4 <= n; k += 4)
        for (int l = 0; l < 4; ++l) lane[l] += v[k + static_cast<std::size_t>(l)];
    for (; k < n; ++k) lane[0] += v[k];
    return (lane[0] + lane[1]) + (lane[2] + lane[3]);
}

const char* kernelSetName(KernelSet set) {
    switch (set) {
        case KernelSet::Portable: return "portable";
        case KernelSet::Avx2: return "avx2";
        case KernelSet::Avx512: return "avx512";
    }
    return "?";
}

KernelSet widestKernels() {
    static const KernelSet widest = detectWidest();
    return widest;
}

KernelSet useKernels(KernelSet wanted) {
    g_kernels.store(std::min(wanted, widestKernels()), std::memory_order_relaxed);
    return kernelsInUse();
}

KernelSet kernelsInUse() { return g_kernels.load(std::memory_order_relaxed); }

SpringSums springBlock(const SpringSet& springs, std::size_t begin, std::size_t end, double stiffness,
                       double damping, const double* x, const double* v, double* f4, int& degenerate) {
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() >= KernelSet::Avx2) return avx2::springBlock(springs, begin, end, stiffness, damping, x, v, f4, degenerate);
#endif
    return portable::springBlock(springs, begin, end, stiffness, damping, x, v, f4, degenerate);
}

SpringSums springRunBlock(const SpringSet& springs, std::size_t begin, std::size_t end, int n, double stiffness,
                          double damping, const double* x, const double* v, double* f4, int& degenerate) {
#if SIMCORE_AVX512_KERNELS
    if (kernelsInUse() == KernelSet::Avx512)
        return avx512::springRunBlock(springs, begin, end, n, stiffness, damping, x, v, f4, degenerate);
#endif
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() == KernelSet::Avx2) return avx2::springRunBlock(springs, begin, end, n, stiffness, damping, x, v, f4, degenerate);
#endif
    return portable::springRunBlock(springs, begin, end, n, stiffness, damping, x, v, f4, degenerate);
}

QuadSums quadBlock(const QuadSet& quads, std::size_t begin, std::size_t end, int n,
                   std::array<double, 2> stiffness, std::array<double, 2> damping, const double* x,
                   const double* v, double* f4, int& degenerate) {
#if SIMCORE_AVX512_KERNELS
    if (kernelsInUse() == KernelSet::Avx512) return avx512::quadBlock(quads, begin, end, n, stiffness, damping, x, v, f4, degenerate);
#endif
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() == KernelSet::Avx2) return avx2::quadBlock(quads, begin, end, n, stiffness, damping, x, v, f4, degenerate);
#endif
    return portable::quadBlock(quads, begin, end, n, stiffness, damping, x, v, f4, degenerate);
}

double triangleBlock(const Surface& surface, std::size_t begin, std::size_t end, const double* x, double* g4) {
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() >= KernelSet::Avx2) return avx2::triangleBlock(surface, begin, end, x, g4);
#endif
    return portable::triangleBlock(surface, begin, end, x, g4);
}

double vertexGradients(const VertexFans& fans, int begin, int end, const double* x, double* g4) {
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() >= KernelSet::Avx2) return avx2::vertexGradients(fans, begin, end, x, g4);
#endif
    return portable::vertexGradients(fans, begin, end, x, g4);
}

StateScan scanState(const double* x, const double* v, const double* invMass3, const double* mass, bool weighs,
                    double g, int begin, int end) {
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() >= KernelSet::Avx2) return avx2::scanState(x, v, invMass3, mass, weighs, g, begin, end);
#endif
    return portable::scanState(x, v, invMass3, mass, weighs, g, begin, end);
}

PairScanBits scanPairs(const std::array<double, 3>& low, const std::array<double, 3>& high, const double* x,
                       const double* g4, int begin, int end, int offset) {
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() >= KernelSet::Avx2) return avx2::scanPairs(low, high, x, g4, begin, end, offset);
#endif
    return portable::scanPairs(low, high, x, g4, begin, end, offset);
}

VertexFans vertexFans(const Topology& topology) {
    VertexFans fans;
    if (topology.dimension != 3 || topology.surfaces.empty()) return fans;
    const auto n = static_cast<std::size_t>(topology.particleCount());
    std::vector<std::vector<std::array<int, 2>>> around(n);
    for (const Surface& s : topology.surfaces)
        for (auto [a, b, c] : s.triangles) {
            around[static_cast<std::size_t>(a)].push_back({b, c});
            around[static_cast<std::size_t>(b)].push_back({c, a});
            around[static_cast<std::size_t>(c)].push_back({a, b});
        }
    fans.start.assign(n + 1, 0);
    fans.ring6.assign(n, 0);
    for (std::size_t v = 0; v < n; ++v) {
        std::vector<std::array<int, 2>>& fan = around[v];
        // A walk around v from its first triangle: the pair whose p is the last q, while one
        // is found (a closed fan comes back to the start; an open one keeps its order).
        for (std::size_t k = 1; k < fan.size(); ++k) {
            const auto next = std::find_if(fan.begin() + static_cast<std::ptrdiff_t>(k), fan.end(),
                                           [&](const std::array<int, 2>& pq) { return pq[0] == fan[k - 1][1]; });
            if (next == fan.end()) break;
            std::iter_swap(fan.begin() + static_cast<std::ptrdiff_t>(k), next);
        }
        bool closed = fan.size() == 6;
        for (std::size_t k = 0; closed && k < fan.size(); ++k) closed = fan[k][1] == fan[(k + 1) % fan.size()][0];
        fans.ring6[v] = closed ? 1 : 0;
        fans.pair.insert(fans.pair.end(), fan.begin(), fan.end());
        fans.start[v + 1] = static_cast<int>(fans.pair.size());
    }
    return fans;
}

void unpad(const double* f4, const double* g4, double p, const double* invMass3, int begin, int end,
           double* out) {
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() >= KernelSet::Avx2) return avx2::unpad(f4, g4, p, invMass3, begin, end, out);
#endif
    portable::unpad(f4, g4, p, invMass3, begin, end, out);
}

void stageSum(double* out, const double* y, double c, const double* k, std::size_t n) {
#if SIMCORE_AVX512_KERNELS
    if (kernelsInUse() == KernelSet::Avx512) return avx512::stageSum(out, y, c, k, n);
#endif
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() == KernelSet::Avx2) return avx2::stageSum(out, y, c, k, n);
#endif
    portable::stageSum(out, y, c, k, n);
}

void rk4Sum(double* y, double h6, const double* k1, const double* k2, const double* k3, const double* k4,
            std::size_t n) {
#if SIMCORE_AVX512_KERNELS
    if (kernelsInUse() == KernelSet::Avx512) return avx512::rk4Sum(y, h6, k1, k2, k3, k4, n);
#endif
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() == KernelSet::Avx2) return avx2::rk4Sum(y, h6, k1, k2, k3, k4, n);
#endif
    portable::rk4Sum(y, h6, k1, k2, k3, k4, n);
}

AlignedBuffer::AlignedBuffer(std::size_t count) : m_size(count) {
    const std::size_t bytes = (count * sizeof(double) + 63) / 64 * 64;
    void* p = std::aligned_alloc(64, std::max<std::size_t>(bytes, 64));
    if (!p) throw std::bad_alloc();
    m_data.reset(static_cast<double*>(p));
    std::fill(data(), data() + count, 0.0);
}

AlignedBuffer::AlignedBuffer(const AlignedBuffer& other) : AlignedBuffer(other.m_size) {
    std::copy(other.data(), other.data() + m_size, data());
}

AlignedBuffer& AlignedBuffer::operator=(const AlignedBuffer& other) {
    if (this != &other) *this = AlignedBuffer(other);
    return *this;
}

void AlignedBuffer::Free::operator()(double* p) const { std::free(p); }

}  // namespace simcore::kernels
