// elastic-lab-cli: the headless tool. Scripts depend on its options, columns and exit codes.
#include <cstdio>
#include <cstring>
#include <cerrno>
#include <exception>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "cli.h"

namespace {

const char* kUsage = R"(usage: elastic-lab-cli <command> [options]

commands:
  scenes                          list the built-in scenes
  params [--scene S]              list every parameter: key, unit, default, range, meaning
  integrators                     list the integrators
  run --scene S [--set key=value]... [--integrator NAME] [--dt H] [--duration T]
      [--csv FILE] [--every N] [--state FILE] [--save-scene FILE.json] [--quiet]
      [--atol A] [--rtol R] [--fixed-step] [--error-estimate] [--newton N]
                                  run headless; CSV row every N steps, final state table;
                                  S may be a scene file (.json), which can carry a saved state;
                                  rk45, cvode-bdf and cvode-adams tolerances (or --fixed-step for
                                  rk45; the CVODE counters are printed and added to the CSV),
                                  step-doubling error_estimate
                                  for fixed-step methods, Newton iterations of implicit-euler

  bench --scene S [--set key=value]... [--integrator NAME] [--steps N] [--threads K] [--header]
      [--kernels portable|avx2|avx512]
                                  time N steps: us/step, ns per spring evaluation, real-time factor,
                                  memory, and the force kernels used (default: the widest the CPU runs)

  study --scene S [--set key=value]... --integrators a,b,... --dts h1,h2,... [--tols t1,...]
      [--duration T] [--repeat R] [--reference auto|exact|rk4|rk45|cvode-bdf] [--csv FILE] [--plot FILE.svg]
      [--shard K/N] [--samples G] [--fixed-step] [--quiet]
  study --from-csv FILE [--plot FILE.svg]
                                  work-precision study: error against wall time, force evaluations
                                  and dt; fitted orders; shards concatenate into the full CSV
  study --scene S [--set key=value]... --refine KEY=v1,v2,... [--integrators NAME] [--dt H | --tols T]
      [--duration T] [--interval I] [--temporal-runs K] [--csv FILE] [--plot FILE.svg] [--quiet]
                                  refinement study: the same body at each resolution (KEY: particles,
                                  subdivisions or slices) against the finest; volume and centre-of-mass
                                  errors, spatial order, and the step's own error beside it
  stability --scene S [--set key=value]... --integrators a,b,... [--duration T] [--csv FILE]
      [--shard K/N] [--perturb A]
                                  largest stable dt per integrator (bisection) beside the
                                  linearised prediction (highest frequency, damping, stability region)
  restitution --scene S [--set key=value]... [--integrator NAME] [--speeds v1,v2,...] [--csv FILE]
                                  rebound / impact speed of a free particle and of the body against
                                  impact speed (weightless), beside the restitution e
  gallery [--run NAME|all] [--list]
                                  stiff and extreme presets with their expected outcome

exit status: 0 success, 2 bad input, 3 the simulation failed
)";

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
        std::fputs(kUsage, args.empty() ? stderr : stdout);
        return args.empty() ? cli::kExitBadInput : cli::kExitOk;
    }
    const std::map<std::string, std::function<int(const std::vector<std::string>&)>> commands = {
        {"scenes", cli::commandScenes},
        {"params", cli::commandParams},
        {"integrators", cli::commandIntegrators},
        {"run", cli::commandRun},
        {"study", cli::commandStudy},
        {"stability", cli::commandStability},
        {"restitution", cli::commandRestitution},
        {"gallery", cli::commandGallery},
        {"bench", cli::commandBench},
    };
    const auto it = commands.find(args[0]);
    if (it == commands.end()) {
        std::string allowed;
        for (const auto& [name, _] : commands) allowed += (allowed.empty() ? "" : ", ") + name;
        std::fprintf(stderr, "error: unknown command '%s'; allowed: %s\n", args[0].c_str(), allowed.c_str());
        return cli::kExitBadInput;
    }
    try {
        const int status = it->second({args.begin() + 1, args.end()});
        // Standard output is a result like any file: a full disk or a closed pipe that lost
        // part of it is an error (exit 2), never a success with the table gone.
        if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
            std::fprintf(stderr, "error: writing standard output failed: %s\n", std::strerror(errno));
            return cli::kExitBadInput;
        }
        return status;
    } catch (const cli::UsageError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return cli::kExitBadInput;
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return cli::kExitBadInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "internal error: %s\n", e.what());
        return 1;
    }
}
