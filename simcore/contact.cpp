#include "simcore/contact.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <mutex>

#include <Eigen/Core>

#include "simcore/scan_kernels.h"

// The wall test runs over every particle in every evaluation: compiled for AVX2 and baseline
// x86-64 and picked at load time, as the force kernels are (force_kernels.cpp).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(ELASTIC_LAB_MULTIVERSION)
#define SIMCORE_VECTOR_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define SIMCORE_VECTOR_KERNEL
#endif

namespace simcore {

SIMCORE_VECTOR_KERNEL bool anyOutsideWalls(const ContactParams& c, const double* x, int begin, int end) {
    const double* p = x + 3 * static_cast<std::ptrdiff_t>(begin);
    const Eigen::Index n = 3 * static_cast<Eigen::Index>(end - begin), columns = n / 12;
    Eigen::Array<double, 12, 1> low, high;
    low.setConstant(std::numeric_limits<double>::infinity());
    high.setConstant(-std::numeric_limits<double>::infinity());
    if (columns > 0) {
        const Eigen::Map<const Eigen::Array<double, 12, Eigen::Dynamic>> block(p, 12, columns);
        low = block.rowwise().minCoeff();
        high = block.rowwise().maxCoeff();
    }
    for (Eigen::Index k = 12 * columns; k < n; ++k) {
        low[k - 12 * columns] = std::min(low[k - 12 * columns], p[k]);
        high[k - 12 * columns] = std::max(high[k - 12 * columns], p[k]);
    }
    bool any = false;
    for (int j = 0; j < 12; ++j)
        any = any || low[j] < c.low[static_cast<std::size_t>(j % 3)] || high[j] > c.high[static_cast<std::size_t>(j % 3)];
    return any;
}


double contactPhi(double u) {
    const double root = std::sqrt(1.0 + u * u);
    // u + sqrt(1 + u^2) = 1 / (sqrt(1 + u^2) - u): the second form has no cancellation for u < 0.
    return u >= 0.0 ? u + root : 1.0 / (root - u);
}

double contactPhiMinusOne(double u) {
    // sqrt(1 + u^2) - 1 = u^2 / (sqrt(1 + u^2) + 1).
    const double root = std::sqrt(1.0 + u * u);
    const double rootMinusOne = u * u / (root + 1.0);
    if (u >= 0.0) return u + rootMinusOne;
    // 1 / (root - u) - 1 = (1 - root + u) / (root - u)
    return (u - rootMinusOne) / (root - u);
}

double wallContact(const ContactParams& c, const double* x, const double* v, double* f, double& power) {
    double energy = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        double depth = 0.0, rate = 0.0, sign = 0.0;
        if (x[axis] < c.low[axis]) {
            depth = c.low[axis] - x[axis];
            rate = -v[axis];
            sign = 1.0;
        } else if (x[axis] > c.high[axis]) {
            depth = x[axis] - c.high[axis];
            rate = v[axis];
            sign = -1.0;
        } else {
            continue;
        }
        const double elastic = c.stiffness * depth * depth * depth;   // k d^3 = -dU/dd
        const double dissipative = elastic * contactPhiMinusOne(c.alpha * rate);
        const double normal = elastic + dissipative;                  // k d^3 phi >= 0
        f[axis] += sign * normal;
        energy += 0.25 * elastic * depth;
        power += dissipative * rate;
        if (c.friction > 0.0) {
            const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            const double slip2 = v[a1] * v[a1] + v[a2] * v[a2];
            const double scale = c.friction * normal / std::sqrt(slip2 + c.frictionSpeed * c.frictionSpeed);
            f[a1] -= scale * v[a1];
            f[a2] -= scale * v[a2];
            power += scale * slip2;
        }
    }
    return energy;
}

double wallContactEnergy(const ContactParams& c, const double* x) {
    double energy = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double depth = x[axis] < c.low[axis] ? c.low[axis] - x[axis]
                             : x[axis] > c.high[axis] ? x[axis] - c.high[axis]
                                                      : 0.0;
        const double d2 = depth * depth;
        energy += 0.25 * c.stiffness * d2 * d2;
    }
    return energy;
}

void addWallContactJacobian(const ContactParams& c, const double* x, const double* v, double* k, double* d) {
    for (int axis = 0; axis < 3; ++axis) {
        double depth = 0.0, rate = 0.0;
        if (x[axis] < c.low[axis]) {
            depth = c.low[axis] - x[axis];
            rate = -v[axis];
        } else if (x[axis] > c.high[axis]) {
            depth = x[axis] - c.high[axis];
            rate = v[axis];
        } else {
            continue;
        }
        // F_axis = s k d^3 phi(alpha ddot) with d = -s x + b and ddot = -s v (s = +-1):
        // dF/dx = -3 k d^2 phi, dF/dv = -k d^3 alpha phi'(u), phi' = phi / sqrt(1 + u^2).
        const double u = c.alpha * rate;
        const double phi = contactPhi(u);
        const double kd3 = c.stiffness * depth * depth * depth;
        k[axis] -= 3.0 * c.stiffness * depth * depth * phi;
        d[axis] -= kd3 * c.alpha * phi / std::sqrt(1.0 + u * u);
        if (c.friction > 0.0) {
            const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            const double slip2 = v[a1] * v[a1] + v[a2] * v[a2];
            const double scale = c.friction * kd3 * phi / std::sqrt(slip2 + c.frictionSpeed * c.frictionSpeed);
            d[a1] -= scale;
            d[a2] -= scale;
        }
    }
}

double restitutionOf(double zeta) {
    // s'' = -s^3 phi(zeta s'), s(0) = 0, s'(0) = 1, by RK4 until s returns to 0. The scaled
    // impact lasts about 3.1 at zeta = 0 (a quarter-power well), longer as zeta grows.
    if (!(zeta > 0.0)) return 1.0;
    constexpr double h = 0.002, tauMax = 400.0;
    auto acc = [zeta](double s, double p) { return -s * s * s * contactPhi(zeta * p); };
    double s = 0.0, p = 1.0;
    for (double tau = 0.0; tau < tauMax; tau += h) {
        const double k1s = p, k1p = acc(s, p);
        const double k2s = p + 0.5 * h * k1p, k2p = acc(s + 0.5 * h * k1s, p + 0.5 * h * k1p);
        const double k3s = p + 0.5 * h * k2p, k3p = acc(s + 0.5 * h * k2s, p + 0.5 * h * k2p);
        const double k4s = p + h * k3p, k4p = acc(s + h * k3s, p + h * k3p);
        const double sNext = s + h / 6.0 * (k1s + 2.0 * k2s + 2.0 * k3s + k4s);
        const double pNext = p + h / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
        if (sNext <= 0.0 && tau > 0.0) {
            // Out of contact the force is 0: the speed at the crossing is the step's end
            // speed up to the force over the sliver of the step beyond s = 0 (~ s^3, nil).
            return std::max(0.0, -pNext);
        }
        s = sNext;
        p = pNext;
    }
    return std::max(0.0, -p);
}

double dampingForRestitution(double e) {
    if (!(e < 1.0)) return 0.0;
    static std::mutex mutex;
    static std::map<double, double> memo;
    {
        std::lock_guard lock(mutex);
        if (auto it = memo.find(e); it != memo.end()) return it->second;
    }
    // restitutionOf decreases with zeta: bisection on log zeta.
    double lo = 1e-9, hi = kMaxZeta;
    if (restitutionOf(hi) >= e) {
        lo = hi;
    } else {
        for (int it = 0; it < 80 && hi / lo > 1.0 + 1e-12; ++it) {
            const double mid = std::sqrt(lo * hi);
            (restitutionOf(mid) > e ? lo : hi) = mid;
        }
    }
    const double zeta = std::sqrt(lo * hi);
    std::lock_guard lock(mutex);
    memo.emplace(e, zeta);
    return zeta;
}

void LayerBarrierSet::clear() {
    inner.clear();
    outer.clear();
    invRestNorm.clear();
    fanStart.assign(1, 0);
    fan.clear();
}

std::array<double, 3> layerBarrierNormal(const LayerBarrierSet& set, std::size_t k, int dimension, const double* x) {
    const int o = set.outer[k];
    const double* xo = x + 3 * o;
    std::array<double, 3> g{0.0, 0.0, 0.0};
    for (int j = set.fanStart[k]; j < set.fanStart[k + 1]; ++j) {
        const auto [b, c] = set.fan[static_cast<std::size_t>(j)];
        const double* xb = x + 3 * b;
        const double* xc = x + 3 * c;
        if (dimension == 2) {
            // g = (n - p)^perp / 2 with (dx, dy)^perp = (dy, -dx); b = previous, c = next.
            g[0] += 0.5 * (xc[1] - xb[1]);
            g[1] -= 0.5 * (xc[0] - xb[0]);
        } else {
            const double B[3] = {xb[0] - xo[0], xb[1] - xo[1], xb[2] - xo[2]};
            const double C[3] = {xc[0] - xo[0], xc[1] - xo[1], xc[2] - xo[2]};
            g[0] += (B[1] * C[2] - B[2] * C[1]) / 6.0;
            g[1] += (B[2] * C[0] - B[0] * C[2]) / 6.0;
            g[2] += (B[0] * C[1] - B[1] * C[0]) / 6.0;
        }
    }
    return g;
}

double layerBarrierDepth(const LayerBarrierSet& set, std::size_t k, const double* x, const double* g4) {
    const int i = set.inner[k], o = set.outer[k];
    const double* g = g4 + 4 * o;
    const double along =
        (x[3 * i] - x[3 * o]) * g[0] + (x[3 * i + 1] - x[3 * o + 1]) * g[1] + (x[3 * i + 2] - x[3 * o + 2]) * g[2];
    if (!(along > 0.0)) return along * set.invRestNorm[k];  // inside: the sign is all that matters
    const double g02 = 1.0 / (set.invRestNorm[k] * set.invRestNorm[k]);
    return kSqrt2 * along / std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + g02);
}

PairScan scanPairedRanges(const ContactParams& c, const double* x, const double* g4, int begin, int end, int offset) {
    // Four pairs at a time (scan_kernels.h). NaN coordinates compare false everywhere: they
    // are the failure check's, not contact's.
    const kernels::PairScanBits bits = kernels::scanPairs(c.low, c.high, x, g4, begin, end, offset);
    PairScan scan;
    scan.outsideWalls = bits.outsideWalls;
    scan.beyondPlane = bits.beyondPlane;
    return scan;
}

namespace {

// A branch-free pass: is any inner particle beyond its partner's tangent plane (w.g > 0)?
// Nearly never.
bool anyBeyondTangentPlane(const LayerBarrierSet& set, const double* x, const double* g4) {
    const int* inner = set.inner.data();
    const int* outer = set.outer.data();
    const std::size_t count = set.size();
    int any = 0;
    const bool run = count > 0 && inner[count - 1] - inner[0] == static_cast<int>(count - 1) &&
                     outer[count - 1] - outer[0] == static_cast<int>(count - 1);
    if (run) {
        // A run (pairs k, k + n in order, as a layered body numbers them; checked at its ends,
        // the set being sorted): consecutive rows, no index loads.
        const double* xi = x + 3 * inner[0];
        const double* xo = x + 3 * outer[0];
        const double* g = g4 + 4 * outer[0];
        for (std::size_t p = 0; p < count; ++p, xi += 3, xo += 3, g += 4)
            any |= (xi[0] - xo[0]) * g[0] + (xi[1] - xo[1]) * g[1] + (xi[2] - xo[2]) * g[2] > 0.0;
    } else {
        for (std::size_t p = 0; p < count; ++p) {
            const double* xi = x + 3 * inner[p];
            const double* xo = x + 3 * outer[p];
            const double* g = g4 + 4 * outer[p];
            any |= (xi[0] - xo[0]) * g[0] + (xi[1] - xo[1]) * g[1] + (xi[2] - xo[2]) * g[2] > 0.0;
        }
    }
    return any != 0;
}

}  // namespace

double layerBarrierForces(const LayerBarrierSet& set, int dimension, double k, const double* x, const double* g4,
                          double* f4, bool screen) {
    // The screen first (nearly always nothing to do); then the pairs are gone through again.
    if (screen && !anyBeyondTangentPlane(set, x, g4)) return 0.0;
    const std::size_t count = set.size();
    double energy = 0.0;
    for (std::size_t p = 0; p < count; ++p) {
        const int i = set.inner[p], o = set.outer[p];
        const double* g = g4 + 4 * o;
        const double w[3] = {x[3 * i] - x[3 * o], x[3 * i + 1] - x[3 * o + 1], x[3 * i + 2] - x[3 * o + 2]};
        // The sign first: no root for the pairs that are inside (nearly all, nearly always).
        const double along = w[0] * g[0] + w[1] * g[1] + w[2] * g[2];
        if (!(along > 0.0)) continue;
        const double g02 = 1.0 / (set.invRestNorm[p] * set.invRestNorm[p]);
        const double norm2 = g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + g02;  // N^2 = |g|^2 + g0^2
        const double inv = kSqrt2 / std::sqrt(norm2);
        const double q = along * inv, q2 = q * q;
        energy += 0.25 * k * q2 * q2;
        // q = sqrt2 w.g / N:  dq = dw.n + dg.t  with n = sqrt2 g / N, t = sqrt2 (w - (w.g) g / N^2) / N;
        // F = -k q^3 dq/dx.
        const double s = k * q2 * q;
        const double n[3] = {g[0] * inv, g[1] * inv, g[2] * inv};
        const double r = along / norm2;
        const double t[3] = {(w[0] - r * g[0]) * inv, (w[1] - r * g[1]) * inv, (w[2] - r * g[2]) * inv};
        double* fi = f4 + 4 * i;
        double* fo = f4 + 4 * o;
        for (int a = 0; a < 3; ++a) {
            fi[a] -= s * n[a];
            fo[a] += s * n[a];
        }
        // dg/dx of o's neighbours (g depends on them) against t.
        for (int j = set.fanStart[p]; j < set.fanStart[p + 1]; ++j) {
            const auto [b, c] = set.fan[static_cast<std::size_t>(j)];
            double* fb = f4 + 4 * b;
            double* fc = f4 + 4 * c;
            if (dimension == 2) {
                // t.g = [(n - p)_y t_x - (n - p)_x t_y] / 2: d/dn = (-t_y, t_x)/2 = -d/dp.
                const double gx = -0.5 * t[1], gy = 0.5 * t[0];
                fc[0] -= s * gx;
                fc[1] -= s * gy;
                fb[0] += s * gx;
                fb[1] += s * gy;
            } else {
                // t.(B x C)/6 with B = x_b - x_o, C = x_c - x_o: d/dx_b = (C x t)/6,
                // d/dx_c = (t x B)/6, d/dx_o = -(both) (the fan's terms; they sum to zero
                // over a closed fan, kept so that the forces sum to zero per triangle).
                const double* xo = x + 3 * o;
                const double B[3] = {x[3 * b] - xo[0], x[3 * b + 1] - xo[1], x[3 * b + 2] - xo[2]};
                const double C[3] = {x[3 * c] - xo[0], x[3 * c + 1] - xo[1], x[3 * c + 2] - xo[2]};
                const double db[3] = {(C[1] * t[2] - C[2] * t[1]) / 6.0, (C[2] * t[0] - C[0] * t[2]) / 6.0,
                                      (C[0] * t[1] - C[1] * t[0]) / 6.0};
                const double dc[3] = {(t[1] * B[2] - t[2] * B[1]) / 6.0, (t[2] * B[0] - t[0] * B[2]) / 6.0,
                                      (t[0] * B[1] - t[1] * B[0]) / 6.0};
                for (int a = 0; a < 3; ++a) {
                    fb[a] -= s * db[a];
                    fc[a] -= s * dc[a];
                    fo[a] += s * (db[a] + dc[a]);
                }
            }
        }
    }
    return energy;
}

}  // namespace simcore
