// elastic-lab-cli: the headless tool. Scripts depend on its options, columns and exit codes;
// the commands and their options are in cli.h and the cmd_*.cpp files.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "app/cli/cli.h"

int main(int argc, char** argv) {
    try {
        return cli::runCommandLine(std::vector<std::string>(argv + 1, argv + argc));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "internal error: %s\n", e.what());
        return 1;
    }
}
