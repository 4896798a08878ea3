// The pointer and inspection of a one-body simulation (simulation.h): picking a particle
// (nearest, along a ray), the mouse spring (grab, move, release; its work booked), and the
// forces of the current state (every particle's total, a particle's free-body diagram).
#include "simcore/simulation.h"

#include <limits>

#include "simcore/internal/body_ode.h"

namespace simcore {

void Simulation::currentForces(double* f) const {
    ForceExtras extras;
    m_forces.evaluate(m_y.data(), m_y.data() + m_n, f, extras, false);
}

ForceBreakdown Simulation::forceBreakdown(int particle) const {
    ForceBreakdown out;
    if (m_breakdownForces.size() != m_n) m_breakdownForces.setZero(m_n);
    m_forces.breakdown(particle, m_y.data(), m_y.data() + m_n, m_breakdownForces.data(), out);
    return out;
}

int Simulation::nearestGrabbable(const Eigen::Vector3d& point) const {
    const auto& layers = m_body.topology.layer;
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    const auto x = positions();
    for (int i = 0; i < particleCount(); ++i) {
        if (layers[static_cast<std::size_t>(i)] == Layer::Inner) continue;
        const double d = (x.col(i) - point).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    return best;
}

int Simulation::pickAlongRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                             double maxDistance) const {
    return simcore::pickAlongRay(m_body.topology.layer, positions().data(), origin, direction, maxDistance);
}

void Simulation::grab(int particle, const Eigen::Vector3d& anchor) {
    if (particle < 0 || particle >= particleCount() || m_failure) return;
    // Creating the spring stores energy: that is work done by the pointer.
    const double before = m_diag.pointer;
    m_ode->dropEnd();
    m_restartIntegrator = true;
    m_forces.pointer = PointerSpring{true, particle, anchor};
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

void Simulation::moveAnchor(const Eigen::Vector3d& anchor) {
    if (!m_forces.pointer.active || m_failure) return;
    // The anchor moves between steps; the change in the spring's energy is the pointer's work.
    const double before = m_diag.pointer;
    m_ode->dropEnd();
    m_restartIntegrator = true;
    m_forces.pointer.anchor = anchor;
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

void Simulation::release() {
    if (!m_forces.pointer.active) return;
    const double before = m_diag.pointer;
    m_ode->dropEnd();
    m_restartIntegrator = true;
    m_forces.pointer = PointerSpring{};
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

}  // namespace simcore
