#include "forces.h"

#include <cmath>

namespace simcore {

std::string_view termName(Term term) {
    switch (term) {
        case Term::Gravity: return "gravity";
        case Term::Springs: return "springs";
        case Term::Gas: return "gas";
        case Term::Pointer: return "pointer";
        case Term::Collisions: return "collisions";
        case Term::LayerConstraint: return "layer-constraint";
        case Term::Count: break;
    }
    return "?";
}

void addGravity(const Eigen::VectorXd& mass, double g, double* f) {
    const Eigen::Index n = mass.size();
    for (Eigen::Index i = 0; i < n; ++i) f[3 * i + 1] -= mass[i] * g;
}

double addSprings(const SpringSet& springs, double ks, double kd, const double* x, const double* v,
                  double* f, int& degenerate) {
    // Spring i-j: d = x_j - x_i, L = |d|, u = d/L,
    //   F_i = [ks (L - L0) + kd (v_j - v_i).u] u,  F_j = -F_i.
    // The damper's power kd ((v_j - v_i).u)^2 is what it removes from the body.
    double power = 0.0;
    const std::size_t count = springs.size();
    const int* ia = springs.a.data();
    const int* ib = springs.b.data();
    const double* rest = springs.rest.data();
    for (std::size_t s = 0; s < count; ++s) {
        const int i = 3 * ia[s], j = 3 * ib[s];
        const double dx = x[j] - x[i], dy = x[j + 1] - x[i + 1], dz = x[j + 2] - x[i + 2];
        const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (length < kDegenerateLength) {
            ++degenerate;  // no direction: contributes nothing rather than a NaN
            continue;
        }
        const double inv = 1.0 / length;
        const double ux = dx * inv, uy = dy * inv, uz = dz * inv;
        const double closing = (v[j] - v[i]) * ux + (v[j + 1] - v[i + 1]) * uy + (v[j + 2] - v[i + 2]) * uz;
        const double magnitude = ks * (length - rest[s]) + kd * closing;
        power += kd * closing * closing;
        const double fx = magnitude * ux, fy = magnitude * uy, fz = magnitude * uz;
        f[i] += fx;
        f[i + 1] += fy;
        f[i + 2] += fz;
        f[j] -= fx;
        f[j + 1] -= fy;
        f[j + 2] -= fz;
    }
    return power;
}

double addGas(const Surface& surface, int dimension, double c, const double* x, double* f) {
    const double volume = enclosedVolume(surface, x, dimension);
    if (!(volume > 0.0)) return volume;  // inside out: the caller reports the failure
    const double pressure = c / volume;
    if (dimension == 2) {
        // Edge a->b with the interior on its left: outward normal * length = (dy, -dx).
        // dA/dx_a summed over both edges of a vertex equals P*L*n/2 from each edge.
        const double half = 0.5 * pressure;
        for (auto [a, b] : surface.edges) {
            const double dx = x[3 * b] - x[3 * a], dy = x[3 * b + 1] - x[3 * a + 1];
            f[3 * a] += half * dy;
            f[3 * a + 1] -= half * dx;
            f[3 * b] += half * dy;
            f[3 * b + 1] -= half * dx;
        }
        return volume;
    }
    // Triangle abc: area * normal = (b-a)x(c-a)/2; each corner gets P*A*n/3, i.e.
    // P/6 * (b-a)x(c-a). Summed over a closed surface this is exactly P * dV/dx.
    const double sixth = pressure / 6.0;
    for (auto [a, b, c3] : surface.triangles) {
        Eigen::Map<const Eigen::Vector3d> xa(x + 3 * a), xb(x + 3 * b), xc(x + 3 * c3);
        const Eigen::Vector3d g = sixth * (xb - xa).cross(xc - xa);
        for (int k : {a, b, c3}) {
            f[3 * k] += g.x();
            f[3 * k + 1] += g.y();
            f[3 * k + 2] += g.z();
        }
    }
    return volume;
}

double addPointer(const PointerSpring& pointer, double mks, double mkd, double rest,
                  const double* x, const double* v, double* f) {
    // A spring from the particle p to the anchor r_m (which does not move during a step):
    // d = r_m - x_p, F_p = [mks (L - rest) - mkd v_p.u] u.
    if (!pointer.active || pointer.particle < 0) return 0.0;
    const int p = 3 * pointer.particle;
    const Eigen::Vector3d d = pointer.anchor - Eigen::Vector3d(x[p], x[p + 1], x[p + 2]);
    const double length = d.norm();
    if (length < kDegenerateLength) return 0.0;
    const Eigen::Vector3d u = d / length;
    const double closing = -(v[p] * u.x() + v[p + 1] * u.y() + v[p + 2] * u.z());
    const double magnitude = mks * (length - rest) + mkd * closing;
    f[p] += magnitude * u.x();
    f[p + 1] += magnitude * u.y();
    f[p + 2] += magnitude * u.z();
    return mkd * closing * closing;
}

double springEnergy(const SpringSet& springs, double ks, const double* x) {
    double energy = 0.0;
    for (std::size_t s = 0; s < springs.size(); ++s) {
        const int i = 3 * springs.a[s], j = 3 * springs.b[s];
        const double dx = x[j] - x[i], dy = x[j + 1] - x[i + 1], dz = x[j + 2] - x[i + 2];
        const double stretch = std::sqrt(dx * dx + dy * dy + dz * dz) - springs.rest[s];
        energy += stretch * stretch;
    }
    return 0.5 * ks * energy;
}

double gasEnergy(double c, double volume) {
    // E = -c ln V, so that -dE/dx = (c/V) dV/dx = P dV/dx: the gas force.
    return volume > 0.0 ? -c * std::log(volume) : 0.0;
}

double pointerEnergy(const PointerSpring& pointer, double mks, double rest, const double* x) {
    if (!pointer.active || pointer.particle < 0) return 0.0;
    const int p = 3 * pointer.particle;
    const double stretch =
        (pointer.anchor - Eigen::Vector3d(x[p], x[p + 1], x[p + 2])).norm() - rest;
    return 0.5 * mks * stretch * stretch;
}

void ForceModel::evaluate(const double* x, const double* v, double* f, ForceExtras& extras) {
    const Topology& topo = *m_topology;
    const std::size_t n3 = static_cast<std::size_t>(3 * topo.particleCount());
    std::fill(f, f + n3, 0.0);
    extras = ForceExtras{};
    ++m_forceEvaluations;

    if (m_terms.has(Term::Gravity)) {
        ++m_evaluations[static_cast<std::size_t>(Term::Gravity)];
        addGravity(*m_mass, params.gravity, f);
    }
    if (m_terms.has(Term::Springs)) {
        ++m_evaluations[static_cast<std::size_t>(Term::Springs)];
        for (int fam = 0; fam < kSpringFamilyCount; ++fam) {
            const auto k = static_cast<std::size_t>(fam);
            extras.dampingPower += addSprings(topo.springs[k], params.ks[k], params.kd[k], x, v,
                                              f, extras.degenerateSprings);
        }
    }
    if (m_terms.has(Term::Gas)) {
        ++m_evaluations[static_cast<std::size_t>(Term::Gas)];
        for (const Surface& s : topo.surfaces) {
            const int slot = layerSlot(s.layer);
            const double c = params.gasConstant[static_cast<std::size_t>(slot)];
            const double volume = addGas(s, topo.dimension, c, x, f);
            extras.volume[static_cast<std::size_t>(slot)] = volume;
            extras.pressure[static_cast<std::size_t>(slot)] = volume > 0.0 ? c / volume : 0.0;
        }
    }
    if (m_terms.has(Term::Pointer) && pointer.active) {
        ++m_evaluations[static_cast<std::size_t>(Term::Pointer)];
        extras.dampingPower += addPointer(pointer, params.mks, params.mkd, params.mouseRest, x, v, f);
    }
}

}  // namespace simcore
