#pragma once
// BodyOde: the body as the ODE the integrators see, with its force Jacobians.
//
//   y     = [x (3N) | v (3N) | E_damp | E_contact]
//   dy/dt = [v      | F / m  | P_damp | P_contact]
//
// The last two are the powers removed by damping and by contact, integrated with the motion
// so that the energy ledger is as accurate as the trajectory. F is ForceModel's (forces.h):
// gravity, wall contact, springs, gas, the layer barrier and the pointer.
//
// The end-of-step cache. A step measures its end state by one force evaluation (measureEnd:
// energies, volumes and the outer layer's normals are by-products of the forces). The
// derivative it computed is f at the state the next step starts from, so the next step's
// first stage takes it instead of evaluating it again (counted as the evaluation it is):
//
//   step n:   ... measureEnd(y) ------------------------- keepEnd()
//   step n+1: offerEnd() -> integrator: derivative(y) takes it -> withdrawEnd()
//
// Anything that changes the state, the parameters or the pointer between two steps drops it
// (dropEnd). Trajectories are bit-identical with or without it (Simulation::setReuseEndForces).
//
// The Jacobians (K = dF/dx, D = dF/dv, matrix-free; kernels in jacobians.h) serve
// implicit-euler, CVODE's Jacobian-vector products and the stability estimates; contact
// enters at the linearisation point, or at a design point (ContactDesign) where the
// estimates need one.

#include <array>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "simcore/body.h"
#include "simcore/contact.h"
#include "simcore/forces.h"
#include "simcore/integrators.h"

namespace simcore {

class BodyOde final : public OdeSystem {
public:
    static constexpr Eigen::Index kAux = 2;  // integrated: energy removed by damping, by contact

    // The body, its force model and its inverse masses per coordinate (3N; 0 on fixed
    // particles and absent axes) are the simulation's and outlive this.
    BodyOde(const Body& body, ForceModel& forces, const Eigen::VectorXd& inverseMass)
        : m_body(body), m_forces(forces), m_invMass(inverseMass) {}

    // What the resolved parameters decide here: whether contact is the thesis program's
    // projection (then implicit solves land particles on the box planes) and xpbd's substeps.
    void configure(bool contactProjection, int substeps) {
        m_contactProjection = contactProjection;
        m_substeps = substeps;
    }

    StateLayout layout() const override { return {positions(), kAux}; }
    void derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) override;
    void derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt, RangeWork then) override;
    // x' = v: derivativeMotion leaves xdot unwritten (OdeSystem::secondOrder).
    bool secondOrder() const override { return true; }
    void derivativeMotion(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt, RangeWork then) override;
    // dy/dt at y with the force by-products; counted as a force evaluation or not. With
    // `then`, the chunks run it on their ranges of dydt as they finish them. Without xdot,
    // dydt.head(n) is not written and `then` runs as derivativeMotion's.
    void compute(const Eigen::VectorXd& y, Eigen::VectorXd& dydt, ForceExtras& extras, bool count,
                 const RangeWork* then = nullptr, bool xdot = true);
    // The by-products of the last derivative() (degenerate springs, ...).
    const ForceExtras& extras() const { return m_extras; }
    int pieces() const override;
    void runPieces(TaskRef task) override;

    // --- the end-of-step cache ---
    // One uncounted evaluation at y, the state a step ended in: returns its by-products (the
    // outer layer's volume gradient stays in the force model until the next evaluation). Its
    // derivative is kept for the step that starts from y once keepEnd() says the step stands.
    // `beside`, when given, is called with each chunk's index inside the evaluation's first
    // pool run (work that reads y only: the step's scan).
    const ForceExtras& measureEnd(const Eigen::VectorXd& y, const TaskRef* beside = nullptr);
    // Sizes the cache for states of `size` (when the body is built: nothing is allocated in a
    // step) and drops it.
    void prepareEnd(Eigen::Index size) {
        m_forces.dropMotion();
        m_end.setZero(size);
        m_endValid = m_offered = false;
    }
    void keepEnd() { m_endValid = true; }
    void dropEnd() {
        m_forces.dropMotion();
        m_endValid = false;
    }
    bool endValid() const { return m_endValid; }
    // For the integrator step about to run: its first derivative() at the measured state takes
    // the kept derivative (once); withdrawEnd() after the step. The cache is then spent.
    // With saveTo, the step's first derivative() also copies the measured state y into
    // *saveTo: in its own pool run, each range before `then` may write it, when it takes the
    // kept derivative; else plainly before it evaluates. For integrators whose first
    // derivative() is at y, before anything writes y (Integrator::startsAtState).
    void offerEnd(Eigen::VectorXd* saveTo = nullptr) {
        m_offered = m_endValid;
        m_endValid = false;
        m_saveTo = saveTo;
    }
    // Returns true when a save asked by offerEnd was not done (no derivative() was called:
    // the integrator broke the contract above).
    bool withdrawEnd() {
        m_offered = false;
        return std::exchange(m_saveTo, nullptr) != nullptr;
    }
    // The kept derivative and by-products, to checkpoint a run; restoreEnd puts them back as
    // measured at y (Simulation::snapshot, restore).
    const Eigen::VectorXd& endDerivative() const;
    const ForceExtras& endExtras() const { return m_endExtras; }
    void restoreEnd(const Eigen::VectorXd& y, const Eigen::VectorXd& derivative, const ForceExtras& extras);

    // --- Jacobians for implicit integrators (kernels in jacobians.h) ---
    bool hasForceJacobian() const override { return true; }
    void linearize(double t, const Eigen::VectorXd& y) override;
    void forceJacobianProduct(const Eigen::VectorXd& dx, const Eigen::VectorXd& dv, Eigen::VectorXd& out) override;
    void forceJacobianDiagonal(Eigen::VectorXd& kdiag, Eigen::VectorXd& ddiag) override;
    const Eigen::VectorXd& coordinateMass() const override { return m_mass; }
    // Adds the design point's contact stiffness at every linearisation (nullopt: none).
    void setContactDesign(std::optional<ContactDesign> design) { m_design = std::move(design); }

    // --- structure for xpbd and implicit-euler's contacts ---
    bool distanceConstraints(DistanceConstraints& out) override;
    bool stronglyNonlinear(double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& v1) override;
    int contactVelocities(double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& v1,
                          Eigen::VectorXd& target) override;

private:
    Eigen::Index positions() const { return 3 * Eigen::Index{m_body.topology.particleCount()}; }
    // Takes the offered end-of-step derivative when y is the state it was measured at.
    // (With `then` run on dydt as the derivative's own would.)
    bool takeOffered(const Eigen::VectorXd& y, Eigen::VectorXd& dydt, const RangeWork* then, bool xdot = true);
    // Contact at the linearisation point: the walls' diagonal Jacobians and the layer
    // barrier's active pairs (see the .cpp), plus the design point when one is set.
    void linearizeContact(const Eigen::VectorXd& y);
    void addBarrierProduct(const Eigen::VectorXd& dx, Eigen::VectorXd& out) const;

    const Body& m_body;
    ForceModel& m_forces;
    const Eigen::VectorXd& m_invMass;
    bool m_contactProjection = false;
    int m_substeps = 1;
    ForceExtras m_extras;

    // The end-of-step cache: f at *m_endAt and its by-products.
    Eigen::VectorXd m_end;
    ForceExtras m_endExtras;
    const Eigen::VectorXd* m_endAt = nullptr;
    bool m_endValid = false;   // kept: the state has not changed since it was measured
    bool m_offered = false;    // offered to the integrator step now running
    Eigen::VectorXd* m_saveTo = nullptr;  // where the first derivative() copies y (offerEnd)

    // Linearisation point and its gas data (sized once, reused every step).
    Eigen::VectorXd m_x, m_mass;
    std::array<Eigen::VectorXd, 2> m_gradient;  // dV/dx of [inner, outer], 3N each
    std::array<double, 2> m_volume{};
    bool m_gasOn = false;
    // Contact at the linearisation point.
    struct ActiveBarrier {
        int inner, outer;
        double stiffness;                // 3 k q^2 [N/m]
        std::array<double, 3> normal;    // g / g0
    };
    bool m_contactOn = false;
    Eigen::VectorXd m_contactK, m_contactD;  // diagonal dF/dx, dF/dv of the walls (3N)
    std::vector<ActiveBarrier> m_barrierActive;
    std::optional<ContactDesign> m_design;
};

}  // namespace simcore
