#pragma once
// Work-precision study: error against cost for several integrators and steps.
//
// For every (integrator, step) of the sweep: run the scene to T, compare with a reference
// solution computed once, and time the run R times (every raw wall time is kept; a point
// reports their minimum, quartiles and median; only the stepping is timed, never sampling or
// output). With a time budget B, a point whose run would take longer than B is recorded as
// "not reached" (no error), and so is every costlier point of the same integrator: the curve
// stops there. With precision float the fixed-step methods run on the float build of the
// reference problem (reference_problem.h) for spring1d without perturbation, and on the float
// path of the Simulation (simcore/float_path.h: euler, midpoint, rk4, symplectic-euler, verlet;
// a body that reaches a wall fails there) for every other body. A sweep can be cut into N shards (contiguous blocks of the
// sweep order) whose CSV rows concatenate into the unsharded result.
//
//   reference     closed form (spring1d, no perturbation, no wall reached), or RK4 at a step
//                 16x below the smallest studied one, or rk45 or cvode-bdf at a tight tolerance; its own
//                 error is estimated against a second, coarser reference run. `auto`: the closed
//                 form where it applies, else RK4, else (RK4 unstable there: stiff) cvode-bdf.
//   error_final   RMS over particles of |x - x_ref| at T                              [m]
//   error_max     largest such RMS over a fixed output grid (G samples, every dt divides it)
//   error_rms     root mean square of that RMS over the grid's samples                  [m]
//   error_energy  largest |energy balance drift| over all steps                        [J]
//
// Adaptive rk45, cvode-bdf and cvode-adams are swept over tolerances (atol = rtol = tol)
// instead of steps; their dt is then the mean step T / steps. With simcore::IntegratorOptions::fixedStep
// rk45 takes the steps given (the CVODE methods are always adaptive).
// Qt-free: the CLI (`elastic-lab-cli study`) and the GUI call the same code.

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "simcore/integrators.h"
#include "simcore/params.h"
#include "simcore/world.h"

namespace simcore {
class Simulation;
}  // namespace simcore

namespace simlab {

struct StudySpec {
    simcore::ParameterSet params{simcore::SceneKind::Spring1d};  // the scene; its dt is ignored
    // A scene of several bodies: every run and the reference run the whole world (params then
    // holds body 1's values); the errors are over every particle of every body. Double only
    // (the float build is of one body); no closed form.
    std::optional<simcore::WorldSpec> world;
    std::vector<std::string> integrators;
    std::vector<double> dts;                   // fixed steps [s]; T must be a multiple of each
    std::vector<double> tolerances{1e-4, 1e-6, 1e-8, 1e-10};  // adaptive rk45 sweep
    double duration = 2.0;                     // T [s]
    int repeat = 1;                            // timing: this many runs of each point
    double timeBudget = 0.0;                   // a run longer than this [s] is "not reached"; 0 = none
    // double: the Simulation; float: the float build of the reference problem (spring1d,
    // reference_problem.h) or the float path (every other body). Each integrator runs in each
    // precision listed.
    std::vector<std::string> precisions{"double"};
    bool compensated = false;                  // float: Kahan-compensated state update
    std::string reference = "auto";            // auto | exact | rk4 | rk45 | cvode-bdf
    int samples = 20;                          // output grid size for error_max (at most)
    simcore::IntegratorOptions options;                 // base options (tolerances are overridden)
    int shardIndex = 0;                        // 0-based shard of shardCount
    int shardCount = 1;
};

// One point of the sweep.
struct StudyItem {
    std::string integrator;
    std::string precision = "double";
    double dt = 0.0;          // fixed step [s], or the initial step of an adaptive run
    double tolerance = -1.0;  // adaptive runs: atol = rtol; < 0 for fixed-step runs
};

struct StudyRow {
    StudyItem item;
    double dt = 0.0;             // the step (fixed) or the mean step T / steps (adaptive) [s]
    long steps = 0;
    std::uint64_t forceEvaluations = 0;
    std::vector<double> walls;   // every repeat's wall time, in run order, stepping only [s]
    double wallSeconds = 0.0;    // median over the repeats [s]
    double wallMin = 0.0, wallQ1 = 0.0, wallQ3 = 0.0;  // minimum and quartiles over the repeats [s]
    double errorFinal = 0.0;     // [m]
    double errorMax = 0.0;       // [m]
    double errorRms = 0.0;       // [m]
    double errorEnergy = 0.0;    // [J]
    bool ok = true;
    bool reached = true;         // false: over the time budget (then ok is false too)
    double failedAt = 0.0;       // simulated time of the failure [s]
    std::string failure;         // reason, when !ok
    std::string status() const;  // "ok", "failed@<time>" or "not reached"
    std::string label() const;   // the curve's name: the integrator, "+ (float)" in float
};

// Quantiles of wall times (linear interpolation between order statistics, q in [0, 1]).
double wallQuantile(std::vector<double> walls, double q);
// Fills wallMin, wallQ1, wallSeconds (median) and wallQ3 from walls.
void summariseWalls(StudyRow& row);

struct StudyReference {
    bool cancelled = false;       // stopped before it was complete: nothing else is set
    std::string description;      // e.g. "closed form", "rk4 at dt = 6.25e-05 s"
    double estimatedError = 0.0;  // RMS position error estimate of the reference at T [m]
    std::vector<double> times;    // the output grid (last = T)
    std::vector<Eigen::Matrix3Xd> positions;  // reference positions at the grid times
};

struct OrderFit {
    std::string integrator;      // the curve's label (StudyRow::label)
    // Least-squares slope of log(error_max) against log(dt) over the three smallest steps
    // whose error is above 10x the reference's error (the asymptotic range). error_max, not
    // error_final: in a damped scene the state at T is near rest and hides the error.
    double order = 0.0;
    int points = 0;
    // The same fit for error_final and error_rms.
    double orderFinal = 0.0, orderRms = 0.0;
    int pointsFinal = 0, pointsRms = 0;
};

// The fastest method of each family at each accuracy: for every decade of error_max between
// the largest and the smallest reached, the least cost (log-log interpolated along each
// curve) at which a method of the family first gets there.
struct FamilyBest {
    std::string family;
    double error = 0.0;          // the accuracy level [m]
    std::string integrator;      // the fastest of the family there (its label)
    double wallSeconds = 0.0;    // its interpolated median wall time [s]
    double forceEvaluations = 0.0;  // and force evaluations (the method fastest in wall time)
};
std::vector<FamilyBest> fastestByFamily(const std::vector<StudyRow>& rows);

struct StudyProgress {
    int done = 0;
    int total = 0;
    std::string what;  // "reference", "rk4 dt=0.01", ...
};
using StudyProgressFn = std::function<void(const StudyProgress&)>;

// The whole sweep in CSV order (integrator-major), and the part one shard runs.
std::vector<StudyItem> studyItems(const StudySpec& spec);
std::vector<StudyItem> shardItems(const std::vector<StudyItem>& items, int shardIndex, int shardCount);

// precision float: spring1d without perturbation runs the float build of the reference problem
// (reference_problem.h, also for the Yoshida compositions); every other body the float path of
// the Simulation (simcore/float_path.h).
bool floatOnReferenceProblem(const StudySpec& spec);

// Validates the spec: returns a message naming the problem, or nothing.
std::optional<std::string> validateStudy(const StudySpec& spec);
// The output grid: G <= samples points k T / G such that T / G is a multiple of every dt.
std::vector<double> studyGrid(const StudySpec& spec);
// The step of the rk4 reference (16x below the smallest studied step, 1e-3 s without fixed
// steps), or 0 when the reference is not rk4 (closed form, rk45, cvode-bdf).
double studyReferenceStep(const StudySpec& spec);

StudyReference computeReference(const StudySpec& spec, const std::atomic<bool>* cancel = nullptr);
StudyRow runStudyItem(const StudySpec& spec, const StudyItem& item, const StudyReference& reference,
                      const std::atomic<bool>* cancel = nullptr);
// runStudyItem, unless a cheaper point of the same curve among `done` was not reached (over
// the time budget): then the point is recorded as not reached without running it.
StudyRow runStudyPoint(const StudySpec& spec, const StudyItem& item, const StudyReference& reference,
                       const std::vector<StudyRow>& done, const std::atomic<bool>* cancel = nullptr);

struct StudyResult {
    StudyReference reference;
    std::vector<StudyRow> rows;
    bool cancelled = false;
};
// Reference + this shard's items. Stops early (cancelled = true) when *cancel becomes true.
StudyResult runStudy(const StudySpec& spec, const StudyProgressFn& progress = {},
                     const std::atomic<bool>* cancel = nullptr);

std::vector<OrderFit> fitOrders(const std::vector<StudyRow>& rows, double referenceError);

// CSV: header integrator,family,precision,dt,steps,force_evals,repeats,wall_min,wall_q1,
// wall_median,wall_q3,error_final,error_max,error_rms,error_energy,status. Errors of a failed or
// unreached row are left empty (such a run has no error value).
std::string studyCsvHeader();
std::string studyCsvRow(const StudyRow& row);
// The raw timings, long format: header integrator,precision,dt,repeat,wall_seconds; one line
// per run (repeat 1..R).
std::string studyTimingsCsvHeader();
std::string studyTimingsCsvRows(const StudyRow& row);
// Parses rows written by studyCsvRow (e.g. concatenated shards); nullopt on a malformed line.
std::optional<std::vector<StudyRow>> parseStudyCsv(const std::string& text, std::string* error = nullptr);

// Three log-log panels: error_max against wall time (work-precision; the median, with a band
// from q1 to q3 of the repeats), against force evaluations, and against dt (with the
// predicted round-off floor eps sqrt(T / h) X of each precision present, X the largest
// |position| of the reference). Failed and unreached rows are not drawn; the fastest method of
// each family at each accuracy is ringed. `roundoffScale` is X (0: no floor drawn) and
// `duration` T.
std::string studySvg(const std::vector<StudyRow>& rows, const std::string& title, double roundoffScale = 0.0,
                     double duration = 0.0);
// The predicted round-off floor of a fixed-step run: eps X sqrt(T / h) (eps the unit round-off
// of the precision, 2^-24 or 2^-53): each step rounds the state, and n = T / h roundings
// add up as a random walk.
double roundoffFloor(const std::string& precision, double scale, double duration, double h);
// The largest |position| coordinate of the reference over its grid [m] (the X above).
double referenceScale(const StudyReference& reference);
// The colour of an integrator's curve in the study diagrams: a shade of its family's hue,
// one of its own for every integrator in the table (grey for an unknown name).
const char* studyColour(std::string_view integrator);
// The hue of a family (the darkest shade of its members).
const char* familyColour(std::string_view family);

// --- shared with the other studies (refinement.h) ------------------------------------------

// Least-squares slope of log y against log x (the points positive); nan below two points.
double logLogSlope(const std::vector<std::pair<double, double>>& points);

// Whether T is (within round-off) a whole multiple of h.
bool isWholeMultiple(double T, double h);

// One run of `params` with `integrator`, single-threaded, from its start state through the
// grid times (ascending, > 0): a fixed-step method takes exactly round(t / dt) steps to each,
// an adaptive one lands on each. sample(sim) is called at every grid time reached. Only the
// stepping is timed (never the sampling). Stops at a failure or when *cancel becomes true.
struct SampledRun {
    bool failed = false;
    double failedAt = 0.0;       // simulated time of the failure [s]
    std::string failure;         // its reason
    bool cancelled = false;
    long steps = 0;
    std::uint64_t evaluations = 0;  // force evaluations
    double wallSeconds = 0.0;    // stepping only [s]
    double maxDrift = 0.0;       // largest |energy balance drift| over the steps [J]
    bool overBudget = false;     // stopped because the stepping took longer than wallBudget
};
SampledRun runSampled(const simcore::ParameterSet& params, const std::string& integrator, double dt,
                      const simcore::IntegratorOptions& options, const std::vector<double>& grid,
                      const std::function<void(const simcore::Simulation&)>& sample,
                      const std::atomic<bool>* cancel = nullptr, double wallBudget = 0.0);
// The same for a world (dt set on every body, as the world's one step).
SampledRun runSampled(const simcore::WorldSpec& world, const std::string& integrator, double dt,
                      const simcore::IntegratorOptions& options, const std::vector<double>& grid,
                      const std::function<void(const simcore::World&)>& sample,
                      const std::atomic<bool>* cancel = nullptr, double wallBudget = 0.0);

// Log-log line plots side by side as SVG (each panel its own decades). A series is a polyline
// through its points in the given order, with a dot (and an optional label) at each; points
// that are not positive and finite are left out. The legend lists each name once.
struct SvgSeries {
    SvgSeries() = default;
    SvgSeries(std::string name_, std::string colour_, std::string dash_ = {},
              std::vector<std::pair<double, double>> points_ = {}, std::vector<std::string> labels_ = {})
        : name(std::move(name_)), colour(std::move(colour_)), dash(std::move(dash_)), points(std::move(points_)),
          labels(std::move(labels_)) {}
    std::string name;
    std::string colour;                           // e.g. "#1f77b4"
    std::string dash;                             // stroke-dasharray, "" = solid
    std::vector<std::pair<double, double>> points;
    std::vector<std::string> labels;              // per point, may be shorter or empty
    // A band around the line (e.g. quartiles of the wall time): per point the x range
    // [bandLow, bandHigh] at its y, drawn as a translucent area; empty = none.
    std::vector<double> bandLow, bandHigh;
    // Points ringed (e.g. the fastest of a family), drawn as open circles.
    std::vector<std::pair<double, double>> rings;
    bool inLegend = true;
};
struct SvgPanel {
    std::string xLabel, yLabel;
    std::vector<SvgSeries> series;
};
std::string logLogSvg(const std::vector<SvgPanel>& panels, const std::string& title);

}  // namespace simlab
