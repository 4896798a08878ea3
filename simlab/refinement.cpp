#include "simlab/refinement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "simcore/body.h"
#include "simcore/forces.h"
#include "simcore/integrator_table.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/output.h"
#include "simlab/stability.h"

namespace simlab {

using simcore::quoteShort;
using simcore::Body;
using simcore::IntegratorOptions;
using simcore::Param;
using simcore::ParameterSet;
using simcore::SceneKind;
using simcore::Simulation;
using simcore::World;
using simcore::WorldBodySpec;
using simcore::WorldSpec;
using simcore::SpringFamily;
using simcore::SpringSet;
using simcore::Surface;
using simcore::Topology;
using simcore::buildBody;
using simcore::enclosedVolume;
using simcore::integratorNames;
using simcore::layerSlot;
using simcore::makeIntegrator;
using simcore::paramSpec;
using simcore::validateShape;

namespace {

// The observables at one grid time, defined at every resolution of the same body: per body
// (one, or every body of a world).
struct Sample {
    // enclosed volume per layer [inner, outer]: area [m^2] 2D, [m^3] 3D
    std::vector<std::array<double, 2>> volume;
    std::vector<Eigen::Vector3d> com;  // mass-weighted centre of mass [m]
};
using Samples = std::vector<Sample>;

void addBody(Sample& s, const Topology& topo, const Eigen::Matrix3Xd& x, const Eigen::VectorXd& m) {
    // The volumes from the surfaces themselves: Diagnostics holds them only when gas is on.
    std::array<double, 2> volume{};
    for (const Surface& surface : topo.surfaces)
        volume[static_cast<std::size_t>(layerSlot(surface.layer))] = enclosedVolume(surface, x.data(), topo.dimension);
    s.volume.push_back(volume);
    s.com.push_back(x * m / m.sum());
}

Sample sampleOf(const Simulation& sim) {
    Sample s;
    addBody(s, sim.topology(), sim.positions(), sim.body().mass);
    return s;
}

Sample sampleOf(const World& world) {
    Sample s;
    for (int k = 0; k < world.bodyCount(); ++k)
        addBody(s, world.body(k).topology, world.positions(k), world.body(k).mass);
    return s;
}

struct Errors {
    double volume = 0.0;  // [1]
    double com = 0.0;     // [m]
};

// Largest errors of `run` against `ref` over every body; run[k] is at the grid time of ref[index[k]].
Errors compare(const Samples& run, const Samples& ref, const std::vector<std::size_t>& index) {
    Errors e;
    for (std::size_t k = 0; k < run.size() && k < index.size(); ++k) {
        const Sample& a = run[k];
        const Sample& r = ref[index[k]];
        for (std::size_t b = 0; b < a.volume.size() && b < r.volume.size(); ++b) {
            for (std::size_t layer = 0; layer < 2; ++layer)
                if (r.volume[b][layer] != 0.0)
                    e.volume = std::max(e.volume, std::abs(a.volume[b][layer] - r.volume[b][layer]) / std::abs(r.volume[b][layer]));
            e.com = std::max(e.com, (a.com[b] - r.com[b]).norm());
        }
    }
    return e;
}

std::vector<std::size_t> identity(std::size_t n) {
    std::vector<std::size_t> index(n);
    for (std::size_t k = 0; k < n; ++k) index[k] = k;
    return index;
}

bool isAdaptive(const RefinementSpec& spec) {
    auto method = makeIntegrator(spec.integrator);
    return method && method->adaptive() && !spec.options.fixedStep;
}

std::optional<std::string> setLevel(ParameterSet& p, const std::string& key, int value) {
    if (auto error = p.set(key, value)) return error;
    if (key == "slices")
        if (auto error = p.set(Param::Stacks, value / 2)) return "slices=" + std::to_string(value) + " gives " + *error;
    return validateShape(p);
}

std::vector<int> sortedLevels(const RefinementSpec& spec) {
    std::vector<int> v = spec.values;
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

std::vector<double> outputGrid(const RefinementSpec& spec) {
    std::vector<double> grid;
    const long n = std::lround(spec.duration / spec.interval);
    for (long k = 1; k <= n; ++k) grid.push_back(k == n ? spec.duration : spec.interval * static_cast<double>(k));
    return grid;
}

std::string shortNumber(double v, int digits = 6) {
    std::ostringstream os;
    os.precision(digits);
    os << v;
    return os.str();
}

struct LevelRun {
    SampledRun run;
    Samples samples;
};

LevelRun runLevel(const RefinementSpec& spec, int value, double dt, double tolerance, const std::vector<double>& grid,
                  const std::atomic<bool>* cancel) {
    IntegratorOptions options = spec.options;
    options.stepDoubling = false;  // never pay for estimates in a timing
    if (tolerance > 0.0) options.atol = options.rtol = tolerance;
    LevelRun out;
    out.samples.reserve(grid.size());
    if (spec.world)
        out.run = runSampled(refinementWorld(spec, value), spec.integrator, dt, options, grid,
                             [&](const World& world) { out.samples.push_back(sampleOf(world)); }, cancel);
    else
        out.run = runSampled(refinementLevel(spec, value), spec.integrator, dt, options, grid,
                             [&](const Simulation& sim) { out.samples.push_back(sampleOf(sim)); }, cancel);
    return out;
}

// The stability advice at the finest level for `dt`: the body's (stabilityAdvice of its
// simulation) or the whole world's (its spectrum).
std::optional<StabilityAdvice> finestAdvice(const RefinementSpec& spec, int finestValue, double dt) {
    if (spec.world) {
        WorldSpec finest = refinementWorld(spec, finestValue);
        for (WorldBodySpec& body : finest.bodies) body.params.set(Param::Dt, dt);
        return stabilityAdvice(stabilityModes(finest), spec.integrator, dt);
    }
    ParameterSet finest = refinementLevel(spec, finestValue);
    finest.set(Param::Dt, dt);
    const Simulation sim(finest, spec.integrator);
    return stabilityAdvice(sim);
}

}  // namespace

std::string RefinementRow::status() const {
    if (ok) return "ok";
    std::string reason = failure;
    std::replace(reason.begin(), reason.end(), ',', ';');
    return "failed@" + formatDouble(failedAt) + (reason.empty() ? "" : ": " + reason);
}

std::optional<Param> refinementParam(SceneKind kind) {
    switch (kind) {
        case SceneKind::Ring2d: return Param::Particles;
        case SceneKind::Sphere3d: return Param::Subdivisions;
        case SceneKind::Sphere3dLatLong: return Param::Slices;
        case SceneKind::Spring1d: break;
    }
    return std::nullopt;
}

std::string refinementKey(SceneKind kind) {
    const std::optional<Param> id = refinementParam(kind);
    return id ? std::string(paramSpec(*id).key) : std::string();
}

ParameterSet refinementLevel(const RefinementSpec& spec, int value) {
    ParameterSet p = spec.params;
    if (auto error = setLevel(p, spec.key, value)) throw std::invalid_argument(*error);
    return p;
}

WorldSpec refinementWorld(const RefinementSpec& spec, int value) {
    WorldSpec world = *spec.world;
    for (std::size_t k = 0; k < world.bodies.size(); ++k)
        if (auto error = setLevel(world.bodies[k].params, spec.key, value))
            throw std::invalid_argument("body" + std::to_string(k + 1) + ": " + *error);
    return world;
}

std::optional<std::string> validateRefinement(const RefinementSpec& spec) {
    const std::string key = refinementKey(spec.params.kind());
    if (key.empty()) return "this scene has no mesh to refine (the 1D spring is two particles)";
    if (spec.key != key)
        return quoteShort(spec.key) + " is not this scene's resolution; refine it with " + key +
               "=v1,v2,... (ring2d: particles, sphere3d: subdivisions, sphere3d-latlong: slices)";
    const std::vector<int> levels = sortedLevels(spec);
    if (levels.size() < 2) return "a refinement needs at least two different levels";
    for (int value : levels) {
        ParameterSet p = spec.params;
        if (auto error = setLevel(p, spec.key, value)) return *error;
    }
    if (spec.world)
        // Every body's resolution is raised together: every body must refine with the same key.
        for (std::size_t k = 0; k < spec.world->bodies.size(); ++k) {
            const std::string own = refinementKey(spec.world->bodies[k].params.kind());
            if (own != key)
                return "body" + std::to_string(k + 1) + " refines with " + own + ", body1 with " + key +
                       ": a world is refined with every body's resolution raised together, so its bodies must be "
                       "of one kind";
            for (int value : levels) {
                ParameterSet p = spec.world->bodies[k].params;
                if (auto error = setLevel(p, spec.key, value)) return "body" + std::to_string(k + 1) + ": " + *error;
            }
        }
    if (!makeIntegrator(spec.integrator))
        return "unknown integrator " + quoteShort(spec.integrator) + "; allowed: " + integratorNames();
    if (!(spec.duration > 0.0)) return "the duration must be positive";
    if (!(spec.interval > 0.0) || spec.interval > spec.duration || !isWholeMultiple(spec.duration, spec.interval))
        return "the duration " + shortNumber(spec.duration) + " s must be a whole multiple of the output interval " +
               shortNumber(spec.interval) + " s";
    if (!(spec.tolerance > 0.0) || spec.tolerance >= 1.0) return "the tolerance must be in (0, 1)";
    if (spec.temporalRuns < 0 || spec.temporalRuns > 10) return "the temporal curve takes 0 to 10 runs";
    if (spec.dt != 0.0 && !isAdaptive(spec)) {
        if (!(spec.dt > 0.0) || spec.dt > 1.0) return "dt must be in (0, 1] s, got " + shortNumber(spec.dt);
        if (!isWholeMultiple(spec.interval, spec.dt))
            return "the output interval " + shortNumber(spec.interval) + " s is not a whole multiple of dt = " +
                   shortNumber(spec.dt) + " s";
        if (auto advice = finestAdvice(spec, levels.back(), spec.dt))
            return "at the finest level (" + spec.key + "=" + std::to_string(levels.back()) + "): " + advice->message +
                   "; use --dt " + shortNumber(advice->suggestedDt) + " or less, or leave --dt out";
    }
    return std::nullopt;
}

std::pair<double, std::string> refinementStep(const RefinementSpec& spec) {
    const double tableDt = spec.params.get(Param::Dt);
    if (isAdaptive(spec))
        return {tableDt, "rk45 at atol = rtol = " + shortNumber(spec.tolerance) + " (first step " + shortNumber(tableDt) + " s)"};
    if (spec.dt > 0.0) return {spec.dt, "dt = " + shortNumber(spec.dt) + " s as given (stable at the finest level)"};
    // The finest body has the fastest modes: probe its stability check at a step far above any
    // stable one, which returns 0.9 of the predicted limit (nothing for implicit-euler).
    const auto advice = finestAdvice(spec, sortedLevels(spec).back(), 1.0);
    const double stable = advice ? advice->suggestedDt : std::numeric_limits<double>::infinity();
    const double quarter = 0.25 * std::min(tableDt, stable);
    const double n = std::ceil(spec.interval / quarter * (1.0 - 1e-12));
    const double dt = spec.interval / n;
    std::string rule = "dt = " + shortNumber(dt) + " s: a quarter of min(scene dt " + shortNumber(tableDt) + " s, stable step " +
                       (advice ? shortNumber(stable) + " s" : std::string("unlimited")) +
                       " at the finest level), rounded down to divide the output interval";
    return {dt, rule};
}

namespace {

std::string levelName(const RefinementSpec& spec, int value) { return spec.key + "=" + std::to_string(value); }

// The row of one level (its samples when it ran to T) and whether the run was cancelled.
std::pair<RefinementRow, bool> runLevelRow(const RefinementSpec& spec, int value, bool reference, double dt,
                                           double tolerance, const std::vector<double>& grid,
                                           const std::atomic<bool>* cancel, Samples* samples) {
    std::vector<ParameterSet> bodies;
    if (spec.world)
        for (const WorldBodySpec& b : refinementWorld(spec, value).bodies) bodies.push_back(b.params);
    else
        bodies.push_back(refinementLevel(spec, value));
    RefinementRow row;
    row.value = value;
    row.reference = reference;
    // A world: every body's particles and springs, h the mean structural rest length over them all.
    std::size_t structuralCount = 0;
    for (const ParameterSet& p : bodies) {
        const Body body = buildBody(p);
        row.particles += body.topology.particleCount();
        row.springs += static_cast<int>(body.topology.springCount());
        const SpringSet& structural = body.topology.family(SpringFamily::Structural);
        for (double r : structural.rest) row.h += r;
        structuralCount += structural.size();
    }
    row.h /= static_cast<double>(std::max<std::size_t>(1, structuralCount));
    LevelRun level = runLevel(spec, value, dt, tolerance, grid, cancel);
    row.steps = level.run.steps;
    row.wallSeconds = level.run.wallSeconds;
    row.dt = isAdaptive(spec) ? spec.duration / static_cast<double>(std::max(1L, level.run.steps)) : dt;
    if (level.run.failed) {
        row.ok = false;
        row.failedAt = level.run.failedAt;
        row.failure = level.run.failure;
    }
    *samples = std::move(level.samples);
    return {row, level.run.cancelled};
}

// The temporal curve: the finest-but-one level at coarser steps (or looser tolerances),
// against its own run at the study's step, on the grid times each coarser step reaches; then
// the time error of the study's step from the first (2 dt or 10 tol) run.
void temporalCurve(const RefinementSpec& spec, const std::vector<double>& grid, const Samples& base, int levelCount,
                   int total, const StudyProgressFn& progress, const std::atomic<bool>* cancel,
                   RefinementResult& result) {
    const bool adaptive = isAdaptive(spec);
    for (int k = 1; k <= spec.temporalRuns; ++k) {
        const double factor = std::pow(adaptive ? 10.0 : 2.0, k);
        TemporalPoint point;
        point.dt = adaptive ? result.dt : result.dt * factor;
        point.tolerance = adaptive ? std::min(0.1, spec.tolerance * factor) : -1.0;
        if (progress)
            progress({levelCount + k - 1, total,
                      levelName(spec, result.temporalValue) +
                          (adaptive ? " tol=" + shortNumber(point.tolerance) : " dt=" + shortNumber(point.dt))});
        std::vector<double> times;
        std::vector<std::size_t> index;
        for (std::size_t g = 0; g < grid.size(); ++g)
            if (adaptive || isWholeMultiple(grid[g], point.dt)) times.push_back(grid[g]), index.push_back(g);
        if (times.empty()) break;  // the step no longer lands on any grid time
        LevelRun run = runLevel(spec, result.temporalValue, point.dt, point.tolerance, times, cancel);
        if (run.run.cancelled || (cancel && cancel->load())) {
            result.cancelled = true;
            break;
        }
        point.steps = run.run.steps;
        point.wallSeconds = run.run.wallSeconds;
        if (adaptive) point.dt = spec.duration / static_cast<double>(std::max(1L, run.run.steps));
        point.ok = !run.run.failed;
        point.failure = run.run.failure;
        if (point.ok) {
            const Errors e = compare(run.samples, base, index);
            point.errorVolume = e.volume;
            point.errorCom = e.com;
        }
        result.temporal.push_back(point);
    }
    if (!result.temporal.empty() && result.temporal.front().ok) {
        const int order = makeIntegrator(spec.integrator)->order();
        const double shrink = adaptive ? 1.0 : std::pow(2.0, order) - 1.0;
        result.timeErrorVolume = result.temporal.front().errorVolume / shrink;
        result.timeErrorCom = result.temporal.front().errorCom / shrink;
    }
}

}  // namespace

RefinementResult runRefinement(const RefinementSpec& spec, const StudyProgressFn& progress,
                               const std::atomic<bool>* cancel) {
    if (auto error = validateRefinement(spec)) throw std::invalid_argument(*error);
    RefinementResult result;
    const std::vector<double> grid = outputGrid(spec);
    const std::vector<int> levels = sortedLevels(spec);
    std::tie(result.dt, result.stepRule) = refinementStep(spec);
    const double tolerance = isAdaptive(spec) ? spec.tolerance : -1.0;
    const int total = static_cast<int>(levels.size()) + spec.temporalRuns;
    auto cancelled = [&] { return cancel && cancel->load(); };

    // The reference first: without it nothing can be measured.
    if (progress) progress({0, total, levelName(spec, levels.back()) + " (reference)"});
    Samples reference;
    auto [finestRow, finestCancelled] = runLevelRow(spec, levels.back(), true, result.dt, tolerance, grid, cancel, &reference);
    if (finestCancelled || cancelled()) {
        result.cancelled = true;
        if (progress) progress({total, total, "cancelled"});
        return result;
    }
    if (!finestRow.ok)
        throw std::runtime_error("the finest level (" + levelName(spec, levels.back()) + ") failed at t = " +
                                 formatDouble(finestRow.failedAt) + " s: " + finestRow.failure);
    result.rows.push_back(finestRow);

    // The others, coarse to fine; the finest-but-one keeps its samples for the temporal curve.
    const int temporalValue = levels[levels.size() - 2];
    Samples temporalBase;
    for (std::size_t i = 0; i + 1 < levels.size(); ++i) {
        if (progress) progress({static_cast<int>(i) + 1, total, levelName(spec, levels[i])});
        Samples samples;
        auto [row, rowCancelled] = runLevelRow(spec, levels[i], false, result.dt, tolerance, grid, cancel, &samples);
        if (rowCancelled || cancelled()) {
            result.cancelled = true;
            break;
        }
        if (row.ok) {
            const Errors e = compare(samples, reference, identity(samples.size()));
            row.errorVolume = e.volume;
            row.errorCom = e.com;
            if (levels[i] == temporalValue) temporalBase = std::move(samples);
        }
        result.rows.push_back(row);
    }
    std::sort(result.rows.begin(), result.rows.end(),
              [](const RefinementRow& a, const RefinementRow& b) { return a.particles < b.particles; });

    result.temporalValue = temporalValue;
    if (!result.cancelled && !temporalBase.empty())
        temporalCurve(spec, grid, temporalBase, static_cast<int>(levels.size()), total, progress, cancel, result);
    if (cancelled()) result.cancelled = true;
    if (progress) progress({total, total, result.cancelled ? "cancelled" : "done"});
    return result;
}

std::vector<SpatialOrder> fitSpatialOrders(const RefinementResult& result) {
    std::vector<SpatialOrder> fits;
    for (const char* observable : {"volume", "com"}) {
        const bool volume = std::string(observable) == "volume";
        const double timeError = volume ? result.timeErrorVolume : result.timeErrorCom;
        // Resolved: above 10x the step's own error, and above round-off (1e-10 of the quantity:
        // volumes are relative; a centre of mass is measured against the coarsest spacing), which
        // is all a symmetric body's centre of mass shows when nothing moves it.
        double scale = 1.0;
        if (!volume)
            for (const RefinementRow& row : result.rows) scale = std::max(scale, row.h);
        const double floor = std::max(std::isfinite(timeError) ? 10.0 * timeError : 0.0, 1e-10 * scale);
        // The asymptotic range: the three finest levels whose error the step resolves.
        std::vector<std::pair<double, double>> points;
        for (const RefinementRow& row : result.rows) {
            const double e = volume ? row.errorVolume : row.errorCom;
            if (!row.reference && row.ok && e > floor && e > 0.0 && row.h > 0.0) points.emplace_back(row.h, e);
        }
        std::sort(points.begin(), points.end());
        if (points.size() > 3) points.resize(3);
        fits.push_back({observable, logLogSlope(points), static_cast<int>(points.size())});
    }
    return fits;
}

std::string refinementCsvHeader() {
    return "key,value,particles,springs,wall_seconds,error_volume,error_com,status,h,dt,steps,reference\n";
}

std::string refinementCsvRow(const std::string& key, const RefinementRow& row) {
    std::string line = key + ',' + std::to_string(row.value) + ',' + std::to_string(row.particles) + ',' +
                       std::to_string(row.springs) + ',' + formatDouble(row.wallSeconds);
    line += row.ok ? ',' + formatDouble(row.errorVolume) + ',' + formatDouble(row.errorCom) : std::string(",,");
    line += ',' + row.status() + ',' + formatDouble(row.h) + ',' + formatDouble(row.dt) + ',' + std::to_string(row.steps);
    return line + ',' + (row.reference ? "1" : "0") + '\n';
}

std::string refinementSvg(const RefinementSpec& spec, const RefinementResult& result, const std::string& title) {
    const bool adaptive = isAdaptive(spec);
    std::vector<SvgPanel> panels;
    for (const bool volume : {true, false}) {
        SvgPanel panel{"wall time [s] (stepping only, one thread)",
                       volume ? "largest relative volume error [1]" : "largest centre-of-mass error [m]",
                       {}};
        // The mesh: every level but the reference, coarse to fine, at the study's step.
        SvgSeries mesh{"mesh: " + spec.key + " (" + spec.integrator + ", " +
                           (adaptive ? "tol " + shortNumber(spec.tolerance, 3) : "dt " + shortNumber(result.dt, 3) + " s") + ")",
                       "#1f77b4", "", {}, {}};
        for (const RefinementRow& row : result.rows)
            if (row.ok && !row.reference) {
                mesh.points.emplace_back(row.wallSeconds, volume ? row.errorVolume : row.errorCom);
                mesh.labels.push_back(std::to_string(row.value));
            }
        // The step: the finest-but-one level at coarser steps, against itself at the study's step.
        SvgSeries step{"step: " + spec.integrator + " at " + spec.key + "=" + std::to_string(result.temporalValue) +
                           (adaptive ? " (tol x10^k)" : " (dt x2^k)"),
                       "#d62728", "5,3", {}, {}};
        for (const TemporalPoint& p : result.temporal)
            if (p.ok) {
                step.points.emplace_back(p.wallSeconds, volume ? p.errorVolume : p.errorCom);
                step.labels.push_back(adaptive ? "tol " + shortNumber(p.tolerance, 3) : "dt " + shortNumber(p.dt, 3));
            }
        panel.series.push_back(std::move(mesh));
        panel.series.push_back(std::move(step));
        panels.push_back(std::move(panel));
    }
    return logLogSvg(panels, title);
}

}  // namespace simlab
