#pragma once
// The per-particle scans beside the force kernels (internal to simcore): the state scan of
// every step (Simulation::scanPiece: finiteness, extent, kinetic and gravity energy, fastest
// speed) and the paired contact screen of every layered force evaluation (scanPairedRanges:
// any particle beyond a wall, any inner particle beyond its outer partner's tangent plane).
//
// Written once (internal/scan_kernels_body.h) over simd.h's vectors and compiled with the
// force kernels (force_kernels.cpp), once per instruction set; kernelsInUse() picks the copy
// (the AVX-512 set runs the AVX2 one: the scans are four lanes wide). Four particles per step, each coordinate loaded once in rows and
// transposed in registers. Every answer is the plain loop's: the order-free parts (extent,
// finiteness, fastest speed, the screens' "any") in lanes, the two energy sums particle by
// particle in the plain order (each term computed four at a time, added one at a time), so
// the bits are the same in every set (tested against the plain loops).

#include <array>

namespace simcore::kernels {

// A state scan of particles [begin, end).
struct StateScan {
    bool finite = true;          // every x and v coordinate finite
    std::array<double, 3> low{}, high{};  // extent of the moving coordinates (invMass3 != 0)
    double kinetic = 0.0;        // sum over free particles, in order, of 0.5 m |v|^2 [J]
    double gravity = 0.0;        // with weighs: sum over free particles, in order, of m g y [J]
    double fastest2 = 0.0;       // largest |v|^2 [m^2/s^2]
};
// x, v: 3 doubles per particle; invMass3: 3 per particle, 0 where a coordinate does not move
// (a fixed particle has none: it is free where its y entry is not 0); mass: 1 per particle.
// |v|^2 is (vx^2 + vy^2) + vz^2 (Eigen's squaredNorm of a 3-vector).
StateScan scanState(const double* x, const double* v, const double* invMass3, const double* mass, bool weighs,
                    double g, int begin, int end);

// Pairs (i, i + offset) for i in [begin, end): outsideWalls is whether any coordinate of
// either is below low or above high (NaN compares false), beyondPlane whether any
// (x_i - x_o) . g_o > 0 with g_o row i + offset of g4 (4 doubles per particle), the dot taken
// ((wx gx + wy gy) + wz gz).
struct PairScanBits {
    bool outsideWalls = false;
    bool beyondPlane = false;
};
PairScanBits scanPairs(const std::array<double, 3>& low, const std::array<double, 3>& high, const double* x,
                       const double* g4, int begin, int end, int offset);

}  // namespace simcore::kernels
