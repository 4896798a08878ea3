#include "simlab/study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "simcore/integrator_table.h"
#include "simcore/simulation.h"
#include "simlab/analytic.h"
#include "simlab/output.h"

namespace simlab {

using simcore::IntegratorOptions;
using simcore::Param;
using simcore::ParameterSet;
using simcore::Simulation;
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

Trajectory runTrajectory(const ParameterSet& base, const std::string& integrator, double dt,
                         const IntegratorOptions& options, const std::vector<double>& grid,
                         const std::atomic<bool>* cancel) {
    Trajectory out;
    out.positions.reserve(grid.size());
    static_cast<SampledRun&>(out) = runSampled(
        base, integrator, dt, options, grid, [&](const Simulation& sim) { out.positions.emplace_back(sim.positions()); },
        cancel);
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

std::string formatShort(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

}  // namespace

SampledRun runSampled(const ParameterSet& base, const std::string& integrator, double dt,
                      const IntegratorOptions& options, const std::vector<double>& grid,
                      const std::function<void(const Simulation&)>& sample, const std::atomic<bool>* cancel) {
    ParameterSet p = base;
    if (auto error = p.set(Param::Dt, dt)) throw std::invalid_argument(*error);
    Simulation sim(p, integrator);
    sim.setThreads(1);  // timings are single-threaded, whatever the machine
    sim.setIntegratorOptions(options);
    SampledRun out;
    using Clock = std::chrono::steady_clock;
    const bool adaptive = sim.integrator().adaptive();
    for (double target : grid) {
        // Fixed steps: count them (t accumulated as a sum of dt drifts by round-off, and one
        // step too many at a grid time is an error of v dt). Adaptive: land on the target.
        const long targetSteps = std::lround(target / dt);
        auto more = [&] { return adaptive ? sim.time() < target - 1e-12 * std::max(1.0, target) : sim.stepCount() < targetSteps; };
        const auto start = Clock::now();
        while (more()) {
            if (!sim.step(target)) break;
            out.maxDrift = std::max(out.maxDrift, std::abs(sim.diagnostics().energyDrift()));
            if (cancel && cancel->load(std::memory_order_relaxed)) {
                out.cancelled = true;
                break;
            }
        }
        out.wallSeconds += std::chrono::duration<double>(Clock::now() - start).count();
        if (sim.failed() || out.cancelled) break;
        sample(sim);
    }
    if (sim.failed()) {
        out.failed = true;
        out.failedAt = sim.failure()->time;
        out.failure = sim.failure()->reason;
    }
    out.steps = sim.stepCount();
    out.evaluations = sim.diagnostics().forceEvaluations;
    return out;
}

bool isWholeMultiple(double T, double h) {
    const double q = T / h;
    return std::abs(q - std::round(q)) <= 1e-9 * std::max(1.0, q);
}

std::string StudyRow::status() const { return ok ? std::string("ok") : "failed@" + formatDouble(failedAt); }

std::vector<StudyItem> studyItems(const StudySpec& spec) {
    std::vector<StudyItem> items;
    for (const std::string& name : spec.integrators) {
        if (isAdaptiveItem(spec, name)) {
            const double h0 = spec.dts.empty() ? 0.01 : *std::max_element(spec.dts.begin(), spec.dts.end());
            for (double tol : spec.tolerances) items.push_back({name, h0, tol});
        } else {
            for (double dt : spec.dts) items.push_back({name, dt, -1.0});
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
        if (!makeIntegrator(name)) return "unknown integrator '" + name + "'; allowed: " + integratorNames();
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
    if (spec.shardCount < 1 || spec.shardIndex < 0 || spec.shardIndex >= spec.shardCount)
        return "shard must be K/N with 1 <= K <= N";
    if (spec.reference != "auto" && spec.reference != "exact" && spec.reference != "rk4" && spec.reference != "rk45" &&
        spec.reference != "cvode-bdf")
        return "unknown reference '" + spec.reference + "'; allowed: auto, exact, rk4, rk45, cvode-bdf";
    if (spec.reference == "exact" && !closedFormApplies(spec))
        return "this scene has no closed form (only spring1d without perturbation and without "
               "reaching a wall has one); use --reference rk4, rk45 or cvode-bdf";
    return std::nullopt;
}

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
        Trajectory fine = runTrajectory(spec.params, method, smallestFixedStep(spec), fineOptions, ref.times, cancel);
        IntegratorOptions coarse = fineOptions;
        coarse.atol = coarse.rtol = loose;
        Trajectory check = runTrajectory(spec.params, method, smallestFixedStep(spec), coarse, ref.times, cancel);
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
    Trajectory fine = runTrajectory(spec.params, "rk4", h, options, ref.times, cancel);
    if (fine.failed && spec.reference == "auto" && !fine.cancelled)
        // Stiff: rk4 16x below the smallest studied step is still unstable. The most accurate
        // reference left is the stiff solver at a tight tolerance.
        return adaptiveReference("cvode-bdf", ", because rk4 at dt = " + formatShort(h) + " s failed (" + fine.failure + ")");
    if (fine.failed)
        throw std::runtime_error("the rk4 reference at dt = " + formatShort(h) + " s failed: " + fine.failure);
    Trajectory check = runTrajectory(spec.params, "rk4", 2.0 * h, options, ref.times, cancel);
    ref.description = "rk4 at dt = " + formatShort(h) + " s (16x below the smallest studied step)";
    ref.positions = fine.positions;
    // The difference to the run at 2h bounds the error for any convergent method; for a
    // smooth (collision-free) run the error is about 1/15 of it (order 4).
    ref.estimatedError = check.failed || check.positions.size() != fine.positions.size()
                             ? std::nan("")
                             : rmsDistance(check.positions.back(), fine.positions.back());
    return ref;
}

StudyRow runStudyItem(const StudySpec& spec, const StudyItem& item, const StudyReference& reference,
                      const std::atomic<bool>* cancel) {
    IntegratorOptions options = spec.options;
    options.stepDoubling = false;  // never pay for estimates in a timing
    if (item.tolerance > 0.0) options.atol = options.rtol = item.tolerance;
    StudyRow row;
    row.item = item;
    std::vector<double> walls;
    Trajectory run;
    for (int r = 0; r < spec.repeat; ++r) {
        run = runTrajectory(spec.params, item.integrator, item.dt, options, reference.times, cancel);
        walls.push_back(run.wallSeconds);
        if (run.failed || run.cancelled) break;
    }
    std::sort(walls.begin(), walls.end());
    const std::size_t mid = walls.size() / 2;
    row.wallSeconds = walls.size() % 2 ? walls[mid] : 0.5 * (walls[mid - 1] + walls[mid]);
    row.steps = run.steps;
    row.forceEvaluations = run.evaluations;
    row.dt = item.tolerance > 0.0 ? spec.duration / static_cast<double>(std::max(1L, run.steps)) : item.dt;
    row.errorEnergy = run.maxDrift;
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
    for (std::size_t k = 0; k < run.positions.size(); ++k)
        row.errorMax = std::max(row.errorMax, rmsDistance(run.positions[k], reference.positions[k]));
    row.errorFinal = rmsDistance(run.positions.back(), reference.positions.back());
    return row;
}

StudyResult runStudy(const StudySpec& spec, const StudyProgressFn& progress, const std::atomic<bool>* cancel) {
    StudyResult result;
    const std::vector<StudyItem> items = shardItems(studyItems(spec), spec.shardIndex, spec.shardCount);
    const int total = static_cast<int>(items.size()) + 1;
    if (progress) progress({0, total, "reference"});
    result.reference = computeReference(spec, cancel);
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
        result.rows.push_back(runStudyItem(spec, item, result.reference, cancel));
    }
    if (cancel && cancel->load()) result.cancelled = true;
    if (progress) progress({total, total, result.cancelled ? "cancelled" : "done"});
    return result;
}

std::vector<OrderFit> fitOrders(const std::vector<StudyRow>& rows, double referenceError) {
    std::vector<OrderFit> fits;
    std::vector<std::string> names;
    for (const StudyRow& r : rows)
        if (std::find(names.begin(), names.end(), r.item.integrator) == names.end()) names.push_back(r.item.integrator);
    const double floor = std::isfinite(referenceError) ? 10.0 * referenceError : 0.0;
    for (const std::string& name : names) {
        // The asymptotic range: the three smallest steps whose error is resolved.
        std::vector<std::pair<double, double>> points;
        for (const StudyRow& r : rows)
            if (r.item.integrator == name && r.ok && r.errorMax > floor && r.errorMax > 0 && r.dt > 0)
                points.emplace_back(r.dt, r.errorMax);
        std::sort(points.begin(), points.end());
        if (points.size() > 3) points.resize(3);
        fits.push_back({name, logLogSlope(points), static_cast<int>(points.size())});
    }
    return fits;
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
    return "integrator,dt,steps,force_evals,wall_seconds,error_final,error_max,error_energy,status\n";
}

std::string studyCsvRow(const StudyRow& row) {
    std::string line = row.item.integrator;
    line += ',' + formatDouble(row.dt);
    line += ',' + std::to_string(row.steps);
    line += ',' + std::to_string(row.forceEvaluations);
    line += ',' + formatDouble(row.wallSeconds);
    if (row.ok) {
        line += ',' + formatDouble(row.errorFinal) + ',' + formatDouble(row.errorMax) + ',' +
                formatDouble(row.errorEnergy);
    } else {
        line += ",,,";
    }
    return line + ',' + row.status() + '\n';
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
        if (f.size() != 9) return fail("expected 9 fields, got " + std::to_string(f.size()));
        StudyRow r;
        r.item.integrator = f[0];
        const auto dt = parseNumber(f[1]), steps = parseNumber(f[2]), evals = parseNumber(f[3]), wall = parseNumber(f[4]);
        if (!dt || !steps || !evals || !wall) return fail("bad number");
        r.dt = r.item.dt = *dt;
        r.steps = static_cast<long>(*steps);
        r.forceEvaluations = static_cast<std::uint64_t>(*evals);
        r.wallSeconds = *wall;
        if (f[8] == "ok") {
            const auto e1 = parseNumber(f[5]), e2 = parseNumber(f[6]), e3 = parseNumber(f[7]);
            if (!e1 || !e2 || !e3) return fail("bad error value");
            r.errorFinal = *e1, r.errorMax = *e2, r.errorEnergy = *e3;
        } else if (f[8].rfind("failed@", 0) == 0) {
            const auto t = parseNumber(f[8].substr(7));
            if (!t) return fail("bad failure time");
            r.ok = false;
            r.failedAt = *t;
        } else {
            return fail("status must be ok or failed@<time>");
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

const char* colourFor(const std::string& name) { return studyColour(name); }

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
        << "<text x=\"" << left << "\" y=\"24\" font-size=\"15\">" << title << "</text>\n";
    auto drawable = [](std::pair<double, double> pt) {
        return pt.first > 0.0 && pt.second > 0.0 && std::isfinite(pt.first) && std::isfinite(pt.second);
    };
    // The legend: every series name once, in order of first appearance, with its style.
    std::vector<const SvgSeries*> legend;
    for (int p = 0; p < count; ++p) {
        const SvgPanel& panel = panels[static_cast<std::size_t>(p)];
        const int x0 = left + p * (panelW + gap), y0 = top;
        std::vector<double> xs, ys;
        for (const SvgSeries& s : panel.series)
            for (auto pt : s.points)
                if (drawable(pt)) xs.push_back(pt.first), ys.push_back(pt.second);
        const Range xr = decades(xs), yr = decades(ys);
        auto px = [&](double v) { return x0 + (std::log10(v) - xr.lo) / (xr.hi - xr.lo) * panelW; };
        auto py = [&](double v) { return y0 + panelH - (std::log10(v) - yr.lo) / (yr.hi - yr.lo) * panelH; };
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
            << panel.xLabel << "</text>\n";
        svg << "<text transform=\"translate(" << x0 - 48 << "," << y0 + panelH / 2
            << ") rotate(-90)\" text-anchor=\"middle\">" << panel.yLabel << "</text>\n";
        for (const SvgSeries& s : panel.series) {
            std::vector<std::pair<double, double>> pts;
            for (auto pt : s.points)
                if (drawable(pt)) pts.push_back(pt);
            if (pts.empty()) continue;
            if (std::none_of(legend.begin(), legend.end(), [&](const SvgSeries* l) { return l->name == s.name; }))
                legend.push_back(&s);
            svg << "<polyline fill=\"none\" stroke=\"" << s.colour << "\" stroke-width=\"1.5\"";
            if (!s.dash.empty()) svg << " stroke-dasharray=\"" << s.dash << "\"";
            svg << " points=\"";
            for (auto [x, y] : pts) svg << px(x) << ',' << py(y) << ' ';
            svg << "\"/>\n";
            for (std::size_t i = 0; i < pts.size(); ++i) {
                const auto [x, y] = pts[i];
                svg << "<circle cx=\"" << px(x) << "\" cy=\"" << py(y) << "\" r=\"3\" fill=\"" << s.colour << "\"/>\n";
                if (i < s.labels.size() && !s.labels[i].empty())
                    svg << "<text x=\"" << px(x) + 5 << "\" y=\"" << py(y) - 5 << "\" font-size=\"10\" fill=\"" << s.colour
                        << "\">" << s.labels[i] << "</text>\n";
            }
        }
    }
    const int lx = left + count * panelW + (count - 1) * gap + 15;
    for (std::size_t i = 0; i < legend.size(); ++i) {
        const double y = top + 15 + 20.0 * static_cast<double>(i);
        svg << "<line x1=\"" << lx << "\" y1=\"" << y << "\" x2=\"" << lx + 20 << "\" y2=\"" << y << "\" stroke=\""
            << legend[i]->colour << "\" stroke-width=\"2\"";
        if (!legend[i]->dash.empty()) svg << " stroke-dasharray=\"" << legend[i]->dash << "\"";
        svg << "/><text x=\"" << lx + 26 << "\" y=\"" << y + 4 << "\">" << legend[i]->name << "</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

std::string studySvg(const std::vector<StudyRow>& rows, const std::string& title) {
    std::vector<std::string> names;
    for (const StudyRow& r : rows)
        if (std::find(names.begin(), names.end(), r.item.integrator) == names.end()) names.push_back(r.item.integrator);
    struct Axis {
        const char* label;
        std::function<double(const StudyRow&)> x;
    };
    const Axis axes[3] = {
        {"wall time [s] (median, stepping only)", [](const StudyRow& r) { return r.wallSeconds; }},
        {"force evaluations", [](const StudyRow& r) { return static_cast<double>(r.forceEvaluations); }},
        {"dt [s] (mean step for adaptive rk45)", [](const StudyRow& r) { return r.dt; }},
    };
    std::vector<SvgPanel> panels;
    for (const Axis& axis : axes) {
        SvgPanel panel{axis.label, "error_max: largest RMS position error [m]", {}};
        for (const std::string& name : names) {
            // Joined in order of dt (timings are noisy; the line follows the refinement).
            std::vector<std::tuple<double, double, double>> sorted;
            for (const StudyRow& r : rows)
                if (r.ok && r.item.integrator == name) sorted.emplace_back(r.dt, axis.x(r), r.errorMax);
            std::sort(sorted.begin(), sorted.end());
            SvgSeries series{name, colourFor(name), "", {}, {}};
            for (auto [dt, x, e] : sorted) series.points.emplace_back(x, e);
            panel.series.push_back(std::move(series));
        }
        panels.push_back(std::move(panel));
    }
    return logLogSvg(panels, title);
}

const char* studyColour(std::string_view integrator) {
    static const std::map<std::string_view, const char*> colours = {
        {"euler", "#d62728"},     {"midpoint", "#ff7f0e"},  {"rk4", "#1f77b4"},       {"symplectic-euler", "#9467bd"},
        {"verlet", "#8c564b"},    {"rk45", "#2ca02c"},      {"implicit-euler", "#e377c2"}, {"cvode-bdf", "#17becf"},
        {"cvode-adams", "#bcbd22"}, {"xpbd", "#393b79"}};
    auto it = colours.find(integrator);
    return it == colours.end() ? "#7f7f7f" : it->second;
}

}  // namespace simlab
