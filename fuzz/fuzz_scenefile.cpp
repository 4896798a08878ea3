// Fuzz target: the scene-file reader. Any input must be refused with a message or accepted;
// an accepted file must build, step, save and load again (saved files always load).
#include <cstdint>
#include <cstdlib>
#include <string>

#include "simcore/simulation.h"
#include "simlab/scenefile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const simlab::SceneFileResult read = simlab::parseSceneFile(text);
    if (!read.file) {
        if (read.error.empty()) std::abort();  // a refusal always says why
        return 0;
    }
    // Keep iterations quick: large bodies are valid but only slow the search down.
    if (simcore::buildBody(read.file->params).topology.particleCount() > 2000) return 0;
    simcore::Simulation sim(read.file->params, read.file->integrator);
    if (read.file->state) simlab::applyState(sim, *read.file->state);
    for (int i = 0; i < 3; ++i) sim.step();
    if (!sim.state().allFinite()) std::abort();  // never a NaN, failed or not
    const simlab::SceneFileResult again = simlab::parseSceneFile(simlab::sceneFileText(sim, read.file->sceneName, true));
    if (!again.file) std::abort();
    return 0;
}
