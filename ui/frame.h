#pragma once
// Frame: an immutable snapshot of the running simulation(s), made on the worker thread and
// handed to the GUI by shared pointer. The GUI never touches simcore::Simulation itself.
//
//   worker thread                         GUI thread
//   ─────────────                         ──────────
//   step, step, step ... ──publish──▶ [ latest frame slot ] ──take──▶ viewport, docks, plots
//                                      (newest wins; the rows of
//                                       every step are kept)
//
// One frame holds one lane per integrator (one in normal mode, up to three side by side).
// The scene part (topology, rest lengths, box) changes only when the body is rebuilt; it is
// shared between frames, so the viewport uploads topology only when `scene` changes.

#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <QMetaType>
#include <QString>
#include <QVector3D>

#include "simcore/body.h"
#include "simcore/forces.h"
#include "simcore/params.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/scenefile.h"
#include "simlab/stability.h"

#include "ui/body_measures.h"

namespace elui {

// Topology and everything else that changes only on a rebuild.
struct SceneData {
    quint64 version = 0;                  // increases on every rebuild
    simcore::SceneKind kind = simcore::SceneKind::Ring2d;
    simcore::Topology topology;
    Eigen::Vector3d boxCentre = Eigen::Vector3d::Zero();
    double boxHalfSize = 2.5;             // [m]
    double bodyRadius = 2.0;              // [m] rough size of the body, for the camera
    // What the table's values mean for this body: per-particle and per-spring values at its
    // resolution under its scaling (simcore::bodyValuesText).
    QString bodyValues;
    // The pre-run check of lane 0's explicit method at the current DT (simlab::stabilityAdvice):
    // the warning (said in the window's language when shown: failure_text.h) with a step
    // predicted stable (its suggestedDt); none when DT is fine.
    std::optional<simlab::StabilityAdvice> stabilityAdvice;
    double suggestedDt() const { return stabilityAdvice ? stabilityAdvice->suggestedDt : 0.0; }  // [s]; 0: none
    // A scene of several bodies (simcore::World): the topology above is every body's, side by
    // side (particles renumbered as the world's); each body's particles [first, first + count)
    // and kind. Empty for one body.
    struct BodySlice {
        int first = 0;
        int count = 0;
        simcore::SceneKind kind = simcore::SceneKind::Sphere3d;
    };
    std::vector<BodySlice> bodies;
    QString worldName;                    // collide2d, ..., or a scene file's name
    bool isWorld() const { return !bodies.empty(); }
};

enum class Speed { RealTime, Quarter, Tenth, AsFastAsPossible };

// The factor simulated seconds advance per wall second (0: as fast as possible).
double speedFactor(Speed speed);
QString speedName(Speed speed);

struct LaneFrame {
    QString integrator;
    std::vector<float> positions;         // 3N [m], x0 y0 z0 x1 ...
    std::vector<float> forces;            // 3N [N], only when force vectors are asked for
    std::vector<float> velocities;        // 3N [m/s]
    BodyMeasures body;                    // centre of mass, layer centres, lowest point
    simcore::Diagnostics diagnostics;
    std::optional<simcore::Failure> failure;
    // A failed lane: its recorded state some time before the failure (the latest checkpoint at
    // least kFailureStretch before it, or the run's first), for the failure banner's check
    // (simlab::checkFailure re-runs the stretch from it at a smaller step). None otherwise.
    std::shared_ptr<const simcore::SimulationSnapshot> stretchStart;
    simcore::PointerSpring pointer;
    double divergence = 0.0;              // RMS distance to the reference lane's particles [m]
    // The lane the distance is measured to: lane 0, or the first live lane once lane 0 has
    // failed (a failed lane's frozen state is no reference).
    int divergenceReference = 0;
    // The selected particle's free-body diagram (a click on a particle selects it); none
    // when nothing is selected.
    std::optional<simcore::ForceBreakdown> breakdown;
    // A scene of several bodies: this lane's world (its integrator's run of every body): its
    // own diagnostics (per body, total momentum, min_gap). None for one body.
    std::shared_ptr<const simcore::WorldDiagnostics> world;
};

// Time travel: where the shown state lies on the run's recorded timeline (sim_worker.h).
// A moment is the state after that many steps of the worker (common DTs side by side) since
// the timeline began (a new scene, a reset, an opened file), with the edits and pointer
// moves made at it.
struct TimelineInfo {
    long moment = 0;                      // the moment shown
    long first = 0, last = 0;             // the moments recorded
    double firstTime = 0.0, lastTime = 0.0;  // lane 0's simulated time at them [s]
    std::size_t bytes = 0;                // what the checkpoints hold
    std::size_t budget = 0;               // ... and may hold
    long interval = 0;                    // a checkpoint every so many moments
    std::size_t checkpoints = 0;
    bool scrubbed() const { return moment < last; }
};

struct Frame {
    std::shared_ptr<const SceneData> scene;
    simcore::ParameterSet parameters;
    std::vector<LaneFrame> lanes;
    bool running = false;
    Speed speed = Speed::RealTime;
    double wallSeconds = 0.0;             // wall time spent running since the last reset [s]
    // Worker steps per wall second (a step of the lane alone, a common DT side by side),
    // measured over the last half second or more.
    double stepsPerSecond = 0.0;
    bool fallingBehind = false;           // real-time mode could not keep up
    double atol = 1e-6, rtol = 1e-6;      // the adaptive methods' tolerances in use [m, m/s] and [1]
    // Precision (issue 27, lanes.h): float asked for, lane 0's last step a float step, the RMS
    // distance between the float run and its shadow double run [m] (< 0: no shadow: a body
    // above Lanes::kShadowParticles), and the float run's predicted round-off [m].
    bool floatWanted = false;
    bool floatActive = false;
    double floatDistance = -1.0;
    double floatRoundoff = 0.0;
    quint64 serial = 0;                   // increases with every published frame
    TimelineInfo timeline;
    // A scene of several bodies: lane 0's world diagnostics (per body, momentum, min_gap; each
    // lane has its own in LaneFrame::world) and the body parameter edits go to (-1: every body).
    // Each lane is then a world with its integrator: all its positions, its totals as a
    // Diagnostics.
    std::shared_ptr<const simcore::WorldDiagnostics> world;
    int worldBody = 0;
    std::shared_ptr<const simcore::WorldSpec> worldSpec;  // its bodies as described (start, parameters)
    // For the reference curve (reference_run.h): lane 0's state when the timeline began (a
    // new scene, a reset, an opened file; the same pointer until the next one), and the
    // simulated time of the first change of the physics since then that is still on the
    // timeline: a parameter edit other than DT, or a grab (+inf: none).
    std::shared_ptr<const simcore::SimulationSnapshot> runStart;
    double physicsChangedAt = std::numeric_limits<double>::infinity();
};

using FramePtr = std::shared_ptr<const Frame>;

// Time-series rows of lane 0 accumulated since the last take (every recorded step).
struct FrameBatch {
    FramePtr frame;
    std::vector<simcore::Diagnostics> rows;
    // Side by side: the other lanes' rows (lane i at index i - 1), recorded at the same
    // common times; a failed lane's rows end where it failed.
    std::vector<std::vector<simcore::Diagnostics>> laneRows;
    bool historyReset = false;            // a reset/rebuild happened: clear plots first
    // Branches (running on from a scrubbed moment) in the order they happened: the first
    // `rowsBefore` rows of `rows` precede it; the history after `time` became the abandoned future.
    struct Branch {
        std::size_t rowsBefore = 0;
        double time = 0.0;                // lane 0's simulated time at the branch [s]
    };
    std::vector<Branch> branches;
};

// A scene file captured on the worker thread between two steps (SimulationController::captureScene).
struct SceneCapture {
    std::string text;                     // simlab::sceneFileText of lane 0, with its exact state
    simcore::ParameterSet parameters;     // what the text holds
    QString integrator;                   // lane 0's
    int lanes = 0;                        // views running (side by side: > 1; only lane 0 is in text)
    double time = 0.0;                    // lane 0's simulated time [s]
    bool world = false;                   // a scene of several bodies (the text is a world's)
};

}  // namespace elui

Q_DECLARE_METATYPE(elui::FramePtr)
Q_DECLARE_METATYPE(simlab::SceneFile)
Q_DECLARE_METATYPE(simcore::ParameterSet)
