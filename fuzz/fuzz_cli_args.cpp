// Fuzz target: the whole command line (CLI11 parsing, every command's options and the checks
// that run before any work), in check-only mode: nothing is written and nothing simulated.
// Input lines are arguments; a first line that is not a command means `run` (the corpus began
// as run's options). Any input ends in exit status 0 or 2, never a crash, a hang or another code.
//
// Files that are not regular (issue 18): the tokens @dir, @fifo, @zero, @null, @empty and
// @scene in an argument stand for a directory, a FIFO, /dev/zero, /dev/null, an empty file and a
// valid scene file, all named *.json in a scratch folder made once; any other argument with a
// '/' is skipped, so that the fuzzer never reads the machine's own files.
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/cli/cli.h"

namespace {

struct Scratch {
    std::filesystem::path dir;
    Scratch() {
        char name[] = "/tmp/elastic-lab-fuzz-XXXXXX";
        if (!::mkdtemp(name)) std::abort();
        dir = name;
        std::filesystem::create_directory(dir / "dir.json");
        if (::mkfifo((dir / "fifo.json").c_str(), 0600) != 0) std::abort();
        std::filesystem::create_symlink("/dev/zero", dir / "zero.json");
        std::filesystem::create_symlink("/dev/null", dir / "null.json");
        std::ofstream(dir / "empty.json").flush();
        std::ofstream(dir / "scene.json") << R"({"format": "elastic-lab-scene", "version": 3, "scene": "ring2d",
            "integrator": "rk4", "parameters": {"ks": 100, "dt": 0.001}})";
    }
    ~Scratch() {
        std::error_code ignored;
        std::filesystem::remove_all(dir, ignored);
    }
};

const Scratch& scratch() {
    static const Scratch s;
    return s;
}

// Replaces the tokens; false when the argument names some other path.
bool substitute(std::string& arg) {
    static const char* tokens[] = {"dir", "fifo", "zero", "null", "empty", "scene"};
    for (const char* token : tokens) {
        const std::string at = std::string("@") + token;
        if (auto pos = arg.find(at); pos != std::string::npos) {
            arg.replace(pos, at.size(), (scratch().dir / (std::string(token) + ".json")).string());
            return true;
        }
    }
    return arg.find('/') == std::string::npos;
}

bool isCommand(const std::string& word) {
    static const char* commands[] = {"scenes", "params", "integrators", "run", "study", "conservation", "stability",
                                     "restitution", "gallery", "bench", "completion", "help"};
    for (const char* c : commands)
        if (word == c) return true;
    return false;
}

}  // namespace

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
    for (std::string& arg : args)
        if (!substitute(arg)) return 0;
    if (args.empty() || !isCommand(args.front())) args.insert(args.begin(), "run");
    const int status = cli::runCommandLine(args, cli::Mode::CheckOnly);
    if (status != cli::kExitOk && status != cli::kExitBadInput) std::abort();
    return 0;
}
