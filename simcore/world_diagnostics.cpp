// What a world measures (world.h): the diagnostics of a state per body and in total, the
// checks a step's end state must pass (fastest speed, a layer collapsed or inside out), and
// the energy error band of the last step's error estimate.
#include "simcore/world.h"

#include <algorithm>
#include <cmath>

#include "simcore/failure_texts.h"
#include "simcore/internal/world_body.h"
#include "simcore/internal/world_ode.h"

namespace simcore {

double World::energyErrorBand() {
    if (!m_lastError || m_failure) return -1.0;
    WorldDiagnostics at, off;
    measure(at);
    m_errorScratch = m_y;
    m_y += Eigen::Map<const Eigen::VectorXd>(m_lastError, m_y.size());
    measure(off);
    m_y = m_errorScratch;  // exactly the state it was (m_y keeps its buffer)
    const double band = std::abs(off.total() - at.total());
    return std::isfinite(band) ? band : -1.0;
}

void World::measure(WorldDiagnostics& d) {
    const double* x = m_y.data();
    const double* v = m_y.data() + m_n;
    d.bodies.resize(m_bodies.size());
    d.kinetic = d.gravity = d.gas = d.contact = d.pointer = 0.0;
    d.spring = {};
    d.momentum.setZero();
    d.angularMomentum.setZero();
    // One uncounted evaluation of the world: the bodies' energies and volumes, the pairs' energy.
    m_ode->compute(m_y, m_rate, false);
    for (std::size_t k = 0; k < m_bodies.size(); ++k) {
        WorldBody& b = *m_bodies[k];
        BodyDiagnostics& out = d.bodies[k];
        const ForceExtras& extras = m_ode->extras()[k];
        for (std::size_t f = 0; f < 3; ++f) d.spring[f] += extras.springEnergy[f];
        d.contact += extras.contactEnergy;
        const bool gas = b.forces().terms().has(Term::Gas);
        out.volume = out.restVolume = out.pressure = {};
        if (gas)
            for (const Surface& s : b.body().topology.surfaces) {
                const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
                out.volume[slot] = extras.volume[slot];
                out.restVolume[slot] = s.restVolume;
                out.pressure[slot] = extras.pressure[slot];
                d.gas += gasEnergy(b.forces().params.gasConstant[slot], extras.volume[slot]);
            }
        const double g = b.forces().terms().has(Term::Gravity) ? b.forces().params.gravity : 0.0;
        Eigen::Vector3d moment = Eigen::Vector3d::Zero(), momentum = Eigen::Vector3d::Zero();
        double mass = 0.0, kinetic = 0.0;
        for (int i = 0; i < b.count(); ++i) {
            if (b.body().fixed[static_cast<std::size_t>(i)]) continue;
            const int w = b.first() + i;
            const double m = b.body().mass[i];
            const Eigen::Map<const Eigen::Vector3d> xi(x + 3 * w), vi(v + 3 * w);
            mass += m;
            moment += m * xi;
            momentum += m * vi;
            kinetic += 0.5 * m * vi.squaredNorm();
            d.gravity += m * g * xi.y();
            d.angularMomentum += xi.cross(m * vi);
        }
        out.mass = mass;
        out.kinetic = kinetic;
        out.com = mass > 0.0 ? Eigen::Vector3d(moment / mass) : Eigen::Vector3d::Zero();
        out.velocity = mass > 0.0 ? Eigen::Vector3d(momentum / mass) : Eigen::Vector3d::Zero();
        d.kinetic += kinetic;
        d.momentum += momentum;
        const PointerSpring& pointer = b.forces().pointer;
        if (pointer.active)
            d.pointer += pointerEnergy(pointer, b.forces().params.mks, b.forces().params.mouseRest, x + 3 * b.first());
    }
    d.contactPairs = m_ode->pairSums().energy;
    d.contact += d.contactPairs;
    const GapReport gap = m_pairs.minimumGap(x, m_contact.skin, gapRange());
    d.minGap = std::min(gap.gap, gapRange());
    d.minGapBodies = gap.gap < gapRange() ? std::array<int, 2>{gap.bodyA, gap.bodyB} : std::array<int, 2>{-1, -1};
    d.removedDamping = m_y[2 * m_n];
    d.removedContact = m_y[2 * m_n + 1];
    d.forceEvaluations = m_bodies.front()->forces().forceEvaluations();
    d.contactPairsActive = m_ode->pairSums().pairs;
}

double World::fastestSpeed() const {
    double fastest = 0.0;
    for (Eigen::Index i = 0; i < m_n / 3; ++i) fastest = std::max(fastest, m_y.segment(m_n + 3 * i, 3).norm());
    return fastest;
}

std::optional<std::string> World::endFailure(const WorldDiagnostics& next, double h) const {
    // Checks: speed, then the shapes.
    const double fastest = fastestSpeed();
    if (fastest * h > 2.0 * m_box || !std::isfinite(next.total())) return failure_text::runawayVelocity(fastest);
    for (std::size_t k = 0; k < m_bodies.size(); ++k)
        for (const Surface& s : m_bodies[k]->body().topology.surfaces) {
            const double volume = next.bodies[k].volume[static_cast<std::size_t>(layerSlot(s.layer))];
            if (volume <= 0.01 * s.restVolume)
                return failure_text::layerLost(k + 1, s.layer, m_dimension, volume, s.restVolume);
        }
    return std::nullopt;
}

}  // namespace simcore
