#pragma once
// Helpers of the window tests of scenes of several bodies (test_gui_world, test_gui_world_tools).
#include <functional>
#include <initializer_list>

#include <QtGlobal>

#include "simcore/world.h"
#include "test_support.h"
#include "ui/simulation_controller.h"

namespace worldtest {

// Waits (a hang guard, not a time limit) for the controller's newest frame to satisfy pred.
inline bool waitForFrame(const elui::SimulationController& c, const std::function<bool(const elui::Frame&)>& pred) {
    return testsupport::waitUntil([&] { return c.latest() && pred(*c.latest()); });
}

// A built-in world with bodyN.key=value settings.
inline simcore::WorldSpec scene(const char* name, std::initializer_list<const char*> set) {
    simcore::WorldSpec spec = *simcore::worldScene(name);
    for (const char* a : set)
        if (auto error = simcore::assignWorld(spec, a)) qFatal("%s", error->c_str());
    return spec;
}

}  // namespace worldtest
