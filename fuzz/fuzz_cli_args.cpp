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
#include "fuzz/scratch.h"

namespace {

using fuzzscratch::substitute;

bool isCommand(const std::string& word) {
    static const char* commands[] = {"scenes", "params", "integrators", "run", "study", "conservation", "stability",
                                     "restitution", "gallery", "bench", "completion", "help", "sweep"};
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
