#pragma once
// The sentences a run's failure is reported with (Failure::reason, the integrators' report.failure):
// made here, in one place, for the simulation of one body, a world of several and the float path,
// so that the GUI can say the same in the window's language (ui/failure_text.h reads them back:
// tests/test_failure_texts.cpp checks every sentence below in every language). The CLI, Python
// and the files keep the English sentence.
#include <cstddef>
#include <optional>
#include <string>

#include "simcore/body.h"

namespace simcore::failure_text {

// The state holds NaN or infinity after a step.
std::string nonFinite();
// A particle would cross more than the whole box in one step.
std::string runawayVelocity(double fastest);
// Kinetic + elastic energy above `factor` times the body's energy scale.
std::string runawayEnergy(double held, double budget, double factor);
// A layer's area (2-D) or volume (3-D) fell to `volume` of `rest`: inside out when <= 0, else
// collapsed. `body` (1-based) names the body in a world of several.
std::string layerLost(std::optional<std::size_t> body, Layer layer, int dimension, double volume, double rest);
// A world: body `a`'s and body `b`'s outer layers crossed (1-based; a == b: a body's outer layer
// passed through itself) in a step of `h`.
std::string layersCrossed(std::size_t a, std::size_t b, double h);
// The float path: a particle's state no longer finite; a particle beyond a wall (it has no contact).
std::string floatNotFinite(std::size_t particle);
std::string floatReachedWall(std::size_t particle);

// The integrators' own failures (fixed sentences).
inline constexpr const char* kRk45MinimumStep =
    "rk45: the step size fell below the minimum step; the tolerance cannot be met (the system is too "
    "stiff or singular)";
inline constexpr const char* kImplicitEulerNoConvergence =
    "implicit-euler: the linear solve (conjugate gradient) did not converge; the linearised system is "
    "not positive definite at this step (the body is too deformed or the step too large)";

}  // namespace simcore::failure_text
