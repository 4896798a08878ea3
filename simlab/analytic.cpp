#include "simlab/analytic.h"

#include <cmath>
#include <stdexcept>

namespace simlab {

using simcore::Param;
using simcore::ParameterSet;
using simcore::SceneKind;

Eigen::Vector2d dampedOscillator(double w0, double gamma, double z0, double v0, double t) {
    const double e = std::exp(-gamma * t);
    const double disc = w0 * w0 - gamma * gamma;
    if (disc > 1e-12 * w0 * w0) {
        const double wd = std::sqrt(disc);
        const double c = std::cos(wd * t), s = std::sin(wd * t);
        const double b = (v0 + gamma * z0) / wd;
        const double z = e * (z0 * c + b * s);
        const double dz = -gamma * z + e * (-z0 * wd * s + b * wd * c);
        return {z, dz};
    }
    if (disc < -1e-12 * w0 * w0) {
        // z = A e^{r1 t} + B e^{r2 t}
        const double q = std::sqrt(-disc);
        const double r1 = -gamma + q, r2 = -gamma - q;
        const double b = (v0 - r1 * z0) / (r2 - r1), a = z0 - b;
        const double e1 = std::exp(r1 * t), e2 = std::exp(r2 * t);
        return {a * e1 + b * e2, a * r1 * e1 + b * r2 * e2};
    }
    // Critical: z = (z0 + (v0 + gamma z0) t) e^{-gamma t}
    const double b = v0 + gamma * z0;
    return {(z0 + b * t) * e, (b - gamma * (z0 + b * t)) * e};
}

bool hasClosedForm(const ParameterSet& params) { return params.kind() == SceneKind::Spring1d; }

void spring1dExact(const ParameterSet& params, double t, Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& v) {
    if (!hasClosedForm(params)) throw std::invalid_argument("no closed form for this scene");
    const double k = params.get(Param::Ks), c = params.get(Param::Kd), m = params.get(Param::Mass);
    const double g = params.get(Param::Gravity), rest = params.get(Param::Length);
    const double start = params.get(Param::InitialLength);
    x.setZero(3, 2);
    v.setZero(3, 2);
    if (params.getInt(Param::FixedEnd) != 0) {
        // Equilibrium y_eq = -(L0 + m g / k); z = y - y_eq.
        const double yEq = -(rest + m * g / k);
        const Eigen::Vector2d z = dampedOscillator(std::sqrt(k / m), c / (2.0 * m), -start - yEq, 0.0, t);
        x(1, 1) = yEq + z[0];
        v(1, 1) = z[1];
        return;
    }
    // Free pair: centre of mass falls freely; separation s = y0 - y1 with reduced mass m/2.
    const double mu = 0.5 * m;
    const Eigen::Vector2d z = dampedOscillator(std::sqrt(k / mu), c / (2.0 * mu), start - rest, 0.0, t);
    const double s = rest + z[0], ds = z[1];
    const double yc = -0.5 * start - 0.5 * g * t * t, vc = -g * t;
    x(1, 0) = yc + 0.5 * s;
    x(1, 1) = yc - 0.5 * s;
    v(1, 0) = vc + 0.5 * ds;
    v(1, 1) = vc - 0.5 * ds;
}

}  // namespace simlab
