#include "ui/sim_worker.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QThread>
#include <QTimer>

#include "simcore/integrator_table.h"
#include "simcore/scaling.h"
#include "simcore/scenes.h"
#include "simlab/stability.h"

namespace elui {

namespace {
Eigen::Vector3d toEigen(const QVector3D& v) { return {v.x(), v.y(), v.z()}; }
}  // namespace

SimWorker::SimWorker(WallClock clock) : m_pacer(std::move(clock)), m_publisher([this] { emit frameReady(); }) {
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &SimWorker::tick);
}

SimWorker::~SimWorker() = default;

Lanes::List SimWorker::buildLanes(const simcore::ParameterSet& params, const QStringList& integrators) {
    std::optional<std::string> error;
    Lanes::List lanes = m_lanes.build(params, integrators, error);
    if (error) emit sceneRejected(QString::fromStdString(*error));
    return lanes;
}

void SimWorker::setScene(const simcore::ParameterSet& params, const QStringList& integrators) {
    auto lanes = buildLanes(params, integrators);
    if (lanes.empty()) return;
    m_worlds.clear();
    m_lanes.adopt(std::move(lanes));
    m_params = params;
    afterRebuild();
}

void SimWorker::openScene(const simlab::SceneFile& file, const QStringList& integrators) {
    if (file.world) {  // a scene file of several bodies, resumed with its state (side by side: every lane)
        std::vector<std::string> names;
        for (const QString& name : integrators) names.push_back(name.toStdString());
        if (names.empty()) names.push_back(file.integrator);
        if (!buildWorlds(std::make_shared<const simcore::WorldSpec>(*file.world), names, nullptr)) return;
        if (file.state)
            for (auto& w : m_worlds)
                if (auto error = simlab::applyState(*w, *file.state)) {
                    emit sceneRejected(QString::fromStdString(*error));
                    break;
                }
        m_worldBody = 0;
        worldSceneData();
        worldStarted();
        return;
    }
    auto lanes = buildLanes(file.params, integrators);
    if (lanes.empty()) return;
    if (file.state)
        for (auto& sim : lanes)
            if (auto error = simlab::applyState(*sim, *file.state)) {
                emit sceneRejected(QString::fromStdString(*error));
                return;
            }
    // The file is the whole experiment: a preset's start kick does not apply to it.
    m_worlds.clear();
    m_lanes.setKick(0.0, 0.0);
    m_lanes.adopt(std::move(lanes));
    m_params = file.params;
    afterRebuild();
}

SceneCapture SimWorker::captureScene() const {
    SceneCapture capture;
    if (worldMode()) {
        capture.text = simlab::sceneFileText(world(), true);
        capture.parameters = world().spec().bodies.front().params;
        capture.integrator = QString::fromUtf8(world().integrator().name().data());
        capture.lanes = int(m_worlds.size());
        capture.time = world().time();
        capture.world = true;
        return capture;
    }
    if (m_lanes.empty()) return capture;
    const simcore::Simulation& sim = m_lanes.front();
    capture.text = simlab::sceneFileText(sim, std::string(simcore::sceneInfo(sim.parameters().kind()).name), true);
    capture.parameters = sim.parameters();
    capture.integrator = integratorName(sim);
    capture.lanes = int(m_lanes.size());
    capture.time = sim.time();
    return capture;
}

void SimWorker::afterRebuild() {
    auto scene = std::make_shared<SceneData>();
    const simcore::Simulation& sim = m_lanes.front();
    scene->version = ++m_sceneVersion;
    m_selected = -1;  // another body: the old index means nothing
    scene->kind = m_params.kind();
    scene->topology = sim.topology();
    scene->boxCentre = sim.boxCentre();
    scene->boxHalfSize = sim.boxHalfSize();
    const auto x = sim.positions();
    const Eigen::Vector3d centre = x.rowwise().mean();
    double radius = 0.0;
    for (Eigen::Index i = 0; i < x.cols(); ++i) radius = std::max(radius, (x.col(i) - centre).norm());
    scene->bodyRadius = std::max(radius, 0.5);
    scene->bodyValues =
        QString::fromStdString(simcore::bodyValuesText(m_params, simcore::bodyValues(m_params, sim.body())));
    // A rebuild can make the current DT unstable for the chosen method (a finer mesh has faster
    // modes): say so before it runs, with a step the same estimate predicts stable.
    scene->stabilityAdvice = simlab::stabilityAdvice(sim);
    const bool unstable = scene->suggestedDt() > 0.0;
    m_scene = std::move(scene);
    m_until = -1.0;
    startHistory();
    if (unstable && m_pacer.running()) pause();
}

void SimWorker::setIntegrator(const QString& name) {
    if (!hasRun()) return;
    if (auto error = simcore::unknownIntegrator(name.toStdString())) {
        emit parameterRejected(QStringLiteral("integrator"), QString::fromStdString(*error));
    } else {
        Input input;
        // A world is built again with it and goes on from its state.
        input.kind = worldMode() ? Input::World : Input::Integrator;
        input.key = name.toStdString();
        if (worldMode()) {  // lane 0's world built again with it, the others as they are
            input.spec = world().sharedSpec();
            input.integrators = worldIntegrators();
            input.integrators.front() = input.key;
        }
        logInput(std::move(input));
    }
    publish(true);
}

void SimWorker::setParameter(simcore::Param id, double value) {
    if (worldMode()) {
        setWorldParameter(id, value);
        return;
    }
    if (m_lanes.empty()) return;
    const simcore::ParamSpec& spec = simcore::paramSpec(id);
    const QString key = QString::fromUtf8(spec.key.data(), qsizetype(spec.key.size()));
    const bool rebuilds = spec.isShape() || spec.group == simcore::ParamGroup::Start;
    if (!rebuilds) {
        // A live edit: part of the timeline (validated first, so a refused value changes nothing).
        simcore::ParameterSet probe = m_lanes.front().parameters();
        if (auto error = probe.set(id, value)) {
            emit parameterRejected(key, QString::fromStdString(*error));
        } else {
            Input input;
            input.kind = Input::Parameter;
            input.param = id;
            input.value = value;
            logInput(std::move(input));
        }
        publish(true);
        return;
    }
    if (auto error = m_lanes.trySetParameter(id, value)) {
        emit parameterRejected(key, QString::fromStdString(*error));
        publish(true);
        return;
    }
    m_params = m_lanes.front().parameters();
    afterRebuild();
}

void SimWorker::setSpeed(int speed) {
    m_pacer.setSpeed(static_cast<Speed>(std::clamp(speed, 0, 3)), worldMode() ? m_worldTime : m_lanes.commonTime());
    if (m_pacer.running()) m_timer->start(m_pacer.timerInterval());
    publish(true);
}

void SimWorker::setTolerances(double atol, double rtol) {
    // The CLI's ranges (--atol in [0, 1], --rtol in (0, 1]); anything else is not sent by the GUI.
    if (!(atol >= 0.0 && atol <= 1.0 && rtol > 0.0 && rtol <= 1.0)) return;
    if (!hasRun()) {
        m_lanes.setTolerances(atol, rtol);
        return;
    }
    Input input;
    input.kind = Input::Tolerances;
    input.value = atol;
    input.value2 = rtol;
    logInput(std::move(input));
    publish(true);
}

void SimWorker::setStepDoubling(bool on) { logSwitch(Input::StepDoubling, on); }

void SimWorker::setFloatPrecision(bool on) { logSwitch(Input::Precision, on); }

void SimWorker::logSwitch(Input::Kind kind, bool on) {
    Input input;
    input.kind = kind;
    input.value = on ? 1.0 : 0.0;
    if (!hasRun()) {  // before the first scene: kept for the lanes to come
        applyInput(input);
        return;
    }
    logInput(std::move(input));
    publish(true);
}


void SimWorker::setForcesWanted(bool on) {
    m_forcesWanted = on;
    publish(true);
}

void SimWorker::setErrorBandsWanted(bool on) { m_bandsWanted = on; }

void SimWorker::setStartKick(double innerVx, double outerVx) { m_lanes.setKick(innerVx, outerVx); }

void SimWorker::run() {
    if (worldMode()) {
        if (worldsStopped()) return;
        m_pacer.start(m_worldTime);
        setUntil(-1.0);
        m_timer->start(m_pacer.timerInterval());
        publish(true);
        return;
    }
    if (m_lanes.empty() || m_lanes.allFailed()) return;
    m_pacer.start(m_lanes.commonTime());
    setUntil(-1.0);
    m_timer->start(m_pacer.timerInterval());
    publish(true);
}

void SimWorker::runUntil(double simulatedTime) {
    if (worldMode()) {
        m_pacer.start(m_worldTime);
        setUntil(simulatedTime);
        m_timer->start(0);
        publish(true);
        return;
    }
    if (m_lanes.empty()) return;
    m_pacer.start(m_lanes.commonTime());
    setUntil(simulatedTime);
    m_timer->start(0);
    publish(true);
}

void SimWorker::pause() {
    m_pacer.stop();
    setUntil(-1.0);
    if (m_timer) m_timer->stop();
    publish(true);
}

void SimWorker::stepOnce() {
    if (m_pacer.running()) pause();
    if (worldMode()) {
        stepWorld();
        publish(true);
        return;
    }
    if (m_lanes.empty()) return;
    stepAll();
    publish(true);
}

void SimWorker::reset() {
    if (worldMode()) {
        for (auto& w : m_worlds) w->reset();
        worldStarted();
        return;
    }
    m_lanes.reset();
    if (m_lanes.empty()) return;
    startHistory();
}

void SimWorker::startHistory() {
    // Back at the start (t = 0 after a new scene or a reset; a saved state's time after
    // openScene): kick, clocks, rows and a first frame.
    m_lanes.applyKick();
    m_lanes.syncCommonTime();
    m_pacer.startOver(m_lanes.commonTime());
    m_failureReported = false;
    m_publisher.startHistory();
    recordRow();
    startTimeline();
    publish(true);
}

void SimWorker::grabAlongRay(const QVector3D& origin, const QVector3D& direction, double maxDistance) {
    if (worldMode()) {  // any body's outer particle (lane 0 picks, every lane grabs the same one)
        const int particle = world().pickAlongRay(toEigen(origin), toEigen(direction).normalized(), maxDistance);
        if (particle < 0) return;
        const Eigen::Vector3d at = Eigen::Map<const Eigen::Vector3d>(world().state().data() + 3 * particle);
        Input input;
        input.kind = Input::Grab;
        input.particle = particle;
        input.anchor = at;
        logInput(std::move(input));
        emit grabbed(particle, QVector3D(float(at.x()), float(at.y()), float(at.z())));
        publish(true);
        return;
    }
    if (m_lanes.empty()) return;
    const Eigen::Vector3d o = toEigen(origin), d = toEigen(direction).normalized();
    const int particle = m_lanes.front().pickAlongRay(o, d, maxDistance);
    if (particle < 0) return;
    const Eigen::Vector3d at = m_lanes.front().positions().col(particle);
    Input input;
    input.kind = Input::Grab;
    input.particle = particle;
    input.anchor = at;
    logInput(std::move(input));
    emit grabbed(particle, QVector3D(float(at.x()), float(at.y()), float(at.z())));
    publish(true);
}

void SimWorker::moveAnchor(const QVector3D& anchor) {
    if (worldMode() ? world().heldParticle() < 0 : m_lanes.empty() || !m_lanes.front().pointer().active) return;
    Input input;
    input.kind = Input::Move;
    input.anchor = toEigen(anchor);
    logInput(std::move(input));
    if (!m_pacer.running()) publish(true);
}

void SimWorker::selectAlongRay(const QVector3D& origin, const QVector3D& direction, double maxDistance) {
    if (!hasRun()) return;
    const Eigen::Vector3d o = toEigen(origin), d = toEigen(direction).normalized();
    m_selected = worldMode() ? world().pickAlongRay(o, d, maxDistance) : m_lanes.front().pickAlongRay(o, d, maxDistance);
    publish(true);
}

void SimWorker::selectParticle(int particle) {
    const int count = worldMode() ? world().particleCount() : m_lanes.empty() ? 0 : m_lanes.front().particleCount();
    m_selected = particle >= 0 && particle < count ? particle : -1;
    publish(true);
}

void SimWorker::release() {
    if (worldMode() ? world().heldParticle() < 0 : m_lanes.empty() || !m_lanes.front().pointer().active) return;
    Input input;
    input.kind = Input::Release;
    logInput(std::move(input));
    publish(true);
}

void SimWorker::shutdown() {
    m_pacer.stop();
    m_until = -1.0;
    delete m_timer;  // a QTimer is stopped and destroyed on the thread that runs it
    m_timer = nullptr;
    m_lanes.clear();
    m_worlds.clear();
    m_worldRows = {};
    m_scene.reset();
    m_params = simcore::ParameterSet{};
    m_recorder.clear();
    m_runStart.reset();
    m_inputs = {};
    m_publisher.clear();
    // Quit from here rather than QThread::quit() on the GUI thread: that would wake this
    // thread's event dispatcher (a write to its eventfd) with no ordering TSan can see before
    // the dispatcher closes it as the thread ends.
    thread()->quit();
}

bool SimWorker::stepAll() {
    if (m_lanes.allFailed()) return false;
    // A step from a scrubbed moment runs on from it: a branch.
    if (!m_replaying && m_moment < m_recorder.last()) branch();
    m_lanes.stepAll(m_until);
    if (!m_replaying) m_pacer.countStep();
    recordRow();
    recordMoment();
    return true;
}

void SimWorker::recordRow() {
    if (m_replaying) return;
    m_publisher.recordRow(m_lanes.front(), m_bandsWanted);
    if (m_lanes.size() > 1) m_publisher.recordLaneRows(m_lanes.views(), m_lanes.commonTime());
}

void SimWorker::tick() {
    if (worldMode() && m_pacer.running()) {
        tickWorld();
        return;
    }
    if (!m_pacer.running() || m_lanes.empty()) return;
    // Where the clock says simulated time should be by the end of this tick.
    const double target = m_pacer.beginTick(m_until >= 0.0);
    bool outOfBudget = false;
    while (m_lanes.commonTime() < target) {
        if (m_until >= 0.0 && m_lanes.commonTime() >= m_until - 1e-12) break;
        if (!stepAll()) break;
        if (m_pacer.budgetSpent()) {
            outOfBudget = true;
            break;
        }
        if (m_lanes.stopped()) break;
    }
    m_pacer.endTick(m_lanes.commonTime(), outOfBudget);

    if (m_lanes.stopped()) {
        pause();
        if (!m_failureReported) {
            m_failureReported = true;
            const auto& f = *m_lanes.front().failure();
            emit runFailed(QString::fromStdString(f.reason));
        }
        return;
    }
    if (m_until >= 0.0 && m_lanes.commonTime() >= m_until - 1e-12) {
        const double reached = m_lanes.commonTime();
        pause();
        emit reachedTime(reached);
        return;
    }
    publish(false);
}

void SimWorker::publish(bool force) {
    if (worldMode()) {
        if (m_pacer.frameDue(force)) publishWorld();
        return;
    }
    if (!m_pacer.frameDue(force) || m_lanes.empty()) return;
    auto frame = std::make_shared<Frame>();
    frame->scene = m_scene;
    frame->parameters = m_params;
    frame->running = m_pacer.running();
    frame->speed = m_pacer.speed();
    frame->wallSeconds = m_pacer.wallSeconds();
    frame->stepsPerSecond = m_pacer.stepsPerSecond();
    frame->fallingBehind = m_pacer.fallingBehind();
    frame->atol = m_lanes.atol();
    frame->rtol = m_lanes.rtol();
    frame->floatWanted = m_lanes.floatWanted();
    frame->floatActive = m_lanes.floatActive();
    frame->floatDistance = m_lanes.floatDistance();
    frame->floatRoundoff = m_lanes.floatRoundoff();
    frame->timeline = timelineInfo();
    frame->lanes = m_lanes.laneFrames(m_forcesWanted, m_selected);
    frame->runStart = m_runStart;
    frame->physicsChangedAt = physicsChangedAt();
    for (std::size_t i = 0; i < frame->lanes.size(); ++i)
        if (frame->lanes[i].failure) frame->lanes[i].stretchStart = stretchStart(i, *frame->lanes[i].failure);
    m_publisher.publish(std::move(frame));
}

std::shared_ptr<const simcore::SimulationSnapshot> SimWorker::stretchStart(std::size_t lane,
                                                                          const simcore::Failure& failure) {
    if (m_stretchStarts.size() != m_lanes.size()) m_stretchStarts.assign(m_lanes.size(), {});
    auto& cached = m_stretchStarts[lane];
    if (cached.first && cached.second == failure.step) return cached.first;
    // The latest checkpoint of this lane, unfailed, at least kFailureStretch before the failure
    // (else the first one: the run's start, or the moment the timeline began).
    const simcore::SimulationSnapshot* best = nullptr;
    for (const simcore::TimelineCheckpoint& c : m_recorder.checkpoints()) {
        if (lane >= c.lanes.size() || c.lanes[lane].failure) continue;
        const simcore::SimulationSnapshot& s = c.lanes[lane];
        if (!best || s.diag.time <= failure.time - kFailureStretch) best = &s;
        if (s.diag.time > failure.time - kFailureStretch) break;
    }
    if (!best) return {};
    cached = {std::make_shared<const simcore::SimulationSnapshot>(*best), failure.step};
    return cached.first;
}

// --- time travel ---

void SimWorker::startTimeline() {
    m_stretchStarts.clear();
    m_recorder.clear();
    m_inputs.clear();
    m_publisher.clearBranches();
    m_moment = 0;
    if (worldMode()) {
        m_recorder.record(0, worldViews(), {m_worldTime, m_until});
        m_runStart.reset();  // the reference curve is one body's
    } else {
        m_recorder.record(0, m_lanes.views(), {m_lanes.commonTime(), m_until});
        m_runStart = std::make_shared<const simcore::SimulationSnapshot>(m_recorder.checkpoints().front().lanes.front());
    }
    m_firstTime = m_lastTime = leadTime();
}

double SimWorker::physicsChangedAt() const {
    double at = std::numeric_limits<double>::infinity();
    for (const Input& input : m_inputs)
        if ((input.kind == Input::Parameter && input.param != simcore::Param::Dt) || input.kind == Input::Grab ||
            input.kind == Input::World)
            at = std::min(at, input.time);
    return at;
}

void SimWorker::recordMoment() {
    ++m_moment;
    if (m_replaying) return;
    if (worldMode()) m_recorder.record(m_moment, worldViews(), {m_worldTime, m_until});
    else m_recorder.record(m_moment, m_lanes.views(), {m_lanes.commonTime(), m_until});
    m_lastTime = leadTime();
}

void SimWorker::logInput(Input input) {
    if (!hasRun()) return;
    if (!m_replaying && m_moment < m_recorder.last()) branch();
    input.moment = m_moment;
    input.time = leadTime();
    if (!m_replaying) m_inputs.push_back(input);
    applyInput(input);
}

void SimWorker::setUntil(double until) {
    if (until == m_until) return;
    if (!hasRun()) {
        m_until = until;
        return;
    }
    Input input;
    input.kind = Input::Until;
    input.value = until;
    logInput(std::move(input));
}

void SimWorker::applyInput(const Input& input) {
    if (worldMode()) {
        applyWorldInput(input);
        return;
    }
    switch (input.kind) {
        case Input::Parameter:
            m_lanes.setParameter(input.param, input.value);
            m_params = m_lanes.front().parameters();
            break;
        case Input::Integrator:
            m_lanes.dropFloat();
            if (auto error = m_lanes.front().setIntegrator(input.key))
                emit parameterRejected(QStringLiteral("integrator"), QString::fromStdString(*error));
            break;
        case Input::StepDoubling: m_lanes.setStepDoubling(input.value != 0.0); break;
        case Input::Precision: m_lanes.setFloatWanted(input.value != 0.0); break;
        case Input::Tolerances: m_lanes.setTolerances(input.value, input.value2); break;
        case Input::Grab: m_lanes.grab(input.particle, input.anchor); break;
        case Input::Move: m_lanes.moveAnchor(input.anchor); break;
        case Input::Release: m_lanes.release(); break;
        case Input::Until: m_until = input.value; break;
        case Input::World: break;  // a world's only
    }
}

void SimWorker::branch() {
    // The moment shown becomes the newest: what came after it is forgotten (the GUI keeps its
    // rows as the abandoned future); what was done at it stays (the lanes have it).
    const long moment = m_moment;
    m_recorder.truncateAfter(moment);
    std::erase_if(m_inputs, [moment](const Input& i) { return i.moment > moment; });
    m_lastTime = leadTime();
    m_publisher.branch(m_lastTime);
    if (worldMode()) cutWorldRows(m_lastTime);
}

void SimWorker::replayForward(long target, bool inputsAtStartApplied) {
    auto next = std::lower_bound(m_inputs.begin(), m_inputs.end(), m_moment,
                                 [](const Input& i, long moment) { return i.moment < moment; });
    if (inputsAtStartApplied)
        while (next != m_inputs.end() && next->moment == m_moment) ++next;
    for (;;) {
        for (; next != m_inputs.end() && next->moment == m_moment; ++next) applyInput(*next);
        if (m_moment >= target) return;
        // A method whose history a checkpoint cannot hold is recorded at every moment and
        // never re-simulated: stop at the last moment held exactly.
        if (worldMode() ? !worldsRestorable() : !m_lanes.restorable()) return;
        const long before = m_moment;
        if (worldMode()) stepWorld();
        else stepAll();
        if (m_moment == before) return;  // every lane failed (the run stopped here too)
    }
}

void SimWorker::scrubTo(long target) {
    if (!hasRun() || m_recorder.empty()) return;
    if (m_pacer.running()) pause();
    goTo(target);
    publish(true);
}

void SimWorker::goTo(long target) {
    target = std::clamp(target, m_recorder.first(), m_recorder.last());
    if (target == m_moment) return;
    m_replaying = true;
    const simcore::TimelineCheckpoint* c = m_recorder.checkpointFor(target);
    const bool restorable = worldMode() ? worldsRestorable() : m_lanes.restorable();
    const bool fromHere = m_moment < target && c && m_moment >= c->index && restorable;
    if (fromHere) {
        // Forward from the moment shown, which lies after the checkpoint: fewer steps.
        replayForward(target, true);
    } else if (c && !c->worlds.empty()) {
        restoreWorld(*c);
        m_until = c->extra.at(1);
        m_moment = c->index;
        replayForward(target, false);
    } else if (c) {
        m_lanes.restore(*c);
        m_lanes.setCommonTime(c->extra.at(0));
        m_until = c->extra.at(1);
        m_moment = c->index;
        m_params = m_lanes.front().parameters();  // side by side, the common DT
        replayForward(target, false);
    }
    m_replaying = false;
    m_until = -1.0;  // shown paused
    if (worldMode()) {
        m_params = world().spec().bodies.front().params;
        m_failureReported = worldsStopped();
        return;
    }
    m_params = m_lanes.front().parameters();
    m_lanes.readOptions();
    m_failureReported = m_lanes.front().failed();
}

void SimWorker::scrubToTime(double t) {
    if (!hasRun() || m_recorder.empty()) return;
    if (m_pacer.running()) pause();
    // From the last checkpoint before t, forward one moment at a time until t is reached.
    const auto& all = m_recorder.checkpoints();
    auto after = std::upper_bound(all.begin(), all.end(), t, [](double time, const simcore::TimelineCheckpoint& c) {
        return time <= (c.worlds.empty() ? c.lanes.front().diag.time : c.extra.at(0));
    });
    goTo(after == all.begin() ? all.front().index : (after - 1)->index);
    const double reach = t - 1e-9 * std::max(1e-3, std::abs(t));
    while (m_moment < m_recorder.last() && leadTime() < reach) {
        const long before = m_moment;
        goTo(m_moment + 1);
        if (m_moment == before) break;  // not re-simulated (CVODE): the nearest kept moment
    }
    publish(true);
}

void SimWorker::scrubBy(long delta) { scrubTo(m_moment + delta); }

void SimWorker::scrubToEnd() { scrubTo(m_recorder.last()); }

void SimWorker::setTimelineBudget(qulonglong bytes) {
    m_recorder.setBudget(std::size_t(bytes));
    publish(true);
}

TimelineInfo SimWorker::timelineInfo() const {
    TimelineInfo t;
    t.moment = m_moment;
    t.first = m_recorder.first();
    t.last = std::max(m_recorder.last(), 0L);
    t.firstTime = m_firstTime;
    t.lastTime = m_lastTime;
    t.bytes = m_recorder.bytes();
    t.budget = m_recorder.budget();
    t.interval = m_recorder.interval();
    t.checkpoints = m_recorder.checkpointCount();
    return t;
}

}  // namespace elui
