#include "integrators.h"

#include <array>

namespace simcore {

namespace {

// clang-format off
constexpr std::array kIntegrators = {
    IntegratorInfo{"euler", 1, "explicit Euler: x and v both from the old state (thesis eq. 22)"},
    IntegratorInfo{"midpoint", 2, "the thesis's midpoint (eq. 31-33), i.e. Heun's RK2: two force evaluations"},
    IntegratorInfo{"rk4", 4, "classical Runge-Kutta 4 (eq. 35-40): four force evaluations"},
    IntegratorInfo{"symplectic-euler", 1, "semi-implicit Euler: v from the old forces, then x from the new v"},
    IntegratorInfo{"verlet", 2, "velocity Verlet (order 1 when damping is on: damping is taken at the half-step velocity)"},
};
// clang-format on

// Base with the stage vectors every explicit method shares.
class ExplicitBase : public Integrator {
public:
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
        system.derivative(t, y, m_k1);
        y += h * m_k1;
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
        system.derivative(t, y, m_k1);
        m_tmp = y + h * m_k1;
        system.derivative(t + h, m_tmp, m_k2);
        y += (0.5 * h) * (m_k1 + m_k2);
        return {h, h, -1.0, 2};
    }
};

class Rk4 final : public ExplicitBase {
public:
    std::string_view name() const override { return "rk4"; }
    int order() const override { return 4; }
    int evaluationsPerStep() const override { return 4; }
    StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) override {
        system.derivative(t, y, m_k1);
        m_tmp = y + (0.5 * h) * m_k1;
        system.derivative(t + 0.5 * h, m_tmp, m_k2);
        m_tmp = y + (0.5 * h) * m_k2;
        system.derivative(t + 0.5 * h, m_tmp, m_k3);
        m_tmp = y + h * m_k3;
        system.derivative(t + h, m_tmp, m_k4);
        y += (h / 6.0) * (m_k1 + 2.0 * m_k2 + 2.0 * m_k3 + m_k4);
        return {h, h, -1.0, 4};
    }
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

}  // namespace

std::span<const IntegratorInfo> integratorTable() { return kIntegrators; }

std::unique_ptr<Integrator> makeIntegrator(std::string_view name) {
    if (name == "euler") return std::make_unique<Euler>();
    if (name == "midpoint") return std::make_unique<Midpoint>();
    if (name == "rk4") return std::make_unique<Rk4>();
    if (name == "symplectic-euler") return std::make_unique<SymplecticEuler>();
    if (name == "verlet") return std::make_unique<VelocityVerlet>();
    return nullptr;
}

std::string integratorNames() {
    std::string names;
    for (const auto& info : integratorTable()) {
        if (!names.empty()) names += ", ";
        names += info.name;
    }
    return names;
}

}  // namespace simcore
