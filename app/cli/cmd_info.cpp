// `scenes`, `params` and `integrators`: listings generated from simcore's tables.
#include <cstdio>
#include <iostream>

#include "cli.h"
#include "integrators.h"
#include "scaling.h"
#include "scenes.h"

namespace cli {

int commandScenes(const std::vector<std::string>& args) {
    Options options(args, {});
    for (const simcore::SceneInfo& s : simcore::sceneTable())
        std::printf("%-18s %s\n", std::string(s.name).c_str(), std::string(s.description).c_str());
    return kExitOk;
}

int commandIntegrators(const std::vector<std::string>& args) {
    Options options(args, {});
    for (const simcore::IntegratorInfo& i : simcore::integratorTable())
        std::printf("%-18s order %d  %s\n", std::string(i.name).c_str(), i.order,
                    std::string(i.description).c_str());
    return kExitOk;
}

int commandParams(const std::vector<std::string>& args) {
    Options options(args, {"scene", "set"});
    if (options.has("set") && !options.has("scene")) throw UsageError("params: --set needs --scene");
    std::vector<const simcore::ParamSpec*> specs;
    std::optional<simcore::SceneKind> kind;
    if (options.has("scene")) {
        const simcore::SceneInfo* scene = simcore::findScene(options.value("scene"));
        if (!scene)
            throw UsageError("unknown scene '" + options.value("scene") + "'; allowed: " + simcore::sceneNames());
        kind = scene->kind;
        specs = simcore::parametersFor(scene->kind);
    } else {
        for (const simcore::ParamSpec& s : simcore::parameterTable()) specs.push_back(&s);
    }
    std::printf("%-15s %-7s %-12s %-22s %s\n", "key", "unit", "default", "range", "meaning");
    for (const simcore::ParamSpec* s : specs) {
        std::string def;
        if (!s->inherits.empty()) {
            def = "=" + std::string(s->inherits);
        } else {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "%g", kind ? s->defaultFor(*kind) : s->defaultValue);
            def = buffer;
        }
        std::string meaning(s->meaning);
        if (!kind) {
            std::string where;
            for (const simcore::SceneInfo& scene : simcore::sceneTable())
                if (s->scenes & simcore::sceneBit(scene.kind)) where += (where.empty() ? "" : ",") + std::string(scene.name);
            meaning += " [" + where + "]";
        }
        std::printf("%-15s %-7s %-12s %-22s %s\n", std::string(s->key).c_str(),
                    s->unit.empty() ? "-" : std::string(s->unit).c_str(), def.c_str(),
                    s->rangeText().c_str(), meaning.c_str());
    }
    if (kind) {
        // What these values mean for this body: the per-particle and per-spring values it uses
        // at its resolution under its scaling (scaling.h), after any --set.
        simcore::ParameterSet params(*kind);
        for (const std::string& assignment : options.all("set"))
            if (auto error = params.assign(assignment)) throw UsageError("--set " + *error);
        if (auto error = simcore::validateShape(params)) throw UsageError(*error);
        std::printf("\nthis body uses:\n%s\n", simcore::bodyValuesText(params, simcore::bodyValues(params)).c_str());
    }
    return kExitOk;
}

}  // namespace cli
