// A world's exact state for the timeline (world.h: WorldSnapshot, World::snapshot, restore):
// with it restored, the steps that follow are the steps the run took, bit for bit.
#include "simcore/world.h"

#include <stdexcept>

#include "simcore/internal/world_body.h"
#include "simcore/internal/world_ode.h"

namespace simcore {

std::size_t WorldSnapshot::bytes() const {
    return sizeof(WorldSnapshot) + sizeof(double) * (std::size_t(y.size()) + integratorHistory.capacity()) +
           sizeof(BodyDiagnostics) * diag.bodies.capacity() + sizeof(ForceModel::Counters) * counters.capacity() +
           integrator.capacity() + (failure ? failure->capacity() : 0);
}

WorldSnapshot World::snapshot() const {
    WorldSnapshot s;
    s.spec = m_spec;
    s.integrator = std::string(m_integrator->name());
    s.options = m_options;
    s.integratorHistory = m_integrator->history();
    s.integratorRestorable = m_integrator->restorable();
    s.y = m_y;
    s.diag = m_diag;
    s.timeCarry = m_timeCarry;
    s.hNext = m_hNext;
    s.failure = m_failure;
    s.failedStep = m_failedStep;
    s.failedTime = m_failedTime;
    s.held = m_held;
    s.anchor = anchor();
    for (const auto& b : m_bodies) s.counters.push_back(b->forces().counters());
    s.jacobianProducts = m_jacobianProducts;
    return s;
}

void World::restore(const WorldSnapshot& s, bool sameSpecOnly) {
    if (sameSpecOnly && s.spec != m_spec) throw std::invalid_argument("the snapshot is of another world");
    if (s.y.size() != m_y.size() || s.counters.size() != m_bodies.size())
        throw std::invalid_argument("the snapshot is of a world of other bodies");
    const bool sameMethod = m_integrator->name() == s.integrator;
    setIntegratorOptions(s.options);
    if (sameMethod) m_integrator->setHistory(s.integratorHistory);
    else m_integrator->prepare(m_ode->layout());
    if (!sameMethod || !s.integratorRestorable || !m_integrator->restorable()) m_integrator->restart();
    m_y = s.y;
    m_lastGood = s.y;
    m_lastError = nullptr;
    m_timeCarry = s.timeCarry;
    m_hNext = sameMethod ? s.hNext : m_dt;
    m_failure = s.failure;
    m_failedStep = s.failedStep;
    m_failedTime = s.failedTime;
    for (std::size_t k = 0; k < m_bodies.size(); ++k) {
        m_bodies[k]->forces().pointer = PointerSpring{};
        m_bodies[k]->forces().setCounters(s.counters[k]);
    }
    m_held = s.held;
    if (m_held >= 0) {
        const int body = bodyOf(m_held);
        m_bodies[static_cast<std::size_t>(body)]->forces().pointer =
            PointerSpring{true, m_held - m_bodies[static_cast<std::size_t>(body)]->first(), s.anchor};
    }
    m_jacobianProducts = s.jacobianProducts;
    m_diag = s.diag;
    if (!sameSpecOnly) {  // this world's values (gravity, gas ...) at the same state
        // What the edit added to the energy (a mass, a gas constant, gravity ...) is the
        // edit's, as one body's W_edits: the drift goes on where it was.
        const double before = m_diag.total();
        measure(m_diag);
        m_diag.initialEnergy += m_diag.total() - before;
        m_diag.forceEvaluations += m_jacobianProducts;
    }
}

}  // namespace simcore
