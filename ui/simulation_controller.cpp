#include "ui/simulation_controller.h"

#include "ui/sim_worker.h"

namespace elui {

template <class... Params, class... Args>
void SimulationController::toWorker(void (SimWorker::*command)(Params...), Args... args) {
    m_inbox->post([w = m_worker, command, ... args = std::move(args)] { (w->*command)(args...); });
}

template <class Signal, class Slot>
void SimulationController::fromWorker(Signal signal, Slot slot) {
    // Runs on the worker thread as the signal is emitted: the arguments are copied into the
    // message there, and the slot runs on this thread.
    connect(
        m_worker, signal, this,
        [this, slot](auto... args) { m_outbox->post([this, slot, args...] { (this->*slot)(args...); }); },
        Qt::DirectConnection);
}

SimulationController::SimulationController(QObject* parent) : SimulationController(steadyWallClock(), parent) {}

SimulationController::SimulationController(WallClock clock, QObject* parent)
    : QObject(parent), m_worker(new SimWorker(std::move(clock))), m_inbox(new Mailbox(m_worker)), m_outbox(new Mailbox(this)) {
    qRegisterMetaType<elui::FramePtr>();
    m_thread.setObjectName(QStringLiteral("simulation"));
    m_worker->moveToThread(&m_thread);

    fromWorker(&SimWorker::frameReady, &SimulationController::takeFrame);
    fromWorker(&SimWorker::grabbed, &SimulationController::grabbed);
    fromWorker(&SimWorker::parameterRejected, &SimulationController::parameterRejected);
    fromWorker(&SimWorker::sceneRejected, &SimulationController::restoreScene);
    fromWorker(&SimWorker::runFailed, &SimulationController::runFailed);
    fromWorker(&SimWorker::reachedTime, &SimulationController::reachedTime);

    // Nothing is posted to the worker before its thread has started and made its event
    // dispatcher (QThread emits started() after that, on the new thread), where the inbox's
    // wake-up notifier registers as it moves in: this wait orders all of that before the
    // first command.
    Latch started;
    const auto connection =
        connect(&m_thread, &QThread::started, &m_thread, [&started] { started.open(); }, Qt::DirectConnection);
    m_thread.start();
    started.wait();
    disconnect(connection);
}

SimulationController::~SimulationController() {
    // The last command, behind every one already sent: the worker stops, destroys its
    // simulations and quits its event loop, all on its own thread, and runs none of our code
    // afterwards (Mailbox::call returns once it has). Then the thread ends and the empty worker
    // (with the inbox) is deleted here.
    m_inbox->call([w = m_worker] { w->shutdown(); });
    m_thread.wait();
    delete m_worker;
    m_worker = nullptr;
    m_inbox = nullptr;
}

void SimulationController::restoreScene(const QString& message) {
    // The worker kept the scene it had: so do we (what setScene/openScene assumed is undone).
    if (m_latest) {
        m_params = m_latest->parameters;
        m_integrators.clear();
        for (const LaneFrame& lane : m_latest->lanes) m_integrators << lane.integrator;
    }
    emit sceneRejected(message);
}

void SimulationController::takeFrame() {
    FrameBatch batch = m_worker->takeBatch();
    if (!batch.frame) return;
    const bool newScene = !m_latest || m_latest->scene != batch.frame->scene;
    m_latest = std::move(batch.frame);
    m_params = m_latest->parameters;
    // The scene first: listeners rebuild for it before the new history arrives.
    if (newScene) emit sceneChanged(m_latest->scene);
    if (batch.historyReset) {
        m_history.clear();
        m_viewHistory.clear();
        const bool hadAbandoned = !m_abandoned.empty();
        m_abandoned.clear();
        emit historyReset();
        if (hadAbandoned) emit abandonedChanged();
    }
    std::size_t done = 0;
    for (const FrameBatch::Branch& b : batch.branches) {
        appendRows(batch.rows, done, b.rowsBefore);
        done = b.rowsBefore;
        cutHistory(b.time);
    }
    appendRows(batch.rows, done, batch.rows.size());
    if (m_viewHistory.size() < batch.laneRows.size()) m_viewHistory.resize(batch.laneRows.size());
    for (std::size_t v = 0; v < batch.laneRows.size(); ++v) {
        const auto& rows = batch.laneRows[v];
        if (rows.empty()) continue;
        auto& history = m_viewHistory[v];
        if (history.size() + rows.size() > kMaxHistoryRows) {
            std::size_t w = 0;
            for (std::size_t r = 0; r < history.size(); r += 2) history[w++] = history[r];
            history.resize(w);
        }
        const int first = int(history.size());
        history.insert(history.end(), rows.begin(), rows.end());
        emit viewRowsAppended(int(v + 1), first, int(rows.size()));
    }
    emit frameArrived(m_latest);
}

void SimulationController::appendRows(const std::vector<simcore::Diagnostics>& rows, std::size_t begin,
                                      std::size_t end) {
    if (begin >= end) return;
    const std::size_t count = end - begin;
    if (m_history.size() + count > kMaxHistoryRows) {
        // Keep the whole run visible at half the resolution.
        std::size_t w = 0;
        for (std::size_t r = 0; r < m_history.size(); r += 2) m_history[w++] = m_history[r];
        m_history.resize(w);
        emit historyReset();
        emit rowsAppended(0, int(m_history.size()));
    }
    const int first = int(m_history.size());
    m_history.insert(m_history.end(), rows.begin() + std::ptrdiff_t(begin), rows.begin() + std::ptrdiff_t(end));
    emit rowsAppended(first, int(count));
}

void SimulationController::cutHistory(double time) {
    // Rows after the branch's instant are the abandoned future (replacing an older one).
    auto cut = std::upper_bound(m_history.begin(), m_history.end(), time,
                                [](double t, const simcore::Diagnostics& d) { return t < d.time; });
    m_abandoned.assign(cut, m_history.end());
    m_history.erase(cut, m_history.end());
    for (auto& history : m_viewHistory)
        history.erase(std::upper_bound(history.begin(), history.end(), time,
                                       [](double t, const simcore::Diagnostics& d) { return t < d.time; }),
                      history.end());
    emit historyBranched(time);
    emit abandonedChanged();
}

void SimulationController::clearAbandoned() {
    if (m_abandoned.empty()) return;
    m_abandoned.clear();
    emit abandonedChanged();
}

void SimulationController::scrubTo(long moment) { toWorker(&SimWorker::scrubTo, moment); }
void SimulationController::scrubBy(long delta) { toWorker(&SimWorker::scrubBy, delta); }
void SimulationController::scrubToEnd() { toWorker(&SimWorker::scrubToEnd); }
void SimulationController::scrubToTime(double t) { toWorker(&SimWorker::scrubToTime, t); }
void SimulationController::setTimelineBudget(qulonglong bytes) { toWorker(&SimWorker::setTimelineBudget, bytes); }

void SimulationController::setScene(const simcore::ParameterSet& params, const QStringList& integrators) {
    m_params = params;
    m_isWorld = false;
    m_integrators = integrators;
    toWorker(&SimWorker::setScene, params, integrators);
}
void SimulationController::setScene(const simcore::ParameterSet& params) { setScene(params, m_integrators); }
void SimulationController::openScene(const simlab::SceneFile& file, const QStringList& integrators) {
    m_params = file.params;
    m_isWorld = file.world.has_value();
    m_integrators = integrators.isEmpty() ? QStringList{QString::fromStdString(file.integrator)} : integrators;
    toWorker(&SimWorker::openScene, file, m_integrators);
}
void SimulationController::setWorld(const simcore::WorldSpec& spec, const QStringList& integrators) {
    m_params = spec.bodies.front().params;
    m_integrators = integrators.isEmpty() ? QStringList{QStringLiteral("rk4")} : integrators;
    m_isWorld = true;
    toWorker(&SimWorker::setWorld, spec, m_integrators);
}
void SimulationController::setWorldBody(int body) { toWorker(&SimWorker::setWorldBody, body); }
SceneCapture SimulationController::captureScene() {
    SceneCapture capture;
    // Behind every command already sent, so the text includes their effect.
    m_inbox->call([&capture, w = m_worker] { capture = w->captureScene(); });
    return capture;
}
QByteArray SimulationController::worldCsv() {
    std::string text;
    m_inbox->call([&text, w = m_worker] { text = w->worldCsv(); });
    return QByteArray::fromStdString(text);
}
void SimulationController::setIntegrator(const QString& name) {
    if (!m_integrators.isEmpty()) m_integrators[0] = name;
    toWorker(&SimWorker::setIntegrator, name);
}
void SimulationController::setParameter(simcore::Param id, double value) {
    toWorker(&SimWorker::setParameter, id, value);
}
void SimulationController::setParameter(const QString& key, double value) {
    const std::string k = key.toStdString();
    if (const simcore::ParamSpec* spec = simcore::findParam(k)) {
        setParameter(spec->id, value);
        return;
    }
    const auto error = simcore::ParameterSet(m_params.kind()).set(k, value);  // the table's message
    emit parameterRejected(key, QString::fromStdString(error.value_or(std::string())));
}
void SimulationController::setSpeed(Speed speed) { toWorker(&SimWorker::setSpeed, int(speed)); }
void SimulationController::setStepDoubling(bool on) { toWorker(&SimWorker::setStepDoubling, on); }
void SimulationController::setFloatPrecision(bool on) { toWorker(&SimWorker::setFloatPrecision, on); }
void SimulationController::setTolerances(double atol, double rtol) { toWorker(&SimWorker::setTolerances, atol, rtol); }
void SimulationController::setForcesWanted(bool on) { toWorker(&SimWorker::setForcesWanted, on); }
void SimulationController::setErrorBandsWanted(bool on) { toWorker(&SimWorker::setErrorBandsWanted, on); }
void SimulationController::setStartKick(double innerVx, double outerVx) {
    toWorker(&SimWorker::setStartKick, innerVx, outerVx);
}
void SimulationController::run() { toWorker(&SimWorker::run); }
void SimulationController::runUntil(double t) { toWorker(&SimWorker::runUntil, t); }
void SimulationController::pause() { toWorker(&SimWorker::pause); }
void SimulationController::step() { toWorker(&SimWorker::stepOnce); }
void SimulationController::reset() { toWorker(&SimWorker::reset); }
void SimulationController::grabAlongRay(const QVector3D& o, const QVector3D& d, double maxDistance) {
    toWorker(&SimWorker::grabAlongRay, o, d, maxDistance);
}
void SimulationController::moveAnchor(const QVector3D& anchor) { toWorker(&SimWorker::moveAnchor, anchor); }
void SimulationController::release() { toWorker(&SimWorker::release); }
void SimulationController::selectParticle(int particle) { toWorker(&SimWorker::selectParticle, particle); }
void SimulationController::selectAlongRay(const QVector3D& o, const QVector3D& d, double maxDistance) {
    toWorker(&SimWorker::selectAlongRay, o, d, maxDistance);
}

}  // namespace elui
