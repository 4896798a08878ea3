#pragma once
// Work-precision study: error against cost for several integrators and steps.
//
// For every (integrator, step) of the sweep: run the scene to T, compare with a reference
// solution computed once, and time the run (median of R repeats; only the stepping is timed,
// never sampling or output). A sweep can be cut into N shards (contiguous blocks of the
// sweep order) whose CSV rows concatenate into the unsharded result.
//
//   reference     closed form (spring1d, no perturbation, no wall reached), or RK4 at a step
//                 16x below the smallest studied one, or rk45 or cvode-bdf at a tight tolerance; its own
//                 error is estimated against a second, coarser reference run. `auto`: the closed
//                 form where it applies, else RK4, else (RK4 unstable there: stiff) cvode-bdf.
//   error_final   RMS over particles of |x - x_ref| at T                              [m]
//   error_max     largest such RMS over a fixed output grid (G samples, every dt divides it)
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
#include <vector>

#include <Eigen/Core>

#include "simcore/integrators.h"
#include "simcore/params.h"

namespace simcore {
class Simulation;
}  // namespace simcore

namespace simlab {

struct StudySpec {
    simcore::ParameterSet params{simcore::SceneKind::Spring1d};  // the scene; its dt is ignored
    std::vector<std::string> integrators;
    std::vector<double> dts;                   // fixed steps [s]; T must be a multiple of each
    std::vector<double> tolerances{1e-4, 1e-6, 1e-8, 1e-10};  // adaptive rk45 sweep
    double duration = 2.0;                     // T [s]
    int repeat = 1;                            // timing: median of this many runs
    std::string reference = "auto";            // auto | exact | rk4 | rk45 | cvode-bdf
    int samples = 20;                          // output grid size for error_max (at most)
    simcore::IntegratorOptions options;                 // base options (tolerances are overridden)
    int shardIndex = 0;                        // 0-based shard of shardCount
    int shardCount = 1;
};

// One point of the sweep.
struct StudyItem {
    std::string integrator;
    double dt = 0.0;          // fixed step [s], or the initial step of an adaptive run
    double tolerance = -1.0;  // adaptive runs: atol = rtol; < 0 for fixed-step runs
};

struct StudyRow {
    StudyItem item;
    double dt = 0.0;             // the step (fixed) or the mean step T / steps (adaptive) [s]
    long steps = 0;
    std::uint64_t forceEvaluations = 0;
    double wallSeconds = 0.0;    // median over the repeats, stepping only [s]
    double errorFinal = 0.0;     // [m]
    double errorMax = 0.0;       // [m]
    double errorEnergy = 0.0;    // [J]
    bool ok = true;
    double failedAt = 0.0;       // simulated time of the failure [s]
    std::string failure;         // reason, when !ok
    std::string status() const;  // "ok" or "failed@<time>"
};

struct StudyReference {
    std::string description;      // e.g. "closed form", "rk4 at dt = 6.25e-05 s"
    double estimatedError = 0.0;  // RMS position error estimate of the reference at T [m]
    std::vector<double> times;    // the output grid (last = T)
    std::vector<Eigen::Matrix3Xd> positions;  // reference positions at the grid times
};

struct OrderFit {
    std::string integrator;
    // Least-squares slope of log(error_max) against log(dt) over the three smallest steps
    // whose error is above 10x the reference's error (the asymptotic range). error_max, not
    // error_final: in a damped scene the state at T is near rest and hides the error.
    double order = 0.0;
    int points = 0;
};

struct StudyProgress {
    int done = 0;
    int total = 0;
    std::string what;  // "reference", "rk4 dt=0.01", ...
};
using StudyProgressFn = std::function<void(const StudyProgress&)>;

// The whole sweep in CSV order (integrator-major), and the part one shard runs.
std::vector<StudyItem> studyItems(const StudySpec& spec);
std::vector<StudyItem> shardItems(const std::vector<StudyItem>& items, int shardIndex, int shardCount);

// Validates the spec: returns a message naming the problem, or nothing.
std::optional<std::string> validateStudy(const StudySpec& spec);
// The output grid: G <= samples points k T / G such that T / G is a multiple of every dt.
std::vector<double> studyGrid(const StudySpec& spec);

StudyReference computeReference(const StudySpec& spec, const std::atomic<bool>* cancel = nullptr);
StudyRow runStudyItem(const StudySpec& spec, const StudyItem& item, const StudyReference& reference,
                      const std::atomic<bool>* cancel = nullptr);

struct StudyResult {
    StudyReference reference;
    std::vector<StudyRow> rows;
    bool cancelled = false;
};
// Reference + this shard's items. Stops early (cancelled = true) when *cancel becomes true.
StudyResult runStudy(const StudySpec& spec, const StudyProgressFn& progress = {},
                     const std::atomic<bool>* cancel = nullptr);

std::vector<OrderFit> fitOrders(const std::vector<StudyRow>& rows, double referenceError);

// CSV: header integrator,dt,steps,force_evals,wall_seconds,error_final,error_max,error_energy,status
// Errors of a failed row are left empty (a failed run has no error value).
std::string studyCsvHeader();
std::string studyCsvRow(const StudyRow& row);
// Parses rows written by studyCsvRow (e.g. concatenated shards); nullopt on a malformed line.
std::optional<std::vector<StudyRow>> parseStudyCsv(const std::string& text, std::string* error = nullptr);

// Three log-log panels: error_max against wall time (work-precision), against force
// evaluations, and against dt. Failed rows are not drawn.
std::string studySvg(const std::vector<StudyRow>& rows, const std::string& title);
// The colour of an integrator's curve in the study diagrams: one of its own for every
// integrator in the table (grey for an unknown name).
const char* studyColour(std::string_view integrator);

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
};
SampledRun runSampled(const simcore::ParameterSet& params, const std::string& integrator, double dt,
                      const simcore::IntegratorOptions& options, const std::vector<double>& grid,
                      const std::function<void(const simcore::Simulation&)>& sample,
                      const std::atomic<bool>* cancel = nullptr);

// Log-log line plots side by side as SVG (each panel its own decades). A series is a polyline
// through its points in the given order, with a dot (and an optional label) at each; points
// that are not positive and finite are left out. The legend lists each name once.
struct SvgSeries {
    std::string name;
    std::string colour;                           // e.g. "#1f77b4"
    std::string dash;                             // stroke-dasharray, "" = solid
    std::vector<std::pair<double, double>> points;
    std::vector<std::string> labels;              // per point, may be shorter or empty
};
struct SvgPanel {
    std::string xLabel, yLabel;
    std::vector<SvgSeries> series;
};
std::string logLogSvg(const std::vector<SvgPanel>& panels, const std::string& title);

}  // namespace simlab
