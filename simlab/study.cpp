#include "simlab/study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "simcore/float_path.h"
#include "simcore/integrator_table.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/analytic.h"
#include "simlab/output.h"
#include "simlab/reference_problem.h"

namespace simlab {

using simcore::quoteShort;
using simcore::IntegratorOptions;
using simcore::Param;
using simcore::ParameterSet;
using simcore::Simulation;
using simcore::World;
using simcore::WorldBodySpec;
using simcore::WorldSpec;
using simcore::integratorFamilies;
using simcore::integratorFamily;
using simcore::integratorNames;
using simcore::makeIntegrator;
using simcore::parseNumber;

namespace {

// rk45 unless it takes fixed steps, and the CVODE methods (always adaptive): swept over
// tolerances.
bool isAdaptiveItem(const StudySpec& spec, const std::string& integrator) {
    if (integrator == "rk45") return !spec.options.fixedStep;
    const auto method = makeIntegrator(integrator);
    return method && method->adaptive();
}

double rmsDistance(const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) {
    return std::sqrt((a - b).squaredNorm() / static_cast<double>(std::max<Eigen::Index>(1, a.cols())));
}

// One run of a trajectory, its positions sampled on the grid.
struct Trajectory : SampledRun {
    std::vector<Eigen::Matrix3Xd> positions;
};

Trajectory runTrajectory(const StudySpec& spec, const std::string& integrator, double dt,
                         const IntegratorOptions& options, const std::vector<double>& grid,
                         const std::atomic<bool>* cancel, double wallBudget = 0.0) {
    Trajectory out;
    out.positions.reserve(grid.size());
    if (spec.world) {
        // Every particle of every body, the bodies side by side (the world's numbering).
        static_cast<SampledRun&>(out) = runSampled(
            *spec.world, integrator, dt, options, grid,
            [&](const World& world) {
                out.positions.emplace_back(
                    Eigen::Map<const Eigen::Matrix3Xd>(world.state().data(), 3, world.particleCount()));
            },
            cancel, wallBudget);
        return out;
    }
    static_cast<SampledRun&>(out) = runSampled(
        spec.params, integrator, dt, options, grid, [&](const Simulation& sim) { out.positions.emplace_back(sim.positions()); },
        cancel, wallBudget);
    return out;
}

double smallestFixedStep(const StudySpec& spec) {
    double h = 0.0;
    for (const std::string& name : spec.integrators)
        if (!isAdaptiveItem(spec, name))
            for (double dt : spec.dts) h = h == 0.0 ? dt : std::min(h, dt);
    if (h == 0.0) h = spec.dts.empty() ? 1e-3 : *std::min_element(spec.dts.begin(), spec.dts.end());
    return h;
}

// The closed form applies: spring1d, unperturbed, and no particle ever reaches a wall.
bool closedFormApplies(const StudySpec& spec) {
    if (spec.world) return false;  // bodies that meet have no closed form
    if (!hasClosedForm(spec.params) || spec.params.get(Param::Perturb) != 0.0) return false;
    Simulation sim(spec.params, "euler");
    const Eigen::Vector3d centre = sim.boxCentre();
    const double box = sim.boxHalfSize();
    Eigen::Matrix3Xd x, v;
    const int checks = 4000;
    for (int k = 0; k <= checks; ++k) {
        spring1dExact(spec.params, spec.duration * k / checks, x, v);
        for (Eigen::Index i = 0; i < x.cols(); ++i)
            if (std::abs(x(1, i) - centre.y()) >= box) return false;
    }
    return true;
}

// One stretch of a timed run: steps while more() holds and step() succeeds (false: failed),
// adding the stretch's wall time to out.wallSeconds; stops at a cancel, or when the run would
// go over wallBudget (read off the clock every 64 steps: a clock read costs ~20 ns).
template <class More, class Step>
void timedStretch(SampledRun& out, More&& more, Step&& step, const std::atomic<bool>* cancel, double wallBudget) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    long counted = 0;
    while (more()) {
        if (!step()) break;
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            out.cancelled = true;
            break;
        }
        if (wallBudget > 0.0 && (++counted & 63) == 0 &&
            out.wallSeconds + std::chrono::duration<double>(Clock::now() - start).count() > wallBudget) {
            out.overBudget = true;
            break;
        }
    }
    out.wallSeconds += std::chrono::duration<double>(Clock::now() - start).count();
    if (wallBudget > 0.0 && out.wallSeconds > wallBudget) out.overBudget = true;
}

// The end of a timed run: its failure, steps and force evaluations (a Simulation or the float path).
template <class Sim>
void endRun(SampledRun& out, const Sim& sim) {
    if (sim.failed()) {
        out.failed = true;
        out.failedAt = sim.failure()->time;
        out.failure = sim.failure()->reason;
    }
    out.steps = sim.stepCount();
    out.evaluations = sim.diagnostics().forceEvaluations;
}

// One run of the float path (FloatSimulation), single-threaded, from the scene's start through
// the grid times, its positions sampled there (in double). Only the stepping is timed; the
// energy drift is measured at the grid times (the float path measures its diagnostics in
// double on request, a pass the double path's step makes anyway: measured every step, it would
// be timed as the float path's cost).
Trajectory runFloatTrajectory(const ParameterSet& base, const std::string& integrator, double dt,
                              const std::vector<double>& grid, const std::atomic<bool>* cancel, double wallBudget) {
    ParameterSet p = base;
    if (auto error = p.set(Param::Dt, dt)) throw std::invalid_argument(*error);
    const Simulation start(p, integrator);
    simcore::FloatSimulation sim(start);
    sim.setThreads(1);  // timings are single-threaded, as runSampled's
    Trajectory out;
    out.positions.reserve(grid.size());
    const auto n = static_cast<Eigen::Index>(sim.topology().particleCount());
    for (double target : grid) {
        const long targetSteps = std::lround(target / dt);
        timedStretch(out, [&] { return sim.stepCount() < targetSteps; }, [&] { return sim.step(); }, cancel, wallBudget);
        if (sim.failed() || out.cancelled || out.overBudget) break;
        out.maxDrift = std::max(out.maxDrift, std::abs(sim.diagnostics().energyDrift()));
        const Eigen::VectorXd y = sim.state();
        out.positions.emplace_back(Eigen::Map<const Eigen::Matrix3Xd>(y.data(), 3, n));
    }
    endRun(out, sim);
    return out;
}

std::string formatShort(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

}  // namespace

namespace {

std::optional<std::pair<double, std::string>> failureOf(const Simulation& sim) {
    if (!sim.failed()) return std::nullopt;
    return std::pair{sim.failure()->time, sim.failure()->reason};
}

std::optional<std::pair<double, std::string>> failureOf(const World& world) {
    if (!world.failed()) return std::nullopt;
    return std::pair{world.failedTime(), *world.failure()};
}

// The stepping of runSampled, for a Simulation or a World.
template <class System>
SampledRun sampleSteps(System& sim, double dt, const std::vector<double>& grid,
                       const std::function<void(const System&)>& sample, const std::atomic<bool>* cancel,
                       double wallBudget) {
    SampledRun out;
    const bool adaptive = sim.integrator().adaptive();
    for (double target : grid) {
        // Fixed steps: count them (t accumulated as a sum of dt drifts by round-off, and one
        // step too many at a grid time is an error of v dt). Adaptive: land on the target.
        const long targetSteps = std::lround(target / dt);
        auto more = [&] { return adaptive ? sim.time() < target - 1e-12 * std::max(1.0, target) : sim.stepCount() < targetSteps; };
        timedStretch(out, more, [&] {
            if (!sim.step(target)) return false;
            out.maxDrift = std::max(out.maxDrift, std::abs(sim.diagnostics().energyDrift()));
            return true;
        }, cancel, wallBudget);
        if (sim.failed() || out.cancelled || out.overBudget) break;
        sample(sim);
    }
    if (const auto failure = failureOf(sim)) {
        out.failed = true;
        out.failedAt = failure->first;
        out.failure = failure->second;
    }
    out.steps = sim.stepCount();
    out.evaluations = sim.diagnostics().forceEvaluations;
    return out;
}

}  // namespace

SampledRun runSampled(const ParameterSet& base, const std::string& integrator, double dt,
                      const IntegratorOptions& options, const std::vector<double>& grid,
                      const std::function<void(const Simulation&)>& sample, const std::atomic<bool>* cancel,
                      double wallBudget) {
    ParameterSet p = base;
    if (auto error = p.set(Param::Dt, dt)) throw std::invalid_argument(*error);
    Simulation sim(p, integrator);
    sim.setThreads(1);  // timings are single-threaded, whatever the machine
    sim.setIntegratorOptions(options);
    return sampleSteps(sim, dt, grid, sample, cancel, wallBudget);
}

SampledRun runSampled(const WorldSpec& base, const std::string& integrator, double dt,
                      const IntegratorOptions& options, const std::vector<double>& grid,
                      const std::function<void(const World&)>& sample, const std::atomic<bool>* cancel,
                      double wallBudget) {
    WorldSpec spec = base;
    for (WorldBodySpec& body : spec.bodies)  // dt is the world's: every body's copy alike
        if (auto error = body.params.set(Param::Dt, dt)) throw std::invalid_argument(*error);
    World world(spec, integrator);  // one thread, as a body's timing
    world.setIntegratorOptions(options);
    return sampleSteps(world, dt, grid, sample, cancel, wallBudget);
}

bool isWholeMultiple(double T, double h) {
    const double q = T / h;
    return std::abs(q - std::round(q)) <= 1e-9 * std::max(1.0, q);
}

std::string StudyRow::status() const {
    if (!reached) return "not reached";
    return ok ? std::string("ok") : "failed@" + formatDouble(failedAt);
}

std::string StudyRow::label() const {
    return item.precision == "float" ? item.integrator + " (float)" : item.integrator;
}

double wallQuantile(std::vector<double> walls, double q) {
    if (walls.empty()) return 0.0;
    std::sort(walls.begin(), walls.end());
    const double pos = q * static_cast<double>(walls.size() - 1);
    const auto i = static_cast<std::size_t>(std::floor(pos));
    const double frac = pos - static_cast<double>(i);
    return i + 1 < walls.size() ? walls[i] + frac * (walls[i + 1] - walls[i]) : walls[i];
}

void summariseWalls(StudyRow& row) {
    row.wallMin = wallQuantile(row.walls, 0.0);
    row.wallQ1 = wallQuantile(row.walls, 0.25);
    row.wallSeconds = wallQuantile(row.walls, 0.5);
    row.wallQ3 = wallQuantile(row.walls, 0.75);
}

std::vector<StudyItem> studyItems(const StudySpec& spec) {
    std::vector<StudyItem> items;
    for (const std::string& precision : spec.precisions)
        for (const std::string& name : spec.integrators) {
            if (isAdaptiveItem(spec, name)) {
                const double h0 = spec.dts.empty() ? 0.01 : *std::max_element(spec.dts.begin(), spec.dts.end());
                for (double tol : spec.tolerances) items.push_back({name, precision, h0, tol});
            } else {
                for (double dt : spec.dts) items.push_back({name, precision, dt, -1.0});
            }
        }
    return items;
}

std::vector<StudyItem> shardItems(const std::vector<StudyItem>& items, int shardIndex, int shardCount) {
    // Contiguous blocks, so that shard CSVs concatenated in shard order are the full CSV.
    const auto m = static_cast<long>(items.size());
    const long begin = m * shardIndex / shardCount, end = m * (shardIndex + 1) / shardCount;
    return {items.begin() + begin, items.begin() + end};
}

std::optional<std::string> validateStudy(const StudySpec& spec) {
    if (spec.integrators.empty()) return "no integrators given";
    for (const std::string& name : spec.integrators)
        if (!makeIntegrator(name)) return "unknown integrator " + quoteShort(name) + "; allowed: " + integratorNames();
    if (!(spec.duration > 0.0)) return "the duration must be positive";
    bool needsSteps = false;
    for (const std::string& name : spec.integrators) needsSteps |= !isAdaptiveItem(spec, name);
    if (needsSteps && spec.dts.empty()) return "no steps given (--dts)";
    for (double dt : spec.dts) {
        if (!(dt > 0.0) || dt > 1.0) return "every dt must be in (0, 1] s, got " + formatShort(dt);
        if (needsSteps && !isWholeMultiple(spec.duration, dt))
            return "the duration " + formatShort(spec.duration) + " s is not a whole multiple of dt = " +
                   formatShort(dt) + " s (every run must end exactly at T)";
    }
    for (double tol : spec.tolerances)
        if (!(tol > 0.0) || tol >= 1.0) return "every tolerance must be in (0, 1), got " + formatShort(tol);
    if (spec.repeat < 1) return "repeat must be at least 1";
    if (!(spec.timeBudget >= 0.0) || !std::isfinite(spec.timeBudget)) return "the time budget must be 0 (none) or positive";
    if (spec.precisions.empty()) return "no precision given (double, float)";
    for (const std::string& precision : spec.precisions) {
        if (precision != "double" && precision != "float")
            return "unknown precision " + quoteShort(precision) + "; allowed: double, float";
        if (std::count(spec.precisions.begin(), spec.precisions.end(), precision) > 1)
            return "precision " + quoteShort(precision) + " is listed twice";
        if (precision != "float") continue;
        if (spec.world)
            return "precision float: the float build is of one body; a scene of several bodies runs in double";
        if (!floatOnReferenceProblem(spec)) {
            // The float path of the Simulation: the front door's words (request.h), as run's and bench's.
            for (const std::string& name : spec.integrators)
                if (std::string refusal = simcore::floatPathIntegratorRefusal(name); !refusal.empty()) return refusal;
            continue;
        }
        for (const std::string& name : spec.integrators)
            if (!referenceProblemSupports(name))
                return "precision float: " + name +
                       " has no float build (only euler, midpoint, rk4, symplectic-euler, verlet, yoshida4, yoshida8)";
        if (!closedFormApplies(spec))
            return "precision float: the body reaches a wall (the float build has no contact); use a larger box";
    }
    if (spec.compensated && std::find(spec.precisions.begin(), spec.precisions.end(), "float") == spec.precisions.end())
        return "compensated summation is an option of the float build (--precision float)";
    if (spec.compensated && !floatOnReferenceProblem(spec))
        return "compensated summation is an option of the float build of spring1d (without perturbation)";
    if (spec.shardCount < 1 || spec.shardIndex < 0 || spec.shardIndex >= spec.shardCount)
        return "shard must be K/N with 1 <= K <= N";
    if (spec.reference != "auto" && spec.reference != "exact" && spec.reference != "rk4" && spec.reference != "rk45" &&
        spec.reference != "cvode-bdf")
        return "unknown reference " + quoteShort(spec.reference) + "; allowed: auto, exact, rk4, rk45, cvode-bdf";
    if (spec.reference == "exact" && !closedFormApplies(spec))
        return "this scene has no closed form (only spring1d without perturbation and without "
               "reaching a wall has one); use --reference rk4, rk45 or cvode-bdf";
    return std::nullopt;
}

bool floatOnReferenceProblem(const StudySpec& spec) { return referenceProblemRefusal(spec.params).empty(); }

std::vector<double> studyGrid(const StudySpec& spec) {
    std::vector<double> fixed;
    for (const std::string& name : spec.integrators)
        if (!isAdaptiveItem(spec, name)) fixed = spec.dts;
    if (spec.reference == "rk4" || (spec.reference == "auto" && !closedFormApplies(spec)))
        fixed.push_back(smallestFixedStep(spec) / 16.0);
    int g = std::max(1, spec.samples);
    for (; g > 1; --g) {
        const double interval = spec.duration / g;
        if (std::all_of(fixed.begin(), fixed.end(), [&](double h) { return isWholeMultiple(interval, h); })) break;
    }
    std::vector<double> grid;
    for (int k = 1; k <= g; ++k) grid.push_back(k == g ? spec.duration : spec.duration * k / g);
    return grid;
}

double studyReferenceStep(const StudySpec& spec) {
    const bool rk4 = spec.reference == "rk4" || (spec.reference == "auto" && !closedFormApplies(spec));
    return rk4 ? smallestFixedStep(spec) / 16.0 : 0.0;
}

StudyReference computeReference(const StudySpec& spec, const std::atomic<bool>* cancel) {
    StudyReference ref;
    ref.times = studyGrid(spec);
    const bool exact = spec.reference == "exact" || (spec.reference == "auto" && closedFormApplies(spec));
    if (exact) {
        ref.description = "closed form (spring1d, analytic.h)";
        Eigen::Matrix3Xd x, v;
        for (double t : ref.times) {
            spring1dExact(spec.params, t, x, v);
            ref.positions.push_back(x);
        }
        ref.estimatedError = 1e-15;  // round-off of the formula
        return ref;
    }
    IntegratorOptions options = spec.options;
    options.stepDoubling = false;
    options.fixedStep = false;
    // Cancelled part-way: no positions, nothing to compare with (a trajectory cut short has
    // fewer samples than the grid, none at all when cancelled before the first).
    auto cancelledReference = [&] {
        StudyReference none;
        none.cancelled = true;
        none.times = ref.times;
        return none;
    };
    // An adaptive reference at a tight tolerance, its error estimated against a run at a
    // looser one: rk45 at 1e-12 (1e-10), or the stiff-capable cvode-bdf at 1e-11 (1e-9; BDF's
    // cost grows gently with the tolerance and is not limited by the stiff modes' stability,
    // as rk4's and rk45's are).
    auto adaptiveReference = [&](const std::string& method, const std::string& why) {
        const bool bdf = method == "cvode-bdf";
        const double tight = bdf ? 1e-11 : 1e-12, loose = bdf ? 1e-9 : 1e-10;
        IntegratorOptions fineOptions = options;
        fineOptions.atol = fineOptions.rtol = tight;
        fineOptions.minStep = 1e-14;
        Trajectory fine = runTrajectory(spec, method, smallestFixedStep(spec), fineOptions, ref.times, cancel);
        IntegratorOptions coarse = fineOptions;
        coarse.atol = coarse.rtol = loose;
        Trajectory check = runTrajectory(spec, method, smallestFixedStep(spec), coarse, ref.times, cancel);
        if (fine.cancelled || check.cancelled) return cancelledReference();
        if (fine.failed) throw std::runtime_error("the " + method + " reference failed: " + fine.failure + why);
        ref.description = method + " at atol = rtol = " + formatShort(tight) + " (" + std::to_string(fine.steps) + " steps)" + why;
        ref.positions = fine.positions;
        ref.estimatedError = check.failed || check.positions.size() != fine.positions.size()
                                 ? std::nan("")
                                 : rmsDistance(check.positions.back(), fine.positions.back());
        return ref;
    };
    if (spec.reference == "rk45" || spec.reference == "cvode-bdf") return adaptiveReference(spec.reference, "");
    const double h = smallestFixedStep(spec) / 16.0;
    Trajectory fine = runTrajectory(spec, "rk4", h, options, ref.times, cancel);
    if (fine.cancelled) return cancelledReference();
    if (fine.failed && spec.reference == "auto")
        // Stiff: rk4 16x below the smallest studied step is still unstable. The most accurate
        // reference left is the stiff solver at a tight tolerance.
        return adaptiveReference("cvode-bdf", ", because rk4 at dt = " + formatShort(h) + " s failed (" + fine.failure + ")");
    if (fine.failed)
        throw std::runtime_error("the rk4 reference at dt = " + formatShort(h) + " s failed: " + fine.failure);
    Trajectory check = runTrajectory(spec, "rk4", 2.0 * h, options, ref.times, cancel);
    if (check.cancelled) return cancelledReference();
    ref.description = "rk4 at dt = " + formatShort(h) + " s (16x below the smallest studied step)";
    ref.positions = fine.positions;
    // The difference to the run at 2h bounds the error for any convergent method; for a
    // smooth (collision-free) run the error is about 1/15 of it (order 4).
    ref.estimatedError = check.failed || check.positions.size() != fine.positions.size()
                             ? std::nan("")
                             : rmsDistance(check.positions.back(), fine.positions.back());
    return ref;
}

namespace {
// A finished run's errors against the reference on the grid: the largest, the RMS over the grid
// and the final one (docs/numerics.md, "How errors are measured").
void measureErrors(const Trajectory& run, const StudyReference& reference, StudyRow& row) {
    double sumSquares = 0.0;
    for (std::size_t k = 0; k < run.positions.size(); ++k) {
        const double e = rmsDistance(run.positions[k], reference.positions[k]);
        row.errorMax = std::max(row.errorMax, e);
        sumSquares += e * e;
    }
    row.errorRms = std::sqrt(sumSquares / static_cast<double>(std::max<std::size_t>(1, run.positions.size())));
    row.errorFinal = rmsDistance(run.positions.back(), reference.positions.back());
}
}  // namespace

StudyRow runStudyItem(const StudySpec& spec, const StudyItem& item, const StudyReference& reference,
                      const std::atomic<bool>* cancel) {
    IntegratorOptions options = spec.options;
    options.stepDoubling = false;  // never pay for estimates in a timing
    if (item.tolerance > 0.0) options.atol = options.rtol = item.tolerance;
    StudyRow row;
    row.item = item;
    if (reference.cancelled || reference.positions.size() != reference.times.size()) {
        row.ok = false;  // no reference to measure against (it was cancelled)
        row.failure = "cancelled";
        return row;
    }
    // A run over the budget is stopped there; its time (at least the budget) is kept. The point
    // is not reached when most of its runs are (the median is over the budget): one run slowed
    // by a neighbour on a shared machine does not stop a curve.
    Trajectory run, completed;
    bool haveCompleted = false;
    int over = 0;
    for (int r = 0; r < spec.repeat; ++r) {
        if (item.precision == "float" && !floatOnReferenceProblem(spec)) {
            run = runFloatTrajectory(spec.params, item.integrator, item.dt, reference.times, cancel, spec.timeBudget);
        } else if (item.precision == "float") {
            ReferenceProblemRun f = runReferenceProblem(spec.params, item.integrator, item.dt, reference.times, "float",
                                                        spec.compensated, cancel, spec.timeBudget);
            run = Trajectory{};
            run.failed = f.failed, run.failedAt = f.failedAt, run.cancelled = f.cancelled, run.overBudget = f.overBudget;
            run.steps = f.steps, run.evaluations = f.evaluations, run.wallSeconds = f.wallSeconds, run.maxDrift = f.maxDrift;
            if (f.failed) run.failure = "the float state is no longer finite";
            run.positions = std::move(f.positions);
        } else {
            run = runTrajectory(spec, item.integrator, item.dt, options, reference.times, cancel, spec.timeBudget);
        }
        row.walls.push_back(run.wallSeconds);
        if (run.cancelled && !run.overBudget) {
            completed = std::move(run);
            haveCompleted = true;
            break;
        }
        if (run.overBudget) {
            if (2 * ++over > spec.repeat) break;
            continue;
        }
        completed = std::move(run);
        haveCompleted = true;
        if (completed.failed) break;
    }
    if (!haveCompleted || 2 * over > spec.repeat) run.overBudget = true;
    else run = std::move(completed);
    summariseWalls(row);
    row.steps = run.steps;
    row.forceEvaluations = run.evaluations;
    row.dt = item.tolerance > 0.0 ? spec.duration / static_cast<double>(std::max(1L, run.steps)) : item.dt;
    row.errorEnergy = run.maxDrift;
    if (run.overBudget) {
        // Not reached: no error, and no timing of a run that was cut short.
        row.ok = row.reached = false;
        row.walls.clear();
        summariseWalls(row);
        row.dt = item.tolerance > 0.0 ? 0.0 : item.dt;
        row.steps = 0;
        row.forceEvaluations = 0;
        row.failure = "over the time budget of " + formatShort(spec.timeBudget) + " s";
        return row;
    }
    if (run.failed) {
        row.ok = false;
        row.failedAt = run.failedAt;
        row.failure = run.failure;
        return row;
    }
    if (run.cancelled) {
        row.ok = false;
        row.failure = "cancelled";
        return row;
    }
    measureErrors(run, reference, row);
    return row;
}

namespace {

// The costlier the point, the larger: 1/dt for fixed steps, 1/tolerance for adaptive runs.
double itemCost(const StudyItem& item) { return item.tolerance > 0.0 ? 1.0 / item.tolerance : 1.0 / item.dt; }

// A point of the same curve at least as costly as one that was not reached is not reached
// either (the curve stops there): recorded without running it.
std::optional<StudyRow> skippedByBudget(const StudySpec& spec, const StudyItem& item, const std::vector<StudyRow>& done) {
    for (const StudyRow& r : done)
        if (!r.reached && r.item.integrator == item.integrator && r.item.precision == item.precision &&
            itemCost(item) >= itemCost(r.item)) {
            StudyRow row;
            row.item = item;
            row.dt = item.tolerance > 0.0 ? 0.0 : item.dt;
            row.ok = row.reached = false;
            row.failure = "over the time budget of " + formatShort(spec.timeBudget) + " s (a cheaper point was)";
            return row;
        }
    return std::nullopt;
}

}  // namespace

StudyRow runStudyPoint(const StudySpec& spec, const StudyItem& item, const StudyReference& reference,
                       const std::vector<StudyRow>& done, const std::atomic<bool>* cancel) {
    if (auto skipped = skippedByBudget(spec, item, done)) return *skipped;
    return runStudyItem(spec, item, reference, cancel);
}

StudyResult runStudy(const StudySpec& spec, const StudyProgressFn& progress, const std::atomic<bool>* cancel) {
    StudyResult result;
    const std::vector<StudyItem> items = shardItems(studyItems(spec), spec.shardIndex, spec.shardCount);
    const int total = static_cast<int>(items.size()) + 1;
    if (progress) progress({0, total, "reference"});
    result.reference = computeReference(spec, cancel);
    if (result.reference.cancelled) {
        result.cancelled = true;
        if (progress) progress({total, total, "cancelled"});
        return result;
    }
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (cancel && cancel->load()) {
            result.cancelled = true;
            break;
        }
        const StudyItem& item = items[i];
        if (progress)
            progress({static_cast<int>(i) + 1, total,
                      item.integrator + (item.tolerance > 0 ? " tol=" + formatShort(item.tolerance)
                                                            : " dt=" + formatShort(item.dt))});
        result.rows.push_back(runStudyPoint(spec, item, result.reference, result.rows, cancel));
    }
    if (cancel && cancel->load()) result.cancelled = true;
    if (progress) progress({total, total, result.cancelled ? "cancelled" : "done"});
    return result;
}

std::vector<OrderFit> fitOrders(const std::vector<StudyRow>& rows, double referenceError) {
    std::vector<OrderFit> fits;
    std::vector<std::string> names;
    for (const StudyRow& r : rows)
        if (std::find(names.begin(), names.end(), r.label()) == names.end()) names.push_back(r.label());
    const double floor = std::isfinite(referenceError) ? 10.0 * referenceError : 0.0;
    // The asymptotic range: the three smallest steps whose error is resolved.
    auto fit = [&](const std::string& name, double StudyRow::*measure) -> std::pair<double, int> {
        std::vector<std::pair<double, double>> points;
        for (const StudyRow& r : rows) {
            const double e = r.*measure;
            if (r.label() == name && r.ok && e > floor && e > 0 && r.dt > 0) points.emplace_back(r.dt, e);
        }
        std::sort(points.begin(), points.end());
        if (points.size() > 3) points.resize(3);
        return {logLogSlope(points), static_cast<int>(points.size())};
    };
    for (const std::string& name : names) {
        OrderFit f;
        f.integrator = name;
        std::tie(f.order, f.points) = fit(name, &StudyRow::errorMax);
        std::tie(f.orderFinal, f.pointsFinal) = fit(name, &StudyRow::errorFinal);
        std::tie(f.orderRms, f.pointsRms) = fit(name, &StudyRow::errorRms);
        fits.push_back(f);
    }
    return fits;
}

namespace {

// The integrator of a label ("rk4 (float)" -> "rk4").
std::string integratorOf(const std::string& label) { return label.substr(0, label.find(' ')); }

// Where a curve (points in order of refinement: error falling) first reaches `level`: the
// cost log-log interpolated between the two points around it; nullopt if it never does.
std::optional<double> costAt(const std::vector<std::pair<double, double>>& curve, double level) {
    for (std::size_t i = 0; i < curve.size(); ++i) {
        if (curve[i].second > level) continue;
        if (i == 0) return curve[0].first;  // already there at its cheapest point
        const auto [c0, e0] = curve[i - 1];
        const auto [c1, e1] = curve[i];
        const double u = (std::log(e0) - std::log(level)) / (std::log(e0) - std::log(e1));
        return std::exp(std::log(c0) + u * (std::log(c1) - std::log(c0)));
    }
    return std::nullopt;
}

}  // namespace

std::vector<FamilyBest> fastestByFamily(const std::vector<StudyRow>& rows) {
    // Each curve in order of refinement (dt falling), ok points only.
    std::map<std::string, std::vector<const StudyRow*>> curves;
    double lo = 1e300, hi = 0.0;
    for (const StudyRow& r : rows)
        if (r.ok && r.errorMax > 0 && r.wallSeconds > 0) {
            curves[r.label()].push_back(&r);
            lo = std::min(lo, r.errorMax), hi = std::max(hi, r.errorMax);
        }
    std::vector<FamilyBest> best;
    if (curves.empty()) return best;
    for (auto& [label, points] : curves)
        std::sort(points.begin(), points.end(), [](const StudyRow* a, const StudyRow* b) { return a->dt > b->dt; });
    for (double d = std::floor(std::log10(hi)); d >= std::ceil(std::log10(lo)); d -= 1.0) {
        const double level = std::pow(10.0, d);
        for (std::string_view family : integratorFamilies()) {
            FamilyBest b;
            for (const auto& [label, points] : curves) {
                if (integratorFamily(integratorOf(label)) != family) continue;
                std::vector<std::pair<double, double>> wall, evals;
                for (const StudyRow* r : points) {
                    wall.emplace_back(r->wallSeconds, r->errorMax);
                    evals.emplace_back(static_cast<double>(r->forceEvaluations), r->errorMax);
                }
                const auto cost = costAt(wall, level);
                if (cost && (b.integrator.empty() || *cost < b.wallSeconds)) {
                    b.integrator = label;
                    b.wallSeconds = *cost;
                    b.forceEvaluations = costAt(evals, level).value_or(0.0);
                }
            }
            if (b.integrator.empty()) continue;
            b.family = std::string(family);
            b.error = level;
            best.push_back(b);
        }
    }
    return best;
}

double logLogSlope(const std::vector<std::pair<double, double>>& points) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (auto [x0, y0] : points) {
        const double x = std::log(x0), y = std::log(y0);
        sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
    }
    const double den = n * sxx - sx * sx;
    return n >= 2 && std::abs(den) > 1e-300 ? (n * sxy - sx * sy) / den : std::nan("");
}

std::string studyCsvHeader() {
    return "integrator,family,precision,dt,steps,force_evals,repeats,wall_min,wall_q1,wall_median,wall_q3,error_final,"
           "error_max,error_rms,error_energy,status\n";
}

std::string studyCsvRow(const StudyRow& row) {
    std::string line = row.item.integrator;
    line += ',' + std::string(integratorFamily(row.item.integrator));
    line += ',' + row.item.precision;
    line += ',' + formatDouble(row.dt);
    line += ',' + std::to_string(row.steps);
    line += ',' + std::to_string(row.forceEvaluations);
    line += ',' + std::to_string(row.walls.size());
    if (row.walls.empty()) {
        line += ",,,,";
    } else {
        for (double w : {row.wallMin, row.wallQ1, row.wallSeconds, row.wallQ3}) line += ',' + formatDouble(w);
    }
    if (row.ok) {
        for (double e : {row.errorFinal, row.errorMax, row.errorRms, row.errorEnergy}) line += ',' + formatDouble(e);
    } else {
        line += ",,,,";
    }
    return line + ',' + row.status() + '\n';
}

std::string studyTimingsCsvHeader() { return "integrator,precision,dt,repeat,wall_seconds\n"; }

std::string studyTimingsCsvRows(const StudyRow& row) {
    std::string out;
    for (std::size_t r = 0; r < row.walls.size(); ++r)
        out += row.item.integrator + ',' + row.item.precision + ',' + formatDouble(row.dt) + ',' + std::to_string(r + 1) +
               ',' + formatDouble(row.walls[r]) + '\n';
    return out;
}

std::optional<std::vector<StudyRow>> parseStudyCsv(const std::string& text, std::string* error) {
    std::vector<StudyRow> rows;
    std::istringstream in(text);
    std::string line;
    int number = 0;
    auto fail = [&](const std::string& what) -> std::optional<std::vector<StudyRow>> {
        if (error) *error = "line " + std::to_string(number) + ": " + what;
        return std::nullopt;
    };
    while (std::getline(in, line)) {
        ++number;
        if (line.empty() || line.rfind("integrator,", 0) == 0) continue;
        std::vector<std::string> f;
        std::stringstream ss(line);
        std::string field;
        while (std::getline(ss, field, ',')) f.push_back(field);
        if (!line.empty() && line.back() == ',') f.emplace_back();
        const bool legacy = f.size() == 9;
        if (legacy) {
            // Written before issue 28: integrator,dt,steps,force_evals,wall_seconds (the median),
            // error_final,error_max,error_energy,status. Read as one timing, no error_rms.
            f = {f[0], std::string(integratorFamily(f[0])), "double", f[1], f[2], f[3], "1", f[4], f[4], f[4], f[4],
                 f[5], f[6], "", f[7], f[8]};
        }
        if (f.size() != 16) return fail("expected 16 fields (or the 9 of an older study), got " + std::to_string(f.size()));
        StudyRow r;
        r.item.integrator = f[0];
        if (f[2] != "double" && f[2] != "float") return fail("precision must be double or float");
        r.item.precision = f[2];
        const auto dt = parseNumber(f[3]), steps = parseNumber(f[4]), evals = parseNumber(f[5]), repeats = parseNumber(f[6]);
        if (!dt || !steps || !evals || !repeats) return fail("bad number");
        r.dt = r.item.dt = *dt;
        r.steps = static_cast<long>(*steps);
        r.forceEvaluations = static_cast<std::uint64_t>(*evals);
        if (*repeats > 0) {
            // The raw times are in the timings CSV; the summary keeps the four statistics.
            double* targets[4] = {&r.wallMin, &r.wallQ1, &r.wallSeconds, &r.wallQ3};
            for (int k = 0; k < 4; ++k) {
                const auto w = parseNumber(f[7 + static_cast<std::size_t>(k)]);
                if (!w) return fail("bad wall time");
                *targets[k] = *w;
            }
        }
        const std::string& status = f[15];
        if (status == "ok") {
            double* targets[4] = {&r.errorFinal, &r.errorMax, &r.errorRms, &r.errorEnergy};
            for (int k = 0; k < 4; ++k) {
                if (legacy && k == 2) {
                    r.errorRms = std::nan("");  // not measured then
                    continue;
                }
                const auto e = parseNumber(f[11 + static_cast<std::size_t>(k)]);
                if (!e) return fail("bad error value");
                *targets[k] = *e;
            }
        } else if (status.rfind("failed@", 0) == 0) {
            const auto t = parseNumber(status.substr(7));
            if (!t) return fail("bad failure time");
            r.ok = false;
            r.failedAt = *t;
        } else if (status == "not reached") {
            r.ok = r.reached = false;
        } else {
            return fail("status must be ok, failed@<time> or not reached");
        }
        rows.push_back(r);
    }
    return rows;
}

// --- SVG ----------------------------------------------------------------------------------

namespace {

struct Range {
    double lo = 0.0, hi = 0.0;  // decades (log10)
};

Range decades(const std::vector<double>& values) {
    double lo = 1e300, hi = -1e300;
    for (double v : values)
        if (v > 0.0 && std::isfinite(v)) lo = std::min(lo, std::log10(v)), hi = std::max(hi, std::log10(v));
    if (lo > hi) return {0.0, 1.0};
    Range r{std::floor(lo), std::ceil(hi)};
    if (r.hi <= r.lo) r.hi = r.lo + 1.0;
    return r;
}

}  // namespace

namespace {

bool drawable(std::pair<double, double> pt) {
    return pt.first > 0.0 && pt.second > 0.0 && std::isfinite(pt.first) && std::isfinite(pt.second);
}

// One panel's place on the page [px] and its decades: where a value pair is drawn.
struct LogPanel {
    int x0 = 0, y0 = 0, w = 0, h = 0;
    Range xr, yr;
    double px(double v) const { return x0 + (std::log10(v) - xr.lo) / (xr.hi - xr.lo) * w; }
    double py(double v) const { return y0 + h - (std::log10(v) - yr.lo) / (yr.hi - yr.lo) * h; }
};

// The panel's frame, its grid at every decade with the decades' labels, and the axis labels.
void drawPanelFrame(std::ostringstream& svg, const SvgPanel& panel, const LogPanel& at) {
    const int x0 = at.x0, y0 = at.y0, panelW = at.w, panelH = at.h;
    const Range xr = at.xr, yr = at.yr;
    svg << "<rect x=\"" << x0 << "\" y=\"" << y0 << "\" width=\"" << panelW << "\" height=\"" << panelH
        << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (double d = xr.lo; d <= xr.hi + 1e-9; d += 1.0) {
        const double x = x0 + (d - xr.lo) / (xr.hi - xr.lo) * panelW;
        svg << "<line x1=\"" << x << "\" y1=\"" << y0 << "\" x2=\"" << x << "\" y2=\"" << y0 + panelH
            << "\" stroke=\"#ddd\"/><text x=\"" << x << "\" y=\"" << y0 + panelH + 16
            << "\" text-anchor=\"middle\">1e" << static_cast<int>(d) << "</text>\n";
    }
    for (double d = yr.lo; d <= yr.hi + 1e-9; d += 1.0) {
        const double y = y0 + panelH - (d - yr.lo) / (yr.hi - yr.lo) * panelH;
        svg << "<line x1=\"" << x0 << "\" y1=\"" << y << "\" x2=\"" << x0 + panelW << "\" y2=\"" << y
            << "\" stroke=\"#ddd\"/><text x=\"" << x0 - 6 << "\" y=\"" << y + 4
            << "\" text-anchor=\"end\">1e" << static_cast<int>(d) << "</text>\n";
    }
    svg << "<text x=\"" << x0 + panelW / 2 << "\" y=\"" << y0 + panelH + 36 << "\" text-anchor=\"middle\">"
        << xmlEscaped(panel.xLabel) << "</text>\n";
    svg << "<text transform=\"translate(" << x0 - 48 << "," << y0 + panelH / 2
        << ") rotate(-90)\" text-anchor=\"middle\">" << xmlEscaped(panel.yLabel) << "</text>\n";
}

// The band: along the low edge, back along the high edge (points with a band only).
void drawBand(std::ostringstream& svg, const SvgSeries& s, const LogPanel& at) {
    if (s.bandLow.empty() || s.bandLow.size() != s.points.size() || s.bandHigh.size() != s.points.size()) return;
    std::vector<std::pair<double, double>> low, high;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
        const double y = s.points[i].second;
        if (drawable({s.bandLow[i], y}) && drawable({s.bandHigh[i], y}))
            low.emplace_back(s.bandLow[i], y), high.emplace_back(s.bandHigh[i], y);
    }
    if (low.empty()) return;
    svg << "<polygon class=\"band\" fill=\"" << s.colour << "\" fill-opacity=\"0.18\" stroke=\"" << s.colour
        << "\" stroke-opacity=\"0.35\" stroke-width=\"0.8\" points=\"";
    for (auto [x, y] : low) svg << at.px(x) << ',' << at.py(y) << ' ';
    for (auto it = high.rbegin(); it != high.rend(); ++it) svg << at.px(it->first) << ',' << at.py(it->second) << ' ';
    svg << "\"/>\n";
}

// A series' drawable points `pts`: the line, a dot (and its label) at each, rings round the
// fastest.
void drawLine(std::ostringstream& svg, const SvgSeries& s, const std::vector<std::pair<double, double>>& pts,
              const LogPanel& at) {
    svg << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"1.5\"";
    if (!s.dash.empty()) svg << " stroke-dasharray=\"" << s.dash << "\"";
    svg << " points=\"";
    for (auto [x, y] : pts) svg << at.px(x) << ',' << at.py(y) << ' ';
    svg << "\"/>\n";
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const auto [x, y] = pts[i];
        svg << "<circle cx=\"" << at.px(x) << "\" cy=\"" << at.py(y) << "\" r=\"3\" fill=\"" << s.colour << "\"/>\n";
        if (i < s.labels.size() && !s.labels[i].empty())
            svg << "<text x=\"" << at.px(x) + 5 << "\" y=\"" << at.py(y) - 5 << "\" font-size=\"10\" fill=\"" << s.colour
                << "\">" << xmlEscaped(s.labels[i]) << "</text>\n";
    }
    for (auto pt : s.rings)
        if (drawable(pt))
            svg << "<circle class=\"fastest\" cx=\"" << at.px(pt.first) << "\" cy=\"" << at.py(pt.second)
                << "\" r=\"7\" fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"2\"/>\n";
}

// The legend from (lx, top): a line in each series' style and its name.
void drawLegend(std::ostringstream& svg, const std::vector<const SvgSeries*>& legend, int lx, int top) {
    for (std::size_t i = 0; i < legend.size(); ++i) {
        const double y = top + 15 + 20.0 * static_cast<double>(i);
        svg << "<line x1=\"" << lx << "\" y1=\"" << y << "\" x2=\"" << lx + 20 << "\" y2=\"" << y << "\" stroke=\""
            << legend[i]->colour << "\" stroke-width=\"2\"";
        if (!legend[i]->dash.empty()) svg << " stroke-dasharray=\"" << legend[i]->dash << "\"";
        svg << "/><text x=\"" << lx + 26 << "\" y=\"" << y + 4 << "\">" << xmlEscaped(legend[i]->name) << "</text>\n";
    }
}

}  // namespace

std::string logLogSvg(const std::vector<SvgPanel>& panels, const std::string& title) {
    const int panelW = 380, panelH = 320, left = 70, top = 50, gap = 90, bottom = 60;
    const int count = static_cast<int>(panels.size());
    std::size_t longest = 0;  // the legend's width follows its longest name (~7 px a character)
    for (const SvgPanel& panel : panels)
        for (const SvgSeries& s : panel.series) longest = std::max(longest, s.name.size());
    const int legendW = std::max(160, 7 * static_cast<int>(longest) + 45);
    const int width = left + count * panelW + (count - 1) * gap + legendW, height = top + panelH + bottom + 20;
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
        << "<text x=\"" << left << "\" y=\"24\" font-size=\"15\">" << xmlEscaped(title) << "</text>\n";
    // The legend: every series name once, in order of first appearance, with its style.
    std::vector<const SvgSeries*> legend;
    for (int p = 0; p < count; ++p) {
        const SvgPanel& panel = panels[static_cast<std::size_t>(p)];
        std::vector<double> xs, ys;
        for (const SvgSeries& s : panel.series) {
            for (auto pt : s.points)
                if (drawable(pt)) xs.push_back(pt.first), ys.push_back(pt.second);
            for (double x : s.bandLow) xs.push_back(x);
            for (double x : s.bandHigh) xs.push_back(x);
        }
        const LogPanel at{left + p * (panelW + gap), top, panelW, panelH, decades(xs), decades(ys)};
        drawPanelFrame(svg, panel, at);
        for (const SvgSeries& s : panel.series) {
            std::vector<std::pair<double, double>> pts;
            for (auto pt : s.points)
                if (drawable(pt)) pts.push_back(pt);
            if (pts.empty()) continue;
            if (s.inLegend &&
                std::none_of(legend.begin(), legend.end(), [&](const SvgSeries* l) { return l->name == s.name; }))
                legend.push_back(&s);
            drawBand(svg, s, at);
            drawLine(svg, s, pts, at);
        }
    }
    drawLegend(svg, legend, left + count * panelW + (count - 1) * gap + 15, top);
    svg << "</svg>\n";
    return svg.str();
}

double roundoffFloor(const std::string& precision, double scale, double duration, double h) {
    const double eps = precision == "float" ? 0x1p-24 : 0x1p-53;
    return eps * scale * std::sqrt(duration / h);
}

double referenceScale(const StudyReference& reference) {
    double scale = 0.0;
    for (const Eigen::Matrix3Xd& x : reference.positions) scale = std::max(scale, x.cwiseAbs().maxCoeff());
    return scale;
}

std::string studySvg(const std::vector<StudyRow>& rows, const std::string& title, double roundoffScale,
                     double duration) {
    std::vector<std::string> names;
    for (const StudyRow& r : rows)
        if (std::find(names.begin(), names.end(), r.label()) == names.end()) names.push_back(r.label());
    struct Axis {
        const char* label;
        std::function<double(const StudyRow&)> x;
    };
    const Axis axes[3] = {
        {"wall time [s] (median, band q1-q3; stepping only)", [](const StudyRow& r) { return r.wallSeconds; }},
        {"force evaluations", [](const StudyRow& r) { return static_cast<double>(r.forceEvaluations); }},
        {"dt [s] (mean step for adaptive rk45)", [](const StudyRow& r) { return r.dt; }},
    };
    const std::vector<FamilyBest> best = fastestByFamily(rows);
    std::vector<SvgPanel> panels;
    for (int a = 0; a < 3; ++a) {
        const Axis& axis = axes[a];
        SvgPanel panel{axis.label, "error_max: largest RMS position error [m]", {}};
        for (const std::string& name : names) {
            // Joined in order of dt (timings are noisy; the line follows the refinement).
            std::vector<const StudyRow*> sorted;
            for (const StudyRow& r : rows)
                if (r.ok && r.label() == name) sorted.push_back(&r);
            std::sort(sorted.begin(), sorted.end(), [](const StudyRow* p, const StudyRow* q) { return p->dt < q->dt; });
            const std::string integrator = integratorOf(name);
            const std::string family(integratorFamily(integrator));
            SvgSeries series{name + (family.empty() ? "" : " [" + family + "]"), studyColour(integrator),
                             name == integrator ? "" : "6,3", {}, {}};
            for (const StudyRow* r : sorted) {
                series.points.emplace_back(axis.x(*r), r->errorMax);
                if (a == 0) series.bandLow.push_back(r->wallQ1), series.bandHigh.push_back(r->wallQ3);
            }
            if (a < 2)
                for (const FamilyBest& b : best)
                    if (b.integrator == name) series.rings.emplace_back(a == 0 ? b.wallSeconds : b.forceEvaluations, b.error);
            panel.series.push_back(std::move(series));
        }
        if (a == 2 && roundoffScale > 0.0 && duration > 0.0) {
            // The predicted floor of each precision present, over the panel's steps.
            std::vector<std::string> precisions;
            double hMin = 1e300, hMax = 0.0;
            for (const StudyRow& r : rows) {
                if (std::find(precisions.begin(), precisions.end(), r.item.precision) == precisions.end())
                    precisions.push_back(r.item.precision);
                if (r.ok && r.dt > 0) hMin = std::min(hMin, r.dt), hMax = std::max(hMax, r.dt);
            }
            if (hMax > 0.0)
                for (const std::string& precision : precisions) {
                    SvgSeries floor{"round-off floor, " + precision + ": eps X sqrt(T/h)", "#555555",
                                    precision == "float" ? "2,3" : "1,4", {}, {}};
                    for (double h : {hMin, hMax}) floor.points.emplace_back(h, roundoffFloor(precision, roundoffScale, duration, h));
                    panel.series.push_back(std::move(floor));
                }
        }
        panels.push_back(std::move(panel));
    }
    std::string svg = logLogSvg(panels, title);
    if (!best.empty()) {
        // A note under the panels: what the rings mean.
        const std::string note = "<text x=\"70\" y=\"";
        const auto end = svg.rfind("</svg>");
        const auto heightPos = svg.find("height=\"") + 8;
        const int height = std::stoi(svg.substr(heightPos));
        svg.insert(end, note + std::to_string(height - 8) +
                            "\" font-size=\"11\">rings: the fastest method of each family at each decade of error "
                            "(wall time and force evaluations)</text>\n");
    }
    return svg;
}

const char* studyColour(std::string_view integrator) {
    // Shades of the family's hue, darkest first (familyColour).
    static const std::map<std::string_view, const char*> colours = {
        {"euler", "#08306b"},       {"midpoint", "#2171b5"},      {"rk4", "#6baed6"},
        {"symplectic-euler", "#67000d"}, {"verlet", "#cb181d"},   {"yoshida4", "#ef6548"},
        {"yoshida8", "#fc9272"},    {"rk45", "#238b45"},          {"implicit-euler", "#6a51a3"},
        {"cvode-bdf", "#8c510a"},   {"cvode-adams", "#d8b365"},   {"xpbd", "#525252"}};
    auto it = colours.find(integrator);
    return it == colours.end() ? "#7f7f7f" : it->second;
}

const char* familyColour(std::string_view family) {
    static const std::map<std::string_view, const char*> colours = {
        {"explicit-rk", "#08306b"}, {"symplectic", "#67000d"}, {"implicit", "#6a51a3"},
        {"adaptive", "#238b45"},    {"production", "#8c510a"}, {"constraint", "#525252"}};
    auto it = colours.find(family);
    return it == colours.end() ? "#7f7f7f" : it->second;
}

}  // namespace simlab
