#pragma once
// The elastic-lab-cli commands on CLI11: each command binds its options to a struct of its own
// (with text, unit and default for --help), checks everything that can be known before any work
// begins, then runs.
//
// Exit status contract: 0 success, 2 bad input (one line on stderr naming the problem and what
// is allowed), 3 the simulation failed (reason, step and time on stderr).

#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "simcore/integrators.h"
#include "simcore/params.h"
#include "simlab/scenefile.h"

namespace cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitFailed = 3;
// The most steps one fixed-step run may take (1e9: about 3 days for the default ring on this
// machine): more is a mistake in --dt or --duration, refused before it runs.
inline constexpr double kMaxSteps = 1e9;

// Bad input: reported on one line, exit status 2.
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// One command of the tool. `check` is the validation layer: it decides, before anything is
// written or run, that the work is well formed and finite (throws UsageError); `run` does it.
struct Command {
    CLI::App* app = nullptr;
    std::function<void()> check;
    std::function<int()> run;
};

// What the command line does after parsing and checking: everything, or nothing more (used by
// the fuzz target, which must never write files or run simulations).
enum class Mode { Execute, CheckOnly };

// The whole tool: parses `args` (without the program name), checks, runs. Returns the exit status;
// reports errors on stderr, help and version on stdout.
int runCommandLine(const std::vector<std::string>& args, Mode mode = Mode::Execute);

// The tool's command tree (for the completion script and the tests).
std::unique_ptr<CLI::App> makeApp(std::vector<Command>& commands);

// --- Option groups shared by several commands --------------------------------------------------

// --scene S|FILE.json, --set key=value..., and optionally --dt H and --integrator NAME.
struct SceneArgs {
    std::string scene = "ring2d";
    std::vector<std::string> set;
    std::optional<std::string> dt;          // validated by the parameter table
    std::optional<std::string> integrator;  // default: the scene file's, else rk4
};
void addSceneOptions(CLI::App& app, SceneArgs& args, bool withDt = true, bool withIntegrator = true);

struct SceneSetup {
    simcore::ParameterSet params;
    std::string sceneName;
    std::string integrator = "rk4";
    std::optional<simlab::SceneFile::State> state;  // from a scene file that saved one
};
SceneSetup sceneSetup(const SceneArgs& args);
// The scene file named by --scene, or empty when it names a built-in scene.
std::string sceneFileOf(const SceneArgs& args);

// Integrator tunables: --atol, --rtol, --newton, --fixed-step, --error-estimate.
void addIntegratorOptions(CLI::App& app, simcore::IntegratorOptions& options);

// --json: print the command's result as JSON on standard output (instead of text).
void addJsonFlag(CLI::App& app, bool& json);
// Writes a JSON value (nlohmann::ordered_json, passed as its text) and a newline to stdout.
void printJsonText(const std::string& text);
template <class Json>
void printJson(const Json& value) {
    printJsonText(value.dump(2));
}
// A CSV output option: FILE, or - for standard output (written in place, never replaced).
CLI::Option* addCsvOption(CLI::App& app, std::string& path, const std::string& help);

// Number validators for CLI11 options: finite numbers in a range, whole numbers in a range.
CLI::Validator finiteIn(double min, double max, bool minExclusive);
CLI::Validator wholeIn(long min, long max);

// The pre-run warning: dt above the explicit stability estimate (empty when none applies).
std::string stabilityWarning(const simcore::ParameterSet& params, std::string_view integrator);

// Outputs never overwrite an input or each other (issue 18): the files named, as (option, path)
// pairs with inputs first and empty paths skipped, are compared by identity, not by spelling
// (device and inode of an existing file, or of the folder a new one goes in and its name, so
// links, "./" and ".." count). A clash is a UsageError naming both options, before anything is
// written.
using NamedPath = std::pair<std::string, std::string>;
void checkDistinctFiles(const std::vector<NamedPath>& inputsThenOutputs);

// Comma-separated lists: both refuse an empty list, an empty item and an item listed twice.
std::vector<double> numberList(const std::string& option, const std::string& text);
std::vector<std::string> nameList(const std::string& option, const std::string& text);
// --shard K/N, returned 0-based: {K-1, N}; {0, 1} when empty.
std::pair<int, int> parseShard(const std::string& text);

// The commands, each registered on the tool's app.
Command addScenesCommand(CLI::App& app);
Command addParamsCommand(CLI::App& app);
Command addIntegratorsCommand(CLI::App& app);
Command addRunCommand(CLI::App& app);
Command addStudyCommand(CLI::App& app);
Command addConservationCommand(CLI::App& app);
Command addSweepCommand(CLI::App& app);
Command addStabilityCommand(CLI::App& app);
Command addRestitutionCommand(CLI::App& app);
Command addGalleryCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addCompletionCommand(CLI::App& app);

}  // namespace cli
