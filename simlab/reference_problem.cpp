#include "simlab/reference_problem.h"

#include <array>
#include <chrono>
#include <cmath>
#include <span>

#include "simcore/compositions.h"

namespace simlab {

using simcore::Param;
using simcore::ParameterSet;
using simcore::SceneKind;
using simcore::compositionWeights;

namespace {

constexpr std::array kMethods = {"euler", "midpoint", "rk4", "symplectic-euler", "verlet", "yoshida4", "yoshida8"};

template <typename Scalar>
struct Spring1d {
    using State = std::array<Scalar, 5>;  // y0, y1, v0, v1, removed
    Scalar k, c, m, g, rest;
    bool fixed;

    State derivative(const State& y) const {
        const Scalar s = y[0] - y[1];
        const Scalar closing = y[2] - y[3];
        const Scalar force = k * (s - rest) + c * closing;  // pulls particle 1 up when stretched
        State d{};
        d[0] = y[2];
        d[1] = y[3];
        d[2] = fixed ? Scalar(0) : -force / m - g;
        d[3] = force / m - g;
        d[4] = c * closing * closing;
        return d;
    }
    double kinetic(const State& y) const {
        const double v0 = y[2], v1 = y[3], M = m;
        return 0.5 * M * ((fixed ? 0.0 : v0 * v0) + v1 * v1);
    }
    double energy(const State& y) const {  // in double, from the Scalar state
        const double s = double(y[0]) - double(y[1]), v0 = y[2], v1 = y[3];
        const double M = m, G = g, K = k, L = rest;
        return 0.5 * M * ((fixed ? 0.0 : v0 * v0) + v1 * v1) + 0.5 * K * (s - L) * (s - L) +
               M * G * ((fixed ? 0.0 : double(y[0])) + double(y[1])) + double(y[4]);
    }
};

// y += dy element by element, compensated (Kahan) when carry is non-null.
template <typename Scalar>
void add(std::array<Scalar, 5>& y, const std::array<Scalar, 5>& dy, std::array<Scalar, 5>* carry) {
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (!carry) {
            y[i] += dy[i];
            continue;
        }
        // volatile-free Kahan: the build does not reassociate (-ffp-contract=off, no fast-math)
        const Scalar corrected = dy[i] - (*carry)[i];
        const Scalar sum = y[i] + corrected;
        (*carry)[i] = (sum - y[i]) - corrected;
        y[i] = sum;
    }
}

template <typename Scalar>
std::array<Scalar, 5> axpy(const std::array<Scalar, 5>& y, Scalar a, const std::array<Scalar, 5>& x) {
    std::array<Scalar, 5> out;
    for (std::size_t i = 0; i < y.size(); ++i) out[i] = y[i] + a * x[i];
    return out;
}

// One step; returns the force evaluations spent.
template <typename Scalar>
int step(const Spring1d<Scalar>& sys, const std::string& method, Scalar h, std::array<Scalar, 5>& y,
         std::array<Scalar, 5>* carry) {
    using State = std::array<Scalar, 5>;
    if (method == "euler") {
        const State k1 = sys.derivative(y);
        State dy;
        for (std::size_t i = 0; i < 5; ++i) dy[i] = h * k1[i];
        add(y, dy, carry);
        return 1;
    }
    if (method == "midpoint") {
        const State k1 = sys.derivative(y);
        const State k2 = sys.derivative(axpy(y, h, k1));
        State dy;
        for (std::size_t i = 0; i < 5; ++i) dy[i] = (Scalar(0.5) * h) * (k1[i] + k2[i]);
        add(y, dy, carry);
        return 2;
    }
    if (method == "rk4") {
        const Scalar half = Scalar(0.5) * h;
        const State k1 = sys.derivative(y);
        const State k2 = sys.derivative(axpy(y, half, k1));
        const State k3 = sys.derivative(axpy(y, half, k2));
        const State k4 = sys.derivative(axpy(y, h, k3));
        State dy;
        for (std::size_t i = 0; i < 5; ++i)
            dy[i] = (h / Scalar(6)) * (k1[i] + Scalar(2) * k2[i] + Scalar(2) * k3[i] + k4[i]);
        add(y, dy, carry);
        return 4;
    }
    if (method == "symplectic-euler") {
        const State k1 = sys.derivative(y);
        State dv{};
        for (std::size_t i = 2; i < 5; ++i) dv[i] = h * k1[i];
        add(y, dv, carry);
        State dx{};
        for (std::size_t i = 0; i < 2; ++i) dx[i] = h * y[i + 2];
        add(y, dx, carry);
        return 1;
    }
    // verlet and its compositions, as simcore's Composition: kick, drift, kick, the end
    // acceleration starting the next substep
    State a = sys.derivative(y);
    int evaluations = 1;
    for (double w : compositionWeights(method)) {
        const Scalar hw = Scalar(w) * h;
        State kick{};
        for (std::size_t i = 2; i < 5; ++i) kick[i] = (Scalar(0.5) * hw) * a[i];
        add(y, kick, carry);
        State drift{};
        for (std::size_t i = 0; i < 2; ++i) drift[i] = hw * y[i + 2];
        add(y, drift, carry);
        a = sys.derivative(y);
        ++evaluations;
        for (std::size_t i = 2; i < 5; ++i) kick[i] = (Scalar(0.5) * hw) * a[i];
        add(y, kick, carry);
    }
    return evaluations;
}

template <typename Scalar>
ReferenceProblemRun run(const ParameterSet& p, const std::string& method, double dt, const std::vector<double>& grid,
                        bool compensated, const std::atomic<bool>* cancel, double wallBudget, bool everyStep) {
    Spring1d<Scalar> sys{Scalar(p.get(Param::Ks)),   Scalar(p.get(Param::Kd)),     Scalar(p.get(Param::Mass)),
                         Scalar(p.get(Param::Gravity)), Scalar(p.get(Param::Length)), p.getInt(Param::FixedEnd) != 0};
    std::array<Scalar, 5> y{Scalar(0), Scalar(-p.get(Param::InitialLength)), Scalar(0), Scalar(0), Scalar(0)};
    std::array<Scalar, 5> carry{};
    const double e0 = sys.energy(y);
    const Scalar h = Scalar(dt);
    ReferenceProblemRun out;
    using Clock = std::chrono::steady_clock;
    for (double target : grid) {
        const long targetSteps = std::lround(target / dt);
        const auto start = Clock::now();
        for (; out.steps < targetSteps; ++out.steps) {
            out.evaluations += static_cast<std::uint64_t>(step(sys, method, h, y, compensated ? &carry : nullptr));
            if (everyStep) {
                out.maxDrift = std::max(out.maxDrift, std::abs(sys.energy(y) - e0));
                out.maxKinetic = std::max(out.maxKinetic, sys.kinetic(y));
            }
            if ((out.steps & 1023) == 1023) {
                if (cancel && cancel->load(std::memory_order_relaxed)) out.cancelled = true;
                if (wallBudget > 0.0 &&
                    out.wallSeconds + std::chrono::duration<double>(Clock::now() - start).count() > wallBudget)
                    out.overBudget = true;
                if (out.cancelled || out.overBudget) {
                    ++out.steps;
                    break;
                }
            }
        }
        out.wallSeconds += std::chrono::duration<double>(Clock::now() - start).count();
        if (out.cancelled || out.overBudget) break;
        bool finite = true;
        for (Scalar v : y) finite = finite && std::isfinite(v);
        if (!finite) {
            out.failed = true;
            out.failedAt = target;
            break;
        }
        Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, 2);
        x(1, 0) = double(y[0]);
        x(1, 1) = double(y[1]);
        out.positions.push_back(x);
        out.maxDrift = std::max(out.maxDrift, std::abs(sys.energy(y) - e0));
        out.maxKinetic = std::max(out.maxKinetic, sys.kinetic(y));
        out.envelope.push_back(out.maxDrift);
    }
    return out;
}

}  // namespace

bool referenceProblemSupports(const std::string& integrator) {
    for (const char* m : kMethods)
        if (integrator == m) return true;
    return false;
}

std::string referenceProblemRefusal(const ParameterSet& params) {
    if (params.kind() != SceneKind::Spring1d)
        return "precision float is built for the reference problem only (spring1d, the scene with a closed form)";
    if (params.get(Param::Perturb) != 0.0) return "precision float: spring1d without perturbation (perturb = 0)";
    return {};
}

ReferenceProblemRun runReferenceProblem(const ParameterSet& params, const std::string& integrator, double dt,
                                        const std::vector<double>& grid, const std::string& precision,
                                        bool compensated, const std::atomic<bool>* cancel, double wallBudget, bool everyStep) {
    if (precision == "float") return run<float>(params, integrator, dt, grid, compensated, cancel, wallBudget, everyStep);
    return run<double>(params, integrator, dt, grid, compensated, cancel, wallBudget, everyStep);
}

}  // namespace simlab
