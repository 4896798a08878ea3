#include "app/cli/cli.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>

#include <fcntl.h>
#include <unistd.h>

#include "elastic_lab_version.h"
#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simcore/scenes.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/output.h"
#include "simlab/scenefile.h"
#include "simlab/stability.h"

namespace cli {

// --- Validators --------------------------------------------------------------------------------

CLI::Validator finiteIn(double min, double max, bool minExclusive) {
    const std::string range = std::string(minExclusive ? "(" : "[") + simlab::formatDouble(min) + ", " +
                              simlab::formatDouble(max) + "]";
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            const auto v = simcore::parseNumber(text);
            if (!v) return simcore::quoteShort(text) + " is not a finite number; allowed " + range;
            if ((minExclusive ? *v <= min : *v < min) || *v > max)
                return simcore::quoteShort(text) + " is out of range; allowed " + range;
            return {};
        },
        "in " + range);
}

CLI::Validator wholeIn(long min, long max) {
    const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
    return CLI::Validator(
        [=](std::string& text) -> std::string {
            const auto v = simcore::parseNumber(text);
            if (!v || *v != std::floor(*v) || *v < static_cast<double>(min) || *v > static_cast<double>(max))
                return simcore::quoteShort(text) + " is not allowed; allowed whole numbers in " + range;
            text = std::to_string(static_cast<long>(*v));  // "1e3" is 1000 for the conversion that follows
            return {};
        },
        "whole, in " + range);
}

// --- Shared option groups ----------------------------------------------------------------------

void addSceneOptions(CLI::App& app, SceneArgs& args, bool withDt, bool withIntegrator) {
    app.add_option("--scene", args.scene, "built-in scene (" + simcore::sceneNames() +
                                              ") or a scene file (.json), which may carry a saved state")
        ->type_name("S|FILE.json")
        ->capture_default_str();
    app.add_option("--set", args.set, "set a parameter (repeatable); `elastic-lab-cli params --scene S` lists them "
                                      "with units, defaults and ranges")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false);
    if (withDt)
        app.add_option("--dt", args.dt, "time step [s] (same as --set dt=H; default: the scene's)")->type_name("H");
    if (withIntegrator)
        // Checked by the front door (simlab::resolveScene), in the words every door uses.
        app.add_option("--integrator", args.integrator, "integration method (default: the scene file's, else rk4): " +
                                                            simcore::integratorNames())
            ->type_name("NAME");
}

void addIntegratorOptions(CLI::App& app, simcore::IntegratorOptions& o) {
    app.add_option("--atol", o.atol, "absolute error tolerance of the adaptive methods (rk45, cvode-bdf, cvode-adams) [m, m/s]")
        ->type_name("A")
        ->check(finiteIn(0.0, 1.0, true))
        ->capture_default_str();
    app.add_option("--rtol", o.rtol, "relative error tolerance of the adaptive methods")->type_name("R")->check(finiteIn(0.0, 1.0, false))->capture_default_str();
    app.add_option("--newton", o.newtonIterations, "Newton iterations per step of implicit-euler")
        ->type_name("N")
        ->check(wholeIn(1, 50))
        ->capture_default_str();
    app.add_flag("--fixed-step", o.fixedStep, "run the adaptive method (rk45) at the fixed step dt");
    app.add_flag("--error-estimate", o.stepDoubling,
                 "step doubling for fixed-step methods: the error_estimate column (costs about 3x)");
}

std::string stabilityWarning(const simcore::ParameterSet& params, std::string_view integrator) {
    simcore::Simulation sim(params, integrator);
    const auto advice = simlab::stabilityAdvice(sim);
    if (!advice) return {};
    char suggestion[64];
    std::snprintf(suggestion, sizeof suggestion, " (predicted stable: --dt %g)", advice->suggestedDt);
    return "warning: " + advice->message + suggestion;
}

// --- Output forms ------------------------------------------------------------------------------

void addJsonFlag(CLI::App& app, bool& json) {
    app.add_flag("--json", json, "print the result as JSON on standard output instead of text");
}

void printJsonText(const std::string& text) {
    std::fwrite(text.data(), 1, text.size(), stdout);
    std::fputc('\n', stdout);
}

namespace {
// `--csv -`: the CSV goes to the standard output the tool was started with, through a copy of
// that descriptor taken when the option is parsed; before the command runs, standard output is
// pointed at standard error, so that the command's report (run's summary, study's table) never
// mixes with the rows.
int g_csvStdout = -1;
}  // namespace

CLI::Option* addCsvOption(CLI::App& app, std::string& path, const std::string& help) {
    return app.add_option("--csv", path, help + " (- for standard output; the report then goes to standard error)")
        ->type_name("FILE|-")
        ->transform(CLI::Validator(
            [](std::string& text) {
                if (text != "-") return std::string();
                if (g_csvStdout < 0) g_csvStdout = ::fcntl(1, F_DUPFD_CLOEXEC, 3);
                if (g_csvStdout < 0) return std::string("cannot use standard output: ") + std::strerror(errno);
                text = "/dev/fd/" + std::to_string(g_csvStdout);  // a pipe or terminal: written in place
                return std::string();
            },
            ""));
}

// --- Long commands: signals and progress ------------------------------------------------------

namespace {
volatile std::sig_atomic_t g_stopSignal = 0;
std::atomic<bool> g_stopFlag{false};
static_assert(std::atomic<bool>::is_always_lock_free, "set from a signal handler");
extern "C" void onStopSignal(int signal) {
    g_stopSignal = signal;
    g_stopFlag.store(true);
}
struct sigaction g_previous[2];
constexpr int kStopSignals[2] = {SIGINT, SIGTERM};
}  // namespace

StopSignals::StopSignals() {
    g_stopSignal = 0;
    g_stopFlag = false;
    for (int i = 0; i < 2; ++i) {
        struct sigaction action {};
        action.sa_handler = onStopSignal;
        sigemptyset(&action.sa_mask);
        ::sigaction(kStopSignals[i], nullptr, &g_previous[i]);
        if (g_previous[i].sa_handler == SIG_IGN) continue;  // started ignoring it: keep ignoring
        ::sigaction(kStopSignals[i], &action, nullptr);
    }
}

StopSignals::~StopSignals() {
    for (int i = 0; i < 2; ++i) ::sigaction(kStopSignals[i], &g_previous[i], nullptr);
}

int StopSignals::caught() const { return g_stopSignal; }

const std::atomic<bool>* StopSignals::flag() const { return &g_stopFlag; }

const char* StopSignals::name(int signal) { return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : "a signal"; }

namespace {
double wallNow() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

ProgressLine::ProgressLine(bool quiet) : m_enabled(!quiet && ::isatty(2) == 1), m_start(wallNow()) {}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::update(double done, double total, const char* unit, long steps) {
    if (!m_enabled || (m_calls++ & 63u) != 0) return;
    const double now = wallNow();
    if (m_last >= 0.0 && now - m_last < 0.25) return;
    m_last = now;
    const double elapsed = now - m_start;
    const double fraction = total > 0.0 ? std::clamp(done / total, 0.0, 1.0) : 0.0;
    char line[160];
    int n = std::snprintf(line, sizeof line, "%.4g / %.4g %s (%.0f %%), step %ld, %.0f s", done, total, unit,
                          100.0 * fraction, steps, elapsed);
    if (fraction > 0.01 && elapsed > 1.0)
        n += std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n), ", about %.0f s left",
                           elapsed * (1.0 - fraction) / fraction);
    const std::size_t width = static_cast<std::size_t>(std::max(n, 0));
    std::fprintf(stderr, "\r%s%*s", line, static_cast<int>(m_width > width ? m_width - width : 0), "");
    std::fflush(stderr);
    m_width = std::max(m_width, width);
}

void ProgressLine::clear() {
    if (!m_enabled || m_width == 0) return;
    std::fprintf(stderr, "\r%*s\r", static_cast<int>(m_width), "");
    std::fflush(stderr);
    m_width = 0;
}

// --- Lists -------------------------------------------------------------------------------------

std::vector<double> numberList(const std::string& option, const std::string& text) {
    simcore::NumberList list = simcore::parseNumberList(option, text);
    if (!list.error.empty()) throw UsageError(list.error);
    return std::move(list.items);
}

std::vector<std::string> nameList(const std::string& option, const std::string& text) {
    simcore::NameList list = simcore::parseNameList(option, text);
    if (!list.error.empty()) throw UsageError(list.error);
    return std::move(list.items);
}

std::pair<int, int> parseShard(const std::string& text) {
    if (text.empty()) return {0, 1};
    const auto slash = text.find('/');
    const auto k = simcore::parseNumber(text.substr(0, slash == std::string::npos ? 0 : slash));
    const auto n = slash == std::string::npos ? std::nullopt : simcore::parseNumber(text.substr(slash + 1));
    if (!k || !n || *k != std::floor(*k) || *n != std::floor(*n) || *n < 1 || *k < 1 || *k > *n || *n > 100000)
        throw UsageError("--shard: " + simcore::quoteShort(text) + " is not allowed; allowed K/N with 1 <= K <= N, e.g. 2/4");
    return {static_cast<int>(*k) - 1, static_cast<int>(*n)};
}

// --- The tool ----------------------------------------------------------------------------------

std::unique_ptr<CLI::App> makeApp(std::vector<Command>& commands) {
    auto app = std::make_unique<CLI::App>(
        "Elastic Lab, headless: run the two-layer elastic bodies, measure integrators' error against cost and "
        "their stability limits, and write CSV, SVG and scene files.",
        "elastic-lab-cli");
    app->set_version_flag("--version", std::string("elastic-lab-cli ") + elastic_lab::kVersion);
    app->require_subcommand(1, 1);
    app->get_formatter()->column_width(34);
    app->footer("`elastic-lab-cli COMMAND --help` lists a command's options with units and defaults.\n"
                "Exit status: 0 success, 2 bad input (one line naming the problem), 3 the simulation failed.");
    for (auto add : {addScenesCommand, addParamsCommand, addIntegratorsCommand, addRunCommand, addStudyCommand, addConservationCommand, addSweepCommand,
                     addStabilityCommand, addRestitutionCommand, addGalleryCommand, addBenchCommand,
                     addCompletionCommand})
        commands.push_back(add(*app));
    return app;
}

namespace {

std::string optionNames(const CLI::App& app) {
    std::string names;
    for (const CLI::Option* o : app.get_options())
        if (!o->get_lnames().empty()) names += (names.empty() ? "--" : ", --") + o->get_lnames().front();
    return names;
}

std::string commandNames(const CLI::App& app) {
    std::string names;
    for (const CLI::App* sub : app.get_subcommands({})) names += (names.empty() ? "" : ", ") + sub->get_name();
    return names;
}

// CLI11's message, on one line, with what is allowed where it does not say so itself.
std::string parseErrorText(const CLI::ParseError& e, const CLI::App& app, const std::vector<std::string>& args) {
    std::string text = e.what();
    std::replace(text.begin(), text.end(), '\n', ' ');
    const std::vector<CLI::App*> chosen = app.get_subcommands();
    if (chosen.empty() && !args.empty())
        return (args.front().starts_with("-") ? "unknown option " : "unknown command ") + simcore::quoteShort(args.front()) +
               "; allowed: --help, --version, or a command: " + commandNames(app);
    if (chosen.empty() && dynamic_cast<const CLI::RequiredError*>(&e))
        return "a command is needed; allowed: " + commandNames(app) + " (elastic-lab-cli --help says more)";
    if (dynamic_cast<const CLI::ExtrasError*>(&e))
        text += chosen.empty() ? "; allowed: --help, --version, or a command: " + commandNames(app)
                               : "; " + chosen.front()->get_name() + " takes " + optionNames(*chosen.front());
    // CLI11 echoes the values it refuses raw: every argument it quoted is quoted and cut by the
    // one helper (a 100 kB value with escape sequences stays one short, inert line).
    std::vector<std::string> longest = args;
    std::sort(longest.begin(), longest.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    for (const std::string& arg : longest) {
        const std::string value = arg.substr(arg.find('=') == std::string::npos || !arg.starts_with("--") ? 0 : arg.find('=') + 1);
        const bool plain = value.size() <= 40 && std::all_of(value.begin(), value.end(), [](char c) {
                               return static_cast<unsigned char>(c) >= 0x20 && c != 0x7f;
                           });
        if (plain || value.empty()) continue;
        for (std::size_t at = 0; (at = text.find(value, at)) != std::string::npos;) {
            const std::string q = simcore::quoteShort(value);
            text.replace(at, value.size(), q);
            at += q.size();
        }
    }
    // Whatever is left (a value CLI11 altered) still never reaches the terminal raw or whole.
    const bool inert = text.size() <= 1000 && std::all_of(text.begin(), text.end(), [](char c) {
                           return static_cast<unsigned char>(c) >= 0x20 && c != 0x7f;
                       });
    return inert ? text : simcore::quoteShort(text, 1000);
}

bool stdoutWritten() {
    // Standard output is a result like any file: a full disk or a closed pipe that lost part of
    // it is an error (exit 2), never a success with the table gone.
    std::cout.flush();
    if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
        std::fprintf(stderr, "error: writing standard output failed: %s\n", std::strerror(errno));
        return false;
    }
    return true;
}

}  // namespace

int runCommandLine(const std::vector<std::string>& argsIn, Mode mode) {
    std::vector<std::string> args = argsIn;
    // `help` and `help COMMAND`, as people type them.
    if (!args.empty() && args.front() == "help") {
        args.erase(args.begin());
        args.emplace_back("--help");
    }
    if (g_csvStdout >= 0) ::close(g_csvStdout);  // a previous call's (the fuzz target calls again)
    g_csvStdout = -1;
    std::vector<Command> commands;
    const std::unique_ptr<CLI::App> app = makeApp(commands);
    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
        app->parse(reversed);
    } catch (const CLI::CallForHelp& e) {
        if (mode == Mode::Execute) std::cout << app->help();
        return stdoutWritten() ? kExitOk : kExitBadInput;
    } catch (const CLI::CallForVersion& e) {
        if (mode == Mode::Execute) std::cout << e.what() << '\n';
        return stdoutWritten() ? kExitOk : kExitBadInput;
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "error: %s\n", parseErrorText(e, *app, args).c_str());
        return kExitBadInput;
    }
    for (const Command& command : commands) {
        if (!command.app->parsed()) continue;
        try {
            // A file option given with an empty name ('' from an unset shell variable) is a
            // mistake, never "no file": refused before anything else.
            for (const CLI::Option* option : command.app->get_options())
                if (option->count() > 0 && option->get_type_name().find("FILE") != std::string::npos)
                    for (const std::string& value : option->results())
                        simlab::checkOutputNamed(option->get_lnames().front(), value);
            try {
                command.check();
            } catch (const std::bad_alloc&) {  // a request too large to even check
                std::fprintf(stderr, "error: out of memory while checking the request; ask for less (a smaller body, "
                                     "fewer samples, a smaller file)\n");
                return kExitBadInput;
            }
            if (mode == Mode::CheckOnly) return kExitOk;
            if (g_csvStdout >= 0) {  // --csv -: the report to standard error
                std::fflush(stdout);
                ::dup2(2, 1);
            }
            int status = kExitFailed;
            try {
                status = command.run();
            } catch (const std::bad_alloc&) {  // the work ran out of memory: a failed run, exit 3
                std::fprintf(stderr, "error: out of memory during the run (the machine or its limits gave less than "
                                     "the request needs; docs/reliability.md)\n");
                return kExitFailed;
            }
            return stdoutWritten() ? status : kExitBadInput;
        } catch (const UsageError& e) {
            std::fprintf(stderr, "error: %s\n", e.what());
            return kExitBadInput;
        } catch (const std::invalid_argument& e) {
            std::fprintf(stderr, "error: %s\n", e.what());
            return kExitBadInput;
        }
    }
    std::fprintf(stderr, "error: a command is needed; allowed: %s\n", commandNames(*app).c_str());
    return kExitBadInput;
}

}  // namespace cli
