#include "simcore/internal/world_ode.h"

#include <algorithm>
#include <cmath>

namespace simcore {

WorldOde::WorldOde(std::vector<std::unique_ptr<WorldBody>>& bodies, ContactPairs& pairs,
                   const PairContactParams& contact, int substeps)
    : m_bodies(bodies), m_pairs(pairs), m_contact(contact), m_substeps(substeps) {
    int particles = 0;
    for (const auto& b : m_bodies) particles += b->count();
    m_n = 3 * Eigen::Index{particles};
    m_invMass3.setZero(m_n);
    for (const auto& b : m_bodies) m_invMass3.segment(3 * Eigen::Index{b->first()}, 3 * Eigen::Index{b->count()}) = b->inverseMass3();
    m_mass.setZero(m_n);
    for (Eigen::Index k = 0; k < m_n; ++k) m_mass[k] = m_invMass3[k] > 0.0 ? 1.0 / m_invMass3[k] : 0.0;
    m_extras.resize(m_bodies.size());
    m_pairForce.setZero(m_n);
    m_pairForce0.setZero(m_n);
    m_y0.setZero(2 * m_n + kAux);
    m_shifted.setZero(2 * m_n + kAux);
    for (const auto& b : m_bodies) {
        const Topology& topo = b->body().topology;
        for (int f = 0; f < kSpringFamilyCount; ++f) {
            const SpringSet& s = topo.springs[static_cast<std::size_t>(f)];
            for (std::size_t k = 0; k < s.size(); ++k)
                m_springs[static_cast<std::size_t>(f)].add(b->first() + s.a[k], b->first() + s.b[k], s.rest[k]);
        }
    }
}

void WorldOde::scatter(const WorldBody& b, const Eigen::VectorXd& local, Eigen::Index localAt, Eigen::VectorXd& world,
                       Eigen::Index worldAt) const {
    const Eigen::Index nb = 3 * Eigen::Index{b.count()};
    world.segment(worldAt + 3 * Eigen::Index{b.first()}, nb) = local.segment(localAt, nb);
}

void WorldOde::derivative(double /*t*/, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) { compute(y, dydt, true); }

void WorldOde::compute(const Eigen::VectorXd& y, Eigen::VectorXd& dydt, bool count) {
    double damping = 0.0, contact = 0.0;
    for (std::size_t k = 0; k < m_bodies.size(); ++k) {
        WorldBody& b = *m_bodies[k];
        const Eigen::Index nb = 3 * Eigen::Index{b.count()};
        b.ode().compute(b.gather(y, m_n), b.localRate(), m_extras[k], count);
        scatter(b, b.localRate(), 0, dydt, 0);
        scatter(b, b.localRate(), nb, dydt, m_n);
        damping += b.localRate()[2 * nb];
        contact += b.localRate()[2 * nb + 1];
    }
    m_pairForce.setZero();
    m_pairSums = m_pairs.addForces(m_contact, y.data(), y.data() + m_n, m_pairForce.data());
    if (m_pairSums.pairs > 0) dydt.segment(m_n, m_n) += m_pairForce.cwiseProduct(m_invMass3);
    dydt[2 * m_n] = damping;
    dydt[2 * m_n + 1] = contact + m_pairSums.power;
}

void WorldOde::linearize(double t, const Eigen::VectorXd& y) {
    for (auto& b : m_bodies) b->ode().linearize(t, b->gather(y, m_n));
    m_y0 = y;
    m_pairForce0.setZero();
    const PairSums sums = m_pairs.addForces(m_contact, y.data(), y.data() + m_n, m_pairForce0.data());
    m_pairsActive = sums.pairs > 0;
}

void WorldOde::forceJacobianProduct(const Eigen::VectorXd& dx, const Eigen::VectorXd& dv, Eigen::VectorXd& out) {
    for (auto& b : m_bodies) {
        const Eigen::Index nb = 3 * Eigen::Index{b->count()}, at = 3 * Eigen::Index{b->first()};
        auto& s = b->scratch();
        s[0] = dx.segment(at, nb);
        s[1] = dv.segment(at, nb);
        b->ode().forceJacobianProduct(s[0], s[1], s[2]);
        out.segment(at, nb) = s[2];
    }
    if (!m_pairsActive) return;
    // The pairs' part: (F(x0 + e dx, v0 + e dv) - F(x0, v0)) / e, e scaled to the state.
    const double size = std::sqrt(dx.squaredNorm() + dv.squaredNorm());
    if (!(size > 0.0)) return;
    const double scale = 1.0 + std::sqrt(m_y0.head(2 * m_n).squaredNorm() / static_cast<double>(2 * m_n));
    const double e = 1e-7 * scale / size;
    m_shifted.head(m_n) = m_y0.head(m_n) + e * dx;
    m_shifted.segment(m_n, m_n) = m_y0.segment(m_n, m_n) + e * dv;
    m_pairForce.setZero();
    m_pairs.addForces(m_contact, m_shifted.data(), m_shifted.data() + m_n, m_pairForce.data());
    for (Eigen::Index k = 0; k < m_n; ++k)
        if (m_mass[k] > 0.0) out[k] += (m_pairForce[k] - m_pairForce0[k]) / e;
}

void WorldOde::forceJacobianDiagonal(Eigen::VectorXd& kdiag, Eigen::VectorXd& ddiag) {
    for (auto& b : m_bodies) {
        const Eigen::Index nb = 3 * Eigen::Index{b->count()}, at = 3 * Eigen::Index{b->first()};
        auto& s = b->scratch();
        b->ode().forceJacobianDiagonal(s[0], s[1]);
        kdiag.segment(at, nb) = s[0];
        ddiag.segment(at, nb) = s[1];
    }
}

std::optional<std::string> WorldOde::xpbdRefusal() const {
    const ForceParams& first = m_bodies.front()->forces().params;
    for (std::size_t k = 1; k < m_bodies.size(); ++k) {
        const ForceParams& p = m_bodies[k]->forces().params;
        if (p.stiffness != first.stiffness || p.damping != first.damping)
            return "xpbd takes one stiffness and damping per spring family for the whole world, and body " +
                   std::to_string(k + 1) + "'s springs differ from body 1's (ks, kd, rks, rkd or the resolution); "
                   "choose another integrator or give the bodies the same springs";
    }
    return std::nullopt;
}

bool WorldOde::distanceConstraints(DistanceConstraints& out) {
    if (xpbdRefusal()) return false;
    const ForceParams& p = m_bodies.front()->forces().params;
    const bool springs = m_bodies.front()->forces().terms().has(Term::Springs);
    for (int f = 0; f < kSpringFamilyCount; ++f) {
        const auto k = static_cast<std::size_t>(f);
        const SpringSet& set = m_springs[k];
        out.families[k] = {set.a, set.b, set.rest, springs ? p.stiffness[k] : 0.0, springs ? p.damping[k] : 0.0};
    }
    out.inverseMass = &m_invMass3;
    out.substeps = m_substeps;
    return true;
}

bool WorldOde::stronglyNonlinear(double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& v1) {
    bool strongly = false;
    for (auto& b : m_bodies) {
        const Eigen::Index nb = 3 * Eigen::Index{b->count()}, at = 3 * Eigen::Index{b->first()};
        auto& s = b->scratch();
        s[0] = v1.segment(at, nb);
        strongly = b->ode().stronglyNonlinear(h, b->gather(y0, m_n), s[0]) || strongly;
    }
    if (strongly) return true;
    // A pair within the skin at the start or at the end the candidate velocities reach.
    m_shifted.head(m_n) = y0.head(m_n) + h * v1;
    return m_pairs.anyWithin(m_contact.skin, y0.data()) || m_pairs.anyWithin(m_contact.skin, m_shifted.data());
}

int WorldOde::contactVelocities(double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& v1,
                                Eigen::VectorXd& target) {
    int marked = 0;
    for (auto& b : m_bodies) {
        const Eigen::Index nb = 3 * Eigen::Index{b->count()}, at = 3 * Eigen::Index{b->first()};
        auto& s = b->scratch();
        s[0] = v1.segment(at, nb);
        s[1] = target.segment(at, nb);
        marked += b->ode().contactVelocities(h, b->gather(y0, m_n), s[0], s[1]);
        target.segment(at, nb) = s[1];
    }
    return marked;
}

}  // namespace simcore
