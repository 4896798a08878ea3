// The float32 path (float_path.h).
//
// One force evaluation is three passes, each split into tasks fixed by the body:
//  1. springs, in blocks: each spring's force F = [ks (L - L0) + kd (dv.u)] u into its own row
//     of a spring buffer (4 floats), its damping power kd (dv.u)^2 summed per task in double;
//     faces, in blocks: each face's row (b - a) x (c - a) (3D; (dy, -dx) in 2D) and its volume
//     term x_a.((b - a) x (c - a)) (= x_a.(x_b x x_c); 2D: the shoelace term), summed per task
//     in double;
//  2. (the caller) volumes and pressures from the task sums, in task order;
//  3. particles, in blocks: each gathers the rows of its springs (+ where it is the first
//     end, - where the second) and of its faces (times P/6, or P/2 in 2D) in a fixed order,
//     adds its weight, divides by its mass, and hands (v, a) to the integrator's update of its
//     own rows.
// Positions and velocities are padded rows (x, y, z, 0) of 16 bytes, so that a particle is one
// 128-bit load. With AVX2 the spring and face passes take eight at a time: the rows of eight
// particles are transposed to columns in registers, the arithmetic runs eight wide, operation
// for operation as the scalar code (no fused multiply-add: simcore builds with
// -ffp-contract=off), so that both give the same bits.
#include "simcore/float_path.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "simcore/force_kernels.h"
#include "simcore/forces.h"
#include "simcore/parallel.h"

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define SIMCORE_FLOAT_AVX2 1
#include <immintrin.h>
#endif

namespace simcore {

namespace {

constexpr std::array<std::string_view, 5> kFloatIntegrators{"euler", "midpoint", "rk4", "symplectic-euler", "verlet"};
constexpr std::size_t kSpringTask = 4096;  // springs per task (a multiple of 8)
constexpr std::size_t kFaceTask = 4096;    // faces per task
constexpr int kParticleTask = 2048;        // particles per task

using F4 = float __attribute__((vector_size(16)));

inline F4 row(const float* p, int i) {
    F4 r;
    std::memcpy(&r, p + 4 * static_cast<std::ptrdiff_t>(i), sizeof r);
    return r;
}
inline void setRow(float* p, int i, F4 r) { std::memcpy(p + 4 * static_cast<std::ptrdiff_t>(i), &r, sizeof r); }
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
    std::vector<float> rest, ks, kd;
    std::size_t size() const { return a.size(); }
};

// One spring, scalar: the reference the eight-wide code follows operation by operation.
inline void springScalar(const SpringArrays& s, std::size_t k, const float* x, const float* v, float* out,
                         LaneSums& power) {
    const F4 xa = row(x, s.a[k]), xb = row(x, s.b[k]), va = row(v, s.a[k]), vb = row(v, s.b[k]);
    const F4 d = xb - xa, dv = vb - va;
    const float len2 = (d[0] * d[0] + d[1] * d[1]) + d[2] * d[2];
    const float len = std::sqrt(len2);
    const float inv = 1.0f / len;
    const float ux = d[0] * inv, uy = d[1] * inv, uz = d[2] * inv;
    const float dvu = (dv[0] * ux + dv[1] * uy) + dv[2] * uz;
    float mag = s.ks[k] * (len - s.rest[k]) + s.kd[k] * dvu;
    float p = s.kd[k] * dvu * dvu;
    if (!(len >= static_cast<float>(kDegenerateLength))) mag = 0.0f, p = 0.0f;
    const float fx = mag * ux, fy = mag * uy, fz = mag * uz;
    const bool ok = len >= static_cast<float>(kDegenerateLength);
    setRow(out, static_cast<int>(k), F4{ok ? fx : 0.0f, ok ? fy : 0.0f, ok ? fz : 0.0f, 0.0f});
    power.lane[k % 8] += static_cast<double>(p);
}

// One face, scalar: its row and its volume term.
// The volume term goes to lane (k - base) % 8, base being where the run of faces began.
inline void faceScalar(const std::vector<std::array<int, 3>>& faces, int dimension, std::size_t base, std::size_t k,
                       const float* x, float* out, LaneSums& volume) {
    const auto& f = faces[k];
    const F4 xa = row(x, f[0]), xb = row(x, f[1]);
    F4 g;
    float term;
    if (dimension == 2) {
        const F4 d = xb - xa;
        g = F4{d[1], 0.0f - d[0], 0.0f, 0.0f};
        term = xa[0] * xb[1] - xb[0] * xa[1];
    } else {
        const F4 xc = row(x, f[2]);
        const F4 e = xb - xa, h = xc - xa;
        g = F4{e[1] * h[2] - e[2] * h[1], e[2] * h[0] - e[0] * h[2], e[0] * h[1] - e[1] * h[0], 0.0f};
        term = (xa[0] * g[0] + xa[1] * g[1]) + xa[2] * g[2];
    }
    setRow(out, static_cast<int>(k), g);
    volume.lane[(k - base) % 8] += static_cast<double>(term);
}

#ifdef SIMCORE_FLOAT_AVX2
#pragma GCC push_options
#pragma GCC target("avx2")
// The x, y, z columns of eight particles' rows (rows idx[0..7] of p).
[[gnu::always_inline]] inline void columns8(const float* p, const int* idx, __m256& cx,
                                                                  __m256& cy, __m256& cz) {
    auto pair = [&](int k) {
        return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(p + 4 * static_cast<std::ptrdiff_t>(idx[k]))),
                                    _mm_loadu_ps(p + 4 * static_cast<std::ptrdiff_t>(idx[k + 4])), 1);
    };
    const __m256 r0 = pair(0), r1 = pair(1), r2 = pair(2), r3 = pair(3);
    const __m256 t0 = _mm256_unpacklo_ps(r0, r1), t1 = _mm256_unpackhi_ps(r0, r1);
    const __m256 t2 = _mm256_unpacklo_ps(r2, r3), t3 = _mm256_unpackhi_ps(r2, r3);
    cx = _mm256_shuffle_ps(t0, t2, 0x44);
    cy = _mm256_shuffle_ps(t0, t2, 0xEE);
    cz = _mm256_shuffle_ps(t1, t3, 0x44);
}

// Rows k..k+7 of out from three columns (the fourth component 0).
[[gnu::always_inline]] inline void storeRows8(float* out, std::size_t k, __m256 cx, __m256 cy,
                                                                    __m256 cz) {
    const __m256 zero = _mm256_setzero_ps();
    const __m256 t0 = _mm256_unpacklo_ps(cx, cy), t1 = _mm256_unpackhi_ps(cx, cy);
    const __m256 t2 = _mm256_unpacklo_ps(cz, zero), t3 = _mm256_unpackhi_ps(cz, zero);
    const __m256 r0 = _mm256_shuffle_ps(t0, t2, 0x44), r1 = _mm256_shuffle_ps(t0, t2, 0xEE);
    const __m256 r2 = _mm256_shuffle_ps(t1, t3, 0x44), r3 = _mm256_shuffle_ps(t1, t3, 0xEE);
    float* o = out + 4 * k;
    _mm256_storeu_ps(o, _mm256_permute2f128_ps(r0, r1, 0x20));
    _mm256_storeu_ps(o + 8, _mm256_permute2f128_ps(r2, r3, 0x20));
    _mm256_storeu_ps(o + 16, _mm256_permute2f128_ps(r0, r1, 0x31));
    _mm256_storeu_ps(o + 24, _mm256_permute2f128_ps(r2, r3, 0x31));
}

[[gnu::always_inline]] inline void addLanes(LaneSums& sums, __m256 v) {
    alignas(32) double d[8];
    _mm256_store_pd(d, _mm256_cvtps_pd(_mm256_castps256_ps128(v)));
    _mm256_store_pd(d + 4, _mm256_cvtps_pd(_mm256_extractf128_ps(v, 1)));
    for (int l = 0; l < 8; ++l) sums.lane[static_cast<std::size_t>(l)] += d[l];
}

void springs8(const SpringArrays& s, std::size_t begin, std::size_t end, const float* x,
                                      const float* v, float* out, LaneSums& power) {
    const __m256 degenerate = _mm256_set1_ps(static_cast<float>(kDegenerateLength)), one = _mm256_set1_ps(1.0f);
    std::size_t k = begin;
    for (; k + 8 <= end; k += 8) {
        const int* ia = s.a.data() + k;
        const int* ib = s.b.data() + k;
        __m256 xax, xay, xaz, xbx, xby, xbz, vax, vay, vaz, vbx, vby, vbz;
        columns8(x, ia, xax, xay, xaz);
        columns8(x, ib, xbx, xby, xbz);
        columns8(v, ia, vax, vay, vaz);
        columns8(v, ib, vbx, vby, vbz);
        const __m256 dx = _mm256_sub_ps(xbx, xax), dy = _mm256_sub_ps(xby, xay), dz = _mm256_sub_ps(xbz, xaz);
        const __m256 wx = _mm256_sub_ps(vbx, vax), wy = _mm256_sub_ps(vby, vay), wz = _mm256_sub_ps(vbz, vaz);
        const __m256 len2 =
            _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(dx, dx), _mm256_mul_ps(dy, dy)), _mm256_mul_ps(dz, dz));
        const __m256 len = _mm256_sqrt_ps(len2);
        const __m256 inv = _mm256_div_ps(one, len);
        const __m256 ux = _mm256_mul_ps(dx, inv), uy = _mm256_mul_ps(dy, inv), uz = _mm256_mul_ps(dz, inv);
        const __m256 dvu =
            _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(wx, ux), _mm256_mul_ps(wy, uy)), _mm256_mul_ps(wz, uz));
        const __m256 ks = _mm256_loadu_ps(s.ks.data() + k), kd = _mm256_loadu_ps(s.kd.data() + k);
        const __m256 ok = _mm256_cmp_ps(len, degenerate, _CMP_GE_OQ);
        const __m256 mag = _mm256_and_ps(
            ok, _mm256_add_ps(_mm256_mul_ps(ks, _mm256_sub_ps(len, _mm256_loadu_ps(s.rest.data() + k))),
                              _mm256_mul_ps(kd, dvu)));
        const __m256 p = _mm256_and_ps(ok, _mm256_mul_ps(_mm256_mul_ps(kd, dvu), dvu));
        storeRows8(out, k, _mm256_and_ps(ok, _mm256_mul_ps(mag, ux)), _mm256_and_ps(ok, _mm256_mul_ps(mag, uy)),
                   _mm256_and_ps(ok, _mm256_mul_ps(mag, uz)));
        addLanes(power, p);
    }
    for (; k < end; ++k) springScalar(s, k, x, v, out, power);
}

void faces8(const std::vector<std::array<int, 3>>& faces, std::size_t begin, std::size_t end,
                                    const int* corners, const float* x, float* out, LaneSums& volume) {
    // corners: the faces' corner indices as three columns (a, b, c) of faces.size() each.
    const std::size_t n = faces.size();
    std::size_t k = begin;
    for (; k + 8 <= end; k += 8) {
        __m256 ax, ay, az, bx, by, bz, cx, cy, cz;
        columns8(x, corners + k, ax, ay, az);
        columns8(x, corners + n + k, bx, by, bz);
        columns8(x, corners + 2 * n + k, cx, cy, cz);
        const __m256 ex = _mm256_sub_ps(bx, ax), ey = _mm256_sub_ps(by, ay), ez = _mm256_sub_ps(bz, az);
        const __m256 hx = _mm256_sub_ps(cx, ax), hy = _mm256_sub_ps(cy, ay), hz = _mm256_sub_ps(cz, az);
        const __m256 gx = _mm256_sub_ps(_mm256_mul_ps(ey, hz), _mm256_mul_ps(ez, hy));
        const __m256 gy = _mm256_sub_ps(_mm256_mul_ps(ez, hx), _mm256_mul_ps(ex, hz));
        const __m256 gz = _mm256_sub_ps(_mm256_mul_ps(ex, hy), _mm256_mul_ps(ey, hx));
        const __m256 term =
            _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(ax, gx), _mm256_mul_ps(ay, gy)), _mm256_mul_ps(az, gz));
        storeRows8(out, k, gx, gy, gz);
        addLanes(volume, term);
    }
    for (; k < end; ++k) faceScalar(faces, 3, begin, k, x, out, volume);
}

#pragma GCC pop_options

bool haveAvx2() { return __builtin_cpu_supports("avx2"); }
#endif

// Per-particle lists of rows, each padded to one width (the longest list, rounded up to even)
// with a row of zeros (index `zero`): every particle's loop then runs the same number of times,
// so its exit is always predicted (lists of 5 to 8 rows of varying length cost a mispredicted
// branch each), and two accumulators take the even and odd positions.
struct Incidence {
    int width = 0;
    std::vector<int> items;  // n x width
    void build(int n, const std::vector<std::pair<int, int>>& pairs, int zero) {  // (particle, item), in item order
        std::vector<int> count(static_cast<std::size_t>(n), 0);
        for (auto [p, item] : pairs) ++count[static_cast<std::size_t>(p)];
        width = 0;
        for (int c : count) width = std::max(width, c);
        width += width % 2;
        items.assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(width), zero);
        std::fill(count.begin(), count.end(), 0);
        for (auto [p, item] : pairs)
            items[static_cast<std::size_t>(p) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(count[static_cast<std::size_t>(p)]++)] = item;
    }
};

}  // namespace

bool floatPathSupports(std::string_view integrator) {
    return std::find(kFloatIntegrators.begin(), kFloatIntegrators.end(), integrator) != kFloatIntegrators.end();
}

std::string floatPathIntegrators() {
    std::string s;
    for (std::string_view name : kFloatIntegrators) s += (s.empty() ? "" : ", ") + std::string(name);
    return s;
}

std::string floatPathRefusal(const Simulation& start) {
    const std::string_view name = start.integrator().name();
    if (!floatPathSupports(name))
        return "precision float is built for the explicit integrators " + floatPathIntegrators() + ", not " +
               std::string(name);
    if (start.pointer().active) return "precision float has no pointer (mouse spring)";
    return "";
}

struct FloatSimulation::Impl {
    // The body.
    const Topology* topo = nullptr;
    int n = 0;
    int dimension = 3;
    Eigen::VectorXd mass;
    std::vector<float> invMass4;  // 4 per particle (0 on fixed particles and absent axes)
    std::vector<float> weight4;   // gravity force rows
    SpringArrays springs;
    std::vector<std::array<int, 3>> faces;  // all surfaces' faces (2D: (a, b, -))
    std::vector<int> faceCorners;           // the corners as columns (AVX2 path)
    std::vector<std::uint8_t> faceSlot;     // [inner, outer] slot of each face's surface
    std::array<std::size_t, 3> faceSlotEnd{};  // faces of slot 0 come first
    Incidence plus, minus, incidentFaces;
    std::vector<std::uint8_t> particleSlot;
    ForceParams params;
    bool gas = false;
    std::array<double, 3> low{}, high{};

    // State and scratch (4 floats per particle).
    std::vector<float> x, v, xt, vt, xa, va;
    std::vector<float> springRows, faceRows;
    std::vector<LaneSums> springPower, faceVolume;  // per task
    std::array<float, 2> pressureScaled{};  // P / 6 (P / 2 in 2D) per slot
    double stagePower = 0.0;                // the last evaluation's damping power [W]
    std::uint64_t evaluations = 0;

    std::unique_ptr<ThreadPool> pool;
    int threads = 1;
    bool wide = false;  // the AVX2 passes

    mutable Diagnostics diag;
    mutable bool measured = false;
    double removed = 0.0;
    double initialEnergy = 0.0;

    int springTasks() const { return static_cast<int>((springs.size() + kSpringTask - 1) / kSpringTask); }
    int faceTasks() const { return static_cast<int>((faces.size() + kFaceTask - 1) / kFaceTask); }
    int particleTasks() const { return (n + kParticleTask - 1) / kParticleTask; }

    void run(int count, TaskRef task) {
        if (pool) {
            pool->run(count, task);
        } else {
            for (int t = 0; t < count; ++t) task(t);
        }
    }

    // Passes 1 and 2 at (px, pv): spring and face rows, damping power and pressures.
    void springsAndFaces(const float* px, const float* pv) {
        const int st = springTasks(), ft = faceTasks();
        auto task = [&](int t) {
            if (t < st) {
                const std::size_t begin = static_cast<std::size_t>(t) * kSpringTask,
                                  end = std::min(springs.size(), begin + kSpringTask);
                LaneSums& sums = springPower[static_cast<std::size_t>(t)];
                sums = {};
#ifdef SIMCORE_FLOAT_AVX2
                if (wide) {
                    springs8(springs, begin, end, px, pv, springRows.data(), sums);
                    return;
                }
#endif
                for (std::size_t k = begin; k < end; ++k) springScalar(springs, k, px, pv, springRows.data(), sums);
            } else {
                const std::size_t f = static_cast<std::size_t>(t - st);
                const std::size_t begin = f * kFaceTask, end = std::min(faces.size(), begin + kFaceTask);
                LaneSums& sums = faceVolume[f];
                sums = {};
#ifdef SIMCORE_FLOAT_AVX2
                if (wide && dimension == 3) {
                    // A task's faces are of one slot or straddle the slot boundary; the volume
                    // sums are split at it below.
                    const std::size_t cut = std::clamp(faceSlotEnd[0], begin, end);
                    faces8(faces, begin, cut, faceCorners.data(), px, faceRows.data(), sums);
                    LaneSums& second = faceVolume[faceVolume.size() / 2 + f];
                    second = {};
                    faces8(faces, cut, end, faceCorners.data(), px, faceRows.data(), second);
                    return;
                }
#endif
                const std::size_t cut = std::clamp(faceSlotEnd[0], begin, end);
                for (std::size_t k = begin; k < cut; ++k) faceScalar(faces, dimension, begin, k, px, faceRows.data(), sums);
                LaneSums& second = faceVolume[faceVolume.size() / 2 + f];
                second = {};
                for (std::size_t k = cut; k < end; ++k) faceScalar(faces, dimension, cut, k, px, faceRows.data(), second);
            }
        };
        run(st + (gas ? ft : 0), task);
        double power = 0.0;
        for (int t = 0; t < st; ++t) power += springPower[static_cast<std::size_t>(t)].total();
        stagePower = power;
        if (gas) {
            const std::size_t half = faceVolume.size() / 2;
            for (std::size_t slot = 0; slot < 2; ++slot) {
                double sum = 0.0;
                for (std::size_t f = 0; f < half; ++f) sum += faceVolume[slot * half + f].total();
                const double volume = dimension == 2 ? 0.5 * sum : sum / 6.0;
                const double pressure = volume > 0.0 ? params.gasConstant[slot] / volume : 0.0;
                pressureScaled[slot] = static_cast<float>(dimension == 2 ? 0.5 * pressure : pressure / 6.0);
            }
        }
        ++evaluations;
    }

    // The sum of particle i's rows of `rows` (list.items) in two interleaved accumulators (even
    // and odd positions, then added): two independent add chains, in an order fixed by the list.
    static F4 sumRows(const float* rows, const Incidence& list, int i) {
        F4 even = splat(0.0f), odd = splat(0.0f);
        const int* items = list.items.data() + static_cast<std::ptrdiff_t>(i) * list.width;
        for (int k = 0; k < list.width; k += 2) {
            even += row(rows, items[k]);
            odd += row(rows, items[k + 1]);
        }
        return even + odd;
    }

    // Pass 3: the force on particle i, times its inverse mass: its weight, the rows of the
    // springs where it is the first end minus those where it is the second, and its faces'
    // rows times the pressure (P / 6; P / 2 in 2D).
    F4 acceleration(int i) const {
        const auto s = static_cast<std::size_t>(i);
        const F4 springForce = sumRows(springRows.data(), plus, i) - sumRows(springRows.data(), minus, i);
        F4 f = row(weight4.data(), i) + springForce;
        if (gas) {
            const F4 g = sumRows(faceRows.data(), incidentFaces, i);
            f += splat(pressureScaled[particleSlot[s]]) * g;
        }
        return f * row(invMass4.data(), i);
    }

    // One evaluation at (px, pv); update(i, v_i, a_i) on each particle's own rows.
    template <class Update>
    void evaluate(const float* px, const float* pv, Update&& update) {
        springsAndFaces(px, pv);
        auto task = [&](int t) {
            const int begin = t * kParticleTask, end = std::min(n, begin + kParticleTask);
            for (int i = begin; i < end; ++i) update(i, row(pv, i), acceleration(i));
        };
        run(particleTasks(), task);
    }

    void step(std::string_view integrator, float h, double hd) {
        float* X = x.data();
        float* V = v.data();
        if (integrator == "euler") {
            evaluate(X, V, [&](int i, F4 vi, F4 ai) {
                setRow(X, i, row(X, i) + splat(h) * vi);
                setRow(V, i, vi + splat(h) * ai);
            });
            removed += hd * stagePower;
        } else if (integrator == "symplectic-euler") {
            evaluate(X, V, [&](int i, F4 vi, F4 ai) {
                const F4 vn = vi + splat(h) * ai;
                setRow(V, i, vn);
                setRow(X, i, row(X, i) + splat(h) * vn);
            });
            removed += hd * stagePower;
        } else if (integrator == "verlet") {
            const float half = 0.5f * h, hh = 0.5f * h * h;
            evaluate(X, V, [&](int i, F4 vi, F4 ai) {
                setRow(X, i, row(X, i) + splat(h) * vi + splat(hh) * ai);
                setRow(V, i, vi + splat(half) * ai);
            });
            const double p1 = stagePower;
            evaluate(X, V, [&](int i, F4 vi, F4 ai) { setRow(V, i, vi + splat(half) * ai); });
            removed += 0.5 * hd * (p1 + stagePower);
        } else if (integrator == "midpoint") {
            float* XT = xt.data();
            float* VT = vt.data();
            const float half = 0.5f * h;
            evaluate(X, V, [&](int i, F4 vi, F4 ai) {
                setRow(XT, i, row(X, i) + splat(half) * vi);
                setRow(VT, i, vi + splat(half) * ai);
            });
            evaluate(XT, VT, [&](int i, F4 vi, F4 ai) {
                setRow(X, i, row(X, i) + splat(h) * vi);
                setRow(V, i, row(V, i) + splat(h) * ai);
            });
            removed += hd * stagePower;
        } else {  // rk4
            float* XT = xt.data();
            float* VT = vt.data();
            float* XA = xa.data();
            float* VA = va.data();
            const float sixth = h / 6.0f, third = h / 3.0f, half = 0.5f * h;
            evaluate(X, V, [&](int i, F4 vi, F4 ai) {
                const F4 xi = row(X, i);
                setRow(XA, i, xi + splat(sixth) * vi);
                setRow(VA, i, vi + splat(sixth) * ai);
                setRow(XT, i, xi + splat(half) * vi);
                setRow(VT, i, vi + splat(half) * ai);
            });
            double power = stagePower;
            auto middle = [&](float c) {
                evaluate(XT, VT, [&](int i, F4 vi, F4 ai) {
                    setRow(XA, i, row(XA, i) + splat(third) * vi);
                    setRow(VA, i, row(VA, i) + splat(third) * ai);
                    setRow(XT, i, row(X, i) + splat(c) * vi);
                    setRow(VT, i, row(V, i) + splat(c) * ai);
                });
                power += 2.0 * stagePower;
            };
            middle(half);
            middle(h);
            evaluate(XT, VT, [&](int i, F4 vi, F4 ai) {
                setRow(X, i, row(XA, i) + splat(sixth) * vi);
                setRow(V, i, row(VA, i) + splat(sixth) * ai);
            });
            power += stagePower;
            removed += hd / 6.0 * power;
        }
    }

    // Finite, and inside the walls; the reason when not.
    std::string check() const {
        for (int i = 0; i < n; ++i) {
            const F4 xi = row(x.data(), i), vi = row(v.data(), i);
            for (int axis = 0; axis < 3; ++axis) {
                if (!std::isfinite(xi[axis]) || !std::isfinite(vi[axis]))
                    return "the state is no longer finite (particle " + std::to_string(i) + ")";
                const double c = xi[axis];
                if (c < low[static_cast<std::size_t>(axis)] || c > high[static_cast<std::size_t>(axis)])
                    return "particle " + std::to_string(i) +
                           " reached a wall: the float path has no contact (use precision double)";
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
                springEnergy(topo->springs[static_cast<std::size_t>(f)], params.ks[static_cast<std::size_t>(f)], px);
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
    s.invMass4.assign(4 * n, 0.0f);
    s.weight4.assign(4 * n, 0.0f);
    for (std::size_t i = 0; i < n; ++i) {
        const bool fixed = i < start.body().fixed.size() && start.body().fixed[i];
        const float inv = fixed ? 0.0f : static_cast<float>(1.0 / s.mass[static_cast<Eigen::Index>(i)]);
        s.invMass4[4 * i + 1] = inv;
        if (s.dimension >= 2) s.invMass4[4 * i] = inv;
        if (s.dimension == 3) s.invMass4[4 * i + 2] = inv;
        s.weight4[4 * i + 1] = static_cast<float>(0.0 - s.mass[static_cast<Eigen::Index>(i)] * s.params.gravity);
    }
    // Springs of all families in one array, ordered by their lower particle (then the
    // other): the mesh is numbered for locality (renumberForLocality), so a particle's springs
    // lie together, near its neighbours', for the gathers of pass 3. Each particle's lists in
    // that order.
    std::vector<std::array<int, 3>> order;  // (family, index, lower particle)
    for (int f = 0; f < kSpringFamilyCount; ++f) {
        const SpringSet& set = topo.springs[static_cast<std::size_t>(f)];
        for (std::size_t k = 0; k < set.size(); ++k) order.push_back({f, static_cast<int>(k), std::min(set.a[k], set.b[k])});
    }
    std::stable_sort(order.begin(), order.end(), [](const auto& p, const auto& q) { return p[2] < q[2]; });
    std::vector<std::pair<int, int>> plus, minus;
    for (const auto& [f, k, lower] : order) {
        const SpringSet& set = topo.springs[static_cast<std::size_t>(f)];
        const auto j = static_cast<std::size_t>(k);
        const int id = static_cast<int>(s.springs.size());
        s.springs.a.push_back(set.a[j]);
        s.springs.b.push_back(set.b[j]);
        s.springs.rest.push_back(static_cast<float>(set.rest[j]));
        s.springs.ks.push_back(static_cast<float>(s.params.ks[static_cast<std::size_t>(f)]));
        s.springs.kd.push_back(static_cast<float>(s.params.kd[static_cast<std::size_t>(f)]));
        plus.emplace_back(set.a[j], id);
        minus.emplace_back(set.b[j], id);
    }
    const int zeroSpring = static_cast<int>(s.springs.size());  // the row of zeros after the springs'
    s.plus.build(s.n, plus, zeroSpring);
    s.minus.build(s.n, minus, zeroSpring);
    // Faces: the inner layer's first (slot 0), then the outer's.
    std::vector<std::pair<int, int>> incident;
    if (s.gas) {
        for (std::size_t slot = 0; slot < 2; ++slot) {
            for (const Surface& surface : topo.surfaces) {
                if (static_cast<std::size_t>(layerSlot(surface.layer)) != slot) continue;
                if (s.dimension == 2) {
                    for (auto [a, b] : surface.edges) s.faces.push_back({a, b, a});
                } else {
                    for (const auto& t : surface.triangles) s.faces.push_back(t);
                }
            }
            s.faceSlotEnd[slot] = s.faces.size();
        }
        for (std::size_t f = 0; f < s.faces.size(); ++f) {
            const int corners = s.dimension == 2 ? 2 : 3;
            for (int c = 0; c < corners; ++c) incident.emplace_back(s.faces[f][static_cast<std::size_t>(c)], static_cast<int>(f));
        }
        s.faceCorners.resize(3 * s.faces.size());
        for (std::size_t f = 0; f < s.faces.size(); ++f)
            for (std::size_t c = 0; c < 3; ++c) s.faceCorners[c * s.faces.size() + f] = s.faces[f][c];
    }
    s.incidentFaces.build(s.n, incident, static_cast<int>(s.faces.size()));
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
    s.springRows.assign(4 * (s.springs.size() + 1), 0.0f);  // + the row of zeros
    s.faceRows.assign(4 * (s.faces.size() + 1), 0.0f);
    s.springPower.resize(static_cast<std::size_t>(s.springTasks()));
    s.faceVolume.resize(2 * static_cast<std::size_t>(s.faceTasks()));
#ifdef SIMCORE_FLOAT_AVX2
    s.wide = kernels::kernelsInUse() != kernels::KernelSet::Portable && haveAvx2();
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
    m_time += m_dt;
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

std::uint64_t FloatSimulation::stateHash() const {
    std::uint64_t h = 14695981039346656037ULL;
    for (const std::vector<float>* buffer : {&m_impl->x, &m_impl->v}) {
        const auto* p = reinterpret_cast<const unsigned char*>(buffer->data());
        for (std::size_t i = 0; i < buffer->size() * sizeof(float); ++i) h = (h ^ p[i]) * 1099511628211ULL;
    }
    return h;
}

}  // namespace simcore
