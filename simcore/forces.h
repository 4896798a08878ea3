#pragma once
// Force terms (thesis ch. 4, MODEL.md "Forces"), each a separate kernel over flat arrays.
//
// Positions, velocities and forces are flat arrays of 3N doubles (x0 y0 z0 x1 ...). A scene
// declares the terms it has (TermSet); a term it does not have is never evaluated, and the
// evaluation counters prove it. The kernels are free functions: testable without a world.

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "body.h"

namespace simcore {

enum class Term : int { Gravity, Springs, Gas, Pointer, Collisions, LayerConstraint, Count };
inline constexpr int kTermCount = static_cast<int>(Term::Count);
std::string_view termName(Term term);

struct TermSet {
    std::array<bool, kTermCount> on{};
    bool has(Term t) const { return on[static_cast<std::size_t>(t)]; }
    void set(Term t, bool value) { on[static_cast<std::size_t>(t)] = value; }
};

// The tunables the force terms read, resolved from the parameter table.
struct ForceParams {
    std::array<double, kSpringFamilyCount> ks{};  // stiffness per spring family [N/m]
    std::array<double, kSpringFamilyCount> kd{};  // damping per family [N*s/m]
    double gravity = 9.81;                        // |g| [m/s^2], acting along -y
    std::array<double, 2> gasConstant{};          // nRT of the gas in [inner, outer] [J]
    double mks = 150.0;                           // mouse spring stiffness [N/m]
    double mkd = 25.0;                            // mouse spring damping [N*s/m]
    double mouseRest = 0.0;                       // mouse spring rest length [m]
};

// The mouse spring: anchor r_m held by the pointer, attached to one particle.
struct PointerSpring {
    bool active = false;
    int particle = -1;
    Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
};

// Per-evaluation by-products of the forces.
struct ForceExtras {
    std::array<double, 2> volume{};    // enclosed volume of [inner, outer] layer
    std::array<double, 2> pressure{};  // P = c / V
    double dampingPower = 0.0;         // power removed by spring and mouse damping [W], >= 0
    int degenerateSprings = 0;         // springs shorter than kDegenerateLength
};

inline constexpr double kDegenerateLength = 1e-12;  // [m]

// Kernels. Each adds into f (3N). x, v are 3N.
void addGravity(const Eigen::VectorXd& mass, double g, double* f);
// Returns the damping power of the family.
double addSprings(const SpringSet& springs, double ks, double kd, const double* x, const double* v,
                  double* f, int& degenerate);
// Gas of one closed layer with nRT = c. Returns the volume V; force P * dV/dx.
double addGas(const Surface& surface, int dimension, double c, const double* x, double* f);
double addPointer(const PointerSpring& pointer, double mks, double mkd, double rest,
                  const double* x, const double* v, double* f);

// Energies of the conservative parts, per family.
double springEnergy(const SpringSet& springs, double ks, const double* x);
double gasEnergy(double c, double volume);  // -c ln V
double pointerEnergy(const PointerSpring& pointer, double mks, double rest, const double* x);

// Index into the [inner, outer] arrays for a surface's layer.
inline int layerSlot(Layer layer) { return layer == Layer::Inner ? 0 : 1; }

// Evaluates every declared term and counts evaluations.
class ForceModel {
public:
    ForceModel() = default;
    ForceModel(const Topology* topology, const Eigen::VectorXd* mass, TermSet terms)
        : m_topology(topology), m_mass(mass), m_terms(terms) {}

    ForceParams params;
    PointerSpring pointer;

    const TermSet& terms() const { return m_terms; }
    // Computes f = F(x, v) (3N). Overwrites f.
    void evaluate(const double* x, const double* v, double* f, ForceExtras& extras);
    // Counts one evaluation of a post-step term (collisions, layer constraint).
    void countPostStep(Term term) { ++m_evaluations[static_cast<std::size_t>(term)]; }
    std::uint64_t evaluations(Term term) const { return m_evaluations[static_cast<std::size_t>(term)]; }
    std::uint64_t forceEvaluations() const { return m_forceEvaluations; }

private:
    const Topology* m_topology = nullptr;
    const Eigen::VectorXd* m_mass = nullptr;
    TermSet m_terms;
    std::array<std::uint64_t, kTermCount> m_evaluations{};
    std::uint64_t m_forceEvaluations = 0;
};

}  // namespace simcore
