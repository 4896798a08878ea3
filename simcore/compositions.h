#pragma once
// The compositions of velocity Verlet (integrators.cpp, Composition): Verlet taken over the
// substeps w_1 h, ..., w_s h of a step h (symmetric weights summing to 1, some negative), the
// acceleration at the end of each substep starting the next.
//
//   method            order  force evaluations per step        error estimate
//   verlet            2 (1)  2 (one substep)                    step doubling (optional)
//   yoshida4          4 (1)  4 (3 Verlet substeps)              step doubling (optional)
//   yoshida8          8 (1)  16 (15 Verlet substeps)            step doubling (optional)
//
// (1): with damping, which the shared evaluation takes at the half-kick velocity.
// The stability analysis (simlab/stability.cpp) builds their step matrices from the weights.

#include <span>
#include <string_view>

namespace simcore {

// The substep weights of a composition of velocity Verlet (verlet itself: {1}; yoshida4,
// yoshida8), empty for other methods.
std::span<const double> compositionWeights(std::string_view name);

}  // namespace simcore
