#pragma once
// Simulation: one body, its parameters, its integrator and its diagnostics.
//
// A step is a fixed list of named stages (Stage), run in this order by step(); each is one
// short function, and StepProfile times them when asked (setProfiling; `bench --stages`):
//
//   save        keep the state the step starts from (put back if the step fails); when the
//               integrator's first stage takes the kept end-of-step forces, that stage's
//               pool run copies it, range by range before its stage sums write them
//   size        the step h: dt, or what an adaptive method proposed, so that no particle
//               crosses a tenth of the box, shortened to land on `until`
//   integrate   the integrator (inside StepDoubling when its error is estimated) calls
//               BodyOde::derivative() once per stage (body_ode.h):
//                 gravity, wall contact -> springs -> gas -> layer barrier -> pointer
//                 -> a = F / m -> its stage sums   (contact = force: contact.h)
//   scan        one pass: finiteness, extent, kinetic and gravity energy, fastest speed;
//               when nothing before the measurement needs it (contact as a force), it runs
//               inside the measurement's first pool run instead
//   collide     contact = projection only (the thesis program): box planes, project back,
//               v_n -> -e v_n (the energy this changes is booked as removed)
//   measure     one force evaluation at the end state (BodyOde::measureEnd): energies,
//               volumes, pressures, the outer layer's normals, and the derivative the next
//               step's first stage takes
//   constrain   contact = projection only: inner layer kept inside the outer one (normals
//               from the measurement; a corrected state is scanned and measured again)
//   check       non-finite, runaway velocity or energy, a layer collapsed or inside out
//               -> failure: the saved state is put back and kept
//   commit      the measured diagnostics become the run's; time (a compensated sum), step
//               count, error estimate; the measured derivative is kept for the next step
//
// On failure no non-finite value ever leaves. Parameters change only between steps (the
// caller owns the thread that steps). Parts: forces.h, body_ode.h, step_doubling.h; by job
// simulation.cpp (state, stages), simulation_contacts.cpp (projection stages, design point),
// simulation_diagnostics.cpp, simulation_inspection.cpp (pointer, forces), simulation_snapshot.cpp.

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "simcore/body.h"
#include "simcore/forces.h"
#include "simcore/integrators.h"
#include "simcore/parallel.h"
#include "simcore/params.h"
#include "simcore/scaling.h"
#include "simcore/scenes.h"
#include "simcore/step_doubling.h"

namespace simcore {

class BodyOde;

// The stages of a step, in the order step() runs them (the header comment says what each
// does).
enum class Stage : int { Save, Size, Integrate, Scan, Collide, Measure, Constrain, Check, Commit, Count };
inline constexpr int kStageCount = static_cast<int>(Stage::Count);
// "save", "size", ... as in the header comment and `bench --stages`.
std::string_view stageName(Stage stage);

// Wall time per stage over the steps timed (Simulation::setProfiling).
struct StepProfile {
    std::array<double, kStageCount> seconds{};  // [s], by Stage
    long steps = 0;                              // steps timed (a failed one included)
    double& operator[](Stage stage) { return seconds[static_cast<std::size_t>(stage)]; }
    double operator[](Stage stage) const { return seconds[static_cast<std::size_t>(stage)]; }
    double total() const;                        // [s]
};

// Half-widths of the error bands of the plotted observables implied by a step's local error
// estimate (Simulation::observableErrors). valid = false: the step had no estimate.
struct ObservableErrors {
    bool valid = false;
    std::array<double, 2> volume{};    // [inner, outer], in the unit of Diagnostics::volume
    std::array<double, 2> pressure{};  // [inner, outer], in the unit of Diagnostics::pressure
    double energy = 0.0;               // of the total energy [J]
};

struct Diagnostics {
    long step = 0;
    double time = 0.0;                       // simulated time [s]
    double dt = 0.0;                         // last step taken [s]
    bool hasGas = false;
    std::array<double, 2> volume{};          // [inner, outer]: area [m^2] in 2D, volume [m^3] in 3D
    std::array<double, 2> restVolume{};
    std::array<double, 2> pressure{};        // P = nRT / V [N/m in 2D, N/m^2 in 3D]
    double kinetic = 0.0;                    // [J]
    std::array<double, kSpringFamilyCount> spring{};  // elastic energy per family [J]
    double gravity = 0.0;                    // sum m g y [J]
    double gas = 0.0;                        // sum -c ln V [J]
    double pointer = 0.0;                    // mouse spring energy [J]
    double contact = 0.0;                    // contact energy: walls + layer barrier (contact = force) [J]
    double removedDamping = 0.0;             // energy removed by spring and mouse damping [J]
    double removedContact = 0.0;             // energy removed by contact dissipation and friction [J]
    double removedCollisions = 0.0;          // energy removed by the projection (contact = projection) [J]
    double workPointer = 0.0;                // work done on the body by moving the pointer [J]
    double workEdits = 0.0;                  // energy changed by parameter edits during the run [J]
    double initialEnergy = 0.0;              // E_0 [J]
    double errorEstimate = -1.0;             // local error estimate of the last step, < 0: none
    int degenerateSprings = 0;
    // Force evaluations of the run; with a CVODE integrator also every Jacobian-vector product.
    std::uint64_t forceEvaluations = 0;
    bool hasSolverCounters = false;          // the integrator is a solver with its own counters (CVODE)
    SolverCounters solver;                   // ... and these are they
    // The error bands of this row: filled only by a caller that asks for them
    // (Simulation::observableErrors; the GUI's plot rows), else not valid.
    ObservableErrors errors;

    double springTotal() const { return spring[0] + spring[1] + spring[2]; }
    double potential() const { return springTotal() + gravity + gas + pointer + contact; }
    double total() const { return kinetic + potential(); }
    double removed() const { return removedDamping + removedContact + removedCollisions; }
    // E_total + E_removed - W_pointer - W_edits - E_0: zero for exact integration.
    double energyDrift() const { return total() + removed() - workPointer - workEdits - initialEnergy; }
};

struct Failure {
    std::string reason;  // plain words: what happened
    long step = 0;       // the step that failed
    double time = 0.0;   // simulated time at the start of that step [s]
};

// Everything a step reads that a run changes: with it restored, the steps that follow are
// the steps the run took, bit for bit (Simulation::snapshot, restore; the GUI's timeline).
// The body's structure is not in it (a rebuild starts a new run), nor the thread count (results
// do not depend on it).
struct SimulationSnapshot {
    ParameterSet params;                   // masses and force parameters follow from these
    std::string integrator;
    IntegratorOptions options;
    std::vector<double> integratorHistory; // Integrator::history()
    bool integratorRestorable = true;      // false: a restore restarts the method (CVODE)
    Eigen::VectorXd y;                     // [x | v | removed-by-damping | removed-by-contact]
    bool endValid = false;                 // the end-of-step derivative below is current
    Eigen::VectorXd endDerivative;
    ForceExtras endExtras;
    bool restartIntegrator = false;
    Diagnostics diag;
    double timeCarry = 0.0;
    std::optional<Failure> failure;
    double hNext = 0.0, hTaken = 0.0;
    double energyScale = 1.0;
    PointerSpring pointer;
    ForceModel::Counters counters;
    std::uint64_t jacobianProducts = 0;

    // Bytes it holds (its vectors and strings included).
    std::size_t bytes() const;
};

class Simulation {
public:
    // Throws std::invalid_argument for an unknown integrator or an impossible shape.
    Simulation(const ParameterSet& params, std::string_view integrator);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    // --- running ---
    // One step of dt. Returns false when the run has failed (now or before).
    // An adaptive integrator takes the step it last proposed (hNext), shortened so as not to
    // pass `until`; a fixed-step one always takes dt.
    bool step(double until = std::numeric_limits<double>::infinity());
    // Steps until time >= t_end (within round-off) or failure. Returns !failed().
    bool advanceTo(double tEnd);
    void reset();  // back to the start state, same parameters

    bool failed() const { return m_failure.has_value(); }
    const std::optional<Failure>& failure() const { return m_failure; }
    const Diagnostics& diagnostics() const { return m_diag; }
    double time() const { return m_diag.time; }
    long stepCount() const { return m_diag.step; }

    // --- parameters (between steps only) ---
    const ParameterSet& parameters() const { return m_params; }
    // The same values resolved into typed groups (params.h): what the step reads.
    const Params& params() const { return m_p; }
    // Validates and applies. A shape or start key rebuilds the body and resets.
    std::optional<std::string> setParameter(Param id, double value);
    // The boundary's form (a key given as text): an unknown key is refused with the list.
    std::optional<std::string> setParameter(std::string_view key, double value);
    std::optional<std::string> setIntegrator(std::string_view name);
    // Tolerances of adaptive methods, CG settings of implicit ones, step doubling.
    void setIntegratorOptions(const IntegratorOptions& options);
    const IntegratorOptions& integratorOptions() const { return m_integratorOptions; }
    // The step the next step() will try (dt for fixed-step integrators) [s].
    double nextStep() const { return m_integrator->adaptive() ? m_hNext : m_p.time.dt; }
    // Sets the step an adaptive integrator tries next (a resumed run); h > 0 and finite.
    void setNextStep(double h) {
        if (std::isfinite(h) && h > 0.0) m_hNext = h;
    }
    const Integrator& integrator() const { return *m_integrator; }
    double dt() const { return m_p.time.dt; }

    // --- pointer (thesis 4.4) ---
    // Nearest particle that may be grabbed (outer layer, or either 1D particle).
    int nearestGrabbable(const Eigen::Vector3d& point) const;
    // Grabbable particle closest to a ray (origin, unit direction), nearest the origin on ties;
    // -1 when none is within maxDistance of the ray.
    int pickAlongRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                     double maxDistance) const;
    void grab(int particle, const Eigen::Vector3d& anchor);
    void moveAnchor(const Eigen::Vector3d& anchor);
    void release();
    const PointerSpring& pointer() const { return m_forces.pointer; }

    // --- threads ---
    // Threads for force evaluation (used when the body is large enough to be split in chunks).
    // Results are bit-identical whatever the count.
    void setThreads(int threads);
    int threads() const { return m_pool ? m_pool->threads() : 1; }

    // --- state and structure ---
    const Body& body() const { return m_body; }
    // The factors from the table's values to this resolution's (scaling.h; 1 under scaling=thesis).
    const BodyScale& scale() const { return m_scale; }
    const Topology& topology() const { return m_body.topology; }
    int particleCount() const { return m_body.topology.particleCount(); }
    const Eigen::VectorXd& state() const { return m_y; }
    Eigen::Map<const Eigen::Matrix3Xd> positions() const;
    Eigen::Map<const Eigen::Matrix3Xd> velocities() const;
    // Replaces positions and velocities (e.g. a saved state); resets the energy bookkeeping.
    void setState(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& v);
    // The same, also setting the step counter and the simulated time (a resumed experiment).
    void setState(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& v, long step, double time);
    // The run's whole changing state, and back (parameters, integrator and its history,
    // diagnostics, pointer, counters): after restore(snapshot()) at step n, the steps that
    // follow equal the original run's bit for bit, unless the snapshot's integrator is not
    // restorable (CVODE), which then restarts from the state. Throws std::invalid_argument
    // for a snapshot of another body (a different particle count).
    SimulationSnapshot snapshot() const;
    void restore(const SimulationSnapshot& s);
    const ForceModel& forces() const { return m_forces; }
    // The total force on every particle in the current state (3N) [N], e.g. to draw force
    // vectors. Not counted as a force evaluation of the run.
    void currentForces(double* f) const;
    // The force on one particle in the current state split by part (gravity, each spring
    // family, each layer's gas, wall contact, the layer barrier, the mouse spring) and the
    // total, for a free-body diagram (ForceModel::breakdown: the parts come from the step's
    // own force code). Not counted as force evaluations of the run.
    ForceBreakdown forceBreakdown(int particle) const;
    // The error bands the last step's local error estimate e implies for the volumes, the
    // pressures and the total energy: e is the integrator's own estimate over the whole state
    // (rk45's embedded difference, CVODE's local error estimate, or step doubling's
    // (y_h/2 - y_h) / (1 - 2^-p)), and each half-width is |O(y + e) - O(y)| with both states
    // measured by measure(). Not valid when the last step had no estimate (fixed-step methods
    // without step doubling), after a reset, a new state or a new integrator, or after a
    // failure. The state is left exactly as it was. Costs two measurements.
    ObservableErrors observableErrors();
    // The ODE the integrators see, with its force Jacobians (for linear stability analysis).
    OdeSystem& odeSystem();
    Eigen::Vector3d boxCentre() const { return m_boxCentre; }
    double boxHalfSize() const { return m_p.world.box; }

    // Energies and volumes of the current state (fills the non-accumulated fields of d).
    void measure(Diagnostics& d) const;
    // Whether each step measures its end state by a force evaluation whose result the next
    // step's first stage reuses (default), instead of separate energy and volume passes.
    // Trajectories are bit-identical either way; the switch exists to test and measure that.
    void setReuseEndForces(bool on);

    // --- profiling ---
    // Whether each step times its stages (two clock reads per stage; off by default). Turning
    // it on starts a new profile.
    void setProfiling(bool on);
    const StepProfile& profile() const { return m_profile; }
    // Cheap upper estimate of the body's fastest rate |s| [1/s] (spring frequency or damping
    // rate); explicit methods need roughly dt * |s| < kExplicitStabilityLimit. Used to warn
    // before a run.
    double estimatedFastestRate() const;

    // Whether contact is the thesis program's projection after the step (contact = projection)
    // rather than a force inside the ODE.
    bool contactProjection() const { return m_contactProjection; }
    // The contact's linearisation point for the stability estimates (contact.h): the
    // particles nearest the floor (the wall gravity pulls towards: those within a tenth of the
    // body's height of its lowest point), each at the depth at which they carry the body's
    // weight at rest (k d^3 = W / count; an impact goes deeper, but only for a few steps:
    // docs/numerics.md). Empty when contact is not a force, when nothing falls (no gravity)
    // or when the body hangs from a fixed particle.
    using ContactDesign = simcore::ContactDesign;
    ContactDesign contactDesign() const;
    // Whether odeSystem()'s Jacobians add the contact design point's stiffness (the stability
    // estimates linearise at the start state, where nothing touches yet). Off for integration.
    void setContactDesignInJacobians(bool on);

private:
    void build();
    void applyForceParams();
    void applyMasses();  // m_body.mass and m_invMass3 from the mass parameters
    void startBookkeeping();
    bool usesStepDoubling() const { return m_integratorOptions.stepDoubling && !m_integrator->adaptive(); }

    // One pass over the particles (in pieces, summed in piece order) for what the checks and
    // the diagnostics need of the state: a step scans once, and again only after contacts.
    struct Scan {
        bool finite = true;                 // no NaN or infinity in x, v or the damping account
        Eigen::Array3d low, high;           // extent of the moving coordinates per axis [m]
        double kinetic = 0.0;               // sum of m v^2 / 2 over free particles [J]
        double gravity = 0.0;               // sum of m g y over free particles [J]
        double fastest = 0.0;               // largest particle speed [m/s]
    };
    Scan scanState() const;
    // scanState's parts: one piece's particles [begin, end), and the pieces combined in order.
    Scan scanPiece(int begin, int end) const;
    Scan combineScans(const std::array<Scan, ForceModel::kChunks>& pieces) const;

    // --- the step's stages (simulation.cpp; collide and constrain: simulation_contacts.cpp) ---
    // What the stages of one step hand on to each other.
    struct StepWork {
        StepWork(const Diagnostics& diag, double end) : t0(diag.time), until(end), next(diag) {}
        double t0 = 0.0;                    // time at the start of the step [s]
        double until = 0.0;                 // an adaptive step does not pass it [s]
        double h = 0.0;                     // the step tried [s]
        bool clamped = false;               // h was shortened to land on `until`
        StepReport report;                  // the integrator's
        Scan scan;                          // of the state as it stands
        // The save and the scan done later, inside pool runs a step makes anyway (fewer runs
        // per step, the same bits): the save by the integrator's first stage, the scan by the
        // measurement's force evaluation.
        bool saveLater = false;
        bool scanLater = false;
        Diagnostics next;                   // the step's diagnostics, the run's once it stands
        std::optional<double> beforeContacts;  // total energy before a contact stage changed the state [J]
    };
    // Runs one stage, timed when profiling; its result: whether the step goes on.
    template <class F>
    bool inStage(Stage stage, F&& run) {
        if (!m_profiling) return run();
        const auto start = std::chrono::steady_clock::now();
        const bool goOn = run();
        m_profile[stage] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return goOn;
    }
    // The stages (false: the step failed there and ends).
    bool save(StepWork& w);
    bool size(StepWork& w);
    bool integrate(StepWork& w);
    bool scan(StepWork& w);
    bool collide(StepWork& w);
    bool measure(StepWork& w);
    bool constrain(StepWork& w);
    bool check(StepWork& w);
    bool commit(StepWork& w);
    // A failed step: the reason is kept and the saved state put back.
    void fail(std::string reason, const StepWork& w);

    // The collide stage's box planes. With apply = false only report whether anything is in
    // contact.
    bool collideWalls(bool apply);
    bool collideRange(bool apply, int begin, int end);
    // The constrain stage's layer pairs; normals: the outer layer's dV/dx per particle
    // (ForceModel::volumeGradient()).
    bool constrainLayers(bool apply, kernels::PaddedRows normals);
    // Per-particle work in a fixed number of pieces (the force model's chunks, so sums
    // combined in piece order are the same for any number of threads), on the pool when
    // there is one: body(piece, firstParticle, endParticle).
    static constexpr int kPiecesMax = ForceModel::kChunks;
    template <class F>
    void inPieces(F&& body) const {
        inPiecesOf(particleCount(), std::forward<F>(body));
    }
    // The same over items 0..n-1 of something else (layer pairs).
    template <class F>
    void inPiecesOf(int n, F&& body) const {
        const int pieces = m_forces.chunks();
        auto task = [&](int k) { body(k, n * k / pieces, n * (k + 1) / pieces); };
        if (m_pool && pieces > 1)
            m_pool->run(pieces, task);
        else
            for (int k = 0; k < pieces; ++k) task(k);
    }
    // Why the state (measured into d) is unusable, or nothing.
    // `scan`: the state's scan (finiteness, fastest particle).
    std::optional<std::string> checkState(const Diagnostics& d, const Scan& scan) const;
    double totalEnergyNow() const;
    // The energies and volumes by the end-of-step force evaluation (BodyOde::measureEnd) when
    // its derivative is kept for the next step, else by their own passes (measureByPasses).
    // With scanToo, scan is taken too (inside the evaluation's pool run when it can be).
    void measureState(Diagnostics& d, Scan& scan, bool scanToo = false);
    void measureByPasses(Diagnostics& d, const Scan& scan) const;
    void fillDiagnostics(Diagnostics& d, const std::array<double, kSpringFamilyCount>& spring,
                         const std::array<double, 2>& volume, double contact, const Scan& scan) const;

    ParameterSet m_params;
    Params m_p;                   // m_params resolved, once each time m_params changes
    int m_threads = availableThreads();  // the CPUs this process may use (parallel.h)
    std::unique_ptr<ThreadPool> m_pool;  // declared before m_forces, which points to it
    Body m_body;
    std::unique_ptr<Integrator> m_integrator;
    mutable ForceModel m_forces;
    std::unique_ptr<BodyOde> m_ode;  // the ODE the integrators see, over m_body, m_forces, m_invMass3
    StepDoubling m_doubling;      // wraps the integrator's step while step doubling is on
    Eigen::VectorXd m_y;          // [x | v | removed-by-damping | removed-by-contact]
    Eigen::VectorXd m_lastGood;   // state before the current step
    Eigen::VectorXd m_invMass3;   // 3N inverse masses, 0 on fixed particles and absent axes
    Diagnostics m_diag;
    double m_timeCarry = 0.0;     // round-off carried by the compensated time sum [s]
    std::optional<Failure> m_failure;
    Eigen::Vector3d m_boxCentre = Eigen::Vector3d::Zero();
    BodyScale m_scale;
    bool m_contactProjection = false;  // contact = projection (else a force in the ODE)
    double m_hNext = 0.003;       // adaptive integrators: the step proposed by the last one [s]
    double m_hTaken = 0.003;      // the step being checked [s]
    IntegratorOptions m_integratorOptions;
    // The last step's local error estimate over the whole state (the integrator's, or step
    // doubling's), nullptr when it had none; for observableErrors().
    const double* m_lastError = nullptr;
    Eigen::VectorXd m_errorScratch;   // observableErrors(): the state while y + e is measured
    mutable Eigen::VectorXd m_breakdownForces;  // forceBreakdown(): 3N scratch
    double m_energyScale = 1.0;   // for runaway detection [J]
    // Whether the measure stage's force evaluation is kept for the next step (BodyOde's cache).
    bool m_reuseEndForces = true;
    Eigen::Index m_n = 0;         // 3N
    // The state or the system changed between steps (a projection, the pointer, a live edit,
    // a new state): the next step tells the integrator (Integrator::restart()).
    bool m_restartIntegrator = false;
    std::uint64_t m_jacobianProducts = 0;  // counted as force evaluations (CVODE)
    bool m_profiling = false;
    StepProfile m_profile;
};

// |h s| beyond which no classical explicit method here is stable (RK4 reaches 2.83 on the
// imaginary axis and 2.79 on the real axis).
inline constexpr double kExplicitStabilityLimit = 2.8;
// The fraction of its rest volume below which a layer counts as collapsed or inside out.
inline constexpr double kCollapsedVolumeFraction = 0.01;
// Kinetic + elastic energy above this multiple of the body's energy scale is a blow-up.
inline constexpr double kRunawayEnergyFactor = 100.0;

}  // namespace simcore
