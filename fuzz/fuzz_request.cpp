// Fuzz target: the one front door itself (simlab/request.h, issue 31), below every door's own
// parsing: a request of any shape, with any values, straight into resolveScene and the checks
// the CLI, the GUI and Python call. Nothing is run or written.
//
// Input: lines. The first names the check (run, study, refinement, stability, restitution,
// conservation, sweep, lanes, files; anything else: run); the others are key=value:
//   scene, set (repeatable), dt, integrator            the scene request
//   duration, max_steps, rows_every, sample_every, columns, fixed_step     a run
//   integrators, dts, tolerances, samples, reference, precisions, repeat   a study (lists: commas)
//   key, values, interval, temporal_runs, tolerance    a refinement
//   hmin, hmax, perturb                                a stability scan
//   speeds                                             restitution
//   periods                                            conservation
//   grid (KEY:v,v,...; repeatable), metrics           a sweep
//   in, out (repeatable)                               files (the tokens of fuzz/scratch.h)
// Numbers are read by strtod (nan, inf, hex and 1e400 included).
//
// Properties, beyond no crash and no sanitizer report: every refusal is a std::invalid_argument
// (the front door's RequestError, or simcore's) whose text is inert (no control byte) and short
// (under 2,000 bytes); nothing else escapes (a bad_alloc, out_of_range, runtime_error: abort);
// and what is accepted is within the bounds docs/reliability.md states (a run's duration in
// (0, 1e7] s and at most max_steps fixed steps; a stability trial of at least kMinTrialSteps
// and at most kMaxSteps steps with 0 < hmin <= hmax; a study's and a refinement's duration
// finite and positive).
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "fuzz/scratch.h"
#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simlab/conservation.h"
#include "simlab/refinement.h"
#include "simlab/request.h"
#include "simlab/stability.h"
#include "simlab/study.h"
#include "simlab/sweep.h"

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail = {}) {
    std::fprintf(stderr, "fuzz_request: %s %s\n", what, detail.c_str());
    std::abort();
}

double num(const std::string& text) { return std::strtod(text.c_str(), nullptr); }

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
        const auto comma = text.find(',', start);
        out.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
        if (comma == std::string::npos) return out;
        start = comma + 1;
    }
}

std::vector<double> numbers(const std::string& text) {
    std::vector<double> out;
    for (const std::string& item : split(text)) out.push_back(num(item));
    return out;
}

struct Input {
    std::string check = "run";
    std::multimap<std::string, std::string> values;
    bool has(const std::string& key) const { return values.count(key) > 0; }
    std::string get(const std::string& key, const std::string& otherwise = {}) const {
        const auto it = values.find(key);
        return it == values.end() ? otherwise : it->second;
    }
    std::vector<std::string> all(const std::string& key) const {
        std::vector<std::string> out;
        for (auto [it, end] = values.equal_range(key); it != end; ++it) out.push_back(it->second);
        return out;
    }
};

// Lines into an Input; false when a path names something outside the scratch folder.
bool parse(const std::uint8_t* data, std::size_t size, Input& in) {
    std::string text(reinterpret_cast<const char*>(data), size);
    std::size_t start = 0;
    bool first = true;
    while (start <= text.size()) {
        const auto nl = text.find('\n', start);
        std::string line = text.substr(start, nl == std::string::npos ? std::string::npos : nl - start);
        start = nl == std::string::npos ? text.size() + 1 : nl + 1;
        if (first) {
            first = false;
            if (line.find('=') == std::string::npos) {
                in.check = line;
                continue;
            }
        }
        const auto eq = line.find('=');
        if (eq == std::string::npos) continue;
        std::string key = line.substr(0, eq), value = line.substr(eq + 1);
        if ((key == "scene" || key == "in" || key == "out") && !fuzzscratch::substitute(value)) return false;
        in.values.emplace(key, value);
    }
    return true;
}

simlab::SceneRequest sceneRequest(const Input& in) {
    simlab::SceneRequest r;
    r.scene = in.get("scene", "ring2d");
    r.set = in.all("set");
    if (in.has("dt")) r.dt = in.get("dt");
    if (in.has("integrator")) r.integrator = in.get("integrator");
    return r;
}

void checkRun(const Input& in) {
    const simlab::SceneSetup setup = simlab::resolveScene(sceneRequest(in));
    simlab::RunRequest run;
    if (in.has("duration")) run.duration = num(in.get("duration"));
    if (in.has("max_steps")) run.maxSteps = num(in.get("max_steps"));
    if (in.has("rows_every")) run.rowsEvery = std::strtol(in.get("rows_every").c_str(), nullptr, 10);
    if (in.has("sample_every")) run.sampleEvery = num(in.get("sample_every"));
    if (in.has("columns")) run.rowColumns = static_cast<int>(std::strtol(in.get("columns").c_str(), nullptr, 10));
    run.options.fixedStep = in.get("fixed_step") == "1";
    simlab::checkRun(setup, run);
    // Accepted: within the stated bounds.
    if (!(run.duration > 0.0 && run.duration <= 1e7)) finding("run accepted with duration", simlab::number(run.duration));
    const double dt = setup.params.get(simcore::Param::Dt);
    const bool fixed = !simcore::makeIntegrator(setup.integrator)->adaptive() || run.options.fixedStep;
    const double limit = std::min(run.maxSteps, simlab::kMaxSteps);
    if (fixed && !(std::ceil(run.duration / dt - 1e-9) <= limit))
        finding("run accepted beyond its steps", simlab::number(run.duration / dt));
}

void checkStudy(const Input& in) {
    simlab::StudySpec spec;
    spec.params = simlab::resolveScene(sceneRequest(in)).params;
    spec.integrators = split(in.get("integrators", "rk4"));
    if (in.has("dts")) spec.dts = numbers(in.get("dts"));
    if (in.has("tolerances")) spec.tolerances = numbers(in.get("tolerances"));
    if (in.has("duration")) spec.duration = num(in.get("duration"));
    if (in.has("samples")) spec.samples = static_cast<int>(std::strtol(in.get("samples").c_str(), nullptr, 10));
    if (in.has("reference")) spec.reference = in.get("reference");
    if (in.has("precisions")) spec.precisions = split(in.get("precisions"));
    if (in.has("repeat")) spec.repeat = static_cast<int>(std::strtol(in.get("repeat").c_str(), nullptr, 10));
    simlab::checkStudy(spec);
    if (!(spec.duration > 0.0 && std::isfinite(spec.duration))) finding("study accepted with duration", simlab::number(spec.duration));
}

void checkRefinement(const Input& in) {
    simlab::RefinementSpec spec;
    spec.params = simlab::resolveScene(sceneRequest(in)).params;
    spec.key = in.get("key", "particles");
    for (double v : numbers(in.get("values", "12,24"))) spec.values.push_back(static_cast<int>(std::fmax(-1e9, std::fmin(1e9, v))));
    if (in.has("integrator")) spec.integrator = in.get("integrator");
    if (in.has("dt")) spec.dt = num(in.get("dt"));
    if (in.has("tolerance")) spec.tolerance = num(in.get("tolerance"));
    if (in.has("duration")) spec.duration = num(in.get("duration"));
    if (in.has("interval")) spec.interval = num(in.get("interval"));
    if (in.has("temporal_runs")) spec.temporalRuns = static_cast<int>(std::strtol(in.get("temporal_runs").c_str(), nullptr, 10));
    simlab::checkRefinement(spec);
    if (!(spec.duration > 0.0 && std::isfinite(spec.duration)))
        finding("refinement accepted with duration", simlab::number(spec.duration));
}

void checkStability(const Input& in) {
    simlab::StabilitySpec spec;
    spec.params = simlab::resolveScene(sceneRequest(in)).params;
    spec.integrators = split(in.get("integrators", "rk4"));
    if (in.has("duration")) spec.duration = num(in.get("duration"));
    if (in.has("hmin")) spec.hMin = num(in.get("hmin"));
    if (in.has("hmax")) spec.hMax = num(in.get("hmax"));
    if (in.has("perturb")) spec.perturb = num(in.get("perturb"));
    simlab::checkStability(spec);
    if (!(spec.hMin > 0.0 && spec.hMin <= spec.hMax && std::isfinite(spec.hMax)))
        finding("stability accepted with steps", simlab::number(spec.hMin) + " " + simlab::number(spec.hMax));
    const double steps = spec.duration / spec.hMin;
    if (!(steps >= simlab::kMinTrialSteps * (1 - 1e-12) && steps <= simlab::kMaxSteps * (1 + 1e-12)))
        finding("stability accepted with a trial of", simlab::number(steps));
}

void checkRestitution(const Input& in) {
    const simlab::SceneSetup setup = simlab::resolveScene(sceneRequest(in));
    simlab::checkRestitution(setup.params, numbers(in.get("speeds", "1")));
}

void checkConservation(const Input& in) {
    simlab::ConservationSpec spec;
    spec.params = simlab::resolveScene(sceneRequest(in)).params;
    spec.integrators = split(in.get("integrators", "verlet"));
    if (in.has("periods")) spec.periods = num(in.get("periods"));
    if (in.has("dt")) spec.dt = num(in.get("dt"));
    if (in.has("samples")) spec.samples = static_cast<int>(std::strtol(in.get("samples").c_str(), nullptr, 10));
    if (in.has("precisions")) spec.precision = in.get("precisions");
    simlab::checkConservation(spec);
}

void checkSweep(const Input& in) {
    const simlab::SceneSetup setup = simlab::resolveScene(sceneRequest(in));
    simlab::SweepSpec spec;
    spec.sceneName = setup.sceneName;
    spec.params = setup.params;
    spec.integrator = setup.integrator;
    spec.state = setup.state;
    if (in.has("duration")) spec.duration = num(in.get("duration"));
    if (in.has("max_steps")) spec.maxSteps = num(in.get("max_steps"));
    for (const std::string& g : in.all("grid")) {
        const auto colon = g.find(':');
        spec.keys.push_back(g.substr(0, colon));
        spec.axes.push_back(colon == std::string::npos ? std::vector<double>{} : numbers(g.substr(colon + 1)));
    }
    if (in.has("metrics")) spec.metrics = split(in.get("metrics"));
    simlab::checkSweep(spec);
    if (simlab::sweepPointCount(spec) > simlab::kMaxSweepPoints) finding("sweep accepted with too many points");
}

void checkFiles(const Input& in) {
    std::vector<simlab::NamedPath> inputs, outputs;
    for (const std::string& p : in.all("in")) inputs.push_back({"scene", p});
    for (const std::string& p : in.all("out")) outputs.push_back({"csv", p});
    for (const auto& [option, path] : outputs) simlab::checkOutputNamed(option, path);
    simlab::checkFiles(inputs, outputs);
}

void inert(const std::string& message) {
    if (message.empty()) finding("a refusal without a reason");
    if (message.size() >= 2000) finding("a refusal of", std::to_string(message.size()) + " bytes");
    for (unsigned char c : message)
        if (c < 0x20 || c == 0x7f) finding("a control byte in", simlab::quoted(message, 200));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Input in;
    if (!parse(data, size, in)) return 0;
    try {
        if (in.check == "study") checkStudy(in);
        else if (in.check == "refinement") checkRefinement(in);
        else if (in.check == "stability") checkStability(in);
        else if (in.check == "restitution") checkRestitution(in);
        else if (in.check == "conservation") checkConservation(in);
        else if (in.check == "sweep") checkSweep(in);
        else if (in.check == "files") checkFiles(in);
        else if (in.check == "lanes") simlab::checkLanes(simlab::resolveScene(sceneRequest(in)).params, split(in.get("integrators", "rk4")));
        else checkRun(in);
    } catch (const std::invalid_argument& e) {
        inert(e.what());
    } catch (const std::exception& e) {
        finding("escaped the front door:", e.what());
    }
    return 0;
}
