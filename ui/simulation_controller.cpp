#include "simulation_controller.h"

#include "sim_worker.h"

namespace elui {

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
    qRegisterMetaType<elui::FramePtr>();
    qRegisterMetaType<simcore::ParameterSet>("simcore::ParameterSet");
    qRegisterMetaType<simcore::SceneFile>("simcore::SceneFile");
    m_thread.setObjectName(QStringLiteral("simulation"));
    m_worker = new SimWorker;
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);

    auto q = Qt::QueuedConnection;
    connect(this, &SimulationController::requestScene, m_worker, &SimWorker::setScene, q);
    connect(this, &SimulationController::requestOpen, m_worker, &SimWorker::openScene, q);
    connect(this, &SimulationController::requestIntegrator, m_worker, &SimWorker::setIntegrator, q);
    connect(this, &SimulationController::requestParameter, m_worker, &SimWorker::setParameter, q);
    connect(this, &SimulationController::requestSpeed, m_worker, &SimWorker::setSpeed, q);
    connect(this, &SimulationController::requestStepDoubling, m_worker, &SimWorker::setStepDoubling, q);
    connect(this, &SimulationController::requestForces, m_worker, &SimWorker::setForcesWanted, q);
    connect(this, &SimulationController::requestKick, m_worker, &SimWorker::setStartKick, q);
    connect(this, &SimulationController::requestRun, m_worker, &SimWorker::run, q);
    connect(this, &SimulationController::requestRunUntil, m_worker, &SimWorker::runUntil, q);
    connect(this, &SimulationController::requestPause, m_worker, &SimWorker::pause, q);
    connect(this, &SimulationController::requestStep, m_worker, &SimWorker::stepOnce, q);
    connect(this, &SimulationController::requestReset, m_worker, &SimWorker::reset, q);
    connect(this, &SimulationController::requestGrab, m_worker, &SimWorker::grabAlongRay, q);
    connect(this, &SimulationController::requestMove, m_worker, &SimWorker::moveAnchor, q);
    connect(this, &SimulationController::requestRelease, m_worker, &SimWorker::release, q);

    connect(m_worker, &SimWorker::frameReady, this, &SimulationController::takeFrame, q);
    connect(m_worker, &SimWorker::grabbed, this, &SimulationController::grabbed, q);
    connect(m_worker, &SimWorker::parameterRejected, this, &SimulationController::parameterRejected, q);
    connect(m_worker, &SimWorker::sceneRejected, this, &SimulationController::restoreScene, q);
    connect(m_worker, &SimWorker::runFailed, this, &SimulationController::runFailed, q);
    connect(m_worker, &SimWorker::reachedTime, this, &SimulationController::reachedTime, q);
    m_thread.start();
}

SimulationController::~SimulationController() {
    // Stop stepping first (queued behind any command already sent), then end the thread; the
    // worker and its simulations are deleted on their own thread as it finishes.
    QMetaObject::invokeMethod(m_worker, &SimWorker::shutdown, Qt::BlockingQueuedConnection);
    m_thread.quit();
    m_thread.wait();
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
        emit historyReset();
    }
    if (!batch.rows.empty()) {
        if (m_history.size() + batch.rows.size() > kMaxHistoryRows) {
            // Keep the whole run visible at half the resolution.
            std::size_t w = 0;
            for (std::size_t r = 0; r < m_history.size(); r += 2) m_history[w++] = m_history[r];
            m_history.resize(w);
            emit historyReset();
            emit rowsAppended(0, int(m_history.size()));
        }
        const int first = int(m_history.size());
        m_history.insert(m_history.end(), batch.rows.begin(), batch.rows.end());
        emit rowsAppended(first, int(batch.rows.size()));
    }
    emit frameArrived(m_latest);
}

void SimulationController::setScene(const simcore::ParameterSet& params, const QStringList& integrators) {
    m_params = params;
    m_integrators = integrators;
    emit requestScene(params, integrators);
}
void SimulationController::setScene(const simcore::ParameterSet& params) { setScene(params, m_integrators); }
void SimulationController::openScene(const simcore::SceneFile& file, const QStringList& integrators) {
    m_params = file.params;
    m_integrators = integrators.isEmpty() ? QStringList{QString::fromStdString(file.integrator)} : integrators;
    emit requestOpen(file, m_integrators);
}
SceneCapture SimulationController::captureScene() {
    SceneCapture capture;
    // Queued behind every command already sent, so the text includes their effect.
    QMetaObject::invokeMethod(
        m_worker, [&capture, this] { capture = m_worker->captureScene(); }, Qt::BlockingQueuedConnection);
    return capture;
}
void SimulationController::setIntegrator(const QString& name) {
    if (!m_integrators.isEmpty()) m_integrators[0] = name;
    emit requestIntegrator(name);
}
void SimulationController::setParameter(const QString& key, double value) { emit requestParameter(key, value); }
void SimulationController::setSpeed(Speed speed) { emit requestSpeed(int(speed)); }
void SimulationController::setStepDoubling(bool on) { emit requestStepDoubling(on); }
void SimulationController::setForcesWanted(bool on) { emit requestForces(on); }
void SimulationController::setStartKick(double innerVx, double outerVx) { emit requestKick(innerVx, outerVx); }
void SimulationController::run() { emit requestRun(); }
void SimulationController::runUntil(double t) { emit requestRunUntil(t); }
void SimulationController::pause() { emit requestPause(); }
void SimulationController::step() { emit requestStep(); }
void SimulationController::reset() { emit requestReset(); }
void SimulationController::grabAlongRay(const QVector3D& o, const QVector3D& d, double maxDistance) {
    emit requestGrab(o, d, maxDistance);
}
void SimulationController::moveAnchor(const QVector3D& anchor) { emit requestMove(anchor); }
void SimulationController::release() { emit requestRelease(); }

}  // namespace elui
