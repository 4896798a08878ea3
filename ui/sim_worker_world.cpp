// SimWorker with a scene of several bodies (simcore::World, docs/model.md "Several bodies"): a
// world steps instead of each one-body lane. What it has: run, pause, step, reset, the pacer's speeds,
// a parameter edit for one body or all (the world is rebuilt with it and goes on from its
// state; a shape or start edit starts it again), an integrator change that keeps the run, the
// mouse on any body's outer particle, frames with every body and rows of the world's totals,
// and the timeline: the world is recorded as the lanes are (checkpoints of WorldSnapshot and
// the log of what was done between steps; a live edit or an integrator change is logged as
// the spec and integrator the world was built again with, so a replay builds it again at the
// same moment); the free-body diagram of a clicked particle (its body's parts and the contact
// from the other bodies and from itself); step doubling and the energy plot's error band.
// Side by side: up to three worlds of one spec, one per integrator (the lanes of a world), stepped
// to a common time as the one-body lanes are; every command above goes to each of them, a lane
// that fails stops alone and the others run on.
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
    if (worldMode()) return m_worldTime;
    return m_lanes.empty() ? 0.0 : m_lanes.front().time();
}

simcore::IntegratorOptions SimWorker::worldOptions() const {
    simcore::IntegratorOptions o;
    o.stepDoubling = m_lanes.stepDoubling();
    o.atol = m_lanes.atol();
    o.rtol = m_lanes.rtol();
    return o;
}

std::vector<const simcore::World*> SimWorker::worldViews() const {
    std::vector<const simcore::World*> views;
    for (const auto& w : m_worlds) views.push_back(w.get());
    return views;
}

std::vector<std::string> SimWorker::worldIntegrators() const {
    std::vector<std::string> names;
    for (const auto& w : m_worlds) names.emplace_back(w->integrator().name());
    return names;
}

bool SimWorker::worldsStopped() const {
    return std::all_of(m_worlds.begin(), m_worlds.end(), [](const auto& w) { return w->failed(); });
}

bool SimWorker::worldsRestorable() const {
    return std::all_of(m_worlds.begin(), m_worlds.end(), [](const auto& w) { return w->integrator().restorable(); });
}

void SimWorker::setWorld(const simcore::WorldSpec& spec, const QStringList& integrators) {
    std::vector<std::string> names;
    for (const QString& name : integrators) names.push_back(name.toStdString());
    if (!buildWorlds(std::make_shared<const simcore::WorldSpec>(spec), names, nullptr)) return;
    m_worldBody = 0;
    worldSceneData();
    worldStarted();
}

bool SimWorker::buildWorlds(std::shared_ptr<const simcore::WorldSpec> spec, const std::vector<std::string>& integrators,
                            const std::vector<std::unique_ptr<simcore::World>>* from) {
    std::vector<std::unique_ptr<simcore::World>> worlds;
    try {
        for (const std::string& name : integrators) worlds.push_back(std::make_unique<simcore::World>(spec, name));
    } catch (const std::invalid_argument& e) {
        emit sceneRejected(QString::fromUtf8(e.what()));
        return false;
    }
    if (worlds.empty()) return false;
    for (std::size_t i = 0; i < worlds.size(); ++i) {
        simcore::World& world = *worlds[i];
        world.setIntegratorOptions(worldOptions());
        // The run goes on: state, accounts, pointer and counters (a shape edit starts again instead).
        if (from && i < from->size() && (*from)[i]->particleCount() == world.particleCount()) {
            simcore::WorldSnapshot state = (*from)[i]->snapshot();
            state.options = worldOptions();
            world.restore(state, false);
        }
    }
    m_lanes.clear();  // worlds run instead of the one-body lanes
    m_worlds = std::move(worlds);
    m_worldSpec = world().sharedSpec();
    m_params = world().spec().bodies.front().params;
    return true;
}

void SimWorker::applyWorldInput(const Input& input) {
    switch (input.kind) {
        case Input::World: {
            std::vector<std::unique_ptr<simcore::World>> old = std::move(m_worlds);
            if (!buildWorlds(input.spec, input.integrators, &old)) m_worlds = std::move(old);
            break;
        }
        case Input::StepDoubling:
        case Input::Tolerances: {
            if (input.kind == Input::StepDoubling) m_lanes.setStepDoubling(input.value != 0.0);
            else m_lanes.setTolerances(input.value, input.value2);
            for (auto& w : m_worlds) w->setIntegratorOptions(worldOptions());
            break;
        }
        case Input::Grab:
            for (auto& w : m_worlds) w->grab(input.particle, input.anchor);
            break;
        case Input::Move:
            for (auto& w : m_worlds) w->moveAnchor(input.anchor);
            break;
        case Input::Release:
            for (auto& w : m_worlds) w->release();
            break;
        case Input::Until: m_until = input.value; break;
        case Input::Parameter:
        case Input::Integrator: break;  // a world logs these as Input::World
        case Input::Precision: break;   // a world steps in double (the Run dock's Precision is one body's)
    }
}

void SimWorker::restoreWorld(const simcore::TimelineCheckpoint& c) {
    // Built again when the lanes held another spec or integrator at that moment.
    bool same = c.worlds.size() == m_worlds.size();
    for (std::size_t i = 0; same && i < c.worlds.size(); ++i)
        same = c.worlds[i].spec == m_worlds[i]->sharedSpec() && c.worlds[i].integrator == m_worlds[i]->integrator().name();
    if (!same) {
        std::vector<std::string> names;
        for (const simcore::WorldSnapshot& s : c.worlds) names.push_back(s.integrator);
        std::vector<std::unique_ptr<simcore::World>> old = std::move(m_worlds);
        if (!buildWorlds(c.worlds.front().spec, names, nullptr)) {
            m_worlds = std::move(old);
            return;
        }
    }
    for (std::size_t i = 0; i < c.worlds.size(); ++i) m_worlds[i]->restore(c.worlds[i]);
    m_worldTime = c.extra.at(0);
    const simcore::IntegratorOptions& o = c.worlds.front().options;
    m_lanes.setStepDoubling(o.stepDoubling);
    m_lanes.setTolerances(o.atol, o.rtol);
}

void SimWorker::worldSceneData() {
    auto scene = std::make_shared<SceneData>();
    scene->version = ++m_sceneVersion;
    m_selected = -1;
    const simcore::World& w = world();
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
    m_worldTime = world().time();
    m_pacer.startOver(m_worldTime);
    m_failureReported = false;
    m_publisher.startHistory();
    m_publisher.recordRow(totalsRow(world().diagnostics()));
    m_worldRows.clear();
    recordWorldRow();
    recordWorldLaneRows();
    startTimeline();
    publish(true);
}

void SimWorker::setWorldBody(int body) {
    if (!worldMode()) return;
    m_worldBody = std::clamp(body, -1, world().bodyCount() - 1);
    publish(true);
}

void SimWorker::setWorldParameter(simcore::Param id, double value) {
    const simcore::ParamSpec& spec = simcore::paramSpec(id);
    const QString key = QString::fromUtf8(spec.key.data(), qsizetype(spec.key.size()));
    simcore::WorldSpec next = world().spec();
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
        // A live edit: on the timeline, every lane's world built again with it at this moment.
        Input input;
        input.kind = Input::World;
        input.spec = std::move(built);
        input.integrators = worldIntegrators();
        logInput(std::move(input));
        publish(true);
        return;
    }
    std::vector<std::unique_ptr<simcore::World>> old = std::move(m_worlds);
    if (!buildWorlds(std::move(built), [&] {
            std::vector<std::string> names;
            for (const auto& w : old) names.emplace_back(w->integrator().name());
            return names;
        }(), nullptr)) {
        m_worlds = std::move(old);
        return;
    }
    worldSceneData();
    worldStarted();
}

bool SimWorker::stepWorld() {
    if (worldsStopped()) return false;
    // A step from a scrubbed moment runs on from it: a branch.
    if (!m_replaying && m_moment < m_recorder.last()) branch();
    if (m_worlds.size() == 1) {
        world().step(m_until >= 0.0 ? m_until : std::numeric_limits<double>::infinity());
        m_worldTime = world().time();
    } else {
        m_worldTime = advanceSideBySide(m_worlds, m_worldTime, world().dt(), m_until);  // as the one-body lanes
    }
    if (!m_replaying) {
        m_pacer.countStep();
        if (!world().failed()) {
            simcore::Diagnostics row = totalsRow(world().diagnostics());
            // The energy plot's error band (two measurements), only while the plots show it.
            if (m_bandsWanted)
                if (const double band = world().energyErrorBand(); band >= 0.0) {
                    row.errors.valid = true;
                    row.errors.energy = band;
                }
            m_publisher.recordRow(row);
            recordWorldRow();
        }
        recordWorldLaneRows();
    }
    recordMoment();  // a failed step too: its moment shows the failure, as a lane's
    return true;
}

void SimWorker::recordWorldLaneRows() {
    if (m_worlds.size() < 2) return;
    std::vector<simcore::Diagnostics> rows;
    rows.reserve(m_worlds.size());
    for (const auto& w : m_worlds) rows.push_back(totalsRow(w->diagnostics()));
    std::vector<const simcore::Diagnostics*> live;
    for (std::size_t i = 0; i < rows.size(); ++i) live.push_back(m_worlds[i]->failed() ? nullptr : &rows[i]);
    m_publisher.recordLaneRows(live, m_worldTime);
}

void SimWorker::recordWorldRow() {
    const simcore::WorldDiagnostics& d = world().diagnostics();
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
    if (!worldMode()) return {};
    const auto columns = simlab::worldColumns(*m_worlds.front());
    std::string text = simlab::csvHeader(columns);
    for (const simcore::WorldDiagnostics& d : m_worldRows) text += simlab::csvRow(columns, d);
    return text;
}

void SimWorker::tickWorld() {
    const double target = m_pacer.beginTick(m_until >= 0.0);
    bool outOfBudget = false;
    while (m_worldTime < target) {
        if (m_until >= 0.0 && m_worldTime >= m_until - 1e-12) break;
        if (!stepWorld()) break;
        if (m_pacer.budgetSpent()) {
            outOfBudget = true;
            break;
        }
        if (worldsStopped()) break;
    }
    m_pacer.endTick(m_worldTime, outOfBudget);
    if (worldsStopped()) {  // alone, or every lane side by side
        pause();
        if (!m_failureReported) {
            m_failureReported = true;
            emit runFailed(QString::fromStdString(*world().failure()));
        }
        return;
    }
    if (m_until >= 0.0 && m_worldTime >= m_until - 1e-12) {
        const double reached = m_worldTime;
        pause();
        emit reachedTime(reached);
        return;
    }
    publish(false);
}

LaneFrame SimWorker::worldLaneFrame(std::size_t lane, int reference) {
    simcore::World& w = *m_worlds[lane];
    LaneFrame frame;
    frame.integrator = QString::fromUtf8(w.integrator().name().data(), qsizetype(w.integrator().name().size()));
    const Eigen::Index n = 3 * Eigen::Index{w.particleCount()};
    frame.positions.resize(std::size_t(n));
    for (Eigen::Index k = 0; k < n; ++k) frame.positions[std::size_t(k)] = float(w.state()[k]);
    if (m_forcesWanted) {  // not counted as the run's force evaluations
        std::vector<double> f(static_cast<std::size_t>(n));
        w.currentForces(f.data());
        frame.forces.assign(f.begin(), f.end());
    }
    // The free-body diagram of the selected particle: its body's parts and the contacts.
    if (m_selected >= 0 && m_selected < w.particleCount()) frame.breakdown = w.forceBreakdown(m_selected);
    frame.diagnostics = totalsRow(w.diagnostics());
    frame.world = std::make_shared<const simcore::WorldDiagnostics>(w.diagnostics());
    if (w.failed()) frame.failure = simcore::Failure{*w.failure(), w.failedStep(), w.failedTime()};
    if (w.heldParticle() >= 0) frame.pointer = simcore::PointerSpring{true, w.heldParticle(), w.anchor()};
    // Side by side: the RMS distance of every particle from the reference lane's.
    const Eigen::VectorXd& x0 = m_worlds[std::size_t(reference)]->state();
    double sum = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) sum += (w.state()[k] - x0[k]) * (w.state()[k] - x0[k]);
    frame.divergence = std::sqrt(sum / double(std::max(1, w.particleCount())));
    frame.divergenceReference = reference;
    return frame;
}

void SimWorker::publishWorld() {
    auto frame = std::make_shared<Frame>();
    const simcore::World& w = world();
    frame->scene = m_scene;
    frame->worldBody = m_worldBody;
    frame->worldSpec = m_worldSpec;
    frame->parameters = w.spec().bodies[std::size_t(std::max(m_worldBody, 0))].params;
    frame->running = m_pacer.running();
    frame->speed = m_pacer.speed();
    frame->wallSeconds = m_pacer.wallSeconds();
    frame->stepsPerSecond = m_pacer.stepsPerSecond();
    frame->fallingBehind = m_pacer.fallingBehind();
    frame->timeline = timelineInfo();
    frame->physicsChangedAt = physicsChangedAt();
    frame->atol = m_lanes.atol();
    frame->rtol = m_lanes.rtol();
    // The distances are to lane 0, or to the first live lane once lane 0 has failed.
    int reference = 0;
    while (reference + 1 < int(m_worlds.size()) && m_worlds[std::size_t(reference)]->failed()) ++reference;
    for (std::size_t i = 0; i < m_worlds.size(); ++i) frame->lanes.push_back(worldLaneFrame(i, reference));
    frame->world = frame->lanes.front().world;
    m_publisher.publish(std::move(frame));
}

}  // namespace elui
