#pragma once
// SimWorker: owns the simulations and steps them on its own thread (see simulation_controller.h).
//
// Every command runs on the worker thread between two steps (the controller's inbox delivers
// them as events, never inside a timer tick), so a parameter edit, a grab, a reset ... can
// never land in the middle of a step. Stepping is driven by a timer:
// each tick advances simulated time to where the clock says it should be (real time, a
// fraction of it, or as far as a time budget allows), then publishes one frame.
//
// Lanes: one simulation per integrator. Side by side, every lane starts from the same
// state, gets the same parameter edits and the same mouse input, and is advanced to the
// same simulated time after every step of the common DT.
//
// Time travel: every moment of the run is recorded (simcore::TimelineRecorder: checkpoints of
// every lane every K steps within a memory budget, plus the log of what was done between
// steps: parameter and integrator edits, step doubling, the pointer, run-until targets).
// scrubTo() pauses and shows a recorded moment, re-simulated from the checkpoint before it and
// the log, so it is the original frame bit for bit. Anything that changes the run at a
// scrubbed moment (an edit, a grab, a step, Run) is a branch: the future after it is
// forgotten here (the GUI keeps its rows as the abandoned future) and the run goes on from it.

#include <algorithm>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include <QObject>
#include <QStringList>
#include <QVector3D>

#include "frame.h"
#include "timeline.h"

class QTimer;

namespace elui {

// Monotonic wall time in seconds. The worker reads the wall only through this: its pacing
// (real time, a fraction of it), the tick budget, the frame rate and the steps-per-second
// meter. The default is std::chrono::steady_clock; a test passes a clock it moves itself.
using WallClock = std::function<double()>;
WallClock steadyWallClock();

class SimWorker : public QObject {
    Q_OBJECT
public:
    explicit SimWorker(WallClock clock = steadyWallClock());
    ~SimWorker() override;

    // Thread-safe: the newest frame and the rows recorded since the last take.
    FrameBatch takeBatch();
    // Thread-safe: the serial number of the newest frame published (0: none yet).
    quint64 publishedSerial() const { return m_published.load(); }
    // Lane 0 as a scene file with its exact state. Worker thread only (between two steps).
    SceneCapture captureScene() const;

    // Smallest simulated interval between two recorded time-series rows [s].
    static constexpr double kRowInterval = 1e-3;

    // --- commands: worker thread only (SimulationController posts them through its inbox) ---
    // Builds the lanes. An impossible scene keeps the old one and reports sceneRejected.
    void setScene(const simcore::ParameterSet& params, const QStringList& integrators);
    // Builds the lanes from a scene file and, if it holds one, gives every lane its saved state
    // (time and step counter included), so the run resumes exactly. No start kick. A file that
    // cannot be built keeps the old scene and reports sceneRejected.
    void openScene(const simcore::SceneFile& file, const QStringList& integrators);
    // Changes lane 0's integrator in place (single mode: the run continues from here).
    void setIntegrator(const QString& name);
    void setParameter(simcore::Param id, double value);
    void setSpeed(int speed);
    void setStepDoubling(bool on);
    void setForcesWanted(bool on);
    // Whether each recorded row gets its error bands (Simulation::observableErrors: two
    // measurements per row, so only while the plots show them).
    void setErrorBandsWanted(bool on);
    // Velocity given to every inner (+) and outer (-) particle along x at each start [m/s].
    void setStartKick(double innerVx, double outerVx);

    void run();
    void runUntil(double simulatedTime);  // runs as fast as possible, pauses at that time
    void pause();
    void stepOnce();
    void reset();

    // --- time travel ---
    // Pauses and shows the recorded moment `moment` (clamped to the recorded ones).
    void scrubTo(long moment);
    void scrubBy(long delta);             // relative to the moment shown (-1: one step back)
    void scrubToEnd();                    // the newest moment recorded
    // The first recorded moment at which lane 0's simulated time is at least t (the newest
    // when none is).
    void scrubToTime(double t);
    // The checkpoints' memory budget (a smaller one thins them at once) [bytes].
    void setTimelineBudget(qulonglong bytes);

    // Grabs the outer particle nearest the ray (lane 0 picks, every lane grabs the same one).
    void grabAlongRay(const QVector3D& origin, const QVector3D& direction, double maxDistance);
    void moveAnchor(const QVector3D& anchor);
    void release();
    // Selects the outer particle nearest the ray for its free-body diagram (every frame then
    // carries its force breakdown); a ray that meets none clears the selection.
    void selectAlongRay(const QVector3D& origin, const QVector3D& direction, double maxDistance);
    // Selects a particle by index (< 0 or out of range: clears), as a click on it would.
    void selectParticle(int particle);

    // The last command: stops, and destroys the timer, the simulations and everything else
    // made or touched on this thread, here, then quits the thread's event loop. Nothing of the
    // worker runs afterwards; the controller joins the thread and deletes the (empty) object.
    void shutdown();

    // Emitted on the worker thread. The controller connects them directly and hands them on
    // through its outbox, so their arguments never travel through Qt's event queue.
signals:
    void frameReady();                    // a frame waits in the slot (emitted once per take)
    void grabbed(int particle, const QVector3D& position);
    void parameterRejected(const QString& key, const QString& message);
    void sceneRejected(const QString& message);
    void runFailed(const QString& reason);
    void reachedTime(double simulatedTime);

private:
    void tick();
    // The lanes for params, one per integrator; empty (after sceneRejected) when impossible.
    std::vector<std::unique_ptr<simcore::Simulation>> buildLanes(const simcore::ParameterSet& params,
                                                                 const QStringList& integrators);
    bool stepAll();                       // one common DT for every lane; false: nothing ran
    void restartClock();
    void applyKick();
    void startHistory();
    void afterRebuild();
    void recordRow();
    void publish(bool force);
    bool allFailed() const;
    void updateDtLimit();

    // Time travel. What was done between two steps, replayed when a moment is re-simulated.
    struct Input {
        enum Kind { Parameter, Integrator, StepDoubling, Grab, Move, Release, Until };
        long moment = 0;                  // done at this moment (after its step)
        Kind kind = Parameter;
        simcore::Param param = simcore::Param::Count;  // Parameter
        std::string key;                  // Integrator: the name
        double value = 0.0;               // Parameter, StepDoubling (0/1), Until
        int particle = -1;                // Grab
        Eigen::Vector3d anchor = Eigen::Vector3d::Zero();  // Grab, Move
    };
    // Logs an input done now (a branch first when the moment shown is not the newest).
    void logInput(Input input);
    void applyInput(const Input& input);
    void setUntil(double until);          // m_until, logged
    void branch();                        // forgets the future after the moment shown
    void recordMoment();                  // after a step: the next moment
    void startTimeline();
    // Steps from the moment shown to `target` applying the log (the inputs at the moment shown
    // too unless already applied). Stops early where a lane cannot be re-simulated exactly
    // (CVODE): the moment shown is then the last exact one.
    void replayForward(long target, bool inputsAtStartApplied);
    void goTo(long target);               // scrubTo without the frame
    TimelineInfo timelineInfo() const;

    std::vector<std::unique_ptr<simcore::Simulation>> m_lanes;
    std::shared_ptr<const SceneData> m_scene;
    quint64 m_sceneVersion = 0;
    simcore::ParameterSet m_params;
    QTimer* m_timer = nullptr;

    bool m_running = false;
    Speed m_speed = Speed::RealTime;
    double m_until = -1.0;                // runUntil target, < 0: none
    bool m_forcesWanted = false;
    bool m_bandsWanted = false;
    int m_selected = -1;                  // the particle whose force breakdown frames carry
    bool m_stepDoubling = false;
    int m_threads = std::max(1, simcore::hardwareThreads() - 1);  // force-evaluation threads
    double m_kickInner = 0.0, m_kickOuter = 0.0;
    double m_dtLimit = 0.0;               // estimated explicit stability limit on DT [s]
    double m_commonTime = 0.0;            // the time every live lane has reached [s]

    // Clock: simulated time at the last (re)start, and wall time since then [s].
    double since(double wallStart) const { return m_now() - wallStart; }
    WallClock m_now;
    double m_clockStart = -1.0;           // wall time of the last (re)start, < 0: never started
    double m_clockSimStart = 0.0;
    double m_wallBeforeStart = 0.0;       // wall time run before the last start [s]
    bool m_fallingBehind = false;
    double m_rateStart = 0.0;
    long m_rateSteps = 0;
    double m_stepsPerSecond = 0.0;
    double m_publishStart = 0.0;
    double m_lastRowTime = -1.0;
    bool m_failureReported = false;

    simcore::TimelineRecorder m_recorder;
    std::vector<Input> m_inputs;          // by moment, in the order they were done
    long m_moment = 0;                    // the moment the lanes are at
    bool m_replaying = false;             // re-simulating: no rows, no recording, no frames
    double m_firstTime = 0.0, m_lastTime = 0.0;  // lane 0's time at the first and newest moment
    std::vector<FrameBatch::Branch> m_branches;  // since the last publish

    std::vector<simcore::Diagnostics> m_rows;  // recorded since the last publish (worker only)
    bool m_historyReset = true;
    quint64 m_serial = 0;
    std::atomic<quint64> m_published{0};

    std::mutex m_slotMutex;               // guards the three fields below
    FrameBatch m_slot;
    bool m_slotPending = false;
};

}  // namespace elui
