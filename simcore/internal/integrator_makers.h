#pragma once
// The makers of the integrators whose step bodies live in separate files, for the table
// (integrator_table.cpp). Internal to simcore.

#include <memory>
#include <string_view>

namespace simcore {

class Integrator;  // integrators.h (not included: the step bodies include this file)

// euler, midpoint, rk4, symplectic-euler, verlet, rk45 (integrators.cpp); nullptr for others.
std::unique_ptr<Integrator> makeExplicitIntegrator(std::string_view name);
std::unique_ptr<Integrator> makeXpbd();          // integrators.cpp
std::unique_ptr<Integrator> makeImplicitEuler();  // implicit_euler.cpp

}  // namespace simcore
