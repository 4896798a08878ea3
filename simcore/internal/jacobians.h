#pragma once
// Force Jacobians as matrix-free kernels, for linearised implicit integration
// (Baraff & Witkin 1998). Each adds K dx + D dv of one term into out (all 3N flat arrays),
// with K = dF/dx and D = dF/dv at the positions x.
//
// Spring i-j, d = x_j - x_i, L = |d|, u = d / L, alpha = 1 - L0 / L:
//   dF_i/dx_j = stiffness [alpha I + (1 - alpha) u u^T]   (= -dF_i/dx_i; F_j = -F_i)
//   dF_i/dv_j = damping u u^T
// The transverse part alpha (I - u u^T) is negative stiffness for a compressed spring
// (alpha < 0) and makes K indefinite; it is clamped at 0 (Choi & Ko 2002), which keeps
// M - h D - h^2 K positive definite. The derivative of the damper's direction u in x is
// dropped, as Baraff & Witkin do. Both only change the linearisation, not the forces.
//
// Gas of a closed layer, F = (c / V) g with g = dV/dx:
//   K_gas = (c / V) H - (c / V^2) g g^T,   H = d^2V/dx^2
// The second term couples every particle of the layer: it is applied as a rank-one update
// (one dot product), never as a dense block. H is sparse: the directional derivative of the
// per-edge (2D) or per-triangle (3D) gradient formula.

#include <Eigen/Core>

#include "simcore/body.h"
#include "simcore/forces.h"

namespace simcore {

void addSpringJacobianProduct(const SpringSet& springs, double stiffness, double damping, const double* x,
                              const double* dx, const double* dv, double* out);
void addSpringJacobianDiagonal(const SpringSet& springs, double stiffness, double damping, const double* x,
                               double* kdiag, double* ddiag);

// g = dV/dx of the layer (adds into g; entries of other particles untouched).
void addVolumeGradient(const Surface& surface, int dimension, const double* x, double* g);
// out += (c/V) H dx - (c/V^2) g (g . dx); g is the full 3N gradient of this layer.
void addGasJacobianProduct(const Surface& surface, int dimension, double c, double volume,
                           const Eigen::VectorXd& g, const double* x, const double* dx, double* out);
// The diagonal of K_gas: H has none (V is linear in each coordinate), so -(c/V^2) g_k^2.
void addGasJacobianDiagonal(double c, double volume, const Eigen::VectorXd& g, double* kdiag);

void addPointerJacobianProduct(const PointerSpring& pointer, double mks, double mkd, double rest,
                               const double* x, const double* dx, const double* dv, double* out);
void addPointerJacobianDiagonal(const PointerSpring& pointer, double mks, double mkd, double rest,
                                const double* x, double* kdiag, double* ddiag);

}  // namespace simcore
