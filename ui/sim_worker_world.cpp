// SimWorker with a scene of several bodies (simcore::World, MODEL.md "Several bodies"): one
// world steps instead of the lanes. What it has: run, pause, step, reset, the pacer's speeds,
// a parameter edit for one body or all (the world is rebuilt with it and goes on from its
// state; a shape or start edit starts it again), an integrator change that keeps the run, the
// mouse on any body's outer particle, frames with every body and rows of the world's totals.
// What it has not yet (the GUI says so): side by side, the timeline, the free-body diagram,
// the stability map, step doubling's bands.
#include <algorithm>
#include <cmath>
#include <limits>

#include <QTimer>

#include "simcore/integrator_table.h"
#include "simcore/scenes.h"
#include "simlab/output.h"
#include "ui/sim_worker.h"

namespace elui {

namespace {

// The world's totals in a one-body row: the Plots dock's energy plot and the energy bars read it.
simcore::Diagnostics totalsRow(const simcore::WorldDiagnostics& w) {
    simcore::Diagnostics d;
    d.step = w.step;
    d.time = w.time;
    d.dt = w.dt;
    d.hasGas = true;
    d.kinetic = w.kinetic;
    d.spring = w.spring;
    d.gravity = w.gravity;
    d.gas = w.gas;
    d.pointer = w.pointer;
    d.contact = w.contact;
    d.removedDamping = w.removedDamping;
    d.removedContact = w.removedContact;
    d.workPointer = w.workPointer;
    d.initialEnergy = w.initialEnergy;
    d.errorEstimate = w.errorEstimate;
    d.forceEvaluations = w.forceEvaluations;
    // Per body, not per world: the Bodies dock plots each body's volume and pressure.
    d.volume = d.restVolume = d.pressure = {std::nan(""), std::nan("")};
    return d;
}

}  // namespace

void SimWorker::setWorld(const simcore::WorldSpec& spec, const QString& integrator) {
    if (!buildWorld(spec, integrator.toStdString(), nullptr)) return;
    m_worldBody = 0;
    worldSceneData();
    worldStarted();
}

bool SimWorker::buildWorld(const simcore::WorldSpec& spec, const std::string& integrator, const simcore::World* from) {
    std::unique_ptr<simcore::World> world;
    try {
        world = std::make_unique<simcore::World>(spec, integrator);
    } catch (const std::invalid_argument& e) {
        emit sceneRejected(QString::fromUtf8(e.what()));
        return false;
    }
    world->setIntegratorOptions(simcore::IntegratorOptions{});
    if (from && from->particleCount() == world->particleCount()) {
        const auto n = Eigen::Index{from->particleCount()};
        world->setState(Eigen::Map<const Eigen::Matrix3Xd>(from->state().data(), 3, n),
                        Eigen::Map<const Eigen::Matrix3Xd>(from->state().data() + 3 * n, 3, n), from->stepCount(),
                        from->time());
        if (from->heldParticle() >= 0) world->grab(from->heldParticle(), from->anchor());
    }
    m_lanes.clear();  // a world runs alone
    m_recorder.clear();
    m_inputs.clear();
    m_world = std::move(world);
    m_worldSpec = std::make_shared<const simcore::WorldSpec>(m_world->spec());
    m_params = m_world->spec().bodies.front().params;
    return true;
}

void SimWorker::worldSceneData() {
    auto scene = std::make_shared<SceneData>();
    scene->version = ++m_sceneVersion;
    m_selected = -1;
    const simcore::World& w = *m_world;
    scene->kind = w.spec().bodies.front().params.kind();
    scene->worldName = QString::fromStdString(w.spec().name);
    simcore::Topology& all = scene->topology;
    all.dimension = w.dimension();
    for (int k = 0; k < w.bodyCount(); ++k) {
        const simcore::Topology& t = w.body(k).topology;
        const int at = w.firstParticle(k);
        scene->bodies.push_back({at, t.particleCount(), w.spec().bodies[std::size_t(k)].params.kind()});
        all.layer.insert(all.layer.end(), t.layer.begin(), t.layer.end());
        for (std::size_t f = 0; f < all.springs.size(); ++f) {
            const simcore::SpringSet& from = t.springs[f];
            simcore::SpringSet& to = all.springs[f];
            for (std::size_t s = 0; s < from.size(); ++s) to.add(from.a[s] + at, from.b[s] + at, from.rest[s]);
        }
        for (simcore::Surface s : t.surfaces) {
            for (auto& e : s.edges) e = {e[0] + at, e[1] + at};
            for (auto& tri : s.triangles) tri = {tri[0] + at, tri[1] + at, tri[2] + at};
            all.surfaces.push_back(std::move(s));
        }
        for (const auto& p : t.layerPairs) all.layerPairs.push_back({p[0] + at, p[1] + at});
        for (const auto& tri : t.fillTriangles) all.fillTriangles.push_back({tri[0] + at, tri[1] + at, tri[2] + at});
    }
    scene->boxHalfSize = w.boxHalfSize();
    const auto x = Eigen::Map<const Eigen::Matrix3Xd>(w.state().data(), 3, w.particleCount());
    const Eigen::Vector3d centre = x.rowwise().mean();
    double radius = 0.0;
    for (Eigen::Index i = 0; i < x.cols(); ++i) radius = std::max(radius, (x.col(i) - centre).norm());
    scene->bodyRadius = std::max(radius, 0.5);
    QStringList values;
    for (int k = 0; k < w.bodyCount(); ++k) {
        const simcore::ParameterSet& p = w.spec().bodies[std::size_t(k)].params;
        values << QStringLiteral("body%1 (%2):\n%3")
                      .arg(k + 1)
                      .arg(QString::fromUtf8(simcore::sceneInfo(p.kind()).name.data()))
                      .arg(QString::fromStdString(simcore::bodyValuesText(p, simcore::bodyValues(p, w.body(k)))));
    }
    scene->bodyValues = values.join(QStringLiteral("\n\n"));
    m_scene = std::move(scene);
}

void SimWorker::worldStarted() {
    m_until = -1.0;
    m_pacer.startOver(m_world->time());
    m_failureReported = false;
    m_publisher.startHistory();
    m_publisher.recordRow(totalsRow(m_world->diagnostics()));
    publish(true);
}

void SimWorker::setWorldBody(int body) {
    if (!worldMode()) return;
    m_worldBody = std::clamp(body, -1, m_world->bodyCount() - 1);
    publish(true);
}

void SimWorker::setWorldParameter(simcore::Param id, double value) {
    const simcore::ParamSpec& spec = simcore::paramSpec(id);
    const QString key = QString::fromUtf8(spec.key.data(), qsizetype(spec.key.size()));
    simcore::WorldSpec next = m_world->spec();
    // A world parameter is every body's; a body parameter goes to the chosen body (or all).
    const bool all = simcore::isWorldParameter(id) || m_worldBody < 0;
    const std::string assignment = (all ? std::string() : "body" + std::to_string(m_worldBody + 1) + ".") +
                                   std::string(spec.key) + "=" + simlab::formatDouble(value);
    std::optional<std::string> error = simcore::assignWorld(next, assignment);
    if (!error) error = simcore::validateWorld(next);
    if (error) {
        emit parameterRejected(key, QString::fromStdString(*error));
        publish(true);
        return;
    }
    const bool restart = spec.isShape() || spec.group == simcore::ParamGroup::Start;
    std::unique_ptr<simcore::World> old = std::move(m_world);
    if (!buildWorld(next, std::string(old->integrator().name()), restart ? nullptr : old.get())) {
        m_world = std::move(old);
        return;
    }
    if (restart) {
        worldSceneData();
        worldStarted();
    } else {
        publish(true);
    }
}

bool SimWorker::stepWorld() {
    if (m_world->failed()) return false;
    const bool ok = m_world->step(m_until >= 0.0 ? m_until : std::numeric_limits<double>::infinity());
    m_pacer.countStep();
    if (ok) m_publisher.recordRow(totalsRow(m_world->diagnostics()));
    return ok;
}

void SimWorker::tickWorld() {
    const double target = m_pacer.beginTick(m_until >= 0.0);
    bool outOfBudget = false;
    while (m_world->time() < target) {
        if (m_until >= 0.0 && m_world->time() >= m_until - 1e-12) break;
        if (!stepWorld()) break;
        if (m_pacer.budgetSpent()) {
            outOfBudget = true;
            break;
        }
    }
    m_pacer.endTick(m_world->time(), outOfBudget);
    if (m_world->failed()) {
        pause();
        if (!m_failureReported) {
            m_failureReported = true;
            emit runFailed(QString::fromStdString(*m_world->failure()));
        }
        return;
    }
    if (m_until >= 0.0 && m_world->time() >= m_until - 1e-12) {
        const double reached = m_world->time();
        pause();
        emit reachedTime(reached);
        return;
    }
    publish(false);
}

void SimWorker::publishWorld() {
    auto frame = std::make_shared<Frame>();
    const simcore::World& w = *m_world;
    frame->scene = m_scene;
    frame->worldBody = m_worldBody;
    frame->worldSpec = m_worldSpec;
    frame->parameters = w.spec().bodies[std::size_t(std::max(m_worldBody, 0))].params;
    frame->running = m_pacer.running();
    frame->speed = m_pacer.speed();
    frame->wallSeconds = m_pacer.wallSeconds();
    frame->stepsPerSecond = m_pacer.stepsPerSecond();
    frame->fallingBehind = m_pacer.fallingBehind();
    frame->world = std::make_shared<const simcore::WorldDiagnostics>(w.diagnostics());
    LaneFrame lane;
    lane.integrator = QString::fromUtf8(w.integrator().name().data(), qsizetype(w.integrator().name().size()));
    const Eigen::Index n = 3 * Eigen::Index{w.particleCount()};
    lane.positions.resize(std::size_t(n));
    for (Eigen::Index k = 0; k < n; ++k) lane.positions[std::size_t(k)] = float(w.state()[k]);
    lane.diagnostics = totalsRow(w.diagnostics());
    if (w.failed()) lane.failure = simcore::Failure{*w.failure(), w.failedStep(), w.failedTime()};
    if (w.heldParticle() >= 0) lane.pointer = simcore::PointerSpring{true, w.heldParticle(), w.anchor()};
    frame->lanes.push_back(std::move(lane));
    m_publisher.publish(std::move(frame));
}

}  // namespace elui
