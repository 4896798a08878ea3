#pragma once
// Time integrators (thesis ch. 5, docs/model.md "Integrators") behind one interface.
//
// The state is one flat, contiguous vector y = [x (n) | v (n) | aux (m)] with
// dy/dt = [v | a(x, v, t) | aux'], where aux holds integrated diagnostics (the energy
// removed by damping) so that they are integrated with the same accuracy as the motion.
// An integrator advances y in place; its stage vectors are allocated once in prepare(),
// never inside a step, and every stage re-evaluates the forces through OdeSystem.
//
// Explicit methods only need derivative(). The implicit method also needs the system's
// mechanical structure, M v' = F(x, v), and the products of the force Jacobians
// K = dF/dx and D = dF/dv with a vector (matrix-free: no matrix is ever assembled).
//
//   method            order  force evaluations per step        error estimate
//   euler             1      1                                  step doubling (optional)
//   midpoint          2      2                                  step doubling (optional)
//   rk4               4      4                                  step doubling (optional)
//   symplectic-euler  1      1                                  step doubling (optional)
//   verlet            2 (1)  2                                  step doubling (optional)
//   rk45              5(4)   7 per attempt (no FSAL, see .cpp)  embedded, every step
//   implicit-euler    1      2 + CG products of K and D         step doubling (optional)
//   cvode-bdf         1-5    CVODE: as it needs (+ Jv products)  CVODE's local error estimate
//   cvode-adams       1-12   CVODE: as it needs                  CVODE's local error estimate
//   xpbd              1      1 per substep (+ a spring pass)     step doubling (optional)
//
// The CVODE methods (cvode_integrators.cpp) keep a history between steps (the Nordsieck
// array): anything that changes the state or the system outside the integrator between two
// steps must be announced with restart(), which re-initialises them (CVodeReInit).

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "simcore/parallel.h"

namespace simcore {

struct StateLayout {
    Eigen::Index positions = 0;   // n: 3 per particle
    Eigen::Index aux = 0;         // m: integrated scalars
    Eigen::Index size() const { return 2 * positions + aux; }
};

// A spring family as distance constraints, for position-based methods (xpbd).
struct DistanceFamily {
    std::span<const int> a, b;        // the end particles of each spring
    std::span<const double> rest;     // rest lengths L0 [m]
    double stiffness = 0.0;           // this family's stiffness [N/m] (compliance 1/stiffness); 0 = not a constraint
    double damping = 0.0;             // this family's damping [N s/m]
};
struct DistanceConstraints {
    std::array<DistanceFamily, 3> families;        // structural, radius, shear
    const Eigen::VectorXd* inverseMass = nullptr;  // per coordinate (3N) [1/kg], 0 where fixed or absent
    int substeps = 1;                              // xpbd substeps per step (parameter `substeps`)
};

class OdeSystem {
public:
    virtual ~OdeSystem() = default;
    virtual StateLayout layout() const = 0;
    // dydt = f(t, y). Must not allocate.
    virtual void derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) = 0;

    // dydt = f(t, y), then then(begin, length) over ranges that cover dydt once, each called
    // when its part of dydt is final; `then` may overwrite its range of y (the system reads
    // no element of y after handing over its range). A system that computes dydt in pieces
    // runs `then` on each piece while it is fresh in cache (a pass and a dispatch less); the
    // default computes dydt, then runs `then` in pieces.
    virtual void derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt, RangeWork then) {
        derivative(t, y, dydt);
        inPieces(dydt.size(), then);
    }

    // Second-order systems (x' = v exactly, y = [x (n) | v (n) | aux (m)]) say so, and then
    // derivativeMotion() writes only dydt's tail [n, size) (a and aux'), never the copy of v
    // that x' would be: a method reads x' from the stage state's v itself. then(begin, length)
    // runs over ranges that cover [n, size) once, each when its part of dydt is final; a range
    // inside [n, 2n) hands over those velocities' derivatives and also the state's x and v of
    // the same coordinates ([begin - n, begin - n + length) and the range itself), so `then`
    // may overwrite either. The default computes the whole of dydt, then runs `then` in pieces.
    virtual bool secondOrder() const { return false; }
    virtual void derivativeMotion(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt, RangeWork then) {
        derivative(t, y, dydt);
        const Eigen::Index n = layout().positions;
        inPieces(dydt.size() - n, [&](Eigen::Index b, Eigen::Index l) { then(n + b, l); });
    }

    // Element-wise vector work of a step (y + h k, ...) may be split in pieces that run on
    // several threads: runPieces calls task(0..pieces()-1) and returns when all are done.
    virtual int pieces() const { return 1; }
    virtual void runPieces(TaskRef task) { task(0); }
    // work(begin, length) over [0, size) in the pieces, split at multiples of eight doubles
    // (one cache line) so that no two threads write the same line. The work is element by
    // element, so the split does not change a bit of the result.
    void inPieces(Eigen::Index size, RangeWork work) {
        const int count = pieces();
        if (count <= 1) {
            work(Eigen::Index{0}, size);
            return;
        }
        auto bound = [&](int k) { return k == count ? size : (size * k / count) / 8 * 8; };
        runPieces([&](int k) { work(bound(k), bound(k + 1) - bound(k)); });
    }

    // --- mechanical structure, for implicit methods (M v' = F(x, v)) ---
    virtual bool hasForceJacobian() const { return false; }
    // Fixes the point (x, v) of y at which the Jacobians below are taken.
    virtual void linearize(double /*t*/, const Eigen::VectorXd& /*y*/) {}
    // out = K dx + D dv with K = dF/dx, D = dF/dv at the linearisation point (all n long).
    // Rows of constrained coordinates (fixed particles, absent axes) are zero.
    virtual void forceJacobianProduct(const Eigen::VectorXd& /*dx*/, const Eigen::VectorXd& /*dv*/,
                                      Eigen::VectorXd& out) {
        out.setZero();
    }
    // Diagonals of K and D (n each), for a Jacobi preconditioner.
    virtual void forceJacobianDiagonal(Eigen::VectorXd& k, Eigen::VectorXd& d) {
        k.setZero();
        d.setZero();
    }
    // Wall contacts inside an implicit solve: given the start state y0 and candidate
    // end-of-step velocities v1 (n), marks each coordinate that would end beyond a wall with
    // the velocity that lands it on the wall (target; NaN = free; marks already set are kept).
    // Returns how many coordinates it newly marked.
    virtual int contactVelocities(double /*h*/, const Eigen::VectorXd& /*y0*/,
                                  const Eigen::VectorXd& /*v1*/, Eigen::VectorXd& /*target*/) {
        return 0;
    }
    // Whether the force is strongly nonlinear over a step from y0 with end velocities v1 (n):
    // a smooth contact force that the end state x0 + h v1 engages (its stiffness grows from 0
    // where the step starts). Implicit methods then iterate Newton to convergence instead of
    // linearising once.
    virtual bool stronglyNonlinear(double /*h*/, const Eigen::VectorXd& /*y0*/, const Eigen::VectorXd& /*v1*/) {
        return false;
    }
    // --- springs as distance constraints, for position-based methods (xpbd) ---
    // Fills `out` and returns true when the system is a mass-spring body.
    virtual bool distanceConstraints(DistanceConstraints& /*out*/) { return false; }
    // Mass of each coordinate [kg] (n), 0 on constrained coordinates.
    virtual const Eigen::VectorXd& coordinateMass() const {
        static const Eigen::VectorXd none;
        return none;
    }
};

struct StepReport {
    double h = 0.0;               // step actually taken [s]
    double hNext = 0.0;           // step suggested for the next step [s]
    double errorEstimate = -1.0;  // local position error estimate [m], RMS over particles; < 0: none
    int evaluations = 0;          // force evaluations spent, including rejected attempts
    int rejected = 0;             // adaptive methods: attempts rejected before this step
    int linearIterations = 0;     // implicit methods: CG iterations (each one K and D product)
    // Products of the force Jacobians with a vector that count as force evaluations (CVODE:
    // every Jacobian-vector product, of GMRES and of its preconditioner; 0 for the others).
    int jacobianProducts = 0;
    // Why the step could not be taken (then y is left unchanged); nullptr when it was.
    const char* failure = nullptr;
};

// Tunables of the integrators (not of the physics), shared by every method.
struct IntegratorOptions {
    double atol = 1e-6;             // rk45, cvode-*: absolute tolerance on x [m] and v [m/s]
    double rtol = 1e-6;             // rk45, cvode-*: relative tolerance
    bool fixedStep = false;         // rk45: take the given step, no control (order studies)
    double minStep = 1e-10;         // rk45, cvode-*: below this step [s] the run fails instead of stalling
    double maxStep = 0.0;           // rk45, cvode-*: largest step [s]; 0 = no cap
    double cgTolerance = 1e-9;      // implicit-euler: CG relative residual
    int cgMaxIterations = 500;      // implicit-euler: a solve that needs more fails the step
    int newtonIterations = 1;       // implicit-euler: 1 = linearised once (Baraff-Witkin);
                                    // more = Newton iterations towards full backward Euler
    bool stepDoubling = false;      // fixed-step methods: estimate the local error by step
                                    // doubling (Richardson); costs about twice the evaluations
};

// Cumulative counters of a solver that keeps its own (CVODE), over every re-initialisation
// since the integrator was prepared.
struct SolverCounters {
    long steps = 0;                 // internal steps taken
    long rhsEvaluations = 0;        // right-hand-side (force) evaluations
    long jacobianProducts = 0;      // force Jacobian products: GMRES's Jv and the preconditioner's
    long linearIterations = 0;      // GMRES iterations
    long preconditionerIterations = 0;  // CG iterations inside the preconditioner
    long nonlinearIterations = 0;   // Newton (BDF) or fixed-point (Adams) iterations
    long errorTestFailures = 0;     // steps rejected by the local error test
    long convergenceFailures = 0;   // nonlinear solver convergence failures
    long reinitialisations = 0;     // CVodeReInit after a change between steps (restart())
    int order = 0;                  // the order of the last step
    double step = 0.0;              // the step size of the last step [s]
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual std::string_view name() const = 0;
    virtual int order() const = 0;
    virtual int evaluationsPerStep() const = 0;
    virtual bool adaptive() const { return false; }
    // Uses the Jacobians of OdeSystem: no explicit stability limit.
    virtual bool implicit() const { return false; }
    // Its step's first call is derivative() at y itself, before anything writes y (the
    // simulation then lets that call save y for a failed step: BodyOde::offerEnd).
    virtual bool startsAtState() const { return false; }
    virtual void prepare(const StateLayout& layout) = 0;
    virtual StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) = 0;
    // The state or the system (parameters, pointer) changed outside the integrator since its
    // last step: a method that keeps a history between steps starts afresh from y.
    virtual void restart() {}
    // A solver's own counters (CVODE), or nullptr.
    virtual const SolverCounters* counters() const { return nullptr; }
    // What of the integrator carries from one step to the next (besides y), for a checkpoint
    // of the run (Simulation::snapshot): restoring it and y, the next step is the step the
    // run took. restorable() is false when that history cannot be restored exactly (CVODE's
    // Nordsieck array and step-size controller): a restored run then restarts the method.
    virtual bool restorable() const { return true; }
    virtual std::vector<double> history() const { return {}; }
    virtual void setHistory(const std::vector<double>& history) { (void)history; }
    // The local error estimate of the last step taken, over the whole state (layout().size()
    // doubles: x, v and aux), as the method's own error control sees it (rk45: the embedded
    // 5th-minus-4th-order difference; CVODE: CVodeGetEstLocalErrors). Valid until the next
    // step or prepare(); nullptr when the method has none or has not stepped since prepare().
    virtual const double* localError() const { return nullptr; }

    void setOptions(const IntegratorOptions& options) { m_options = options; }
    const IntegratorOptions& options() const { return m_options; }

protected:
    IntegratorOptions m_options;
};

}  // namespace simcore
