#include "simlab/conservation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>

#include "simcore/integrator_table.h"
#include "simcore/simulation.h"
#include "simlab/output.h"
#include "simlab/reference_problem.h"
#include "simlab/stability.h"
#include "simlab/study.h"

namespace simlab {

using simcore::Diagnostics;
using simcore::Param;
using simcore::ParameterSet;
using simcore::Simulation;
using simcore::makeIntegrator;
using simcore::paramSpec;
using simcore::unknownIntegrator;

namespace {

// Two-sided 95 % quantile of Student's t with nu degrees of freedom (Cornish-Fisher
// expansion about the normal quantile; within 1e-3 for nu >= 3).
double studentT95(int nu) {
    const double z = 1.959963984540054, v = std::max(1, nu);
    const double z3 = z * z * z, z5 = z3 * z * z, z7 = z5 * z * z;
    return z + (z3 + z) / (4 * v) + (5 * z5 + 16 * z3 + 3 * z) / (96 * v * v) +
           (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * v * v * v);
}

std::string shortNumber(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

// Step counts of the sample times: log-spaced from one period to the end, distinct.
std::vector<long> sampleSteps(long perPeriod, long total, int samples) {
    std::vector<long> steps;
    const double a = std::log(static_cast<double>(std::max(1L, perPeriod))), b = std::log(static_cast<double>(total));
    for (int k = 0; k < samples; ++k) {
        const double u = samples == 1 ? 1.0 : static_cast<double>(k) / (samples - 1);
        const long s = std::clamp(std::lround(std::exp(a + u * (b - a))), 1L, total);
        if (steps.empty() || s > steps.back()) steps.push_back(s);
    }
    if (steps.empty() || steps.back() != total) steps.push_back(total);
    return steps;
}

}  // namespace

std::string ConservationRow::status() const { return ok ? std::string("ok") : "failed@" + formatDouble(failedAt); }

ParameterSet undampedParameters(const ParameterSet& params, std::string* changed) {
    ParameterSet p = params;
    std::string what;
    for (auto [param, value] : {std::pair{Param::Kd, 0.0}, {Param::Rkd, 0.0}, {Param::Restitution, 1.0}, {Param::Friction, 0.0}}) {
        if (!p.has(param) || p.get(param) == value) continue;
        if (p.set(param, value)) continue;  // refused: the scene has no such term
        if (!what.empty()) what += ", ";
        what += std::string(paramSpec(param).key) + " = " + shortNumber(value);
    }
    if (changed) *changed = what.empty() ? "nothing (already undamped)" : what;
    return p;
}

std::string growthClass(double alpha) {
    if (!std::isfinite(alpha)) return "";
    if (alpha < 0.25) return "bounded";
    if (alpha < 0.75) return "random-walk";
    return "drift";
}

SlopeFit logLogSlopeInterval(const std::vector<std::pair<double, double>>& points) {
    SlopeFit fit;
    std::vector<std::pair<double, double>> logs;
    for (auto [x, y] : points)
        if (x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y)) logs.emplace_back(std::log(x), std::log(y));
    fit.points = static_cast<int>(logs.size());
    const double nan = std::nan("");
    if (logs.size() < 3) {
        fit.slope = fit.lo = fit.hi = nan;
        return fit;
    }
    const double n = static_cast<double>(logs.size());
    double mx = 0, my = 0;
    for (auto [x, y] : logs) mx += x / n, my += y / n;
    double sxx = 0, sxy = 0;
    for (auto [x, y] : logs) sxx += (x - mx) * (x - mx), sxy += (x - mx) * (y - my);
    if (!(sxx > 0)) {
        fit.slope = fit.lo = fit.hi = nan;
        return fit;
    }
    fit.slope = sxy / sxx;
    double rss = 0;
    for (auto [x, y] : logs) {
        const double r = y - my - fit.slope * (x - mx);
        rss += r * r;
    }
    const double se = std::sqrt(rss / (n - 2.0) / sxx);
    const double half = studentT95(static_cast<int>(n) - 2) * se;
    fit.lo = fit.slope - half;
    fit.hi = fit.slope + half;
    return fit;
}

std::optional<std::string> validateConservation(const ConservationSpec& spec) {
    if (spec.integrators.empty()) return "no integrators given";
    for (const std::string& name : spec.integrators) {
        if (auto unknown = unknownIntegrator(name)) return *unknown;
        const auto method = makeIntegrator(name);
        if (method->adaptive())
            return name + " chooses its own steps; the conservation study runs fixed steps (--dt)";
        if (std::count(spec.integrators.begin(), spec.integrators.end(), name) > 1) return "'" + name + "' is listed twice";
    }
    if (!(spec.periods >= 20.0) || spec.periods > 1e7)
        return "periods must be in [20, 1e7] (the growth is fitted from 10 periods on)";
    if (!(spec.dt > 0.0) || spec.dt > 1.0) return "the step --dt must be in (0, 1] s";
    if (spec.samples < 10 || spec.samples > 100000) return "samples must be in [10, 100000]";
    if (spec.precision != "double" && spec.precision != "float")
        return "unknown precision '" + spec.precision + "'; allowed: double, float";
    if (spec.precision == "float") {
        if (const std::string refusal = referenceProblemRefusal(spec.params); !refusal.empty()) return refusal;
        for (const std::string& name : spec.integrators)
            if (!referenceProblemSupports(name))
                return "precision float: " + name +
                       " has no float build (only euler, midpoint, rk4, symplectic-euler, verlet, yoshida4, yoshida8)";
    }
    return std::nullopt;
}

namespace {

// One integrator's run: the energy-error envelope at the sample steps (float: the float
// build of the reference problem; double: the Simulation), its cost and largest kinetic
// energy. Sets `cancelled` when the run was cancelled.
ConservationRow conservationRun(const ConservationSpec& spec, const ParameterSet& params, const std::string& name,
                                const std::vector<long>& steps, const std::atomic<bool>* cancel, bool& cancelled) {
    ConservationRow row;
    row.integrator = name;
    if (spec.precision == "float") {
        std::vector<double> grid;
        for (long s : steps) grid.push_back(static_cast<double>(s) * spec.dt);
        const ReferenceProblemRun run = runReferenceProblem(params, name, spec.dt, grid, "float", false, cancel, 0.0, true);
        for (std::size_t k = 0; k < run.envelope.size(); ++k) row.curve.emplace_back(grid[k], run.envelope[k]);
        row.steps = run.steps;
        row.wallSeconds = run.wallSeconds;
        row.kineticMax = run.maxKinetic;
        if (run.cancelled) cancelled = true;
        if (run.failed) row.ok = false, row.failedAt = run.failedAt, row.failure = "the float state is no longer finite";
        return row;
    }
    ParameterSet p = params;
    if (auto error = p.set(Param::Dt, spec.dt)) throw std::invalid_argument(*error);
    Simulation sim(p, name);
    sim.setThreads(1);
    double envelope = 0.0, kineticMax = 0.0;
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    for (long target : steps) {
        while (sim.stepCount() < target) {
            if (!sim.step()) break;
            const Diagnostics& d = sim.diagnostics();
            envelope = std::max(envelope, std::abs(d.energyDrift()));
            kineticMax = std::max(kineticMax, d.kinetic);
            if (cancel && (sim.stepCount() & 1023) == 0 && cancel->load(std::memory_order_relaxed)) break;
        }
        if (sim.failed() || (cancel && cancel->load())) break;
        row.curve.emplace_back(static_cast<double>(target) * spec.dt, envelope);
    }
    row.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    row.steps = sim.stepCount();
    row.kineticMax = kineticMax;
    if (cancel && cancel->load()) cancelled = true;
    if (sim.failed()) row.ok = false, row.failedAt = sim.failure()->time, row.failure = sim.failure()->reason;
    return row;
}

// The growth of a finished row's envelope: the log-log slope over t >= fitFrom and its class.
void fitGrowth(ConservationRow& row, double fitFrom) {
    std::vector<std::pair<double, double>> tail;
    for (auto [t, e] : row.curve)
        if (t >= fitFrom * (1.0 - 1e-12)) tail.emplace_back(t, e);
    const SlopeFit fit = logLogSlopeInterval(tail);
    row.alpha = fit.slope, row.alphaLo = fit.lo, row.alphaHi = fit.hi, row.fitPoints = fit.points;
    row.growth = growthClass(fit.slope);
    row.finalError = row.curve.empty() ? 0.0 : row.curve.back().second;
    if (!std::isfinite(fit.slope)) {
        // No growth to fit: the envelope stayed at 0 (exact to the last bit) or too few points.
        row.growth = row.finalError == 0.0 ? "bounded" : "";
        row.alpha = row.alphaLo = row.alphaHi = row.finalError == 0.0 ? 0.0 : std::nan("");
    }
}

}  // namespace

ConservationResult runConservation(const ConservationSpec& spec, const ConservationProgressFn& progress,
                                   const std::atomic<bool>* cancel) {
    ConservationResult result;
    const ParameterSet params = undampedParameters(spec.params, &result.undamped);
    const LinearModes modes = linearModes(params);
    result.omegaMax = modes.omegaMax;
    if (!(result.omegaMax > 0.0)) throw std::runtime_error("the scene has no oscillating mode (omega_max = 0)");
    result.period = 2.0 * std::numbers::pi / result.omegaMax;
    const double wanted = std::ceil(spec.periods * result.period / spec.dt - 1e-9);
    if (wanted > 1e9)
        throw std::runtime_error(shortNumber(spec.periods) + " periods of " + shortNumber(result.period) + " s at dt = " +
                                 shortNumber(spec.dt) + " s would take " + shortNumber(wanted) +
                                 " steps; at most 1e9 (fewer periods or a larger step)");
    const long total = std::max(1L, static_cast<long>(wanted));
    result.duration = static_cast<double>(total) * spec.dt;
    const long perPeriod = std::max(1L, std::lround(result.period / spec.dt));
    const std::vector<long> steps = sampleSteps(perPeriod, total, spec.samples);
    const double fitFrom = std::min(10.0 * result.period, 0.1 * result.duration);
    int done = 0;
    for (const std::string& name : spec.integrators) {
        if (cancel && cancel->load()) {
            result.cancelled = true;
            break;
        }
        if (progress) progress(done, static_cast<int>(spec.integrators.size()), name);
        ConservationRow row = conservationRun(spec, params, name, steps, cancel, result.cancelled);
        if (result.cancelled) break;
        if (row.ok) fitGrowth(row, fitFrom);
        result.rows.push_back(std::move(row));
        ++done;
    }
    // The energy scale: the largest kinetic energy of the most accurate run (a run that blew up
    // must not set it).
    const ConservationRow* best = nullptr;
    for (const ConservationRow& row : result.rows)
        if (row.ok && (!best || row.finalError < best->finalError)) best = &row;
    result.energyScale = best ? best->kineticMax : 0.0;
    for (ConservationRow& row : result.rows)
        row.relativeError = result.energyScale > 0.0 ? row.finalError / result.energyScale : std::nan("");
    if (progress) progress(done, static_cast<int>(spec.integrators.size()), result.cancelled ? "cancelled" : "done");
    return result;
}

std::string conservationCsvHeader() {
    return "integrator,alpha,alpha_lo,alpha_hi,class,final_error,relative_error,fit_points,steps,wall_seconds,status\n";
}

std::string conservationCsvRow(const ConservationRow& row) {
    std::string line = row.integrator;
    if (row.ok) {
        for (double v : {row.alpha, row.alphaLo, row.alphaHi}) line += ',' + formatDouble(v);
        line += ',' + row.growth;
        for (double v : {row.finalError, row.relativeError}) line += ',' + formatDouble(v);
    } else {
        line += ",,,,,,";
    }
    line += ',' + std::to_string(row.fitPoints) + ',' + std::to_string(row.steps) + ',' + formatDouble(row.wallSeconds);
    return line + ',' + row.status() + '\n';
}

std::string conservationCurvesCsv(const ConservationResult& result) {
    std::string out = "integrator,t,energy_error\n";
    for (const ConservationRow& row : result.rows)
        for (auto [t, e] : row.curve) out += row.integrator + ',' + formatDouble(t) + ',' + formatDouble(e) + '\n';
    return out;
}

std::string conservationSvg(const ConservationResult& result, const std::string& title) {
    SvgPanel panel{"t [s]", "|energy error| envelope [J]", {}};
    for (const ConservationRow& row : result.rows) {
        SvgSeries s{row.integrator + (row.ok ? " (" + row.growth + ", alpha " + shortNumber(std::round(row.alpha * 100) / 100) + ")" : " (failed)"),
                    studyColour(row.integrator), "", row.curve, {}};
        panel.series.push_back(std::move(s));
    }
    // Reference slopes from the first positive point of the middle curve: sqrt(t) and t.
    if (!result.rows.empty()) {
        const ConservationRow& mid = result.rows[result.rows.size() / 2];
        for (auto [t0, e0] : mid.curve) {
            if (!(e0 > 0)) continue;
            const double t1 = result.duration;
            panel.series.push_back({"slope 1/2 (random walk)", "#999999", "2,3", {{t0, e0}, {t1, e0 * std::sqrt(t1 / t0)}}, {}});
            panel.series.push_back({"slope 1 (drift)", "#999999", "6,3", {{t0, e0}, {t1, e0 * (t1 / t0)}}, {}});
            break;
        }
    }
    return logLogSvg({panel}, title);
}

}  // namespace simlab
