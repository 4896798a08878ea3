#pragma once
// The elastic-lab-cli commands on CLI11: each command binds its options to a struct of its own
// (with text, unit and default for --help), checks everything that can be known before any work
// begins, then runs.
//
// Exit status contract: 0 success, 2 bad input (one line on stderr naming the problem and what
// is allowed), 3 the simulation failed (reason, step and time on stderr).

#include <atomic>
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
#include "simlab/request.h"
#include "simlab/scenefile.h"

namespace cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitFailed = 3;
// The most steps one fixed-step run may take: the front door's bound (simlab/request.h).
inline constexpr double kMaxSteps = simlab::kMaxSteps;

// Bad input: reported on one line, exit status 2. The front door's refusal (simlab/request.h),
// so that a check made there and one made here read and exit alike.
using UsageError = simlab::RequestError;

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

// --scene S|FILE.json, --set key=value..., and optionally --dt H and --integrator NAME: the
// front door's scene request, resolved and checked by simlab::resolveScene.
using SceneArgs = simlab::SceneRequest;
void addSceneOptions(CLI::App& app, SceneArgs& args, bool withDt = true, bool withIntegrator = true);

using SceneSetup = simlab::SceneSetup;
inline SceneSetup sceneSetup(const SceneArgs& args) { return simlab::resolveScene(args); }
// The scene file named by --scene, or empty when it names a built-in scene.
inline std::string sceneFileOf(const SceneArgs& args) { return simlab::sceneFileOf(args.scene); }

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

// Outputs never overwrite an input or each other, never a FIFO (simlab::checkFiles): a clash
// is a UsageError naming both options, before anything is written.
using NamedPath = simlab::NamedPath;
inline void checkFiles(const std::vector<NamedPath>& inputs, const std::vector<NamedPath>& outputs) {
    simlab::checkFiles(inputs, outputs);
}

// Ctrl+C (SIGINT) and SIGTERM (a Slurm time limit, a container stop) during a long command:
// while one of these lives, the signal only sets a flag the command polls between whole steps;
// the command then writes its outputs so far and exits 128 + the signal (130, 143). A signal
// the tool was started ignoring (a background job's SIGINT) stays ignored. The previous
// handlers come back at destruction.
class StopSignals {
public:
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;
    // The signal caught, or 0.
    int caught() const;
    // True once a signal is caught: the cancel flag simlab's long computations poll (a lock-free
    // atomic, set by the handler itself).
    const std::atomic<bool>* flag() const;
    static const char* name(int signal);
};

// A progress line on standard error, rewritten in place ("\r"), only on a terminal and unless
// quiet; cleared at the end. update() is cheap: it looks at the clock every 64 calls and writes
// at most 4 times a second.
class ProgressLine {
public:
    explicit ProgressLine(bool quiet);
    ~ProgressLine();
    bool enabled() const { return m_enabled; }
    void update(double done, double total, const char* unit, long steps);
    void clear();

private:
    bool m_enabled = false;
    unsigned m_calls = 0;
    double m_start = 0.0, m_last = -1.0;
    std::size_t m_width = 0;
};

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

// bench --interleave N: the order in which `runs` runs of `steps` timed steps each take turns of
// at most `interleave` steps (run 0, 1, ..., 0, 1, ...; the last turns shorter when `steps` is not
// a multiple of N), so that each run's timed steps are spread over the same minutes.
struct BenchTurn {
    int run;
    long steps;
};
std::vector<BenchTurn> benchTurns(long steps, long interleave, int runs);

}  // namespace cli
