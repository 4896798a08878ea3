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
    if (auto error = m_lanes.front()->setIntegrator(name.toStdString()))
        emit parameterRejected(QStringLiteral("integrator"), QString::fromStdString(*error));
    publish(true);
}

void SimWorker::setParameter(const QString& key, double value) {
    if (m_lanes.empty()) return;
    const std::string k = key.toStdString();
    const simcore::ParamSpec* spec = simcore::findParam(k);
    const bool rebuilds = spec && (spec->isShape() || spec->group == simcore::ParamGroup::Start);
    for (std::size_t i = 0; i < m_lanes.size(); ++i) {
        if (auto error = m_lanes[i]->setParameter(k, value)) {
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
    m_stepDoubling = on;
    for (auto& sim : m_lanes) {
        simcore::IntegratorOptions o = sim->integratorOptions();
        o.stepDoubling = on;
        sim->setIntegratorOptions(o);
    }
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
    m_until = -1.0;
    m_timer->start(m_speed == Speed::AsFastAsPossible ? 0 : 4);
    publish(true);
}

void SimWorker::runUntil(double simulatedTime) {
    if (m_lanes.empty()) return;
    if (!m_running) restartClock();
    m_running = true;
    m_until = simulatedTime;
    m_timer->start(0);
    publish(true);
}

void SimWorker::pause() {
    if (m_running) m_wallBeforeStart += since(m_clockStart);
    m_running = false;
    m_until = -1.0;
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
    publish(true);
}

void SimWorker::grabAlongRay(const QVector3D& origin, const QVector3D& direction, double maxDistance) {
    if (m_lanes.empty()) return;
    const Eigen::Vector3d o = toEigen(origin), d = toEigen(direction).normalized();
    const int particle = m_lanes.front()->pickAlongRay(o, d, maxDistance);
    if (particle < 0) return;
    const Eigen::Vector3d at = m_lanes.front()->positions().col(particle);
    for (auto& sim : m_lanes) sim->grab(particle, at);
    emit grabbed(particle, QVector3D(float(at.x()), float(at.y()), float(at.z())));
    publish(true);
}

void SimWorker::moveAnchor(const QVector3D& anchor) {
    for (auto& sim : m_lanes) sim->moveAnchor(toEigen(anchor));
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
    for (auto& sim : m_lanes) sim->release();
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
    if (m_lanes.size() == 1) {
        simcore::Simulation& sim = *m_lanes.front();
        const double until = m_until >= 0.0 ? m_until : std::numeric_limits<double>::infinity();
        sim.step(until);
        m_commonTime = sim.time();
    } else {
        // Side by side: every live lane reaches the same time after each common DT.
        double target = m_commonTime + m_params.get("dt");
        if (m_until >= 0.0) target = std::min(target, m_until);
        for (auto& sim : m_lanes)
            if (!sim->failed()) sim->advanceTo(target);
        m_commonTime = target;
    }
    ++m_rateSteps;
    recordRow();
    return true;
}

void SimWorker::recordRow() {
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
        m_historyReset = false;
    }
    m_slot.rows.insert(m_slot.rows.end(), m_rows.begin(), m_rows.end());
    m_rows.clear();
    m_published.store(m_slot.frame->serial);
    if (!m_slotPending) {
        m_slotPending = true;
        emit frameReady();
    }
}

}  // namespace elui
