#pragma once
// SimulationController: the GUI's handle on the simulation thread.
//
//   GUI thread                                              worker thread ("simulation")
//   SimulationController ── inbox: commands (closures) ──▶ SimWorker, between two steps
//        public signals ◀── outbox: takeFrame, grabbed, ── worker signals (connected
//        (emitted here)      rejections, runFailed, ...     directly, posted as closures)
//
// Both mailboxes (mailbox.h) hand their messages over under a std::mutex and wake the
// receiving thread through an eventfd, so nothing crosses the threads through Qt and
// ThreadSanitizer sees every hand-over even though Qt itself is not instrumented. Commands are applied between steps, in the order they were sent;
// frames come back through a one-frame slot — the newest wins, and while the GUI is busy the
// worker simply overwrites the slot, so frames are skipped instead of queued. The time-series
// rows of every recorded step are kept (history) for the plots and CSV export.

#include <QObject>
#include <QStringList>
#include <QThread>
#include <QVector3D>

#include "ui/frame.h"
#include "ui/mailbox.h"
#include "ui/sim_worker.h"

namespace elui {

class SimWorker;

class SimulationController : public QObject {
    Q_OBJECT
public:
    explicit SimulationController(QObject* parent = nullptr);
    // With the worker's wall clock given (a test moves its own; see sim_worker.h).
    SimulationController(WallClock clock, QObject* parent = nullptr);
    ~SimulationController() override;  // shuts the worker down, joins its thread, deletes it

    // The newest frame taken (nullptr before the first).
    const FramePtr& latest() const { return m_latest; }
    // Lane 0's recorded rows since the last reset (every step, at most one per kRowInterval).
    const std::vector<simcore::Diagnostics>& history() const { return m_history; }
    // Side by side: the other views' rows (view v >= 1 at index v - 1), at the same common
    // times; a failed view's end where it failed. Cut at a branch as the history is.
    const std::vector<std::vector<simcore::Diagnostics>>& viewHistory() const { return m_viewHistory; }
    // The abandoned future: lane 0's rows after the last branch's instant, as they were
    // before the branch (one level; empty when none or cleared).
    const std::vector<simcore::Diagnostics>& abandoned() const { return m_abandoned; }
    simcore::SceneKind sceneKind() const { return m_params.kind(); }
    const simcore::ParameterSet& parameters() const { return m_params; }
    QStringList integrators() const { return m_integrators; }
    bool running() const { return m_latest && m_latest->running; }
    QThread* workerThread() { return &m_thread; }
    SimWorker* worker() const { return m_worker; }
    // Commands sent and not yet taken by the worker (0 right after captureScene returns).
    std::size_t commandsInFlight() const { return m_inbox->pending(); }

    // --- commands (all asynchronous) ---
    void setScene(const simcore::ParameterSet& params, const QStringList& integrators);
    void setScene(const simcore::ParameterSet& params);  // keeps the integrators
    // A scene file (already read and validated): its scene, parameters and exact state, in one
    // lane with the file's integrator, or side by side with the given integrators.
    void openScene(const simlab::SceneFile& file, const QStringList& integrators = {});
    // A scene of several bodies (simcore::World; sim_worker_world.cpp): one world per integrator,
    // side by side with up to three.
    void setWorld(const simcore::WorldSpec& spec, const QStringList& integrators = {QStringLiteral("rk4")});
    // The body (from 0; -1: every body) a world's parameter edits go to.
    void setWorldBody(int body);
    // Whether the scene asked for last is one of several bodies.
    bool isWorld() const { return m_isWorld; }
    // Lane 0 as a scene file with its exact state. Blocks until the worker has applied every
    // command sent before and is between two steps (at most one tick, ~15 ms); the GUI never
    // reads the simulation itself.
    SceneCapture captureScene();
    // A world's run so far as elastic-lab-cli run --csv writes it (SimWorker::worldCsv);
    // empty for one body. Behind every command already sent.
    QByteArray worldCsv();
    void setIntegrator(const QString& name);             // lane 0 only, keeps the run
    // A parameter travels as its Param: the worker applies it to every lane, or reports
    // parameterRejected (out of range, or not a parameter of this scene).
    void setParameter(simcore::Param id, double value);
    // The same from a key given as text (a field, a test): looked up once here; a name that is
    // not in the table is rejected at once.
    void setParameter(const QString& key, double value);
    void setSpeed(Speed speed);
    void setStepDoubling(bool on);
    void setFloatPrecision(bool on);
    // The adaptive methods' tolerances (rk45, cvode-bdf, cvode-adams), every lane; logged for time travel.
    void setTolerances(double atol, double rtol);
    void setForcesWanted(bool on);
    void setErrorBandsWanted(bool on);  // fill the rows' error bands (Diagnostics::errors)
    void setStartKick(double innerVx, double outerVx);
    void run();
    void runUntil(double simulatedTime);
    void pause();
    void step();
    void reset();
    void grabAlongRay(const QVector3D& origin, const QVector3D& direction, double maxDistance);
    void moveAnchor(const QVector3D& anchor);
    void release();
    // Time travel (sim_worker.h): pause and show a recorded moment, re-simulated.
    void scrubTo(long moment);
    void scrubBy(long delta);  // relative to the moment shown: -1 is one step back
    void scrubToStart() { scrubTo(0); }
    void scrubToEnd();
    void scrubToTime(double simulatedTime);  // the first moment at or after it
    void setTimelineBudget(qulonglong bytes);
    void clearAbandoned();
    void selectAlongRay(const QVector3D& origin, const QVector3D& direction, double maxDistance);
    void selectParticle(int particle);  // its free-body diagram; < 0 clears

signals:
    // To the GUI (emitted on the GUI thread).
    void frameArrived(const elui::FramePtr& frame);
    void historyReset();
    void rowsAppended(int first, int count);
    void viewRowsAppended(int view, int first, int count);  // viewHistory()[view - 1] grew
    // A branch cut the history at `time`: what followed is now abandoned() (the history was
    // truncated: listeners redraw it whole).
    void historyBranched(double time);
    void abandonedChanged();  // abandoned() was cleared or replaced
    void sceneChanged(const std::shared_ptr<const elui::SceneData>& scene);
    void grabbed(int particle, const QVector3D& position);
    void parameterRejected(const QString& key, const QString& message);
    void sceneRejected(const QString& message);
    void runFailed(const QString& reason);
    void reachedTime(double simulatedTime);

private:
    void takeFrame();
    void restoreScene(const QString& message);
    // Queues (worker.*command)(args...) for the worker thread; args are copied here.
    template <class... Params, class... Args>
    void toWorker(void (SimWorker::*command)(Params...), Args... args);
    // Worker signal → slot(args...) on the GUI thread, through the outbox.
    template <class Signal, class Slot>
    void fromWorker(Signal signal, Slot slot);

    QThread m_thread;
    SimWorker* m_worker = nullptr;  // deleted by the destructor once its thread has ended
    Mailbox* m_inbox = nullptr;     // to the worker thread (the worker's child)
    Mailbox* m_outbox = nullptr;    // to this (GUI) thread (our child)
    FramePtr m_latest;
    std::vector<simcore::Diagnostics> m_history;
    std::vector<simcore::Diagnostics> m_abandoned;
    std::vector<std::vector<simcore::Diagnostics>> m_viewHistory;
    void appendRows(const std::vector<simcore::Diagnostics>& rows, std::size_t begin, std::size_t end);
    void cutHistory(double time);
    simcore::ParameterSet m_params;
    QStringList m_integrators{QStringLiteral("rk4")};
    quint64 m_sceneVersion = 0;
    bool m_isWorld = false;
};

// The history is capped: beyond this many rows every other old row is dropped.
inline constexpr std::size_t kMaxHistoryRows = 2'000'000;

}  // namespace elui
