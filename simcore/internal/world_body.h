#pragma once
// One body of a world: its parameters, its built body placed at its start, its force model
// and its ODE (BodyOde), each the one-body simulation's own pieces (docs/model.md "Several
// bodies": every body is built as a body alone is, with its own parameters).
//
// The world's state is the bodies' states side by side: body b's particles are the world's
// [first, first + count), so its x and v are the world's x and v from 3 first on; the world's
// ODE (world_ode.h) hands each body its slice and adds what passes between bodies.

#include <array>
#include <memory>

#include <Eigen/Core>

#include "simcore/body.h"
#include "simcore/forces.h"
#include "simcore/internal/body_ode.h"
#include "simcore/params.h"
#include "simcore/scaling.h"

namespace simcore {

// The force model's parameters from the resolved values: springs per family at this
// resolution (scaling.h), gas, gravity, the pointer and the wall contact around `boxCentre`
// on the axes the body moves along. Returns whether contact is the thesis program's
// projection (else a force). One function for the one-body simulation and every body of a
// world.
bool configureForces(ForceModel& forces, const ParameterSet& set, const Params& p, const BodyScale& scale,
                     int dimension, const Eigen::Vector3d& boxCentre);
// The wall contact's linearisation point for the stability estimates (contact.h ContactDesign)
// of a body at positions x: the free particles within a tenth of its height of its lowest
// point, each at the depth that carries its weight. One function for the one-body simulation
// and every body of a world.
ContactDesign contactDesignOf(const ForceModel& forces, const Body& body, bool projection,
                              const Eigen::Ref<const Eigen::Matrix3Xd>& x);
// 3N inverse masses: 0 on fixed particles and on the axes a body of this dimension does not
// move along (1D: y only; 2D: x and y).
Eigen::VectorXd inverseMasses(const Body& body);
// Adds the seeded start perturbation (parameter `perturb`, `seed`) to the moving coordinates.
void perturbStart(const Params::Start& start, const Eigen::VectorXd& inverseMass3, double* x);

class WorldBody {
public:
    // Builds the body with its centroid at `position`, every particle moving at `velocity`;
    // throws std::invalid_argument for a shape it refuses.
    WorldBody(const ParameterSet& params, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity, int first,
              const Eigen::Vector3d& boxCentre);
    WorldBody(const WorldBody&) = delete;
    WorldBody& operator=(const WorldBody&) = delete;

    const ParameterSet& parameters() const { return m_params; }
    const Eigen::Vector3d& startVelocity() const { return m_velocity; }
    const Params& params() const { return m_p; }
    const Body& body() const { return m_body; }  // positions: the start, placed
    const BodyScale& scale() const { return m_scale; }
    ForceModel& forces() { return m_forces; }
    const ForceModel& forces() const { return m_forces; }
    BodyOde& ode() { return *m_ode; }
    const Eigen::VectorXd& inverseMass3() const { return m_invMass3; }
    bool contactProjection() const { return m_contactProjection; }
    int first() const { return m_first; }  // its particle 0 in the world
    int count() const { return m_body.topology.particleCount(); }
    double mass() const { return m_totalMass; }

    // Its slice of a world state y = [x | v | aux] (n = 3 x the world's particles) into its
    // own scratch state [x_b | v_b | 0 0], and back.
    const Eigen::VectorXd& gather(const Eigen::VectorXd& y, Eigen::Index n);
    Eigen::VectorXd& local() { return m_y; }
    Eigen::VectorXd& localRate() { return m_dydt; }
    // Scratch vectors of its 3N (Jacobian products and the like).
    std::array<Eigen::VectorXd, 3>& scratch() { return m_scratch; }

private:
    ParameterSet m_params;
    Eigen::Vector3d m_velocity;
    Params m_p;
    Body m_body;
    BodyScale m_scale;
    ForceModel m_forces;
    Eigen::VectorXd m_invMass3;
    std::unique_ptr<BodyOde> m_ode;
    bool m_contactProjection = false;
    int m_first = 0;
    double m_totalMass = 0.0;
    Eigen::VectorXd m_y, m_dydt;
    std::array<Eigen::VectorXd, 3> m_scratch;
};

}  // namespace simcore
