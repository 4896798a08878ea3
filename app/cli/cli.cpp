#include "cli.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <sys/stat.h>

#include "integrators.h"
#include "scenefile.h"
#include "scenes.h"
#include "simulation.h"
#include "stability.h"

namespace cli {

Options::Options(const std::vector<std::string>& args, const std::vector<std::string>& withValue,
                 const std::vector<std::string>& flags) {
    auto listed = [](const std::vector<std::string>& list, const std::string& name) {
        return std::find(list.begin(), list.end(), name) != list.end();
    };
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.rfind("--", 0) != 0) throw UsageError("unexpected argument '" + arg + "'");
        std::string name = arg.substr(2), inlineValue;
        bool hasInline = false;
        if (auto eq = name.find('='); eq != std::string::npos) {
            inlineValue = name.substr(eq + 1);
            name = name.substr(0, eq);
            hasInline = true;
        }
        if (listed(flags, name)) {
            if (hasInline) throw UsageError("--" + name + " takes no value");
            m_values[name].push_back("1");
        } else if (listed(withValue, name)) {
            if (hasInline) {
                m_values[name].push_back(inlineValue);
            } else {
                if (i + 1 >= args.size()) throw UsageError("--" + name + " needs a value");
                m_values[name].push_back(args[++i]);
            }
        } else {
            std::string allowed;
            for (const auto& list : {withValue, flags})
                for (const auto& n : list) allowed += (allowed.empty() ? "--" : ", --") + n;
            throw UsageError("unknown option '" + arg + "'; allowed: " + allowed);
        }
    }
}

const std::vector<std::string>& Options::all(const std::string& name) const {
    static const std::vector<std::string> none;
    auto it = m_values.find(name);
    return it == m_values.end() ? none : it->second;
}

double Options::number(const std::string& name, double fallback, double min, double max,
                       bool minExclusive) const {
    if (!has(name)) return fallback;
    const auto v = simcore::parseNumber(value(name));
    const std::string range = std::string(minExclusive ? "(" : "[") + std::to_string(min) + ", " +
                              std::to_string(max) + "]";
    if (!v) throw UsageError("--" + name + ": '" + value(name) + "' is not a finite number; allowed " + range);
    if ((minExclusive ? *v <= min : *v < min) || *v > max)
        throw UsageError("--" + name + " = " + value(name) + " is out of range; allowed " + range);
    return *v;
}

long Options::integer(const std::string& name, long fallback, long min, long max) const {
    if (!has(name)) return fallback;
    const auto v = simcore::parseNumber(value(name));
    const std::string range = "whole numbers in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
    if (!v || *v != std::floor(*v) || *v < static_cast<double>(min) || *v > static_cast<double>(max))
        throw UsageError("--" + name + ": '" + value(name) + "' is not allowed; allowed " + range);
    return static_cast<long>(*v);
}

namespace {

// What a path names: an existing file's (device, inode), or for a file still to be created the
// (device, inode) of its folder and its name.
struct FileIdentity {
    dev_t device = 0;
    ino_t inode = 0;
    std::string newName;  // empty: an existing file
    bool operator==(const FileIdentity&) const = default;
};

std::optional<FileIdentity> identify(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) return FileIdentity{st.st_dev, st.st_ino, {}};
    const std::filesystem::path p(path);
    const std::filesystem::path folder = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
    if (::stat(folder.c_str(), &st) != 0) return std::nullopt;  // the write reports the missing folder
    return FileIdentity{st.st_dev, st.st_ino, p.filename().string()};
}

}  // namespace

void checkDistinctFiles(const Options& options, std::initializer_list<const char*> outputs) {
    std::vector<std::pair<std::string, FileIdentity>> seen;  // option, identity
    auto add = [&](const std::string& option, const std::string& path) {
        const auto id = identify(path);
        if (!id) return;
        for (const auto& [other, otherId] : seen)
            if (otherId == *id)
                throw UsageError("--" + option + " " + simcore::quoteShort(path, 200) + " is the same file as --" + other +
                                 "; every output must be a file of its own, apart from the inputs");
        seen.emplace_back(option, *id);
    };
    // Inputs first, so that the message names the output that would have destroyed one.
    if (options.has("scene") && options.value("scene").ends_with(".json")) add("scene", options.value("scene"));
    if (options.has("from-csv")) add("from-csv", options.value("from-csv"));
    for (const char* name : outputs)
        if (options.has(name)) add(name, options.value(name));
}

std::vector<std::string> sceneOptionNames() { return {"scene", "set", "dt", "integrator"}; }

SceneSetup sceneSetup(const Options& options) {
    SceneSetup setup;
    setup.sceneName = options.valueOr("scene", "ring2d");
    const simcore::SceneInfo* scene = simcore::findScene(setup.sceneName);
    std::string fileIntegrator;
    if (!scene && setup.sceneName.size() > 5 && setup.sceneName.ends_with(".json")) {
        // A scene file wherever a scene name is taken; --set, --dt, --integrator override it.
        simcore::SceneFileResult read = simcore::readSceneFile(setup.sceneName);
        if (!read.file) throw UsageError(read.error);
        setup.sceneName = read.file->sceneName;
        scene = simcore::findScene(setup.sceneName);
        setup.params = read.file->params;
        fileIntegrator = read.file->integrator;
        setup.state = read.file->state;
    } else if (!scene) {
        throw UsageError("unknown scene '" + setup.sceneName + "'; allowed: " + simcore::sceneNames() +
                         ", or a scene file (.json)");
    } else {
        setup.params = simcore::ParameterSet(scene->kind);
    }
    for (const std::string& assignment : options.all("set"))
        if (auto error = setup.params.assign(assignment)) throw UsageError("--set " + *error);
    if (options.has("dt"))
        if (auto error = setup.params.setFromText("dt", options.value("dt")))
            throw UsageError("--" + *error);
    setup.integrator = options.valueOr("integrator", fileIntegrator.empty() ? "rk4" : fileIntegrator);
    if (!simcore::makeIntegrator(setup.integrator))
        throw UsageError("unknown integrator '" + setup.integrator +
                         "'; allowed: " + simcore::integratorNames());
    if (auto error = simcore::validateShape(setup.params)) throw UsageError(*error);
    return setup;
}

std::vector<std::string> integratorOptionNames() { return {"atol", "rtol", "newton"}; }
std::vector<std::string> integratorFlagNames() { return {"fixed-step", "error-estimate"}; }

simcore::IntegratorOptions integratorOptions(const Options& options) {
    simcore::IntegratorOptions o;
    o.atol = options.number("atol", o.atol, 0.0, 1.0, true);
    o.rtol = options.number("rtol", o.rtol, 0.0, 1.0, false);
    o.newtonIterations = static_cast<int>(options.integer("newton", o.newtonIterations, 1, 50));
    o.fixedStep = options.has("fixed-step");
    o.stepDoubling = options.has("error-estimate");
    return o;
}

std::string stabilityWarning(const simcore::ParameterSet& params, std::string_view integrator) {
    simcore::Simulation sim(params, integrator);
    const auto advice = simcore::stabilityAdvice(sim);
    if (!advice) return {};
    char suggestion[64];
    std::snprintf(suggestion, sizeof suggestion, " (predicted stable: --dt %g)", advice->suggestedDt);
    return "warning: " + advice->message + suggestion;
}

}  // namespace cli
