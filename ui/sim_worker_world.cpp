// SimWorker with a scene of several bodies (simcore::World, docs/model.md "Several bodies"): one
// world steps instead of the lanes. What it has: run, pause, step, reset, the pacer's speeds,
// a parameter edit for one body or all (the world is rebuilt with it and goes on from its
// state; a shape or start edit starts it again), an integrator change that keeps the run, the
// mouse on any body's outer particle, frames with every body and rows of the world's totals,
// and the timeline: the world is recorded as the lanes are (checkpoints of WorldSnapshot and
// the log of what was done between steps; a live edit or an integrator change is logged as
// the spec and integrator the world was built again with, so a replay builds it again at the
// same moment); the free-body diagram of a clicked particle (its body's parts and the contact
// from the other bodies and from itself); step doubling and the energy plot's error band.
// What it has not yet (the GUI says so): side by side, the stability map.
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

double SimWorker::leadTime() const {
    if (m_world) return m_world->time();
    return m_lanes.empty() ? 0.0 : m_lanes.front().time();
}

simcore::IntegratorOptions SimWorker::worldOptions() const {
    simcore::IntegratorOptions o;
    o.stepDoubling = m_lanes.stepDoubling();
    o.atol = m_lanes.atol();
    o.rtol = m_lanes.rtol();
    return o;
}

void SimWorker::setWorld(const simcore::WorldSpec& spec, const QString& integrator) {
    if (!buildWorld(std::make_shared<const simcore::WorldSpec>(spec), integrator.toStdString(), nullptr)) return;
    m_worldBody = 0;
    worldSceneData();
    worldStarted();
}

bool SimWorker::buildWorld(std::shared_ptr<const simcore::WorldSpec> spec, const std::string& integrator,
                           const simcore::World* from) {
    std::unique_ptr<simcore::World> world;
    try {
        world = std::make_unique<simcore::World>(std::move(spec), integrator);
    } catch (const std::invalid_argument& e) {
        emit sceneRejected(QString::fromUtf8(e.what()));
        return false;
    }
    world->setIntegratorOptions(worldOptions());
    // The run goes on: state, accounts, pointer and counters (a shape edit starts again instead).
    if (from && from->particleCount() == world->particleCount()) {
        simcore::WorldSnapshot state = from->snapshot();
        state.options = worldOptions();
        world->restore(state, false);
    }
    m_lanes.clear();  // a world runs alone
    m_world = std::move(world);
    m_worldSpec = m_world->sharedSpec();
    m_params = m_world->spec().bodies.front().params;
    return true;
}

void SimWorker::applyWorldInput(const Input& input) {
    switch (input.kind) {
        case Input::World: {
            std::unique_ptr<simcore::World> old = std::move(m_world);
            if (!buildWorld(input.spec, input.key, old.get())) m_world = std::move(old);
            break;
        }
        case Input::StepDoubling:
        case Input::Tolerances: {
            if (input.kind == Input::StepDoubling) m_lanes.setStepDoubling(input.value != 0.0);
            else m_lanes.setTolerances(input.value, input.value2);
            m_world->setIntegratorOptions(worldOptions());
            break;
        }
        case Input::Grab: m_world->grab(input.particle, input.anchor); break;
        case Input::Move: m_world->moveAnchor(input.anchor); break;
        case Input::Release: m_world->release(); break;
        case Input::Until: m_until = input.value; break;
        case Input::Parameter:
        case Input::Integrator: break;  // a world logs these as Input::World
        case Input::Precision: break;   // a world steps in double (the Run dock's Precision is one body's)
    }
}

void SimWorker::restoreWorld(const simcore::TimelineCheckpoint& c) {
    const simcore::WorldSnapshot& s = *c.world;
    if (s.spec != m_world->sharedSpec() || s.integrator != m_world->integrator().name()) {
        std::unique_ptr<simcore::World> old = std::move(m_world);
        if (!buildWorld(s.spec, s.integrator, nullptr)) {
            m_world = std::move(old);
            return;
        }
    }
    m_world->restore(s);
    const simcore::IntegratorOptions& o = s.options;
    m_lanes.setStepDoubling(o.stepDoubling);
    m_lanes.setTolerances(o.atol, o.rtol);
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
    m_worldRows.clear();
    recordWorldRow();
    startTimeline();
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
    auto built = std::make_shared<const simcore::WorldSpec>(std::move(next));
    if (!(spec.isShape() || spec.group == simcore::ParamGroup::Start)) {
        // A live edit: on the timeline, the world built again with it at this moment.
        Input input;
        input.kind = Input::World;
        input.spec = std::move(built);
        input.key = std::string(m_world->integrator().name());
        logInput(std::move(input));
        publish(true);
        return;
    }
    std::unique_ptr<simcore::World> old = std::move(m_world);
    if (!buildWorld(std::move(built), std::string(old->integrator().name()), nullptr)) {
        m_world = std::move(old);
        return;
    }
    worldSceneData();
    worldStarted();
}

bool SimWorker::stepWorld() {
    if (m_world->failed()) return false;
    // A step from a scrubbed moment runs on from it: a branch.
    if (!m_replaying && m_moment < m_recorder.last()) branch();
    const bool ok = m_world->step(m_until >= 0.0 ? m_until : std::numeric_limits<double>::infinity());
    if (!m_replaying) {
        m_pacer.countStep();
        if (ok) {
            simcore::Diagnostics row = totalsRow(m_world->diagnostics());
            // The energy plot's error band (two measurements), only while the plots show it.
            if (m_bandsWanted)
                if (const double band = m_world->energyErrorBand(); band >= 0.0) {
                    row.errors.valid = true;
                    row.errors.energy = band;
                }
            m_publisher.recordRow(row);
            recordWorldRow();
        }
    }
    recordMoment();  // a failed step too: its moment shows the failure, as a lane's
    return ok;
}

void SimWorker::recordWorldRow() {
    const simcore::WorldDiagnostics& d = m_world->diagnostics();
    if (!m_worldRows.empty() && d.time - m_worldRows.back().time < kRowInterval * (1.0 - 1e-9)) return;
    if (m_worldRows.size() >= kMaxWorldRows) {  // every other old row goes, as the plots' history
        std::size_t w = 0;
        for (std::size_t r = 0; r < m_worldRows.size(); r += 2) m_worldRows[w++] = std::move(m_worldRows[r]);
        m_worldRows.resize(w);
    }
    m_worldRows.push_back(d);
}

void SimWorker::cutWorldRows(double time) {
    std::erase_if(m_worldRows, [time](const simcore::WorldDiagnostics& d) { return d.time > time; });
}

std::string SimWorker::worldCsv() const {
    if (!m_world) return {};
    const auto columns = simlab::worldColumns(*m_world);
    std::string text = simlab::csvHeader(columns);
    for (const simcore::WorldDiagnostics& d : m_worldRows) text += simlab::csvRow(columns, d);
    return text;
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
    frame->timeline = timelineInfo();
    frame->physicsChangedAt = physicsChangedAt();
    frame->atol = m_lanes.atol();
    frame->rtol = m_lanes.rtol();
    LaneFrame lane;
    lane.integrator = QString::fromUtf8(w.integrator().name().data(), qsizetype(w.integrator().name().size()));
    const Eigen::Index n = 3 * Eigen::Index{w.particleCount()};
    lane.positions.resize(std::size_t(n));
    for (Eigen::Index k = 0; k < n; ++k) lane.positions[std::size_t(k)] = float(w.state()[k]);
    if (m_forcesWanted) {  // not counted as the run's force evaluations
        std::vector<double> f(static_cast<std::size_t>(n));
        m_world->currentForces(f.data());
        lane.forces.assign(f.begin(), f.end());
    }
    // The free-body diagram of the selected particle: its body's parts and the contacts.
    if (m_selected >= 0 && m_selected < w.particleCount()) lane.breakdown = m_world->forceBreakdown(m_selected);
    lane.diagnostics = totalsRow(w.diagnostics());
    if (w.failed()) lane.failure = simcore::Failure{*w.failure(), w.failedStep(), w.failedTime()};
    if (w.heldParticle() >= 0) lane.pointer = simcore::PointerSpring{true, w.heldParticle(), w.anchor()};
    frame->lanes.push_back(std::move(lane));
    m_publisher.publish(std::move(frame));
}

}  // namespace elui
