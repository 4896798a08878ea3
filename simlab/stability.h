#pragma once
// Stability: the largest stable step, measured and predicted, side by side.
//
// Measured: bisection on dt per integrator. A run is stable when it does not fail (NaN,
// runaway speed or energy, collapsed layer: simcore::Simulation's checks) and its energy stays bounded
// over T, from a seeded small perturbation of the rest state: the energy balance is unbounded
// when its gain exceeds half the energy the body can plausibly convert (gravity over the box
// height + the start's kinetic and elastic energy + 1 J) and its largest gain in the second
// half of the run is more than twice that of the first half (still growing). Energy lost
// (numerical damping) is never counted as instability.
//
// Predicted: the system linearised at the start state, M x'' = K x + D x', split into modes of
// M^-1 K (mass-normalised, symmetric eigenproblem): mode i has frequency w_i and damping
// c_i = phi_i^T D phi_i (the diagonal of D in the modal basis: exact for proportional
// damping, an approximation otherwise). Each mode is the scalar oscillator
// x'' + c x' + w^2 x = 0; a method is stable at h when the spectral radius of its one-step
// map on every mode is <= 1. Symplectic Euler and velocity Verlet use their 2x2 step matrix
// per mode. Euler/midpoint/rk4/rk45/implicit-euler use their stability function R(h lambda)
// on the exact eigenvalues lambda of the first-order system when the body has at most
// kExactEigenLimit free coordinates (no damping approximation), on the modes otherwise;
// symplectic Euler and Verlet use the spectral radius of their exact 2m x 2m step matrix up
// to kExactStepLimit free coordinates (the modal damping is ambiguous for degenerate modes).
//   undamped limits (h w):  euler none (grows for every h), midpoint none, rk4 2*sqrt(2),
//   rk45 (fixed step) ~3.3, symplectic-euler 2, verlet 2, yoshida4 1.57, yoshida8 (see
//   docs/numerics.md), implicit-euler unlimited. The compositions of Verlet (yoshida4,
//   yoshida8) are treated as Verlet is: their step matrix is the product of Verlet's over
//   the substeps (integrators.h, compositionWeights).

#include <atomic>

#include <Eigen/Core>
#include <complex>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "simcore/params.h"
#include "simcore/simulation.h"
#include "simcore/world.h"

namespace simcore {
class Simulation;
}  // namespace simcore

namespace simlab {

struct LinearModes {
    int freeCoordinates = 0;
    bool dense = true;             // all modes (dense eigen-solver) or only the highest (power iteration)
    std::vector<double> omega2;    // w_i^2 [1/s^2], ascending; negative = unstable physical mode
    std::vector<double> damping;   // c_i [1/s]
    // Exact eigenvalues of the first-order linearised system y' = [[0, I], [A, C]] y
    // (A = M^-1 K, C = M^-1 D), when the body is small enough (kExactEigenLimit free
    // coordinates). Methods with a stability function R use these (no modal approximation).
    std::vector<std::complex<double>> eigenvalues;
    std::complex<double> fastest{0.0, 0.0};  // the eigenvalue of largest modulus [1/s]
    // Large bodies (dense = false): Ritz values of the first-order system by Arnoldi
    // (arnoldiSteps steps on the Jacobian products, fully re-orthogonalised); its extreme
    // eigenvalues (largest modulus) converge first. Empty for dense bodies.
    std::vector<std::complex<double>> ritzValues;
    int arnoldiSteps = 0;
    // Mass-normalised stiffness and damping, a = -A x - C v (kept up to kExactStepLimit free
    // coordinates): the partitioned methods' exact step matrices are built from them.
    Eigen::MatrixXd stiffness, damping2;
    double omegaMax = 0.0;         // highest frequency [rad/s]
    double dampingAtMax = 0.0;     // c of that mode [1/s]
    double fastestDamping = 0.0;   // largest c_i [1/s]
    int unstableModes = 0;         // w^2 < 0 (e.g. buckling under pressure): excluded from limits
};

// Linearised at the start state of the scene without its perturbation (stabilityModes).
inline constexpr int kExactEigenLimit = 400;
inline constexpr int kExactStepLimit = 120;
inline constexpr int kDenseModeLimit = 1200;
// exactEigenLimit: up to this many free coordinates the first-order eigenvalues are computed
// (a dense non-symmetric eigen-solve of twice that size: ~1 s at 400). denseLimit: up to this
// many, all modes (dense symmetric eigen-solve); above it the highest mode alone, by power
// iteration on the Jacobian products (dense = false).
LinearModes linearModes(const simcore::ParameterSet& params, int exactEigenLimit = kExactEigenLimit,
                        int denseLimit = kDenseModeLimit);

// The one linearisation every door judges stability by (the pre-run banner, the failure
// banner, the stability map, the `stability` command, Python's stability()): the scene's
// start without its random perturbation (the rest shape the body is built in, which is the
// GUI's start and does not depend on the seed; the trials of the scan still start perturbed,
// to excite every mode). Exact first-order eigenvalues up to kVerdictExactLimit free
// coordinates (a dense solve well under 0.1 s); above, the extreme eigenvalues by Arnoldi on
// the Jacobian products (linearModes's iterative path) - never the modal approximation,
// which misses the fastest pure decay of non-proportional damping.
inline constexpr int kVerdictExactLimit = 150;
LinearModes stabilityModes(const simcore::ParameterSet& params);

// A scene of several bodies: the whole system's eigenvalues. The world's ODE (WorldOde) is
// linearised as one body's is: every body's forces (the blocks of a block-diagonal Jacobian),
// each body's wall contact at its design point (as for the body alone: Simulation::
// contactDesign), and the contact between bodies and within one outer layer wherever a pair
// is within the contact skin at that state (the pairs' Jacobian by directional differences of
// their forces). Bodies apart (every world at its start: validateWorld keeps them a skin
// apart) give the union of the bodies' own spectra. The spec form linearises the start
// without the perturbation; the World form the world as it is now (e.g. at an impact).
LinearModes linearModes(const simcore::WorldSpec& world, int exactEigenLimit = kExactEigenLimit,
                        int denseLimit = kDenseModeLimit);
LinearModes linearModes(simcore::World& world, int exactEigenLimit = kExactEigenLimit, int denseLimit = kDenseModeLimit);
LinearModes stabilityModes(const simcore::WorldSpec& world);

// The spectrum the prediction uses: the exact eigenvalues, or else Arnoldi's Ritz values
// (empty for a LinearModes built by hand from modes alone).
const std::vector<std::complex<double>>& spectrumOf(const LinearModes& modes);

// The verdict on one method at one step, from stabilityModes: the same figure everywhere.
struct StabilityVerdict {
    std::string integrator;
    double dt = 0.0;              // the step judged [s]
    // The method's largest stable step on this body [s]: 0 when none (Euler and Heun on
    // undamped modes), +inf when unlimited (implicit Euler) or when the method picks its own
    // step (adaptive rk45, CVODE, XPBD: `ownStep`).
    double limit = 0.0;
    bool ownStep = false;
    std::string basis;            // "exact spectrum (N eigenvalues)", "Arnoldi (N Ritz values)", ...
    // The same in parts, for a window that says it in another language: the kind, the values
    // it counts (eigenvalues, Ritz values) and, for Arnoldi, of how many (2 x free coordinates).
    enum class Basis { ExactSpectrum, Arnoldi, Modes, StepMatrix };
    Basis basisKind = Basis::Modes;
    std::size_t basisValues = 0, basisOf = 0;
    double omegaMax = 0.0;        // highest frequency [rad/s]
    std::complex<double> fastest{0.0, 0.0};  // the spectrum's eigenvalue of largest modulus [1/s]
    bool stable() const { return dt <= limit; }
};
// `adaptive`: the method runs with its own error-controlled step (rk45 unless fixed), so no
// DT limit applies; its fixed-step region is still what `limit` would be with adaptive false.
StabilityVerdict stabilityVerdict(const LinearModes& modes, const std::string& integrator, double dt,
                                  bool adaptive = false);
// The verdict as one line: "rk4 is stable up to DT = 0.00888 s on this body (exact spectrum
// ...)"; the figure printed with three significant digits, as every door prints it.
std::string verdictText(const StabilityVerdict& verdict);
// The limit as every door prints it: three significant digits ("0.00888"), "none", "unlimited".
std::string limitText(double limit);

// Spectral radius of one step of `integrator` on x'' + c x' + w^2 x = 0.
double modeAmplification(const std::string& integrator, double h, double omega, double c);
// The partitioned methods (symplectic-euler, verlet and its compositions): no scalar stability
// function; their step matrix per mode (or for the whole linear body) decides.
bool isPartitioned(const std::string& integrator);
// Largest h with every mode's amplification <= 1 (+1e-9): 0 when there is none (grows for
// every h), +infinity when unlimited (A-stable), searched up to hMax.
double predictedStableStep(const std::string& integrator, const LinearModes& modes, double hMax = 10.0);

struct StabilitySpec {
    simcore::ParameterSet params{simcore::SceneKind::Ring2d};
    // A scene of several bodies: the trials run the whole world (params then holds body 1's
    // values, as SceneSetup::params does) and the prediction is the world's spectrum.
    std::optional<simcore::WorldSpec> world;
    std::vector<std::string> integrators;
    double duration = 2.0;      // T [s]
    double perturb = 0.01;      // used when params has no explicit perturb [m]
    double hMin = 1e-5;         // [s] below this: "none"
    double hMax = 1.0;          // [s] the parameter table's largest dt
    double relativePrecision = 0.02;  // bisection stops when hi / lo < 1 + this
    int shardIndex = 0;
    int shardCount = 1;
};

// The one linearisation of a scan: the world's when spec.world is set, else the body's.
LinearModes stabilityModes(const StabilitySpec& spec);

struct StabilityRow {
    std::string integrator;
    double stable = 0.0;         // largest dt found stable [s] (0: none down to hMin)
    double unstable = 0.0;       // smallest dt found unstable [s] (inf: stable up to hMax)
    std::string reasonAbove;     // why the run at `unstable` failed
    double predicted = 0.0;      // linearised prediction [s] (0 none, inf unlimited)
    int runs = 0;
};

struct StabilityProgress {
    int done = 0;
    int total = 0;
    std::string what;
};
using StabilityProgressFn = std::function<void(const StabilityProgress&)>;

// One trial: stable (empty) or the reason it is not.
// One run at a fixed step: why it is unstable, or nothing. A run cancelled part-way (*cancel
// true) returns nothing too: the caller checks the flag before it believes the answer.
std::optional<std::string> stabilityTrial(const StabilitySpec& spec, const std::string& integrator, double dt,
                                          const std::atomic<bool>* cancel = nullptr);
StabilityRow scanIntegrator(const StabilitySpec& spec, const std::string& integrator, const LinearModes& modes,
                            const std::atomic<bool>* cancel = nullptr);
std::vector<StabilityRow> runStability(const StabilitySpec& spec, const LinearModes& modes,
                                       const StabilityProgressFn& progress = {},
                                       const std::atomic<bool>* cancel = nullptr);
std::vector<std::string> shardNames(const std::vector<std::string>& names, int shardIndex, int shardCount);

// The pre-run check: for an explicit fixed-step method, dt above its verdict's limit
// (stabilityVerdict on stabilityModes) gives a warning text. Adaptive rk45 and
// implicit-euler never warn.
std::optional<std::string> preRunStabilityWarning(const simcore::Simulation& sim);
// The same check with what to do about it: the warning and a step that the same estimate
// predicts stable (0.9 of the limit, rounded down to two significant digits), for the GUI's
// one-click offer and the CLI's advice. Nothing when the current dt is fine.
struct StabilityAdvice {
    std::string message;
    double suggestedDt = 0.0;  // [s]
    // The message's parts (the GUI says it in the window's language): the verdict (method, the
    // step judged, its limit and basis, the fastest eigenvalue); with no stable step at all
    // (Euler, Heun on undamped modes) the highest frequency and the growth per second instead.
    StabilityVerdict verdict;
    bool noStableStep = false;
    double omegaMax = 0.0;          // [rad/s]
    double growthPerSecond = 0.0;
};
std::optional<StabilityAdvice> stabilityAdvice(const simcore::Simulation& sim);
// The same from a linearisation (a world's: stabilityModes of its WorldSpec) for `integrator` at dt.
std::optional<StabilityAdvice> stabilityAdvice(const LinearModes& modes, const std::string& integrator, double dt);
// The failure banner's question: numerics or physics? A run failed at `failure.time`; the
// stretch from `start` (a snapshot some time before it) is run again at a smaller step -
// a quarter of the failed one, and no more than 0.9 of the method's verdict limit when that
// is smaller - up to failure.time + kFailureCheckMargin (or 10 of the failed steps, if
// longer). When the re-run fails too inside that window, the failure is the body's own (no
// step size saves it: a layer collapses under its load, ...); when it runs through, the step
// was too large. The verdict on the failed step comes with it (stabilityModes of the
// snapshot's parameters), for the banner's figure.
inline constexpr double kFailureCheckMargin = 0.1;  // [s]
inline constexpr long kFailureCheckMaxSteps = 400000;
struct FailureCheck {
    bool checked = false;          // false: cancelled, or more than kFailureCheckMaxSteps steps
    bool physical = false;         // the re-run failed as well
    std::string integrator;
    double failedDt = 0.0;         // [s]
    double rerunDt = 0.0;          // [s]
    double from = 0.0, until = 0.0;  // the stretch re-run [s]
    std::optional<simcore::Failure> rerunFailure;
    StabilityVerdict verdict;      // of the failed step
    // What a class can do: for a physical failure the body's remedies, for a numerical one
    // the step that ran through (rounded down to two digits) [s].
    double workingDt = 0.0;
};
FailureCheck checkFailure(const simcore::SimulationSnapshot& start, const simcore::Failure& failure,
                          const std::atomic<bool>* cancel = nullptr);
// The banner's words for a check: one paragraph, plain text (no markup).
std::string failureCheckText(const FailureCheck& check);

// x rounded down to two significant digits (0.000734 -> 0.00073).
double roundDownTwoDigits(double x);

// The energy a body can plausibly convert from its current state [J]: 1 J + its kinetic and
// elastic energy + its weight falling the box height + each gas expanding 100-fold (c ln 100).
// The yardstick of "bounded energy" here and of the gallery's tolerances.
double convertibleEnergy(const simcore::Simulation& sim);
// The same for a world: the bodies' sums (each body's weight over the box height, each gas
// expanding 100-fold).
double convertibleEnergy(const simcore::World& world);

std::string stabilityCsvHeader();  // integrator,dt_stable,dt_unstable,dt_predicted,h_omega_stable,reason
std::string stabilityCsvRow(const StabilityRow& row, const LinearModes& modes);

}  // namespace simlab
