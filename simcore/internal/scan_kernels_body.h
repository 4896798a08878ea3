// The scans' kernels (scan_kernels.h), written once over simd.h's vectors.
//
// Deliberately without an include guard: force_kernels.cpp includes this once per instruction
// set, right after simd.h and force_kernels_body.h (same SIMCORE_SIMD_ISA and SIMCORE_SIMD_NS),
// and so gets the scans of each set in simcore::kernels::<ns>.

namespace simcore::kernels::SIMCORE_SIMD_NS {

using namespace simd::SIMCORE_SIMD_NS;

// The smaller (larger) of an accumulator and a candidate as std::min(acc, c) (std::max) picks
// it: a NaN candidate leaves the accumulator as it was.
template <class V>
[[gnu::always_inline]] inline V keepLower(V acc, V c) {
    return c < acc ? c : acc;
}
template <class V>
[[gnu::always_inline]] inline V keepHigher(V acc, V c) {
    return acc < c ? c : acc;
}

inline StateScan scanState(const double* x, const double* v, const double* invMass3, const double* mass, bool weighs,
                           double g, int begin, int end) {
    const double infinity = __builtin_inf();
    const Vec4 zero = splat<Vec4>(0.0), inf = splat<Vec4>(infinity), minusInf = splat<Vec4>(-infinity);
    const Vec4 half = splat<Vec4>(0.5), gv = splat<Vec4>(g);
    Vec4 lowX = inf, lowY = inf, lowZ = inf, highX = minusInf, highY = minusInf, highZ = minusInf;
    // (x - x) + (v - v) is 0 for finite coordinates and NaN otherwise: summed per lane, any
    // NaN stays.
    Vec4 nonFinite = zero, fastest2 = zero;
    double kinetic = 0.0, gravity = 0.0;
    int i = begin;
    for (; i + 4 <= end; i += 4) {
        const std::size_t at = 3 * static_cast<std::size_t>(i);
        Vec4 X, Y, Z, VX, VY, VZ, IX, IY, IZ;
        rowsToColumns(x + at, X, Y, Z);
        rowsToColumns(v + at, VX, VY, VZ);
        rowsToColumns(invMass3 + at, IX, IY, IZ);
        nonFinite = nonFinite + (((X - X) + (Y - Y)) + (Z - Z)) + (((VX - VX) + (VY - VY)) + (VZ - VZ));
        // Only moving coordinates (not a fixed particle's, not an axis the body does not move
        // in) count for the extent.
        lowX = keepLower(lowX, IX != zero ? X : inf), highX = keepHigher(highX, IX != zero ? X : minusInf);
        lowY = keepLower(lowY, IY != zero ? Y : inf), highY = keepHigher(highY, IY != zero ? Y : minusInf);
        lowZ = keepLower(lowZ, IZ != zero ? Z : inf), highZ = keepHigher(highZ, IZ != zero ? Z : minusInf);
        const Vec4 speed2 = (VX * VX + VY * VY) + VZ * VZ;
        fastest2 = keepHigher(fastest2, speed2);
        // The energies term by term in lanes, summed one particle at a time (the plain order;
        // a fixed particle adds 0, which leaves a sum that started at +0 as it was).
        const Vec4 m = loadu<Vec4>(mass + i);
        const auto isFree = IY != zero;
        double term[4];
        storeu(term, isFree ? (half * m) * speed2 : zero);
        kinetic = kinetic + term[0];
        kinetic = kinetic + term[1];
        kinetic = kinetic + term[2];
        kinetic = kinetic + term[3];
        if (weighs) {
            storeu(term, isFree ? (m * gv) * Y : zero);
            gravity = gravity + term[0];
            gravity = gravity + term[1];
            gravity = gravity + term[2];
            gravity = gravity + term[3];
        }
    }
    StateScan s;
    double lanes[4], bad = 0.0;
    storeu(lanes, nonFinite);
    for (double l : lanes) bad += l;
    const Vec4 low[3] = {lowX, lowY, lowZ}, high[3] = {highX, highY, highZ};
    for (std::size_t axis = 0; axis < 3; ++axis) {
        s.low[axis] = infinity;
        s.high[axis] = -infinity;
        for (std::size_t l = 0; l < 4; ++l) {
            s.low[axis] = keepLower(s.low[axis], low[axis][l]);
            s.high[axis] = keepHigher(s.high[axis], high[axis][l]);
        }
    }
    double fastest = 0.0;
    for (std::size_t l = 0; l < 4; ++l) fastest = keepHigher(fastest, fastest2[l]);
    // The last particles one by one, as the plain loop.
    for (; i < end; ++i) {
        const std::size_t at = 3 * static_cast<std::size_t>(i);
        for (std::size_t axis = 0; axis < 3; ++axis) {
            const std::size_t k = at + axis;
            bad += (x[k] - x[k]) + (v[k] - v[k]);
            const bool moves = invMass3[k] != 0.0;
            s.low[axis] = keepLower(s.low[axis], moves ? x[k] : infinity);
            s.high[axis] = keepHigher(s.high[axis], moves ? x[k] : -infinity);
        }
        const double speed2 = (v[at] * v[at] + v[at + 1] * v[at + 1]) + v[at + 2] * v[at + 2];
        fastest = keepHigher(fastest, speed2);
        if (invMass3[at + 1] == 0.0) continue;
        kinetic += 0.5 * mass[i] * speed2;
        if (weighs) gravity += mass[i] * g * x[at + 1];
    }
    s.finite = bad == 0.0;
    s.kinetic = kinetic;
    s.gravity = gravity;
    s.fastest2 = fastest;
    return s;
}

inline PairScanBits scanPairs(const std::array<double, 3>& low, const std::array<double, 3>& high, const double* x,
                              const double* g4, int begin, int end, int offset) {
    const double infinity = __builtin_inf();
    // Extent per lane (NaN left out), compared with the walls once at the end.
    Vec4 lowX = splat<Vec4>(infinity), lowY = lowX, lowZ = lowX;
    Vec4 highX = splat<Vec4>(-infinity), highY = highX, highZ = highX;
    auto beyond = splat<Vec4>(0.0) < splat<Vec4>(0.0);  // all false
    int i = begin;
    for (; i + 4 <= end; i += 4) {
        const std::size_t inner = static_cast<std::size_t>(i), outer = static_cast<std::size_t>(i + offset);
        Vec4 XI, YI, ZI, XO, YO, ZO, GX, GY, GZ;
        rowsToColumns(x + 3 * inner, XI, YI, ZI);
        rowsToColumns(x + 3 * outer, XO, YO, ZO);
        toColumns(loadPadded(g4, outer), loadPadded(g4, outer + 1), loadPadded(g4, outer + 2), loadPadded(g4, outer + 3),
                  GX, GY, GZ);
        lowX = keepLower(keepLower(lowX, XI), XO), highX = keepHigher(keepHigher(highX, XI), XO);
        lowY = keepLower(keepLower(lowY, YI), YO), highY = keepHigher(keepHigher(highY, YI), YO);
        lowZ = keepLower(keepLower(lowZ, ZI), ZO), highZ = keepHigher(keepHigher(highZ, ZI), ZO);
        beyond = beyond | ((((XI - XO) * GX + (YI - YO) * GY) + (ZI - ZO) * GZ) > splat<Vec4>(0.0));
    }
    PairScanBits scan;
    bool any = false;
    for (std::size_t l = 0; l < 4; ++l) any = any || beyond[l] != 0;
    std::array<double, 3> lo{infinity, infinity, infinity}, hi{-infinity, -infinity, -infinity};
    for (std::size_t l = 0; l < 4; ++l) {
        lo[0] = keepLower(lo[0], lowX[l]), hi[0] = keepHigher(hi[0], highX[l]);
        lo[1] = keepLower(lo[1], lowY[l]), hi[1] = keepHigher(hi[1], highY[l]);
        lo[2] = keepLower(lo[2], lowZ[l]), hi[2] = keepHigher(hi[2], highZ[l]);
    }
    for (; i < end; ++i) {
        const double* xi = x + 3 * static_cast<std::size_t>(i);
        const double* xo = x + 3 * static_cast<std::size_t>(i + offset);
        const double* g = g4 + 4 * static_cast<std::size_t>(i + offset);
        for (std::size_t axis = 0; axis < 3; ++axis) {
            lo[axis] = keepLower(keepLower(lo[axis], xi[axis]), xo[axis]);
            hi[axis] = keepHigher(keepHigher(hi[axis], xi[axis]), xo[axis]);
        }
        any = any || (xi[0] - xo[0]) * g[0] + (xi[1] - xo[1]) * g[1] + (xi[2] - xo[2]) * g[2] > 0.0;
    }
    scan.outsideWalls = lo[0] < low[0] || lo[1] < low[1] || lo[2] < low[2] || hi[0] > high[0] || hi[1] > high[1] ||
                        hi[2] > high[2];
    scan.beyondPlane = any;
    return scan;
}

}  // namespace simcore::kernels::SIMCORE_SIMD_NS
