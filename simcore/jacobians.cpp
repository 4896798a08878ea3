#include "simcore/internal/jacobians.h"

#include <algorithm>
#include <cmath>

namespace simcore {

namespace {

// K_ij block of a spring-like pair, applied to r: stiffness [alpha r + (1 - alpha)(u.r) u].
inline Eigen::Vector3d stiffnessBlock(const Eigen::Vector3d& u, double alpha, double stiffness,
                                      const Eigen::Vector3d& r) {
    return stiffness * (alpha * r + (1.0 - alpha) * u.dot(r) * u);
}

}  // namespace

void addSpringJacobianProduct(const SpringSet& springs, double stiffness, double damping, const double* x,
                              const double* dx, const double* dv, double* out) {
    for (std::size_t s = 0; s < springs.size(); ++s) {
        const int i = 3 * springs.a[s], j = 3 * springs.b[s];
        const Eigen::Vector3d d(x[j] - x[i], x[j + 1] - x[i + 1], x[j + 2] - x[i + 2]);
        const double length = d.norm();
        if (length < kDegenerateLength) continue;  // no direction, as in the force
        const Eigen::Vector3d u = d / length;
        const double alpha = std::max(0.0, 1.0 - springs.rest[s] / length);
        const Eigen::Vector3d rx(dx[j] - dx[i], dx[j + 1] - dx[i + 1], dx[j + 2] - dx[i + 2]);
        const Eigen::Vector3d rv(dv[j] - dv[i], dv[j + 1] - dv[i + 1], dv[j + 2] - dv[i + 2]);
        const Eigen::Vector3d f = stiffnessBlock(u, alpha, stiffness, rx) + damping * u.dot(rv) * u;
        for (int k = 0; k < 3; ++k) {
            out[i + k] += f[k];
            out[j + k] -= f[k];
        }
    }
}

void addSpringJacobianDiagonal(const SpringSet& springs, double stiffness, double damping, const double* x,
                               double* kdiag, double* ddiag) {
    for (std::size_t s = 0; s < springs.size(); ++s) {
        const int i = 3 * springs.a[s], j = 3 * springs.b[s];
        const Eigen::Vector3d d(x[j] - x[i], x[j + 1] - x[i + 1], x[j + 2] - x[i + 2]);
        const double length = d.norm();
        if (length < kDegenerateLength) continue;
        const Eigen::Vector3d u = d / length;
        const double alpha = std::max(0.0, 1.0 - springs.rest[s] / length);
        for (int k = 0; k < 3; ++k) {
            const double kk = -stiffness * (alpha + (1.0 - alpha) * u[k] * u[k]);
            const double dd = -damping * u[k] * u[k];
            kdiag[i + k] += kk;
            kdiag[j + k] += kk;
            ddiag[i + k] += dd;
            ddiag[j + k] += dd;
        }
    }
}

void addVolumeGradient(const Surface& surface, int dimension, const double* x, double* g) {
    if (dimension == 2) {
        // Shoelace: dA/dx_a from edge a->b and edge p->a is (y_b - y_p) / 2, (x_p - x_b) / 2.
        for (auto [a, b] : surface.edges) {
            const double dx = x[3 * b] - x[3 * a], dy = x[3 * b + 1] - x[3 * a + 1];
            g[3 * a] += 0.5 * dy;
            g[3 * a + 1] -= 0.5 * dx;
            g[3 * b] += 0.5 * dy;
            g[3 * b + 1] -= 0.5 * dx;
        }
        return;
    }
    // Each corner gets (b - a) x (c - a) / 6; summed over a closed surface this is dV/dx.
    for (auto [a, b, c] : surface.triangles) {
        Eigen::Map<const Eigen::Vector3d> xa(x + 3 * a), xb(x + 3 * b), xc(x + 3 * c);
        const Eigen::Vector3d t = (xb - xa).cross(xc - xa) / 6.0;
        for (int k : {a, b, c})
            for (int axis = 0; axis < 3; ++axis) g[3 * k + axis] += t[axis];
    }
}

void addGasJacobianProduct(const Surface& surface, int dimension, double c, double volume,
                           const Eigen::VectorXd& g, const double* x, const double* dx, double* out) {
    if (!(volume > 0.0)) return;
    const double pressure = c / volume;
    // Rank-one term: -(c / V^2) g (g . dx), one dot product over the layer.
    const Eigen::Index n = g.size();
    const double gdx = g.dot(Eigen::Map<const Eigen::VectorXd>(dx, n));
    const double w = -pressure / volume * gdx;
    // Sparse term P H dx: the gradient formula differentiated along dx.
    if (dimension == 2) {
        // The 2D gradient is linear in x, so H dx is the same formula applied to dx.
        for (auto [a, b] : surface.edges) {
            const double ddx = dx[3 * b] - dx[3 * a], ddy = dx[3 * b + 1] - dx[3 * a + 1];
            out[3 * a] += 0.5 * pressure * ddy;
            out[3 * a + 1] -= 0.5 * pressure * ddx;
            out[3 * b] += 0.5 * pressure * ddy;
            out[3 * b + 1] -= 0.5 * pressure * ddx;
        }
    } else {
        for (auto [a, b, c3] : surface.triangles) {
            Eigen::Map<const Eigen::Vector3d> xa(x + 3 * a), xb(x + 3 * b), xc(x + 3 * c3);
            Eigen::Map<const Eigen::Vector3d> ua(dx + 3 * a), ub(dx + 3 * b), uc(dx + 3 * c3);
            const Eigen::Vector3d t =
                (pressure / 6.0) * ((ub - ua).cross(xc - xa) + (xb - xa).cross(uc - ua));
            for (int k : {a, b, c3})
                for (int axis = 0; axis < 3; ++axis) out[3 * k + axis] += t[axis];
        }
    }
    // Apply the rank-one term to every coordinate of the layer (g is zero elsewhere).
    for (Eigen::Index k = 0; k < n; ++k)
        if (g[k] != 0.0) out[k] += w * g[k];
}

void addGasJacobianDiagonal(double c, double volume, const Eigen::VectorXd& g, double* kdiag) {
    if (!(volume > 0.0)) return;
    const double s = c / (volume * volume);
    for (Eigen::Index k = 0; k < g.size(); ++k) kdiag[k] -= s * g[k] * g[k];
}

void addPointerJacobianProduct(const PointerSpring& pointer, double mks, double mkd, double rest,
                               const double* x, const double* dx, const double* dv, double* out) {
    if (!pointer.active || pointer.particle < 0) return;
    const int p = 3 * pointer.particle;
    const Eigen::Vector3d d = pointer.anchor - Eigen::Vector3d(x[p], x[p + 1], x[p + 2]);
    const double length = d.norm();
    if (length < kDegenerateLength) {
        // At the anchor with rest 0 the spring is isotropic: F = mks d, K = -mks I.
        for (int k = 0; k < 3; ++k) out[p + k] -= mks * dx[p + k] + mkd * dv[p + k];
        return;
    }
    const Eigen::Vector3d u = d / length;
    const double alpha = std::max(0.0, 1.0 - rest / length);
    const Eigen::Vector3d rx(dx[p], dx[p + 1], dx[p + 2]), rv(dv[p], dv[p + 1], dv[p + 2]);
    const Eigen::Vector3d f = -stiffnessBlock(u, alpha, mks, rx) - mkd * u.dot(rv) * u;
    for (int k = 0; k < 3; ++k) out[p + k] += f[k];
}

void addPointerJacobianDiagonal(const PointerSpring& pointer, double mks, double mkd, double rest,
                                const double* x, double* kdiag, double* ddiag) {
    if (!pointer.active || pointer.particle < 0) return;
    const int p = 3 * pointer.particle;
    const Eigen::Vector3d d = pointer.anchor - Eigen::Vector3d(x[p], x[p + 1], x[p + 2]);
    const double length = d.norm();
    const Eigen::Vector3d u = length < kDegenerateLength ? Eigen::Vector3d::Zero() : Eigen::Vector3d(d / length);
    const double alpha = length < kDegenerateLength ? 1.0 : std::max(0.0, 1.0 - rest / length);
    for (int k = 0; k < 3; ++k) {
        kdiag[p + k] -= mks * (alpha + (1.0 - alpha) * u[k] * u[k]);
        ddiag[p + k] -= mkd * (length < kDegenerateLength ? 1.0 : u[k] * u[k]);
    }
}

}  // namespace simcore
