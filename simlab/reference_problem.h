#pragma once
// The reference problem built in float (and in double): spring1d, the scene with a closed form
// (analytic.h), as its own small ODE, integrated with Scalar arithmetic throughout by the
// fixed-step explicit and symplectic methods. It exists to show round-off: in float the
// error of a fixed-step method stops falling where the step's rounding (eps ~ 6e-8 per step,
// growing like sqrt(steps)) overtakes the truncation error, and rises beyond. The Simulation
// is double only; this is the float path of the work-precision study (study --precision
// float), and its double build is checked against the Simulation to round-off (test_numerics).
//
//   state y = [y0, y1 | v0, v1 | removed]   (the two particles' heights and speeds, and the
//             energy removed by damping, integrated like the Simulation's aux)
//   m y1'' = k (s - L0) + c (v0 - v1) - m g,  s = y0 - y1;  particle 0 the opposite spring
//             force, or fixed (fixed_end = 1); removed' = c (v0 - v1)^2
//
// Compensated (Kahan) summation of the state update, on request: every y += dy of a step keeps
// the low-order part the addition lost and adds it back at the next update, so the state's
// rounding no longer walks like sqrt(steps) (the stage arithmetic still rounds).
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "simcore/params.h"

namespace simlab {

// Whether the reference problem has a build of this method (euler, midpoint, rk4,
// symplectic-euler, verlet, yoshida4, yoshida8).
bool referenceProblemSupports(const std::string& integrator);
// "" when params is spring1d (the caller checks that no wall is reached), else why not.
std::string referenceProblemRefusal(const simcore::ParameterSet& params);

struct ReferenceProblemRun {
    std::vector<Eigen::Matrix3Xd> positions;  // at the grid times (3 x 2, in double)
    long steps = 0;
    std::uint64_t evaluations = 0;
    double wallSeconds = 0.0;     // stepping only [s]
    double maxDrift = 0.0;        // largest |energy balance drift| over the grid times [J]
                                  // (over every step with everyStep)
    std::vector<double> envelope; // maxDrift so far at each grid time reached [J]
    double maxKinetic = 0.0;      // largest kinetic energy seen [J]
    bool failed = false;          // a non-finite state
    double failedAt = 0.0;
    bool cancelled = false;
    bool overBudget = false;      // the stepping took longer than wallBudget
};

// One run to each grid time (ascending; every time a whole number of steps dt), in float
// (precision "float") or double.
ReferenceProblemRun runReferenceProblem(const simcore::ParameterSet& params, const std::string& integrator, double dt,
                                        const std::vector<double>& grid, const std::string& precision,
                                        bool compensated, const std::atomic<bool>* cancel = nullptr,
                                        double wallBudget = 0.0, bool everyStep = false);

}  // namespace simlab
