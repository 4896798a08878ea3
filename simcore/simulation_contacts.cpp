// The contact stages of a step with contact = projection (the thesis program's collision
// response, docs/model.md "Contact"): the box planes (collide) and the layer pairs (constrain),
// and the contact design point of the stability estimates. Contact as a force inside the
// ODE is contact.h; its Jacobians are in body_ode.cpp.
#include "simcore/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "simcore/internal/body_ode.h"
#include "simcore/internal/world_body.h"

namespace simcore {

bool Simulation::collide(StepWork& w) {
    // The box walls change the state outside the ODE: the energy they change is measured
    // across them (the check stage books it as removed by collisions).
    if (!w.scan.finite || !m_contactProjection || !m_forces.terms().has(Term::Collisions)) return true;
    m_forces.countPostStep(Term::Collisions);
    // Most steps touch no wall: the scan's extent says so without a second pass. The planes
    // are the force model's (the box on each axis the body moves along, infinite on the others).
    const ContactParams& c = m_forces.contact;
    const Eigen::Array3d wallLow(c.low[0], c.low[1], c.low[2]), wallHigh(c.high[0], c.high[1], c.high[2]);
    if (!((w.scan.low <= wallLow) || (w.scan.high >= wallHigh)).any() || !collideWalls(false)) return true;
    w.beforeContacts = totalEnergyNow();
    collideWalls(true);
    m_restartIntegrator = true;
    w.scan = scanState();
    return true;
}

bool Simulation::constrain(StepWork& w) {
    // The layer constraint's normals are the outer layer's volume gradient, which the measure
    // stage's force evaluation leaves behind: it runs after that measurement, and a state it
    // corrects is scanned and measured again.
    if (!w.scan.finite || !m_contactProjection || !m_forces.terms().has(Term::LayerConstraint)) return true;
    m_forces.countPostStep(Term::LayerConstraint);
    const kernels::PaddedRows normals =
        m_reuseEndForces ? m_forces.volumeGradient() : m_forces.computeVolumeGradient(m_y.data());
    if (!constrainLayers(false, normals)) return true;
    if (!w.beforeContacts) w.beforeContacts = w.next.total();
    constrainLayers(true, normals);
    m_restartIntegrator = true;
    w.scan = scanState();
    measureState(w.next, w.scan);
    return true;
}

bool Simulation::collideWalls(bool apply) {
    // Axis-aligned box planes (thesis 4.6; docs/model.md): a particle outside is projected back
    // and its normal velocity becomes -e v_n; friction scales the tangential velocity by
    // (1 - mu). Only the axes the body moves in are bounded. Particles are independent: the
    // pieces run in parallel.
    std::array<bool, kPiecesMax> pieceAny{};
    inPieces([&](int piece, int begin, int end) {
        pieceAny[static_cast<std::size_t>(piece)] = collideRange(apply, begin, end);
    });
    return std::find(pieceAny.begin(), pieceAny.end(), true) != pieceAny.end();
}

bool Simulation::collideRange(bool apply, int begin, int end) {
    const int dims = m_body.topology.dimension;
    const double restingSpeed = 2.0 * m_forces.params.gravity * m_hTaken;
    bool any = false;
    for (int i = begin; i < end; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            const Eigen::Index k = 3 * i + axis;
            if (m_invMass3[k] == 0.0) continue;
            const double lo = m_forces.contact.low[static_cast<std::size_t>(axis)];
            const double hi = m_forces.contact.high[static_cast<std::size_t>(axis)];
            double& x = m_y[k];
            double& v = m_y[m_n + k];
            // On the wall and moving into it counts too: an implicit step lands particles
            // exactly on the wall (contacts inside its solve) and leaves restitution to here.
            const bool below = x < lo || (x == lo && v < 0.0), above = x > hi || (x == hi && v > 0.0);
            if (!below && !above) continue;
            any = true;
            if (!apply) return true;
            x = below ? lo : hi;
            // Resting contact: an approach no faster than what gravity adds in two steps is
            // stopped, not bounced. Bouncing it would make a resting body chatter, each step
            // sinking, being lifted back and bounced, pumping energy that damping then removes.
            if ((below && v < 0.0) || (above && v > 0.0))
                v = std::abs(v) <= restingSpeed ? 0.0 : -m_p.world.restitution * v;
            if (m_p.world.friction > 0.0) {
                for (int other = 0; other < dims && other < 3; ++other) {
                    const int tangent = dims == 1 ? 1 : other;
                    if (tangent == axis) continue;
                    m_y[m_n + 3 * i + tangent] *= 1.0 - m_p.world.friction;
                }
            }
        }
    }
    return any;
}

bool Simulation::constrainLayers(bool apply, kernels::PaddedRows normals) {
    // Each inner particle must stay on the inner side of the tangent plane of its paired
    // outer particle. The outer vertex normal is the direction of the outer layer's volume
    // gradient dV/dx there (normals): the area-weighted mean of the adjacent face
    // normals (3D) or the perpendicular of the neighbouring chords (2D). A violation is undone
    // symmetrically: positions and relative normal velocity are corrected with mass weights,
    // so momentum is conserved. Pairs are independent: the pieces run in parallel.
    const auto& pairs = m_body.topology.layerPairs;
    if (pairs.empty() || !normals) return false;
    double* x = m_y.data();
    double* v = m_y.data() + m_n;
    std::array<bool, kPiecesMax> pieceAny{};
    inPiecesOf(static_cast<int>(pairs.size()), [&](int piece, int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const auto [in, out] = pairs[static_cast<std::size_t>(k)];
            const Eigen::Map<const Eigen::Vector3d> gradient = normals[out];
            Eigen::Map<Eigen::Vector3d> xi(x + 3 * in), xo(x + 3 * out), vi(v + 3 * in), vo(v + 3 * out);
            // The sign first (no root, no division for the pairs that are fine, nearly all).
            if (!((xi - xo).dot(gradient) > 0.0)) continue;
            const double norm = gradient.norm();
            if (norm <= 0.0) continue;
            const Eigen::Vector3d n = gradient / norm;
            const double depth = (xi - xo).dot(n);
            if (depth <= 0.0) continue;
            pieceAny[static_cast<std::size_t>(piece)] = true;
            if (!apply) return;
            const double mi = m_body.mass[in], mo = m_body.mass[out];
            const double wi = mo / (mi + mo), wo = mi / (mi + mo);
            xi -= wi * depth * n;
            xo += wo * depth * n;
            const double separating = (vi - vo).dot(n);
            if (separating > 0.0) {
                vi -= wi * separating * n;
                vo += wo * separating * n;
            }
        }
    });
    return std::find(pieceAny.begin(), pieceAny.end(), true) != pieceAny.end();
}


ContactDesign contactDesignOf(const ForceModel& forces, const Body& body, bool projection,
                              const Eigen::Ref<const Eigen::Matrix3Xd>& x) {
    ContactDesign design;
    const ContactParams& c = forces.contact;
    const double g = forces.terms().has(Term::Gravity) ? forces.params.gravity : 0.0;
    // A body held by a fixed particle hangs from it: only free bodies are taken to fall.
    const bool held = std::find(body.fixed.begin(), body.fixed.end(), true) != body.fixed.end();
    if (projection || !forces.contactWalls() || !(g > 0.0) || !(c.stiffness > 0.0) || held) return design;
    const int count = body.topology.particleCount();
    double lowest = std::numeric_limits<double>::infinity(), weight = 0.0;
    for (int i = 0; i < count; ++i) {
        if (body.fixed[static_cast<std::size_t>(i)]) continue;
        lowest = std::min(lowest, x(1, i));
        weight += body.mass[i] * g;
    }
    // The contact patch: the free particles within a tenth of the body's height of its lowest
    // point (measured on the default scenes, the particles touching at rest carry their
    // weight with these depths to within 10 %: docs/numerics.md).
    double highest = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < count; ++i)
        if (!body.fixed[static_cast<std::size_t>(i)]) highest = std::max(highest, x(1, i));
    const double band = 0.1 * (highest - lowest);
    for (int i = 0; i < count; ++i)
        if (!body.fixed[static_cast<std::size_t>(i)] && x(1, i) <= lowest + band) design.particles.push_back(i);
    if (design.particles.empty()) return design;
    // Rest: the weight shared by the patch (k d^3 = W / count). An impact goes deeper, but
    // only for a few steps: a step beyond the stable one there amplifies by a bounded factor,
    // while the resting contact lasts (measured: the impact depth as design point predicts
    // half the measured limits; docs/numerics.md).
    design.depth = std::cbrt(weight / (static_cast<double>(design.particles.size()) * c.stiffness));
    const double d = design.depth;
    design.stiffness = 3.0 * c.stiffness * d * d;
    design.damping = c.stiffness * d * d * d * c.alpha;
    design.friction = c.friction * c.stiffness * d * d * d / c.frictionSpeed;
    return design;
}

Simulation::ContactDesign Simulation::contactDesign() const {
    return contactDesignOf(m_forces, m_body, m_contactProjection, positions());
}

void Simulation::setContactDesignInJacobians(bool on) {
    m_ode->setContactDesign(on ? std::optional<ContactDesign>(contactDesign()) : std::nullopt);
}

}  // namespace simcore
