#include "app/cli/cli.h"

#include <algorithm>
#include <cerrno>
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
        app.add_option("--integrator", args.integrator, "integration method (default: the scene file's, else rk4)")
            ->type_name("NAME")
            ->check(CLI::Validator(
                [](std::string& name) { return simcore::unknownIntegrator(name).value_or(std::string()); },
                "{" + simcore::integratorNames() + "}"));
}

std::string sceneFileOf(const SceneArgs& args) {
    return !simcore::findScene(args.scene) && args.scene.size() > 5 && args.scene.ends_with(".json") ? args.scene
                                                                                                      : std::string();
}

SceneSetup sceneSetup(const SceneArgs& args) {
    SceneSetup setup;
    setup.sceneName = args.scene;
    const simcore::SceneInfo* scene = simcore::findScene(setup.sceneName);
    std::string fileIntegrator;
    if (!sceneFileOf(args).empty()) {
        // A scene file wherever a scene name is taken; --set, --dt, --integrator override it.
        simlab::SceneFileResult read = simlab::readSceneFile(setup.sceneName);
        if (!read.file) throw UsageError(read.error);
        if (read.file->world)
            throw UsageError(setup.sceneName + " is a scene of several bodies: `run` takes it; this command studies "
                                               "one body (" + simcore::sceneNames() + ")");
        setup.sceneName = read.file->sceneName;
        scene = simcore::findScene(setup.sceneName);
        setup.params = read.file->params;
        fileIntegrator = read.file->integrator;
        setup.state = read.file->state;
    } else if (!scene && simcore::worldScene(setup.sceneName)) {
        throw UsageError(setup.sceneName + " is a scene of several bodies: `run` and `params` take it; this command "
                                           "studies one body (" + simcore::sceneNames() + ")");
    } else if (!scene) {
        throw UsageError(simcore::unknownSceneMessage(setup.sceneName) + ", or a scene file (.json)");
    } else {
        setup.params = simcore::ParameterSet(scene->kind);
    }
    for (const std::string& assignment : args.set)
        if (auto error = setup.params.assign(assignment)) throw UsageError("--set " + *error);
    if (args.dt)
        if (auto error = setup.params.setFromText("dt", *args.dt)) throw UsageError("--" + *error);
    setup.integrator = args.integrator.value_or(fileIntegrator.empty() ? "rk4" : fileIntegrator);
    if (auto error = simcore::unknownIntegrator(setup.integrator)) throw UsageError(*error);
    if (auto error = simcore::validateShape(setup.params, setup.integrator)) throw UsageError(*error);
    return setup;
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

// --- Files -------------------------------------------------------------------------------------

void checkDistinctFiles(const std::vector<NamedPath>& inputsThenOutputs) {
    if (auto clash = simlab::fileClash(inputsThenOutputs)) throw UsageError(*clash);
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
    return text;
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
            command.check();
            if (mode == Mode::CheckOnly) return kExitOk;
            if (g_csvStdout >= 0) {  // --csv -: the report to standard error
                std::fflush(stdout);
                ::dup2(2, 1);
            }
            const int status = command.run();
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
