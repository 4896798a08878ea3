#pragma once
// SimWorker: owns the simulations and steps them on its own thread (see simulation_controller.h).
// It is the QObject that takes the commands and orchestrates four parts, one job each:
//
//   Lanes           (lanes.h)            one simulation per integrator, stepped side by side
//                                        to a common time; edits and mouse input go to all
//   Pacer           (pacer.h)            the wall clock: where simulated time should be, the
//                                        tick budget, falling behind, steps/s, frames due
//   FramePublisher  (frame_publisher.h)  rows since the last frame, the slot the GUI takes from
//   the timeline    (here)               recorder, input log, scrubbing and replay
//
// Every command runs on the worker thread between two steps (the controller's inbox delivers
// them as events, never inside a timer tick), so a parameter edit, a grab, a reset ... can
// never land in the middle of a step. Stepping is driven by a timer:
// each tick advances simulated time to where the clock says it should be (real time, a
// fraction of it, or as far as a time budget allows), then publishes one frame.
//
// Time travel: every moment of the run is recorded (simcore::TimelineRecorder: checkpoints of
// every lane every K steps within a memory budget, plus the log of what was done between
// steps: parameter and integrator edits, step doubling, the pointer, run-until targets).
// scrubTo() pauses and shows a recorded moment, re-simulated from the checkpoint before it and
// the log, so it is the original frame bit for bit. Anything that changes the run at a
// scrubbed moment (an edit, a grab, a step, Run) is a branch: the future after it is
// forgotten here (the GUI keeps its rows as the abandoned future) and the run goes on from it.
// The timeline stays in SimWorker because a replay is orchestration of the other three: it
// steps the lanes, applies the logged edits (which can emit a rejection), keeps rows and
// frames back while it re-simulates, and marks branches in the publisher; as a class of its
// own it would need a way back into all of them and into this object's signals.

#include <memory>
#include <string>
#include <vector>

#include <QObject>
#include <QStringList>
#include <QVector3D>

#include "simcore/timeline.h"
#include "simcore/world.h"
#include "ui/frame.h"
#include "ui/frame_publisher.h"
#include "ui/lanes.h"
#include "ui/pacer.h"

class QTimer;

namespace elui {

class SimWorker : public QObject {
    Q_OBJECT
public:
    explicit SimWorker(WallClock clock = steadyWallClock());
    ~SimWorker() override;

    // Thread-safe: the newest frame and the rows recorded since the last take.
    FrameBatch takeBatch() { return m_publisher.takeBatch(); }
    // Thread-safe: the serial number of the newest frame published (0: none yet).
    quint64 publishedSerial() const { return m_publisher.publishedSerial(); }
    // Lane 0 as a scene file with its exact state. Worker thread only (between two steps).
    SceneCapture captureScene() const;
    // A world's run so far as the CSV of elastic-lab-cli run --csv (simlab::worldColumns: per
    // body columns, momentum, min_gap), one row per recorded row (at most one per kRowInterval
    // of simulated time; after a branch the abandoned future is not in it); empty for one
    // body. Worker thread only.
    std::string worldCsv() const;
    // The most rows of a world kept for worldCsv: beyond, every other old row is dropped.
    static constexpr std::size_t kMaxWorldRows = 200'000;

    // Smallest simulated interval between two recorded time-series rows [s].
    static constexpr double kRowInterval = FramePublisher::kRowInterval;

    // --- commands: worker thread only (SimulationController posts them through its inbox) ---
    // Builds the lanes. An impossible scene keeps the old one and reports sceneRejected.
    void setScene(const simcore::ParameterSet& params, const QStringList& integrators);
    // Builds the lanes from a scene file and, if it holds one, gives every lane its saved state
    // (time and step counter included), so the run resumes exactly. No start kick. A file that
    // cannot be built keeps the old scene and reports sceneRejected.
    void openScene(const simlab::SceneFile& file, const QStringList& integrators);
    // A scene of several bodies: one simcore::World per integrator instead of the one-body lanes
    // (side by side with up to three), on the same timeline as one body. A world that cannot be
    // built keeps the old scene and reports sceneRejected.
    void setWorld(const simcore::WorldSpec& spec, const QStringList& integrators);
    // The body (from 0) the parameter edits of a world go to; -1: every body.
    void setWorldBody(int body);
    // Changes lane 0's integrator in place (single mode: the run continues from here).
    void setIntegrator(const QString& name);
    void setParameter(simcore::Param id, double value);
    void setSpeed(int speed);
    void setStepDoubling(bool on);
    // Precision float (lanes.h): lane 0 steps on the float path where it can. Logged on the
    // timeline, as an edit.
    void setFloatPrecision(bool on);
    void setTolerances(double atol, double rtol);
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
    Lanes::List buildLanes(const simcore::ParameterSet& params, const QStringList& integrators);
    bool stepAll();                       // one common DT for every lane; false: nothing ran
    void startHistory();
    void afterRebuild();
    void recordRow();                     // lane 0's row, unless re-simulating
    void publish(bool force);             // a frame, if one is due (always when forced)
    // A failed lane's state some time before its failure (Frame's LaneFrame::stretchStart).
    static constexpr double kFailureStretch = 0.2;  // [s]
    std::shared_ptr<const simcore::SimulationSnapshot> stretchStart(std::size_t lane, const simcore::Failure& failure);

    // Time travel. What was done between two steps, replayed when a moment is re-simulated.
    struct Input {
        enum Kind { Parameter, Integrator, StepDoubling, Tolerances, Grab, Move, Release, Until, Precision, World };
        long moment = 0;                  // done at this moment (after its step)
        double time = 0.0;                // lane 0's simulated time then [s]
        Kind kind = Parameter;
        simcore::Param param = simcore::Param::Count;  // Parameter
        std::string key;                  // Integrator: the name
        double value = 0.0;               // Parameter, StepDoubling and Precision (0/1), Until, Tolerances: atol
        double value2 = 0.0;              // Tolerances: rtol
        int particle = -1;                // Grab
        Eigen::Vector3d anchor = Eigen::Vector3d::Zero();  // Grab, Move
        // World: every lane's world built again with this spec and its integrator in
        // `integrators`, going on from its state (a live edit of a world, an integrator change).
        std::shared_ptr<const simcore::WorldSpec> spec;
        std::vector<std::string> integrators;
    };
    // A switch (step doubling, precision float) as a logged input; before the first scene, kept.
    void logSwitch(Input::Kind kind, bool on);
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

    // --- a world (sim_worker_world.cpp) ---
    bool worldMode() const { return !m_worlds.empty(); }
    // A scene to run: the lanes or a world.
    bool hasRun() const { return worldMode() || !m_lanes.empty(); }
    // Lane 0's simulated time, or the worlds' common time [s].
    double leadTime() const;
    // Lane 0's world (worldMode() only).
    simcore::World& world() { return *m_worlds.front(); }
    const simcore::World& world() const { return *m_worlds.front(); }
    std::vector<const simcore::World*> worldViews() const;
    std::vector<std::string> worldIntegrators() const;
    // Every world lane has failed (the one alone, or all side by side): the run cannot go on.
    bool worldsStopped() const;
    bool worldsRestorable() const;
    // Builds one world per integrator; with `from` (the worlds running so far) each goes on from
    // its lane's state and accounts (an edit that keeps the shape, an integrator change), else
    // from its start.
    bool buildWorlds(std::shared_ptr<const simcore::WorldSpec> spec, const std::vector<std::string>& integrators,
                     const std::vector<std::unique_ptr<simcore::World>>* from);
    // The world's integrator options: step doubling and the tolerances as the lanes keep them.
    simcore::IntegratorOptions worldOptions() const;
    void applyWorldInput(const Input& input);
    // Back to a checkpoint of the world (built again when its spec or integrator differs).
    void restoreWorld(const simcore::TimelineCheckpoint& c);
    void worldStarted();                  // a new world or its start again: rows, clocks, frame
    void worldSceneData();
    bool stepWorld();
    void tickWorld();
    void publishWorld();
    // World lane `lane` as a frame shows it, its distance measured to lane `reference`.
    LaneFrame worldLaneFrame(std::size_t lane, int reference);
    void recordWorldLaneRows();           // side by side: the other lanes' totals for the plots
    void setWorldParameter(simcore::Param id, double value);
    // The world's rows for worldCsv, recorded as the plots' rows are; cut at a branch.
    void recordWorldRow();
    void cutWorldRows(double time);
    std::vector<simcore::WorldDiagnostics> m_worldRows;
    std::vector<std::unique_ptr<simcore::World>> m_worlds;  // one per integrator (lane)
    double m_worldTime = 0.0;             // the time every live world has reached [s]
    std::shared_ptr<const simcore::WorldSpec> m_worldSpec;  // the worlds', shared with the frames
    int m_worldBody = 0;

    Lanes m_lanes;
    Pacer m_pacer;
    FramePublisher m_publisher;
    std::shared_ptr<const SceneData> m_scene;
    quint64 m_sceneVersion = 0;
    simcore::ParameterSet m_params;
    QTimer* m_timer = nullptr;

    double m_until = -1.0;                // runUntil target, < 0: none
    bool m_forcesWanted = false;
    bool m_bandsWanted = false;
    int m_selected = -1;                  // the particle whose force breakdown frames carry
    bool m_failureReported = false;
    // Per lane: the stretch start given for its failure, and that failure's step.
    std::vector<std::pair<std::shared_ptr<const simcore::SimulationSnapshot>, long>> m_stretchStarts;

    simcore::TimelineRecorder m_recorder;
    std::vector<Input> m_inputs;          // by moment, in the order they were done
    // Lane 0's state when the timeline began (Frame::runStart).
    std::shared_ptr<const simcore::SimulationSnapshot> m_runStart;
    // The simulated time of the first input on the timeline that changes the physics.
    double physicsChangedAt() const;
    long m_moment = 0;                    // the moment the lanes are at
    bool m_replaying = false;             // re-simulating: no rows, no recording, no frames
    double m_firstTime = 0.0, m_lastTime = 0.0;  // lane 0's time at the first and newest moment
};

}  // namespace elui
