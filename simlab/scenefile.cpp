#include "simlab/scenefile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "simcore/integrator_table.h"
#include "simcore/scenes.h"
#include "simcore/simulation.h"
#include "simlab/output.h"

namespace simlab {

using simcore::Param;
using simcore::ParamSpec;
using simcore::ParameterSet;
using simcore::SceneInfo;
using simcore::Simulation;
using simcore::bodySize;
using simcore::findParam;
using simcore::findScene;
using simcore::integratorNames;
using simcore::makeIntegrator;
using simcore::parametersFor;
using simcore::quoteShort;
using simcore::sceneNames;
using simcore::validateShape;

namespace {

using Json = nlohmann::json;

SceneFileResult failure(std::string message) { return {std::nullopt, std::move(message)}; }

// 1-based line of a byte offset.
int lineOf(const std::string& text, std::size_t offset) {
    int line = 1;
    for (std::size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n';
    return line;
}

std::optional<std::string> onlyKeys(const Json& object, const std::string& where,
                                    std::initializer_list<const char*> allowed) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        bool known = false;
        for (const char* key : allowed) known |= it.key() == key;
        if (!known) {
            std::string list;
            for (const char* key : allowed) list += (list.empty() ? "" : ", ") + std::string(key);
            return "unknown key " + quoteShort(it.key()) + " in " + where + "; allowed: " + list;
        }
    }
    return std::nullopt;
}

std::optional<std::string> readVectors(const Json& array, const std::string& key, int count,
                                       Eigen::Matrix3Xd& out) {
    if (!array.is_array()) return "state." + key + " must be an array of [x, y, z]";
    if (static_cast<int>(array.size()) != count)
        return "state." + key + " has " + std::to_string(array.size()) + " rows; the body has " +
               std::to_string(count) + " particles";
    out.resize(3, count);
    for (int i = 0; i < count; ++i) {
        const Json& row = array[static_cast<std::size_t>(i)];
        if (!row.is_array() || row.size() != 3)
            return "state." + key + "[" + std::to_string(i) + "] must be [x, y, z]";
        for (int k = 0; k < 3; ++k) {
            const Json& value = row[static_cast<std::size_t>(k)];
            if (!value.is_number() || !std::isfinite(value.get<double>()))
                return "state." + key + "[" + std::to_string(i) + "] must hold finite numbers";
            out(k, i) = value.get<double>();
        }
    }
    return std::nullopt;
}

// A key that appears twice in one object: JSON leaves it to the reader (nlohmann keeps the last),
// and a scene file with two "ks" is a mistake to point at, not a value to pick.
struct DuplicateKey {
    std::string key;
    int occurrence = 0;  // the how-many-th time this key text appears in the file
};

// 1-based line of the n-th `"key"` followed by a colon (only keys are followed by one).
int lineOfKey(const std::string& text, const std::string& key, int occurrence) {
    const std::string quoted = '"' + key + '"';
    std::size_t at = 0;
    for (int seen = 0; (at = text.find(quoted, at)) != std::string::npos; at += quoted.size()) {
        std::size_t after = at + quoted.size();
        while (after < text.size() && std::isspace(static_cast<unsigned char>(text[after]))) ++after;
        if (after < text.size() && text[after] == ':' && ++seen == occurrence) return lineOf(text, at);
    }
    return 0;
}

struct TooLarge {
    std::string what;
};
// One value of a "parameters" object into `set`: a number, or a choice by its name ("contact":
// "projection"). The message starts with `where` and the key.
std::optional<std::string> readParameter(const std::string& key, const Json& value, const std::string& where,
                                         ParameterSet& set) {
    const ParamSpec* spec = findParam(key);
    if (value.is_string() && spec && !spec->choices.empty()) {
        if (auto error = set.setFromText(key, value.get<std::string>())) return where + *error;
        return std::nullopt;
    }
    if (!value.is_number())
        return where + quoteShort(key) + ": expected a number, got " + std::string(value.type_name());
    if (auto error = set.set(key, value.get<double>())) return where + *error;
    return std::nullopt;
}

std::optional<std::string> readParameters(const Json& params, const std::string& where, ParameterSet& set) {
    if (!params.is_object()) return where + " expected an object of key: number";
    for (auto it = params.begin(); it != params.end(); ++it)
        if (auto error = readParameter(it.key(), it.value(), where, set)) return error;
    return std::nullopt;
}

// [x, y, z] of finite numbers.
std::optional<std::string> readVector(const Json& value, const std::string& where, Eigen::Vector3d& out) {
    if (!value.is_array() || value.size() != 3) return where + ": expected [x, y, z]";
    for (std::size_t k = 0; k < 3; ++k) {
        if (!value[k].is_number() || !std::isfinite(value[k].get<double>()) || std::abs(value[k].get<double>()) > 1e6)
            return where + ": expected finite numbers within +-1e6";
        out[static_cast<Eigen::Index>(k)] = value[k].get<double>();
    }
    return std::nullopt;
}

std::string bodyLabel(std::size_t k) { return "body" + std::to_string(k + 1); }

// One entry of "bodies": kind, position, velocity, its own parameters (over `common`: the
// top-level ones). World parameters belong at the top.
std::optional<std::string> readBody(const Json& entry, std::size_t k, const Json* common, simcore::WorldBodySpec& body) {
    const std::string name = bodyLabel(k);
    if (!entry.is_object()) return name + ": expected an object with kind, position, velocity, parameters";
    if (auto error = onlyKeys(entry, name, {"kind", "position", "velocity", "parameters"})) return error;
    if (!entry.contains("kind") || !entry["kind"].is_string()) return name + ".kind: expected a body kind (ring2d, sphere3d, sphere3d-latlong)";
    const std::string kind = entry["kind"].get<std::string>();
    const SceneInfo* scene = findScene(kind);
    if (!scene || scene->kind == simcore::SceneKind::Spring1d)
        return name + ".kind: unknown body kind " + quoteShort(kind) + "; allowed: ring2d, sphere3d, sphere3d-latlong";
    body.params = ParameterSet(scene->kind);
    // The top-level values first (those this kind has), then the body's own.
    if (common)
        for (auto it = common->begin(); it != common->end(); ++it)
            if (const ParamSpec* spec = findParam(it.key()); spec && body.params.has(spec->id))
                if (auto error = readParameter(it.key(), it.value(), "parameters.", body.params)) return error;
    if (entry.contains("parameters")) {
        const Json& own = entry["parameters"];
        if (!own.is_object()) return name + ".parameters: expected an object of key: number";
        for (auto it = own.begin(); it != own.end(); ++it) {
            const ParamSpec* spec = findParam(it.key());
            if (spec && simcore::isWorldParameter(spec->id))
                return name + "." + it.key() + ": a world parameter, shared by every body; give it in the top-level "
                                               "parameters";
            if (!spec || !body.params.has(spec->id))
                return name + "." + quoteShort(it.key()) + ": " + *ParameterSet(body.params.kind()).set(it.key(), 0.0);
            if (auto error = readParameter(it.key(), it.value(), name + ".", body.params)) return error;
        }
    }
    if (entry.contains("position"))
        if (auto error = readVector(entry["position"], name + ".position", body.position)) return error;
    if (entry.contains("velocity"))
        if (auto error = readVector(entry["velocity"], name + ".velocity", body.velocity)) return error;
    if (scene->kind == simcore::SceneKind::Ring2d && (body.position.z() != 0.0 || body.velocity.z() != 0.0))
        return name + ".position/velocity: a 2D body moves in the xy plane (z stays 0)";
    return std::nullopt;
}

// state.step, state.time, state.next_step.
std::optional<std::string> readClock(const Json& state, SceneFile::State& s) {
    if (state.contains("step")) {
        // 64 bits, and room left to run on: a step count near 2^63 would overflow.
        const Json& step = state["step"];
        if (!step.is_number_integer() || (step.is_number_unsigned() ? step.get<std::uint64_t>() > kMaxSavedStep
                                                                    : step.get<std::int64_t>() < 0))
            return "state.step: expected a whole number in [0, " + std::to_string(kMaxSavedStep) + "]";
        s.step = static_cast<long>(step.get<std::int64_t>());
    }
    if (state.contains("time")) {
        if (!state["time"].is_number() || !std::isfinite(state["time"].get<double>()) || state["time"].get<double>() < 0)
            return std::string("state.time: expected a finite number >= 0");
        s.time = state["time"].get<double>();
    }
    if (state.contains("next_step")) {
        const Json& h = state["next_step"];
        if (!h.is_number() || !std::isfinite(h.get<double>()) || !(h.get<double>() > 0.0))
            return std::string("state.next_step: expected a finite number > 0 (seconds)");
        s.nextStep = h.get<double>();
    }
    return std::nullopt;
}

// "state" of a world: step, time, next_step and each body's positions and velocities.
std::optional<std::string> readWorldState(const Json& state, const simcore::WorldSpec& spec, SceneFile::State& s);

// "state" of one body: step, time, next_step, and its positions and velocities, as many as the
// shape `params` has particles.
std::optional<std::string> readBodyState(const Json& state, const ParameterSet& params, SceneFile::State& s) {
    if (!state.is_object()) return std::string("state: expected an object");
    if (auto error = onlyKeys(state, "state", {"step", "time", "next_step", "positions", "velocities"})) return error;
    if (auto error = readClock(state, s)) return error;
    // The particle count follows from the shape (counted, not built).
    const auto count = static_cast<int>(bodySize(params).particles);
    if (!state.contains("positions") || !state.contains("velocities"))
        return std::string("state: needs both positions and velocities");
    if (auto error = readVectors(state["positions"], "positions", count, s.positions)) return error;
    if (auto error = readVectors(state["velocities"], "velocities", count, s.velocities)) return error;
    return std::nullopt;
}

// A scene of several bodies (version 4): a built-in one by name, or the bodies listed.
SceneFileResult parseWorldJson(const Json& root, SceneFile file) {
    if (file.sceneName.empty() || file.sceneName.size() > 64)
        return failure("scene: a name of 1 to 64 characters");
    if (root.contains("integrator")) {
        if (!root["integrator"].is_string()) return failure("integrator: expected a name");
        file.integrator = root["integrator"].get<std::string>();
        if (!makeIntegrator(file.integrator))
            return failure("integrator: unknown '" + file.integrator + "'; allowed: " + integratorNames());
    }
    const Json* common = nullptr;
    if (root.contains("parameters")) {
        common = &root["parameters"];
        if (!common->is_object()) return failure("parameters: expected an object of key: number");
    }
    simcore::WorldSpec spec;
    spec.name = file.sceneName;
    if (root.contains("bodies")) {
        const Json& bodies = root["bodies"];
        if (!bodies.is_array() || bodies.empty()) return failure("bodies: expected a list of at least one body");
        if (bodies.size() > static_cast<std::size_t>(simcore::kMaxBodies))
            return failure("bodies: " + std::to_string(bodies.size()) + " bodies; at most " +
                           std::to_string(simcore::kMaxBodies));
        for (std::size_t k = 0; k < bodies.size(); ++k) {
            simcore::WorldBodySpec body;
            if (auto error = readBody(bodies[k], k, common, body)) return failure(*error);
            spec.bodies.push_back(std::move(body));
        }
    } else {
        spec = *simcore::worldScene(file.sceneName);
        if (common)
            for (auto& body : spec.bodies)
                for (auto it = common->begin(); it != common->end(); ++it)
                    if (auto error = readParameter(it.key(), it.value(), "parameters.", body.params)) return failure(*error);
    }
    // A top-level key no body has (or a typo) is refused, as the one-body reader does.
    if (common)
        for (auto it = common->begin(); it != common->end(); ++it) {
            const ParamSpec* param = findParam(it.key());
            const bool someBody = param && std::any_of(spec.bodies.begin(), spec.bodies.end(), [&](const auto& b) {
                                      return b.params.has(param->id);
                                  });
            if (!someBody)
                return failure("parameters." + quoteShort(it.key()) + ": no body of this scene has it");
        }
    if (auto error = simcore::validateWorld(spec)) return failure(*error);
    if (root.contains("state")) {
        SceneFile::State s;
        if (auto error = readWorldState(root["state"], spec, s)) return failure(*error);
        file.state = std::move(s);
    }
    file.params = spec.bodies.front().params;
    file.world = std::move(spec);
    return {std::move(file), {}};
}

// The JSON tree of `text` into root, bounded in depth and memory, every key once per object; the
// error otherwise.
std::optional<std::string> parseBoundedJson(const std::string& text, Json& root) {
    try {
        std::vector<std::set<std::string>> open;  // the keys of each object being parsed
        std::map<std::string, int> occurrences;
        // Bounded for any accepted size: the nesting (a scene file needs 4 levels; 64 MiB of
        // '[' reached 4.9 GB) and the memory the parsed tree takes, estimated as it grows
        // (a container ~128 B, a value 32 B, a key its length and 96 B): refused past the bound.
        double estimated = 0.0;
        root = Json::parse(text, [&](int depth, Json::parse_event_t event, Json& parsed) {
            if (event == Json::parse_event_t::object_start || event == Json::parse_event_t::array_start) {
                if (depth >= kMaxSceneDepth) throw TooLarge{"nested deeper than " + std::to_string(kMaxSceneDepth) + " levels"};
                estimated += 128.0;
            } else if (event == Json::parse_event_t::value) {
                estimated += 32.0;
            } else if (event == Json::parse_event_t::key) {
                estimated += 96.0 + static_cast<double>(parsed.get_ref<const std::string&>().size());
            }
            if (estimated > kMaxSceneParseBytes)
                throw TooLarge{"reading it would take more than " + std::to_string(kMaxSceneParseBytes >> 20) +
                               " MiB of memory (more values than any body within the 1 GiB limit has)"};
            if (event == Json::parse_event_t::object_start) {
                open.emplace_back();
            } else if (event == Json::parse_event_t::object_end) {
                open.pop_back();
            } else if (event == Json::parse_event_t::key) {
                const std::string key = parsed.get<std::string>();
                const int n = ++occurrences[key];
                if (!open.back().insert(key).second) throw DuplicateKey{key, n};
            }
            return true;
        });
    } catch (const TooLarge& t) {
        return "not a scene file this program reads: " + t.what;
    } catch (const DuplicateKey& d) {
        return "duplicate key " + quoteShort(d.key) + " at line " +
               std::to_string(lineOfKey(text, d.key, d.occurrence)) + ": a key may appear once per object";
    } catch (const Json::parse_error& e) {
        return "not valid JSON at line " + std::to_string(lineOf(text, e.byte == 0 ? 0 : e.byte - 1)) + ": " + e.what();
    } catch (const Json::exception& e) {  // e.g. a number too large for a double (found by fuzzing)
        return std::string("not a readable scene file: ") + e.what();
    }
    return std::nullopt;
}

// Everything but the exception boundary (parseSceneFile).
SceneFileResult parseSceneJson(const std::string& text) {
    Json root;
    if (auto error = parseBoundedJson(text, root)) return failure(*error);
    if (!root.is_object()) return failure("a scene file must be a JSON object");
    if (auto error = onlyKeys(root, "the file", {"format", "version", "scene", "integrator", "parameters", "bodies", "state"}))
        return failure(*error);
    if (!root.contains("format") || root["format"] != "elastic-lab-scene")
        return failure("format: expected \"elastic-lab-scene\"");
    if (!root.contains("version") || !root["version"].is_number_integer())
        return failure("version: expected a whole number");
    // Read as 64 bits (2^32 + 2 is not version 2), unsigned ones above 2^63 too.
    const Json& v = root["version"];
    if (v.is_number_unsigned() ? v.get<std::uint64_t>() > static_cast<std::uint64_t>(kWorldSceneFormatVersion)
                               : v.get<std::int64_t>() > kWorldSceneFormatVersion)
        return failure("version " + v.dump() + " is newer than this program reads (up to " +
                       std::to_string(kWorldSceneFormatVersion) + "); update Elastic Lab");
    const int version = static_cast<int>(v.get<std::int64_t>());
    if (version < 1) return failure("version: must be 1 or more");
    if (!root.contains("scene") || !root["scene"].is_string()) return failure("scene: expected a scene name");
    SceneFile file;
    file.sceneName = root["scene"].get<std::string>();
    if (root.contains("bodies") || simcore::worldScene(file.sceneName)) {
        if (version < kWorldSceneFormatVersion)
            return failure("bodies: scenes of several bodies came with version " +
                           std::to_string(kWorldSceneFormatVersion) + "; this file says version " + std::to_string(version));
        return parseWorldJson(root, std::move(file));
    }
    const SceneInfo* scene = findScene(file.sceneName);
    if (!scene) return failure("scene: unknown scene " + quoteShort(file.sceneName) + "; allowed: " + sceneNames());
    file.params = ParameterSet(scene->kind);
    if (root.contains("integrator")) {
        if (!root["integrator"].is_string()) return failure("integrator: expected a name");
        file.integrator = root["integrator"].get<std::string>();
        if (!makeIntegrator(file.integrator))
            return failure("integrator: unknown " + quoteShort(file.integrator) + "; allowed: " + integratorNames());
    }
    if (root.contains("parameters"))
        if (auto error = readParameters(root["parameters"], "parameters.", file.params)) return failure(*error);
    // Version 3 added `scaling` (scaling.h). Every earlier file lists per-particle and per-spring
    // values and ran them as such: it loads as scaling=thesis, so it runs the body it saved.
    if (version < 3 && !file.params.isExplicit(Param::Scaling) && file.params.has(Param::Scaling))
        file.params.set(Param::Scaling, 1.0);
    if (auto error = validateShape(file.params)) return failure("parameters: " + *error);
    if (root.contains("state")) {
        SceneFile::State s;
        if (auto error = readBodyState(root["state"], file.params, s)) return failure(*error);
        file.state = std::move(s);
    }
    return {std::move(file), {}};
}


std::optional<std::string> readWorldState(const Json& state, const simcore::WorldSpec& spec, SceneFile::State& s) {
    if (!state.is_object()) return std::string("state: expected an object");
    if (auto error = onlyKeys(state, "state", {"step", "time", "next_step", "bodies"})) return error;
    if (auto error = readClock(state, s)) return error;
    if (!state.contains("bodies") || !state["bodies"].is_array() || state["bodies"].size() != spec.bodies.size())
        return "state.bodies: expected one entry per body (" + std::to_string(spec.bodies.size()) + ")";
    int total = 0;
    for (const auto& b : spec.bodies) total += static_cast<int>(bodySize(b.params).particles);
    s.positions.resize(3, total);
    s.velocities.resize(3, total);
    int first = 0;
    for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
        const Json& entry = state["bodies"][k];
        const std::string name = bodyLabel(k);
        if (!entry.is_object()) return "state." + name + ": expected an object with positions and velocities";
        if (auto error = onlyKeys(entry, "state." + name, {"positions", "velocities"})) return error;
        if (!entry.contains("positions") || !entry.contains("velocities"))
            return "state." + name + ": needs both positions and velocities";
        const auto count = static_cast<int>(bodySize(spec.bodies[k].params).particles);
        Eigen::Matrix3Xd x, v;
        if (auto error = readVectors(entry["positions"], name + ".positions", count, x)) return error;
        if (auto error = readVectors(entry["velocities"], name + ".velocities", count, v)) return error;
        s.positions.middleCols(first, count) = x;
        s.velocities.middleCols(first, count) = v;
        first += count;
    }
    return std::nullopt;
}

}  // namespace

SceneFileResult parseSceneFile(const std::string& text) {
    try {
        return parseSceneJson(text);
    } catch (const nlohmann::json::exception& e) {  // e.g. get<> on a value out of range
        return failure(std::string("not a readable scene file: ") + e.what());
    }
}

InputFile readInputFile(const std::string& path, const std::string& what) {
    // Only a regular file of bounded size is read: a directory, a FIFO (which would wait for a
    // writer for ever), a device (/dev/zero never ends) or a socket is refused by what it is.
    // O_NONBLOCK: opening a FIFO must not wait for a writer either.
    InputFile input;
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    // The path is quoted (escaped, shortened): a name may hold any byte, a NUL included.
    const std::string name = quoteShort(path, 300);
    if (fd < 0) {
        input.error = name + ": cannot read (" + std::strerror(errno) + ")";
        return input;
    }
    struct stat st {};
    std::string& text = input.text;
    std::string error;
    if (::fstat(fd, &st) != 0) {
        error = std::string("cannot read (") + std::strerror(errno) + ")";
    } else if (S_ISDIR(st.st_mode)) {
        error = "is a directory, not " + what;
    } else if (!S_ISREG(st.st_mode)) {
        error = std::string("is not a regular file (") +
                (S_ISFIFO(st.st_mode) ? "a FIFO" : S_ISCHR(st.st_mode) ? "a character device"
                                               : S_ISBLK(st.st_mode) ? "a block device"
                                               : S_ISSOCK(st.st_mode) ? "a socket" : "a special file") +
                "); " + what + " is read from a regular file only";
    } else if (st.st_size > kMaxInputFileBytes) {
        error = "is " + std::to_string(st.st_size) + " bytes; " + what + " is at most " +
                std::to_string(kMaxInputFileBytes) + " bytes (256 MiB)";
    } else {
        // Read what is there, never more than the bound (the file may grow while we read).
        text.resize(static_cast<std::size_t>(st.st_size) + 1);
        std::size_t got = 0;
        while (got < text.size()) {
            const ssize_t n = ::read(fd, text.data() + got, text.size() - got);
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) {
                error = std::string("cannot read (") + std::strerror(errno) + ")";
                break;
            }
            if (n == 0) break;
            got += static_cast<std::size_t>(n);
            if (got > static_cast<std::size_t>(kMaxInputFileBytes)) {
                error = "grew beyond " + std::to_string(kMaxInputFileBytes) + " bytes while it was read";
                break;
            }
            if (got == text.size()) text.resize(std::min<std::size_t>(2 * text.size(), kMaxInputFileBytes + 1));
        }
        text.resize(got);
    }
    ::close(fd);
    if (!error.empty()) {
        input.error = name + ": " + error;
        text.clear();
    }
    return input;
}

SceneFileResult readSceneFile(const std::string& path) {
    const InputFile input = readInputFile(path, "a scene file");
    if (!input.error.empty()) return failure(input.error);
    SceneFileResult result = parseSceneFile(input.text);
    if (!result.file) result.error = quoteShort(path, 300) + ": " + result.error;
    return result;
}

namespace {

// The writer of both forms: the parameters given (in the table's order), the state if any.
// Numbers go out with to_chars' shortest round-trip form, so a reload is bit-exact.
template <class Matrix>
void writeVectors(std::ostream& os, const char* key, const Matrix& m) {
    os << ",\n    \"" << key << "\": [";
    for (Eigen::Index i = 0; i < m.cols(); ++i)
        os << (i ? ", " : "") << "[" << formatDouble(m(0, i)) << ", " << formatDouble(m(1, i)) << ", "
           << formatDouble(m(2, i)) << "]";
    os << "]";
}

void writeHead(std::ostream& os, const std::string& sceneName, std::string_view integrator,
               const std::vector<std::pair<const ParamSpec*, double>>& values) {
    os << "{\n  \"format\": \"elastic-lab-scene\",\n  \"version\": " << kSceneFormatVersion << ",\n"
       << "  \"scene\": \"" << sceneName << "\",\n  \"integrator\": \"" << integrator << "\",\n"
       << "  \"parameters\": {";
    bool first = true;
    for (const auto& [spec, value] : values) {
        os << (first ? "\n" : ",\n") << "    \"" << spec->key << "\": ";
        if (spec->choices.empty()) os << formatDouble(value);
        else os << '"' << spec->choiceName(value) << '"';  // a choice by its name: "scaling": "physical"
        first = false;
    }
    os << "\n  }";
}

// A world's text: the first body's world parameters at the top, each body's own below (all of
// them, or only those set explicitly), then the state if any.
void writeWorld(std::ostream& os, const simcore::WorldSpec& spec, std::string_view integrator, bool all,
                const SceneFile::State* state, std::optional<double> nextStep) {
    const auto chosen = [all](const ParameterSet& set, bool world) {
        std::vector<std::pair<const ParamSpec*, double>> values;
        for (const ParamSpec* p : parametersFor(set.kind()))
            if (simcore::isWorldParameter(p->id) == world && (all || set.isExplicit(p->id)))
                values.emplace_back(p, set.get(p->id));
        return values;
    };
    const auto object = [&os](const std::vector<std::pair<const ParamSpec*, double>>& values, const char* indent) {
        os << "{";
        bool first = true;
        for (const auto& [param, value] : values) {
            os << (first ? "\n" : ",\n") << indent << "  \"" << param->key << "\": ";
            if (param->choices.empty()) os << formatDouble(value);
            else os << '"' << param->choiceName(value) << '"';
            first = false;
        }
        os << "\n" << indent << "}";
    };
    const auto vector = [&os](const Eigen::Vector3d& v) {
        os << "[" << formatDouble(v.x()) << ", " << formatDouble(v.y()) << ", " << formatDouble(v.z()) << "]";
    };
    os << "{\n  \"format\": \"elastic-lab-scene\",\n  \"version\": " << kWorldSceneFormatVersion << ",\n"
       << "  \"scene\": \"" << spec.name << "\",\n  \"integrator\": \"" << integrator << "\",\n  \"parameters\": ";
    object(chosen(spec.bodies.front().params, true), "  ");
    os << ",\n  \"bodies\": [";
    for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
        const simcore::WorldBodySpec& b = spec.bodies[k];
        os << (k ? ",\n" : "\n") << "    {\n      \"kind\": \"" << simcore::sceneInfo(b.params.kind()).name
           << "\",\n      \"position\": ";
        vector(b.position);
        os << ",\n      \"velocity\": ";
        vector(b.velocity);
        os << ",\n      \"parameters\": ";
        object(chosen(b.params, false), "      ");
        os << "\n    }";
    }
    os << "\n  ]";
    if (state) {
        os << ",\n  \"state\": {\n    \"step\": " << state->step << ",\n    \"time\": " << formatDouble(state->time);
        if (nextStep) os << ",\n    \"next_step\": " << formatDouble(*nextStep);
        os << ",\n    \"bodies\": [";
        Eigen::Index first = 0;
        for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
            const auto count = static_cast<Eigen::Index>(bodySize(spec.bodies[k].params).particles);
            os << (k ? ",\n" : "\n") << "      {";
            std::ostringstream xv;
            writeVectors(xv, "positions", state->positions.middleCols(first, count));
            writeVectors(xv, "velocities", state->velocities.middleCols(first, count));
            os << xv.str().substr(1) << "\n      }";  // without writeVectors' first comma
            first += count;
        }
        os << "\n    ]\n  }";
    }
    os << "\n}\n";
}

}  // namespace

std::string sceneFileText(const simcore::World& world, bool withState) {
    std::ostringstream os;
    std::optional<SceneFile::State> state;
    if (withState) {
        state = SceneFile::State{};  // not emplace(): clang 14 judges the nested type not default-constructible
        state->step = world.stepCount();
        state->time = world.time();
        state->positions = Eigen::Map<const Eigen::Matrix3Xd>(world.state().data(), 3, world.particleCount());
        state->velocities =
            Eigen::Map<const Eigen::Matrix3Xd>(world.state().data() + 3 * world.particleCount(), 3, world.particleCount());
    }
    std::optional<double> next;
    if (withState && world.integrator().adaptive()) next = world.nextStep();
    writeWorld(os, world.spec(), world.integrator().name(), true, state ? &*state : nullptr, next);
    return os.str();
}

std::optional<std::string> applyState(simcore::World& world, const SceneFile::State& state) {
    if (state.positions.cols() != world.particleCount()) return std::string("state does not fit the world");
    world.setState(state.positions, state.velocities, state.step, state.time);
    if (state.nextStep) world.setNextStep(*state.nextStep);
    return std::nullopt;
}

std::string sceneFileText(const Simulation& sim, const std::string& sceneName, bool withState) {
    std::vector<std::pair<const ParamSpec*, double>> values;
    for (const ParamSpec* spec : parametersFor(sim.parameters().kind())) values.emplace_back(spec, sim.parameters().get(spec->id));
    std::ostringstream os;
    writeHead(os, sceneName, sim.integrator().name(), values);
    if (withState) {
        os << ",\n  \"state\": {\n    \"step\": " << sim.stepCount() << ",\n    \"time\": " << formatDouble(sim.time());
        if (sim.integrator().adaptive()) os << ",\n    \"next_step\": " << formatDouble(sim.nextStep());
        writeVectors(os, "positions", sim.positions());
        writeVectors(os, "velocities", sim.velocities());
        os << "\n  }";
    }
    os << "\n}\n";
    return os.str();
}

std::string sceneFileText(const SceneFile& file) {
    if (file.world) {
        std::ostringstream os;
        writeWorld(os, *file.world, file.integrator, false, file.state ? &*file.state : nullptr,
                   file.state ? file.state->nextStep : std::nullopt);
        return os.str();
    }
    std::vector<std::pair<const ParamSpec*, double>> values;
    for (const auto& [id, value] : file.params.explicitValues()) values.emplace_back(&paramSpec(id), value);
    std::ostringstream os;
    writeHead(os, file.sceneName, file.integrator, values);
    if (file.state) {
        const SceneFile::State& s = *file.state;
        os << ",\n  \"state\": {\n    \"step\": " << s.step << ",\n    \"time\": " << formatDouble(s.time);
        if (s.nextStep) os << ",\n    \"next_step\": " << formatDouble(*s.nextStep);
        writeVectors(os, "positions", s.positions);
        writeVectors(os, "velocities", s.velocities);
        os << "\n  }";
    }
    os << "\n}\n";
    return os.str();
}

std::optional<std::string> applyState(Simulation& sim, const SceneFile::State& state) {
    if (state.positions.cols() != sim.particleCount()) return std::string("state does not fit the body");
    sim.setState(state.positions, state.velocities, state.step, state.time);
    if (state.nextStep) sim.setNextStep(*state.nextStep);
    return std::nullopt;
}

}  // namespace simlab
