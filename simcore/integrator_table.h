#pragma once
// The integrator table: every integrator's name, order and one-line description, the factory
// that makes one by name, the one message for a name that is not an integrator, and the
// stability functions of the linear one-step methods. A file of its own so that the step
// bodies (integrators.cpp, implicit_euler.cpp, cvode_integrators.cpp) do not know each other.

#include <complex>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "simcore/integrators.h"

namespace simcore {

struct IntegratorInfo {
    std::string_view name;
    int order;
    std::string_view description;
    // explicit-rk, symplectic, implicit, adaptive, production (SUNDIALS) or constraint (xpbd):
    // the diagrams colour by it and mark each family's fastest method at each accuracy.
    std::string_view family;
};

std::span<const IntegratorInfo> integratorTable();
// nullptr when the name is unknown.
std::unique_ptr<Integrator> makeIntegrator(std::string_view name);
std::string integratorNames();  // "euler, midpoint, ..." for messages
// The family of an integrator (IntegratorInfo::family), empty for an unknown name, and every
// family in the order the diagrams list them.
std::string_view integratorFamily(std::string_view name);
std::span<const std::string_view> integratorFamilies();
// (compositionWeights, the substeps of verlet's compositions: compositions.h.)
// The one message for a name that is not an integrator (CLI, GUI, Python); nothing when it is one.
std::optional<std::string> unknownIntegrator(std::string_view name);

// Stability function of a linear one-step method applied to y' = lambda y with z = h lambda:
// y_{n+1} = R(z) y_n. Defined for euler, midpoint, rk4, rk45 (fixed step, 5th-order
// solution) and implicit-euler; the partitioned methods (symplectic-euler, verlet and its
// compositions) have no scalar R and are treated per oscillator mode in stability.h.
bool hasStabilityFunction(std::string_view name);
std::complex<double> stabilityFunction(std::string_view name, std::complex<double> z);

}  // namespace simcore
