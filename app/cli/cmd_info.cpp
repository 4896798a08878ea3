// `scenes`, `params` and `integrators`: listings generated from simcore's tables.
#include <cstdio>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/cli/cli.h"
#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simcore/scaling.h"
#include "simcore/scenes.h"
#include "simcore/world.h"
#include "simlab/request.h"

namespace cli {

Command addScenesCommand(CLI::App& app) {
    CLI::App* sub = app.add_subcommand("scenes", "list the built-in scenes");
    auto json = std::make_shared<bool>(false);
    addJsonFlag(*sub, *json);
    return {sub, [] {}, [json] {
                nlohmann::ordered_json list = nlohmann::ordered_json::array();
                for (const simcore::SceneInfo& s : simcore::sceneTable()) {
                    if (*json)
                        list.push_back({{"name", s.name}, {"description", s.description}, {"gas", simcore::hasGas(s.kind)}});
                    else
                        std::printf("%-18s %s\n", std::string(s.name).c_str(), std::string(s.description).c_str());
                }
                for (const simcore::WorldSceneInfo& s : simcore::worldSceneTable()) {
                    if (*json)
                        list.push_back({{"name", s.name}, {"description", s.description}, {"gas", true},
                                        {"bodies", simcore::worldScene(s.name)->bodies.size()}});
                    else
                        std::printf("%-18s %s\n", std::string(s.name).c_str(), std::string(s.description).c_str());
                }
                if (*json) printJson(list);
                return kExitOk;
            }};
}

Command addIntegratorsCommand(CLI::App& app) {
    CLI::App* sub = app.add_subcommand("integrators", "list the integrators with their order and family");
    auto json = std::make_shared<bool>(false);
    addJsonFlag(*sub, *json);
    return {sub, [] {}, [json] {
                nlohmann::ordered_json list = nlohmann::ordered_json::array();
                for (const simcore::IntegratorInfo& i : simcore::integratorTable()) {
                    if (*json)
                        list.push_back({{"name", i.name}, {"order", i.order}, {"family", i.family}, {"description", i.description}});
                    else
                        std::printf("%-18s order %-2d %-12s %s\n", std::string(i.name).c_str(), i.order,
                                    std::string(i.family).c_str(), std::string(i.description).c_str());
                }
                if (*json) printJson(list);
                return kExitOk;
            }};
}

namespace {

struct ParamsArgs {
    std::optional<std::string> scene;
    std::vector<std::string> set;
    std::optional<simcore::SceneKind> kind;
    std::optional<simcore::ParameterSet> params;  // the scene's, after --set
    std::optional<simcore::WorldSpec> world;      // a scene of several bodies, after --set
    bool json = false;
};

// A scene of several bodies: the world's shared values, then what each body uses.
int listWorldParams(const simcore::WorldSpec& spec) {
    const simcore::ParameterSet& lead = spec.bodies.front().params;
    std::printf("%s: %zu bodies; world parameters (shared by every body; --set key=value):\n", spec.name.c_str(),
                spec.bodies.size());
    for (const simcore::ParamSpec* s : simcore::parametersFor(lead.kind()))
        if (simcore::isWorldParameter(s->id))
            std::printf("  %-17s %-12g %-7s %s\n", std::string(s->key).c_str(), lead.get(s->id),
                        s->unit.empty() ? "-" : std::string(s->unit).c_str(), std::string(s->meaning).c_str());
    for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
        const simcore::WorldBodySpec& b = spec.bodies[k];
        std::printf("\nbody%zu: %s (--set body%zu.key=value)\n", k + 1,
                    std::string(simcore::sceneInfo(b.params.kind()).name).c_str(), k + 1);
        std::printf("  %-17s (%g, %g, %g) m\n  %-17s (%g, %g, %g) m/s\n", "position_x/y/z", b.position.x(),
                    b.position.y(), b.position.z(), "velocity_x/y/z", b.velocity.x(), b.velocity.y(), b.velocity.z());
        for (const simcore::ParamSpec* s : simcore::parametersFor(b.params.kind()))
            if (!simcore::isWorldParameter(s->id))
                std::printf("  %-17s %-12g %-7s %s\n", std::string(s->key).c_str(), b.params.get(s->id),
                            s->unit.empty() ? "-" : std::string(s->unit).c_str(), std::string(s->meaning).c_str());
        std::printf("  this body uses:\n%s\n",
                    simcore::bodyValuesText(b.params, simcore::bodyValues(b.params)).c_str());
    }
    return kExitOk;
}

// --json for a scene of several bodies: {"world": {key: value}, "bodies": [{"kind", "position",
// "velocity", key: value...}]}, the values after --set.
int listWorldParamsJson(const simcore::WorldSpec& spec) {
    const simcore::ParameterSet& lead = spec.bodies.front().params;
    nlohmann::ordered_json world = nlohmann::ordered_json::object();
    for (const simcore::ParamSpec* s : simcore::parametersFor(lead.kind()))
        if (simcore::isWorldParameter(s->id)) world[std::string(s->key)] = lead.get(s->id);
    nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
    for (const simcore::WorldBodySpec& b : spec.bodies) {
        nlohmann::ordered_json body = {{"kind", simcore::sceneInfo(b.params.kind()).name},
                                       {"position", {b.position.x(), b.position.y(), b.position.z()}},
                                       {"velocity", {b.velocity.x(), b.velocity.y(), b.velocity.z()}}};
        for (const simcore::ParamSpec* s : simcore::parametersFor(b.params.kind()))
            if (!simcore::isWorldParameter(s->id)) body[std::string(s->key)] = b.params.get(s->id);
        bodies.push_back(body);
    }
    printJson(nlohmann::ordered_json{{"scene", spec.name}, {"world", world}, {"bodies", bodies}});
    return kExitOk;
}

// --json: the same listing as a JSON array (defaults as numbers; an inherited default as null
// with "inherits": the key it follows; choices as a list of names).
int listParamsJson(const ParamsArgs& args, const std::vector<const simcore::ParamSpec*>& specs) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const simcore::ParamSpec* s : specs) {
        nlohmann::ordered_json p = {{"key", s->key}, {"unit", s->unit}};
        if (s->inherits != simcore::Param::Count) {
            p["default"] = nullptr;
            p["inherits"] = simcore::paramSpec(s->inherits).key;
        } else {
            p["default"] = args.kind ? s->defaultFor(*args.kind) : s->defaultValue;
        }
        p["min"] = s->minValue;
        p["max"] = s->maxValue;
        p["min_exclusive"] = s->minExclusive;
        p["integer"] = s->integer;
        nlohmann::ordered_json choices = nlohmann::ordered_json::array();
        for (std::string_view rest = s->choices; !rest.empty();) {
            const auto bar = rest.find('|');
            choices.push_back(rest.substr(0, bar));
            rest = bar == std::string_view::npos ? std::string_view{} : rest.substr(bar + 1);
        }
        p["choices"] = choices;
        p["meaning"] = s->meaning;
        if (args.kind) p["value"] = args.params->get(s->id);  // after --set
        list.push_back(p);
    }
    printJson(list);
    return kExitOk;
}

int listParams(const ParamsArgs& args) {
    std::vector<const simcore::ParamSpec*> specs;
    const std::optional<simcore::SceneKind> kind = args.kind;
    if (kind) {
        specs = simcore::parametersFor(*kind);
    } else {
        for (const simcore::ParamSpec& s : simcore::parameterTable()) specs.push_back(&s);
    }
    if (args.json) return listParamsJson(args, specs);
    std::printf("%-15s %-7s %-12s %-22s %s\n", "key", "unit", "default", "range", "meaning");
    for (const simcore::ParamSpec* s : specs) {
        std::string def;
        if (s->inherits != simcore::Param::Count) {
            def = "=" + std::string(simcore::paramSpec(s->inherits).key);
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
        const simcore::ParameterSet& params = *args.params;
        std::printf("\nthis body uses:\n%s\n", simcore::bodyValuesText(params, simcore::bodyValues(params)).c_str());
    }
    return kExitOk;
}

}  // namespace

Command addParamsCommand(CLI::App& app) {
    auto args = std::make_shared<ParamsArgs>();
    CLI::App* sub = app.add_subcommand("params", "list every parameter: key, unit, default, range, meaning; with "
                                                 "--scene, the scene's, and the values its body uses");
    CLI::Option* scene = sub->add_option("--scene", args->scene, "a built-in scene (" + simcore::sceneNames() + ")")
                             ->type_name("S");
    sub->add_option("--set", args->set, "set a parameter first (repeatable), to see the values the body then uses")
        ->type_name("KEY=VALUE")
        ->allow_extra_args(false)
        ->needs(scene);
    addJsonFlag(*sub, args->json);
    return {sub,
            [args] {
                if (!args->scene) return;
                if (simcore::worldScene(*args->scene)) {  // through the front door, as `run` takes it
                    simlab::SceneRequest request;
                    request.scene = *args->scene;
                    request.set = args->set;
                    request.severalBodies = true;
                    args->world = simlab::resolveScene(request).world;
                    return;
                }
                const simcore::SceneInfo* info = simcore::findScene(*args->scene);
                if (!info)
                    throw UsageError(simcore::unknownSceneMessage(*args->scene));
                args->kind = info->kind;
                simcore::ParameterSet params(info->kind);
                for (const std::string& assignment : args->set)
                    if (auto error = params.assign(assignment)) throw UsageError("--set " + *error);
                if (auto error = simcore::validateShape(params)) throw UsageError(*error);
                args->params = std::move(params);
            },
            [args] {
                if (args->world) return args->json ? listWorldParamsJson(*args->world) : listWorldParams(*args->world);
                return listParams(*args);
            }};
}

}  // namespace cli
