#include "sim_worker.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <QThread>
#include <QTimer>

#include "scaling.h"
#include "scenes.h"
#include "stability.h"

namespace elui {

double speedFactor(Speed speed) {
    switch (speed) {
        case Speed::RealTime: return 1.0;
        case Speed::Quarter: return 0.25;
        case Speed::Tenth: return 0.1;
        case Speed::AsFastAsPossible: return 0.0;
    }
    return 1.0;
}

QString speedName(Speed speed) {
    switch (speed) {
        case Speed::RealTime: return QStringLiteral("Real time");
        case Speed::Quarter: return QStringLiteral("1/4 speed");
        case Speed::Tenth: return QStringLiteral("1/10 speed");
        case Speed::AsFastAsPossible: return QStringLiteral("As fast as possible");
    }
    return {};
}

namespace {
// Per tick, stepping stops after this much wall time so commands and frames keep flowing [s].
constexpr double kTickBudget = 0.015;
// Frames are published at most this often while running [s] (the screen cannot show more).
constexpr double kPublishInterval = 1.0 / 90.0;

Eigen::Vector3d toEigen(const QVector3D& v) { return {v.x(), v.y(), v.z()}; }
QString integratorName(const simcore::Simulation& sim) {
    const std::string_view name = sim.integrator().name();
    return QString::fromUtf8(name.data(), qsizetype(name.size()));
}
}  // namespace

WallClock steadyWallClock() {
    return [] { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); };
}

SimWorker::SimWorker(WallClock clock) : m_now(std::move(clock)) {
    m_timer = new QTimer(this);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &SimWorker::tick);
    m_publishStart = m_rateStart = m_now();
}

SimWorker::~SimWorker() = default;

FrameBatch SimWorker::takeBatch() {
    std::lock_guard lock(m_slotMutex);
    FrameBatch out = std::move(m_slot);
    m_slot = FrameBatch{};
    m_slotPending = false;
    return out;
}

std::vector<std::unique_ptr<simcore::Simulation>> SimWorker::buildLanes(const simcore::ParameterSet& params,
                                                                        const QStringList& integrators) {
    std::vector<std::unique_ptr<simcore::Simulation>> lanes;
    try {
        for (const QString& name : integrators) {
            auto sim = std::make_unique<simcore::Simulation>(params, name.toStdString());
            // One force thread: the GUI thread (and a software GL renderer) needs the other core.
            sim->setThreads(m_threads);
            sim->setIntegratorOptions([&] {
                simcore::IntegratorOptions o = sim->integratorOptions();
                o.stepDoubling = m_stepDoubling;
                return o;
            }());
            lanes.push_back(std::move(sim));
        }
    } catch (const std::exception& e) {
        emit sceneRejected(QString::fromStdString(e.what()));
        return {};
    }
    return lanes;
}

void SimWorker::setScene(const simcore::ParameterSet& params, const QStringList& integrators) {
    auto lanes = buildLanes(params, integrators);
    if (lanes.empty()) return;
    m_lanes = std::move(lanes);
    m_params = params;
    afterRebuild();
}

void SimWorker::openScene(const simcore::SceneFile& file, const QStringList& integrators) {
    auto lanes = buildLanes(file.params, integrators);
    if (lanes.empty()) return;
    if (file.state)
        for (auto& sim : lanes)
            if (auto error = simcore::applyState(*sim, *file.state)) {
                emit sceneRejected(QString::fromStdString(*error));
                return;
            }
    // The file is the whole experiment: a preset's start kick does not apply to it.
    m_kickInner = m_kickOuter = 0.0;
    m_lanes = std::move(lanes);
    m_params = file.params;
    afterRebuild();
}

SceneCapture SimWorker::captureScene() const {
    SceneCapture capture;
    if (m_lanes.empty()) return capture;
    const simcore::Simulation& sim = *m_lanes.front();
    capture.text = simcore::sceneFileText(sim, std::string(simcore::sceneInfo(sim.parameters().kind()).name), true);
    capture.parameters = sim.parameters();
    capture.integrator = integratorName(sim);
    capture.lanes = int(m_lanes.size());
    capture.time = sim.time();
    return capture;
}

void SimWorker::afterRebuild() {
    auto scene = std::make_shared<SceneData>();
    const simcore::Simulation& sim = *m_lanes.front();
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
    if (auto advice = simcore::stabilityAdvice(sim)) {
        scene->stabilityWarning = QString::fromStdString(advice->message);
        scene->suggestedDt = advice->suggestedDt;
    }
    const bool unstable = scene->suggestedDt > 0.0;
    m_scene = std::move(scene);
    updateDtLimit();
    m_until = -1.0;
    startHistory();
    if (unstable && m_running) pause();
}

void SimWorker::applyKick() {
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

void SimWorker::setIntegrator(const QString& name) {
    if (m_lanes.empty()) return;
    if (auto error = simcore::unknownIntegrator(name.toStdString())) {
        emit parameterRejected(QStringLiteral("integrator"), QString::fromStdString(*error));
    } else {
        Input input;
        input.kind = Input::Integrator;
        input.key = name.toStdString();
        logInput(std::move(input));
    }
    publish(true);
}

void SimWorker::setParameter(simcore::Param id, double value) {
    if (m_lanes.empty()) return;
    const simcore::ParamSpec& spec = simcore::paramSpec(id);
    const QString key = QString::fromUtf8(spec.key.data(), qsizetype(spec.key.size()));
    const bool rebuilds = spec.isShape() || spec.group == simcore::ParamGroup::Start;
    if (!rebuilds) {
        // A live edit: part of the timeline (validated first, so a refused value changes nothing).
        simcore::ParameterSet probe = m_lanes.front()->parameters();
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
    for (std::size_t i = 0; i < m_lanes.size(); ++i) {
        if (auto error = m_lanes[i]->setParameter(id, value)) {
            if (i == 0) {
                emit parameterRejected(key, QString::fromStdString(*error));
                publish(true);
                return;
            }
        }
    }
    m_params = m_lanes.front()->parameters();
    updateDtLimit();
    if (rebuilds) {
        afterRebuild();
        return;
    }
    publish(true);
}

void SimWorker::setSpeed(int speed) {
    m_speed = static_cast<Speed>(std::clamp(speed, 0, 3));
    restartClock();
    if (m_running) m_timer->start(m_speed == Speed::AsFastAsPossible ? 0 : 4);
    publish(true);
}

void SimWorker::setStepDoubling(bool on) {
    if (m_lanes.empty()) {
        m_stepDoubling = on;
        return;
    }
    Input input;
    input.kind = Input::StepDoubling;
    input.value = on ? 1.0 : 0.0;
    logInput(std::move(input));
    publish(true);
}

void SimWorker::setForcesWanted(bool on) {
    m_forcesWanted = on;
    publish(true);
}

void SimWorker::setErrorBandsWanted(bool on) { m_bandsWanted = on; }

void SimWorker::setStartKick(double innerVx, double outerVx) {
    m_kickInner = innerVx;
    m_kickOuter = outerVx;
}

void SimWorker::run() {
    if (m_lanes.empty() || allFailed()) return;
    if (!m_running) restartClock();
    m_running = true;
    setUntil(-1.0);
    m_timer->start(m_speed == Speed::AsFastAsPossible ? 0 : 4);
    publish(true);
}

void SimWorker::runUntil(double simulatedTime) {
    if (m_lanes.empty()) return;
    if (!m_running) restartClock();
    m_running = true;
    setUntil(simulatedTime);
    m_timer->start(0);
    publish(true);
}

void SimWorker::pause() {
    if (m_running) m_wallBeforeStart += since(m_clockStart);
    m_running = false;
    setUntil(-1.0);
    if (m_timer) m_timer->stop();
    publish(true);
}

void SimWorker::stepOnce() {
    if (m_running) pause();
    if (m_lanes.empty()) return;
    stepAll();
    publish(true);
}

void SimWorker::reset() {
    for (auto& sim : m_lanes) sim->reset();
    if (m_lanes.empty()) return;
    startHistory();
}

void SimWorker::startHistory() {
    // Back at the start (t = 0 after a new scene or a reset; a saved state's time after
    // openScene): kick, clocks, rows and a first frame.
    applyKick();
    m_commonTime = m_lanes.front()->time();
    restartClock();
    m_wallBeforeStart = 0.0;
    m_lastRowTime = -1.0;
    m_failureReported = false;
    m_rows.clear();
    m_historyReset = true;
    recordRow();
    startTimeline();
    publish(true);
}

void SimWorker::grabAlongRay(const QVector3D& origin, const QVector3D& direction, double maxDistance) {
    if (m_lanes.empty()) return;
    const Eigen::Vector3d o = toEigen(origin), d = toEigen(direction).normalized();
    const int particle = m_lanes.front()->pickAlongRay(o, d, maxDistance);
    if (particle < 0) return;
    const Eigen::Vector3d at = m_lanes.front()->positions().col(particle);
    Input input;
    input.kind = Input::Grab;
    input.particle = particle;
    input.anchor = at;
    logInput(std::move(input));
    emit grabbed(particle, QVector3D(float(at.x()), float(at.y()), float(at.z())));
    publish(true);
}

void SimWorker::moveAnchor(const QVector3D& anchor) {
    if (m_lanes.empty() || !m_lanes.front()->pointer().active) return;
    Input input;
    input.kind = Input::Move;
    input.anchor = toEigen(anchor);
    logInput(std::move(input));
    if (!m_running) publish(true);
}

void SimWorker::selectAlongRay(const QVector3D& origin, const QVector3D& direction, double maxDistance) {
    if (m_lanes.empty()) return;
    m_selected = m_lanes.front()->pickAlongRay(toEigen(origin), toEigen(direction).normalized(), maxDistance);
    publish(true);
}

void SimWorker::selectParticle(int particle) {
    m_selected = !m_lanes.empty() && particle >= 0 && particle < m_lanes.front()->particleCount() ? particle : -1;
    publish(true);
}

void SimWorker::release() {
    if (m_lanes.empty() || !m_lanes.front()->pointer().active) return;
    Input input;
    input.kind = Input::Release;
    logInput(std::move(input));
    publish(true);
}

void SimWorker::shutdown() {
    m_running = false;
    m_until = -1.0;
    delete m_timer;  // a QTimer is stopped and destroyed on the thread that runs it
    m_timer = nullptr;
    m_lanes.clear();
    m_scene.reset();
    m_params = simcore::ParameterSet{};
    m_rows = {};
    m_recorder.clear();
    m_inputs = {};
    {
        std::lock_guard lock(m_slotMutex);
        m_slot = FrameBatch{};
    }
    // Quit from here rather than QThread::quit() on the GUI thread: that would wake this
    // thread's event dispatcher (a write to its eventfd) with no ordering TSan can see before
    // the dispatcher closes it as the thread ends.
    thread()->quit();
}

void SimWorker::restartClock() {
    // The wall time run so far is kept; the clock then counts from here.
    if (m_running && m_clockStart >= 0.0) m_wallBeforeStart += since(m_clockStart);
    m_clockStart = m_now();
    m_clockSimStart = m_commonTime;
    m_fallingBehind = false;
}

void SimWorker::updateDtLimit() {
    const double rate = m_lanes.front()->estimatedFastestRate();
    m_dtLimit = rate > 0.0 ? simcore::kExplicitStabilityLimit / rate : 0.0;
}

bool SimWorker::allFailed() const {
    return std::all_of(m_lanes.begin(), m_lanes.end(), [](const auto& s) { return s->failed(); });
}

bool SimWorker::stepAll() {
    if (allFailed()) return false;
    // A step from a scrubbed moment runs on from it: a branch.
    if (!m_replaying && m_moment < m_recorder.last()) branch();
    if (m_lanes.size() == 1) {
        simcore::Simulation& sim = *m_lanes.front();
        const double until = m_until >= 0.0 ? m_until : std::numeric_limits<double>::infinity();
        sim.step(until);
        m_commonTime = sim.time();
    } else {
        // Side by side: every live lane reaches the same time after each common DT.
        double target = m_commonTime + m_lanes.front()->params().time.dt;
        if (m_until >= 0.0) target = std::min(target, m_until);
        for (auto& sim : m_lanes)
            if (!sim->failed()) sim->advanceTo(target);
        m_commonTime = target;
    }
    if (!m_replaying) ++m_rateSteps;
    recordRow();
    recordMoment();
    return true;
}

void SimWorker::recordRow() {
    if (m_replaying) return;
    simcore::Simulation& sim = *m_lanes.front();
    if (sim.failed()) return;
    const double t = sim.time();
    if (m_lastRowTime >= 0.0 && t - m_lastRowTime < kRowInterval * (1.0 - 1e-9)) return;
    m_lastRowTime = t;
    m_rows.push_back(sim.diagnostics());
    // The plots' error bands (two measurements per row, only for steps with an estimate and
    // while the plots show them).
    if (m_bandsWanted) m_rows.back().errors = sim.observableErrors();
}

void SimWorker::tick() {
    if (!m_running || m_lanes.empty()) return;
    const double tickStart = m_now();
    const bool fast = m_speed == Speed::AsFastAsPossible || m_until >= 0.0;
    // Where the honest clock says simulated time should be now.
    const double target =
        fast ? std::numeric_limits<double>::infinity()
             : m_clockSimStart + since(m_clockStart) * speedFactor(m_speed);
    bool outOfBudget = false;
    while (m_commonTime < target) {
        if (m_until >= 0.0 && m_commonTime >= m_until - 1e-12) break;
        if (!stepAll()) break;
        if (since(tickStart) > kTickBudget) {
            outOfBudget = true;
            break;
        }
        if (m_lanes.size() == 1 ? m_lanes.front()->failed() : allFailed()) break;
    }
    if (!fast) {
        // Could not keep up: say so and restart the clock here instead of piling up debt.
        m_fallingBehind = outOfBudget && m_commonTime < target;
        if (m_fallingBehind) {
            const double now = m_now();
            m_wallBeforeStart += now - m_clockStart;
            m_clockStart = now;
            m_clockSimStart = m_commonTime;
        }
    }
    const double now = m_now(), rateWindow = now - m_rateStart;
    if (rateWindow >= 0.5) {
        m_stepsPerSecond = double(m_rateSteps) / rateWindow;
        m_rateSteps = 0;
        m_rateStart = now;
    }

    const bool laneZeroFailed = m_lanes.front()->failed();
    if ((m_lanes.size() == 1 && laneZeroFailed) || allFailed()) {
        pause();
        if (!m_failureReported) {
            m_failureReported = true;
            const auto& f = *m_lanes.front()->failure();
            emit runFailed(QString::fromStdString(f.reason));
        }
        return;
    }
    if (m_until >= 0.0 && m_commonTime >= m_until - 1e-12) {
        const double reached = m_commonTime;
        pause();
        emit reachedTime(reached);
        return;
    }
    publish(false);
}

void SimWorker::publish(bool force) {
    const double now = m_now();
    if (!force && now - m_publishStart < kPublishInterval) return;
    m_publishStart = now;
    if (m_lanes.empty()) return;

    auto frame = std::make_shared<Frame>();
    frame->scene = m_scene;
    frame->parameters = m_params;
    frame->running = m_running;
    frame->speed = m_speed;
    frame->wallSeconds = m_wallBeforeStart + (m_running ? now - m_clockStart : 0.0);
    frame->stepsPerSecond = m_running ? m_stepsPerSecond : 0.0;
    frame->fallingBehind = m_fallingBehind;
    frame->explicitDtLimit = m_dtLimit;
    frame->serial = ++m_serial;
    frame->timeline = timelineInfo();
    const auto x0 = m_lanes.front()->positions();
    for (const auto& sim : m_lanes) {
        LaneFrame lane;
        lane.integrator = integratorName(*sim);
        const auto x = sim->positions();
        lane.positions.resize(std::size_t(x.size()));
        for (Eigen::Index k = 0; k < x.size(); ++k) lane.positions[std::size_t(k)] = float(x.data()[k]);
        if (m_forcesWanted) {
            // Not counted as one of the run's force evaluations.
            std::vector<double> f(std::size_t(x.size()));
            sim->currentForces(f.data());
            lane.forces.assign(f.begin(), f.end());
        }
        lane.diagnostics = sim->diagnostics();
        lane.failure = sim->failure();
        lane.pointer = sim->pointer();
        // Nine uncounted force evaluations (ForceModel::breakdown), only while one is selected.
        if (m_selected >= 0 && m_selected < sim->particleCount()) lane.breakdown = sim->forceBreakdown(m_selected);
        lane.divergence = std::sqrt((x - x0).colwise().squaredNorm().mean());
        frame->lanes.push_back(std::move(lane));
    }

    std::lock_guard lock(m_slotMutex);
    m_slot.frame = std::move(frame);
    if (m_historyReset) {
        // Rows not yet taken from before the reset belong to the old history: drop them.
        m_slot.rows.clear();
        m_slot.historyReset = true;
        m_slot.branches.clear();
        m_historyReset = false;
    }
    for (FrameBatch::Branch b : m_branches) {
        b.rowsBefore += m_slot.rows.size();
        m_slot.branches.push_back(b);
    }
    m_branches.clear();
    m_slot.rows.insert(m_slot.rows.end(), m_rows.begin(), m_rows.end());
    m_rows.clear();
    m_published.store(m_slot.frame->serial);
    if (!m_slotPending) {
        m_slotPending = true;
        emit frameReady();
    }
}

// --- time travel ---

void SimWorker::startTimeline() {
    m_recorder.clear();
    m_inputs.clear();
    m_branches.clear();
    m_moment = 0;
    std::vector<const simcore::Simulation*> lanes;
    for (const auto& sim : m_lanes) lanes.push_back(sim.get());
    m_recorder.record(0, lanes, {m_commonTime, m_until});
    m_firstTime = m_lastTime = m_lanes.front()->time();
}

void SimWorker::recordMoment() {
    ++m_moment;
    if (m_replaying) return;
    std::vector<const simcore::Simulation*> lanes;
    for (const auto& sim : m_lanes) lanes.push_back(sim.get());
    m_recorder.record(m_moment, lanes, {m_commonTime, m_until});
    m_lastTime = m_lanes.front()->time();
}

void SimWorker::logInput(Input input) {
    if (m_lanes.empty()) return;
    if (!m_replaying && m_moment < m_recorder.last()) branch();
    input.moment = m_moment;
    if (!m_replaying) m_inputs.push_back(input);
    applyInput(input);
}

void SimWorker::setUntil(double until) {
    if (until == m_until) return;
    if (m_lanes.empty()) {
        m_until = until;
        return;
    }
    Input input;
    input.kind = Input::Until;
    input.value = until;
    logInput(std::move(input));
}

void SimWorker::applyInput(const Input& input) {
    switch (input.kind) {
        case Input::Parameter:
            for (auto& sim : m_lanes) sim->setParameter(input.param, input.value);
            m_params = m_lanes.front()->parameters();
            updateDtLimit();
            break;
        case Input::Integrator:
            if (auto error = m_lanes.front()->setIntegrator(input.key))
                emit parameterRejected(QStringLiteral("integrator"), QString::fromStdString(*error));
            break;
        case Input::StepDoubling:
            m_stepDoubling = input.value != 0.0;
            for (auto& sim : m_lanes) {
                simcore::IntegratorOptions o = sim->integratorOptions();
                o.stepDoubling = m_stepDoubling;
                sim->setIntegratorOptions(o);
            }
            break;
        case Input::Grab:
            for (auto& sim : m_lanes) sim->grab(input.particle, input.anchor);
            break;
        case Input::Move:
            for (auto& sim : m_lanes) sim->moveAnchor(input.anchor);
            break;
        case Input::Release:
            for (auto& sim : m_lanes) sim->release();
            break;
        case Input::Until:
            m_until = input.value;
            break;
    }
}

void SimWorker::branch() {
    // The moment shown becomes the newest: what came after it is forgotten (the GUI keeps its
    // rows as the abandoned future); what was done at it stays (the lanes have it).
    const long moment = m_moment;
    m_recorder.truncateAfter(moment);
    std::erase_if(m_inputs, [moment](const Input& i) { return i.moment > moment; });
    m_lastTime = m_lanes.front()->time();
    m_branches.push_back({m_rows.size(), m_lastTime});
    m_lastRowTime = -1.0;  // the branch's rows start at once
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
        for (const auto& sim : m_lanes)
            if (!sim->integrator().restorable()) return;
        const long before = m_moment;
        stepAll();
        if (m_moment == before) return;  // every lane failed (the run stopped here too)
    }
}

void SimWorker::scrubTo(long target) {
    if (m_lanes.empty() || m_recorder.empty()) return;
    if (m_running) pause();
    goTo(target);
    publish(true);
}

void SimWorker::goTo(long target) {
    target = std::clamp(target, m_recorder.first(), m_recorder.last());
    if (target == m_moment) return;
    m_replaying = true;
    const simcore::TimelineCheckpoint* c = m_recorder.checkpointFor(target);
    bool fromHere = m_moment < target && c && m_moment >= c->index;
    for (const auto& sim : m_lanes) fromHere = fromHere && sim->integrator().restorable();
    if (fromHere) {
        // Forward from the moment shown, which lies after the checkpoint: fewer steps.
        replayForward(target, true);
    } else if (c) {
        for (std::size_t i = 0; i < m_lanes.size() && i < c->lanes.size(); ++i) m_lanes[i]->restore(c->lanes[i]);
        m_commonTime = c->extra.at(0);
        m_until = c->extra.at(1);
        m_moment = c->index;
        m_params = m_lanes.front()->parameters();  // side by side, the common DT
        replayForward(target, false);
    }
    m_replaying = false;
    m_until = -1.0;  // shown paused
    m_params = m_lanes.front()->parameters();
    m_stepDoubling = m_lanes.front()->integratorOptions().stepDoubling;
    m_failureReported = m_lanes.front()->failed();
    updateDtLimit();
}

void SimWorker::scrubToTime(double t) {
    if (m_lanes.empty() || m_recorder.empty()) return;
    if (m_running) pause();
    // From the last checkpoint before t, forward one moment at a time until t is reached.
    const auto& all = m_recorder.checkpoints();
    auto after = std::upper_bound(all.begin(), all.end(), t, [](double time, const simcore::TimelineCheckpoint& c) {
        return time <= c.lanes.front().diag.time;
    });
    goTo(after == all.begin() ? all.front().index : (after - 1)->index);
    const double reach = t - 1e-9 * std::max(1e-3, std::abs(t));
    while (m_moment < m_recorder.last() && m_lanes.front()->time() < reach) {
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
