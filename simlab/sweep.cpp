#include "simlab/sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "elastic_lab_version.h"
#include "simcore/body.h"
#include "simcore/integrator_table.h"
#include "simcore/scenes.h"
#include "simcore/simulation.h"
#include "simlab/output.h"

namespace simlab {

using simcore::Diagnostics;
using simcore::Failure;
using simcore::ParameterSet;
using simcore::ParamSpec;
using simcore::SceneKind;
using simcore::Simulation;
using simcore::SpringSet;
using simcore::findParam;
using simcore::hasGas;
using simcore::parseNumber;
using simcore::quoteShort;
using simcore::sceneInfo;
using simcore::unknownIntegrator;
using simcore::validateShape;

namespace {

using Json = nlohmann::json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A number as the CSV shows it: shortest round-trip text, and nan / inf / -inf as such.
std::string numberText(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return formatDouble(v);
}

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + '"';
}

// What one run leaves: every metric of the scene in sweepMetricNames' order.
struct Observer {
    bool gas = false;
    bool wantStrain = false, wantBounce = false;
    std::array<double, 2> volumeMin{kNaN, kNaN}, volumeMax{kNaN, kNaN}, pressureMin{kNaN, kNaN}, pressureMax{kNaN, kNaN};
    double driftMax = 0.0, strainMax = 0.0;
    // The first bounce: a particle touched the floor, then the centre of mass turned upwards.
    bool touched = false, bounced = false, apexFound = false;
    double previousVy = 0.0, bounceTime = kNaN, apex = -std::numeric_limits<double>::infinity(), bounceHeight = kNaN;

    void observe(const Simulation& sim) {
        const Diagnostics& d = sim.diagnostics();
        if (gas)
            for (int l = 0; l < 2; ++l) {
                volumeMin[l] = std::fmin(volumeMin[l], d.volume[l]);
                volumeMax[l] = std::fmax(volumeMax[l], d.volume[l]);
                pressureMin[l] = std::fmin(pressureMin[l], d.pressure[l]);
                pressureMax[l] = std::fmax(pressureMax[l], d.pressure[l]);
            }
        driftMax = std::fmax(driftMax, std::abs(d.energyDrift()));
        const auto x = sim.positions();
        if (wantStrain)
            for (const SpringSet& set : sim.topology().springs)
                for (std::size_t s = 0; s < set.size(); ++s) {
                    const double length = (x.col(set.a[s]) - x.col(set.b[s])).norm();
                    strainMax = std::fmax(strainMax, std::abs(length / set.rest[s] - 1.0));
                }
        if (wantBounce && !apexFound) {
            const auto v = sim.velocities();
            const Eigen::VectorXd& mass = sim.body().mass;
            double m = 0.0, y = 0.0, vy = 0.0, lowest = std::numeric_limits<double>::infinity();
            for (Eigen::Index i = 0; i < x.cols(); ++i) {  // summed in order (bit-identical everywhere)
                m += mass[i];
                y += mass[i] * x(1, i);
                vy += mass[i] * v(1, i);
                lowest = std::fmin(lowest, x(1, i));
            }
            y /= m;
            vy /= m;
            const double floor = sim.boxCentre().y() - sim.boxHalfSize();
            if (!bounced) {
                touched |= lowest <= floor + 1e-9 * sim.boxHalfSize();
                if (touched && previousVy <= 0.0 && vy > 0.0) {
                    bounced = true;
                    bounceTime = d.time;
                }
            }
            if (bounced) {
                apex = std::fmax(apex, y - floor);
                if (vy <= 0.0) {
                    apexFound = true;
                    bounceHeight = apex;
                }
            }
            previousVy = vy;
        }
    }
};

std::vector<double> metricValues(const Simulation& sim, const Observer& o, long steps, double wall) {
    const Diagnostics& d = sim.diagnostics();
    std::vector<double> v;
    if (o.gas)
        for (int l = 0; l < 2; ++l) v.insert(v.end(), {d.volume[l], o.volumeMin[l], o.volumeMax[l]});
    if (o.gas)
        for (int l = 0; l < 2; ++l) v.insert(v.end(), {d.pressure[l], o.pressureMin[l], o.pressureMax[l]});
    v.insert(v.end(), {d.kinetic, d.total(), d.energyDrift(), o.driftMax, o.bounceTime, o.bounceHeight, o.strainMax,
                       d.time, static_cast<double>(steps), static_cast<double>(d.forceEvaluations), wall});
    return v;
}

std::optional<std::string> checkValue(const ParameterSet& base, const std::string& key, double value) {
    ParameterSet p = base;
    return p.set(key, value);
}

}  // namespace

std::vector<std::string> sweepMetricNames(SceneKind kind) {
    std::vector<std::string> names;
    if (hasGas(kind))
        for (const char* q : {"volume", "pressure"})
            for (const char* layer : {"inner", "outer"})
                for (const char* what : {"final", "min", "max"})
                    names.push_back(std::string(q) + "_" + layer + "_" + what);
    for (const char* n : {"energy_kinetic_final", "energy_total_final", "energy_drift_final", "energy_drift_max",
                          "bounce_time", "bounce_height", "strain_max", "t_end", "steps", "force_evals", "wall_seconds"})
        names.emplace_back(n);
    return names;
}

SweepRange sweepRange(std::string_view kind, double a, double b, double n) {
    SweepRange r;
    const std::string what = std::string(kind) + "(" + numberText(a) + ", " + numberText(b) + ", " + numberText(n) + ")";
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(n) || n < 1 || n != std::floor(n) || n > 1e6)
        r.error = what + ": the ends must be finite and the count a whole number in [1, 1e6]";
    else if (kind != "linear" && (!(a > 0) || !(b > 0)))
        r.error = what + ": a logarithmic range needs both ends > 0";
    else if (kind == "decades" && !(b >= a))
        r.error = what + ": the end must not be below the start";
    else if (kind != "linear" && kind != "log" && kind != "decades")
        r.error = "unknown range " + quoteShort(kind) + "; allowed: linear, log, decades";
    if (!r.error.empty()) return r;
    const auto count = static_cast<long>(n);
    if (kind == "decades") {
        for (long i = 0;; ++i) {
            const double v = i % count == 0 ? a * std::pow(10.0, static_cast<double>(i / count))
                                            : a * std::pow(10.0, static_cast<double>(i) / n);
            if (v > b * (1 + 1e-12) || r.values.size() >= 1000000) break;
            r.values.push_back(v);
        }
        return r;
    }
    for (long i = 0; i < count; ++i) {
        const double f = count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(count - 1);
        r.values.push_back(i == 0 ? a : i == count - 1 ? b
                           : kind == "linear" ? a + (b - a) * f
                                              : std::exp(std::log(a) + (std::log(b) - std::log(a)) * f));
    }
    return r;
}

long sweepPointCount(const SweepSpec& spec) {
    if (!spec.points.empty()) return static_cast<long>(spec.points.size());
    long n = 1;
    for (const auto& axis : spec.axes) n *= static_cast<long>(axis.size());
    return n;
}

std::vector<double> sweepPoint(const SweepSpec& spec, long index) {
    if (!spec.points.empty()) return spec.points.at(static_cast<std::size_t>(index));
    std::vector<double> values(spec.axes.size());
    for (std::size_t k = spec.axes.size(); k-- > 0;) {  // the last key varies fastest
        const auto n = static_cast<long>(spec.axes[k].size());
        values[k] = spec.axes[k][static_cast<std::size_t>(index % n)];
        index /= n;
    }
    return values;
}

std::pair<long, long> sweepShard(const SweepSpec& spec, int shardIndex, int shardCount) {
    const long m = sweepPointCount(spec);
    return {m * shardIndex / shardCount, m * (shardIndex + 1) / shardCount};
}

std::optional<std::string> validateSweep(SweepSpec& spec) {
    if (auto error = unknownIntegrator(spec.integrator)) return error;
    if (!std::isfinite(spec.duration) || !(spec.duration > 0.0) || spec.duration > 1e7)
        return "duration = " + numberText(spec.duration) + " is out of range; allowed (0, 1e+07] s";
    if (!std::isfinite(spec.maxSteps) || spec.maxSteps < 1.0 || spec.maxSteps > 1e12)
        return "max_steps = " + numberText(spec.maxSteps) + " is out of range; allowed [1, 1e+12]";
    std::set<std::string> seen;
    bool shapeSwept = false;
    for (const std::string& key : spec.keys) {
        if (!seen.insert(key).second) return "grid: " + quoteShort(key) + " is given twice";
        const ParamSpec* p = findParam(key);
        if (!p || !spec.params.has(p->id)) {
            ParameterSet probe = spec.params;
            return probe.set(key, 0.0).value_or("grid: " + quoteShort(key) + " is not a parameter of this scene");
        }
        shapeSwept |= p->isShape();
    }
    if (spec.points.empty()) {
        if (spec.axes.size() != spec.keys.size()) return std::string("grid: one list of values per key");
        double count = 1.0;
        for (std::size_t k = 0; k < spec.keys.size(); ++k) {
            if (spec.axes[k].empty()) return "grid: " + spec.keys[k] + " has no values";
            std::set<double> values;
            for (double v : spec.axes[k]) {
                if (auto error = checkValue(spec.params, spec.keys[k], v)) return "grid: " + *error;
                if (!values.insert(v).second)
                    return "grid " + spec.keys[k] + ": " + quoteShort(sweepValueText(spec.keys[k], v)) + " is listed twice";
            }
            count *= static_cast<double>(spec.axes[k].size());
        }
        if (count > kMaxSweepPoints)
            return "grid: " + numberText(count) + " points; at most " + numberText(kMaxSweepPoints) + " per sweep";
    } else {
        if (static_cast<double>(spec.points.size()) > kMaxSweepPoints)
            return "samples: at most " + numberText(kMaxSweepPoints) + " per sweep";
        for (const auto& point : spec.points) {
            if (point.size() != spec.keys.size()) return std::string("grid: one value per key in every point");
            for (std::size_t k = 0; k < point.size(); ++k)
                if (auto error = checkValue(spec.params, spec.keys[k], point[k])) return "grid: " + *error;
        }
    }
    if (spec.state && shapeSwept)
        return std::string("grid: a scene file with a saved state fixes the body's shape; sweep a shape key "
                           "(subdivisions, ...) from a built-in scene or a scene file without state");
    // Every point's body with the integrator (memory, size), as a single run checks it.
    const long n = sweepPointCount(spec);
    for (long i = 0; i < (shapeSwept ? n : 1); ++i) {
        ParameterSet p = spec.params;
        const std::vector<double> values = sweepPoint(spec, i);
        for (std::size_t k = 0; k < values.size(); ++k) p.set(spec.keys[k], values[k]);
        if (auto error = validateShape(p, spec.integrator)) return error;
    }
    const std::vector<std::string> all = sweepMetricNames(spec.params.kind());
    if (spec.metrics.empty()) spec.metrics = all;
    std::set<std::string> metrics;
    for (const std::string& m : spec.metrics) {
        if (std::find(all.begin(), all.end(), m) == all.end()) {
            std::string list;
            for (const std::string& a : all) list += (list.empty() ? "" : ", ") + a;
            return "metrics: unknown " + quoteShort(m) + " for " + std::string(sceneInfo(spec.params.kind()).name) +
                   "; allowed: " + list;
        }
        if (!metrics.insert(m).second) return "metrics: " + m + " is listed twice";
    }
    return std::nullopt;
}

SweepRow runSweepPoint(const SweepSpec& spec, long index, const std::atomic<bool>* cancel) {
    SweepRow row;
    row.index = index;
    row.values = sweepPoint(spec, index);
    const std::vector<std::string> all = sweepMetricNames(spec.params.kind());
    auto want = [&](std::string_view name) { return std::find(spec.metrics.begin(), spec.metrics.end(), name) != spec.metrics.end(); };
    std::vector<double> values(all.size(), kNaN);
    const auto start = std::chrono::steady_clock::now();
    try {
        ParameterSet p = spec.params;
        for (std::size_t k = 0; k < row.values.size(); ++k)
            if (auto error = p.set(spec.keys[k], row.values[k])) throw std::invalid_argument(*error);
        Simulation sim(p, spec.integrator);
        sim.setIntegratorOptions(spec.options);
        if (spec.state)
            if (auto error = applyState(sim, *spec.state)) throw std::invalid_argument(*error);
        Observer o;
        o.gas = sim.diagnostics().hasGas;
        o.wantStrain = want("strain_max");
        o.wantBounce = want("bounce_time") || want("bounce_height");
        o.observe(sim);
        const double tEnd = sim.time() + spec.duration;
        const long firstStep = sim.stepCount();
        const bool fixed = !sim.integrator().adaptive() || spec.options.fixedStep;
        const double stepsNeeded = std::ceil(spec.duration / sim.dt() - 1e-9);
        if (fixed && stepsNeeded > spec.maxSteps) {
            row.status = "over budget";
            row.reason = "would take " + numberText(stepsNeeded) + " steps of dt " + numberText(sim.dt()) +
                         " s; at most " + numberText(spec.maxSteps) + " per point (max_steps)";
        } else {
            while (sim.time() < tEnd - 1e-9 * sim.dt()) {
                if (cancel && cancel->load(std::memory_order_relaxed)) {
                    row.status = "failed";
                    row.reason = "cancelled";
                    break;
                }
                if (!sim.step(tEnd)) break;
                o.observe(sim);
                const bool last = sim.time() >= tEnd - 1e-9 * sim.dt();
                if (static_cast<double>(sim.stepCount() - firstStep) >= spec.maxSteps && !last) {
                    row.status = "over budget";
                    row.reason = "stopped at t = " + numberText(sim.time()) + " s after " + numberText(spec.maxSteps) +
                                 " steps, the most per point (max_steps)";
                    break;
                }
            }
            if (sim.failed()) {
                const Failure& f = *sim.failure();
                row.status = "failed";
                row.reason = f.reason + " (step " + std::to_string(f.step) + ", t = " + numberText(f.time) + " s)";
            }
        }
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        values = metricValues(sim, o, sim.stepCount() - firstStep, wall);
    } catch (const std::exception& e) {  // a point that cannot be built (e.g. out of memory) is a failed row
        row.status = "failed";
        row.reason = e.what();
    }
    for (const std::string& m : spec.metrics)
        row.metrics.push_back(values[static_cast<std::size_t>(std::find(all.begin(), all.end(), m) - all.begin())]);
    return row;
}

std::vector<std::string> sweepColumns(const SweepSpec& spec) {
    std::vector<std::string> c{"index"};
    c.insert(c.end(), spec.keys.begin(), spec.keys.end());
    c.insert(c.end(), {"integrator", "status", "reason"});
    c.insert(c.end(), spec.metrics.begin(), spec.metrics.end());
    c.emplace_back("version");
    return c;
}

std::string sweepValueText(const std::string& key, double value) {
    const ParamSpec* p = findParam(key);
    if (p && !p->choices.empty()) return p->choiceName(value);
    return numberText(value);
}

std::string sweepCsvHeader(const SweepSpec& spec) {
    std::string line;
    for (const std::string& c : sweepColumns(spec)) line += (line.empty() ? "" : ",") + c;
    return line + "\n";
}

std::string sweepCsvRow(const SweepSpec& spec, const SweepRow& row) {
    std::string line = std::to_string(row.index);
    for (std::size_t k = 0; k < row.values.size(); ++k) line += "," + csvField(sweepValueText(spec.keys[k], row.values[k]));
    line += "," + spec.integrator + "," + row.status + "," + csvField(row.reason);
    for (double m : row.metrics) line += "," + numberText(m);
    return line + "," + elastic_lab::kVersion + "\n";
}

std::optional<long> sweepCsvRowIndex(const std::string& line) {
    const auto comma = line.find(',');
    const auto value = parseNumber(line.substr(0, comma));
    if (!value || *value < 0 || *value != std::floor(*value)) return std::nullopt;
    return static_cast<long>(*value);
}

// --- the spec as text --------------------------------------------------------------------------

std::string sweepSpecText(const SweepSpec& spec) {
    SceneFile base;
    base.sceneName = spec.sceneName;
    base.params = spec.params;
    base.integrator = spec.integrator;
    base.state = spec.state;
    const simcore::IntegratorOptions& o = spec.options;
    Json j = {{"format", "elastic-lab-sweep"},
              {"version", 1},
              {"scene", Json::parse(sceneFileText(base))},
              {"options",
               {{"atol", o.atol}, {"rtol", o.rtol}, {"fixed_step", o.fixedStep}, {"min_step", o.minStep},
                {"max_step", o.maxStep}, {"cg_tolerance", o.cgTolerance}, {"cg_max_iterations", o.cgMaxIterations},
                {"newton", o.newtonIterations}, {"error_estimate", o.stepDoubling}}},
              {"keys", spec.keys},
              {"axes", spec.axes},
              {"points", spec.points},
              {"duration", spec.duration},
              {"metrics", spec.metrics},
              {"max_steps", spec.maxSteps}};
    return j.dump();
}

SweepSpecResult parseSweepSpec(const std::string& text) {
    try {
        const Json j = Json::parse(text);
        if (j.value("format", "") != "elastic-lab-sweep" || j.value("version", 0) != 1)
            return {std::nullopt, "not a sweep of this version"};
        SceneFileResult scene = parseSceneFile(j.at("scene").dump());
        if (!scene.file) return {std::nullopt, scene.error};
        SweepSpec spec;
        spec.sceneName = scene.file->sceneName;
        spec.params = scene.file->params;
        spec.integrator = scene.file->integrator;
        spec.state = scene.file->state;
        const Json& o = j.at("options");
        spec.options.atol = o.at("atol").get<double>();
        spec.options.rtol = o.at("rtol").get<double>();
        spec.options.fixedStep = o.at("fixed_step").get<bool>();
        spec.options.minStep = o.at("min_step").get<double>();
        spec.options.maxStep = o.at("max_step").get<double>();
        spec.options.cgTolerance = o.at("cg_tolerance").get<double>();
        spec.options.cgMaxIterations = o.at("cg_max_iterations").get<int>();
        spec.options.newtonIterations = o.at("newton").get<int>();
        spec.options.stepDoubling = o.at("error_estimate").get<bool>();
        spec.keys = j.at("keys").get<std::vector<std::string>>();
        spec.axes = j.at("axes").get<std::vector<std::vector<double>>>();
        spec.points = j.at("points").get<std::vector<std::vector<double>>>();
        spec.duration = j.at("duration").get<double>();
        spec.metrics = j.at("metrics").get<std::vector<std::string>>();
        spec.maxSteps = j.at("max_steps").get<double>();
        if (auto error = validateSweep(spec)) return {std::nullopt, *error};
        return {std::move(spec), {}};
    } catch (const Json::exception& e) {
        return {std::nullopt, std::string("not a readable sweep: ") + e.what()};
    }
}

}  // namespace simlab
