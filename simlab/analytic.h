#pragma once
// Closed-form solutions used as references by tests and studies.
//
// spring1d without collisions is a linear damped oscillator. With the top end fixed:
//   m y'' = -k (y + L0) - c y' - m g      (y of the moving particle, the fixed one at 0)
// With both ends free the centre of mass falls freely and the separation s = y0 - y1 obeys
//   mu s'' = -k (s - L0) - c s'           (mu = m/2, both masses equal)
// Both reduce to z'' + 2 gamma z' + omega0^2 z = 0 around an equilibrium.

#include <Eigen/Core>

#include "simcore/params.h"

namespace simlab {

// Solution of z'' + 2 gamma z' + w0^2 z = 0, z(0) = z0, z'(0) = v0: under-, critically
// and over-damped. Returns (z, z').
Eigen::Vector2d dampedOscillator(double w0, double gamma, double z0, double v0, double t);

// Whether the closed form applies: spring1d (collisions must not occur; the caller checks).
bool hasClosedForm(const simcore::ParameterSet& params);
// Positions and velocities (3 x 2 each) of spring1d at time t, from its start state
// (no perturbation). Requires hasClosedForm(params).
void spring1dExact(const simcore::ParameterSet& params, double t, Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& v);

}  // namespace simlab
