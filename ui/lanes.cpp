#include "ui/lanes.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "simlab/stability.h"
#include "simlab/study.h"

namespace elui {

QString integratorName(const simcore::Simulation& sim) {
    const std::string_view name = sim.integrator().name();
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}

Lanes::List Lanes::build(const simcore::ParameterSet& params, const QStringList& integrators,
                         std::optional<std::string>& error) const {
    List lanes;
    try {
        for (const QString& name : integrators) {
            auto sim = std::make_unique<simcore::Simulation>(params, name.toStdString());
            // All cores but one for the forces: the GUI thread (and a software GL renderer) needs one.
            sim->setThreads(m_threads);
            sim->setIntegratorOptions([&] {
                simcore::IntegratorOptions o = sim->integratorOptions();
                o.stepDoubling = m_stepDoubling;
                o.atol = m_atol;
                o.rtol = m_rtol;
                return o;
            }());
            lanes.push_back(std::move(sim));
        }
    } catch (const std::exception& e) {
        error = e.what();
        return {};
    }
    return lanes;
}

std::vector<const simcore::Simulation*> Lanes::views() const {
    std::vector<const simcore::Simulation*> views;
    for (const auto& sim : m_lanes) views.push_back(sim.get());
    return views;
}

bool Lanes::canStepFloat() const {
    if (!m_floatWanted || m_lanes.size() != 1) return false;
    const simcore::Simulation& sim = *m_lanes.front();
    return !sim.failed() && simcore::floatPathRefusal(sim).empty();
}

void Lanes::dropFloat() {
    m_float.reset();
    m_shadow.reset();
}

void Lanes::startFloat() {
    const simcore::Simulation& sim = *m_lanes.front();
    m_floatBase = sim.diagnostics();
    m_floatFirstStep = sim.stepCount();
    m_float = std::make_unique<simcore::FloatSimulation>(sim);
    m_float->setThreads(m_threads);
    m_shadow.reset();
    if (sim.particleCount() <= kShadowParticles) {
        m_shadow = std::make_unique<simcore::Simulation>(sim.parameters(), sim.integrator().name());
        m_shadow->setThreads(m_threads);
        m_shadow->restore(sim.snapshot());
    }
}

void Lanes::stepFloat() {
    simcore::Simulation& sim = *m_lanes.front();
    if (!m_float) startFloat();
    m_float->step();
    if (m_shadow && !m_shadow->failed()) m_shadow->step();
    // The lane takes the float state; its ledger goes on from where the float run began: the
    // float run's own drift added to the lane's drift then.
    simcore::SimulationSnapshot s = sim.snapshot();
    const Eigen::VectorXd y = m_float->state();
    s.y.head(y.size()) = y;
    const simcore::Diagnostics& f = m_float->diagnostics();
    simcore::Diagnostics d = f;
    const simcore::Diagnostics& b = m_floatBase;
    d.removedDamping = b.removedDamping + f.removedDamping;
    d.removedContact = b.removedContact;
    d.removedCollisions = b.removedCollisions;
    d.workPointer = b.workPointer;
    d.workEdits = b.workEdits;
    d.initialEnergy = b.initialEnergy + (f.initialEnergy - b.total());
    d.forceEvaluations = b.forceEvaluations + f.forceEvaluations;
    d.restVolume = b.restVolume;
    s.y[y.size()] = d.removedDamping;  // the aux values after x and v, as the lane keeps them
    s.diag = d;
    s.endValid = false;
    s.restartIntegrator = true;
    s.failure = m_float->failure();
    sim.restore(s);
}

double Lanes::floatDistance() const {
    if (!m_float || !m_shadow || m_lanes.empty()) return -1.0;
    const auto x = m_lanes.front()->positions();
    return std::sqrt((x - m_shadow->positions()).colwise().squaredNorm().mean());
}

double Lanes::floatRoundoff() const {
    if (!m_float || m_lanes.empty()) return 0.0;
    const simcore::Simulation& sim = *m_lanes.front();
    const double steps = static_cast<double>(sim.stepCount() - m_floatFirstStep);
    const double dt = sim.params().time.dt;
    return simlab::roundoffFloor("float", sim.positions().cwiseAbs().maxCoeff(), steps * dt, dt);
}

void Lanes::stepAll(double until) {
    if (canStepFloat()) {
        stepFloat();
        m_commonTime = m_lanes.front()->time();
        return;
    }
    dropFloat();  // a held particle, side by side, or double: the float run starts afresh later
    if (m_lanes.size() == 1) {
        simcore::Simulation& sim = *m_lanes.front();
        sim.step(until >= 0.0 ? until : std::numeric_limits<double>::infinity());
        m_commonTime = sim.time();
    } else {
        m_commonTime = advanceSideBySide(m_lanes, m_commonTime, m_lanes.front()->params().time.dt, until);
    }
}

bool Lanes::allFailed() const {
    return std::all_of(m_lanes.begin(), m_lanes.end(), [](const auto& s) { return s->failed(); });
}

bool Lanes::restorable() const {
    return std::all_of(m_lanes.begin(), m_lanes.end(), [](const auto& s) { return s->integrator().restorable(); });
}

void Lanes::reset() {
    dropFloat();
    for (auto& sim : m_lanes) sim->reset();
}

void Lanes::restore(const simcore::TimelineCheckpoint& c) {
    dropFloat();
    for (std::size_t i = 0; i < m_lanes.size() && i < c.lanes.size(); ++i) m_lanes[i]->restore(c.lanes[i]);
}

std::optional<std::string> Lanes::trySetParameter(simcore::Param id, double value) {
    dropFloat();
    for (std::size_t i = 0; i < m_lanes.size(); ++i)
        if (auto error = m_lanes[i]->setParameter(id, value))
            if (i == 0) return error;
    return std::nullopt;
}

void Lanes::setParameter(simcore::Param id, double value) {
    dropFloat();
    for (auto& sim : m_lanes) sim->setParameter(id, value);
}

void Lanes::setTolerances(double atol, double rtol) {
    dropFloat();
    m_atol = atol;
    m_rtol = rtol;
    for (auto& sim : m_lanes) {
        simcore::IntegratorOptions o = sim->integratorOptions();
        o.atol = m_atol;
        o.rtol = m_rtol;
        sim->setIntegratorOptions(o);
    }
}

void Lanes::setStepDoubling(bool on) {
    dropFloat();
    m_stepDoubling = on;
    for (auto& sim : m_lanes) {
        simcore::IntegratorOptions o = sim->integratorOptions();
        o.stepDoubling = m_stepDoubling;
        sim->setIntegratorOptions(o);
    }
}

void Lanes::grab(int particle, const Eigen::Vector3d& anchor) {
    dropFloat();
    for (auto& sim : m_lanes) sim->grab(particle, anchor);
}

void Lanes::moveAnchor(const Eigen::Vector3d& anchor) {
    dropFloat();
    for (auto& sim : m_lanes) sim->moveAnchor(anchor);
}

void Lanes::release() {
    dropFloat();
    for (auto& sim : m_lanes) sim->release();
}

void Lanes::applyKick() {
    if (m_kickInner == 0.0 && m_kickOuter == 0.0) return;
    dropFloat();
    for (auto& sim : m_lanes) {
        const Eigen::Matrix3Xd x = sim->positions();
        Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, x.cols());
        const auto& layer = sim->topology().layer;
        for (Eigen::Index i = 0; i < x.cols(); ++i) {
            const auto l = layer[static_cast<std::size_t>(i)];
            v(0, i) = l == simcore::Layer::Inner ? m_kickInner
                      : l == simcore::Layer::Outer ? m_kickOuter : 0.0;
        }
        sim->setState(x, v);
    }
}

std::vector<LaneFrame> Lanes::laneFrames(bool forces, int selected) const {
    std::vector<LaneFrame> frames;
    std::size_t reference = 0;
    while (reference + 1 < m_lanes.size() && m_lanes[reference]->failed()) ++reference;
    const auto x0 = m_lanes[reference]->positions();
    for (const auto& sim : m_lanes) {
        LaneFrame lane;
        lane.integrator = integratorName(*sim);
        const auto x = sim->positions();
        lane.positions.resize(std::size_t(x.size()));
        for (Eigen::Index k = 0; k < x.size(); ++k) lane.positions[std::size_t(k)] = float(x.data()[k]);
        const auto v = sim->velocities();
        lane.velocities.resize(std::size_t(v.size()));
        for (Eigen::Index k = 0; k < v.size(); ++k) lane.velocities[std::size_t(k)] = float(v.data()[k]);
        lane.body = measureBody(*sim);
        if (forces) {
            // Not counted as one of the run's force evaluations.
            std::vector<double> f(std::size_t(x.size()));
            sim->currentForces(f.data());
            lane.forces.assign(f.begin(), f.end());
        }
        lane.diagnostics = sim->diagnostics();
        lane.failure = sim->failure();
        lane.pointer = sim->pointer();
        // Nine uncounted force evaluations (ForceModel::breakdown), only while one is selected.
        if (selected >= 0 && selected < sim->particleCount()) lane.breakdown = sim->forceBreakdown(selected);
        lane.divergence = std::sqrt((x - x0).colwise().squaredNorm().mean());
        lane.divergenceReference = int(reference);
        frames.push_back(std::move(lane));
    }
    return frames;
}

}  // namespace elui
