#pragma once
// Time integrators (thesis ch. 5, MODEL.md "Integrators") behind one interface.
//
// The state is one flat, contiguous vector y = [x (n) | v (n) | aux (m)] with
// dy/dt = [v | a(x, v, t) | aux'], where aux holds integrated diagnostics (the energy
// removed by damping) so that they are integrated with the same accuracy as the motion.
// An integrator advances y in place; its stage vectors are allocated once in prepare(),
// never inside a step, and every stage re-evaluates the forces through OdeSystem.

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include <Eigen/Core>

namespace simcore {

struct StateLayout {
    Eigen::Index positions = 0;   // n: 3 per particle
    Eigen::Index aux = 0;         // m: integrated scalars
    Eigen::Index size() const { return 2 * positions + aux; }
};

class OdeSystem {
public:
    virtual ~OdeSystem() = default;
    virtual StateLayout layout() const = 0;
    // dydt = f(t, y). Must not allocate.
    virtual void derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) = 0;
};

struct StepReport {
    double h = 0.0;               // step actually taken [s]
    double hNext = 0.0;           // step suggested for the next step [s]
    double errorEstimate = -1.0;  // local error estimate, < 0 when the method has none
    int evaluations = 0;          // force evaluations spent, including rejected attempts
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual std::string_view name() const = 0;
    virtual int order() const = 0;
    virtual int evaluationsPerStep() const = 0;
    virtual bool adaptive() const { return false; }
    virtual void prepare(const StateLayout& layout) = 0;
    virtual StepReport step(OdeSystem& system, double t, double h, Eigen::VectorXd& y) = 0;
};

struct IntegratorInfo {
    std::string_view name;
    int order;
    std::string_view description;
};

std::span<const IntegratorInfo> integratorTable();
// nullptr when the name is unknown.
std::unique_ptr<Integrator> makeIntegrator(std::string_view name);
std::string integratorNames();  // "euler, midpoint, ..." for messages

}  // namespace simcore
