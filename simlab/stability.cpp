#include "simlab/stability.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>

#include <Eigen/Eigenvalues>

#include "simcore/compositions.h"
#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/output.h"

namespace simlab {

using simcore::Diagnostics;
using simcore::Failure;
using simcore::SimulationSnapshot;
using simcore::Integrator;
using simcore::IntegratorOptions;
using simcore::OdeSystem;
using simcore::Param;
using simcore::ParameterSet;
using simcore::Simulation;
using simcore::Term;
using simcore::World;
using simcore::WorldBodySpec;
using simcore::WorldSpec;
using simcore::compositionWeights;
using simcore::hasStabilityFunction;
using simcore::kExplicitStabilityLimit;
using simcore::stabilityFunction;

namespace {

// Spectral radius of a real 2x2 matrix.
double radius2(double a, double b, double c, double d) {
    // Eigenvalues tr/2 +- sqrt(D) with D = ((a - d)/2)^2 + b c: the same as tr^2/4 - det but
    // without the cancellation that makes a double root at 1 look like 1 + 1e-9.
    const double half = 0.5 * (a + d), diff = 0.5 * (a - d);
    const double disc = diff * diff + b * c;
    if (disc >= 0.0) return std::abs(half) + std::sqrt(disc);
    return std::sqrt(std::abs(a * d - b * c));  // complex pair: |lambda|^2 = det
}

// One step of a partitioned method on (x, v) for x'' = -w^2 x - c v.
std::pair<double, double> partitionedStep(const std::string& name, double h, double w2, double c, double x, double v) {
    auto acc = [&](double xx, double vv) { return -w2 * xx - c * vv; };
    if (name == "symplectic-euler") {
        const double v1 = v + h * acc(x, v);
        return {x + h * v1, v1};
    }
    // velocity Verlet and its compositions, damping at the half-step velocity (as the
    // integrators do): each substep's end acceleration starts the next
    double a = acc(x, v);
    for (double w : compositionWeights(name)) {
        const double hw = w * h;
        const double vh = v + 0.5 * hw * a;
        x += hw * vh;
        a = acc(x, vh);
        v = vh + 0.5 * hw * a;
    }
    return {x, v};
}

}  // namespace

bool isPartitioned(const std::string& integrator) {
    return integrator == "symplectic-euler" || !compositionWeights(integrator).empty();
}

double modeAmplification(const std::string& integrator, double h, double omega, double c) {
    const double w2 = omega * omega;
    if (isPartitioned(integrator)) {
        const auto [a, cc] = partitionedStep(integrator, h, w2, c, 1.0, 0.0);
        const auto [b, d] = partitionedStep(integrator, h, w2, c, 0.0, 1.0);
        return radius2(a, b, cc, d);
    }
    // lambda^2 + c lambda + w^2 = 0
    const std::complex<double> disc = std::sqrt(std::complex<double>(c * c / 4.0 - w2, 0.0));
    const std::complex<double> l1 = -c / 2.0 + disc, l2 = -c / 2.0 - disc;
    return std::max(std::abs(stabilityFunction(integrator, h * l1)), std::abs(stabilityFunction(integrator, h * l2)));
}

namespace {

// The body's linearisation on its free coordinates, mass-normalised:
// apply(u, false) = A u and apply(u, true) = C u, with A = -M^-1/2 K M^-1/2 and
// C = -M^-1/2 D M^-1/2 (K, D the force's Jacobians in position and velocity).
class MassNormalised {
public:
    explicit MassNormalised(OdeSystem& system) : m_system(system) {
        const Eigen::VectorXd& mass = system.coordinateMass();
        for (Eigen::Index i = 0; i < mass.size(); ++i)
            if (mass[i] > 0.0) m_free.push_back(i);
        m_n = mass.size();
        m_zero = Eigen::VectorXd::Zero(m_n);
        m_out.resize(m_n);
    }
    Eigen::Index size() const { return static_cast<Eigen::Index>(m_free.size()); }
    Eigen::VectorXd apply(const Eigen::VectorXd& u, bool damping) {
        const Eigen::VectorXd& mass = m_system.coordinateMass();
        const Eigen::Index m = size();
        Eigen::VectorXd full = Eigen::VectorXd::Zero(m_n);
        for (Eigen::Index j = 0; j < m; ++j) full[m_free[j]] = u[j] / std::sqrt(mass[m_free[j]]);
        if (damping) m_system.forceJacobianProduct(m_zero, full, m_out);
        else m_system.forceJacobianProduct(full, m_zero, m_out);
        Eigen::VectorXd r(m);
        for (Eigen::Index j = 0; j < m; ++j) r[j] = -m_out[m_free[j]] / std::sqrt(mass[m_free[j]]);
        return r;
    }

private:
    OdeSystem& m_system;
    std::vector<Eigen::Index> m_free;
    Eigen::Index m_n = 0;
    Eigen::VectorXd m_zero, m_out;
};

// Small bodies: A and C column by column, every mode (and, up to exactEigenLimit coordinates,
// the first-order system's exact spectrum).
void denseModes(MassNormalised& op, int exactEigenLimit, LinearModes& modes) {
    const Eigen::Index m = op.size();
    Eigen::MatrixXd A(m, m), C(m, m);
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(m);
    for (Eigen::Index j = 0; j < m; ++j) {
        unit[j] = 1.0;
        A.col(j) = op.apply(unit, false);
        C.col(j) = op.apply(unit, true);
        unit[j] = 0.0;
    }
    A = 0.5 * (A + A.transpose());
    if (m <= kExactStepLimit) {
        modes.stiffness = A;
        modes.damping2 = C;
    }
    if (m <= exactEigenLimit) {
        // y = [M^1/2 x, M^1/2 v]: y' = [[0, I], [-A, -C]] y (A, C as built are -M^-1/2 K M^-1/2
        // and -M^-1/2 D M^-1/2), same eigenvalues as [[0, I], [M^-1 K, M^-1 D]].
        Eigen::MatrixXd J = Eigen::MatrixXd::Zero(2 * m, 2 * m);
        J.topRightCorner(m, m).setIdentity();
        J.bottomLeftCorner(m, m) = -A;
        J.bottomRightCorner(m, m) = -C;
        Eigen::EigenSolver<Eigen::MatrixXd> eig(J, false);
        for (Eigen::Index i = 0; i < 2 * m; ++i) {
            modes.eigenvalues.push_back(eig.eigenvalues()[i]);
            if (std::abs(eig.eigenvalues()[i]) > std::abs(modes.fastest)) modes.fastest = eig.eigenvalues()[i];
        }
    }
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(A);
    const Eigen::MatrixXd& phi = solver.eigenvectors();
    for (Eigen::Index i = 0; i < m; ++i) {
        modes.omega2.push_back(solver.eigenvalues()[i]);
        modes.damping.push_back(phi.col(i).dot(C * phi.col(i)));
    }
}

// Large bodies: the highest mode by power iteration, and the first-order system's extreme
// eigenvalues (damping included, which the stiffest mode alone misses when a heavily damped
// mode is faster) by Arnoldi on J [p; q] = [q; -A p - C q], Gram-Schmidt done twice.
void iterativeModes(MassNormalised& op, LinearModes& modes) {
    const Eigen::Index m = op.size();
    modes.dense = false;
    Eigen::VectorXd x = Eigen::VectorXd::Ones(m).normalized();
    double lambda = 0.0;
    for (int it = 0; it < 300; ++it) {
        Eigen::VectorXd y = op.apply(x, false);
        lambda = x.dot(y);
        if (y.norm() == 0.0) break;
        x = y.normalized();
    }
    modes.omega2.push_back(lambda);
    modes.damping.push_back(x.dot(op.apply(x, true)));
    const Eigen::Index size = 2 * m;
    const int steps = int(std::min<Eigen::Index>(size, 80));
    Eigen::MatrixXd V = Eigen::MatrixXd::Zero(size, steps + 1);
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(steps + 1, steps);
    for (Eigen::Index i = 0; i < size; ++i) V(i, 0) = std::sin(1.0 + 12.9898 * double(i)) + 0.5;  // fixed start
    V.col(0).normalize();
    int k = 0;
    for (; k < steps; ++k) {
        const Eigen::VectorXd p = V.col(k).head(m), q = V.col(k).tail(m);
        Eigen::VectorXd w(size);
        w.head(m) = q;
        w.tail(m) = -op.apply(p, false) - op.apply(q, true);
        for (int pass = 0; pass < 2; ++pass) {
            const Eigen::VectorXd h = V.leftCols(k + 1).transpose() * w;
            w -= V.leftCols(k + 1) * h;
            H.col(k).head(k + 1) += h;
        }
        H(k + 1, k) = w.norm();
        if (H(k + 1, k) <= 1e-12 * H.col(k).head(k + 1).norm()) {
            ++k;  // an invariant subspace: its Ritz values are exact
            break;
        }
        V.col(k + 1) = w / H(k + 1, k);
    }
    Eigen::EigenSolver<Eigen::MatrixXd> ritz(H.topLeftCorner(k, k), false);
    for (Eigen::Index i = 0; i < k; ++i) modes.ritzValues.push_back(ritz.eigenvalues()[i]);
    modes.arnoldiSteps = k;
}

}  // namespace

namespace {

// The modes of a linearised system (its Jacobians at the point `linearize` was given).
LinearModes modesOf(OdeSystem& system, int exactEigenLimit, int denseLimit) {
    MassNormalised op(system);
    LinearModes modes;
    modes.freeCoordinates = static_cast<int>(op.size());
    if (op.size() == 0) return modes;
    if (op.size() <= denseLimit) denseModes(op, exactEigenLimit, modes);
    else iterativeModes(op, modes);
    for (std::size_t i = 0; i < modes.omega2.size(); ++i) {
        if (modes.omega2[i] < -1e-9 * std::abs(modes.omega2.back())) ++modes.unstableModes;
        modes.fastestDamping = std::max(modes.fastestDamping, modes.damping[i]);
    }
    const auto top = std::max_element(modes.omega2.begin(), modes.omega2.end()) - modes.omega2.begin();
    modes.omegaMax = std::sqrt(std::max(0.0, modes.omega2[static_cast<std::size_t>(top)]));
    modes.dampingAtMax = modes.damping[static_cast<std::size_t>(top)];
    return modes;
}

}  // namespace

LinearModes linearModes(const ParameterSet& params, int exactEigenLimit, int denseLimit) {
    // At the rest shape: the perturbation is the trials' way to excite every mode, not part
    // of the body (stabilityModes).
    ParameterSet rest = params;
    rest.set(Param::Perturb, 0.0);
    Simulation sim(rest, "implicit-euler");
    // Contact as a force has no stiffness at the start (U'' = 3 k d^2 is 0 at d = 0): the
    // estimate adds it at the contact's design point (Simulation::contactDesign).
    sim.setContactDesignInJacobians(true);
    OdeSystem& system = sim.odeSystem();
    system.linearize(0.0, sim.state());
    return modesOf(system, exactEigenLimit, denseLimit);
}

LinearModes linearModes(World& world, int exactEigenLimit, int denseLimit) {
    // Every body's forces (block diagonal), each body's wall contact at its design point as
    // for a body alone, and the pairs' forces where two bodies (or two elements of one) are
    // within the contact skin at this state (WorldOde::linearize).
    world.setContactDesignInJacobians(true);
    OdeSystem& system = world.odeSystem();
    system.linearize(world.time(), world.state());
    LinearModes modes = modesOf(system, exactEigenLimit, denseLimit);
    world.setContactDesignInJacobians(false);
    return modes;
}

LinearModes linearModes(const WorldSpec& spec, int exactEigenLimit, int denseLimit) {
    // At the start without the perturbation, as for one body.
    WorldSpec rest = spec;
    for (WorldBodySpec& body : rest.bodies) body.params.set(Param::Perturb, 0.0);
    World world(rest, "implicit-euler");
    return linearModes(world, exactEigenLimit, denseLimit);
}

namespace {

// Spectral radius of one step of a partitioned method on y'' = -A y - C y' (exact matrices).
double partitionedRadius(const std::string& name, double h, const Eigen::MatrixXd& A, const Eigen::MatrixXd& C) {
    const Eigen::Index m = A.rows();
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(m, m);
    Eigen::MatrixXd S(2 * m, 2 * m);  // [x; v] -> [x1; v1]
    if (name == "symplectic-euler") {
        const Eigen::MatrixXd vx = -h * A, vv = I - h * C;  // v1 = vx x + vv v
        S << I + h * vx, h * vv, vx, vv;
    } else {  // velocity Verlet and its compositions, damping at the half-step velocity
        // Rows of x and v as linear maps of the start state [x; v] (m x 2m each).
        Eigen::MatrixXd X(m, 2 * m), V(m, 2 * m);
        X << I, Eigen::MatrixXd::Zero(m, m);
        V << Eigen::MatrixXd::Zero(m, m), I;
        Eigen::MatrixXd a = -A * X - C * V;
        for (double w : compositionWeights(name)) {
            const double hw = w * h;
            const Eigen::MatrixXd vh = V + 0.5 * hw * a;
            X += hw * vh;
            a = -A * X - C * vh;
            V = vh + 0.5 * hw * a;
        }
        S << X, V;
    }
    Eigen::EigenSolver<Eigen::MatrixXd> eig(S, false);
    return eig.eigenvalues().cwiseAbs().maxCoeff();
}

}  // namespace

namespace {

// The largest h <= hMax with stable(h) (0: not even the smallest; inf: stable at hMax): a
// geometric scan from h0 by `grow`, then bisection.
double largestStable(const std::function<bool(double)>& stable, double hMax, double h0, double grow, int bisections) {
    double lo = 0.0, h = h0;
    if (!stable(h)) return 0.0;
    while (h < hMax && stable(h)) lo = h, h *= grow;
    if (h >= hMax && stable(hMax)) return std::numeric_limits<double>::infinity();
    double hi = std::min(h, hMax);
    for (int it = 0; it < bisections; ++it) {
        const double mid = 0.5 * (lo + hi);
        (stable(mid) ? lo : hi) = mid;
    }
    return lo;
}

}  // namespace

const std::vector<std::complex<double>>& spectrumOf(const LinearModes& modes) {
    return modes.eigenvalues.empty() ? modes.ritzValues : modes.eigenvalues;
}

double predictedStableStep(const std::string& integrator, const LinearModes& modes, double hMax) {
    if (integrator == "implicit-euler") return std::numeric_limits<double>::infinity();
    const bool partitioned = isPartitioned(integrator);
    // (With physically unstable modes the exact step matrix grows for every h; the spectrum
    // and modal paths leave them out.)
    if (partitioned && modes.stiffness.rows() > 0 && modes.unstableModes == 0) {
        // Rigid modes are Jordan blocks at 1, whose computed eigenvalues scatter by ~sqrt(eps):
        // hence the looser 1e-6.
        return largestStable(
            [&](double h) { return partitionedRadius(integrator, h, modes.stiffness, modes.damping2) <= 1.0 + 1e-6; },
            hMax, 1e-5, 1.1, 30);
    }
    const std::vector<std::complex<double>>& spectrum = spectrumOf(modes);
    if ((hasStabilityFunction(integrator) || partitioned) && !spectrum.empty()) {
        // The first-order spectrum, exact (dense eigen-solve) or its extreme part (Arnoldi's
        // Ritz values, which converge first and are the ones that limit an explicit step):
        // |R(h lambda)| <= 1 for every eigenvalue. The partitioned methods have no R: each
        // eigenvalue is taken as one of the pair of a mode that decouples (w = |lambda|,
        // c = -2 Re lambda), the oscillator's region of the stability map. Growing physical
        // modes (Re lambda > 0) are excluded, as in the modal path.
        double scale = 0.0;
        for (const auto& l : spectrum) scale = std::max(scale, std::abs(l));
        std::vector<std::complex<double>> lambdas;
        // Rigid-body modes (|lambda| ~ 0, with round-off of either sign) cannot limit a step.
        for (const auto& l : spectrum)
            if (std::abs(l) > 1e-6 * scale && l.real() <= 1e-9 * scale) lambdas.push_back(l);
        if (integrator == "euler" || integrator == "midpoint")
            for (const auto& l : lambdas)
                if (std::abs(l.real()) <= 1e-9 * scale && std::abs(l.imag()) > 1e-6 * scale) return 0.0;
        auto growth = [&](double h, std::complex<double> l) {
            return partitioned ? modeAmplification(integrator, h, std::abs(l), -2.0 * l.real())
                               : std::abs(stabilityFunction(integrator, h * l));
        };
        return largestStable(
            [&](double h) {
                for (const auto& l : lambdas)
                    if (growth(h, l) > 1.0 + 1e-9) return false;
                return true;
            },
            hMax, 1e-7, 1.05, 60);
    }
    // Euler's and Heun's regions touch the imaginary axis only at 0: an undamped oscillating
    // mode grows for every h (too slowly near 0 to see in double precision, hence explicit).
    if (integrator == "euler" || integrator == "midpoint")
        for (std::size_t i = 0; i < modes.omega2.size(); ++i)
            if (modes.omega2[i] > 1e-9 * modes.omegaMax * modes.omegaMax && modes.damping[i] <= 1e-12 * modes.omegaMax)
                return 0.0;
    return largestStable(
        [&](double h) {
            for (std::size_t i = 0; i < modes.omega2.size(); ++i) {
                if (modes.omega2[i] < 0.0) continue;
                if (modeAmplification(integrator, h, std::sqrt(modes.omega2[i]), modes.damping[i]) > 1.0 + 1e-9)
                    return false;
            }
            return true;
        },
        hMax, 1e-7, 1.05, 60);
}

LinearModes stabilityModes(const ParameterSet& params) {
    return linearModes(params, kVerdictExactLimit, kVerdictExactLimit);
}

LinearModes stabilityModes(const WorldSpec& world) { return linearModes(world, kVerdictExactLimit, kVerdictExactLimit); }

LinearModes stabilityModes(const StabilitySpec& spec) {
    return spec.world ? stabilityModes(*spec.world) : stabilityModes(spec.params);
}

StabilityVerdict stabilityVerdict(const LinearModes& modes, const std::string& integrator, double dt, bool adaptive) {
    StabilityVerdict v;
    v.integrator = integrator;
    v.dt = dt;
    v.omegaMax = modes.omegaMax;
    const auto& spectrum = spectrumOf(modes);
    for (const auto& l : spectrum)
        if (std::abs(l) > std::abs(v.fastest)) v.fastest = l;
    const bool partitioned = isPartitioned(integrator);
    if (!modes.eigenvalues.empty()) {
        v.basisKind = StabilityVerdict::Basis::ExactSpectrum;
        v.basisValues = modes.eigenvalues.size();
        v.basis = "exact spectrum, " + std::to_string(v.basisValues) + " eigenvalues";
    } else if (!modes.ritzValues.empty()) {
        v.basisKind = StabilityVerdict::Basis::Arnoldi;
        v.basisValues = modes.ritzValues.size();
        v.basisOf = 2 * static_cast<std::size_t>(modes.freeCoordinates);
        v.basis = "Arnoldi, " + std::to_string(v.basisValues) + " Ritz values of " + std::to_string(v.basisOf);
    } else {
        v.basisKind = StabilityVerdict::Basis::Modes;
        v.basis = "modes of M^-1 K";
    }
    if (partitioned && modes.stiffness.rows() > 0 && modes.unstableModes == 0) {
        v.basisKind = StabilityVerdict::Basis::StepMatrix;
        v.basis = "exact step matrix";
    }
    if (adaptive || !(hasStabilityFunction(integrator) || partitioned)) {
        v.ownStep = true;
        v.limit = std::numeric_limits<double>::infinity();
        return v;
    }
    v.limit = predictedStableStep(integrator, modes, std::max(10.0, 1e4 * dt));
    return v;
}

std::string limitText(double limit) {
    if (std::isinf(limit)) return "unlimited";
    if (!(limit > 0.0)) return "none";
    char text[40];
    std::snprintf(text, sizeof text, "%.3g", limit);
    return text;
}

std::string verdictText(const StabilityVerdict& v) {
    if (v.ownStep) return v.integrator + " chooses its own step: no DT limit from stability";
    if (std::isinf(v.limit)) return v.integrator + " is stable at every DT on this body";
    if (!(v.limit > 0.0))
        return v.integrator + " has no stable DT on this body: its undamped modes grow for every DT (" + v.basis + ")";
    return v.integrator + " is stable up to DT = " + limitText(v.limit) + " s on this body (" + v.basis + ")";
}

namespace {

// Bounded energy: gains (never losses) in the energy balance. A run is unbounded when it
// gains more than the budget and is still growing: its largest gain in the second half of
// the run is more than twice that of the first half. A bounded but inaccurate method
// (symplectic Euler's energy oscillates by ~h w / 2 of the energy) is not unstable. `System`
// is a Simulation or a World (the same checks: NaN, runaway, collapsed layer, crossing).
template <class System, class Reason>
std::optional<std::string> boundedTrial(System& sim, const StabilitySpec& spec, double dt, double budget,
                                        const Reason& reason, const std::atomic<bool>* cancel) {
    double firstHalf = 0.0, secondHalf = 0.0;
    while (sim.time() < spec.duration - 1e-9 * dt) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return std::nullopt;
        if (!sim.step()) return reason(sim);
        const double gain = std::max(0.0, sim.diagnostics().energyDrift());
        (sim.time() <= 0.5 * spec.duration ? firstHalf : secondHalf) = std::max(
            sim.time() <= 0.5 * spec.duration ? firstHalf : secondHalf, gain);
    }
    if (secondHalf > budget && secondHalf > 2.0 * firstHalf) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "energy grows without bound: the balance gained %.3g J by T (%.3g J by T/2; budget %.3g J)",
                      secondHalf, firstHalf, budget);
        return std::string(text);
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::string> stabilityTrial(const StabilitySpec& spec, const std::string& integrator, double dt,
                                          const std::atomic<bool>* cancel) {
    IntegratorOptions options;
    options.fixedStep = true;  // rk45 at a fixed step: an adaptive step is always "stable"
    if (spec.world) {
        // The whole world, every body perturbed as a body alone is (its own seed and amplitude
        // when given), the pairs' contact and the exact intersection test included.
        WorldSpec world = *spec.world;
        for (WorldBodySpec& body : world.bodies) {
            if (!body.params.isExplicit(Param::Perturb)) body.params.set(Param::Perturb, spec.perturb);
            if (auto error = body.params.set(Param::Dt, dt)) return *error;
        }
        World sim(world, integrator);
        sim.setIntegratorOptions(options);
        return boundedTrial(sim, spec, dt, 0.5 * convertibleEnergy(sim), [](const World& w) { return *w.failure(); },
                            cancel);
    }
    ParameterSet p = spec.params;
    if (!p.isExplicit(Param::Perturb)) p.set(Param::Perturb, spec.perturb);
    if (auto error = p.set(Param::Dt, dt)) return *error;
    Simulation sim(p, integrator);
    sim.setThreads(1);
    sim.setIntegratorOptions(options);
    return boundedTrial(sim, spec, dt, 0.5 * convertibleEnergy(sim),
                        [](const Simulation& s) { return s.failure()->reason; }, cancel);
}

StabilityRow scanIntegrator(const StabilitySpec& spec, const std::string& integrator, const LinearModes& modes,
                            const std::atomic<bool>* cancel) {
    StabilityRow row;
    row.integrator = integrator;
    row.predicted = predictedStableStep(integrator, modes);
    auto trial = [&](double h) {
        ++row.runs;
        return stabilityTrial(spec, integrator, h, cancel);
    };
    double h0 = std::isfinite(row.predicted) && row.predicted > 0.0 ? row.predicted : 0.01;
    h0 = std::clamp(h0, spec.hMin, spec.hMax);
    double lo = 0.0, hi = std::numeric_limits<double>::infinity();
    std::string reason;
    if (auto r = trial(h0)) {
        hi = h0, reason = *r;
        for (double h = h0 / 2.0;; h /= 2.0) {
            if (h < spec.hMin) break;
            if (cancel && cancel->load()) break;
            if (auto rr = trial(h)) hi = h, reason = *rr;
            else {
                lo = h;
                break;
            }
        }
    } else {
        lo = h0;
        for (double h = std::min(h0 * 2.0, spec.hMax);; h = std::min(h * 2.0, spec.hMax)) {
            if (cancel && cancel->load()) break;
            if (auto rr = trial(h)) {
                hi = h, reason = *rr;
                break;
            }
            lo = h;
            if (h >= spec.hMax) break;
        }
    }
    while (lo > 0.0 && std::isfinite(hi) && hi / lo > 1.0 + spec.relativePrecision) {
        if (cancel && cancel->load()) break;
        const double mid = std::sqrt(lo * hi);
        if (auto r = trial(mid)) hi = mid, reason = *r;
        else lo = mid;
    }
    row.stable = lo;
    row.unstable = hi;
    row.reasonAbove = reason;
    return row;
}

std::vector<std::string> shardNames(const std::vector<std::string>& names, int shardIndex, int shardCount) {
    const auto m = static_cast<long>(names.size());
    return {names.begin() + m * shardIndex / shardCount, names.begin() + m * (shardIndex + 1) / shardCount};
}

std::vector<StabilityRow> runStability(const StabilitySpec& spec, const LinearModes& modes,
                                       const StabilityProgressFn& progress, const std::atomic<bool>* cancel) {
    std::vector<StabilityRow> rows;
    const auto names = shardNames(spec.integrators, spec.shardIndex, spec.shardCount);
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (cancel && cancel->load()) break;
        if (progress) progress({static_cast<int>(i), static_cast<int>(names.size()), names[i]});
        StabilityRow row = scanIntegrator(spec, names[i], modes, cancel);
        if (cancel && cancel->load()) break;  // a scan cut short has no limits to report
        rows.push_back(std::move(row));
    }
    if (progress) progress({static_cast<int>(names.size()), static_cast<int>(names.size()), "done"});
    return rows;
}

double convertibleEnergy(const Simulation& sim) {
    const Diagnostics& d = sim.diagnostics();
    double energy = 1.0 + d.kinetic + d.springTotal();
    energy += sim.body().mass.sum() * sim.forces().params.gravity * 2.0 * sim.boxHalfSize();
    if (sim.forces().terms().has(Term::Gas))
        energy += (sim.forces().params.gasConstant[0] + sim.forces().params.gasConstant[1]) * std::log(100.0);
    return energy;
}

double convertibleEnergy(const World& world) {
    const simcore::WorldDiagnostics& d = world.diagnostics();
    double energy = 1.0 + d.kinetic + d.springTotal();
    for (int k = 0; k < world.bodyCount(); ++k) {
        const simcore::Params p = simcore::resolve(world.spec().bodies[static_cast<std::size_t>(k)].params);
        energy += d.bodies[static_cast<std::size_t>(k)].mass * p.world.gravity * 2.0 * world.boxHalfSize();
        energy += (p.forces.gasConstant[0] + p.forces.gasConstant[1]) * std::log(100.0);
    }
    return energy;
}

double roundDownTwoDigits(double x) {
    if (!(x > 0.0) || !std::isfinite(x)) return x;
    const double scale = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
    return std::floor(x / scale * (1.0 + 1e-12)) * scale;
}

std::optional<std::string> preRunStabilityWarning(const Simulation& sim) {
    auto advice = stabilityAdvice(sim);
    if (!advice) return std::nullopt;
    return std::move(advice->message);
}

namespace {
std::optional<StabilityAdvice> adviceFor(const LinearModes& modes, const std::string& name, double dt);
}  // namespace

std::optional<StabilityAdvice> stabilityAdvice(const Simulation& sim) {
    const Integrator& method = sim.integrator();
    if (method.implicit() || method.adaptive()) return std::nullopt;
    // The one verdict (stabilityModes: exact spectrum for small bodies, Arnoldi above), the
    // same figure the stability map, the failure banner and `stability` give.
    return adviceFor(stabilityModes(sim.parameters()), std::string(method.name()), sim.dt());
}

std::optional<StabilityAdvice> stabilityAdvice(const LinearModes& modes, const std::string& name, double dt) {
    const auto method = simcore::makeIntegrator(name);
    if (!method || method->implicit() || method->adaptive()) return std::nullopt;
    return adviceFor(modes, name, dt);
}

namespace {

std::optional<StabilityAdvice> adviceFor(const LinearModes& modes, const std::string& name, double dt) {
    char text[500];
    const StabilityVerdict verdict = stabilityVerdict(modes, name, dt);
    if (verdict.stable()) return std::nullopt;
    if (verdict.limit <= 0.0) {
        // Euler and Heun grow on undamped modes for every dt; say so only when it matters
        // (the growth rate ~ h w^2 / 2 per second is above 1/s).
        if (dt * modes.omegaMax * modes.omegaMax / 2.0 < 1.0) return std::nullopt;
        const double suggested = roundDownTwoDigits(0.9 * 2.0 / (modes.omegaMax * modes.omegaMax));
        const double growth = dt * modes.omegaMax * modes.omegaMax / 2.0;
        std::snprintf(text, sizeof text,
                      "%s has no stable step on this body's undamped modes (highest w = %.3g rad/s): its "
                      "energy grows for every dt, here by ~%.2g per second; use dt <= %.2g s (growth below 1 "
                      "per second) or another method",
                      name.c_str(), modes.omegaMax, growth, suggested);
        return StabilityAdvice{text, suggested, verdict, true, modes.omegaMax, growth};
    }
    std::snprintf(text, sizeof text,
                  "dt = %g s is above %s's largest stable step on this body, %s s (linearised: %s; fastest "
                  "|lambda| = %.3g 1/s); it will likely blow up (implicit-euler or rk45 will not)",
                  dt, name.c_str(), limitText(verdict.limit).c_str(), verdict.basis.c_str(),
                  std::abs(verdict.fastest));
    return StabilityAdvice{text, roundDownTwoDigits(0.9 * verdict.limit), verdict};
}

}  // namespace

FailureCheck checkFailure(const SimulationSnapshot& start, const Failure& failure, const std::atomic<bool>* cancel) {
    FailureCheck check;
    check.integrator = start.integrator;
    check.failedDt = start.params.get(Param::Dt);
    Simulation sim(start.params, start.integrator);
    sim.setThreads(1);
    sim.restore(start);
    check.verdict = stabilityVerdict(stabilityModes(start.params), start.integrator, check.failedDt,
                                     sim.integrator().adaptive());
    check.rerunDt = check.failedDt / 4.0;
    if (check.verdict.limit > 0.0 && std::isfinite(check.verdict.limit))
        check.rerunDt = std::min(check.rerunDt, 0.9 * check.verdict.limit);
    check.from = start.diag.time;
    check.until = failure.time + std::max(kFailureCheckMargin, 10.0 * check.failedDt);
    if ((check.until - check.from) / check.rerunDt > double(kFailureCheckMaxSteps)) return check;
    if (sim.setParameter(Param::Dt, check.rerunDt)) return check;
    while (sim.time() < check.until - 1e-9 * check.rerunDt) {
        if (cancel && cancel->load(std::memory_order_relaxed)) return check;
        if (!sim.step()) {
            check.rerunFailure = sim.failure();
            break;
        }
    }
    check.checked = true;
    check.physical = check.rerunFailure.has_value();
    if (!check.physical) check.workingDt = roundDownTwoDigits(check.rerunDt);
    return check;
}

std::string failureCheckText(const FailureCheck& c) {
    char text[900];
    if (!c.checked) return "";
    if (c.physical) {
        std::snprintf(text, sizeof text,
                      "The body itself collapses — no step size will save it: run again from t = %.3f s at a "
                      "step of %.3g s (%s), it fails at t = %.3f s as well (%s). Change the body instead: lighter "
                      "masses or less gravity, stiffer springs (ks, and the radial ones), more gas pressure, or "
                      "more damping.",
                      c.from, c.rerunDt, c.integrator.c_str(), c.rerunFailure->time, c.rerunFailure->reason.c_str());
        return text;
    }
    const std::string verdict = verdictText(c.verdict);
    std::snprintf(text, sizeof text,
                  "The step was too large: run again from t = %.3f s at a step of %.3g s, the same stretch runs "
                  "through t = %.3f s. The linearised body agrees: %s.",
                  c.from, c.rerunDt, c.until, verdict.c_str());
    return text;
}

std::string stabilityCsvHeader() {
    return "integrator,dt_stable,dt_unstable,dt_predicted,h_omega_stable,h_omega_predicted,reason\n";
}

std::string stabilityCsvRow(const StabilityRow& row, const LinearModes& modes) {
    auto num = [](double v) { return std::isinf(v) ? std::string("inf") : formatDouble(v); };
    std::string reason = row.reasonAbove;
    std::replace(reason.begin(), reason.end(), ',', ';');
    return row.integrator + ',' + num(row.stable) + ',' + num(row.unstable) + ',' + num(row.predicted) + ',' +
           num(row.stable * modes.omegaMax) + ',' + num(row.predicted * modes.omegaMax) + ',' + reason + '\n';
}

}  // namespace simlab
