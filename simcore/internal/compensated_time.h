#pragma once
// The simulated time advanced step by step by a compensated (Kahan) sum, shared by Simulation,
// World and the float path: a million steps of 0.003 s land on the intended time, so advanceTo()
// never takes an extra step from accumulated round-off, and a float run started at a scene's start
// (no carry yet) has the double run's times to the last bit.

namespace simcore {

// t0 + h, with `carry` the round-off the sum has lost so far [s] (updated).
inline double advanceTime(double t0, double h, double& carry) {
    const double increment = h - carry;
    const double t = t0 + increment;
    carry = (t - t0) - increment;
    return t;
}

}  // namespace simcore
