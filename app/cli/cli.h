#pragma once
// Shared pieces of the elastic-lab-cli commands: option parsing and scene setup.
//
// Exit status contract: 0 success, 2 bad input (one line on stderr naming the problem and
// what is allowed), 3 the simulation failed (reason, step and time on stderr).

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "integrators.h"
#include "params.h"
#include "scenefile.h"

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

// Options of one command: "--name value" pairs (repeatable ones keep their order) and flags.
class Options {
public:
    Options(const std::vector<std::string>& args, const std::vector<std::string>& withValue,
            const std::vector<std::string>& flags = {});
    bool has(const std::string& name) const { return m_values.count(name) != 0; }
    const std::string& value(const std::string& name) const { return m_values.at(name).back(); }
    std::string valueOr(const std::string& name, const std::string& fallback) const {
        return has(name) ? value(name) : fallback;
    }
    const std::vector<std::string>& all(const std::string& name) const;

    double number(const std::string& name, double fallback, double min, double max,
                  bool minExclusive) const;
    long integer(const std::string& name, long fallback, long min, long max) const;

private:
    std::map<std::string, std::vector<std::string>> m_values;
};

struct SceneSetup {
    simcore::ParameterSet params;
    std::string sceneName;
    std::string integrator = "rk4";
    std::optional<simcore::SceneFile::State> state;  // from a scene file that saved one
};

// --scene S|FILE.json (default ring2d), --set key=value..., --dt H, --integrator NAME.
SceneSetup sceneSetup(const Options& options);

// Integrator tunables: --atol, --rtol, --fixed-step, --error-estimate, --newton.
simcore::IntegratorOptions integratorOptions(const Options& options);
std::vector<std::string> integratorOptionNames();  // the ones with a value
std::vector<std::string> integratorFlagNames();    // the flags
// The pre-run warning: dt above the explicit stability estimate (empty when none applies).
std::string stabilityWarning(const simcore::ParameterSet& params, std::string_view integrator);
// Outputs never overwrite an input or each other (issue 18): the files named by the given output
// options, by `--scene FILE.json` and by `--from-csv`, compared by identity, not by spelling
// (device and inode of an existing file, or of the folder a new one goes in and its name, so
// links, "./" and ".." count). A clash is a UsageError naming both options, before anything is
// written.
void checkDistinctFiles(const Options& options, std::initializer_list<const char*> outputs);
// The option names sceneSetup reads, for a command's allowed list.
std::vector<std::string> sceneOptionNames();

int commandScenes(const std::vector<std::string>& args);
int commandParams(const std::vector<std::string>& args);
int commandIntegrators(const std::vector<std::string>& args);
// Comma-separated lists and --shard K/N (returned 0-based: {K-1, N}).
std::vector<double> numberList(const std::string& option, const std::string& text);
std::vector<std::string> nameList(const std::string& option, const std::string& text);
// Both refuse an empty list, an empty item and an item listed twice.
std::pair<int, int> parseShard(const Options& options);

int commandRun(const std::vector<std::string>& args);
int commandStudy(const std::vector<std::string>& args);
int commandStability(const std::vector<std::string>& args);
int commandRestitution(const std::vector<std::string>& args);
int commandGallery(const std::vector<std::string>& args);
int commandBench(const std::vector<std::string>& args);

}  // namespace cli
