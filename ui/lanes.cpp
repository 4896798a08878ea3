#include "ui/lanes.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "simlab/stability.h"

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

void Lanes::stepAll(double until) {
    if (m_lanes.size() == 1) {
        simcore::Simulation& sim = *m_lanes.front();
        sim.step(until >= 0.0 ? until : std::numeric_limits<double>::infinity());
        m_commonTime = sim.time();
    } else {
        // Side by side: every live lane reaches the same time after each common DT (the
        // distances between the lanes are measured there). A fixed-step lane takes whole
        // steps, so a run-until target off the DT grid is not shortened to unless every lane
        // can land on it (all adaptive): the common clock then stops on the first tick past it,
        // and the lanes stay together for the rest of the run.
        double target = m_commonTime + m_lanes.front()->params().time.dt;
        const bool allAdaptive = std::all_of(m_lanes.begin(), m_lanes.end(), [](const auto& s) {
            return s->failed() || s->integrator().adaptive();
        });
        if (until >= 0.0 && allAdaptive) target = std::min(target, until);
        for (auto& sim : m_lanes)
            if (!sim->failed()) sim->advanceTo(target);
        m_commonTime = target;
    }
}

bool Lanes::allFailed() const {
    return std::all_of(m_lanes.begin(), m_lanes.end(), [](const auto& s) { return s->failed(); });
}

bool Lanes::restorable() const {
    return std::all_of(m_lanes.begin(), m_lanes.end(), [](const auto& s) { return s->integrator().restorable(); });
}

void Lanes::reset() {
    for (auto& sim : m_lanes) sim->reset();
}

void Lanes::restore(const simcore::TimelineCheckpoint& c) {
    for (std::size_t i = 0; i < m_lanes.size() && i < c.lanes.size(); ++i) m_lanes[i]->restore(c.lanes[i]);
}

std::optional<std::string> Lanes::trySetParameter(simcore::Param id, double value) {
    for (std::size_t i = 0; i < m_lanes.size(); ++i)
        if (auto error = m_lanes[i]->setParameter(id, value))
            if (i == 0) return error;
    return std::nullopt;
}

void Lanes::setParameter(simcore::Param id, double value) {
    for (auto& sim : m_lanes) sim->setParameter(id, value);
}

void Lanes::setTolerances(double atol, double rtol) {
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
    m_stepDoubling = on;
    for (auto& sim : m_lanes) {
        simcore::IntegratorOptions o = sim->integratorOptions();
        o.stepDoubling = m_stepDoubling;
        sim->setIntegratorOptions(o);
    }
}

void Lanes::grab(int particle, const Eigen::Vector3d& anchor) {
    for (auto& sim : m_lanes) sim->grab(particle, anchor);
}

void Lanes::moveAnchor(const Eigen::Vector3d& anchor) {
    for (auto& sim : m_lanes) sim->moveAnchor(anchor);
}

void Lanes::release() {
    for (auto& sim : m_lanes) sim->release();
}

void Lanes::applyKick() {
    if (m_kickInner == 0.0 && m_kickOuter == 0.0) return;
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
