// elasticlab: simcore as a Python module (pybind11). The API and the decisions behind it are in
// docs/python.md; in short:
//
//   input     a scene name or a scene file and the parameters as keyword arguments, checked by
//             the parameter table (ParameterSet): ValueError with the table's own message, the
//             text the CLI prints after "error: --set "
//   state     positions and velocities are read-only numpy views onto the simulation's state
//             vector (no copy); the array's base is the Simulation, which they keep alive
//   stepping  in slices of at most kSlice wall time with the GIL released; between slices the
//             GIL is taken back and pending signals run, so Ctrl+C raises KeyboardInterrupt
//             with the simulation at the end of its last full step
//   studies   on a worker thread with simcore's cancel flag; the calling thread waits in
//             slices too and sets the flag on Ctrl+C. CSV and SVG come from simcore's writers.
//
// One thread steps a Simulation at a time: a second one gets RuntimeError, never a race.

#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#ifdef ELASTICLAB_EMBEDDED
#include <pybind11/embed.h>
#endif

#include "elastic_lab_version.h"
#include "simcore/body.h"
#include "simcore/float_path.h"
#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simcore/params.h"
#include "simcore/scenes.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/analytic.h"
#include "simlab/conservation.h"
#include "simlab/output.h"
#include "simlab/refinement.h"
#include "simlab/request.h"
#include "simlab/scenefile.h"
#include "simlab/stability.h"
#include "simlab/study.h"
#include "simlab/sweep.h"
#include "simlab/timeseries.h"

namespace py = pybind11;

namespace {

// The longest stretch of work between two looks at Python's pending signals (Ctrl+C): short
// enough to feel immediate, long enough that taking the GIL back costs nothing measurable.
// It only decides where a run may be interrupted, never what it computes.
constexpr std::chrono::milliseconds kSlice{50};

// elasticlab.SimulationFailed (a RuntimeError); the module holds the reference.
py::handle g_simulationFailed;
struct SimulationFailedTag {};

std::string pathText(const py::object& path) {
    return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

// --- input ------------------------------------------------------------------------------------

// A Python number (int, float, numpy scalar; not bool, not text) as a double, else TypeError.
double numberOf(const py::handle& value, const std::string& key, const char* expected = "a number") {
    if (py::isinstance<py::bool_>(value) || py::isinstance<py::str>(value) || !py::hasattr(value, "__float__"))
        throw py::type_error(key + ": expected " + expected + ", got " +
                             py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>());
    return py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
}

// A scene through the front door (simlab::resolveScene), as the CLI's --scene, --set and
// --integrator give it: the keyword parameters in the order given, each as `key=value` text
// (a number as its shortest text, as `--set key=value` would give it, nan and inf included).
// Its refusals are RequestError, a std::invalid_argument: ValueError with the CLI's text.
using Scene = simlab::SceneSetup;

std::string parameterText(const std::string& key, const py::handle& value) {
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();  // a number or a choice's name
    return py::repr(py::float_(numberOf(value, key, "a number or a name"))).cast<std::string>();
}

Scene sceneFrom(const py::object& scene, const py::kwargs& parameters, const py::object& integrator = py::none(),
                bool severalBodies = false) {
    simlab::SceneRequest request;
    request.scene = pathText(scene);
    request.severalBodies = severalBodies;  // where the CLI's command takes a world, so does Python
    for (const auto& [k, value] : parameters) {
        const std::string key = py::str(k).cast<std::string>();
        if (key.find('=') != std::string::npos)
            throw py::value_error("unknown parameter " + simlab::quoted(key) + " (a keyword holds no '=')");
        request.set.push_back(key + "=" + parameterText(key, value));
    }
    if (!integrator.is_none()) request.integrator = integrator.cast<std::string>();
    return simlab::resolveScene(request);
}

void checkIntegrator(const std::string& name) {
    if (auto error = simcore::unknownIntegrator(name)) throw py::value_error(*error);
}

// A number that is not a table parameter (a duration, an integrator option), checked and worded
// as the table checks its own: "atol = 2 is out of range; allowed (0, 1]".
double checkedNumber(const py::handle& value, std::string_view key, double min, double max, bool minExclusive,
                     bool integer = false, std::string_view unit = {}) {
    const double v = numberOf(value, std::string(key));
    simcore::ParamSpec spec{};
    spec.key = key;
    spec.unit = unit;
    spec.minValue = min;
    spec.maxValue = max;
    spec.minExclusive = minExclusive;
    spec.integer = integer;
    if (auto error = simcore::validateValue(spec, v)) throw py::value_error(*error);
    return v;
}

// Integrator options from a dict; the names are the CLI's (--atol, --rtol, --newton,
// --fixed-step, --error-estimate) and IntegratorOptions' other fields.
simcore::IntegratorOptions integratorOptions(const py::object& options, simcore::IntegratorOptions o = {}) {
    if (options.is_none()) return o;
    const auto flag = [](const py::handle& v, const std::string& key) {
        if (!py::isinstance<py::bool_>(v)) throw py::type_error(key + ": expected True or False");
        return v.cast<bool>();
    };
    for (const auto& [k, v] : options.cast<py::dict>()) {
        const std::string key = py::str(k).cast<std::string>();
        if (key == "atol") o.atol = checkedNumber(v, key, 0.0, 1.0, true);
        else if (key == "rtol") o.rtol = checkedNumber(v, key, 0.0, 1.0, false);
        else if (key == "newton") o.newtonIterations = static_cast<int>(checkedNumber(v, key, 1, 50, false, true));
        else if (key == "fixed_step") o.fixedStep = flag(v, key);
        else if (key == "error_estimate") o.stepDoubling = flag(v, key);
        else if (key == "min_step") o.minStep = checkedNumber(v, key, 0.0, 1.0, true, false, "s");
        else if (key == "max_step") o.maxStep = checkedNumber(v, key, 0.0, 1e6, false, false, "s");
        else if (key == "cg_tolerance") o.cgTolerance = checkedNumber(v, key, 0.0, 1.0, true);
        else if (key == "cg_max_iterations") o.cgMaxIterations = static_cast<int>(checkedNumber(v, key, 1, 1e6, false, true));
        else
            throw py::value_error("unknown integrator option " + simlab::quoted(key) +
                                  "; allowed: atol, rtol, newton, fixed_step, error_estimate, min_step, max_step, "
                                  "cg_tolerance, cg_max_iterations");
    }
    return o;
}

// --- running ---------------------------------------------------------------------------------

// Calls stepOnce() (which returns whether to go on) until it says stop, with the GIL released,
// taking the GIL back every kSlice to run pending signal handlers: a KeyboardInterrupt (or
// any exception a handler raises) propagates from between two calls.
// `between` (if any) runs with the GIL after every slice: a progress callback, which may raise.
template <class StepOnce>
void inSlices(StepOnce&& stepOnce, const std::function<void()>& between = {}) {
    for (bool more = true; more;) {
        {
            py::gil_scoped_release release;
            const auto start = std::chrono::steady_clock::now();
            do more = stepOnce();
            while (more && std::chrono::steady_clock::now() - start < kSlice);
        }
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (between) between();
    }
}

// Runs work(cancel) on a worker thread and waits for it in slices, GIL released; on a pending
// signal's exception it sets the cancel flag simcore's studies poll, waits for the worker to
// stop, and raises that exception.
template <class Work>
auto cancellable(Work&& work) {
    std::atomic<bool> cancel{false};
    auto result = std::async(std::launch::async, [&] { return work(&cancel); });
    for (;;) {
        {
            py::gil_scoped_release release;
            if (result.wait_for(kSlice) == std::future_status::ready) break;
        }
        if (PyErr_CheckSignals() != 0) {
            py::error_already_set interrupted;  // takes the pending exception
            cancel = true;
            {
                py::gil_scoped_release release;
                result.wait();
            }
            throw interrupted;
        }
    }
    py::gil_scoped_release release;  // get() may rethrow a C++ exception: pybind11 translates it
    return result.get();
}

// One thread at a time steps a Simulation: a second thread that calls in while one steps gets
// RuntimeError instead of a data race (the stepping thread does not hold the GIL).
class Busy {
public:
    explicit Busy(std::atomic<bool>& flag) : m_flag(flag) {
        if (m_flag.exchange(true, std::memory_order_acquire))
            throw std::runtime_error("this Simulation is being stepped by another thread");
    }
    ~Busy() { m_flag.store(false, std::memory_order_release); }
    Busy(const Busy&) = delete;
    Busy& operator=(const Busy&) = delete;

private:
    std::atomic<bool>& m_flag;
};

// Every parameter of a set, resolved (explicit or from the table); choices by name.
py::dict parameterDict(const simcore::ParameterSet& p) {
    py::dict out;
    for (const simcore::ParamSpec* spec : simcore::parametersFor(p.kind())) {
        const double v = p.get(spec->id);
        const std::string name = spec->choiceName(v);
        if (name.empty()) out[py::str(std::string(spec->key))] = v;
        else out[py::str(std::string(spec->key))] = name;
    }
    return out;
}

py::dict optionsDict(const simcore::IntegratorOptions& o) {
    return py::dict(py::arg("atol") = o.atol, py::arg("rtol") = o.rtol, py::arg("newton") = o.newtonIterations,
                    py::arg("fixed_step") = o.fixedStep, py::arg("error_estimate") = o.stepDoubling,
                    py::arg("min_step") = o.minStep, py::arg("max_step") = o.maxStep,
                    py::arg("cg_tolerance") = o.cgTolerance, py::arg("cg_max_iterations") = o.cgMaxIterations);
}

// Rows recorded one after another (`width` values each) as an array, one row per line.
py::object rowsArray(const std::vector<double>& rows, std::size_t width) {
    const auto w = static_cast<py::ssize_t>(width);
    py::array_t<double> a({static_cast<py::ssize_t>(rows.size()) / w, w});
    std::copy(rows.begin(), rows.end(), a.mutable_data());
    return a;
}

// A run's csv= and xlsx= through the front door (an empty name, a FIFO, one over the other)
// and its CSV dialect.
simlab::TimeSeriesFiles checkedFiles(const py::object& csvPath, const py::object& xlsxPath, const std::string& dialectName) {
    const auto dialect = simlab::csvDialectNamed(dialectName);
    if (!dialect) throw py::value_error(simlab::unknownCsvDialectMessage(dialectName));
    simlab::TimeSeriesFiles files{csvPath.is_none() ? "" : pathText(csvPath), *dialect,
                                  xlsxPath.is_none() ? "" : pathText(xlsxPath)};
    if (!csvPath.is_none()) simlab::checkOutputNamed("csv", files.csv);
    if (!xlsxPath.is_none()) simlab::checkOutputNamed("xlsx", files.xlsx);
    simlab::checkFiles({}, {{"csv", files.csv}, {"xlsx", files.xlsx}});
    return files;
}

// What a run samples, checked by the front door before it starts: the duration, rows every so
// many steps (`every`), at given times or every so many seconds (`times`, built here after the
// rows they make are bounded), within the steps of a fixed-step run and the memory rows may hold.
struct Sampling {
    double duration = 0.0;
    long every = 0;
    std::vector<double> times;
    bool sampled = false;
};

Sampling checkedSampling(const simcore::ParameterSet& params, const std::string& integrator,
                         const simcore::IntegratorOptions& options, double start, std::size_t columns,
                         const py::handle& durationArg, const py::object& everyArg, const py::object& timesArg,
                         const py::object& everySecondsArg, const std::string& precision = "double") {
    Sampling s;
    s.duration = checkedNumber(durationArg, "duration", 0.0, 1e7, true, false, "s");
    s.every = everyArg.is_none() ? 0 : static_cast<long>(checkedNumber(everyArg, "every", 1, 1e9, false, true));
    const double everySeconds =
        everySecondsArg.is_none() ? 0.0 : checkedNumber(everySecondsArg, "every", 0.0, 1e7, true, false, "s");
    simlab::SceneSetup setup;
    setup.params = params;
    setup.integrator = integrator;
    simlab::RunRequest request;
    request.duration = s.duration;
    request.rowsEvery = s.every;
    request.sampleEvery = everySeconds;
    request.rowColumns = static_cast<int>(columns);
    request.options = options;
    request.precision = precision;
    simlab::checkRun(setup, request);
    s.times = timesArg.is_none() ? std::vector<double>{} : timesArg.cast<std::vector<double>>();
    if (everySeconds > 0.0) {  // the start, every so many seconds, within the bound just checked
        const auto count = static_cast<long>(std::floor(s.duration / everySeconds + 1e-9));
        s.times.clear();
        for (long k = 0; k <= count; ++k) s.times.push_back(start + static_cast<double>(k) * everySeconds);
    }
    s.sampled = s.every || everySeconds > 0.0 || !timesArg.is_none();
    return s;
}

// Runs `sim` (a Simulation or a World) for `duration` seconds of simulated time (whole steps; a
// fixed-step run ends at the first step at or past the end, as the CLI's run). Rows of the
// diagnostics (`columns`), one per line, are recorded at the start, every `every` steps and the
// end, or at `times` (absolute simulated times, ascending): the first step at or past each (an
// adaptive method shortens its step to land on it, as it does at the end). `progress`, when
// given, is called with the simulated time between slices of work; `published` after each step;
// `recorded` with the diagnostics of each row recorded (a file writer takes them).
// Returns the rows as an array, or None when nothing was sampled.
template <class Sim, class Columns, class Published, class Recorded>
py::object sampledRun(Sim& sim, const Columns& columns, const Sampling& s, const py::object& progress, Published&& published,
                      Recorded&& recorded) {
    const double duration = s.duration;
    const long every = s.every;
    const std::vector<double>& times = s.times;
    const bool sampled = s.sampled;
    std::vector<double> rows;
    auto record = [&] {
        for (const auto& c : columns) rows.push_back(c.value(sim.diagnostics()));
        recorded(sim.diagnostics());
    };
    std::size_t next = 0;  // the next of `times` not yet recorded
    auto due = [&] {       // records one row for every sample time reached (one per step)
        bool reached = false;
        while (next < times.size() && sim.time() >= times[next] - 1e-9 * sim.dt()) ++next, reached = true;
        return reached;
    };
    if (every || due()) record();
    const long firstStep = sim.stepCount();
    const double tEnd = sim.time() + duration;
    auto reached = [&] { return sim.time() >= tEnd - 1e-9 * sim.dt(); };
    std::function<void()> between;
    if (!progress.is_none()) between = [&] { progress(sim.time()); };
    if (!reached())
        inSlices([&] {
            const bool ok = sim.step(next < times.size() ? std::min(tEnd, times[next]) : tEnd);
            published();
            if (!ok) return false;
            const bool last = reached();
            const bool sample = due();
            if ((every && (sim.stepCount() % every == 0 || last)) || sample || (last && sampled && !every)) record();
            // An adaptive run stops at the bound, as the CLI's (its rows up to there kept).
            if (!last && static_cast<double>(sim.stepCount() - firstStep) >= simlab::kMaxSteps)
                throw std::runtime_error("run stopped at step " + std::to_string(sim.stepCount()) + ": " +
                                         simlab::number(simlab::kMaxSteps) + " steps taken, the most one run may take");
            return !last;
        }, between);
    return sampled ? rowsArray(rows, columns.size()) : py::none();
}

// One body as sampledRun steps it: the Simulation, or the float path started from it
// (precision="float", a fixed step: it ends at the first step at or past the end).
struct OneBody {
    simcore::Simulation& sim;
    simcore::FloatSimulation* single;  // null: the double path
    const simcore::Diagnostics& diagnostics() const { return single ? single->diagnostics() : sim.diagnostics(); }
    double time() const { return single ? single->time() : sim.time(); }
    long stepCount() const { return single ? single->stepCount() : sim.stepCount(); }
    double dt() const { return sim.dt(); }
    bool step(double until) { return single ? single->step() : sim.step(until); }
};

class PySimulation {
public:
    PySimulation(const py::object& scene, const py::object& integrator, const py::object& options,
                 const py::object& threads, const py::kwargs& parameters) {
        const Scene s = sceneFrom(scene, parameters, integrator);  // the integrator's memory too, as the CLI
        m_scene = s.sceneName;
        m_sim = std::make_unique<simcore::Simulation>(s.params, s.integrator);
        m_sim->setIntegratorOptions(integratorOptions(options));
        if (!threads.is_none()) m_sim->setThreads(static_cast<int>(checkedNumber(threads, "threads", 1, 256, false, true)));
        if (s.state)
            if (auto error = simlab::applyState(*m_sim, *s.state)) throw py::value_error(*error);
        m_columns = simlab::timeSeriesColumns(s.params.kind());
        constructed().insert(this);
        publish();
    }
    ~PySimulation() { constructed().erase(this); }
    PySimulation(const PySimulation&) = delete;
    PySimulation& operator=(const PySimulation&) = delete;

    // Pickling (through the scene file format): the scene file with the state, the integrator
    // options and the thread count. A restored simulation goes on bit for bit (the state, the
    // step counter, time and an adaptive method's next step are in the scene file).
    py::tuple getState() const {
        return py::make_tuple(simlab::sceneFileText(sim(), m_scene, true), integratorOptionsDict(), sim().threads());
    }
    static std::unique_ptr<PySimulation> fromState(const py::tuple& state) {
        if (state.size() != 3) throw std::runtime_error("not a pickled elasticlab.Simulation");
        simlab::SceneFileResult read = simlab::parseSceneFile(state[0].cast<std::string>());
        if (!read.file) throw py::value_error(read.error);
        auto self = std::unique_ptr<PySimulation>(new PySimulation());
        self->m_scene = read.file->sceneName;
        self->m_sim = std::make_unique<simcore::Simulation>(read.file->params, read.file->integrator);
        self->m_sim->setIntegratorOptions(integratorOptions(state[1]));
        self->m_sim->setThreads(state[2].cast<int>());
        if (read.file->state)
            if (auto error = simlab::applyState(*self->m_sim, *read.file->state)) throw py::value_error(*error);
        self->m_columns = simlab::timeSeriesColumns(read.file->params.kind());
        self->publish();
        constructed().insert(self.get());
        return self;
    }

    // Simulated time and step count as the stepping thread last published them: readable from
    // any thread at any moment (a progress bar beside a running run).
    double time() const { return initialised().m_time.load(std::memory_order_relaxed); }
    long stepCount() const { return initialised().m_steps.load(std::memory_order_relaxed); }

    // Simulation.__new__(Simulation) without __init__: pybind11 hands the methods raw,
    // never-constructed memory; only objects whose constructor ran are in the set.
    const PySimulation& initialised() const {
        if (!constructed().contains(this)) throw std::runtime_error("this Simulation was not initialised; create it with Simulation(scene, ...)");
        return *this;
    }

    // For reading: refused while another thread steps (a look, not a claim: a reader never
    // makes a stepping thread fail).
    const simcore::Simulation& sim() const {
        initialised();
        if (m_busy.load(std::memory_order_acquire))
            throw std::runtime_error("this Simulation is being stepped by another thread");
        return *m_sim;
    }

    // Steps n times; SimulationFailed when a step fails.
    void step(const py::handle& count) {
        const long n = static_cast<long>(checkedNumber(count, "n", 1, 1e12, false, true));
        sim();
        Busy busy(m_busy);
        long done = 0;
        inSlices([&] {
            const bool more = m_sim->step() && ++done < n;
            publish();
            return more;
        });
        raiseIfFailed(py::none());
    }

    // Runs for `duration` seconds of simulated time (whole steps; a fixed-step run ends at the
    // first step at or past the end, as the CLI's run). Rows of the diagnostics (columns as
    // diagnostics_columns), one per line, are recorded at the start, every `every` steps and the
    // end, or at `times` (absolute simulated times, ascending): the first step at or past each
    // (an adaptive method shortens its step to land on it, as it does at the end). `progress`,
    // when given, is called with the simulated time between slices of work. csv= and xlsx= write
    // the same rows in the CLI's `run --csv/--xlsx` formats (its columns), the CSV in csv_dialect.
    py::object run(const py::handle& durationArg, const py::object& everyArg, const py::object& timesArg,
                   const py::object& progress, const py::object& csvPath, const py::object& xlsxPath,
                   const std::string& dialectName, const py::object& everySecondsArg, const std::string& precision) {
        const Sampling s = checkedSampling(sim().parameters(), std::string(sim().integrator().name()), sim().integratorOptions(),
                                           m_sim->time(), m_columns.size(), durationArg, everyArg, timesArg, everySecondsArg,
                                           precision);
        const simlab::TimeSeriesFiles files = checkedFiles(csvPath, xlsxPath, dialectName);
        const simcore::SceneKind kind = m_sim->parameters().kind();
        simlab::TimeSeriesWriter writer(kind, simlab::timeSeriesColumns(kind, m_sim->diagnostics().hasSolverCounters),
                                         files);
        if (!writer.ok()) throw py::value_error(writer.error());
        // precision="float": the float path (simcore/float_path.h) steps the run from this state,
        // with this simulation's threads; its rows are its diagnostics (measured in double), and
        // the simulation takes its end state (in double) afterwards, as the CLI's run.
        std::unique_ptr<simcore::FloatSimulation> single;
        if (precision == "float") {
            single = std::make_unique<simcore::FloatSimulation>(*m_sim);
            single->setThreads(m_sim->threads());
        }
        Busy busy(m_busy);
        OneBody body{*m_sim, single.get()};
        const py::object table = sampledRun(
            body, m_columns, s, progress, [&] { single ? publish(single->time(), single->stepCount()) : publish(); },
            [&](const simcore::Diagnostics& d) {
                if (files.any()) writer.add(d);
            });
        // A failed float run leaves the simulation at its start (the float state at a failure
        // may not be finite); a good one hands its end state over.
        if (single && !single->failed()) {
            single->writeStateTo(*m_sim);
            publish();
        }
        // The files hold the run so far also when it failed (as the CLI's).
        if (files.any() && !writer.commit()) throw py::value_error(writer.error());
        raiseIfFailed(table, single ? single->failure() : m_sim->failure());
        return table;
    }

    void reset() {
        sim();
        Busy busy(m_busy);
        m_sim->reset();
        publish();
    }

    // A read-only view of 3 x N doubles of the state (positions or velocities) as N x 3.
    py::array stateView(const py::object& self, bool velocities) {
        const simcore::Simulation& s = sim();
        const double* data = velocities ? s.velocities().data() : s.positions().data();
        py::array view(py::dtype::of<double>(), {static_cast<py::ssize_t>(s.particleCount()), py::ssize_t{3}},
                       {static_cast<py::ssize_t>(3 * sizeof(double)), static_cast<py::ssize_t>(sizeof(double))}, data,
                       self);
        view.attr("setflags")(py::arg("write") = false);
        return view;
    }

    py::dict diagnostics() {
        const simcore::Diagnostics& d = sim().diagnostics();
        py::dict out;
        for (const simlab::CsvColumn& c : m_columns) out[py::str(c.name)] = c.value(d);
        return out;
    }
    py::array_t<double> diagnosticsRow() {
        const simcore::Diagnostics& d = sim().diagnostics();
        py::array_t<double> row(static_cast<py::ssize_t>(m_columns.size()));
        for (std::size_t i = 0; i < m_columns.size(); ++i) row.mutable_at(i) = m_columns[i].value(d);
        return row;
    }
    std::vector<std::string> columns() const {
        sim();
        std::vector<std::string> names;
        for (const simlab::CsvColumn& c : m_columns) names.push_back(c.name);
        return names;
    }

    py::object failure() {
        const auto& f = sim().failure();
        if (!f) return py::none();
        return py::dict(py::arg("reason") = f->reason, py::arg("step") = f->step, py::arg("time") = f->time);
    }

    // Every parameter of the scene, resolved (explicit or from the table).
    py::dict parameters() {
        return parameterDict(sim().parameters());
    }

    py::dict integratorOptionsDict() const {
        return optionsDict(sim().integratorOptions());
    }
    void setIntegrator(const std::string& name, const py::object& options) {
        checkIntegrator(name);
        const simcore::IntegratorOptions o = integratorOptions(options, sim().integratorOptions());
        Busy busy(m_busy);
        if (auto error = m_sim->setIntegrator(name)) throw py::value_error(*error);
        m_sim->setIntegratorOptions(o);
    }

    // The closed-form positions and velocities at the current time (spring1d only).
    py::tuple exact() {
        const simcore::Simulation& s = sim();
        if (!simlab::hasClosedForm(s.parameters()))
            throw py::value_error("no closed form for scene " + simlab::quoted(m_scene) + "; spring1d has one");
        Eigen::Matrix3Xd x, v;
        simlab::spring1dExact(s.parameters(), s.time(), x, v);
        auto table = [](const Eigen::Matrix3Xd& m) {
            py::array_t<double> a({static_cast<py::ssize_t>(m.cols()), py::ssize_t{3}});
            std::copy(m.data(), m.data() + m.size(), a.mutable_data());
            return a;
        };
        return py::make_tuple(table(x), table(v));
    }

    void saveScene(const py::object& path) {
        const std::string text = simlab::sceneFileText(sim(), m_scene, true);
        simlab::checkFiles({}, {{"save-scene", pathText(path)}});
        simlab::AtomicFile file(pathText(path));
        if (!file.ok() || !file.write(text) || !file.commit()) throw py::value_error(file.error());
    }

    const std::string& scene() const {
        sim();
        return m_scene;
    }

    std::string repr() const {
        if (!constructed().contains(this)) return "<elasticlab.Simulation, not initialised>";
        if (m_busy.load(std::memory_order_acquire)) return "<elasticlab.Simulation '" + m_scene + "', stepping>";
        char text[160];
        std::snprintf(text, sizeof text, ", %d particles, step %ld, t = %g s%s>", m_sim->particleCount(),
                      m_sim->stepCount(), m_sim->time(), m_sim->failed() ? ", failed" : "");
        return "<elasticlab.Simulation '" + m_scene + "', " + std::string(m_sim->integrator().name()) + text;
    }

private:
    PySimulation() = default;
    void publish() { publish(m_sim->time(), m_sim->stepCount()); }
    void publish(double time, long steps) {
        m_time.store(time, std::memory_order_relaxed);
        m_steps.store(steps, std::memory_order_relaxed);
    }
    // The Simulations whose constructor completed (read and changed with the GIL held).
    static std::set<const PySimulation*>& constructed() {
        static std::set<const PySimulation*> live;
        return live;
    }

    // SimulationFailed("simulation failed at step S, t = T s: reason") with .reason, .step,
    // .time and, from run(every=...), .rows up to the last good step.
    void raiseIfFailed(const py::object& rows) { raiseIfFailed(rows, m_sim->failure()); }
    void raiseIfFailed(const py::object& rows, const std::optional<simcore::Failure>& f) {
        if (!f) return;
        char where[96];
        std::snprintf(where, sizeof where, "simulation failed at step %ld, t = %g s: ", f->step, f->time);
        py::object e = g_simulationFailed(where + f->reason);
        e.attr("reason") = f->reason;
        e.attr("step") = f->step;
        e.attr("time") = f->time;
        e.attr("rows") = rows;
        PyErr_SetObject(g_simulationFailed.ptr(), e.ptr());
        throw py::error_already_set();
    }

    std::string m_scene;
    std::unique_ptr<simcore::Simulation> m_sim;
    std::vector<simlab::CsvColumn> m_columns;
    std::atomic<bool> m_busy{false};
    std::atomic<double> m_time{0.0};
    std::atomic<long> m_steps{0};
};

// --- worlds: scenes of several bodies ----------------------------------------------------------

// A value as `--set key=value` text: a name as given, a number as Python's shortest repr.
std::string assignmentText(const py::handle& value, const std::string& key) {
    if (py::isinstance<py::str>(value)) return value.cast<std::string>();
    return py::repr(py::float_(numberOf(value, key, "a number or a name"))).cast<std::string>();
}

void assignWorldValue(simcore::WorldSpec& spec, const std::string& assignment) {
    if (auto error = simcore::assignWorld(spec, assignment)) throw py::value_error(*error);
}

// [x, y, z] (or [x, y] for the plane) as a vector.
Eigen::Vector3d vectorOf(const py::handle& value, const std::string& key) {
    const auto list = py::reinterpret_borrow<py::object>(value).cast<std::vector<py::object>>();
    if (list.size() != 2 && list.size() != 3) throw py::value_error(key + ": expected (x, y) or (x, y, z)");
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < list.size(); ++k) v[static_cast<Eigen::Index>(k)] = numberOf(list[k], key);
    return v;
}

// bodies=[{"kind": "sphere3d", "position": (x, y, z), "velocity": (...), "mass": 4, ...}, ...]:
// each body's kind, start and own parameters, every refusal naming the body as bodyN.key.
simcore::WorldSpec worldFromList(const std::string& name, const py::list& bodies) {
    simcore::WorldSpec spec;
    spec.name = name;
    if (bodies.empty()) throw py::value_error("bodies: a world needs at least one body");
    if (bodies.size() > static_cast<std::size_t>(simcore::kMaxBodies))
        throw py::value_error("bodies: " + std::to_string(bodies.size()) + " bodies; at most " +
                              std::to_string(simcore::kMaxBodies));
    for (std::size_t k = 0; k < bodies.size(); ++k) {
        const std::string label = "body" + std::to_string(k + 1);
        if (!py::isinstance<py::dict>(bodies[k])) throw py::type_error(label + ": expected a dict with kind, position, velocity, parameters");
        const auto body = bodies[k].cast<py::dict>();
        if (!body.contains("kind")) throw py::value_error(label + ".kind: missing (ring2d, sphere3d, sphere3d-latlong)");
        const std::string kind = py::str(body["kind"]).cast<std::string>();
        const simcore::SceneInfo* info = simcore::findScene(kind);
        if (!info || info->kind == simcore::SceneKind::Spring1d)
            throw py::value_error(label + ".kind: unknown body kind " + simcore::quoteShort(kind) +
                                  "; allowed: ring2d, sphere3d, sphere3d-latlong");
        simcore::WorldBodySpec b;
        b.params = simcore::ParameterSet(info->kind);
        spec.bodies.push_back(b);
    }
    for (std::size_t k = 0; k < bodies.size(); ++k) {
        const std::string prefix = "body" + std::to_string(k + 1) + ".";
        for (const auto& [keyObject, value] : bodies[k].cast<py::dict>()) {
            const std::string key = py::str(keyObject).cast<std::string>();
            if (key == "kind") continue;
            if (key == "position" || key == "velocity") {
                const Eigen::Vector3d v = vectorOf(value, prefix + key);
                for (int axis = 0; axis < 3; ++axis)
                    assignWorldValue(spec, prefix + key + "_" + "xyz"[axis] + "=" + simlab::formatDouble(v[axis]));
                continue;
            }
            assignWorldValue(spec, prefix + key + "=" + assignmentText(value, prefix + key));
        }
    }
    return spec;
}

class PyWorld {
public:
    PyWorld(const py::object& scene, const py::object& bodies, const py::object& set, const py::object& integrator,
            const py::object& options, const py::kwargs& parameters) {
        // Through the front door, as `run` takes a scene: keywords set every body (as --set
        // key=value), then set=["body2.mass=4", ...] one body; each key once.
        const std::string name = scene.is_none() ? std::string("world") : pathText(scene);
        simlab::SceneRequest request;
        request.scene = name;
        request.severalBodies = true;
        for (const auto& [key, value] : parameters) {
            const std::string k = py::str(key).cast<std::string>();
            request.set.push_back(k + "=" + assignmentText(value, k));
        }
        if (!set.is_none())
            for (const std::string& assignment : set.cast<std::vector<std::string>>()) request.set.push_back(assignment);
        if (!integrator.is_none()) request.integrator = integrator.cast<std::string>();
        simlab::SceneSetup setup;
        if (!bodies.is_none()) {
            setup = simlab::resolveWorld(worldFromList(name, bodies.cast<py::list>()), request);
        } else if (simcore::findScene(name)) {
            throw py::value_error(name + " is one body: elasticlab.Simulation takes it");
        } else {
            setup = simlab::resolveScene(request);
            if (!setup.world) throw py::value_error(simlab::quoted(name, 200) + " holds one body: elasticlab.Simulation takes it");
        }
        build(*setup.world, setup.integrator, integratorOptions(options), setup.state);
    }

    static std::unique_ptr<PyWorld> fromState(const py::tuple& state) {
        if (state.size() != 2) throw std::runtime_error("not a pickled elasticlab.World");
        simlab::SceneFileResult read = simlab::parseSceneFile(state[0].cast<std::string>());
        if (!read.file || !read.file->world) throw py::value_error(read.error);
        auto self = std::unique_ptr<PyWorld>(new PyWorld());
        self->build(*read.file->world, read.file->integrator, integratorOptions(state[1]), read.file->state);
        return self;
    }
    py::tuple getState() const { return py::make_tuple(simlab::sceneFileText(world(), true), optionsDict()); }

    const simcore::World& world() const {
        if (m_busy.load(std::memory_order_acquire)) throw std::runtime_error("this World is being stepped by another thread");
        return *m_world;
    }

    void step(const py::handle& count) {
        const long n = static_cast<long>(checkedNumber(count, "n", 1, 1e12, false, true));
        Busy busy(m_busy);
        long done = 0;
        inSlices([&] { return m_world->step() && ++done < n; });
        raiseIfFailed(py::none());
    }

    // As Simulation.run (sampledRun).
    py::object run(const py::handle& durationArg, const py::object& everyArg, const py::object& timesArg,
                   const py::object& progress, const py::object& everySecondsArg) {
        const Sampling s = checkedSampling(m_world->spec().bodies.front().params, std::string(m_world->integrator().name()),
                                           m_world->integratorOptions(), m_world->time(), m_columns.size(), durationArg,
                                           everyArg, timesArg, everySecondsArg);
        Busy busy(m_busy);
        py::object table = sampledRun(*m_world, m_columns, s, progress, [] {}, [](const auto&) {});
        raiseIfFailed(table);
        return table;
    }

    void reset() {
        Busy busy(m_busy);
        m_world->reset();
    }

    // A read-only N x 3 view of particles [first, first + count) of the positions or velocities.
    py::array view(const py::object& owner, bool velocities, int first, int count) const {
        const simcore::World& w = world();
        const double* data = w.state().data() + (velocities ? 3 * Eigen::Index{w.particleCount()} : 0) + 3 * first;
        py::array out(py::dtype::of<double>(), {static_cast<py::ssize_t>(count), py::ssize_t{3}},
                      {static_cast<py::ssize_t>(3 * sizeof(double)), static_cast<py::ssize_t>(sizeof(double))}, data, owner);
        out.attr("setflags")(py::arg("write") = false);
        return out;
    }

    py::dict diagnostics() const {
        py::dict out;
        for (const simlab::WorldCsvColumn& c : m_columns) out[py::str(c.name)] = c.value(world().diagnostics());
        return out;
    }
    std::vector<std::string> columns() const {
        std::vector<std::string> names;
        for (const simlab::WorldCsvColumn& c : m_columns) names.push_back(c.name);
        return names;
    }
    py::object failure() const {
        const simcore::World& w = world();
        if (!w.failed()) return py::none();
        return py::dict(py::arg("reason") = *w.failure(), py::arg("step") = w.failedStep(), py::arg("time") = w.failedTime());
    }
    void saveScene(const py::object& path) const {
        const std::string text = simlab::sceneFileText(world(), true);
        simlab::AtomicFile file(pathText(path));
        if (!file.ok() || !file.write(text) || !file.commit()) throw py::value_error(file.error());
    }
    py::dict optionsDict() const {
        return ::optionsDict(m_options);
    }
    std::string repr() const {
        if (m_busy.load(std::memory_order_acquire)) return "<elasticlab.World '" + m_world->spec().name + "', stepping>";
        char text[160];
        std::snprintf(text, sizeof text, ", %d bodies, %d particles, step %ld, t = %g s%s>", m_world->bodyCount(),
                      m_world->particleCount(), m_world->stepCount(), m_world->time(), m_world->failed() ? ", failed" : "");
        return "<elasticlab.World '" + m_world->spec().name + "', " + std::string(m_world->integrator().name()) + text;
    }

private:
    PyWorld() = default;
    void build(const simcore::WorldSpec& spec, const std::string& integrator, const simcore::IntegratorOptions& options,
               const std::optional<simlab::SceneFile::State>& state) {
        try {
            m_world = std::make_unique<simcore::World>(spec, integrator);
        } catch (const std::invalid_argument& e) {
            throw py::value_error(e.what());
        }
        m_options = options;
        m_world->setIntegratorOptions(options);
        if (state)
            if (auto error = simlab::applyState(*m_world, *state)) throw py::value_error(*error);
        m_columns = simlab::worldColumns(*m_world);
    }
    void raiseIfFailed(const py::object& rows) {
        if (!m_world->failed()) return;
        const std::string& reason = *m_world->failure();
        char where[96];
        std::snprintf(where, sizeof where, "simulation failed at step %ld, t = %g s: ", m_world->failedStep(),
                      m_world->failedTime());
        py::object e = g_simulationFailed(where + reason);
        e.attr("reason") = reason;
        e.attr("step") = m_world->failedStep();
        e.attr("time") = m_world->failedTime();
        e.attr("rows") = rows;
        PyErr_SetObject(g_simulationFailed.ptr(), e.ptr());
        throw py::error_already_set();
    }

    std::unique_ptr<simcore::World> m_world;
    simcore::IntegratorOptions m_options;
    std::vector<simlab::WorldCsvColumn> m_columns;
    std::atomic<bool> m_busy{false};
};

// world.bodies[k]: a view of one body of a world (it keeps the world alive).
struct PyWorldBody {
    py::object owner;  // the PyWorld
    int index = 0;     // from 0
    const PyWorld& py() const { return owner.cast<const PyWorld&>(); }
    const simcore::World& world() const { return py().world(); }

    py::dict parameters() const {
        return parameterDict(world().spec().bodies[static_cast<std::size_t>(index)].params);
    }
    py::dict diagnostics() const {
        const simcore::BodyDiagnostics& b = world().diagnostics().bodies[static_cast<std::size_t>(index)];
        auto vec = [](const Eigen::Vector3d& v) { return py::make_tuple(v.x(), v.y(), v.z()); };
        return py::dict(py::arg("mass") = b.mass, py::arg("kinetic") = b.kinetic, py::arg("com") = vec(b.com),
                        py::arg("velocity") = vec(b.velocity), py::arg("momentum") = vec(b.mass * b.velocity),
                        py::arg("volume_inner") = b.volume[0], py::arg("volume_outer") = b.volume[1],
                        py::arg("rest_volume_inner") = b.restVolume[0], py::arg("rest_volume_outer") = b.restVolume[1],
                        py::arg("pressure_inner") = b.pressure[0], py::arg("pressure_outer") = b.pressure[1]);
    }
    py::array positions() const { return py().view(owner, false, world().firstParticle(index), world().bodyParticles(index)); }
    py::array velocities() const { return py().view(owner, true, world().firstParticle(index), world().bodyParticles(index)); }
    std::string kind() const {
        return std::string(simcore::sceneInfo(world().spec().bodies[static_cast<std::size_t>(index)].params.kind()).name);
    }
};

// --- studies -----------------------------------------------------------------------------------

// Output files are opened before any work, as the CLI does: an unwritable path costs nothing.
std::unique_ptr<simlab::AtomicFile> openOutput(const py::object& path) {
    if (path.is_none()) return nullptr;
    auto file = std::make_unique<simlab::AtomicFile>(pathText(path));
    if (!file->ok()) throw py::value_error(file->error());
    return file;
}
void commit(simlab::AtomicFile& file) {
    if (!file.commit()) throw py::value_error(file.error());
}

std::vector<std::string> integratorList(const std::vector<std::string>& names) {
    // As the CLI's --integrators a,b,c: the same list rules and the same words.
    std::string joined;
    for (const std::string& name : names) {
        if (name.find(',') != std::string::npos) throw py::value_error("integrator " + simlab::quoted(name) + " holds a comma");
        joined += (joined.empty() ? "" : ",") + name;
    }
    if (names.size() == 1 && names.front().empty()) joined = ",";  // [""]: an empty item, not an empty list
    const simcore::NameList list = simcore::parseNameList("integrators", joined);
    if (!list.error.empty()) throw py::value_error(list.error);
    simlab::checkIntegrators(names);
    return names;
}

// The outputs against the scene file read and each other (the front door's checkFiles).
void checkOutputs(const Scene& scene, const std::vector<std::pair<std::string, py::object>>& outputs) {
    std::vector<simlab::NamedPath> named;
    for (const auto& [option, path] : outputs) {
        if (path.is_none()) continue;
        named.emplace_back(option, pathText(path));
        simlab::checkOutputNamed(option, named.back().second);
    }
    simlab::checkFiles({{"scene", scene.sceneFile}}, named);
}

double nanIfFailed(bool ok, double v) { return ok ? v : std::nan(""); }
// An adaptive run's tolerance, None for a fixed-step run (simcore: < 0).
py::object toleranceOrNone(double tolerance) { return tolerance > 0 ? py::object(py::float_(tolerance)) : py::none(); }

// One row of study()'s result: the point, its cost and its errors (NaN where not measured).
py::dict studyRowDict(const simlab::StudyRow& r) {
    py::dict row(py::arg("integrator") = r.item.integrator,
                 py::arg("family") = std::string(simcore::integratorFamily(r.item.integrator)),
                 py::arg("precision") = r.item.precision, py::arg("dt") = r.dt,
                 py::arg("tolerance") = toleranceOrNone(r.item.tolerance), py::arg("steps") = r.steps,
                 py::arg("force_evals") = r.forceEvaluations, py::arg("walls") = r.walls);
    const bool timed = !r.walls.empty();
    row["wall_min"] = nanIfFailed(timed, r.wallMin);
    row["wall_q1"] = nanIfFailed(timed, r.wallQ1);
    row["wall_median"] = nanIfFailed(timed, r.wallSeconds);
    row["wall_q3"] = nanIfFailed(timed, r.wallQ3);
    row["wall_seconds"] = nanIfFailed(timed, r.wallSeconds);  // the median, as before issue 28
    row["error_final"] = nanIfFailed(r.ok, r.errorFinal);
    row["error_max"] = nanIfFailed(r.ok, r.errorMax);
    row["error_rms"] = nanIfFailed(r.ok, r.errorRms);
    row["error_energy"] = nanIfFailed(r.ok, r.errorEnergy);
    row["status"] = r.status();
    row["failure"] = r.failure;
    return row;
}

py::dict study(const py::object& scene, const std::vector<std::string>& integrators,
               const std::optional<std::vector<double>>& dts, const std::optional<std::vector<double>>& tolerances,
               const py::handle& duration, const py::handle& repeat, const std::string& reference,
               const py::handle& samples, bool fixedStep, const py::handle& timeBudget,
               const std::vector<std::string>& precision, bool compensated, const py::object& csvPath,
               const py::object& timingsPath, const py::object& plotPath, const py::object& title,
               const py::kwargs& parameters) {
    const Scene s = sceneFrom(scene, parameters, py::none(), true);
    simlab::StudySpec spec;
    spec.params = s.params;
    spec.world = s.world;  // a scene of several bodies: the whole world, as the CLI's study
    spec.integrators = integratorList(integrators);
    if (dts) spec.dts = *dts;
    if (tolerances) spec.tolerances = *tolerances;
    spec.duration = checkedNumber(duration, "duration", 0.0, 1e6, true, false, "s");
    spec.repeat = static_cast<int>(checkedNumber(repeat, "repeat", 1, 1000, false, true));
    spec.samples = static_cast<int>(checkedNumber(samples, "samples", 1, 100000, false, true));
    spec.timeBudget = checkedNumber(timeBudget, "time_budget", 0.0, 1e6, false, false, "s");
    spec.precisions = precision;
    spec.compensated = compensated;
    spec.reference = reference;
    spec.options.fixedStep = fixedStep;
    simlab::checkStudy(spec);
    checkOutputs(s, {{"csv", csvPath}, {"plot", plotPath}});
    auto csv = openOutput(csvPath);
    auto timings = openOutput(timingsPath);
    auto plot = openOutput(plotPath);

    const simlab::StudyResult result =
        cancellable([&](const std::atomic<bool>* cancel) { return simlab::runStudy(spec, {}, cancel); });

    py::list rows;
    for (const simlab::StudyRow& r : result.rows) rows.append(studyRowDict(r));
    py::dict orders, ordersFinal, ordersRms;
    for (const simlab::OrderFit& fit : simlab::fitOrders(result.rows, result.reference.estimatedError)) {
        orders[py::str(fit.integrator)] = fit.order;
        ordersFinal[py::str(fit.integrator)] = fit.orderFinal;
        ordersRms[py::str(fit.integrator)] = fit.orderRms;
    }
    py::list fastest;
    for (const simlab::FamilyBest& b : simlab::fastestByFamily(result.rows))
        fastest.append(py::dict(py::arg("family") = b.family, py::arg("error") = b.error,
                                py::arg("integrator") = b.integrator, py::arg("wall_seconds") = b.wallSeconds,
                                py::arg("force_evals") = b.forceEvaluations));
    if (csv) {
        csv->write(simlab::studyCsvHeader());
        for (const simlab::StudyRow& r : result.rows) csv->write(simlab::studyCsvRow(r));
        commit(*csv);
    }
    if (timings) {
        timings->write(simlab::studyTimingsCsvHeader());
        for (const simlab::StudyRow& r : result.rows) timings->write(simlab::studyTimingsCsvRows(r));
        commit(*timings);
    }
    const double scale = simlab::referenceScale(result.reference);
    if (plot) {
        const std::string t = title.is_none() ? s.sceneName + ": error against cost, T = " + simlab::formatDouble(spec.duration) + " s"
                                              : title.cast<std::string>();
        plot->write(simlab::studySvg(result.rows, t, scale, spec.duration));
        commit(*plot);
    }
    py::dict out(py::arg("rows") = rows, py::arg("orders") = orders, py::arg("orders_final") = ordersFinal,
                 py::arg("orders_rms") = ordersRms, py::arg("fastest") = fastest,
                 py::arg("reference") = result.reference.description,
                 py::arg("reference_error") = result.reference.estimatedError);
    out["roundoff_scale"] = scale;  // X of the floor eps X sqrt(T / h)
    return out;
}

py::dict conservation(const py::object& scene, const std::vector<std::string>& integrators, const py::handle& periods,
                      const py::handle& dt, const py::handle& samples, const std::string& precision,
                      const py::object& csvPath, const py::object& plotPath, const py::object& title,
                      const py::kwargs& parameters) {
    const Scene s = sceneFrom(scene, parameters);
    simlab::ConservationSpec spec;
    spec.params = s.params;
    spec.integrators = integratorList(integrators);
    spec.periods = checkedNumber(periods, "periods", 20.0, 1e7, false, false);
    spec.dt = dt.is_none() ? s.params.get(simcore::Param::Dt) : checkedNumber(dt, "dt", 0.0, 1.0, true, false, "s");
    spec.samples = static_cast<int>(checkedNumber(samples, "samples", 10, 100000, false, true));
    spec.precision = precision;
    simlab::checkConservation(spec);
    checkOutputs(s, {{"csv", csvPath}, {"plot", plotPath}});
    auto csv = openOutput(csvPath);
    auto plot = openOutput(plotPath);
    const simlab::ConservationResult result = cancellable(
        [&](const std::atomic<bool>* cancel) { return simlab::runConservation(spec, {}, cancel); });
    py::list rows;
    for (const simlab::ConservationRow& r : result.rows) {
        py::list t, e;
        for (auto [time, error] : r.curve) t.append(time), e.append(error);
        py::dict row(py::arg("integrator") = r.integrator, py::arg("alpha") = nanIfFailed(r.ok, r.alpha),
                     py::arg("alpha_lo") = nanIfFailed(r.ok, r.alphaLo), py::arg("alpha_hi") = nanIfFailed(r.ok, r.alphaHi),
                     py::arg("class") = r.growth, py::arg("final_error") = nanIfFailed(r.ok, r.finalError),
                     py::arg("relative_error") = nanIfFailed(r.ok, r.relativeError), py::arg("steps") = r.steps);
        row["wall_seconds"] = r.wallSeconds;
        row["status"] = r.status();
        row["failure"] = r.failure;
        row["t"] = t;
        row["energy_error"] = e;
        rows.append(row);
    }
    if (csv) {
        csv->write(simlab::conservationCsvHeader());
        for (const simlab::ConservationRow& r : result.rows) csv->write(simlab::conservationCsvRow(r));
        commit(*csv);
    }
    if (plot) {
        const std::string t = title.is_none() ? s.sceneName + ": |energy error| over " + simlab::formatDouble(spec.periods) + " periods"
                                              : title.cast<std::string>();
        plot->write(simlab::conservationSvg(result, t));
        commit(*plot);
    }
    return py::dict(py::arg("rows") = rows, py::arg("omega_max") = result.omegaMax, py::arg("period") = result.period,
                    py::arg("duration") = result.duration, py::arg("energy_scale") = result.energyScale,
                    py::arg("undamped") = result.undamped);
}

py::dict stability(const py::object& scene, const std::vector<std::string>& integrators, const py::handle& duration,
                   const py::handle& perturb, const py::handle& hmin, const py::handle& hmax, const py::object& csvPath,
                   const py::kwargs& parameters) {
    const Scene s = sceneFrom(scene, parameters, py::none(), true);
    simlab::StabilitySpec spec;
    spec.params = s.params;
    spec.world = s.world;  // a scene of several bodies: the whole world, as the CLI's stability
    spec.integrators = integratorList(integrators);
    spec.duration = checkedNumber(duration, "duration", 0.0, 1e5, true, false, "s");
    spec.perturb = checkedNumber(perturb, "perturb", 0.0, 1e3, false, false, "m");
    spec.hMin = checkedNumber(hmin, "hmin", 0.0, 1.0, true, false, "s");
    spec.hMax = checkedNumber(hmax, "hmax", 0.0, 1.0, true, false, "s");
    simlab::checkStability(spec);
    checkOutputs(s, {{"csv", csvPath}});
    auto csv = openOutput(csvPath);

    // The one verdict's linearisation (simlab::stabilityModes: the rest shape, as the CLI's
    // stability and the GUI's banners and map); the trials start perturbed.
    struct Outcome {
        simlab::LinearModes modes;
        std::vector<simlab::StabilityRow> rows;
    };
    const Outcome out = cancellable([&](const std::atomic<bool>* cancel) {
        Outcome o{simlab::stabilityModes(spec), {}};
        if (!*cancel) o.rows = simlab::runStability(spec, o.modes, {}, cancel);
        return o;
    });

    py::list rows;
    for (const simlab::StabilityRow& r : out.rows)
        rows.append(py::dict(py::arg("integrator") = r.integrator, py::arg("dt_stable") = r.stable,
                             py::arg("dt_unstable") = r.unstable, py::arg("dt_predicted") = r.predicted,
                             py::arg("h_omega_stable") = r.stable * out.modes.omegaMax,
                             py::arg("h_omega_predicted") = r.predicted * out.modes.omegaMax,
                             py::arg("reason") = r.reasonAbove, py::arg("runs") = r.runs));
    if (csv) {
        csv->write(simlab::stabilityCsvHeader());
        for (const simlab::StabilityRow& r : out.rows) csv->write(simlab::stabilityCsvRow(r, out.modes));
        commit(*csv);
    }
    py::dict result(py::arg("rows") = rows, py::arg("omega_max") = out.modes.omegaMax,
                    py::arg("free_coordinates") = out.modes.freeCoordinates,
                    py::arg("unstable_modes") = out.modes.unstableModes);
    if (spec.world) result["bodies"] = spec.world->bodies.size();
    return result;
}

py::dict refinement(const py::object& scene, const std::vector<int>& levels, const py::object& keyArg,
                    const std::string& integrator, const py::object& tolerance, const py::handle& duration,
                    const py::handle& interval, const py::handle& temporalRuns, bool fixedStep,
                    const py::object& csvPath, const py::object& plotPath, const py::object& title,
                    const py::kwargs& parameters) {
    const Scene s = sceneFrom(scene, parameters, py::none(), true);
    simlab::RefinementSpec spec;
    spec.params = s.params;
    spec.world = s.world;  // a world: every body's resolution raised together, as the CLI's
    spec.key = keyArg.is_none() ? simlab::refinementKey(s.params.kind()) : keyArg.cast<std::string>();
    spec.values = levels;
    checkIntegrator(integrator);
    spec.integrator = integrator;
    if (parameters.contains("dt")) spec.dt = s.params.get(simcore::Param::Dt);  // as the CLI's --dt: the study's step
    if (!tolerance.is_none()) spec.tolerance = checkedNumber(tolerance, "tolerance", 0.0, 1.0, true);
    spec.duration = checkedNumber(duration, "duration", 0.0, 1e6, true, false, "s");
    spec.interval = checkedNumber(interval, "interval", 0.0, 1e6, true, false, "s");
    spec.temporalRuns = static_cast<int>(checkedNumber(temporalRuns, "temporal_runs", 0, 10, false, true));
    spec.options.fixedStep = fixedStep;
    simlab::checkRefinement(spec);
    checkOutputs(s, {{"csv", csvPath}, {"plot", plotPath}});
    auto csv = openOutput(csvPath);
    auto plot = openOutput(plotPath);

    const simlab::RefinementResult result =
        cancellable([&](const std::atomic<bool>* cancel) { return simlab::runRefinement(spec, {}, cancel); });

    py::list rows;
    for (const simlab::RefinementRow& r : result.rows)
        rows.append(py::dict(py::arg("key") = spec.key, py::arg("value") = r.value, py::arg("particles") = r.particles,
                             py::arg("springs") = r.springs, py::arg("h") = r.h, py::arg("dt") = r.dt,
                             py::arg("steps") = r.steps, py::arg("wall_seconds") = r.wallSeconds,
                             py::arg("error_volume") = nanIfFailed(r.ok, r.errorVolume),
                             py::arg("error_com") = nanIfFailed(r.ok, r.errorCom), py::arg("reference") = r.reference,
                             py::arg("status") = r.status()));
    py::list temporal;
    for (const simlab::TemporalPoint& p : result.temporal)
        temporal.append(py::dict(py::arg("dt") = p.dt,
                                 py::arg("tolerance") = toleranceOrNone(p.tolerance),
                                 py::arg("steps") = p.steps, py::arg("wall_seconds") = p.wallSeconds,
                                 py::arg("error_volume") = nanIfFailed(p.ok, p.errorVolume),
                                 py::arg("error_com") = nanIfFailed(p.ok, p.errorCom), py::arg("failure") = p.failure));
    py::dict orders;
    for (const simlab::SpatialOrder& fit : simlab::fitSpatialOrders(result)) orders[py::str(fit.observable)] = fit.order;
    if (csv) {
        csv->write(simlab::refinementCsvHeader());
        for (const simlab::RefinementRow& r : result.rows) csv->write(simlab::refinementCsvRow(spec.key, r));
        commit(*csv);
    }
    if (plot) {
        const std::string t = title.is_none() ? s.sceneName + ": mesh error and step error against run time, T = " +
                                                    simlab::formatDouble(spec.duration) + " s"
                                              : title.cast<std::string>();
        plot->write(simlab::refinementSvg(spec, result, t));
        commit(*plot);
    }
    return py::dict(py::arg("rows") = rows, py::arg("orders") = orders, py::arg("temporal") = temporal,
                    py::arg("dt") = result.dt, py::arg("step_rule") = result.stepRule,
                    py::arg("time_error_volume") = result.timeErrorVolume,
                    py::arg("time_error_com") = result.timeErrorCom);
}

// --- sweeps -----------------------------------------------------------------------------------
// elasticlab.sweep (elasticlab/sweep.py) makes the grid and the table; here are the checked plan
// (simlab's validateSweep: ValueError with the CLI's message, before anything runs) and one
// point's run, which is what a worker process or a Dask worker executes.

// A swept value: a number, or a choice parameter's name ("projection").
double sweepValue(const simcore::ParameterSet& params, const std::string& key, const py::handle& value) {
    if (!py::isinstance<py::str>(value)) return numberOf(value, key, "a number or a name");
    const simcore::ParamSpec* p = simcore::findParam(key);
    if (!p) return std::nan("");  // validateSweep names the unknown key
    if (auto v = simcore::parseValue(*p, value.cast<std::string>())) return *v;
    simcore::ParameterSet probe = params;
    throw py::value_error("grid " + probe.setFromText(key, value.cast<std::string>()).value_or(key + ": not a value"));
}

py::tuple sweepPlan(const py::object& scene, const std::vector<std::string>& keys, const py::object& axes,
                    const py::object& points, const py::handle& duration, const py::object& integrator,
                    const py::object& options, const py::object& metrics, const py::object& maxSteps,
                    const py::kwargs& fixed) {
    const Scene s = sceneFrom(scene, fixed);
    simlab::SweepSpec spec;
    spec.sceneName = s.sceneName;
    spec.params = s.params;
    spec.integrator = integrator.is_none() ? s.integrator : integrator.cast<std::string>();
    spec.state = s.state;
    spec.options = integratorOptions(options);
    spec.duration = checkedNumber(duration, "duration", 0.0, 1e7, true, false, "s");
    if (!maxSteps.is_none()) spec.maxSteps = checkedNumber(maxSteps, "max_steps", 1, simlab::kMaxSteps, false);
    spec.keys = keys;
    auto values = [&](const py::handle& list, std::size_t k) {
        std::vector<double> out;
        for (const py::handle& v : list) out.push_back(sweepValue(spec.params, keys.at(k), v));
        return out;
    };
    if (!axes.is_none())
        for (std::size_t k = 0; k < py::len(axes); ++k) spec.axes.push_back(values(axes[py::int_(k)], k));
    if (!points.is_none())
        for (const py::handle& point : points) {
            std::vector<double> v;
            std::size_t k = 0;
            for (const py::handle& x : point) v.push_back(sweepValue(spec.params, keys.at(std::min(k++, keys.size() - 1)), x));
            spec.points.push_back(std::move(v));
        }
    if (!metrics.is_none()) spec.metrics = metrics.cast<std::vector<std::string>>();
    simlab::checkSweep(spec);
    return py::make_tuple(simlab::sweepSpecText(spec), simlab::sweepColumns(spec), simlab::sweepPointCount(spec));
}

// One point of a plan given as its text: a tuple in the order of the plan's columns.
py::tuple sweepRun(const std::string& text, long index) {
    static std::mutex mutex;  // the last plan parsed, kept: a worker runs many points of one plan
    static std::string lastText;
    static std::shared_ptr<const simlab::SweepSpec> last;
    std::shared_ptr<const simlab::SweepSpec> spec;
    {
        std::lock_guard lock(mutex);
        if (!last || text != lastText) {
            simlab::SweepSpecResult parsed = simlab::parseSweepSpec(text);
            if (!parsed.spec) throw py::value_error(parsed.error);
            last = std::make_shared<const simlab::SweepSpec>(std::move(*parsed.spec));
            lastText = text;
        }
        spec = last;
    }
    if (index < 0 || index >= simlab::sweepPointCount(*spec)) throw py::index_error("no point " + std::to_string(index));
    const simlab::SweepRow row =
        cancellable([&](const std::atomic<bool>* cancel) { return simlab::runSweepPoint(*spec, index, cancel); });
    py::list out;
    out.append(row.index);
    for (std::size_t k = 0; k < row.values.size(); ++k) {
        const simcore::ParamSpec* p = simcore::findParam(spec->keys[k]);
        if (p && !p->choices.empty()) out.append(p->choiceName(row.values[k]));
        else out.append(row.values[k]);
    }
    out.append(spec->integrator);
    out.append(row.status);
    out.append(row.reason);
    for (std::size_t m = 0; m < row.metrics.size(); ++m) {
        const std::string& name = spec->metrics[m];
        if ((name == "steps" || name == "force_evals") && std::isfinite(row.metrics[m]))
            out.append(static_cast<long long>(row.metrics[m]));
        else
            out.append(row.metrics[m]);
    }
    out.append(std::string(elastic_lab::kVersion));
    return py::tuple(out);
}

std::vector<double> sweepRange(const std::string& kind, const py::handle& a, const py::handle& b, const py::handle& n) {
    simlab::SweepRange r = simlab::sweepRange(kind, numberOf(a, "start"), numberOf(b, "stop"), numberOf(n, "num"));
    if (!r.error.empty()) throw py::value_error(r.error);
    return r.values;
}

}  // namespace

// fuzz/fuzz_python.cpp compiles this file into a program with an embedded interpreter (the
// package's Python entry under libFuzzer): the same module, registered as a built-in.
#ifdef ELASTICLAB_EMBEDDED
#define ELASTICLAB_MODULE PYBIND11_EMBEDDED_MODULE
#else
#define ELASTICLAB_MODULE PYBIND11_MODULE
#endif
// Kept whole: the module's table of bindings, one definition after another.
ELASTICLAB_MODULE(_core, m) {
    m.doc() = "Elastic Lab: two-layer elastic bodies (particles, springs, gas pressure) from Python. "
              "See docs/python.md.";
    m.attr("__version__") = elastic_lab::kVersion;
    g_simulationFailed = py::exception<SimulationFailedTag>(m, "SimulationFailed", PyExc_RuntimeError);

    m.def("scenes", [] {
        std::vector<std::string> names;
        for (const simcore::SceneInfo& s : simcore::sceneTable()) names.emplace_back(s.name);
        return names;
    }, "The built-in scene names.");
    m.def("integrators", [] {
        py::list out;
        for (const simcore::IntegratorInfo& i : simcore::integratorTable())
            out.append(py::dict(py::arg("name") = std::string(i.name), py::arg("order") = i.order,
                                py::arg("description") = std::string(i.description),
                                py::arg("family") = std::string(i.family)));
        return out;
    }, "The integrators: name, order, description, family (explicit-rk, symplectic, implicit, adaptive, "
       "production, constraint).");
    m.def("parameters", [](const std::string& scene) {
        const simcore::SceneInfo* info = simcore::findScene(scene);
        if (!info)
            throw py::value_error(simcore::unknownSceneMessage(scene));
        py::list out;
        for (const simcore::ParamSpec* p : simcore::parametersFor(info->kind))
            out.append(py::dict(py::arg("key") = std::string(p->key), py::arg("unit") = std::string(p->unit),
                                py::arg("default") = p->defaultFor(info->kind), py::arg("range") = p->rangeText(),
                                py::arg("choices") = std::string(p->choices), py::arg("meaning") = std::string(p->meaning)));
        return out;
    }, py::arg("scene"), "The parameter table of a scene: key, unit, default, range, choices, meaning.");

    py::class_<PySimulation>(m, "Simulation",
                             "One body, its parameters, its integrator and its diagnostics (simcore::Simulation).")
        .def(py::init<const py::object&, const py::object&, const py::object&, const py::object&, const py::kwargs&>(),
             py::arg("scene") = "ring2d", py::kw_only(), py::arg("integrator") = py::none(),
             py::arg("options") = py::none(), py::arg("threads") = py::none(),
             "Simulation(scene='ring2d', *, integrator=None, options=None, threads=None, **parameters): a built-in "
             "scene or a scene file (.json, resumed with its state), parameters as keywords (ks=900, "
             "contact='projection'), integrator options as a dict (atol, rtol, newton, fixed_step, ...).")
        .def("__repr__", &PySimulation::repr)
        .def("step", &PySimulation::step, py::arg("n") = 1, "Takes n steps (SimulationFailed when one fails).")
        .def("run", &PySimulation::run, py::arg("duration"), py::arg("every") = py::none(),
             py::arg("times") = py::none(), py::arg("progress") = py::none(), py::kw_only(),
             py::arg("csv") = py::none(), py::arg("xlsx") = py::none(), py::arg("csv_dialect") = "plain",
             py::arg("every_seconds") = py::none(), py::arg("precision") = "double",
             "Runs for duration seconds [s]; with every=N (steps) or times=[t...] (absolute simulated times [s], "
             "ascending) returns the diagnostics rows (start, then every N steps or the first step at or past each "
             "time, end) as an array, columns as diagnostics_columns; progress(t) is called between slices. "
             "csv= and xlsx= write the same rows as the CLI's `run --csv/--xlsx` files; csv_dialect='excel-semicolon' "
             "spells the CSV for spreadsheets in decimal-comma locales (semicolon, decimal comma, CRLF, byte-order mark); "
             "every_seconds=S samples every S seconds from the start (the rows held bounded before it starts); "
             "precision='float' steps the float32 path (euler, midpoint, rk4, symplectic-euler, verlet; no contact).")
        .def("reset", &PySimulation::reset, "Back to the start state, same parameters.")
        .def("set_integrator", &PySimulation::setIntegrator, py::arg("name"), py::arg("options") = py::none(),
             "Changes the integrator between steps (options as in the constructor, added to the current ones).")
        .def("exact", &PySimulation::exact, "spring1d: the closed-form (positions, velocities) at the current time.")
        .def("save_scene", &PySimulation::saveScene, py::arg("path"),
             "Writes the scene, its parameters, integrator and state as a scene file (atomically).")
        .def_property_readonly("positions", [](const py::object& self) { return self.cast<PySimulation&>().stateView(self, false); },
                               "N x 3 positions [m]: a read-only view of the state, updated as the simulation steps.")
        .def_property_readonly("velocities", [](const py::object& self) { return self.cast<PySimulation&>().stateView(self, true); },
                               "N x 3 velocities [m/s]: a read-only view of the state, updated as the simulation steps.")
        .def_property_readonly("diagnostics", &PySimulation::diagnostics, "The diagnostics row as a dict (CSV names).")
        .def_property_readonly("diagnostics_row", &PySimulation::diagnosticsRow, "The diagnostics row as an array.")
        .def_property_readonly("diagnostics_columns", &PySimulation::columns, "The names of the diagnostics row.")
        .def_property_readonly("failure", &PySimulation::failure, "None, or reason, step and time of the failure.")
        .def_property_readonly("parameters", &PySimulation::parameters, "Every parameter of the scene, resolved.")
        .def_property_readonly("integrator_options", &PySimulation::integratorOptionsDict)
        .def_property_readonly("scene", &PySimulation::scene)
        .def_property_readonly("integrator", [](PySimulation& s) { return std::string(s.sim().integrator().name()); })
        .def_property_readonly("time", &PySimulation::time, "Simulated time [s] (readable while another thread runs it).")
        .def_property_readonly("step_count", &PySimulation::stepCount, "Steps taken (readable while another thread runs it).")
        .def(py::pickle([](const PySimulation& s) { return s.getState(); }, &PySimulation::fromState))
        .def_property_readonly("dt", [](PySimulation& s) { return s.sim().dt(); }, "The step [s].")
        .def_property_readonly("particle_count", [](PySimulation& s) { return s.sim().particleCount(); })
        .def_property_readonly("spring_count", [](PySimulation& s) { return s.sim().topology().springCount(); });

    m.def("world_scenes", [] {
        std::vector<std::string> names;
        for (const simcore::WorldSceneInfo& s : simcore::worldSceneTable()) names.emplace_back(s.name);
        return names;
    }, "The built-in scenes of several bodies (elasticlab.World).");

    py::class_<PyWorldBody>(m, "WorldBody", "One body of a World: a view that follows the world as it steps.")
        .def_property_readonly("number", [](const PyWorldBody& b) { return b.index + 1; },
                               "The body's number as people count (body1, body2, ...: the CSV suffix and --set prefix).")
        .def_property_readonly("kind", &PyWorldBody::kind, "ring2d, sphere3d or sphere3d-latlong.")
        .def_property_readonly("positions", &PyWorldBody::positions, "Its particles' N x 3 positions [m] (read-only view).")
        .def_property_readonly("velocities", &PyWorldBody::velocities, "Its particles' N x 3 velocities [m/s] (read-only view).")
        .def_property_readonly("parameters", &PyWorldBody::parameters, "Its parameters, resolved (world ones included).")
        .def_property_readonly("diagnostics", &PyWorldBody::diagnostics,
                               "mass [kg], kinetic [J], com [m], velocity [m/s] and momentum of its centre of mass, "
                               "volume and pressure per layer.")
        .def_property_readonly("particle_count", [](const PyWorldBody& b) { return b.world().bodyParticles(b.index); })
        .def_property_readonly("start_position", [](const PyWorldBody& b) {
            const Eigen::Vector3d& p = b.world().spec().bodies[static_cast<std::size_t>(b.index)].position;
            return py::make_tuple(p.x(), p.y(), p.z());
        })
        .def_property_readonly("start_velocity", [](const PyWorldBody& b) {
            const Eigen::Vector3d& v = b.world().spec().bodies[static_cast<std::size_t>(b.index)].velocity;
            return py::make_tuple(v.x(), v.y(), v.z());
        })
        .def("__repr__", [](const PyWorldBody& b) {
            return "<elasticlab.WorldBody body" + std::to_string(b.index + 1) + " " + b.kind() + ", " +
                   std::to_string(b.world().bodyParticles(b.index)) + " particles>";
        });

    py::class_<PyWorld>(m, "World", "Several two-layer bodies in one box, stepped as one ODE (simcore::World).")
        .def(py::init<const py::object&, const py::object&, const py::object&, const py::object&, const py::object&,
                      const py::kwargs&>(),
             py::arg("scene") = py::none(), py::kw_only(), py::arg("bodies") = py::none(), py::arg("set") = py::none(),
             py::arg("integrator") = py::none(), py::arg("options") = py::none(),
             "World(scene=None, *, bodies=None, set=None, integrator=None, options=None, **parameters): a built-in "
             "scene of several bodies (collide2d, collide3d, stack3d), a scene file of several bodies (.json, resumed "
             "with its state), or bodies=[{'kind': 'sphere3d', 'position': (x, y, z), 'velocity': (...), 'mass': 4}, "
             "...]; keyword parameters set every body (gravity=0, offset=0.5), set=['body2.mass=4'] one body, as the "
             "CLI's --set.")
        .def("__repr__", &PyWorld::repr)
        .def("step", &PyWorld::step, py::arg("n") = 1, "Takes n steps (SimulationFailed when one fails).")
        .def("run", &PyWorld::run, py::arg("duration"), py::arg("every") = py::none(), py::arg("times") = py::none(),
             py::arg("progress") = py::none(), py::kw_only(), py::arg("every_seconds") = py::none(),
             "As Simulation.run: rows every N steps or at the given times, columns as diagnostics_columns.")
        .def("reset", &PyWorld::reset, "Back to the start state.")
        .def("save_scene", &PyWorld::saveScene, py::arg("path"), "Writes the world and its exact state as a scene file.")
        .def_property_readonly("bodies", [](const py::object& self) {
            py::list out;
            for (int k = 0; k < self.cast<const PyWorld&>().world().bodyCount(); ++k) out.append(PyWorldBody{self, k});
            return out;
        }, "The bodies, in order (bodies[0] is body1).")
        .def_property_readonly("positions", [](const py::object& self) {
            const PyWorld& w = self.cast<const PyWorld&>();
            return w.view(self, false, 0, w.world().particleCount());
        }, "Every particle's N x 3 positions [m], the bodies side by side (read-only view).")
        .def_property_readonly("velocities", [](const py::object& self) {
            const PyWorld& w = self.cast<const PyWorld&>();
            return w.view(self, true, 0, w.world().particleCount());
        })
        .def_property_readonly("diagnostics", &PyWorld::diagnostics,
                               "The CSV row as a dict: energies, ledger, per-body columns (suffix _N), momentum, min_gap.")
        .def_property_readonly("diagnostics_columns", &PyWorld::columns)
        .def_property_readonly("momentum", [](const PyWorld& w) {
            const Eigen::Vector3d& p = w.world().diagnostics().momentum;
            return py::make_tuple(p.x(), p.y(), p.z());
        }, "Total linear momentum [kg m/s].")
        .def_property_readonly("angular_momentum", [](const PyWorld& w) {
            const Eigen::Vector3d& l = w.world().diagnostics().angularMomentum;
            return py::make_tuple(l.x(), l.y(), l.z());
        }, "Total angular momentum about the origin [kg m^2/s].")
        .def_property_readonly("min_gap", [](const PyWorld& w) { return w.world().diagnostics().minGap; },
                               "The smallest gap between two bodies' outer layers or non-adjacent elements of one [m].")
        .def_property_readonly("failure", &PyWorld::failure)
        .def_property_readonly("scene", [](const PyWorld& w) { return w.world().spec().name; })
        .def_property_readonly("integrator", [](const PyWorld& w) { return std::string(w.world().integrator().name()); })
        .def_property_readonly("integrator_options", &PyWorld::optionsDict)
        .def_property_readonly("time", [](const PyWorld& w) { return w.world().time(); })
        .def_property_readonly("step_count", [](const PyWorld& w) { return w.world().stepCount(); })
        .def_property_readonly("dt", [](const PyWorld& w) { return w.world().dt(); })
        .def_property_readonly("particle_count", [](const PyWorld& w) { return w.world().particleCount(); })
        .def(py::pickle([](const PyWorld& w) { return w.getState(); }, &PyWorld::fromState));

    m.def("study", &study, py::arg("scene"), py::kw_only(),
          py::arg("integrators") = std::vector<std::string>{"euler", "midpoint", "rk4"},
          py::arg("dts") = py::none(), py::arg("tolerances") = py::none(), py::arg("duration") = 2.0,
          py::arg("repeat") = 1, py::arg("reference") = "auto", py::arg("samples") = 20, py::arg("fixed_step") = false,
          py::arg("time_budget") = 0.0, py::arg("precision") = std::vector<std::string>{"double"},
          py::arg("compensated") = false, py::arg("csv") = py::none(), py::arg("timings") = py::none(),
          py::arg("plot") = py::none(), py::arg("title") = py::none(),
          "Work-precision study (the CLI's `study`): {'rows': [dict per point: walls (every repeat), wall_min, "
          "wall_q1, wall_median, wall_q3, error_final, error_max, error_rms, ...], 'orders', 'orders_final', "
          "'orders_rms': {curve: fitted order}, 'fastest': [the fastest of each family at each accuracy], "
          "'reference', 'reference_error', 'roundoff_scale'}; time_budget= (s) records slower points as 'not "
          "reached'; precision=['double', 'float'] adds the float build of spring1d (compensated= its Kahan "
          "update); csv=, timings= and plot= write the CLI's CSV, raw timings and SVG.");
    m.def("conservation", &conservation, py::arg("scene"), py::kw_only(),
          py::arg("integrators") = std::vector<std::string>{"verlet", "yoshida4", "rk4"}, py::arg("periods") = 1000.0,
          py::arg("dt") = py::none(), py::arg("samples") = 120, py::arg("precision") = "double",
          py::arg("csv") = py::none(), py::arg("plot") = py::none(), py::arg("title") = py::none(),
          "Long-time energy (the CLI's `conservation`): the undamped scene for `periods` periods of its fastest "
          "mode at dt (default: the scene's); {'rows': [dict per integrator: alpha, alpha_lo, alpha_hi, class "
          "(bounded, random-walk, drift), final_error, t, energy_error, ...], 'omega_max', 'period', 'duration', "
          "'energy_scale', 'undamped'}; csv= and plot= as the CLI.");
    m.def("refinement", &refinement, py::arg("scene"), py::kw_only(), py::arg("levels"),
          py::arg("key") = py::none(), py::arg("integrator") = "rk4", py::arg("tolerance") = py::none(),
          py::arg("duration") = 1.0, py::arg("interval") = 0.01, py::arg("temporal_runs") = 4,
          py::arg("fixed_step") = false, py::arg("csv") = py::none(), py::arg("plot") = py::none(),
          py::arg("title") = py::none(),
          "Refinement study (the CLI's `study --refine`): the same body at several resolutions (levels of "
          "key, the scene's own by default) against the finest: {'rows', 'orders': {'volume', 'com'}, "
          "'temporal', 'dt', 'step_rule', ...}; dt= (a parameter) fixes the step; csv= and plot= as the CLI.");
    m.def("_sweep_plan", &sweepPlan, py::arg("scene"), py::arg("keys"), py::arg("axes"), py::arg("points"),
          py::arg("duration"), py::arg("integrator"), py::arg("options"), py::arg("metrics"), py::arg("max_steps"),
          "The checked plan of a sweep: (text, columns, points); ValueError for a bad request (elasticlab.sweep).");
    m.def("_sweep_run", &sweepRun, py::arg("plan"), py::arg("index"), "One point of a plan: its row (a tuple).");
    m.def("_sweep_range", &sweepRange, py::arg("kind"), py::arg("start"), py::arg("stop"), py::arg("num"),
          "linear, log or decades values (elasticlab.linear, log, decades).");
    m.def("stability", &stability, py::arg("scene"), py::kw_only(),
          py::arg("integrators") = std::vector<std::string>{"euler", "midpoint", "rk4", "symplectic-euler", "verlet",
                                                            "rk45", "implicit-euler"},
          py::arg("duration") = 2.0, py::arg("perturb") = 0.01, py::arg("hmin") = 1e-5, py::arg("hmax") = 1.0,
          py::arg("csv") = py::none(),
          "Stability scan (the CLI's `stability`): {'rows': [dict per integrator], 'omega_max', ...}; csv= writes "
          "the CLI's CSV. A scene of several bodies (collide2d, ...) is scanned as one world: its whole "
          "system's eigenvalues, the trials run the world; keywords set every body.");
}
