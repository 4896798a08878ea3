#pragma once
// Contact as a force inside the equations of motion (docs/model.md "Contact"; thesis 4.6, which
// calls its collision response a penalty method). Free functions on flat arrays, testable
// without a world; ForceModel calls them in every force evaluation, so every stage of every
// integrator sees them, the energy ledger books them and the Jacobians include them.
//
// Box walls. A plane with inward unit normal n (an axis of the box) and a particle at x, v:
//
//     d    = max(0, -(n.x - b))            penetration [m]
//     ddot = -n.v                          penetration rate [m/s] (> 0: moving in)
//     f_n  = k d^3 phi(alpha ddot),   phi(u) = u + sqrt(1 + u^2)          along n [N]
//
//   * k d^3 = -dU/dd with U = k d^4 / 4, the contact energy (in E_total). U, U', U'' and U'''
//     vanish at d = 0, so the force is C^2 in x: RK4 sees a smooth right-hand side (a Hertz
//     d^{3/2} law is only C^1 at the onset and would cost it its order).
//   * k d^3 (phi - 1) is the dissipation, Hunt & Crossley's k d^n (1 + alpha ddot) made
//     smooth: phi(u) = 1 + u + u^2/2 + O(u^4) near 0, (phi - 1) u >= 0 (it only removes
//     energy; its power k d^3 (phi - 1) ddot is booked as removed by contact), and phi > 0
//     (the total never pulls the particle into the wall, the clip is analytic, not a max).
//   * friction: F_t = -mu f_n v_t / sqrt(|v_t|^2 + eps^2), Coulomb regularised below the
//     slip speed eps (smooth in v_t, no switch); its power mu f_n |v_t|^2 / sqrt(..) is booked
//     as removed by contact too.
//
// Restitution. For one particle of mass m hitting a wall at speed v0, the substitution
// d = D s, t = T tau with T^4 = m / (k v0^2), D = v0 T turns the impact into
//     s'' = -s^3 phi(zeta s'),  s(0) = 0, s'(0) = 1,  zeta = alpha v0,
// so the rebound ratio e = -s'(end) depends on zeta alone, not on k or m. restitutionOf(zeta)
// integrates that once; dampingForRestitution(e) inverts it: alpha = zeta(e) / v_ref makes a
// particle that hits at the reference speed v_ref rebound with exactly e. Hunt & Crossley's
// small-damping result zeta = 3 (1 - e^2) / 4 (derived for any power d^n) is its limit at e -> 1.
// The rebound of a whole body differs (its springs take part of the energy; contact_speed
// sets where a single particle matches): docs/numerics.md measures both.
//
// Layer barrier. Inner particle i must stay behind the tangent plane of its outer partner o.
// With g = dV_outer/dx_o (the outer layer's volume gradient at o: the area-weighted normal,
// a polynomial in o's neighbours) and g0 = |g| in the rest shape,
//     q = sqrt2 (x_i - x_o).g / sqrt(|g|^2 + g0^2)   [m] (> 0: i is outside the plane),
//     U = k q^4 / 4 for q > 0,
// and the force is exactly -dU/dx on i, o and o's neighbours (g depends on them), so the
// barrier is conservative and in the ledger. At rest q is the distance to the tangent plane;
// where the outer layer stretches (|g| >> g0) it stays that distance, and where a fan folds
// (|g| -> 0, the plane's direction turning fast) q fades instead of growing stiff: dq/dx is
// bounded by |x_i - x_o| / g0, q is C^inf and U is C^2 at q = 0. The projection it replaces was a jump.

#include <array>
#include <limits>
#include <vector>

namespace simcore {

// The tunables contact forces read, resolved from the parameter table.
struct ContactParams {
    bool walls = false;          // box walls as a force (contact = force)
    bool layerBarrier = false;   // inner layer kept inside the outer one by a barrier
    double stiffness = 0.0;      // k in U = k d^4 / 4 [N/m^3]
    double alpha = 0.0;          // Hunt-Crossley coefficient alpha [s/m]; 0: no dissipation
    double friction = 0.0;       // Coulomb coefficient mu
    double frictionSpeed = 0.5;  // slip speed eps below which friction is regularised [m/s]
    // Wall planes per axis [m]: particles stay in [low, high]; infinite on axes the body does
    // not move along.
    std::array<double, 3> low{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                              -std::numeric_limits<double>::infinity()};
    std::array<double, 3> high{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity()};
};

// The contact's linearisation point for the stability estimates (a body at its start has no
// contact, and U'' = 3 k d^2 vanishes at d = 0): the particles nearest the floor, each at a
// design depth d* (Simulation::contactDesign says how they are chosen). Empty when contact is
// not a force, when nothing falls (no gravity) or when the body hangs from a fixed particle.
struct ContactDesign {
    std::vector<int> particles;  // the free particles nearest the floor
    int axis = 1;                // the floor's normal axis
    double depth = 0.0;          // d* [m]
    double stiffness = 0.0;      // -dF/dx = 3 k d*^2 [N/m]
    double damping = 0.0;        // -dF/dv = k d*^3 alpha at ddot = 0 [N s/m]
    double friction = 0.0;       // tangential -dF/dv = mu k d*^3 / eps [N s/m]
};

// phi(u) = u + sqrt(1 + u^2), evaluated without cancellation for u < 0.
double contactPhi(double u);
// phi(u) - 1 without cancellation near u = 0.
double contactPhiMinusOne(double u);

// Whether a particle at x is beyond any wall (the cheap test before wallContact).
inline bool outsideWalls(const ContactParams& c, const double* x) {
    return x[0] < c.low[0] || x[0] > c.high[0] || x[1] < c.low[1] || x[1] > c.high[1] || x[2] < c.low[2] ||
           x[2] > c.high[2];
}

// Whether any of particles [begin, end) is beyond a wall. Four particles (twelve coordinates,
// the period of the x y z pattern in a vector of four) per iteration, as a running minimum and
// maximum per coordinate slot, compared with the planes once at the end: a loop the compiler
// vectorises, a few operations per particle (nothing touches a wall nearly always).
bool anyOutsideWalls(const ContactParams& c, const double* x, int begin, int end);

// The wall force on one particle at x, v added into f (3 doubles); returns its contact
// energy sum U [J] and adds the power removed by dissipation and friction [W] into power.
double wallContact(const ContactParams& c, const double* x, const double* v, double* f, double& power);
// Contact energy of one particle alone [J].
double wallContactEnergy(const ContactParams& c, const double* x);
// Diagonal of the wall force Jacobians of one particle, added into k (dF/dx) and d (dF/dv),
// 3 each. The normal terms are exact; friction contributes its isotropic part
// -mu f_n / sqrt(|v_t|^2 + eps^2) on the tangential axes (the rank-one part that softens it
// and the coupling through f_n are left out: the estimate errs on the stiff side).
void addWallContactJacobian(const ContactParams& c, const double* x, const double* v, double* k, double* d);

// Restitution of one particle hitting a wall with zeta = alpha v0 (see above), in [0, 1].
double restitutionOf(double zeta);
// zeta with restitutionOf(zeta) = e (bisection; memoised); e = 1 gives 0. Below
// restitutionOf(kMaxZeta) the largest zeta is returned.
double dampingForRestitution(double e);
inline constexpr double kMaxZeta = 1000.0;

// The layer barrier's pairs, with the outer vertex's neighbourhood (its fan) that g depends on.
struct LayerBarrierSet {
    std::vector<int> inner, outer;     // strictly increasing (pairs in layerPairs order)
    std::vector<double> invRestNorm;   // 1 / |g| in the rest shape [1/m^2 in 3D, 1/m in 2D]
    std::vector<int> fanStart;         // pair k's fan is fan[fanStart[k] .. fanStart[k + 1])
    // 3D: (b, c) of each outer triangle (o, b, c), oriented; 2D: one (previous, next) entry.
    std::vector<std::array<int, 2>> fan;
    std::size_t size() const { return inner.size(); }
    void clear();
};

// Layered bodies: one pass over paired particle ranges (inner [begin, end), outer the same +
// offset) gives both whether any of them is beyond a wall and whether any pair may be beyond
// its tangent plane (g4 of outer particles whose faces are not all summed yet may give a false
// "maybe", never a false "no" for a pair whose faces are).
struct PairScan {
    bool outsideWalls = false;
    bool beyondPlane = false;
};
PairScan scanPairedRanges(const ContactParams& c, const double* x, const double* g4, int begin, int end, int offset);

// Adds the barrier forces of every pair of the set into f4 (padded, 4 doubles per particle),
// reading g from g4 (the outer layer's dV/dx, padded). Returns the barrier energy [J]. With
// screen, a branch-free pass first finds whether any pair is beyond its plane at all (without,
// the caller has found that some may be).
double layerBarrierForces(const LayerBarrierSet& set, int dimension, double k, const double* x, const double* g4,
                          double* f4, bool screen = true);

inline constexpr double kSqrt2 = 1.4142135623730951;
// The penetration q [m] of pair k (> 0: inner particle outside), from g in g4 (when inside,
// only its sign is meaningful).
double layerBarrierDepth(const LayerBarrierSet& set, std::size_t k, const double* x, const double* g4);
// g of pair k's outer vertex computed from its fan at positions x (3 per particle).
std::array<double, 3> layerBarrierNormal(const LayerBarrierSet& set, std::size_t k, int dimension, const double* x);

}  // namespace simcore
