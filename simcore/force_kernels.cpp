#include "force_kernels.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <new>

#include "forces.h"  // kDegenerateLength

// The AVX2 and AVX-512 kernels build with GCC. Clang 14 refuses their width-generic helpers
// (vector arguments into an always-inlined template without a target attribute), so a clang
// build (the fuzz preset) runs the portable kernels; results are bit-identical across sets.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
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

// The portable arithmetic is compiled twice (AVX2 and baseline x86-64) and picked at load
// time. Without -ffast-math and with FP contraction off (ISO C++ mode) both round alike.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(ELASTIC_LAB_MULTIVERSION)
#define SIMCORE_VECTOR_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define SIMCORE_VECTOR_KERNEL
#endif

namespace simcore::kernels {

namespace {

// ---------------------------------------------------------------------------------------------
// Portable kernels

// A block's quad sums from their accumulators [parity][lane] (see QuadSums).
QuadSums combineQuadLanes(const double (&power)[2][4], const double (&square)[2][4]) {
    double p[4], q[4];
    for (int l = 0; l < 4; ++l) {
        p[l] = power[0][l] + power[1][l];
        q[l] = square[0][l] + square[1][l];
    }
    return {(p[0] + p[1]) + (p[2] + p[3]), {q[0] + q[1], q[2] + q[3]}};
}

// One spring's arithmetic: separation d and relative velocity dv in; force on the first
// particle, damping power and squared stretch out. A spring shorter than kDegenerateLength keeps
// a finite direction (divided by the epsilon instead of its length) and a zero force. The AVX2
// kernels (springLanes) do these operations in this order.
struct SpringResult {
    double fx, fy, fz, power, stretch2;
};
inline SpringResult springArithmetic(double dx, double dy, double dz, double dvx, double dvy, double dvz,
                                     double ks, double kd, double rest) {
    const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
    const bool tooShort = length < kDegenerateLength;
    const double inv = 1.0 / std::max(length, kDegenerateLength);
    const double live = tooShort ? 0.0 : 1.0;
    const double ux = dx * inv, uy = dy * inv, uz = dz * inv;
    const double closing = dvx * ux + dvy * uy + dvz * uz;
    const double magnitude = live * (ks * (length - rest) + kd * closing);
    return {magnitude * ux, magnitude * uy, magnitude * uz, live * kd * closing * closing,
            (length - rest) * (length - rest)};
}

SIMCORE_VECTOR_KERNEL
void springMath(std::size_t count, double ks, double kd, const double* __restrict rest,
                double* __restrict dx, double* __restrict dy, double* __restrict dz,
                const double* __restrict dvx, const double* __restrict dvy,
                const double* __restrict dvz, double* __restrict power, double* __restrict stretch2) {
    // Structure-of-arrays in and out (the forces overwrite d): a loop the compiler vectorises.
    for (std::size_t s = 0; s < count; ++s) {
        const SpringResult r = springArithmetic(dx[s], dy[s], dz[s], dvx[s], dvy[s], dvz[s], ks, kd, rest[s]);
        dx[s] = r.fx;
        dy[s] = r.fy;
        dz[s] = r.fz;
        power[s] = r.power;
        stretch2[s] = r.stretch2;
    }
}

SpringSums springBlockPortable(const SpringSet& springs, std::size_t begin, std::size_t end,
                               double ks, double kd, const double* x, const double* v, double* f4,
                               int& degenerate, Scratch& scratch) {
    const int* ia = springs.a.data() + begin;
    const int* ib = springs.b.data() + begin;
    const std::size_t count = end - begin;
    double *dx = scratch.dx, *dy = scratch.dy, *dz = scratch.dz;
    double *dvx = scratch.dvx, *dvy = scratch.dvy, *dvz = scratch.dvz;
    for (std::size_t k = 0; k < count; ++k) {
        const int i = 3 * ia[k], j = 3 * ib[k];
        dx[k] = x[j] - x[i];
        dy[k] = x[j + 1] - x[i + 1];
        dz[k] = x[j + 2] - x[i + 2];
        degenerate += dx[k] * dx[k] + dy[k] * dy[k] + dz[k] * dz[k] < kDegenerateLength * kDegenerateLength;
        dvx[k] = v[j] - v[i];
        dvy[k] = v[j + 1] - v[i + 1];
        dvz[k] = v[j + 2] - v[i + 2];
    }
    springMath(count, ks, kd, springs.rest.data() + begin, dx, dy, dz, dvx, dvy, dvz, scratch.power,
               scratch.stretch2);
    for (std::size_t k = 0; k < count; ++k) {
        double* fa = f4 + 4 * ia[k];
        double* fb = f4 + 4 * ib[k];
        fa[0] += dx[k];
        fa[1] += dy[k];
        fa[2] += dz[k];
        fb[0] -= dx[k];
        fb[1] -= dy[k];
        fb[2] -= dz[k];
    }
    return {sumLanes(scratch.power, count), sumLanes(scratch.stretch2, count)};
}

SIMCORE_VECTOR_KERNEL
void triangleMath(const std::array<int, 3>* tri, std::size_t count, const double* x,
                  double* __restrict gx, double* __restrict gy, double* __restrict gz,
                  double* __restrict volume6) {
    for (std::size_t k = 0; k < count; ++k) {
        const int a = 3 * tri[k][0], b = 3 * tri[k][1], c = 3 * tri[k][2];
        volume6[k] = x[a] * (x[b + 1] * x[c + 2] - x[b + 2] * x[c + 1]) +
                     x[a + 1] * (x[b + 2] * x[c] - x[b] * x[c + 2]) +
                     x[a + 2] * (x[b] * x[c + 1] - x[b + 1] * x[c]);
        const double ux = x[b] - x[a], uy = x[b + 1] - x[a + 1], uz = x[b + 2] - x[a + 2];
        const double wx = x[c] - x[a], wy = x[c + 1] - x[a + 1], wz = x[c + 2] - x[a + 2];
        gx[k] = (uy * wz - uz * wy) / 6.0;
        gy[k] = (uz * wx - ux * wz) / 6.0;
        gz[k] = (ux * wy - uy * wx) / 6.0;
    }
}

double triangleBlockPortable(const Surface& surface, std::size_t begin, std::size_t end,
                             const double* x, double* g4, Scratch& scratch) {
    const std::array<int, 3>* tri = surface.triangles.data() + begin;
    const std::size_t count = end - begin;
    triangleMath(tri, count, x, scratch.dx, scratch.dy, scratch.dz, scratch.power);
    for (std::size_t k = 0; k < count; ++k)
        for (int corner : tri[k]) {
            double* g = g4 + 4 * corner;
            g[0] += scratch.dx[k];
            g[1] += scratch.dy[k];
            g[2] += scratch.dz[k];
        }
    return sumLanes(scratch.power, count);
}

void unpadPortable(const double* f4, const double* g4, double p, const double* invMass3, int begin,
                   int end, double* out) {
    for (int i = begin; i < end; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            const int k = 3 * i + axis;
            const double f = g4 ? f4[4 * i + axis] + p * g4[4 * i + axis] : f4[4 * i + axis];
            out[k] = invMass3 ? f * invMass3[k] : f;
        }
}

QuadSums quadBlockPortable(const QuadSet& quads, std::size_t begin, std::size_t end, int n,
                           std::array<double, 2> ks, std::array<double, 2> kd, const double* x,
                           const double* v, double* f4, int& degenerate) {
    double powerLane[2][4] = {}, squareLane[2][4] = {};
    for (std::size_t q = begin; q < end; ++q) {
        const std::size_t parity = (q - begin) & 1;
        const int a = quads.a[q], b = quads.b[q], A = a + n, B = b + n;
        const int first[4] = {a, A, A, B}, second[4] = {b, B, b, a};
        double F[4][3];
        for (int l = 0; l < 4; ++l) {
            const double* xi = x + 3 * first[l];
            const double* xj = x + 3 * second[l];
            const double* vi = v + 3 * first[l];
            const double* vj = v + 3 * second[l];
            const double dx = xj[0] - xi[0], dy = xj[1] - xi[1], dz = xj[2] - xi[2];
            degenerate += dx * dx + dy * dy + dz * dz < kDegenerateLength * kDegenerateLength;
            const SpringResult r = springArithmetic(dx, dy, dz, vj[0] - vi[0], vj[1] - vi[1], vj[2] - vi[2],
                                                    ks[l / 2], kd[l / 2], quads.rest[q][static_cast<std::size_t>(l)]);
            F[l][0] = r.fx;
            F[l][1] = r.fy;
            F[l][2] = r.fz;
            powerLane[parity][l] += r.power;
            squareLane[parity][l] += r.stretch2;
        }
        for (int axis = 0; axis < 3; ++axis) {
            f4[4 * a + axis] += F[0][axis] - F[3][axis];
            f4[4 * b + axis] -= F[0][axis] + F[2][axis];
            f4[4 * A + axis] += F[1][axis] + F[2][axis];
            f4[4 * B + axis] += F[3][axis] - F[1][axis];
        }
    }
    return combineQuadLanes(powerLane, squareLane);
}

// ---------------------------------------------------------------------------------------------
// AVX2 kernels

#if SIMCORE_AVX2_KERNELS

#define SIMCORE_AVX2 __attribute__((target("avx2")))

// A particle index as an unsigned offset (indices are never negative): addresses from it need
// no sign extension.
inline std::size_t index(int p) { return static_cast<std::uint32_t>(p); }

// (x, y, z, 0) of particle p from a 3-per-particle array; the fourth double is never read.
SIMCORE_AVX2 inline __m256d loadRow(const double* a, std::size_t p) {
    return _mm256_maskload_pd(a + 3 * p, _mm256_setr_epi64x(-1, -1, -1, 0));
}

// Four rows (x, y, z, w) to three columns X, Y, Z.
SIMCORE_AVX2 inline void toColumns(__m256d r0, __m256d r1, __m256d r2, __m256d r3, __m256d& X,
                                   __m256d& Y, __m256d& Z) {
    const __m256d t0 = _mm256_unpacklo_pd(r0, r1);  // x0 x1 z0 z1
    const __m256d t1 = _mm256_unpackhi_pd(r0, r1);  // y0 y1 w0 w1
    const __m256d t2 = _mm256_unpacklo_pd(r2, r3);  // x2 x3 z2 z3
    const __m256d t3 = _mm256_unpackhi_pd(r2, r3);  // y2 y3 w2 w3
    X = _mm256_permute2f128_pd(t0, t2, 0x20);
    Y = _mm256_permute2f128_pd(t1, t3, 0x20);
    Z = _mm256_permute2f128_pd(t0, t2, 0x31);
}

// Three columns to four rows (x, y, z, 0).
SIMCORE_AVX2 inline void toRows(__m256d X, __m256d Y, __m256d Z, __m256d (&r)[4]) {
    const __m256d zero = _mm256_setzero_pd();
    const __m256d t0 = _mm256_unpacklo_pd(X, Y);     // x0 y0 x2 y2
    const __m256d t1 = _mm256_unpackhi_pd(X, Y);     // x1 y1 x3 y3
    const __m256d t2 = _mm256_unpacklo_pd(Z, zero);  // z0 0 z2 0
    const __m256d t3 = _mm256_unpackhi_pd(Z, zero);  // z1 0 z3 0
    r[0] = _mm256_permute2f128_pd(t0, t2, 0x20);
    r[1] = _mm256_permute2f128_pd(t1, t3, 0x20);
    r[2] = _mm256_permute2f128_pd(t0, t2, 0x31);
    r[3] = _mm256_permute2f128_pd(t1, t3, 0x31);
}

SIMCORE_AVX2 inline void addRow(double* f4, std::size_t p, __m256d row) {
    double* at = f4 + 4 * p;
    _mm256_store_pd(at, _mm256_add_pd(_mm256_load_pd(at), row));
}
SIMCORE_AVX2 inline void subRow(double* f4, std::size_t p, __m256d row) {
    double* at = f4 + 4 * p;
    _mm256_store_pd(at, _mm256_sub_pd(_mm256_load_pd(at), row));
}

SIMCORE_AVX2 inline __m256d vectorSqrt(__m256d v) { return _mm256_sqrt_pd(v); }
#if SIMCORE_AVX512_KERNELS
#define SIMCORE_AVX512 __attribute__((target("avx512f,avx2")))
SIMCORE_AVX512 inline __m512d vectorSqrt(__m512d v) { return _mm512_sqrt_pd(v); }
#endif

// The spring arithmetic of four or eight lanes (springArithmetic's, operation by operation):
// forces on the first particles (fx, fy, fz), damping power and stretch L - L0 per lane;
// counts degenerate lanes into `shortCount` (a 64-bit count per lane: no scalar chain through
// the loop). Written once with GCC's vector operators for __m256d and __m512d; inlined into
// the AVX2 and AVX-512 kernels, it compiles to their instructions (and, with
// -ffp-contract=off, never to a fused multiply-add).
// (Plain vector types: __m256d's may_alias attribute would be dropped as a template argument.)
using Vec4 = double __attribute__((vector_size(32)));
using Vec8 = double __attribute__((vector_size(64)));
template <class V>
struct SpringLanes {
    V fx, fy, fz, power, stretch;
};
// Always inlined into a kernel with the instructions enabled, so the vector arguments never
// cross a call: GCC's note on their calling convention does not apply.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
template <class V, class Count>
[[gnu::always_inline]] inline SpringLanes<V> springLanes(V dx, V dy, V dz, V dvx, V dvy, V dvz, V rest, V ks,
                                                         V kd, Count& shortCount) {
    const V zero{}, one = zero + 1.0, eps = zero + kDegenerateLength;
    const V length2 = (dx * dx + dy * dy) + dz * dz;
    shortCount -= length2 < eps * eps;  // a true comparison is -1 in each lane
    const V length = vectorSqrt(length2);
    const auto tooShort = length < eps;
    const V inv = one / (tooShort ? eps : length);
    const V live = tooShort ? zero : one;
    const V ux = dx * inv, uy = dy * inv, uz = dz * inv;
    const V closing = (dvx * ux + dvy * uy) + dvz * uz;
    const V stretch = length - rest;
    const V magnitude = live * (ks * stretch + kd * closing);
    return {magnitude * ux, magnitude * uy, magnitude * uz, ((live * kd) * closing) * closing, stretch};
}
#pragma GCC diagnostic pop

// Per-lane counts (the type a comparison of V gives) and their total.
template <class V>
using LaneCount = decltype(V{} < V{});
template <class Count>
[[gnu::always_inline]] inline int laneTotal(Count count) {
    long long total = 0;
    for (std::size_t l = 0; l < sizeof(Count) / sizeof(long long); ++l) total += count[l];
    return static_cast<int>(total);
}

// A block's spring sums in four lanes (spring k of the block in lane k mod 4) while they
// are accumulated.
struct SpringAccumulators {
    Vec4 power{};   // damping power
    Vec4 square{};  // (L - L0)^2
    LaneCount<Vec4> shortSprings{};
};

// Springs [k, end) in groups of four from k into the accumulators; returns where it stopped
// (fewer than four left).
SIMCORE_AVX2 inline std::size_t springGroupsAvx2(const SpringSet& springs, std::size_t k, std::size_t end,
                                                 __m256d ks, __m256d kd, const double* x, const double* v,
                                                 double* f4, SpringAccumulators& sums) {
    const int* ia = springs.a.data();
    const int* ib = springs.b.data();
    for (; k + 4 <= end; k += 4) {
        __m256d d[4], dv[4];
        for (std::size_t l = 0; l < 4; ++l) {
            const int i = ia[k + l], j = ib[k + l];
            d[l] = _mm256_sub_pd(loadRow(x, j), loadRow(x, i));
            dv[l] = _mm256_sub_pd(loadRow(v, j), loadRow(v, i));
        }
        __m256d dx, dy, dz, dvx, dvy, dvz;
        toColumns(d[0], d[1], d[2], d[3], dx, dy, dz);
        toColumns(dv[0], dv[1], dv[2], dv[3], dvx, dvy, dvz);
        const SpringLanes<Vec4> lane =
            springLanes(dx, dy, dz, dvx, dvy, dvz, _mm256_loadu_pd(springs.rest.data() + k), ks, kd, sums.shortSprings);
        sums.power = _mm256_add_pd(sums.power, lane.power);
        sums.square = _mm256_add_pd(sums.square, _mm256_mul_pd(lane.stretch, lane.stretch));
        __m256d force[4];
        toRows(lane.fx, lane.fy, lane.fz, force);
        for (std::size_t l = 0; l < 4; ++l) {
            addRow(f4, ia[k + l], force[l]);
            subRow(f4, ib[k + l], force[l]);
        }
    }
    return k;
}

// The last one to three springs [k, end) by the portable path (like sumLanes, their sums go
// into lane 0 one by one), and the block's sums.
SIMCORE_AVX2 inline SpringSums finishSprings(const SpringSet& springs, std::size_t k, std::size_t end, double ks,
                                             double kd, const double* x, const double* v, double* f4,
                                             int& degenerate, Scratch& scratch, const SpringAccumulators& sums) {
    degenerate += laneTotal(sums.shortSprings);
    alignas(32) double lane[4], square[4];
    _mm256_store_pd(lane, sums.power);
    _mm256_store_pd(square, sums.square);
    if (k < end) {
        springBlockPortable(springs, k, end, ks, kd, x, v, f4, degenerate, scratch);
        for (std::size_t t = 0; t < end - k; ++t) {
            lane[0] += scratch.power[t];
            square[0] += scratch.stretch2[t];
        }
    }
    return {(lane[0] + lane[1]) + (lane[2] + lane[3]), (square[0] + square[1]) + (square[2] + square[3])};
}

SIMCORE_AVX2
SpringSums springBlockAvx2(const SpringSet& springs, std::size_t begin, std::size_t end, double ks,
                           double kd, const double* x, const double* v, double* f4,
                           int& degenerate, Scratch& scratch) {
    SpringAccumulators sums;
    const std::size_t k = springGroupsAvx2(springs, begin, end, _mm256_set1_pd(ks), _mm256_set1_pd(kd), x, v, f4, sums);
    return finishSprings(springs, k, end, ks, kd, x, v, f4, degenerate, scratch, sums);
}

// Four consecutive rows (x, y, z) of a 3-per-particle array (12 doubles, three registers) to
// columns X = (x0 x1 x2 x3) and so on: blends, then one permute each.
SIMCORE_AVX2 inline void rowsToColumns(const double* at, Vec4& X, Vec4& Y, Vec4& Z) {
    const __m256d r0 = _mm256_loadu_pd(at);      // x0 y0 z0 x1
    const __m256d r1 = _mm256_loadu_pd(at + 4);  // y1 z1 x2 y2
    const __m256d r2 = _mm256_loadu_pd(at + 8);  // z2 x3 y3 z3
    X = _mm256_permute4x64_pd(_mm256_blend_pd(_mm256_blend_pd(r0, r1, 0b0100), r2, 0b0010), 0x6c);  // x0 x3 x2 x1
    Y = _mm256_permute_pd(_mm256_blend_pd(_mm256_blend_pd(r0, r1, 0b1001), r2, 0b0100), 0b0101);     // y1 y0 y3 y2
    Z = _mm256_permute4x64_pd(_mm256_blend_pd(_mm256_blend_pd(r0, r1, 0b0010), r2, 0b1001), 0xc6);  // z2 z1 z0 z3
}

// The springs from particles p.. to q.. (a run's group of four or eight): their end rows read
// as whole rows and transposed, then springLanes. (Written once for both widths; always
// inlined into a kernel with the instructions enabled.)
#if SIMCORE_AVX512_KERNELS
SIMCORE_AVX512 inline void rowsToColumns(const double* at, Vec8& X, Vec8& Y, Vec8& Z);
#endif
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
template <class V, class Count>
[[gnu::always_inline]] inline SpringLanes<V> radiusLanes(const double* x, const double* v, std::size_t p,
                                                         std::size_t q, V rest, V ks, V kd, Count& shortCount) {
    V ax, ay, az, bx, by, bz, avx, avy, avz, bvx, bvy, bvz;
    rowsToColumns(x + 3 * p, ax, ay, az);
    rowsToColumns(x + 3 * q, bx, by, bz);
    rowsToColumns(v + 3 * p, avx, avy, avz);
    rowsToColumns(v + 3 * q, bvx, bvy, bvz);
    return springLanes<V>(bx - ax, by - ay, bz - az, bvx - avx, bvy - avy, bvz - avz, rest, ks, kd, shortCount);
}
#pragma GCC diagnostic pop

// Springs [k, end) of a run (spring k joins particle first + (k - begin) and that + n) in groups
// of four read as whole rows, into the accumulators; returns where it stopped.
SIMCORE_AVX2 inline std::size_t radiusGroupsAvx2(const SpringSet& springs, std::size_t begin, std::size_t k,
                                                 std::size_t end, std::size_t n, __m256d ks, __m256d kd,
                                                 const double* x, const double* v, double* f4,
                                                 SpringAccumulators& sums) {
    const std::size_t first = index(springs.a[begin]);
    for (; k + 4 <= end; k += 4) {
        const std::size_t p = first + (k - begin), q = p + n;
        const SpringLanes<Vec4> lane =
            radiusLanes<Vec4>(x, v, p, q, _mm256_loadu_pd(springs.rest.data() + k), ks, kd, sums.shortSprings);
        sums.power = _mm256_add_pd(sums.power, lane.power);
        sums.square = _mm256_add_pd(sums.square, _mm256_mul_pd(lane.stretch, lane.stretch));
        __m256d force[4];
        toRows(lane.fx, lane.fy, lane.fz, force);
        for (std::size_t l = 0; l < 4; ++l) {
            addRow(f4, p + l, force[l]);
            subRow(f4, q + l, force[l]);
        }
    }
    return k;
}

SIMCORE_AVX2
SpringSums radiusRunAvx2(const SpringSet& springs, std::size_t begin, std::size_t end, int n, double ks,
                         double kd, const double* x, const double* v, double* f4, int& degenerate,
                         Scratch& scratch) {
    SpringAccumulators sums;
    const std::size_t k = radiusGroupsAvx2(springs, begin, begin, end, index(n), _mm256_set1_pd(ks),
                                           _mm256_set1_pd(kd), x, v, f4, sums);
    return finishSprings(springs, k, end, ks, kd, x, v, f4, degenerate, scratch, sums);
}

// p q - r s
SIMCORE_AVX2 inline __m256d cross(__m256d p, __m256d q, __m256d r, __m256d s) {
    return _mm256_sub_pd(_mm256_mul_pd(p, q), _mm256_mul_pd(r, s));
}

// Triangles tri[0..3]: their gradients (rows, not yet added) and x_a.(x_b x x_c).
struct TriangleGroup {
    __m256d gradient[4];
    __m256d volume6;
};
SIMCORE_AVX2 inline TriangleGroup triangleGroupAvx2(const std::array<int, 3>* tri, const double* x) {
    const __m256d six = _mm256_set1_pd(6.0);
    __m256d ax, ay, az, bx, by, bz, cx, cy, cz;
    toColumns(loadRow(x, index(tri[0][0])), loadRow(x, index(tri[1][0])), loadRow(x, index(tri[2][0])),
              loadRow(x, index(tri[3][0])), ax, ay, az);
    toColumns(loadRow(x, index(tri[0][1])), loadRow(x, index(tri[1][1])), loadRow(x, index(tri[2][1])),
              loadRow(x, index(tri[3][1])), bx, by, bz);
    toColumns(loadRow(x, index(tri[0][2])), loadRow(x, index(tri[1][2])), loadRow(x, index(tri[2][2])),
              loadRow(x, index(tri[3][2])), cx, cy, cz);
    // The portable triangleMath, operation by operation.
    TriangleGroup r;
    r.volume6 = _mm256_add_pd(
        _mm256_add_pd(_mm256_mul_pd(ax, cross(by, cz, bz, cy)), _mm256_mul_pd(ay, cross(bz, cx, bx, cz))),
        _mm256_mul_pd(az, cross(bx, cy, by, cx)));
    const __m256d ux = _mm256_sub_pd(bx, ax), uy = _mm256_sub_pd(by, ay), uz = _mm256_sub_pd(bz, az);
    const __m256d wx = _mm256_sub_pd(cx, ax), wy = _mm256_sub_pd(cy, ay), wz = _mm256_sub_pd(cz, az);
    toRows(_mm256_div_pd(cross(uy, wz, uz, wy), six), _mm256_div_pd(cross(uz, wx, ux, wz), six),
           _mm256_div_pd(cross(ux, wy, uy, wx), six), r.gradient);
    return r;
}
// A group's gradients added to its corners' rows, triangle by triangle.
SIMCORE_AVX2 inline void addTriangleGroup(const std::array<int, 3>* tri, const TriangleGroup& group, double* g4) {
    for (int l = 0; l < 4; ++l)
        for (int corner : tri[l]) addRow(g4, index(corner), group.gradient[l]);
}

SIMCORE_AVX2
double triangleBlockAvx2(const Surface& surface, std::size_t begin, std::size_t end,
                         const double* x, double* g4, Scratch& scratch) {
    const std::array<int, 3>* tri = surface.triangles.data() + begin;
    const std::size_t count = end - begin;
    __m256d lanes = _mm256_setzero_pd();  // x_a.(x_b x x_c), triangle k in lane k mod 4
    std::size_t k = 0;
    // Two groups per iteration, both computed before either is added (independent chains
    // for the out-of-order core to overlap).
    for (; k + 8 <= count; k += 8) {
        const TriangleGroup first = triangleGroupAvx2(tri + k, x), second = triangleGroupAvx2(tri + k + 4, x);
        lanes = _mm256_add_pd(_mm256_add_pd(lanes, first.volume6), second.volume6);
        addTriangleGroup(tri + k, first, g4);
        addTriangleGroup(tri + k + 4, second, g4);
    }
    if (k + 4 <= count) {
        const TriangleGroup last = triangleGroupAvx2(tri + k, x);
        lanes = _mm256_add_pd(lanes, last.volume6);
        addTriangleGroup(tri + k, last, g4);
        k += 4;
    }
    alignas(32) double lane[4];
    _mm256_store_pd(lane, lanes);
    if (k < count) {
        // The last one to three triangles by the portable path, into lane 0 one by one.
        triangleBlockPortable(surface, begin + k, end, x, g4, scratch);
        for (std::size_t t = 0; t < count - k; ++t) lane[0] += scratch.power[t];
    }
    return (lane[0] + lane[1]) + (lane[2] + lane[3]);
}

SIMCORE_AVX2
void unpadAvx2(const double* f4, const double* g4, double p, const double* invMass3, int begin,
               int end, double* out) {
    // Four doubles are stored per particle; the fourth lands on the next particle's x, which
    // is written right after. The last particle of the range is left to the portable loop
    // (its fourth double belongs to another range, or lies beyond the array).
    const __m256d vp = _mm256_set1_pd(p);
    int i = begin;
    for (; i + 1 < end; ++i) {
        __m256d f = _mm256_load_pd(f4 + 4 * i);
        if (g4) f = _mm256_add_pd(f, _mm256_mul_pd(vp, _mm256_load_pd(g4 + 4 * i)));
        if (invMass3) f = _mm256_mul_pd(f, loadRow(invMass3, i));
        _mm256_storeu_pd(out + 3 * i, f);
    }
    unpadPortable(f4, g4, p, invMass3, i, end, out);
}

// One quad: lanes (a, b), (A, B), (A, b), (B, a), the arithmetic of springArithmetic: its
// force rows (not yet added) and sums.
struct QuadLanes {
    std::size_t a, b;
    __m256d fa, fb, fA, fB;  // added to a, subtracted from b, added to A and B
    __m256d power, square;
};
SIMCORE_AVX2 inline QuadLanes quadLanesAvx2(std::size_t a, std::size_t b, std::size_t n, const double* rest,
                                            __m256d ks, __m256d kd, const double* x, const double* v,
                                            LaneCount<Vec4>& shortCount) {
    const std::size_t A = a + n, B = b + n;
    const __m256d xa = loadRow(x, a), xb = loadRow(x, b), xA = loadRow(x, A), xB = loadRow(x, B);
    const __m256d va = loadRow(v, a), vb = loadRow(v, b), vA = loadRow(v, A), vB = loadRow(v, B);
    __m256d dx, dy, dz, dvx, dvy, dvz;
    toColumns(_mm256_sub_pd(xb, xa), _mm256_sub_pd(xB, xA), _mm256_sub_pd(xb, xA), _mm256_sub_pd(xa, xB), dx, dy, dz);
    toColumns(_mm256_sub_pd(vb, va), _mm256_sub_pd(vB, vA), _mm256_sub_pd(vb, vA), _mm256_sub_pd(va, vB), dvx, dvy, dvz);
    const SpringLanes<Vec4> lane = springLanes(dx, dy, dz, dvx, dvy, dvz, _mm256_loadu_pd(rest), ks, kd, shortCount);
    __m256d F[4];
    toRows(lane.fx, lane.fy, lane.fz, F);
    return {a, b, _mm256_sub_pd(F[0], F[3]), _mm256_add_pd(F[0], F[2]), _mm256_add_pd(F[1], F[2]),
            _mm256_sub_pd(F[3], F[1]), lane.power, _mm256_mul_pd(lane.stretch, lane.stretch)};
}
SIMCORE_AVX2 inline void addQuad(const QuadLanes& r, std::size_t n, double* f4) {
    addRow(f4, r.a, r.fa);
    subRow(f4, r.b, r.fb);
    addRow(f4, r.a + n, r.fA);
    addRow(f4, r.b + n, r.fB);
}
// One quad computed and added, its sums into the given accumulators.
SIMCORE_AVX2 inline void quadAvx2(std::size_t a, std::size_t b, std::size_t n, const double* rest, __m256d ks,
                                  __m256d kd, const double* x, const double* v, double* f4, __m256d& power,
                                  __m256d& square, LaneCount<Vec4>& shortCount) {
    const QuadLanes r = quadLanesAvx2(a, b, n, rest, ks, kd, x, v, shortCount);
    power = _mm256_add_pd(power, r.power);
    square = _mm256_add_pd(square, r.square);
    addQuad(r, n, f4);
}

SIMCORE_AVX2 inline QuadSums finishQuads(__m256d evenPower, __m256d oddPower, __m256d evenSquare,
                                         __m256d oddSquare) {
    alignas(32) double power[2][4], square[2][4];
    _mm256_store_pd(power[0], evenPower);
    _mm256_store_pd(power[1], oddPower);
    _mm256_store_pd(square[0], evenSquare);
    _mm256_store_pd(square[1], oddSquare);
    return combineQuadLanes(power, square);
}

SIMCORE_AVX2
QuadSums quadBlockAvx2(const QuadSet& quads, std::size_t begin, std::size_t end, int n,
                       std::array<double, 2> ks, std::array<double, 2> kd, const double* x,
                       const double* v, double* f4, int& degenerate) {
    const __m256d vks = _mm256_setr_pd(ks[0], ks[0], ks[1], ks[1]);
    const __m256d vkd = _mm256_setr_pd(kd[0], kd[0], kd[1], kd[1]);
    __m256d power[2] = {_mm256_setzero_pd(), _mm256_setzero_pd()}, square[2] = {power[0], power[0]};
    LaneCount<Vec4> shortSprings{};
    const std::size_t outer = index(n);
    std::size_t q = begin;
    // Two quads (even, odd) per iteration, both computed before either is added.
    for (; q + 2 <= end; q += 2) {
        const QuadLanes even = quadLanesAvx2(index(quads.a[q]), index(quads.b[q]), outer, quads.rest[q].data(), vks,
                                             vkd, x, v, shortSprings);
        const QuadLanes odd = quadLanesAvx2(index(quads.a[q + 1]), index(quads.b[q + 1]), outer,
                                            quads.rest[q + 1].data(), vks, vkd, x, v, shortSprings);
        power[0] = _mm256_add_pd(power[0], even.power);
        square[0] = _mm256_add_pd(square[0], even.square);
        power[1] = _mm256_add_pd(power[1], odd.power);
        square[1] = _mm256_add_pd(square[1], odd.square);
        addQuad(even, outer, f4);
        addQuad(odd, outer, f4);
    }
    if (q < end)
        quadAvx2(index(quads.a[q]), index(quads.b[q]), outer, quads.rest[q].data(), vks, vkd, x, v, f4, power[0],
                 square[0], shortSprings);
    degenerate += laneTotal(shortSprings);
    return finishQuads(power[0], power[1], square[0], square[1]);
}

#if SIMCORE_AVX512_KERNELS

// Rows of particles p and q in one register: [p | q].
SIMCORE_AVX512 inline __m512d loadPair(const double* a, std::size_t p, std::size_t q) {
    return _mm512_insertf64x4(_mm512_castpd256_pd512(loadRow(a, p)), loadRow(a, q), 1);
}

// Four registers of row pairs [r_j | r'_j] to three columns whose lanes hold
// (j = 0, 1, 0', 1', 2, 3, 2', 3').
SIMCORE_AVX512 inline void toColumns8(__m512d r0, __m512d r1, __m512d r2, __m512d r3, __m512d& X,
                                      __m512d& Y, __m512d& Z) {
    const __m512d t0 = _mm512_unpacklo_pd(r0, r1);  // x0 x1 z0 z1 | x0' x1' z0' z1'
    const __m512d t1 = _mm512_unpackhi_pd(r0, r1);  // y0 y1 w0 w1 | y0' y1' w0' w1'
    const __m512d t2 = _mm512_unpacklo_pd(r2, r3);  // x2 x3 z2 z3 | x2' x3' z2' z3'
    const __m512d t3 = _mm512_unpackhi_pd(r2, r3);  // y2 y3 w2 w3 | y2' y3' w2' w3'
    X = _mm512_shuffle_f64x2(t0, t2, 0x88);  // 128-bit pieces 0, 2 of t0, then 0, 2 of t2
    Y = _mm512_shuffle_f64x2(t1, t3, 0x88);
    Z = _mm512_shuffle_f64x2(t0, t2, 0xdd);  // pieces 1, 3 of t0, then 1, 3 of t2
}

// Three such columns back to row pairs (x, y, z, 0): r[j] = [row j | row j'].
SIMCORE_AVX512 inline void toRows8(__m512d X, __m512d Y, __m512d Z, __m512d (&r)[4]) {
    const __m512d zero = _mm512_setzero_pd();
    const __m512i first = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11);
    const __m512i second = _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15);
    const __m512d t0 = _mm512_unpacklo_pd(X, Y);     // x0 y0 x0' y0' | x2 y2 x2' y2'
    const __m512d t1 = _mm512_unpackhi_pd(X, Y);     // x1 y1 x1' y1' | x3 y3 x3' y3'
    const __m512d t2 = _mm512_unpacklo_pd(Z, zero);  // z0 0 z0' 0 | z2 0 z2' 0
    const __m512d t3 = _mm512_unpackhi_pd(Z, zero);  // z1 0 z1' 0 | z3 0 z3' 0
    r[0] = _mm512_permutex2var_pd(t0, first, t2);
    r[1] = _mm512_permutex2var_pd(t1, first, t3);
    r[2] = _mm512_permutex2var_pd(t0, second, t2);
    r[3] = _mm512_permutex2var_pd(t1, second, t3);
}

SIMCORE_AVX512 inline __m256d low(__m512d v) { return _mm512_castpd512_pd256(v); }
SIMCORE_AVX512 inline __m256d high(__m512d v) { return _mm512_extractf64x4_pd(v, 1); }

// Two quads q (even) and q' (odd) in lanes (0, 1, 0', 1', 2, 3, 2', 3') of the four springs
// (a, b), (A, B), (A, b), (B, a), so lanes 0-3 are structural, 4-7 shear: their forces per
// particle row pair [quad | quad'], computed but not yet added.
struct QuadPair {
    std::size_t a, b, a1, b1;
    __m512d fa, fb, fA, fB;  // added to a, subtracted from b, added to A and B
    __m512d power, square;
};

SIMCORE_AVX512 inline QuadPair quadPairAvx512(const QuadSet& quads, std::size_t q, const double* x, const double* v,
                                              const double* xo, const double* vo, __m512d ks, __m512d kd,
                                              LaneCount<Vec8>& shortSprings) {
    // Outer particles through the outer layer's base pointers: no index arithmetic beyond
    // each index's own scaling (unsigned: no sign extension either).
    QuadPair r;
    r.a = index(quads.a[q]);
    r.b = index(quads.b[q]);
    r.a1 = index(quads.a[q + 1]);
    r.b1 = index(quads.b[q + 1]);
    const __m512d xa = loadPair(x, r.a, r.a1), xb = loadPair(x, r.b, r.b1);
    const __m512d xA = loadPair(xo, r.a, r.a1), xB = loadPair(xo, r.b, r.b1);
    const __m512d va = loadPair(v, r.a, r.a1), vb = loadPair(v, r.b, r.b1);
    const __m512d vA = loadPair(vo, r.a, r.a1), vB = loadPair(vo, r.b, r.b1);
    __m512d dx, dy, dz, dvx, dvy, dvz;
    toColumns8(_mm512_sub_pd(xb, xa), _mm512_sub_pd(xB, xA), _mm512_sub_pd(xb, xA), _mm512_sub_pd(xa, xB), dx, dy, dz);
    toColumns8(_mm512_sub_pd(vb, va), _mm512_sub_pd(vB, vA), _mm512_sub_pd(vb, vA), _mm512_sub_pd(va, vB), dvx, dvy, dvz);
    const __m512i restOrder = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11);
    const __m512d rest = _mm512_permutex2var_pd(_mm512_castpd256_pd512(_mm256_loadu_pd(quads.rest[q].data())), restOrder,
                                                _mm512_castpd256_pd512(_mm256_loadu_pd(quads.rest[q + 1].data())));
    const SpringLanes<Vec8> lane = springLanes(dx, dy, dz, dvx, dvy, dvz, rest, ks, kd, shortSprings);
    r.power = lane.power;
    r.square = _mm512_mul_pd(lane.stretch, lane.stretch);
    __m512d F[4];  // [F_j | F_j'] per spring j
    toRows8(lane.fx, lane.fy, lane.fz, F);
    r.fa = _mm512_sub_pd(F[0], F[3]);
    r.fb = _mm512_add_pd(F[0], F[2]);
    r.fA = _mm512_add_pd(F[1], F[2]);
    r.fB = _mm512_sub_pd(F[3], F[1]);
    return r;
}

// A pair's forces into f4 (inner rows) and fo (outer rows), quad q's before quad q''s.
SIMCORE_AVX512 inline void addQuadPair(const QuadPair& r, double* f4, double* fo) {
    addRow(f4, r.a, low(r.fa));
    subRow(f4, r.b, low(r.fb));
    addRow(fo, r.a, low(r.fA));
    addRow(fo, r.b, low(r.fB));
    addRow(f4, r.a1, high(r.fa));
    subRow(f4, r.b1, high(r.fb));
    addRow(fo, r.a1, high(r.fA));
    addRow(fo, r.b1, high(r.fB));
}

SIMCORE_AVX512
QuadSums quadBlockAvx512(const QuadSet& quads, std::size_t begin, std::size_t end, int n,
                         std::array<double, 2> ks, std::array<double, 2> kd, const double* x,
                         const double* v, double* f4, int& degenerate) {
    const __m512d vks = _mm512_setr_pd(ks[0], ks[0], ks[0], ks[0], ks[1], ks[1], ks[1], ks[1]);
    const __m512d vkd = _mm512_setr_pd(kd[0], kd[0], kd[0], kd[0], kd[1], kd[1], kd[1], kd[1]);
    __m512d power = _mm512_setzero_pd(), square = power;
    LaneCount<Vec8> shortSprings{};
    const std::size_t outer = index(n);
    const double *xo = x + 3 * outer, *vo = v + 3 * outer;
    double* fo = f4 + 4 * outer;
    std::size_t q = begin;
    // Two pairs per iteration, both computed before either is added: two independent chains
    // of sqrt, divide and shuffles for the out-of-order core to overlap.
    for (; q + 4 <= end; q += 4) {
        const QuadPair first = quadPairAvx512(quads, q, x, v, xo, vo, vks, vkd, shortSprings);
        const QuadPair second = quadPairAvx512(quads, q + 2, x, v, xo, vo, vks, vkd, shortSprings);
        power = _mm512_add_pd(_mm512_add_pd(power, first.power), second.power);
        square = _mm512_add_pd(_mm512_add_pd(square, first.square), second.square);
        addQuadPair(first, f4, fo);
        addQuadPair(second, f4, fo);
    }
    if (q + 2 <= end) {
        const QuadPair last = quadPairAvx512(quads, q, x, v, xo, vo, vks, vkd, shortSprings);
        power = _mm512_add_pd(power, last.power);
        square = _mm512_add_pd(square, last.square);
        addQuadPair(last, f4, fo);
        q += 2;
    }
    // Lanes (0, 1, 0', 1', 2, 3, 2', 3') to the even and odd accumulators.
    const __m512i evenLanes = _mm512_setr_epi64(0, 1, 4, 5, 0, 0, 0, 0);
    const __m512i oddLanes = _mm512_setr_epi64(2, 3, 6, 7, 0, 0, 0, 0);
    __m256d evenPower = low(_mm512_permutexvar_pd(evenLanes, power));
    __m256d evenSquare = low(_mm512_permutexvar_pd(evenLanes, square));
    const __m256d oddPower = low(_mm512_permutexvar_pd(oddLanes, power));
    const __m256d oddSquare = low(_mm512_permutexvar_pd(oddLanes, square));
    LaneCount<Vec4> tailShort{};
    if (q < end)  // an odd count: the last quad is an even one
        quadAvx2(index(quads.a[q]), index(quads.b[q]), outer, quads.rest[q].data(),
                 _mm256_setr_pd(ks[0], ks[0], ks[1], ks[1]), _mm256_setr_pd(kd[0], kd[0], kd[1], kd[1]), x, v, f4,
                 evenPower, evenSquare, tailShort);
    degenerate += laneTotal(shortSprings) + laneTotal(tailShort);
    return finishQuads(evenPower, oddPower, evenSquare, oddSquare);
}

// Eight consecutive rows (x, y, z) of a 3-per-particle array, from three registers
// (24 doubles), to columns in natural order: X = (x0 .. x7) and so on.
SIMCORE_AVX512 inline void rowsToColumns(const double* at, Vec8& X, Vec8& Y, Vec8& Z) {
    const __m512d r0 = _mm512_loadu_pd(at), r1 = _mm512_loadu_pd(at + 8), r2 = _mm512_loadu_pd(at + 16);
    // Indices 0-7 pick from the first operand, 8-15 from the second.
    const __m512d x01 = _mm512_permutex2var_pd(r0, _mm512_setr_epi64(0, 3, 6, 9, 12, 15, 0, 0), r1);
    const __m512d y01 = _mm512_permutex2var_pd(r0, _mm512_setr_epi64(1, 4, 7, 10, 13, 0, 0, 0), r1);
    const __m512d z01 = _mm512_permutex2var_pd(r0, _mm512_setr_epi64(2, 5, 8, 11, 14, 0, 0, 0), r1);
    X = _mm512_permutex2var_pd(x01, _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 10, 13), r2);
    Y = _mm512_permutex2var_pd(y01, _mm512_setr_epi64(0, 1, 2, 3, 4, 8, 11, 14), r2);
    Z = _mm512_permutex2var_pd(z01, _mm512_setr_epi64(0, 1, 2, 3, 4, 9, 12, 15), r2);
}

// Columns in natural order to padded rows (x, y, z, 0), two per register: [row 2j | row 2j+1].
SIMCORE_AVX512 inline void columnsToRowPairs(__m512d X, __m512d Y, __m512d Z, __m512d (&r)[4]) {
    const __m512d zero = _mm512_setzero_pd();
    const __m512d t0 = _mm512_unpacklo_pd(X, Y);     // x0 y0 | x2 y2 | x4 y4 | x6 y6
    const __m512d t1 = _mm512_unpackhi_pd(X, Y);     // x1 y1 | x3 y3 | x5 y5 | x7 y7
    const __m512d t2 = _mm512_unpacklo_pd(Z, zero);  // z0 0 | z2 0 | z4 0 | z6 0
    const __m512d t3 = _mm512_unpackhi_pd(Z, zero);  // z1 0 | z3 0 | z5 0 | z7 0
    const __m512i first = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11);
    const __m512i second = _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15);
    const __m512d even02 = _mm512_permutex2var_pd(t0, first, t2);   // [row 0 | row 2]
    const __m512d odd13 = _mm512_permutex2var_pd(t1, first, t3);    // [row 1 | row 3]
    const __m512d even46 = _mm512_permutex2var_pd(t0, second, t2);  // [row 4 | row 6]
    const __m512d odd57 = _mm512_permutex2var_pd(t1, second, t3);   // [row 5 | row 7]
    r[0] = _mm512_shuffle_f64x2(even02, odd13, 0x44);  // [row 0 | row 1]
    r[1] = _mm512_shuffle_f64x2(even02, odd13, 0xee);  // [row 2 | row 3]
    r[2] = _mm512_shuffle_f64x2(even46, odd57, 0x44);
    r[3] = _mm512_shuffle_f64x2(even46, odd57, 0xee);
}

SIMCORE_AVX512
SpringSums radiusRunAvx512(const SpringSet& springs, std::size_t begin, std::size_t end, int n, double ks,
                           double kd, const double* x, const double* v, double* f4, int& degenerate,
                           Scratch& scratch) {
    // Spring k joins particles p = a[begin] + (k - begin) and p + n: eight consecutive ones per
    // iteration, read and written as whole rows. Lanes 0-3 then 4-7 go into the four-lane sums
    // in that order, as springBlock adds them.
    const __m512d vks = _mm512_set1_pd(ks), vkd = _mm512_set1_pd(kd);
    SpringAccumulators sums;
    LaneCount<Vec8> shortSprings{};
    const int first = springs.a[begin];
    std::size_t k = begin;
    for (; k + 8 <= end; k += 8) {
        const std::size_t p = index(first) + (k - begin), q = p + index(n);
        const SpringLanes<Vec8> lane =
            radiusLanes<Vec8>(x, v, p, q, _mm512_loadu_pd(springs.rest.data() + k), vks, vkd, shortSprings);
        const __m512d square = _mm512_mul_pd(lane.stretch, lane.stretch);
        sums.power = _mm256_add_pd(_mm256_add_pd(sums.power, low(lane.power)), high(lane.power));
        sums.square = _mm256_add_pd(_mm256_add_pd(sums.square, low(square)), high(square));
        __m512d rows[4];
        columnsToRowPairs(lane.fx, lane.fy, lane.fz, rows);
        for (int j = 0; j < 4; ++j) {
            double* at = f4 + 4 * (p + 2 * j);
            _mm512_storeu_pd(at, _mm512_add_pd(_mm512_loadu_pd(at), rows[j]));
            double* bt = f4 + 4 * (q + 2 * j);
            _mm512_storeu_pd(bt, _mm512_sub_pd(_mm512_loadu_pd(bt), rows[j]));
        }
    }
    degenerate += laneTotal(shortSprings);
    k = radiusGroupsAvx2(springs, begin, k, end, index(n), _mm256_set1_pd(ks), _mm256_set1_pd(kd), x, v, f4, sums);
    return finishSprings(springs, k, end, ks, kd, x, v, f4, degenerate, scratch, sums);
}

#endif  // SIMCORE_AVX512_KERNELS

#endif  // SIMCORE_AVX2_KERNELS

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

Scratch::Scratch() : storage(new double[8 * kBlock]()) {
    double* p = storage.get();
    for (double** buffer : {&dx, &dy, &dz, &dvx, &dvy, &dvz, &power, &stretch2}) {
        *buffer = p;
        p += kBlock;
    }
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

SpringSums springBlock(const SpringSet& springs, std::size_t begin, std::size_t end, double ks,
                       double kd, const double* x, const double* v, double* f4, int& degenerate,
                       Scratch& scratch) {
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() >= KernelSet::Avx2) return springBlockAvx2(springs, begin, end, ks, kd, x, v, f4, degenerate, scratch);
#endif
    return springBlockPortable(springs, begin, end, ks, kd, x, v, f4, degenerate, scratch);
}

SpringSums springRunBlock(const SpringSet& springs, std::size_t begin, std::size_t end, int n, double ks,
                          double kd, const double* x, const double* v, double* f4, int& degenerate,
                          Scratch& scratch) {
#if SIMCORE_AVX512_KERNELS
    if (kernelsInUse() == KernelSet::Avx512)
        return radiusRunAvx512(springs, begin, end, n, ks, kd, x, v, f4, degenerate, scratch);
#endif
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() == KernelSet::Avx2) return radiusRunAvx2(springs, begin, end, n, ks, kd, x, v, f4, degenerate, scratch);
#endif
    (void)n;
    return springBlock(springs, begin, end, ks, kd, x, v, f4, degenerate, scratch);
}

QuadSums quadBlock(const QuadSet& quads, std::size_t begin, std::size_t end, int n,
                   std::array<double, 2> ks, std::array<double, 2> kd, const double* x,
                   const double* v, double* f4, int& degenerate) {
#if SIMCORE_AVX512_KERNELS
    if (kernelsInUse() == KernelSet::Avx512) return quadBlockAvx512(quads, begin, end, n, ks, kd, x, v, f4, degenerate);
#endif
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() >= KernelSet::Avx2) return quadBlockAvx2(quads, begin, end, n, ks, kd, x, v, f4, degenerate);
#endif
    return quadBlockPortable(quads, begin, end, n, ks, kd, x, v, f4, degenerate);
}

double triangleBlock(const Surface& surface, std::size_t begin, std::size_t end, const double* x,
                     double* g4, Scratch& scratch) {
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() >= KernelSet::Avx2) return triangleBlockAvx2(surface, begin, end, x, g4, scratch);
#endif
    return triangleBlockPortable(surface, begin, end, x, g4, scratch);
}

void unpad(const double* f4, const double* g4, double p, const double* invMass3, int begin, int end,
           double* out) {
#if SIMCORE_AVX2_KERNELS
    if (kernelsInUse() >= KernelSet::Avx2) return unpadAvx2(f4, g4, p, invMass3, begin, end, out);
#endif
    unpadPortable(f4, g4, p, invMass3, begin, end, out);
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
