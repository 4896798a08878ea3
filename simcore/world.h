#pragma once
// World: several two-layer bodies in one box, stepped as one ODE by any integrator
// (docs/model.md "Several bodies"; the thesis's future work, section 8.3).
//
// Where the parts live:
//   internal/world_body.h  one body: its parameters, its built body placed at its start, its force
//                    model and BodyOde (the one-body simulation's pieces)
//   internal/world_ode.h   the bodies side by side as one ODE, with the pairs' forces and Jacobians
//   contact_pairs.h  body-body and self contact: the barrier force, the broad phase, gaps and
//                    the exact intersection test
//   world_spec.h     the world's description before it is built (WorldSpec: built-in scenes,
//                    bodyN.key settings, the checks before a run), world_spec.cpp
//   world.h          (this) the World: its state and stepping (world.cpp), its diagnostics
//                    (world_diagnostics.cpp), the pointer and the forces of a state
//                    (world_inspection.cpp), its snapshots (world_snapshot.cpp)
//
// A step: size (dt, or the adaptive method's proposal, no particle crossing a tenth of the
// box), integrate (inside StepDoubling when its error is estimated), the exact intersection
// test, measure, check, commit. Nothing passes through: the pair potential is a barrier
// (contact_pairs.h), and a step that ends with two elements crossing is refused. An adaptive
// method retries it at half the step (step control); a fixed-step method cannot shorten its
// step, so its run fails with the two bodies named (an intersection is a failure, like a
// layer turned inside out).
//
// One-body scenes do not come here: Simulation (simulation.h) runs them, unchanged.

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "simcore/body.h"
#include "simcore/contact_pairs.h"
#include "simcore/forces.h"
#include "simcore/integrators.h"
#include "simcore/params.h"
#include "simcore/step_doubling.h"
#include "simcore/world_spec.h"

namespace simcore {

class WorldBody;
class WorldOde;

// What the world measures per body at the end of each step.
struct BodyDiagnostics {
    std::array<double, 2> volume{};      // [inner, outer] (area in 2D)
    std::array<double, 2> restVolume{};
    std::array<double, 2> pressure{};
    Eigen::Vector3d com = Eigen::Vector3d::Zero();       // centre of mass [m]
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  // of the centre of mass [m/s]
    double mass = 0.0;                                   // [kg]
    double kinetic = 0.0;                                // [J]
};

struct WorldDiagnostics {
    long step = 0;
    double time = 0.0;
    double dt = 0.0;
    double kinetic = 0.0;
    std::array<double, 3> spring{};      // per family [J]
    double gravity = 0.0;
    double gas = 0.0;
    double contact = 0.0;                // walls, layer barriers and the pairs [J]
    double contactPairs = 0.0;           // the pairs' part of it [J]
    double pointer = 0.0;                // the mouse spring's energy [J]
    double workPointer = 0.0;            // work done by moving the pointer [J]
    double removedDamping = 0.0;
    double removedContact = 0.0;
    double initialEnergy = 0.0;
    double errorEstimate = -1.0;
    std::uint64_t forceEvaluations = 0;
    std::vector<BodyDiagnostics> bodies;
    Eigen::Vector3d momentum = Eigen::Vector3d::Zero();         // sum m v [kg m/s]
    Eigen::Vector3d angularMomentum = Eigen::Vector3d::Zero();  // sum x x m v about the origin [kg m^2/s]
    // The smallest distance between two bodies' outer surfaces or two non-adjacent elements
    // of one outer surface [m], exact up to World::gapRange(); nothing that close: the range.
    double minGap = std::numeric_limits<double>::infinity();
    std::array<int, 2> minGapBodies{-1, -1};  // 0-based, of the closest pair within range (equal: self)
    int contactPairsActive = 0;                                // pairs within the skin

    double springTotal() const { return spring[0] + spring[1] + spring[2]; }
    double potential() const { return springTotal() + gravity + gas + pointer + contact; }
    double total() const { return kinetic + potential(); }
    double removed() const { return removedDamping + removedContact; }
    double energyDrift() const { return total() + removed() - workPointer - initialEnergy; }
};

// Everything a world's step reads that a run changes: with it restored, the steps that follow
// are the steps the run took, bit for bit (World::snapshot, restore; the GUI's timeline of a
// world, as SimulationSnapshot is one body's). The bodies' structure is not in it: the spec is
// shared with the world it came from, and a snapshot restores only into a world of that spec.
struct WorldSnapshot {
    std::shared_ptr<const WorldSpec> spec;
    std::string integrator;
    IntegratorOptions options;
    std::vector<double> integratorHistory;  // Integrator::history()
    bool integratorRestorable = true;       // false: a restore restarts the method (CVODE)
    Eigen::VectorXd y;                      // [x | v | removed-by-damping | removed-by-contact]
    WorldDiagnostics diag;
    double timeCarry = 0.0;
    double hNext = 0.0;
    std::optional<std::string> failure;
    long failedStep = 0;
    double failedTime = 0.0;
    int held = -1;                          // the pointer's particle (world numbering), -1: none
    Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
    std::vector<ForceModel::Counters> counters;  // per body
    std::uint64_t jacobianProducts = 0;

    // Bytes it holds (its vectors and strings; the shared spec not).
    std::size_t bytes() const;
};

class World {
public:
    // Throws std::invalid_argument for an unknown integrator, or a world validateWorld refuses.
    World(const WorldSpec& spec, std::string_view integrator);
    World(std::shared_ptr<const WorldSpec> spec, std::string_view integrator);
    ~World();
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    bool step(double until = std::numeric_limits<double>::infinity());
    bool advanceTo(double tEnd);
    void reset();
    // Restores a saved state (every particle in the world's numbering, 3 x particleCount()), at
    // `step` and `time`: the accounts start again from it (as Simulation::setState), a failure
    // is cleared. Throws std::invalid_argument when the sizes do not fit.
    void setState(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& v, long step, double time);
    // The run's state with its accounts, counters, pointer and integrator history.
    WorldSnapshot snapshot() const;
    // Goes back to a snapshot of this world's spec (the same shared spec; throws
    // std::invalid_argument for another), or of a world of the same particles with other
    // values (`sameSpecOnly` false: a live edit goes on from the old world's run; the accounts
    // are kept and measured again with this world's values, the energy the new values add
    // booked as the edit's, so the drift goes on where it was). Another integrator than the
    // snapshot's, or one whose history cannot be restored, starts afresh from the state.
    void restore(const WorldSnapshot& s, bool sameSpecOnly = true);
    // An adaptive method's next proposed step [s] (saved with the state so a resume is exact).
    double nextStep() const { return m_hNext; }
    void setNextStep(double h) { m_hNext = h; }

    bool failed() const { return m_failure.has_value(); }
    const std::optional<std::string>& failure() const { return m_failure; }
    long failedStep() const { return m_failedStep; }
    double failedTime() const { return m_failedTime; }
    const WorldDiagnostics& diagnostics() const { return m_diag; }
    double time() const { return m_diag.time; }
    long stepCount() const { return m_diag.step; }
    double dt() const { return m_dt; }
    double boxHalfSize() const { return m_box; }
    const Integrator& integrator() const { return *m_integrator; }
    void setIntegratorOptions(const IntegratorOptions& options);
    const IntegratorOptions& integratorOptions() const { return m_options; }

    const WorldSpec& spec() const { return *m_spec; }
    // The spec as shared with this world's snapshots.
    const std::shared_ptr<const WorldSpec>& sharedSpec() const { return m_spec; }
    int bodyCount() const { return static_cast<int>(m_bodies.size()); }
    // Body k (from 0) as built and placed at its start, its first particle in the world's
    // numbering and its particle count.
    const Body& body(int k) const;
    int firstParticle(int k) const;
    int bodyParticles(int k) const;
    int dimension() const { return m_dimension; }
    int particleCount() const { return static_cast<int>(m_n / 3); }
    const Eigen::VectorXd& state() const { return m_y; }
    // Body k's positions and velocities (3 x its particles).
    Eigen::Map<const Eigen::Matrix3Xd> positions(int k) const;
    Eigen::Map<const Eigen::Matrix3Xd> velocities(int k) const;
    const PairContactParams& pairContact() const { return m_contact; }
    // How far min_gap is measured exactly: twice the contact skin. Farther gaps read as the
    // range (a query's cost grows with the square of its reach: at the rest gap between
    // non-adjacent elements of one layer, about an edge, it would cost more than the forces).
    double gapRange() const { return 2.0 * m_contact.skin; }
    ContactPairs& pairs() { return m_pairs; }

    // --- the pointer (the GUI's mouse drag): one spring from a particle of any body to an anchor
    // (particles numbered as the world's; its energy and the work it does are in the ledger).
    int pickAlongRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double maxDistance) const;
    void grab(int particle, const Eigen::Vector3d& anchor);
    void moveAnchor(const Eigen::Vector3d& anchor);
    void release();
    // The held particle (world numbering; -1 when none) and its anchor.
    int heldParticle() const { return m_held; }
    Eigen::Vector3d anchor() const;
    // The body (from 0) a world particle belongs to.
    int bodyOf(int particle) const;
    // Every particle's layer, the bodies side by side.
    const std::vector<Layer>& layers() const { return m_layers; }

    // The ODE the integrators step (the stability estimates linearise it: simlab/stability.h).
    OdeSystem& odeSystem();
    // Whether odeSystem()'s Jacobians add each body's wall contact at its design point (as
    // Simulation::setContactDesignInJacobians does for a body alone, from the current positions).
    void setContactDesignInJacobians(bool on);
    // The force on one particle (world numbering) in the current state split by part, for a
    // free-body diagram: its body's own parts (Simulation::forceBreakdown's: gravity, springs,
    // gas, walls, barrier, the mouse), the contact from the other bodies and the self-contact
    // (ForcePart::BodyContact, SelfContact), and the total the world's ODE applies. Not
    // counted as force evaluations of the run; -1 or out of range: an empty breakdown.
    ForceBreakdown forceBreakdown(int particle);
    // The total force on every particle in the current state (3N) [N], e.g. to draw force
    // vectors. Not counted as a force evaluation of the run.
    void currentForces(double* f);

    // The error band the last step's local error estimate e implies for the world's total
    // energy, |E(y + e) - E(y)| [J] (as Simulation::observableErrors; e is step doubling's or
    // the adaptive method's own estimate); < 0 when the last step had none (a fixed-step
    // method without step doubling, or after a reset, a restore or a new state).
    double energyErrorBand();

    // Measures the current state into d (everything but the accounts and counters).
    void measure(WorldDiagnostics& d);

private:
    void fail(std::string reason, double t0);

    std::shared_ptr<const WorldSpec> m_spec;
    std::vector<std::unique_ptr<WorldBody>> m_bodies;
    ContactPairs m_pairs;
    PairContactParams m_contact;
    std::unique_ptr<WorldOde> m_ode;
    std::unique_ptr<Integrator> m_integrator;
    IntegratorOptions m_options;
    StepDoubling m_doubling;
    int m_dimension = 3;
    Eigen::Index m_n = 0;
    Eigen::VectorXd m_y, m_lastGood;
    Eigen::VectorXd m_rate;  // dy/dt of measure()'s evaluation
    WorldDiagnostics m_diag;
    double m_timeCarry = 0.0;
    double m_dt = 0.003, m_box = 1.0;
    double m_hNext = 0.003;
    std::uint64_t m_jacobianProducts = 0;  // counted as force evaluations (CVODE)
    std::optional<std::string> m_failure;
    std::vector<Layer> m_layers;
    int m_held = -1;
    Eigen::VectorXd m_breakdownScratch;  // forceBreakdown(): 3N
    const double* m_lastError = nullptr;  // the last step's local error estimate, or none
    Eigen::VectorXd m_errorScratch;       // energyErrorBand(): y
    void pointerChanged(const PointerSpring& pointer, int body);
    long m_failedStep = 0;
    double m_failedTime = 0.0;

    // The fastest particle's speed in the current state [m/s].
    double fastestSpeed() const;
    // Why the state a step of h [s] ended in does not stand (a runaway speed, a layer collapsed
    // or inside out), measured as `next`; nothing when it stands.
    std::optional<std::string> endFailure(const WorldDiagnostics& next, double h) const;
};

}  // namespace simcore
