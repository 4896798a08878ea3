// A one-body simulation's exact state for the timeline (simulation.h: SimulationSnapshot,
// Simulation::snapshot, restore): with it restored, the steps that follow are the steps the run
// took, bit for bit.
#include "simcore/simulation.h"

#include <stdexcept>
#include <utility>

#include "simcore/integrator_table.h"
#include "simcore/internal/body_ode.h"

namespace simcore {

std::size_t SimulationSnapshot::bytes() const {
    return sizeof(SimulationSnapshot) + sizeof(double) * std::size_t(y.size() + endDerivative.size()) +
           sizeof(double) * integratorHistory.capacity() + integrator.capacity() +
           (failure ? failure->reason.capacity() : 0);
}

SimulationSnapshot Simulation::snapshot() const {
    SimulationSnapshot s;
    s.params = m_params;
    s.integrator = std::string(m_integrator->name());
    s.options = m_integratorOptions;
    s.integratorHistory = m_integrator->history();
    s.integratorRestorable = m_integrator->restorable();
    s.y = m_y;
    s.endValid = m_ode->endValid();
    if (s.endValid) {
        s.endDerivative = m_ode->endDerivative();
        s.endExtras = m_ode->endExtras();
    }
    s.restartIntegrator = m_restartIntegrator;
    s.diag = m_diag;
    s.timeCarry = m_timeCarry;
    s.failure = m_failure;
    s.hNext = m_hNext;
    s.hTaken = m_hTaken;
    s.energyScale = m_energyScale;
    s.pointer = m_forces.pointer;
    s.counters = m_forces.counters();
    s.jacobianProducts = m_jacobianProducts;
    return s;
}

void Simulation::restore(const SimulationSnapshot& s) {
    if (s.y.size() != m_y.size()) throw std::invalid_argument("the snapshot is of another body");
    // Parameters (live edits only: a shape edit rebuilds the body, and a new run begins).
    m_params = s.params;
    m_p = resolve(m_params);
    applyMasses();
    applyForceParams();
    if (m_integrator->name() != s.integrator) {
        auto next = makeIntegrator(s.integrator);
        if (!next) throw std::invalid_argument("unknown integrator " + quoteShort(s.integrator));
        m_integrator = std::move(next);
        m_integrator->prepare(m_ode->layout());
    }
    setIntegratorOptions(s.options);
    m_integrator->setHistory(s.integratorHistory);
    m_y = s.y;
    m_lastGood = s.y;
    if (s.endValid)
        m_ode->restoreEnd(m_y, s.endDerivative, s.endExtras);
    else
        m_ode->dropEnd();
    // A method whose history cannot be restored starts afresh from this state.
    m_restartIntegrator = s.restartIntegrator || !s.integratorRestorable || !m_integrator->restorable();
    m_diag = s.diag;
    m_timeCarry = s.timeCarry;
    m_failure = s.failure;
    m_hNext = s.hNext;
    m_hTaken = s.hTaken;
    m_energyScale = s.energyScale;
    m_forces.pointer = s.pointer;
    m_forces.setCounters(s.counters);
    m_jacobianProducts = s.jacobianProducts;
}

}  // namespace simcore
