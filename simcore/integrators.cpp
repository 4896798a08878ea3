#include "simcore/integrators.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "simcore/compositions.h"
#include "simcore/failure_texts.h"
#include "simcore/force_kernels.h"
#include "simcore/internal/integrator_makers.h"
#include "simcore/params.h"

namespace simcore {

namespace {


// Base with the stage vectors every explicit method shares.
class ExplicitBase : public Integrator {
public:
    // Every one below evaluates at y first.
    bool startsAtState() const override { return true; }
    void prepare(const StateLayout& layout) override {
        m_layout = layout;
        const Eigen::Index n = layout.size();
        for (auto* v : {&m_k1, &m_k2, &m_k3, &m_k4, &m_tmp}) v->setZero(n);
    }

protected:
    StateLayout m_layout;
    Eigen::VectorXd m_k1, m_k2, m_k3, m_k4, m_tmp;
};

class Euler final : public ExplicitBase {
public:
    std::string_view name() const override { return "euler"; }
    int order() const override { return 1; }
    int evaluationsPerStep() const override { return 1; }
    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        // The update of each range as soon as its derivative is final (see OdeSystem).
        system.derivative(t, y, m_k1, [&](Eigen::Index b, Eigen::Index l) { y.segment(b, l) += h * m_k1.segment(b, l); });
        return {h, h, -1.0, 1};
    }
};

class Midpoint final : public ExplicitBase {
public:
    std::string_view name() const override { return "midpoint"; }
    int order() const override { return 2; }
    int evaluationsPerStep() const override { return 2; }
    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        // Thesis eq. 31-33: k1 = A(y), k2 = A(y + h k1), y += h (k1 + k2) / 2.
        system.derivative(t, y, m_k1, [&](Eigen::Index b, Eigen::Index l) {
            m_tmp.segment(b, l) = y.segment(b, l) + h * m_k1.segment(b, l);
        });
        system.derivative(t + h, m_tmp, m_k2, [&](Eigen::Index b, Eigen::Index l) {
            y.segment(b, l) += (0.5 * h) * (m_k1.segment(b, l) + m_k2.segment(b, l));
        });
        return {h, h, -1.0, 2};
    }
};

class Rk4 final : public ExplicitBase {
public:
    std::string_view name() const override { return "rk4"; }
    int order() const override { return 4; }
    int evaluationsPerStep() const override { return 4; }
    void prepare(const StateLayout& layout) override {
        ExplicitBase::prepare(layout);
        m_s2.setZero(layout.size());
        m_s3.setZero(layout.size());
    }
    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        // The stage sums element by element, each range as soon as its derivative is final
        // (see OdeSystem::derivative), in the widest vectors the CPU has (kernels::stageSum
        // and rk4Sum: y + c k and y + h/6 (k1 + 2 k2 + 2 k3 + k4), the same bits as plain loops).
        if (system.secondOrder()) return motionStep(system, t, h, y);
        auto stage = [this, &y](double c, const Eigen::VectorXd* k) {
            return [this, &y, c, k](Eigen::Index b, Eigen::Index l) {
                kernels::stageSum(m_tmp.data() + b, y.data() + b, c, k->data() + b, static_cast<std::size_t>(l));
            };
        };
        system.derivative(t, y, m_k1, stage(0.5 * h, &m_k1));
        system.derivative(t + 0.5 * h, m_tmp, m_k2, stage(0.5 * h, &m_k2));
        system.derivative(t + 0.5 * h, m_tmp, m_k3, stage(h, &m_k3));
        system.derivative(t + h, m_tmp, m_k4, [&](Eigen::Index b, Eigen::Index l) {
            kernels::rk4Sum(y.data() + b, h / 6.0, m_k1.data() + b, m_k2.data() + b, m_k3.data() + b, m_k4.data() + b,
                            static_cast<std::size_t>(l));
        });
        return {h, h, -1.0, 4};
    }

private:
    // On a second-order system (OdeSystem::secondOrder) x' is never copied out of v: the
    // stage states are kept apart (y, s1, s2, s3) and x's sums read their v, which are the
    // very numbers a copy would hold, so the bits are those of the sums above. Each range
    // [b, b + l) of v comes with x's range [b - n, b - n + l) (aux ranges alone).
    template <class Work>
    static auto motionRanges(Eigen::Index n, Work work) {
        return [n, work](Eigen::Index b, Eigen::Index l) {
            const Eigen::Index vEnd = std::min(b + l, 2 * n);
            if (b < vEnd) work(b - n, b, static_cast<std::size_t>(vEnd - b));
            if (vEnd < b + l) work(-1, vEnd, static_cast<std::size_t>(b + l - vEnd));
        };
    }
    StepReport motionStep(OdeSystem& system, double t, double h, Eigen::VectorXd& y) {
        const Eigen::Index n = m_layout.positions;
        Eigen::VectorXd &s1 = m_tmp, &s2 = m_s2, &s3 = m_s3;
        // s = y + c k, x's from the stage state's v (xb: where x's range starts; < 0 for aux).
        auto stage = [&](double c, const Eigen::VectorXd& at, const Eigen::VectorXd& k, Eigen::VectorXd& s) {
            return motionRanges(n, [&y, c, &at, &k, &s](Eigen::Index xb, Eigen::Index b, std::size_t l) {
                if (xb >= 0) kernels::stageSum(s.data() + xb, y.data() + xb, c, at.data() + b, l);
                kernels::stageSum(s.data() + b, y.data() + b, c, k.data() + b, l);
            });
        };
        system.derivativeMotion(t, y, m_k1, stage(0.5 * h, y, m_k1, s1));
        system.derivativeMotion(t + 0.5 * h, s1, m_k2, stage(0.5 * h, s1, m_k2, s2));
        system.derivativeMotion(t + 0.5 * h, s2, m_k3, stage(h, s2, m_k3, s3));
        // x before v: x's sum reads y's v, which v's sum overwrites.
        system.derivativeMotion(t + h, s3, m_k4, motionRanges(n, [&](Eigen::Index xb, Eigen::Index b, std::size_t l) {
            if (xb >= 0) kernels::rk4Sum(y.data() + xb, h / 6.0, y.data() + b, s1.data() + b, s2.data() + b, s3.data() + b, l);
            kernels::rk4Sum(y.data() + b, h / 6.0, m_k1.data() + b, m_k2.data() + b, m_k3.data() + b, m_k4.data() + b, l);
        }));
        return {h, h, -1.0, 4};
    }

    Eigen::VectorXd m_s2, m_s3;
};

class SymplecticEuler final : public ExplicitBase {
public:
    std::string_view name() const override { return "symplectic-euler"; }
    int order() const override { return 1; }
    int evaluationsPerStep() const override { return 1; }
    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        // v_{n+1} = v_n + h a(x_n, v_n); x_{n+1} = x_n + h v_{n+1}.
        const Eigen::Index n = m_layout.positions;
        system.derivative(t, y, m_k1);
        y.segment(n, n + m_layout.aux) += h * m_k1.segment(n, n + m_layout.aux);
        y.head(n) += h * y.segment(n, n);
        return {h, h, -1.0, 1};
    }
};

class VelocityVerlet final : public ExplicitBase {
public:
    std::string_view name() const override { return "verlet"; }
    int order() const override { return 2; }
    int evaluationsPerStep() const override { return 2; }
    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        // x_{n+1} = x_n + h v_n + h^2/2 a_n;  v_{n+1/2} = v_n + h/2 a_n;
        // v_{n+1} = v_{n+1/2} + h/2 a(x_{n+1}, v_{n+1/2}).
        // a_n is re-evaluated each step (parameters and collisions may have changed it). With
        // velocity-dependent (damping) forces the last stage sees the half-step velocity,
        // which makes the method first order: a known property, tested as such.
        const Eigen::Index n = m_layout.positions, m = m_layout.aux;
        system.derivative(t, y, m_k1);
        y.head(n) += h * y.segment(n, n) + (0.5 * h * h) * m_k1.segment(n, n);
        y.segment(n, n + m) += (0.5 * h) * m_k1.segment(n, n + m);
        system.derivative(t + h, y, m_k2);
        y.segment(n, n + m) += (0.5 * h) * m_k2.segment(n, n + m);
        return {h, h, -1.0, 2};
    }
};

// Composition methods (Yoshida, "Construction of higher order symplectic integrators",
// Phys. Lett. A 150, 1990; Hairer, Lubich & Wanner, "Geometric Numerical Integration", II.4):
// velocity Verlet taken over substeps w_1 h, ..., w_s h with symmetric weights that sum to 1,
// some negative, chosen so that the composition's error terms cancel up to order p. Each is
// symplectic and time-reversible for velocity-independent forces. The kicks between two
// substeps share one force evaluation (the acceleration at the end of a substep starts the
// next), so a step costs s + 1 evaluations; for velocity-independent forces this is exactly s
// Verlet steps. With damping the shared evaluation sees the half-kick velocity (as verlet's
// second one does): consistent, first order, like verlet.
class Composition final : public ExplicitBase {
public:
    Composition(std::string_view name, int order, std::span<const double> weights)
        : m_name(name), m_order(order), m_weights(weights) {}
    std::string_view name() const override { return m_name; }
    int order() const override { return m_order; }
    int evaluationsPerStep() const override { return static_cast<int>(m_weights.size()) + 1; }
    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        const Eigen::Index n = m_layout.positions, m = m_layout.aux;
        Eigen::VectorXd* a = &m_k1;
        Eigen::VectorXd* next = &m_k2;
        system.derivative(t, y, *a);
        double tau = t;
        for (double w : m_weights) {
            const double hw = w * h;
            // v_half = v + hw/2 a;  x += hw v_half;  v = v_half + hw/2 a(x, v_half)
            y.segment(n, n + m) += (0.5 * hw) * a->segment(n, n + m);
            y.head(n) += hw * y.segment(n, n);
            tau += hw;
            system.derivative(tau, y, *next);
            y.segment(n, n + m) += (0.5 * hw) * next->segment(n, n + m);
            std::swap(a, next);
        }
        return {h, h, -1.0, evaluationsPerStep()};
    }

private:
    std::string_view m_name;
    int m_order;
    std::span<const double> m_weights;
};

// Yoshida's 4th-order triple jump: w1 = 1 / (2 - 2^(1/3)), w0 = 1 - 2 w1.
constexpr double kCubeRoot2 = 1.2599210498948731647672106;
constexpr std::array<double, 3> kYoshida4 = {1.0 / (2.0 - kCubeRoot2), -kCubeRoot2 / (2.0 - kCubeRoot2),
                                             1.0 / (2.0 - kCubeRoot2)};
// Yoshida 1990, table 2, solution D (the smallest error of the 8th-order solutions):
// w7 ... w1 w0 w1 ... w7 with w0 = 1 - 2 (w1 + ... + w7).
constexpr std::array<double, 7> kYoshida8Half = {0.102799849391985, -0.196061023297549e1, 0.193813913762276e1,
                                                 -0.158240635368243, -0.144485223686048e1, 0.253693336566229,
                                                 0.914844246229740};
constexpr std::array<double, 15> symmetricWeights(const std::array<double, 7>& w) {
    std::array<double, 15> out{};
    double sum = 0.0;
    for (double x : w) sum += x;
    for (std::size_t i = 0; i < 7; ++i) out[6 - i] = w[i], out[8 + i] = w[i];
    out[7] = 1.0 - 2.0 * sum;
    return out;
}
constexpr std::array<double, 15> kYoshida8 = symmetricWeights(kYoshida8Half);
constexpr std::array<double, 1> kVerlet = {1.0};

// Dormand-Prince 5(4) (Dormand & Prince 1980; Hairer, Norsett & Wanner, "Solving ODEs I",
// table 5.2). The 5th-order solution is propagated (local extrapolation); the difference to
// the embedded 4th-order one is the error estimate. The seventh stage k7 = f(t + h, y1) is
// needed for the estimate; it could be reused as the next k1 (FSAL), but between two steps
// the state may be changed by collisions, the pointer or a parameter edit, so every step
// re-evaluates k1: 7 evaluations per attempt instead of 6, always correct.
//
// Step control on the max-norm of e_i / (atol + rtol max(|y0_i|, |y1_i|)) over x and v:
//   accept when err <= 1;  h_new = h * clamp(0.9 err^(-1/5), 0.2, 5)  (no growth right after
//   a rejection). A non-finite trial state counts as a rejection with the smallest factor.
class DormandPrince final : public Integrator {
public:
    std::string_view name() const override { return "rk45"; }
    int order() const override { return 5; }
    int evaluationsPerStep() const override { return 7; }
    bool adaptive() const override { return !m_options.fixedStep; }
    void prepare(const StateLayout& layout) override {
        m_layout = layout;
        const Eigen::Index n = layout.size();
        for (auto& k : m_k) k.setZero(n);
        m_tmp.setZero(n);
        m_y1.setZero(n);
        m_err.setZero(n);
        m_hasError = false;
    }
    const double* localError() const override { return m_hasError ? m_err.data() : nullptr; }
    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        // clang-format off
        static constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
        static constexpr double a21 = 1.0 / 5;
        static constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
        static constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
        static constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
        static constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176, a65 = -5103.0 / 18656;
        static constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
        // e = b(5th) - b(4th)
        static constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
        // clang-format on
        StepReport report;
        const Eigen::Index n = m_layout.positions;
        const bool control = !m_options.fixedStep;
        bool rejectedBefore = false;
        auto& [k1, k2, k3, k4, k5, k6, k7] = m_k;
        for (;;) {
            if (control && h < m_options.minStep) {
                report.failure = failure_text::kRk45MinimumStep;
                return report;
            }
            system.derivative(t, y, k1);
            m_tmp = y + h * a21 * k1;
            system.derivative(t + c2 * h, m_tmp, k2);
            m_tmp = y + h * (a31 * k1 + a32 * k2);
            system.derivative(t + c3 * h, m_tmp, k3);
            m_tmp = y + h * (a41 * k1 + a42 * k2 + a43 * k3);
            system.derivative(t + c4 * h, m_tmp, k4);
            m_tmp = y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4);
            system.derivative(t + c5 * h, m_tmp, k5);
            m_tmp = y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5);
            system.derivative(t + h, m_tmp, k6);
            m_y1 = y + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
            system.derivative(t + h, m_y1, k7);
            report.evaluations += 7;
            m_err = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);

            double err = 0.0;
            for (Eigen::Index i = 0; i < 2 * n; ++i) {
                const double scale = m_options.atol + m_options.rtol * std::max(std::abs(y[i]), std::abs(m_y1[i]));
                err = std::max(err, std::abs(m_err[i]) / scale);
            }
            if (!std::isfinite(err) || !m_y1.allFinite()) err = std::numeric_limits<double>::infinity();
            if (!control || err <= 1.0) {
                y = m_y1;
                m_hasError = true;
                report.h = h;
                // Position error, RMS over particles: sqrt(sum |e_x,i|^2 / N), N = n / 3.
                report.errorEstimate = std::sqrt(m_err.head(n).squaredNorm() / std::max(1.0, static_cast<double>(n) / 3.0));
                double factor = err > 0.0 ? 0.9 * std::pow(err, -0.2) : 5.0;
                factor = std::clamp(factor, 0.2, rejectedBefore ? 1.0 : 5.0);
                report.hNext = control ? h * factor : h;
                if (control && m_options.maxStep > 0.0) report.hNext = std::min(report.hNext, m_options.maxStep);
                return report;
            }
            rejectedBefore = true;
            ++report.rejected;
            const double factor = std::isfinite(err) ? std::clamp(0.9 * std::pow(err, -0.2), 0.2, 1.0) : 0.2;
            h *= factor;
        }
    }

private:
    StateLayout m_layout;
    std::array<Eigen::VectorXd, 7> m_k;
    Eigen::VectorXd m_tmp, m_y1, m_err;
    bool m_hasError = false;  // m_err holds the last accepted step's estimate
};

// Extended position-based dynamics (Macklin, Mueller & Chentanez, "XPBD: position-based
// simulation of compliant constrained dynamics", MIG 2016) with the "small steps" scheme
// (Macklin, Storey, Lu, Terdiman, Chentanez, Jeschke & Mueller, SCA 2019): the step h is cut
// into s substeps of hs = h / s, each with one Gauss-Seidel pass over the constraints and the
// multipliers starting from 0:
//
//   v += hs a_ext(x, v)            gravity, gas, contact, pointer: every force but the springs
//   x_prev = x;  x += hs v
//   each spring (i, j):  C = |x_i - x_j| - L0,  n = (x_i - x_j) / |x_i - x_j|
//     alpha~ = 1 / (stiffness hs^2)  (compliance 1/stiffness),  gamma = alpha~ (damping hs^2) / hs = damping / (stiffness hs)
//     dlambda = (-C - gamma n.(dx_i - dx_j)) / ((1 + gamma) w + alpha~),  dx = x - x_prev,
//     w = n.(W_i n) + n.(W_j n)   (W: inverse masses per coordinate)
//     x_i += W_i n dlambda;  x_j -= W_j n dlambda
//   v = (x - x_prev) / hs
//
// a_ext is the system's acceleration less the springs' (computed here from the same formula
// as the force kernels): one force evaluation and one spring pass per substep. The gas is an
// external force, as Jolt's soft bodies treat it (SoftBodyMotionProperties::ApplyPressure adds
// P A n hs / m to the velocities once per substep, P = nRT / V from the current volume): the
// pressure is soft beside the springs, the constraint projection has no volume constraint to
// offer for P = nRT / V (a gas has no rest volume), and its force is smooth. The energy
// accounts (aux) take the rates at the start of each substep; what XPBD itself dissipates
// beyond the physical damping shows in the balance (energy_drift). First order.
class Xpbd final : public Integrator {
public:
    std::string_view name() const override { return "xpbd"; }
    int order() const override { return 1; }
    int evaluationsPerStep() const override { return m_substeps; }
    // The springs are compliant constraints solved implicitly: no explicit stability limit
    // for them (the external forces keep theirs, per substep).
    bool implicit() const override { return true; }
    void prepare(const StateLayout& layout) override {
        m_layout = layout;
        m_k.setZero(layout.size());
        m_springs.setZero(layout.positions);
        m_previous.setZero(layout.positions);
        m_sweeps = 0;
    }
    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        StepReport report;
        DistanceConstraints c;
        if (!system.distanceConstraints(c) || !c.inverseMass) {
            report.failure = "xpbd: this system has no distance constraints";
            return report;
        }
        const Eigen::Index n = m_layout.positions, m = m_layout.aux;
        const Eigen::VectorXd& w = *c.inverseMass;
        m_substeps = std::max(1, c.substeps);
        const double hs = h / m_substeps;
        for (int sub = 0; sub < m_substeps; ++sub) {
            system.derivative(t + sub * hs, y, m_k);
            ++report.evaluations;
            springForces(c, y);
            y.segment(n, n) += hs * (m_k.segment(n, n) - w.cwiseProduct(m_springs));
            y.tail(m) += hs * m_k.tail(m);
            m_previous = y.head(n);
            y.head(n) += hs * y.segment(n, n);
            project(c, hs, y, m_sweeps++ % 2 == 1);
            y.segment(n, n) = (y.head(n) - m_previous) / hs;
        }
        report.h = report.hNext = h;
        return report;
    }
    // The sweep direction alternates with the substeps counted since prepare().
    std::vector<double> history() const override { return {double(m_substeps), double(m_sweeps)}; }
    void setHistory(const std::vector<double>& history) override {
        if (history.size() != 2) return;
        m_substeps = int(history[0]);
        m_sweeps = long(history[1]);
    }

private:
    // The springs' forces at (x, v) into m_springs (docs/model.md: F_i = [stiffness (L - L0) + damping (v_j - v_i).u] u,
    // u = (x_j - x_i) / L).
    void springForces(const DistanceConstraints& c, const Eigen::VectorXd& y) {
        const Eigen::Index n = m_layout.positions;
        m_springs.setZero();
        const double* x = y.data();
        const double* v = y.data() + n;
        for (const DistanceFamily& f : c.families) {
            if (f.stiffness == 0.0 && f.damping == 0.0) continue;
            for (std::size_t s = 0; s < f.a.size(); ++s) {
                const int i = f.a[s], j = f.b[s];
                const double dx = x[3 * j] - x[3 * i], dy = x[3 * j + 1] - x[3 * i + 1], dz = x[3 * j + 2] - x[3 * i + 2];
                const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
                if (length < 1e-12) continue;
                const double ux = dx / length, uy = dy / length, uz = dz / length;
                const double closing = (v[3 * j] - v[3 * i]) * ux + (v[3 * j + 1] - v[3 * i + 1]) * uy +
                                       (v[3 * j + 2] - v[3 * i + 2]) * uz;
                const double magnitude = f.stiffness * (length - f.rest[s]) + f.damping * closing;
                m_springs[3 * i] += magnitude * ux, m_springs[3 * i + 1] += magnitude * uy, m_springs[3 * i + 2] += magnitude * uz;
                m_springs[3 * j] -= magnitude * ux, m_springs[3 * j + 1] -= magnitude * uy, m_springs[3 * j + 2] -= magnitude * uz;
            }
        }
    }
    // One Gauss-Seidel pass over every spring: forward (families and springs in index order)
    // on even substeps, backward on odd ones. Measured: with the forward order at every
    // substep, the two-layer ring (five springs per pair of particles) is unstable for
    // stiffness hs^2 / m between about 2 and several hundred (the stiff ring at DT 1/60 with 8 to
    // 32 substeps gained energy until it blew up); alternating the order (symmetric
    // Gauss-Seidel over two substeps) is stable there.
    void project(const DistanceConstraints& c, double hs, Eigen::VectorXd& y, bool backward) const {
        const Eigen::VectorXd& w = *c.inverseMass;
        double* x = y.data();
        const double* x0 = m_previous.data();
        for (std::size_t fi = 0; fi < c.families.size(); ++fi) {
            const DistanceFamily& f = c.families[backward ? c.families.size() - 1 - fi : fi];
            if (!(f.stiffness > 0.0)) continue;  // no stiffness: no constraint (its damping alone is not one)
            const double compliance = 1.0 / (f.stiffness * hs * hs);
            const double gamma = f.damping / (f.stiffness * hs);
            for (std::size_t si = 0; si < f.a.size(); ++si) {
                const std::size_t s = backward ? f.a.size() - 1 - si : si;
                const int i = f.a[s], j = f.b[s];
                double d[3], moved = 0.0, length2 = 0.0;
                for (int k = 0; k < 3; ++k) d[k] = x[3 * i + k] - x[3 * j + k], length2 += d[k] * d[k];
                const double length = std::sqrt(length2);
                if (length < 1e-12) continue;
                double weight = 0.0;
                for (int k = 0; k < 3; ++k) {
                    d[k] /= length;
                    weight += d[k] * d[k] * (w[3 * i + k] + w[3 * j + k]);
                    moved += d[k] * ((x[3 * i + k] - x0[3 * i + k]) - (x[3 * j + k] - x0[3 * j + k]));
                }
                if (weight == 0.0) continue;
                const double dlambda = (-(length - f.rest[s]) - gamma * moved) / ((1.0 + gamma) * weight + compliance);
                for (int k = 0; k < 3; ++k) {
                    x[3 * i + k] += w[3 * i + k] * d[k] * dlambda;
                    x[3 * j + k] -= w[3 * j + k] * d[k] * dlambda;
                }
            }
        }
    }

    StateLayout m_layout;
    int m_substeps = 1;
    long m_sweeps = 0;  // substeps since prepare(): odd ones sweep backward
    Eigen::VectorXd m_k, m_springs, m_previous;
};
}  // namespace

std::unique_ptr<Integrator> makeExplicitIntegrator(std::string_view name) {
    if (name == "euler") return std::make_unique<Euler>();
    if (name == "midpoint") return std::make_unique<Midpoint>();
    if (name == "rk4") return std::make_unique<Rk4>();
    if (name == "symplectic-euler") return std::make_unique<SymplecticEuler>();
    if (name == "verlet") return std::make_unique<VelocityVerlet>();
    if (name == "yoshida4") return std::make_unique<Composition>("yoshida4", 4, kYoshida4);
    if (name == "yoshida8") return std::make_unique<Composition>("yoshida8", 8, kYoshida8);
    if (name == "rk45") return std::make_unique<DormandPrince>();
    return nullptr;
}

std::span<const double> compositionWeights(std::string_view name) {
    if (name == "verlet") return kVerlet;
    if (name == "yoshida4") return kYoshida4;
    if (name == "yoshida8") return kYoshida8;
    return {};
}

std::unique_ptr<Integrator> makeXpbd() { return std::make_unique<Xpbd>(); }

}  // namespace simcore
