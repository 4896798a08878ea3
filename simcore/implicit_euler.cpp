// Linearised backward Euler: the step body (the operator and its Jacobian products are in
// internal/implicit_operator.h).
#include <algorithm>
#include <cmath>

#include "simcore/failure_texts.h"
#include "simcore/integrators.h"
#include "simcore/internal/implicit_operator.h"
#include "simcore/internal/integrator_makers.h"

namespace simcore {

namespace {

// Linearised backward Euler (Baraff & Witkin, "Large steps in cloth simulation", 1998).
// Backward Euler on M v' = F(x, v), x' = v, linearised once at the start of the step:
//
//   (M - h D - h^2 K) dv = h (F0 + h K v0),   v1 = v0 + dv,   x1 = x0 + h v1
//
// with K = dF/dx, D = dF/dv at (x0, v0). The matrix is never formed: CG only needs its
// product with a vector, which the system computes spring by spring plus, for each gas layer,
// the rank-one term -(c/V^2) g g^T (g = dV/dx) that couples the whole layer (see
// implicit_operator.h). Constrained coordinates (fixed particles, absent axes) are filtered:
// the operator is the identity there and the right-hand side zero, so they never move.
// The integrated damping energy (aux) takes the explicit rate at the start of the step.
// With the clamped spring Jacobian (compressed springs drop their indefinite part) this is
// a W-method: first order whatever the approximation, and stable for stiff springs at any h.
class ImplicitEuler final : public Integrator {
public:
    std::string_view name() const override { return "implicit-euler"; }
    int order() const override { return 1; }
    int evaluationsPerStep() const override { return 1 + m_options.newtonIterations; }
    bool implicit() const override { return true; }
    void prepare(const StateLayout& layout) override {
        m_layout = layout;
        const Eigen::Index n = layout.positions;
        m_k1.setZero(layout.size());
        m_yk.setZero(layout.size());
        m_kk.setZero(layout.size());
        for (auto* v : {&m_rhs, &m_dv, &m_kv, &m_zero, &m_v, &m_v1, &m_z, &m_rhs2, &m_target}) v->setZero(n);
        m_operator.resize(n);
    }
    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        StepReport report;
        if (!system.hasForceJacobian()) {
            report.failure = "implicit-euler: this system provides no force Jacobian";
            return report;
        }
        const Eigen::Index n = m_layout.positions, m = m_layout.aux;
        system.derivative(t, y, m_k1);
        report.evaluations = 1;
        m_v = y.segment(n, n);
        m_target.setConstant(std::numeric_limits<double>::quiet_NaN());
        const int iterations = std::max(1, m_options.newtonIterations);
        for (int it = 0;; ++it) {
            // Contact forces (k d^3) have no stiffness where a step starts out of contact and a
            // large one where it ends in contact: linearised once, a large step lands deep in
            // the wall and the next one throws the body out with energy it never had. While the
            // end state is in contact, Newton continues (at most kContactNewton iterations).
            if (it >= iterations && (it >= kContactNewton || !system.stronglyNonlinear(h, y, m_v))) break;
            const Eigen::VectorXd& mass = system.coordinateMass();
            if (it == 0) {
                // Baraff-Witkin: linearised at (x0, v0); rhs = h (F0 + h K v0), F0 = M a0.
                system.linearize(t, y);
                system.forceJacobianProduct(y.segment(n, n), m_zero, m_kv);
                m_rhs = h * (mass.cwiseProduct(m_k1.segment(n, n)) + h * m_kv);
            } else {
                // Newton on G(v) = M (v - v0) - h F(x0 + h v, v) = 0 at the current iterate.
                m_yk = y;
                m_yk.head(n) = y.head(n) + h * m_v;
                m_yk.segment(n, n) = m_v;
                system.derivative(t + h, m_yk, m_kk);
                ++report.evaluations;
                system.linearize(t + h, m_yk);
                m_rhs = h * mass.cwiseProduct(m_kk.segment(n, n)) - mass.cwiseProduct(m_v - y.segment(n, n));
            }
            for (Eigen::Index i = 0; i < n; ++i)
                if (mass[i] == 0.0) m_rhs[i] = 0.0;
            m_operator.set(system, h);
            if (!solve(system, y, h, report)) {
                report.failure = failure_text::kImplicitEulerNoConvergence;
                return report;
            }
            m_v += m_dv;
            if (it > 0 && m_dv.norm() <= 1e-10 * (1.0 + m_v.norm())) break;
        }
        // The integrated diagnostics (aux: energy removed by damping) take the rate at the end
        // of the step, as backward Euler does: with the rate at the start a large step would
        // book far more damping than the implicit step actually removes. One more evaluation.
        m_yk.head(n) = y.head(n) + h * m_v;
        m_yk.segment(n, n) = m_v;
        m_yk.tail(m) = y.tail(m);
        system.derivative(t + h, m_yk, m_kk);
        ++report.evaluations;
        y.head(2 * n) = m_yk.head(2 * n);
        y.tail(m) += h * m_kk.tail(m);
        report.h = h;
        report.hNext = h;
        return report;
    }

private:
    static constexpr int kContactNewton = 12;
    // Solves A dv = rhs for the current iterate m_v, with wall contacts inside the solve: a
    // coordinate that would end beyond a wall gets the velocity that lands it on the wall and
    // the solve is repeated with that velocity prescribed, so the springs feel the stop in the
    // same step (with contacts only handled after the step, a large step lets the rest of the
    // body crash through the stopped particles). A prescribed dv = z moves to the right-hand
    // side: rhs - A z on the free rows.
    bool solve(OdeSystem& system, const Eigen::VectorXd& y, double h, StepReport& report) {
        const Eigen::Index n = m_layout.positions;
        auto prescribe = [&] {
            for (Eigen::Index i = 0; i < n; ++i) m_z[i] = std::isfinite(m_target[i]) ? m_target[i] - m_v[i] : 0.0;
            m_operator.constrain(&m_target);
            const Eigen::VectorXd& coupled = m_operator.coupling(m_z);
            for (Eigen::Index i = 0; i < n; ++i) m_rhs2[i] = m_operator.isFree(i) ? m_rhs[i] - coupled[i] : 0.0;
        };
        prescribe();  // contacts found by earlier iterations stay prescribed
        m_solver.setTolerance(m_options.cgTolerance);
        m_solver.setMaxIterations(m_options.cgMaxIterations);
        for (int pass = 0;; ++pass) {
            m_solver.compute(m_operator);
            m_dv = m_solver.solve(m_rhs2);
            report.linearIterations += static_cast<int>(m_solver.iterations());
            if (m_solver.info() != Eigen::Success || !m_dv.allFinite()) return false;
            m_dv += m_z;
            if (pass == 12) return true;
            m_v1 = m_v + m_dv;
            if (system.contactVelocities(h, y, m_v1, m_target) == 0) return true;
            prescribe();
        }
    }

    StateLayout m_layout;
    Eigen::VectorXd m_k1, m_yk, m_kk;
    Eigen::VectorXd m_rhs, m_dv, m_kv, m_zero, m_v, m_v1, m_z, m_rhs2, m_target;
    ImplicitOperator m_operator;
    Eigen::ConjugateGradient<ImplicitOperator, Eigen::Lower | Eigen::Upper, JacobiPreconditioner> m_solver;
};


}  // namespace

std::unique_ptr<Integrator> makeImplicitEuler() { return std::make_unique<ImplicitEuler>(); }

}  // namespace simcore
