#pragma once
// Resolution scaling (docs/model.md "Resolution"): what the per-particle and per-spring values of
// the parameter table mean when the mesh is refined.
//
// scaling=thesis: MASS is per particle and KS/KD/RKS/RKD per spring at every resolution, as in
// the thesis program; a finer mesh is a heavier, more tightly coupled body.
//
// scaling=physical (the default): the table's values describe the body at the scene's
// reference resolution (its default shape: 12 particles per ring layer, octahedron level 2,
// 8 x 4 lat/long), and the body keeps its totals and material constants when refined. With
// n particles per layer, L0 a structural spring's rest length and "count" a family's springs:
//
//   family            how the springs combine            per particle / per spring
//   mass              a layer's total is fixed           m  = MASS * n_ref / n
//   structural, 2D    a chain around the ring (series)   k  = KS * L0_ref / L0   (EA = k L0 fixed)
//   structural, 3D    a membrane on each layer           k  = KS                 (k per spring is the
//                                                                                 membrane's stiffness)
//   radius            between the layers, in parallel    k  = RKS * count_ref / count  (sum k cos^2)
//   shear             between the layers, in parallel,   k  = RKS * S_ref / S,  S = sum of sin^2 of
//                     kept in shear                      the angle to the radial direction
//   contact           per particle, a pressure on a wall k_c = CONTACT_K * n_ref / n
//   gas               nRT of a layer                     unchanged
//
// Damping follows its spring (a dashpot beside each spring combines the same way). Contact
// scales with the mass, so each particle's contact keeps its time scale, its resting depth
// (k_c d^3 = m g) and its restitution. At the reference resolution every factor is x / x = 1
// exactly: the physical body is the thesis's body bit for bit (tested). The derivations are in
// docs/numerics.md ("Resolution").

#include <array>
#include <string>

#include "simcore/body.h"
#include "simcore/params.h"

namespace simcore {

// The `scaling` parameter of a scene (a scene without layers, the 1D spring, is Thesis).
Scaling scalingOf(const ParameterSet& params);

// Factors that turn the table's values into the values a body of this resolution uses.
struct BodyScale {
    double mass = 1.0;                                      // per-particle mass factor
    std::array<double, kSpringFamilyCount> spring = {1.0, 1.0, 1.0};  // k and kd, per family
    double contact = 1.0;                                   // contact_stiffness factor
    bool operator==(const BodyScale&) const = default;
};

// The reference resolution of a scene: params with every resolution key at its default.
ParameterSet referenceShape(const ParameterSet& params);
// The name and value(s) of a scene's resolution, e.g. "subdivisions=4" ("" for the 1D spring).
std::string resolutionText(const ParameterSet& params);

// The factors for `body` built from `params` (all 1 under scaling=thesis); `shape` is
// resolve(params).shape when the caller has it.
BodyScale bodyScale(const ParameterSet& params, const Body& body);
BodyScale bodyScale(const ParameterSet& params, const Params::Shape& shape, const Body& body);

// The body a scene's parameters describe: its shape (body.h's buildShape) with the factors
// applied to the mass (the springs' and contact's factors are applied by the force model).
// Throws std::invalid_argument with validateShape's message for a shape it refuses.
struct ScaledBody {
    Body body;
    BodyScale scale;
};
ScaledBody buildScaledBody(const ParameterSet& params, const Params& resolved);
Body buildBody(const ParameterSet& params);

// The per-particle and per-spring values a body built from params actually uses.
struct BodyValues {
    BodyScale scale;
    int particlesPerLayer = 0;
    int referenceParticlesPerLayer = 0;
    double massInner = 0.0, massOuter = 0.0;    // per particle [kg] (1D: massOuter = mass)
    double layerMassInner = 0.0, layerMassOuter = 0.0;  // per layer [kg]
    std::array<double, kSpringFamilyCount> stiffness{};  // per spring, per family [N/m]
    std::array<double, kSpringFamilyCount> damping{};    // per spring, per family [N*s/m]
    std::array<int, kSpringFamilyCount> springs{};  // count per family
    double contactStiffness = 0.0;                // per particle [N/m^3]
};
BodyValues bodyValues(const ParameterSet& params, const Body& body);
// Builds the body to find out (for listings; a simulation has its topology already).
BodyValues bodyValues(const ParameterSet& params);

// One paragraph for listings and tooltips: what this body uses per particle and per spring.
std::string bodyValuesText(const ParameterSet& params, const BodyValues& values);

}  // namespace simcore
