// SUNDIALS CVODE (Hindmarsh et al., "SUNDIALS: Suite of nonlinear and differential/algebraic
// equation solvers", ACM TOMS 2005; CVODE 6.4 user guide) as two integrators of the lab.
//
//   cvode-bdf    variable-order BDF 1-5, Newton's method, matrix-free GMRES (SPGMR):
//                  Jv       the analytic force Jacobians (OdeSystem::forceJacobianProduct):
//                           J [wx | wv | wa] = [wv | M^-1 (K wx + D wv) | 0]
//                  P^-1 r   implicit-euler's linear solve: the Newton matrix I - gamma J has
//                           the exact block reduction
//                             (M - gamma D - gamma^2 K) zv = M rv + gamma K rx,
//                             zx = rx + gamma zv,  za = ra
//                           solved by Jacobi-preconditioned CG on ImplicitOperator (h = gamma),
//                           to the tolerance CVODE asks of a preconditioner (delta)
//                No dense Jacobian is ever formed.
//   cvode-adams  variable-order Adams-Moulton 1-12, fixed-point (functional) iteration: no
//                Jacobian at all, for non-stiff motion.
//
// One call of step() is one internal CVODE step (CV_ONE_STEP) with the stop time t + h, so
// the lab's step loop, its checks and its diagnostics run after every CVODE step. The state
// N_Vector is N_VMake_Serial over the caller's buffer: CVODE writes each step's result into
// the simulation's state directly (no copy per step). The right-hand side and the Jacobian
// products go through OdeSystem, whose interface takes Eigen vectors: each callback copies
// its N_Vector in and its result out (two passes over 6N doubles, small beside a force
// evaluation).
//
// Tolerances: atol on x [m] and v [m/s], rtol relative, as rk45 (CVODE's norm is the
// weighted RMS, rk45's the max norm). The integrated energy accounts (aux) are integrated
// with the motion but, as in rk45, do not take part in the step control (atol 1e30 there).
//
// CVODE keeps a history between steps (the Nordsieck array); restart() marks it stale and
// the next step calls CVodeReInit from the current state (counted).

#include "simcore/internal/cvode_integrators.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <cvode/cvode.h>
#include <cvode/cvode_ls.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "simcore/internal/implicit_operator.h"

namespace simcore {

namespace {

// Forwards the mechanical structure of a system and counts its Jacobian products (each is
// one pass over the springs, like a force evaluation).
class CountingJacobian final : public OdeSystem {
public:
    void bind(OdeSystem* system) { m_system = system; }
    using OdeSystem::derivative;
    StateLayout layout() const override { return m_system->layout(); }
    void derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) override {
        m_system->derivative(t, y, dydt);
    }
    bool hasForceJacobian() const override { return m_system->hasForceJacobian(); }
    void forceJacobianProduct(const Eigen::VectorXd& dx, const Eigen::VectorXd& dv, Eigen::VectorXd& out) override {
        ++products;
        m_system->forceJacobianProduct(dx, dv, out);
    }
    void forceJacobianDiagonal(Eigen::VectorXd& k, Eigen::VectorXd& d) override {
        m_system->forceJacobianDiagonal(k, d);
    }
    const Eigen::VectorXd& coordinateMass() const override { return m_system->coordinateMass(); }
    long products = 0;

private:
    OdeSystem* m_system = nullptr;
};

class Cvode final : public Integrator {
public:
    explicit Cvode(bool bdf) : m_bdf(bdf) {}
    ~Cvode() override { destroy(); }
    Cvode(const Cvode&) = delete;
    Cvode& operator=(const Cvode&) = delete;

    std::string_view name() const override { return m_bdf ? "cvode-bdf" : "cvode-adams"; }
    int order() const override { return m_bdf ? 5 : 12; }
    int evaluationsPerStep() const override { return 2; }  // typical; CVODE decides
    bool adaptive() const override { return true; }
    bool implicit() const override { return m_bdf; }
    const double* localError() const override { return m_hasError ? m_localError.data() : nullptr; }
    void prepare(const StateLayout& layout) override {
        destroy();
        m_layout = layout;
        const Eigen::Index n = layout.positions;
        m_y.setZero(layout.size());
        m_dydt.setZero(layout.size());
        m_localError.setZero(layout.size());
        m_hasError = false;
        for (auto* v : {&m_dx, &m_dv, &m_out, &m_rhs, &m_zv, &m_zero, &m_invMass, &m_residual, &m_z, &m_p, &m_ap, &m_invDiagonal})
            v->setZero(n);
        m_operator.resize(n);
        m_counters = SolverCounters{};
        m_base = SolverCounters{};
        m_jacobian.products = 0;
        m_cgIterations = 0;
        m_reinitialisations = 0;
        m_needInit = true;
        m_restart = false;
    }
    void restart() override { m_restart = true; }
    const SolverCounters* counters() const override { return &m_counters; }
    // The Nordsieck array, the order and step-size controller live inside CVODE's memory.
    bool restorable() const override { return false; }

    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        StepReport report;
        if (m_bdf && !system.hasForceJacobian()) {
            report.failure = "cvode-bdf: this system provides no force Jacobian";
            return report;
        }
        m_system = &system;
        m_jacobian.bind(&system);
        if (!m_mem && !create(y)) {
            report.failure = m_message.c_str();
            return report;
        }
        if (N_VGetArrayPointer(m_state) != y.data()) N_VSetArrayPointer_Serial(y.data(), m_state);
        if (m_needInit || m_restart) {
            // A restart keeps the counts so far: CVodeReInit zeroes CVODE's own.
            if (!m_needInit) {
                m_base = cumulative();
                m_base.jacobianProducts -= m_jacobian.products;  // counted apart, cumulatively
                ++m_reinitialisations;
            }
            if (!check(CVodeReInit(m_mem, t, m_state), report)) return report;
            // At the start of a run CVODE estimates its first step; after a restart it starts
            // (at order 1) from the step it was taking (at most the lab's h). With its own
            // estimate (a tiny step) every restart would cost dozens of steps, and a body
            // resting on the floor under contact = projection restarts at nearly every step.
            CVodeSetInitStep(m_mem, m_needInit ? 0.0 : m_planned > 0.0 ? std::min(h, m_planned) : h);
            m_fresh = true;
            m_tn = t;
            m_needInit = m_restart = false;
        }
        setTolerances();
        if (!check(CVodeSetMinStep(m_mem, m_options.minStep), report) ||
            !check(CVodeSetMaxStep(m_mem, std::max(0.0, m_options.maxStep)), report))
            return report;
        // The lab's time and CVODE's may differ by the round-off of the lab's compensated sum:
        // CVODE steps from its own time. The lab's step is a hard limit where the lab shortened
        // it (to land on a sampling time, or the speed cap): then a stop time. Otherwise none:
        // a stop time one step ahead also clamps the step after it (CVODE checks it after each
        // step) and counts as a step change at every step, which keeps CVODE from ever raising
        // its order or its step (measured: stuck at 1e-6 s on spring1d). The step reported as
        // the next one is kHeadroom times the one CVODE plans, more than CVODE ever grows a
        // step (10x), so that a lab step not shortened never lets CVODE pass a sampling time
        // (after a stop time CVODE may take more than the step it reported: measured
        // 0.55 s -> 0.628 s past a sample at 0.6 s with the plain report).
        const bool shortened = m_fresh || h < m_reported * (1.0 - 1e-12);
        const double tstop = m_tn + (shortened ? h : 1e20);
        if (!check(CVodeSetStopTime(m_mem, tstop), report)) return report;
        const SolverCounters before = cumulative();
        double tret = m_tn;
        m_message.clear();
        const int flag = CVode(m_mem, m_tn + h, m_state, &tret, CV_ONE_STEP);
        m_fresh = false;
        m_counters = cumulative();
        report.evaluations = static_cast<int>(m_counters.rhsEvaluations - before.rhsEvaluations);
        report.jacobianProducts = static_cast<int>(m_counters.jacobianProducts - before.jacobianProducts);
        report.rejected = static_cast<int>(m_counters.errorTestFailures - before.errorTestFailures);
        report.linearIterations = static_cast<int>(m_counters.linearIterations - before.linearIterations);
        if (flag < 0) {
            failure(flag);
            report.failure = m_message.c_str();
            return report;
        }
        report.h = tret - m_tn;
        m_tn = tret;
        double hcur = 0.0;
        CVodeGetCurrentStep(m_mem, &hcur);
        report.hNext = m_reported = kHeadroom * hcur;
        m_planned = hcur;
        // Position error, RMS over particles, from CVODE's local error estimate (as rk45's).
        m_hasError = false;
        if (CVodeGetEstLocalErrors(m_mem, m_work) == CV_SUCCESS) {
            const Eigen::Index n = m_layout.positions;
            const Eigen::Map<const Eigen::VectorXd> e(N_VGetArrayPointer(m_work), n);
            report.errorEstimate = std::sqrt(e.squaredNorm() / std::max(1.0, static_cast<double>(n) / 3.0));
            // Kept apart: m_work also serves the preconditioner (error weights) in the next step.
            m_localError = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(m_work), m_layout.size());
            m_hasError = true;
        }
        return report;
    }

private:
    bool create(Eigen::VectorXd& y) {
        const auto size = static_cast<sunindextype>(m_layout.size());
        if (SUNContext_Create(nullptr, &m_context) != 0) return fail("cvode: cannot create a SUNDIALS context");
        m_state = N_VMake_Serial(size, y.data(), m_context);
        m_atol = N_VNew_Serial(size, m_context);
        m_work = N_VNew_Serial(size, m_context);
        m_mem = CVodeCreate(m_bdf ? CV_BDF : CV_ADAMS, m_context);
        if (!m_state || !m_atol || !m_work || !m_mem) return fail("cvode: out of memory");
        CVodeSetErrHandlerFn(m_mem, &Cvode::errorHandler, this);
        if (CVodeInit(m_mem, &Cvode::rhs, 0.0, m_state) != CV_SUCCESS || CVodeSetUserData(m_mem, this) != CV_SUCCESS)
            return fail("cvode: initialisation failed: " + m_message);
        m_appliedAtol = m_appliedRtol = -1.0;
        setTolerances();
        if (m_bdf) {
            // Left preconditioning; the preconditioner is nearly an exact solve, so a short
            // Krylov space suffices (CVODE's default, 5).
            m_linear = SUNLinSol_SPGMR(m_state, SUN_PREC_LEFT, 5, m_context);
            if (!m_linear || CVodeSetLinearSolver(m_mem, m_linear, nullptr) != CV_SUCCESS ||
                CVodeSetJacTimes(m_mem, &Cvode::jacobianSetup, &Cvode::jacobianTimes) != CV_SUCCESS ||
                CVodeSetPreconditioner(m_mem, &Cvode::preconditionerSetup, &Cvode::preconditionerSolve) != CV_SUCCESS)
                return fail("cvode: cannot attach the linear solver: " + m_message);
        } else {
            m_nonlinear = SUNNonlinSol_FixedPoint(m_state, 0, m_context);
            if (!m_nonlinear || CVodeSetNonlinearSolver(m_mem, m_nonlinear) != CV_SUCCESS)
                return fail("cvode: cannot attach the fixed-point solver: " + m_message);
        }
        // One internal step per call: the work limit never binds.
        CVodeSetMaxNumSteps(m_mem, 1000000);
        return true;
    }
    bool fail(const std::string& what) {
        m_message = what;
        return false;
    }
    void destroy() {
        if (m_mem) CVodeFree(&m_mem);
        if (m_linear) SUNLinSolFree(m_linear);
        if (m_nonlinear) SUNNonlinSolFree(m_nonlinear);
        for (N_Vector* v : {&m_state, &m_atol, &m_work})
            if (*v) {
                N_VDestroy(*v);
                *v = nullptr;
            }
        if (m_context) SUNContext_Free(&m_context);
        m_mem = nullptr;
        m_linear = nullptr;
        m_nonlinear = nullptr;
        m_context = nullptr;
    }
    void setTolerances() {
        if (m_options.atol == m_appliedAtol && m_options.rtol == m_appliedRtol) return;
        const Eigen::Index n2 = 2 * m_layout.positions;
        Eigen::Map<Eigen::VectorXd> atol(N_VGetArrayPointer(m_atol), m_layout.size());
        atol.head(n2).setConstant(m_options.atol);
        atol.tail(m_layout.aux).setConstant(1e30);  // the energy accounts: not controlled
        CVodeSVtolerances(m_mem, std::max(0.0, m_options.rtol), m_atol);
        m_appliedAtol = m_options.atol;
        m_appliedRtol = m_options.rtol;
    }
    bool check(int flag, StepReport& report) {
        if (flag >= 0) return true;
        failure(flag);
        report.failure = m_message.c_str();
        return false;
    }
    // CVODE's own message (from its error handler), in words, after what the flag means.
    void failure(int flag) {
        std::string what;
        switch (flag) {
            case CV_TOO_MUCH_WORK: what = "too much work (the step limit was reached)"; break;
            case CV_TOO_MUCH_ACC: what = "the tolerances are too tight for the machine precision"; break;
            case CV_ERR_FAILURE: what = "the local error test failed repeatedly or with the minimum step"; break;
            case CV_CONV_FAILURE:
                what = m_bdf ? "Newton's method failed to converge repeatedly or with the minimum step"
                             : "the fixed-point iteration failed to converge repeatedly or with the minimum step "
                               "(the motion is too stiff for functional iteration: use cvode-bdf)";
                break;
            case CV_LSETUP_FAIL: what = "the preconditioner setup failed"; break;
            case CV_LSOLVE_FAIL: what = "the linear solve (GMRES with the implicit-euler preconditioner) failed"; break;
            case CV_RHSFUNC_FAIL:
            case CV_REPTD_RHSFUNC_ERR:
            case CV_UNREC_RHSFUNC_ERR:
            case CV_FIRST_RHSFUNC_ERR:
                what = "the forces became non-finite at every step size tried";
                break;
            case CV_TOO_CLOSE: what = "the step asked for is too small to take"; break;
            default: what = "error " + std::to_string(flag);
        }
        const char* flagName = CVodeGetReturnFlagName(flag);
        std::string text = std::string(name()) + ": " + what;
        if (flagName) {
            text += " (";
            text += flagName;
            std::free(const_cast<char*>(flagName));  // CVodeGetReturnFlagName allocates
            text += ")";
        }
        if (!m_message.empty()) text += ": CVODE says \"" + m_message + "\"";
        m_message = text;
    }
    // Counts since prepare(): CVODE's own (zeroed by each re-initialisation, and stale until
    // the first step after one) on top of those before the last re-initialisation, plus the
    // preconditioner's, which are counted here.
    SolverCounters cumulative() const {
        SolverCounters c = m_base;
        c.jacobianProducts = m_base.jacobianProducts;
        if (m_mem && !m_fresh) {
            long v = 0;
            CVodeGetNumSteps(m_mem, &v), c.steps += v;
            CVodeGetNumRhsEvals(m_mem, &v), c.rhsEvaluations += v;
            CVodeGetNumErrTestFails(m_mem, &v), c.errorTestFailures += v;
            CVodeGetNumNonlinSolvIters(m_mem, &v), c.nonlinearIterations += v;
            CVodeGetNumNonlinSolvConvFails(m_mem, &v), c.convergenceFailures += v;
            if (m_bdf) {
                CVodeGetNumJtimesEvals(m_mem, &v), c.jacobianProducts += v;
                CVodeGetNumLinIters(m_mem, &v), c.linearIterations += v;
            }
            int q = 0;
            CVodeGetLastOrder(m_mem, &q);
            c.order = q;
            double hlast = 0.0;
            CVodeGetLastStep(m_mem, &hlast);
            c.step = hlast;
        }
        // m_base holds CVODE's counts only; the preconditioner's are cumulative here.
        c.jacobianProducts += m_jacobian.products;
        c.preconditionerIterations = m_cgIterations;
        c.reinitialisations = m_reinitialisations;
        return c;
    }

    // --- callbacks (user_data = this) ---
    static Cvode& self(void* data) { return *static_cast<Cvode*>(data); }
    static int rhs(double t, N_Vector y, N_Vector ydot, void* data) {
        Cvode& c = self(data);
        const Eigen::Index size = c.m_layout.size();
        c.m_y = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(y), size);
        c.m_system->derivative(t, c.m_y, c.m_dydt);
        if (!c.m_dydt.allFinite()) return 1;  // recoverable: CVODE retries with a smaller step
        Eigen::Map<Eigen::VectorXd>(N_VGetArrayPointer(ydot), size) = c.m_dydt;
        return 0;
    }
    void linearize(double t, N_Vector y) {
        m_y = Eigen::Map<const Eigen::VectorXd>(N_VGetArrayPointer(y), m_layout.size());
        m_system->linearize(t, m_y);
        const Eigen::VectorXd& mass = m_system->coordinateMass();
        for (Eigen::Index i = 0; i < m_layout.positions; ++i) m_invMass[i] = mass[i] > 0.0 ? 1.0 / mass[i] : 0.0;
        m_gamma = -1.0;  // the operator's diagonal must be recomputed
    }
    static int jacobianSetup(double t, N_Vector y, N_Vector /*fy*/, void* data) {
        self(data).linearize(t, y);
        return 0;
    }
    static int jacobianTimes(N_Vector v, N_Vector jv, double /*t*/, N_Vector /*y*/, N_Vector /*fy*/, void* data,
                             N_Vector /*tmp*/) {
        Cvode& c = self(data);
        const Eigen::Index n = c.m_layout.positions;
        const double* w = N_VGetArrayPointer(v);
        double* out = N_VGetArrayPointer(jv);
        c.m_dx = Eigen::Map<const Eigen::VectorXd>(w, n);
        c.m_dv = Eigen::Map<const Eigen::VectorXd>(w + n, n);
        // Not through the counting wrapper: CVODE counts these itself (njtimes).
        c.m_system->forceJacobianProduct(c.m_dx, c.m_dv, c.m_out);
        Eigen::Map<Eigen::VectorXd>(out, n) = c.m_dv;
        Eigen::Map<Eigen::VectorXd>(out + n, n) = c.m_invMass.cwiseProduct(c.m_out);
        Eigen::Map<Eigen::VectorXd>(out + 2 * n, c.m_layout.aux).setZero();
        return 0;
    }
    static int preconditionerSetup(double t, N_Vector y, N_Vector /*fy*/, int jok, int* jcur, double /*gamma*/,
                                   void* data) {
        Cvode& c = self(data);
        if (!jok) c.linearize(t, y);
        *jcur = jok ? 0 : 1;
        return 0;
    }
    static int preconditionerSolve(double /*t*/, N_Vector /*y*/, N_Vector /*fy*/, N_Vector r, N_Vector z,
                                   double gamma, double delta, int /*lr*/, void* data) {
        Cvode& c = self(data);
        const Eigen::Index n = c.m_layout.positions, m = c.m_layout.aux;
        const double* rr = N_VGetArrayPointer(r);
        double* zz = N_VGetArrayPointer(z);
        if (gamma != c.m_gamma) {
            c.m_operator.set(c.m_jacobian, gamma);
            c.m_gamma = gamma;
            c.m_invDiagonal = c.m_operator.diagonal().unaryExpr([](double d) { return d > 0.0 ? 1.0 / d : 1.0; });
        }
        const Eigen::Map<const Eigen::VectorXd> rx(rr, n), rv(rr + n, n);
        c.m_dx = rx;
        c.m_jacobian.forceJacobianProduct(c.m_dx, c.m_zero, c.m_out);  // K rx
        const Eigen::VectorXd& mass = c.m_jacobian.coordinateMass();
        for (Eigen::Index i = 0; i < n; ++i)
            c.m_rhs[i] = c.m_operator.isFree(i) ? mass[i] * rv[i] + gamma * c.m_out[i] : rv[i];
        // The accuracy CVODE asks of the preconditioner, relative to the right-hand side
        // (delta is in CVODE's weighted 2-norm); never looser than 1e-2 nor tighter than the
        // implicit-euler CG tolerance.
        double tolerance = 1e-2;
        if (CVodeGetErrWeights(c.m_mem, c.m_work) == CV_SUCCESS) {
            const Eigen::Map<const Eigen::VectorXd> w(N_VGetArrayPointer(c.m_work), c.m_layout.size());
            const Eigen::Map<const Eigen::VectorXd> all(rr, c.m_layout.size());
            const double norm = all.head(2 * n).cwiseProduct(w.head(2 * n)).norm();
            if (norm > 0.0 && delta > 0.0) tolerance = std::clamp(delta / norm, c.m_options.cgTolerance, 1e-2);
        }
        c.m_cgIterations += c.conjugateGradient(tolerance);
        if (!c.m_zv.allFinite()) return 1;  // recoverable: CVODE updates the Jacobian or cuts h
        Eigen::Map<Eigen::VectorXd>(zz, n) = rx + gamma * c.m_zv;
        Eigen::Map<Eigen::VectorXd>(zz + n, n) = c.m_zv;
        Eigen::Map<Eigen::VectorXd>(zz + 2 * n, m) = Eigen::Map<const Eigen::VectorXd>(rr + 2 * n, m);
        return 0;
    }
    // Jacobi-preconditioned conjugate gradient on ImplicitOperator: m_zv from m_rhs, to the
    // relative residual `tolerance` (at most cgMaxIterations; a preconditioner need not be
    // exact). Written out rather than Eigen's, which spends an operator product on the
    // residual of the zero start. Returns the iterations (one operator product each).
    long conjugateGradient(double tolerance) {
        m_zv.setZero();
        m_residual = m_rhs;
        const double bound2 = tolerance * tolerance * m_rhs.squaredNorm();
        if (!(bound2 > 0.0)) return 0;
        m_z = m_residual.cwiseProduct(m_invDiagonal);
        m_p = m_z;
        double rz = m_residual.dot(m_z);
        long it = 0;
        while (it < m_options.cgMaxIterations) {
            m_ap = m_operator.product(m_p);
            ++it;
            const double alpha = rz / m_p.dot(m_ap);
            m_zv += alpha * m_p;
            m_residual -= alpha * m_ap;
            if (!(m_residual.squaredNorm() > bound2)) break;
            m_z = m_residual.cwiseProduct(m_invDiagonal);
            const double next = m_residual.dot(m_z);
            m_p = m_z + (next / rz) * m_p;
            rz = next;
        }
        return it;
    }
    static void errorHandler(int code, const char* /*module*/, const char* /*function*/, char* message, void* data) {
        if (code < 0) self(data).m_message = message ? message : "";
    }

    static constexpr double kHeadroom = 11.0;  // reported next step / CVODE's planned step
    const bool m_bdf;
    StateLayout m_layout;
    OdeSystem* m_system = nullptr;
    CountingJacobian m_jacobian;
    SUNContext m_context = nullptr;
    void* m_mem = nullptr;
    N_Vector m_state = nullptr;  // over the caller's state buffer
    N_Vector m_atol = nullptr;   // per-component absolute tolerances
    N_Vector m_work = nullptr;   // local error estimates, error weights
    Eigen::VectorXd m_localError;  // the last step's local error estimate (localError())
    bool m_hasError = false;
    SUNLinearSolver m_linear = nullptr;
    SUNNonlinearSolver m_nonlinear = nullptr;
    bool m_needInit = true;
    bool m_restart = false;
    double m_tn = 0.0;           // CVODE's time [s]
    double m_planned = 0.0;      // the step CVODE plans next [s]
    double m_reported = 0.0;     // the next step reported to the lab (kHeadroom x planned) [s]
    double m_appliedAtol = -1.0, m_appliedRtol = -1.0;
    double m_gamma = -1.0;       // the gamma the operator's diagonal was computed for
    std::string m_message;
    SolverCounters m_counters, m_base;
    bool m_fresh = false;        // (re)initialised, no step since: CVODE's counters are stale
    long m_reinitialisations = 0;
    long m_cgIterations = 0;
    // Scratch, sized in prepare().
    Eigen::VectorXd m_y, m_dydt, m_dx, m_dv, m_out, m_rhs, m_zv, m_zero, m_invMass;
    Eigen::VectorXd m_residual, m_z, m_p, m_ap, m_invDiagonal;
    ImplicitOperator m_operator;
};

}  // namespace

std::unique_ptr<Integrator> makeCvodeIntegrator(bool bdf) { return std::make_unique<Cvode>(bdf); }

}  // namespace simcore
