// The world's pointer and inspection (world.h): picking a particle of any body along a ray,
// the mouse spring (grab, move, release; its work booked), and the forces of the current state
// (a particle's free-body diagram, every particle's total force).
#include "simcore/world.h"

#include "simcore/internal/world_body.h"
#include "simcore/internal/world_ode.h"

namespace simcore {

int World::pickAlongRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double maxDistance) const {
    return simcore::pickAlongRay(m_layers, m_y.data(), origin, direction, maxDistance);
}

Eigen::Vector3d World::anchor() const {
    if (m_held < 0) return Eigen::Vector3d::Zero();
    return m_bodies[static_cast<std::size_t>(bodyOf(m_held))]->forces().pointer.anchor;
}

// The pointer spring of body k becomes `pointer`: the change of its energy is the pointer's
// work (as Simulation::grab); the method restarts (the force changed between steps).
void World::pointerChanged(const PointerSpring& pointer, int body) {
    if (m_failure) return;
    const double before = m_diag.pointer;
    m_bodies[static_cast<std::size_t>(body)]->forces().pointer = pointer;
    m_integrator->restart();
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

void World::grab(int particle, const Eigen::Vector3d& anchor) {
    const int body = bodyOf(particle);
    if (body < 0 || m_failure) return;
    if (m_held >= 0) release();
    pointerChanged(PointerSpring{true, particle - m_bodies[static_cast<std::size_t>(body)]->first(), anchor}, body);
    m_held = particle;
}

void World::moveAnchor(const Eigen::Vector3d& anchor) {
    if (m_held < 0) return;
    const int body = bodyOf(m_held);
    PointerSpring pointer = m_bodies[static_cast<std::size_t>(body)]->forces().pointer;
    pointer.anchor = anchor;
    pointerChanged(pointer, body);
}

void World::release() {
    if (m_held < 0) return;
    const int body = bodyOf(m_held);
    m_held = -1;
    pointerChanged(PointerSpring{}, body);
}

ForceBreakdown World::forceBreakdown(int particle) {
    ForceBreakdown out;
    const int k = bodyOf(particle);
    if (k < 0) return out;
    WorldBody& b = *m_bodies[static_cast<std::size_t>(k)];
    const Eigen::Index at = 3 * Eigen::Index{b.first()};
    m_breakdownScratch.setZero(m_n);
    b.forces().breakdown(particle - b.first(), m_y.data() + at, m_y.data() + m_n + at, m_breakdownScratch.data(), out);
    out.particle = particle;
    // The pairs' parts, as WorldOde adds them to the bodies' forces.
    auto pairs = [&](ForcePart part, ContactPairs::Which which) {
        m_breakdownScratch.setZero(m_n);
        m_pairs.addForces(m_contact, m_y.data(), m_y.data() + m_n, m_breakdownScratch.data(), which);
        out[part] = m_breakdownScratch.segment<3>(3 * Eigen::Index{particle});
        out.present[static_cast<std::size_t>(part)] = true;
        out.total += out[part];
    };
    if (bodyCount() > 1) pairs(ForcePart::BodyContact, ContactPairs::Which::BetweenBodies);
    pairs(ForcePart::SelfContact, ContactPairs::Which::Self);
    return out;
}

void World::currentForces(double* f) {
    Eigen::VectorXd rate(m_y.size());
    m_ode->compute(m_y, rate, false);
    const Eigen::VectorXd& mass = m_ode->coordinateMass();
    for (Eigen::Index k = 0; k < m_n; ++k) f[k] = mass.size() == m_n ? mass[k] * rate[m_n + k] : 0.0;
}

}  // namespace simcore
