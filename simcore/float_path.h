#pragma once
// The float32 path (issue 27): the same body, force terms and explicit integrators as a
// Simulation, with the state (positions, velocities) and the forces in float.
//
// What it has: gravity, the springs of every family (with damping) and the gas of each closed
// layer; the explicit integrators euler, midpoint, rk4, symplectic-euler and verlet (each a
// fixed sequence of force evaluations and element-wise updates, which is all a float state
// needs). What it has not, and why:
//  - rk45: its step control compares an error estimate with tolerances; in float the estimate
//    is rounding noise below ~1e-6 of the state, so the controller would chase round-off;
//  - implicit-euler, cvode-bdf, cvode-adams: their Newton and Krylov solves (Jacobians,
//    linear solvers) are double code; a float state would be converted at every iteration;
//  - xpbd and the Yoshida compositions: possible, not built (not needed for the goal);
//  - contact (walls, layer barrier or projection), the layer constraint and the pointer: a
//    run stops with a plain failure when a particle reaches a wall; the float path is for
//    bodies in free flight (the benchmark's gravity-off sphere, a ring or sphere falling
//    before it lands).
//
// The diagnostics (energies, volumes, pressures) are measured in double from the float state,
// by the double path's own functions, so the energy ledger closes as in double: the energy
// removed by damping is integrated in double from each stage's damping power (summed in double
// in a fixed order) with the integrator's own weights.
//
// Results do not depend on the thread count: the particles are owned by chunks fixed by the
// body alone (as ForceModel's), each chunk's springs and faces add into its own particles'
// rows in a fixed order, the shared ones after, and the sums are combined in chunk order
// (tested bit for bit, also between the portable and the AVX2 code).

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "simcore/simulation.h"

namespace simcore {

// Whether the float path has a build of this integrator.
bool floatPathSupports(std::string_view integrator);
// "euler, midpoint, rk4, symplectic-euler, verlet" for messages.
std::string floatPathIntegrators();
// Why this integrator cannot take the float path ("" when it can): "precision float is built
// for the explicit integrators ..., not 'NAME'" (the front door's words, simlab/request.h).
std::string floatPathIntegratorRefusal(std::string_view integrator);
// Why a run of this simulation cannot take the float path ("" when it can): an integrator
// without a float build, or the pointer held.
std::string floatPathRefusal(const Simulation& start);

class FloatSimulation {
public:
    // From `start` as it stands (its body, parameters, state and time): its state rounded to
    // float. Throws std::invalid_argument with floatPathRefusal's text.
    explicit FloatSimulation(const Simulation& start);
    ~FloatSimulation();
    FloatSimulation(const FloatSimulation&) = delete;
    FloatSimulation& operator=(const FloatSimulation&) = delete;

    void setThreads(int threads);
    int threads() const;

    // One step of dt; false when the run has failed (now or before).
    bool step();
    bool failed() const { return m_failure.has_value(); }
    const std::optional<Failure>& failure() const { return m_failure; }
    double time() const { return m_time; }
    long stepCount() const { return m_step; }
    double dt() const { return m_dt; }
    std::string_view integrator() const { return m_integrator; }
    const Topology& topology() const { return *m_topology; }

    // Energies, volumes and pressures of the current state, measured in double (computed on
    // the first call after a step; forceEvaluations counts this path's evaluations).
    const Diagnostics& diagnostics() const;
    // The state in double, laid out as Simulation::state()'s first 6N values (positions, then
    // velocities).
    Eigen::VectorXd state() const;
    // Hands the state to `sim` (the simulation this one started from, or one of the same body):
    // its positions, velocities, step counter and time, in double (Simulation::setState).
    void writeStateTo(Simulation& sim) const;
    // FNV-1a (64 bits) of the float state's bytes (positions, velocities): the same hash is the
    // same trajectory.
    std::uint64_t stateHash() const;

    struct Impl;

private:
    std::unique_ptr<Impl> m_impl;
    const Topology* m_topology = nullptr;
    std::string m_integrator;
    double m_dt = 0.0;
    double m_time = 0.0;
    double m_timeCarry = 0.0;  // round-off carried by the compensated time sum [s]
    long m_step = 0;
    std::optional<Failure> m_failure;
};

}  // namespace simcore
