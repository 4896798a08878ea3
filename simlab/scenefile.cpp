#include "simlab/scenefile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
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

// Everything but the exception boundary (parseSceneFile).
SceneFileResult parseSceneJson(const std::string& text) {
    Json root;
    try {
        std::vector<std::set<std::string>> open;  // the keys of each object being parsed
        std::map<std::string, int> occurrences;
        root = Json::parse(text, [&](int, Json::parse_event_t event, Json& parsed) {
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
    } catch (const DuplicateKey& d) {
        return failure("duplicate key " + quoteShort(d.key) + " at line " +
                       std::to_string(lineOfKey(text, d.key, d.occurrence)) + ": a key may appear once per object");
    } catch (const Json::parse_error& e) {
        return failure("not valid JSON at line " + std::to_string(lineOf(text, e.byte == 0 ? 0 : e.byte - 1)) +
                       ": " + e.what());
    } catch (const Json::exception& e) {  // e.g. a number too large for a double (found by fuzzing)
        return failure(std::string("not a readable scene file: ") + e.what());
    }
    if (!root.is_object()) return failure("a scene file must be a JSON object");
    if (auto error = onlyKeys(root, "the file", {"format", "version", "scene", "integrator", "parameters", "state"}))
        return failure(*error);
    if (!root.contains("format") || root["format"] != "elastic-lab-scene")
        return failure("format: expected \"elastic-lab-scene\"");
    if (!root.contains("version") || !root["version"].is_number_integer())
        return failure("version: expected a whole number");
    const int version = root["version"].get<int>();
    if (version > kSceneFormatVersion)
        return failure("version " + std::to_string(version) + " is newer than this program reads (up to " +
                       std::to_string(kSceneFormatVersion) + "); update Elastic Lab");
    if (version < 1) return failure("version: must be 1 or more");
    if (!root.contains("scene") || !root["scene"].is_string()) return failure("scene: expected a scene name");
    SceneFile file;
    file.sceneName = root["scene"].get<std::string>();
    const SceneInfo* scene = findScene(file.sceneName);
    if (!scene) return failure("scene: unknown scene '" + file.sceneName + "'; allowed: " + sceneNames());
    file.params = ParameterSet(scene->kind);
    if (root.contains("integrator")) {
        if (!root["integrator"].is_string()) return failure("integrator: expected a name");
        file.integrator = root["integrator"].get<std::string>();
        if (!makeIntegrator(file.integrator))
            return failure("integrator: unknown '" + file.integrator + "'; allowed: " + integratorNames());
    }
    if (root.contains("parameters")) {
        const Json& params = root["parameters"];
        if (!params.is_object()) return failure("parameters: expected an object of key: number");
        for (auto it = params.begin(); it != params.end(); ++it) {
            // A choice parameter may also be given by name ("contact": "projection").
            const ParamSpec* spec = findParam(it.key());
            if (it.value().is_string() && spec && !spec->choices.empty()) {
                if (auto error = file.params.setFromText(it.key(), it.value().get<std::string>()))
                    return failure("parameters." + *error);
                continue;
            }
            if (!it.value().is_number())
                return failure("parameters." + quoteShort(it.key()) + ": expected a number, got " + std::string(it.value().type_name()));
            if (auto error = file.params.set(it.key(), it.value().get<double>()))
                return failure("parameters." + *error);
        }
    }
    // Version 3 added `scaling` (scaling.h). Every earlier file lists per-particle and per-spring
    // values and ran them as such: it loads as scaling=thesis, so it runs the body it saved.
    if (version < 3 && !file.params.isExplicit(Param::Scaling) && file.params.has(Param::Scaling))
        file.params.set(Param::Scaling, 1.0);
    if (auto error = validateShape(file.params)) return failure("parameters: " + *error);
    if (root.contains("state")) {
        const Json& state = root["state"];
        if (!state.is_object()) return failure("state: expected an object");
        if (auto error = onlyKeys(state, "state", {"step", "time", "next_step", "positions", "velocities"}))
            return failure(*error);
        SceneFile::State s;
        if (state.contains("step")) {
            if (!state["step"].is_number_integer() || state["step"].get<long>() < 0)
                return failure("state.step: expected a whole number >= 0");
            s.step = state["step"].get<long>();
        }
        if (state.contains("time")) {
            if (!state["time"].is_number() || !std::isfinite(state["time"].get<double>()) || state["time"].get<double>() < 0)
                return failure("state.time: expected a finite number >= 0");
            s.time = state["time"].get<double>();
        }
        if (state.contains("next_step")) {
            const Json& h = state["next_step"];
            if (!h.is_number() || !std::isfinite(h.get<double>()) || !(h.get<double>() > 0.0))
                return failure("state.next_step: expected a finite number > 0 (seconds)");
            s.nextStep = h.get<double>();
        }
        // The particle count follows from the shape (counted, not built).
        const auto count = static_cast<int>(bodySize(file.params).particles);
        if (!state.contains("positions") || !state.contains("velocities"))
            return failure("state: needs both positions and velocities");
        if (auto error = readVectors(state["positions"], "positions", count, s.positions)) return failure(*error);
        if (auto error = readVectors(state["velocities"], "velocities", count, s.velocities)) return failure(*error);
        file.state = std::move(s);
    }
    return {std::move(file), {}};
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

}  // namespace

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
