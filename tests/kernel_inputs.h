#pragma once
// The force kernels' test inputs, shared by test_force_kernels (every kernel set on x86-64, bit
// for bit) and tests/cross/force_hash.cpp (the same inputs built for AArch64): random rows for
// two layers of kPerLayer particles, and kBegin + kMaxLength springs, quads, a radius run and
// triangles, so that blocks [kBegin, kBegin + length) for every length up to kMaxLength start
// inside the arrays. Qt-free (the cross driver has no Qt).

#include <random>
#include <vector>

#include "simcore/force_kernels.h"
#include "simcore/forces.h"

namespace kernel_inputs {

constexpr int kPerLayer = 64;  // particles per layer; two layers
constexpr int kParticles = 2 * kPerLayer;
constexpr std::size_t kBegin = 3;  // blocks start inside the arrays, not at 0
constexpr std::size_t kMaxLength = 40;

struct Inputs {
    std::vector<double> x, v, invMass3, f4Start;
    simcore::SpringSet springs, run;
    simcore::kernels::QuadSet quads;
    simcore::Surface surface;
};

inline Inputs makeInputs() {
    std::mt19937_64 rng(14);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Inputs in;
    for (int i = 0; i < 3 * kParticles; ++i) {
        in.x.push_back(unit(rng));
        in.v.push_back(unit(rng));
        in.invMass3.push_back(1.5 + unit(rng));
    }
    for (int i = 0; i < 4 * kParticles; ++i) in.f4Start.push_back(i % 4 == 3 ? 0.0 : unit(rng));
    // Particle 7 sits on particle 8: spring kBegin + 5 (7, 8) is degenerate.
    for (int axis = 0; axis < 3; ++axis) in.x[3 * 7 + axis] = in.x[3 * 8 + axis];
    std::uniform_int_distribution<int> any(0, kParticles - 1), inner(0, kPerLayer - 1);
    for (std::size_t k = 0; k < kBegin + kMaxLength; ++k) {
        int a = any(rng), b = any(rng);
        if (k == kBegin + 5) a = 7, b = 8;
        while (b == a) b = any(rng);
        in.springs.add(a, b, 0.5 + 0.5 * unit(rng));
        // A run: spring k joins particle 10 + k to that + kPerLayer.
        in.run.add(10 + static_cast<int>(k), 10 + static_cast<int>(k) + kPerLayer, 0.5 + 0.5 * unit(rng));
        int qa = inner(rng), qb = inner(rng);
        while (qb == qa) qb = inner(rng);
        in.quads.a.push_back(qa);
        in.quads.b.push_back(qb);
        in.quads.rest.push_back({0.4 + 0.1 * unit(rng), 0.4 + 0.1 * unit(rng), 0.6 + 0.1 * unit(rng), 0.6 + 0.1 * unit(rng)});
        in.surface.triangles.push_back({any(rng), any(rng), any(rng)});
    }
    return in;
}

}  // namespace kernel_inputs
