#pragma once
// WorldOde: the bodies of a world as one ODE, the bodies' states side by side.
//
//   y     = [x_1 .. x_N | v_1 .. v_N | E_damp | E_contact]
//   dy/dt = [v          | F / m      | P_damp | P_contact]
//
// Each body's forces are its own BodyOde's (walls, springs, gas, layer barrier, pointer), on
// its slice of the state; the pairs between bodies and within one outer layer
// (contact_pairs.h) add theirs, equal and opposite. Every integrator steps the whole world:
// the Jacobians are the bodies' (block diagonal), plus the pairs' by a directional difference
// of their forces at the linearisation point (one pair evaluation per product, only while a
// pair is within the skin); xpbd gets the bodies' springs as one set of constraints.

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "simcore/contact_pairs.h"
#include "simcore/integrators.h"
#include "simcore/internal/world_body.h"

namespace simcore {

class WorldOde final : public OdeSystem {
public:
    static constexpr Eigen::Index kAux = BodyOde::kAux;

    WorldOde(std::vector<std::unique_ptr<WorldBody>>& bodies, ContactPairs& pairs, const PairContactParams& contact,
             int substeps);

    Eigen::Index positions() const { return m_n; }
    StateLayout layout() const override { return {m_n, kAux}; }
    using OdeSystem::derivative;
    void derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) override;
    // dy/dt with the by-products summed over the bodies; counted as a force evaluation or not.
    // pairSums: what the pairs added.
    void compute(const Eigen::VectorXd& y, Eigen::VectorXd& dydt, bool count);
    const PairSums& pairSums() const { return m_pairSums; }
    // The bodies' by-products of the last compute(), per body.
    const std::vector<ForceExtras>& extras() const { return m_extras; }
    const Eigen::VectorXd& inverseMass3() const { return m_invMass3; }

    bool hasForceJacobian() const override { return true; }
    void linearize(double t, const Eigen::VectorXd& y) override;
    void forceJacobianProduct(const Eigen::VectorXd& dx, const Eigen::VectorXd& dv, Eigen::VectorXd& out) override;
    void forceJacobianDiagonal(Eigen::VectorXd& kdiag, Eigen::VectorXd& ddiag) override;
    const Eigen::VectorXd& coordinateMass() const override { return m_mass; }
    bool distanceConstraints(DistanceConstraints& out) override;
    bool stronglyNonlinear(double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& v1) override;
    int contactVelocities(double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& v1,
                          Eigen::VectorXd& target) override;
    // Whether xpbd can take the world: every body's springs of a family have the same ks and kd
    // (xpbd's constraints carry one compliance per family). The message when not.
    std::optional<std::string> xpbdRefusal() const;

private:
    // x_b and v_b of a whole-world vector (3N, or its x or v part) to a body's, and back.
    void scatter(const WorldBody& b, const Eigen::VectorXd& local, Eigen::Index localAt, Eigen::VectorXd& world,
                 Eigen::Index worldAt) const;

    std::vector<std::unique_ptr<WorldBody>>& m_bodies;
    ContactPairs& m_pairs;
    const PairContactParams& m_contact;
    int m_substeps = 1;
    Eigen::Index m_n = 0;
    Eigen::VectorXd m_invMass3, m_mass;
    std::vector<ForceExtras> m_extras;
    PairSums m_pairSums;
    Eigen::VectorXd m_pairForce;  // 3N scratch
    // The linearisation point for the pairs' directional differences.
    Eigen::VectorXd m_y0, m_pairForce0, m_shifted;
    bool m_pairsActive = false;
    // xpbd: every body's springs in world numbering.
    std::array<SpringSet, kSpringFamilyCount> m_springs;
};

}  // namespace simcore
