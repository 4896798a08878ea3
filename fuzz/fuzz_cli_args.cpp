// Fuzz target: the CLI's option and --set parsing. Input lines are arguments; any input is
// either a scene setup or a UsageError (exit status 2), never a crash.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args;
    std::string current;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == '\n') {
            args.push_back(current);
            current.clear();
        } else {
            current.push_back(static_cast<char>(data[i]));
        }
    }
    if (!current.empty()) args.push_back(current);
    try {
        auto names = cli::sceneOptionNames();
        names.insert(names.end(), {"duration", "every", "csv"});
        cli::Options options(args, names, {"quiet"});
        // Scene files are the other fuzz target's business: skip paths here.
        if (options.has("scene") && options.value("scene").find('/') != std::string::npos) return 0;
        cli::SceneSetup setup = cli::sceneSetup(options);
        options.number("duration", 1.0, 0.0, 1e7, true);
        options.integer("every", 1, 1, 1000000000L);
        for (const simcore::ParamSpec* spec : simcore::parametersFor(setup.params.kind()))
            if (simcore::validateValue(*spec, setup.params.get(spec->key))) std::abort();  // nothing invalid gets through
    } catch (const cli::UsageError& e) {
        if (std::string(e.what()).empty()) std::abort();
    }
    return 0;
}
