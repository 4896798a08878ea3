#pragma once
// Refinement study: spatial error against run time (docs/numerics.md "Refinement study").
//
// The same body (scaling as set; under scaling=physical it keeps its totals and material
// constants, scaling.h) runs at several resolutions of its mesh, each with the same step, small
// enough that the time error is negligible against the space error. Observables that exist at
// every resolution are compared against the FINEST resolution (most particles) on an output
// grid (every `interval` seconds up to T):
//
//   error_volume  largest relative error of a layer's enclosed volume (area in 2D), over both
//                 layers and every grid time: max |V - V_finest| / |V_finest|           [1]
//   error_com     largest distance of the centre of mass, mass-weighted (sum m x / sum m),
//                 from the finest's, over the grid times                                [m]
//
// The step. A given fixed dt must divide the output interval and be stable at the finest
// level (stabilityAdvice of that body). Without one: a quarter of the smaller of the scene's dt
// and the step the stability check suggests at the finest level (stabilityAdvice probed at
// dt = 1 s: 0.9 of the predicted limit), rounded down to divide the interval; the same step at
// every level (a coarser body's modes are slower, so it is stable there too). Adaptive rk45
// runs at atol = rtol = tolerance instead. The time error of that step is then MEASURED, not
// assumed: the finest-but-one level runs again at 2, 4, 8, ... dt (rk45: 10, 100, ...
// times the tolerance) and is compared with its own run at dt on the same observables. These
// are the temporal curve the plot draws beside the spatial one ("is my error from the mesh or
// from the step?"), and the 2 dt point gives the time error estimate of dt itself:
// difference / (2^p - 1) for a method of order p (rk45: the difference to 10x its tolerance,
// an upper bound). Spatial errors below 10x that estimate are not resolved: the order fit
// leaves them out.
//
// The start state must be the same body at every level: a random start perturbation
// (`perturb`, independent per particle) gives each level a different start shape, an error that
// does not shrink with h. Weightless (gravity = 0), the default body inflates from its rest shape
// to its equilibrium, a smooth motion every level resolves; with gravity it also hits the floor.
//
// The spatial order: the least-squares slope of log(error) against log(h) over the three
// finest resolved levels (not the reference), h = the mean rest length of the structural
// springs (the mesh spacing) at that level. Measured against the finest level, an error
// C h^p appears as C (h^p - h_finest^p): for p = 2 and levels halving h the next-to-finest
// point is 3/4 of its true value, which steepens the fit slightly (2.3 for a true 2).
//
// Qt-free: the CLI (`elastic-lab-cli study --refine`) and the GUI call the same code.

#include <array>
#include <atomic>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "simcore/integrators.h"
#include "simcore/params.h"
#include "simcore/world.h"
#include "simlab/study.h"

namespace simlab {

struct RefinementSpec {
    simcore::ParameterSet params{simcore::SceneKind::Ring2d};  // the body; its resolution key is set per level
    // A scene of several bodies: every body's resolution is raised together (the bodies of one
    // kind, one key); params holds body 1's values. The observables are every body's: the
    // largest volume error over every body and layer, the largest centre-of-mass distance over
    // every body; particles and springs are the world's, h the mean over every body.
    std::optional<simcore::WorldSpec> world;
    std::string key;                 // the scene's resolution key: particles, subdivisions or slices
                                     // (lat/long: stacks = slices / 2 at every level)
    std::vector<int> values;         // the levels (at least two); the one with most particles is the reference
    std::string integrator = "rk4";
    double dt = 0.0;                 // fixed step [s]; 0 = chosen as in the header
    double tolerance = 1e-9;         // adaptive rk45: atol = rtol
    double duration = 1.0;           // T [s]
    double interval = 0.01;          // output grid spacing [s]; T must be a whole multiple
    int temporalRuns = 4;            // runs of the temporal curve (2^k dt or 10^k tol, k = 1..), 0 = none
    simcore::IntegratorOptions options;       // base options (rk45's tolerances are overridden)
};

// One resolution.
struct RefinementRow {
    int value = 0;                   // the level (value of the key)
    int particles = 0;               // all particles of the body
    int springs = 0;                 // all springs (every family)
    double h = 0.0;                  // mean structural rest length [m]
    double dt = 0.0;                 // the step (fixed) or the mean step T / steps (rk45) [s]
    long steps = 0;
    double wallSeconds = 0.0;        // stepping only, one thread [s]
    double errorVolume = 0.0;        // [1], 0 for the reference
    double errorCom = 0.0;           // [m], 0 for the reference
    bool reference = false;          // the finest level, against which the others are measured
    bool ok = true;
    double failedAt = 0.0;           // simulated time of the failure [s]
    std::string failure;             // reason, when !ok
    std::string status() const;      // "ok", or "failed@<time>: <reason>" (no commas)
};

// One run of the temporal curve (the finest-but-one level at a coarser step or tolerance).
struct TemporalPoint {
    double dt = 0.0;                 // the step, or the mean step (rk45) [s]
    double tolerance = -1.0;         // rk45: atol = rtol; < 0 for fixed steps
    long steps = 0;
    double wallSeconds = 0.0;        // [s]
    double errorVolume = 0.0;        // against the same level at the study's step [1]
    double errorCom = 0.0;           // [m]
    bool ok = true;
    std::string failure;
};

struct RefinementResult {
    std::vector<RefinementRow> rows;          // ascending particle count (levels that ran)
    double dt = 0.0;                          // the step every level used [s] (rk45: its first step)
    std::string stepRule;                     // how dt was chosen, one line
    int temporalValue = 0;                    // the level of the temporal curve
    std::vector<TemporalPoint> temporal;      // ascending step
    double timeErrorVolume = std::nan("");    // estimated time error of dt (nan: not measured) [1]
    double timeErrorCom = std::nan("");       // [m]
    bool cancelled = false;
};

struct SpatialOrder {
    std::string observable;          // "volume" or "com"
    double order = std::nan("");     // slope of log error against log h
    int points = 0;
};

// The parameter a scene refines with (Param::Particles for ring2d, ...); none for the 1D spring.
std::optional<simcore::Param> refinementParam(simcore::SceneKind kind);
// Its key, for messages and the command line ("particles"); empty for the 1D spring.
std::string refinementKey(simcore::SceneKind kind);
// Validates the spec (key, levels, step, tolerances, grid): a message naming the problem, or nothing.
std::optional<std::string> validateRefinement(const RefinementSpec& spec);
// The parameters of one level (the key set; lat/long: stacks = slices / 2).
simcore::ParameterSet refinementLevel(const RefinementSpec& spec, int value);
// A world's level: every body's key set.
simcore::WorldSpec refinementWorld(const RefinementSpec& spec, int value);
// The step of the study and one line saying how it was chosen (header comment).
std::pair<double, std::string> refinementStep(const RefinementSpec& spec);

// Runs the finest level (the reference), the others, then the temporal curve. Throws
// std::runtime_error when the reference fails. Stops early (cancelled = true) when *cancel
// becomes true; rows finished by then are kept.
RefinementResult runRefinement(const RefinementSpec& spec, const StudyProgressFn& progress = {},
                               const std::atomic<bool>* cancel = nullptr);

std::vector<SpatialOrder> fitSpatialOrders(const RefinementResult& result);

// CSV: key,value,particles,springs,wall_seconds,error_volume,error_com,status,h,dt,steps,reference
// Errors of a failed row are empty.
std::string refinementCsvHeader();
std::string refinementCsvRow(const std::string& key, const RefinementRow& row);

// Two panels (volume, centre of mass): error against wall time for the mesh levels (the
// spatial curve) and for the steps of the temporal curve, side by side on the same axes.
std::string refinementSvg(const RefinementSpec& spec, const RefinementResult& result, const std::string& title);

}  // namespace simlab
