#pragma once
// Long-time energy: how the energy error of each integrator grows over many periods.
//
// The scene is made undamped (kd = rkd = 0, restitution = 1, friction = 0: nothing removes
// energy, so the exact energy is constant) and run for P periods of its fastest mode
// (omega_max of the linearised body, stability.h) at the fixed step H. At log-spaced times
// t_k from one period to the end, the envelope |dE|(t_k) = max over steps so far of the
// energy balance's |drift| [J] is recorded, and the growth exponent alpha is the
// least-squares slope of log |dE| against log t over the samples from 10 periods on (the
// first decade is the start-up). Its 95 % confidence interval is the regression's
// (Student t with n - 2 degrees of freedom on the slope's standard error); the samples of an
// envelope are correlated, so the interval says how well a power law fits, not how much a
// second run would differ.
//
//   class         alpha            what it means
//   bounded       < 0.25           the error oscillates and does not grow (symplectic methods:
//                                  they conserve a modified energy; Verlet, yoshida4, ...)
//   random-walk   0.25 .. 0.75     grows like sqrt(t): round-off alone (Brouwer's law), each
//                                  step's rounding a random kick of the energy
//   drift         >= 0.75          grows like t or faster: the method's own error pumps energy
//                                  in or out every step (rk4 loses it; euler gains it)
//
// Precision float runs spring1d's float build (reference_problem.h), where the round-off walk
// shows within seconds. Qt-free: the CLI (`conservation`), the GUI and Python call this.
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "simcore/params.h"
#include "simcore/world.h"

namespace simlab {

struct ConservationSpec {
    simcore::ParameterSet params{simcore::SceneKind::Spring1d};  // the scene (damping is switched off)
    std::vector<std::string> integrators{"verlet", "yoshida4", "rk4"};
    double periods = 1000.0;  // P: run length in periods of the fastest mode
    double dt = 0.0;          // H [s]
    int samples = 120;        // log-spaced sample times (at most)
    std::string precision = "double";  // double | float (spring1d only)
    // A scene of several bodies asked for (the GUI's Studies menu on a world): refused by
    // checkConservation, which studies one body, with the words the CLI's refusal has.
    std::optional<simcore::WorldSpec> world;
};

struct ConservationRow {
    std::string integrator;
    double alpha = 0.0, alphaLo = 0.0, alphaHi = 0.0;  // growth exponent and its 95 % interval
    std::string growth;            // bounded | random-walk | drift ("" when not ok)
    double finalError = 0.0;       // |dE| envelope at the end [J]
    double relativeError = 0.0;    // that over the energy scale (ConservationResult) [-]
    double kineticMax = 0.0;       // the largest kinetic energy of this run [J]
    long steps = 0;
    double wallSeconds = 0.0;
    int fitPoints = 0;
    std::vector<std::pair<double, double>> curve;  // (t [s], envelope |dE| [J])
    bool ok = true;
    double failedAt = 0.0;
    std::string failure;
    std::string status() const;  // "ok" or "failed@<time>"
};

struct ConservationResult {
    double omegaMax = 0.0;     // fastest mode [rad/s]
    double period = 0.0;       // 2 pi / omegaMax [s]
    double duration = 0.0;     // P periods rounded up to whole steps [s]
    double energyScale = 0.0;  // the largest kinetic energy of the most accurate run [J] (relative errors)
    std::string undamped;      // what was switched off, e.g. "kd = 0, restitution = 1"
    std::vector<ConservationRow> rows;
    bool cancelled = false;
};

// The scene with every damping off (and what was changed, for the report).
simcore::ParameterSet undampedParameters(const simcore::ParameterSet& params, std::string* changed = nullptr);
std::optional<std::string> validateConservation(const ConservationSpec& spec);
// The classification of a growth exponent.
std::string growthClass(double alpha);
// Slope of log y on log x with its 95 % interval (nan when fewer than 3 points).
struct SlopeFit {
    double slope = 0.0, lo = 0.0, hi = 0.0;
    int points = 0;
};
SlopeFit logLogSlopeInterval(const std::vector<std::pair<double, double>>& points);

using ConservationProgressFn = std::function<void(int done, int total, const std::string& what)>;
ConservationResult runConservation(const ConservationSpec& spec, const ConservationProgressFn& progress = {},
                                   const std::atomic<bool>* cancel = nullptr);

// CSV: integrator,alpha,alpha_lo,alpha_hi,class,final_error,relative_error,fit_points,steps,
// wall_seconds,status (one row per integrator); the curves long-format:
// integrator,t,energy_error.
std::string conservationCsvHeader();
std::string conservationCsvRow(const ConservationRow& row);
std::string conservationCurvesCsv(const ConservationResult& result);
// Log-log plot of the envelopes |dE| against t, one curve per integrator, with reference
// slopes t^0.5 and t^1 drawn dashed from the middle curve's start.
std::string conservationSvg(const ConservationResult& result, const std::string& title);

}  // namespace simlab
