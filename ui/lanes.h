#pragma once
// Lanes: the worker's simulations, one per integrator (see sim_worker.h).
//
// In normal mode there is one lane; side by side there are up to three, every one built from
// the same parameters, given the same start kick, the same edits and the same mouse input, and
// advanced to the same simulated time (the common time) after every step of the common DT.
// Lanes owns them and what holds for all of them together: the common time, the start kick, step doubling and the force-evaluation
// threads. SimWorker calls it, on the worker thread only, between two steps; what a lane
// looks like in a frame comes from laneFrames().

#include <algorithm>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QStringList>

#include "simcore/float_path.h"
#include "simcore/timeline.h"
#include "ui/frame.h"

namespace elui {

class Lanes {
public:
    using List = std::vector<std::unique_ptr<simcore::Simulation>>;

    // One lane per integrator from params, with this set's threads and step doubling; empty, with
    // the reason in `error`, when the scene is impossible (empty, no error, for no integrator).
    // The set itself is left as it was.
    List build(const simcore::ParameterSet& params, const QStringList& integrators,
               std::optional<std::string>& error) const;
    // Takes the lanes built (the old ones go).
    void adopt(List lanes) {
        dropFloat();
        m_lanes = std::move(lanes);
    }
    void clear() {
        dropFloat();
        m_lanes.clear();
    }

    bool empty() const { return m_lanes.empty(); }
    std::size_t size() const { return m_lanes.size(); }
    simcore::Simulation& front() { return *m_lanes.front(); }
    const simcore::Simulation& front() const { return *m_lanes.front(); }
    // Read-only views of every lane, in order (the recorder's argument).
    std::vector<const simcore::Simulation*> views() const;

    // --- stepping ---
    // One step of the common DT for every live lane, never past `until` (< 0: no limit). One
    // lane steps on its own (its own adaptive step, if any); side by side every live lane is
    // advanced to the same time. The common time then is where they are.
    void stepAll(double until);
    double commonTime() const { return m_commonTime; }
    // The common time as a checkpoint held it [s].
    void setCommonTime(double t) { m_commonTime = t; }
    // The common time is lane 0's (after a rebuild, a reset or an opened state).
    void syncCommonTime() { m_commonTime = m_lanes.front()->time(); }
    bool allFailed() const;
    // Whether the run cannot go on: lane 0 failed on its own, or every lane side by side.
    bool stopped() const { return m_lanes.size() == 1 ? m_lanes.front()->failed() : allFailed(); }
    // Every lane's integrator can be restored exactly from a checkpoint (CVODE cannot).
    bool restorable() const;
    void reset();
    // Every lane back to checkpoint c (the lanes it holds).
    void restore(const simcore::TimelineCheckpoint& c);

    // --- what applies to every lane ---
    // A shape or start parameter: lane 0 first; its refusal is returned and no lane changes.
    // The others follow (a refusal of theirs is not reported: lane 0 decides).
    std::optional<std::string> trySetParameter(simcore::Param id, double value);
    // A live edit already validated: every lane.
    void setParameter(simcore::Param id, double value);
    bool stepDoubling() const { return m_stepDoubling; }
    void setStepDoubling(bool on);
    // The adaptive methods' tolerances (IntegratorOptions::atol, rtol) of every lane.
    double atol() const { return m_atol; }
    double rtol() const { return m_rtol; }
    void setTolerances(double atol, double rtol);
    // Step doubling and the tolerances as lane 0 has them (after a checkpoint was restored).
    void readOptions() {
        const simcore::IntegratorOptions& o = m_lanes.front()->integratorOptions();
        m_stepDoubling = o.stepDoubling;
        m_atol = o.atol;
        m_rtol = o.rtol;
    }
    void grab(int particle, const Eigen::Vector3d& anchor);
    void moveAnchor(const Eigen::Vector3d& anchor);
    void release();

    // The start kick: velocity along x given to every inner (+) and outer (-) particle [m/s].
    void setKick(double innerVx, double outerVx) {
        m_kickInner = innerVx;
        m_kickOuter = outerVx;
    }
    // Gives every lane the start kick (replacing its velocities), if there is one.
    void applyKick();

    // --- precision float (simcore/float_path.h) ---
    // Wanted: a single lane whose integrator has a float build steps on the float path (state
    // and forces in float) while no particle is held (the float path has no pointer); side by
    // side, or while held, the lanes step in double. After every float step the lane takes the
    // float state in double (simcore::FloatSimulation::writeStateTo's values, handed over
    // through a snapshot so that the energy ledger goes on: rows, frames, the timeline and
    // the failure banner read the lane as before). Any change to the lane (an edit, a grab,
    // a reset, a restored moment) restarts the float run from the lane at the next step.
    void setFloatWanted(bool on) {
        m_floatWanted = on;
        if (!on) dropFloat();
    }
    bool floatWanted() const { return m_floatWanted; }
    // Whether the last step of lane 0 was a float step.
    bool floatActive() const { return m_float != nullptr; }
    // The float run restarts from the lane at its next step.
    void dropFloat();
    // The shadow: a double run of lane 0's body, started with the float run from the same
    // state and stepped beside it, while the body has at most this many particles (a bigger
    // body would step at half the speed; its readout shows the round-off estimate instead).
    static constexpr int kShadowParticles = 6000;
    // RMS distance between the float run's particles and the shadow's [m]; < 0: no shadow.
    double floatDistance() const;
    // The float run's predicted round-off, eps_float X sqrt(n) (simlab::roundoffFloor: X the
    // largest |coordinate|, n the float steps so far) [m]; 0 when no float run.
    double floatRoundoff() const;

    // Every lane as a frame shows it: positions, diagnostics, failure, pointer, divergence from
    // lane 0 (from the first live lane once lane 0 has failed), and (when wanted) the force vectors and the selected particle's breakdown.
    std::vector<LaneFrame> laneFrames(bool forces, int selected) const;

private:
    bool canStepFloat() const;
    void startFloat();
    void stepFloat();
    List m_lanes;
    bool m_floatWanted = false;
    std::unique_ptr<simcore::FloatSimulation> m_float;
    std::unique_ptr<simcore::Simulation> m_shadow;
    simcore::Diagnostics m_floatBase;     // lane 0's ledger when the float run started
    long m_floatFirstStep = 0;
    double m_commonTime = 0.0;            // the time every live lane has reached [s]
    double m_kickInner = 0.0, m_kickOuter = 0.0;  // start kick along x [m/s]
    bool m_stepDoubling = false;
    double m_atol = simcore::IntegratorOptions{}.atol, m_rtol = simcore::IntegratorOptions{}.rtol;
    int m_threads = std::max(1, simcore::availableThreads() - 1);  // force-evaluation threads
};

// Side by side, one common DT: every live run (Simulations or Worlds, by pointer) reaches the
// same time `common + dt` (the distances between the views are measured there). A fixed-step
// run takes whole steps, so a run-until target `until` (< 0: none) off the DT grid is not
// shortened to unless every live run can land on it (all adaptive): the common clock then
// stops on the first tick past it, and the runs stay together. Returns the new common time.
template <class Runs>
double advanceSideBySide(Runs& runs, double common, double dt, double until) {
    double target = common + dt;
    const bool allAdaptive = std::all_of(runs.begin(), runs.end(), [](const auto& r) {
        return r->failed() || r->integrator().adaptive();
    });
    if (until >= 0.0 && allAdaptive) target = std::min(target, until);
    for (auto& r : runs)
        if (!r->failed()) r->advanceTo(target);
    return target;
}

// Lane sim's integrator name, as the GUI shows it.
QString integratorName(const simcore::Simulation& sim);

}  // namespace elui
