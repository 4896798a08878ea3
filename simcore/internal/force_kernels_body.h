// The force kernels, written once over simd.h's width-generic vectors (internal to simcore).
//
// Deliberately without an include guard: force_kernels.cpp includes this once per
// instruction set, right after simd.h with the same SIMCORE_SIMD_ISA and SIMCORE_SIMD_NS (see
// there), and so gets the kernels of each set in simcore::kernels::<ns>. Their contracts are
// the public ones of force_kernels.h. All sets do the same operations in the same order on the
// same numbers, so their results are bit-identical (tested).

namespace simcore::kernels::SIMCORE_SIMD_NS {

using namespace simd::SIMCORE_SIMD_NS;

// A particle index as an unsigned offset (indices are never negative): addresses from it need
// no sign extension.
[[gnu::always_inline]] inline std::size_t index(int p) { return static_cast<std::uint32_t>(p); }

// ---------------------------------------------------------------------------------------------
// The arithmetic, lane by lane (V a vector, or double for the last few elements of a block)

// One spring per lane: separation d and relative velocity dv in; force on the first particle,
// damping power damping * (dv.u)^2 and stretch L - L0 out. Counts springs shorter than
// kDegenerateLength into `shortCount`; they keep a finite direction (divided by the epsilon
// instead of their length) and get a zero force.
template <class V>
struct SpringLanes {
    V fx, fy, fz, power, stretch;
};
template <class V, class Count>
[[gnu::always_inline]] inline SpringLanes<V> springLanes(V dx, V dy, V dz, V dvx, V dvy, V dvz, V rest, V stiffness,
                                                         V damping, Count& shortCount) {
    const V zero = splat<V>(0.0), one = splat<V>(1.0), eps = splat<V>(kDegenerateLength);
    const V length2 = (dx * dx + dy * dy) + dz * dz;
    countTrue(shortCount, length2 < eps * eps);
    const V length = sqrt(length2);
    const auto tooShort = length < eps;
    const V inv = one / (tooShort ? eps : length);
    const V live = tooShort ? zero : one;
    const V ux = dx * inv, uy = dy * inv, uz = dz * inv;
    const V closing = (dvx * ux + dvy * uy) + dvz * uz;
    const V stretch = length - rest;
    const V magnitude = live * (stiffness * stretch + damping * closing);
    return {magnitude * ux, magnitude * uy, magnitude * uz, ((live * damping) * closing) * closing, stretch};
}

// One triangle (corners a, b, c) per lane: the volume gradient (b-a)x(c-a)/6 that each corner
// gets, and x_a.(x_b x x_c) (six times the triangle's share of the volume).
template <class V>
struct TriangleLanes {
    V gx, gy, gz, volume6;
};
template <class V>
[[gnu::always_inline]] inline TriangleLanes<V> triangleLanes(V ax, V ay, V az, V bx, V by, V bz, V cx, V cy,
                                                             V cz) {
    const V six = splat<V>(6.0);
    const V ux = bx - ax, uy = by - ay, uz = bz - az;
    const V wx = cx - ax, wy = cy - ay, wz = cz - az;
    return {(uy * wz - uz * wy) / six, (uz * wx - ux * wz) / six, (ux * wy - uy * wx) / six,
            (ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz)) + az * (bx * cy - by * cx)};
}

// ---------------------------------------------------------------------------------------------
// Springs

// A block's spring sums in four lanes (spring k of the block in lane k mod 4) while they are
// accumulated.
struct SpringAccumulators {
    Vec4 power{};   // damping power
    Vec4 square{};  // (L - L0)^2
    int degenerate = 0;
};

// Springs [k, end) in groups of four from k into the accumulators; returns where it stopped
// (fewer than four left).
[[gnu::always_inline]] inline std::size_t springGroups(const SpringSet& springs, std::size_t k, std::size_t end,
                                                       double stiffness, double damping, const double* x, const double* v,
                                                       double* f4, SpringAccumulators& sums) {
    const int* ia = springs.a.data();
    const int* ib = springs.b.data();
    const Vec4 vStiffness = splat<Vec4>(stiffness), vDamping = splat<Vec4>(damping);
    Mask<Vec4> shortSprings{};
    for (; k + 4 <= end; k += 4) {
        Vec4 d[4], dv[4];
        for (std::size_t l = 0; l < 4; ++l) {
            const std::size_t i = index(ia[k + l]), j = index(ib[k + l]);
            d[l] = loadRow(x, j) - loadRow(x, i);
            dv[l] = loadRow(v, j) - loadRow(v, i);
        }
        Vec4 dx, dy, dz, dvx, dvy, dvz;
        toColumns(d[0], d[1], d[2], d[3], dx, dy, dz);
        toColumns(dv[0], dv[1], dv[2], dv[3], dvx, dvy, dvz);
        const SpringLanes<Vec4> lane =
            springLanes(dx, dy, dz, dvx, dvy, dvz, loadu<Vec4>(springs.rest.data() + k), vStiffness, vDamping, shortSprings);
        sums.power = sums.power + lane.power;
        sums.square = sums.square + lane.stretch * lane.stretch;
        Vec4 force[4];
        toRows(lane.fx, lane.fy, lane.fz, force);
        for (std::size_t l = 0; l < 4; ++l) {
            addRow(f4, index(ia[k + l]), force[l]);
            subRow(f4, index(ib[k + l]), force[l]);
        }
    }
    sums.degenerate += laneTotal(shortSprings);
    return k;
}

// The last springs [k, end) one at a time (like sumLanes, their sums go into lane 0 one by
// one), and the block's sums.
[[gnu::always_inline]] inline SpringSums finishSprings(const SpringSet& springs, std::size_t k, std::size_t end,
                                                       double stiffness, double damping, const double* x, const double* v,
                                                       double* f4, int& degenerate,
                                                       const SpringAccumulators& sums) {
    degenerate += sums.degenerate;
    double power[4], square[4];
    storeu(power, sums.power);
    storeu(square, sums.square);
    for (; k < end; ++k) {
        const std::size_t i = 3 * index(springs.a[k]), j = 3 * index(springs.b[k]);
        const SpringLanes<double> s =
            springLanes(x[j] - x[i], x[j + 1] - x[i + 1], x[j + 2] - x[i + 2], v[j] - v[i], v[j + 1] - v[i + 1],
                        v[j + 2] - v[i + 2], springs.rest[k], stiffness, damping, degenerate);
        power[0] += s.power;
        square[0] += s.stretch * s.stretch;
        double* fa = f4 + 4 * index(springs.a[k]);
        double* fb = f4 + 4 * index(springs.b[k]);
        fa[0] += s.fx;
        fa[1] += s.fy;
        fa[2] += s.fz;
        fb[0] -= s.fx;
        fb[1] -= s.fy;
        fb[2] -= s.fz;
    }
    return {(power[0] + power[1]) + (power[2] + power[3]), (square[0] + square[1]) + (square[2] + square[3])};
}

inline SpringSums springBlock(const SpringSet& springs, std::size_t begin, std::size_t end, double stiffness, double damping,
                              const double* x, const double* v, double* f4, int& degenerate) {
    SpringAccumulators sums;
    const std::size_t k = springGroups(springs, begin, end, stiffness, damping, x, v, f4, sums);
    return finishSprings(springs, k, end, stiffness, damping, x, v, f4, degenerate, sums);
}

// Springs [k, end) of a run (spring k joins particle first + (k - begin) and that + n) in
// groups of kLanes<V>, their end rows read as whole rows and transposed, into the
// accumulators (lanes 0-3, then 4-7); returns where it stopped.
template <class V>
[[gnu::always_inline]] inline std::size_t runGroups(const SpringSet& springs, std::size_t begin, std::size_t k,
                                                    std::size_t end, std::size_t n, double stiffness, double damping,
                                                    const double* x, const double* v, double* f4,
                                                    SpringAccumulators& sums) {
    constexpr std::size_t W = kLanes<V>;
    const V vStiffness = splat<V>(stiffness), vDamping = splat<V>(damping);
    Mask<V> shortSprings{};
    const std::size_t first = index(springs.a[begin]);
    for (; k + W <= end; k += W) {
        const std::size_t p = first + (k - begin), q = p + n;
        V ax, ay, az, bx, by, bz, avx, avy, avz, bvx, bvy, bvz;
        rowsToColumns(x + 3 * p, ax, ay, az);
        rowsToColumns(x + 3 * q, bx, by, bz);
        rowsToColumns(v + 3 * p, avx, avy, avz);
        rowsToColumns(v + 3 * q, bvx, bvy, bvz);
        const SpringLanes<V> lane = springLanes(bx - ax, by - ay, bz - az, bvx - avx, bvy - avy, bvz - avz,
                                                loadu<V>(springs.rest.data() + k), vStiffness, vDamping, shortSprings);
        sums.power = addLanes(sums.power, lane.power);
        sums.square = addLanes(sums.square, lane.stretch * lane.stretch);
        addSubRows(f4, p, q, lane.fx, lane.fy, lane.fz);
    }
    sums.degenerate += laneTotal(shortSprings);
    return k;
}

inline SpringSums springRunBlock(const SpringSet& springs, std::size_t begin, std::size_t end, int n, double stiffness,
                                 double damping, const double* x, const double* v, double* f4, int& degenerate) {
    SpringAccumulators sums;
    std::size_t k = runGroups<Widest>(springs, begin, begin, end, index(n), stiffness, damping, x, v, f4, sums);
    // Four at a time what is left of eight (nothing is left when Widest is Vec4).
    if (kLanes<Widest> > 4) k = runGroups<Vec4>(springs, begin, k, end, index(n), stiffness, damping, x, v, f4, sums);
    return finishSprings(springs, k, end, stiffness, damping, x, v, f4, degenerate, sums);
}

// ---------------------------------------------------------------------------------------------
// Edge quads

// kGroups<V> consecutive quads (one per group of four lanes), lanes (a, b), (A, B), (A, b),
// (B, a): their force row blocks (not yet added) and sums.
template <class V>
struct QuadGroup {
    std::size_t a[kGroups<V>], b[kGroups<V>];
    V fa, fb, fA, fB;  // added to a, subtracted from b, added to A and B
    V power, square;
};
template <class V>
[[gnu::always_inline]] inline QuadGroup<V> quadGroup(const QuadSet& quads, std::size_t q, const double* x,
                                                     const double* v, const double* xo, const double* vo, V stiffness,
                                                     V damping, Mask<V>& shortSprings) {
    // Outer particles through the outer layer's base pointers xo, vo: no index arithmetic
    // beyond each index's own scaling.
    QuadGroup<V> r;
    const double* rest[kGroups<V>];
    for (std::size_t g = 0; g < kGroups<V>; ++g) {
        r.a[g] = index(quads.a[q + g]);
        r.b[g] = index(quads.b[q + g]);
        rest[g] = quads.rest[q + g].data();
    }
    // (Inner rows by plain loads: a, b < n, so none is the array's last row.)
    const V xa = loadInnerRows<V>(x, r.a), xb = loadInnerRows<V>(x, r.b);
    const V xA = loadRows<V>(xo, r.a), xB = loadRows<V>(xo, r.b);
    const V va = loadInnerRows<V>(v, r.a), vb = loadInnerRows<V>(v, r.b);
    const V vA = loadRows<V>(vo, r.a), vB = loadRows<V>(vo, r.b);
    V dx, dy, dz, dvx, dvy, dvz;
    toColumns(xb - xa, xB - xA, xb - xA, xa - xB, dx, dy, dz);
    toColumns(vb - va, vB - vA, vb - vA, va - vB, dvx, dvy, dvz);
    const SpringLanes<V> lane = springLanes(dx, dy, dz, dvx, dvy, dvz, blockLanes<V>(rest), stiffness, damping, shortSprings);
    V F[4];  // F[j]: spring j's force rows
    toRows(lane.fx, lane.fy, lane.fz, F);
    r.fa = F[0] - F[3];
    r.fb = F[0] + F[2];
    r.fA = F[1] + F[2];
    r.fB = F[3] - F[1];
    r.power = lane.power;
    r.square = lane.stretch * lane.stretch;
    return r;
}
// A group's forces into f4 (inner rows) and fo (outer rows), quad by quad.
template <class V>
[[gnu::always_inline]] inline void addQuadGroup(const QuadGroup<V>& r, double* f4, double* fo) {
    for (std::size_t g = 0; g < kGroups<V>; ++g) {
        addRow(f4, r.a[g], rowOf(r.fa, g));
        subRow(f4, r.b[g], rowOf(r.fb, g));
        addRow(fo, r.a[g], rowOf(r.fA, g));
        addRow(fo, r.b[g], rowOf(r.fB, g));
    }
}

// Quads [q, end) in groups of kGroups<V>, two groups per iteration (both computed before
// either is added: independent chains of sqrt, divide and shuffles for the out-of-order core
// to overlap), then one more group if it fits; their lane sums added to the even and odd
// quads' four-lane sums. q - begin must be even. Returns where it stopped.
template <class V>
[[gnu::always_inline]] inline std::size_t quadGroups(const QuadSet& quads, std::size_t q, std::size_t end, int n,
                                                     std::array<double, 2> stiffness, std::array<double, 2> damping,
                                                     const double* x, const double* v, double* f4,
                                                     Vec4 (&power)[2], Vec4 (&square)[2], int& degenerate) {
    constexpr std::size_t G = kGroups<V>;
    constexpr std::size_t kParities = 2 / G;  // accumulators: a Vec4 per parity, or a Vec8 for both
    const double stiffnessLanes[4] = {stiffness[0], stiffness[0], stiffness[1], stiffness[1]}, dampingLanes[4] = {damping[0], damping[0], damping[1], damping[1]};
    const double* stiffnessFrom[2] = {stiffnessLanes, stiffnessLanes};
    const double* dampingFrom[2] = {dampingLanes, dampingLanes};
    const V vStiffness = blockLanes<V>(stiffnessFrom), vDamping = blockLanes<V>(dampingFrom);
    V powerAcc[kParities] = {}, squareAcc[kParities] = {};
    Mask<V> shortSprings{};
    const std::size_t outer = index(n);
    const double *xo = x + 3 * outer, *vo = v + 3 * outer;
    double* fo = f4 + 4 * outer;
    for (; q + 2 * G <= end; q += 2 * G) {
        const QuadGroup<V> first = quadGroup<V>(quads, q, x, v, xo, vo, vStiffness, vDamping, shortSprings);
        const QuadGroup<V> second = quadGroup<V>(quads, q + G, x, v, xo, vo, vStiffness, vDamping, shortSprings);
        powerAcc[0] = powerAcc[0] + first.power;
        squareAcc[0] = squareAcc[0] + first.square;
        powerAcc[kParities - 1] = powerAcc[kParities - 1] + second.power;
        squareAcc[kParities - 1] = squareAcc[kParities - 1] + second.square;
        addQuadGroup(first, f4, fo);
        addQuadGroup(second, f4, fo);
    }
    if (q + G <= end) {  // an even quad, or an even pair
        const QuadGroup<V> last = quadGroup<V>(quads, q, x, v, xo, vo, vStiffness, vDamping, shortSprings);
        powerAcc[0] = powerAcc[0] + last.power;
        squareAcc[0] = squareAcc[0] + last.square;
        addQuadGroup(last, f4, fo);
        q += G;
    }
    addParities(power, powerAcc);
    addParities(square, squareAcc);
    degenerate += laneTotal(shortSprings);
    return q;
}

inline QuadSums quadBlock(const QuadSet& quads, std::size_t begin, std::size_t end, int n,
                          std::array<double, 2> stiffness, std::array<double, 2> damping, const double* x, const double* v,
                          double* f4, int& degenerate) {
    Vec4 power[2] = {}, square[2] = {};
    std::size_t q = quadGroups<Widest>(quads, begin, end, n, stiffness, damping, x, v, f4, power, square, degenerate);
    // The last quad of an odd count four lanes wide (nothing is left when Widest is Vec4).
    if (q < end) quadGroups<Vec4>(quads, q, end, n, stiffness, damping, x, v, f4, power, square, degenerate);
    double p[2][4], s[2][4];
    for (std::size_t parity = 0; parity < 2; ++parity) {
        storeu(p[parity], power[parity]);
        storeu(s[parity], square[parity]);
    }
    return combineQuadLanes(p, s);
}

// ---------------------------------------------------------------------------------------------
// Triangles

// Triangles tri[0..3]: their gradients (rows, not yet added) and x_a.(x_b x x_c).
struct TriangleGroup {
    Vec4 gradient[4];
    Vec4 volume6;
};
[[gnu::always_inline]] inline TriangleGroup triangleGroup(const std::array<int, 3>* tri, const double* x) {
    Vec4 c[3][3];  // corner, axis
    for (std::size_t corner = 0; corner < 3; ++corner)
        toColumns(loadRow(x, index(tri[0][corner])), loadRow(x, index(tri[1][corner])),
                  loadRow(x, index(tri[2][corner])), loadRow(x, index(tri[3][corner])), c[corner][0], c[corner][1],
                  c[corner][2]);
    const TriangleLanes<Vec4> lane =
        triangleLanes(c[0][0], c[0][1], c[0][2], c[1][0], c[1][1], c[1][2], c[2][0], c[2][1], c[2][2]);
    TriangleGroup r;
    r.volume6 = lane.volume6;
    toRows(lane.gx, lane.gy, lane.gz, r.gradient);
    return r;
}
// A group's gradients added to its corners' rows, triangle by triangle.
[[gnu::always_inline]] inline void addTriangleGroup(const std::array<int, 3>* tri, const TriangleGroup& group,
                                                    double* g4) {
    for (std::size_t l = 0; l < 4; ++l)
        for (int corner : tri[l]) addRow(g4, index(corner), group.gradient[l]);
}

inline double triangleBlock(const Surface& surface, std::size_t begin, std::size_t end, const double* x,
                            double* g4) {
    const std::array<int, 3>* tri = surface.triangles.data() + begin;
    const std::size_t count = end - begin;
    Vec4 lanes{};  // x_a.(x_b x x_c), triangle k in lane k mod 4
    std::size_t k = 0;
    // Two groups per iteration, both computed before either is added.
    for (; k + 8 <= count; k += 8) {
        const TriangleGroup first = triangleGroup(tri + k, x), second = triangleGroup(tri + k + 4, x);
        lanes = (lanes + first.volume6) + second.volume6;
        addTriangleGroup(tri + k, first, g4);
        addTriangleGroup(tri + k + 4, second, g4);
    }
    if (k + 4 <= count) {
        const TriangleGroup last = triangleGroup(tri + k, x);
        lanes = lanes + last.volume6;
        addTriangleGroup(tri + k, last, g4);
        k += 4;
    }
    double lane[4];
    storeu(lane, lanes);
    // The last one to three triangles one at a time, into lane 0 one by one.
    for (; k < count; ++k) {
        const double* a = x + 3 * index(tri[k][0]);
        const double* b = x + 3 * index(tri[k][1]);
        const double* c = x + 3 * index(tri[k][2]);
        const TriangleLanes<double> t = triangleLanes(a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]);
        lane[0] += t.volume6;
        for (int corner : tri[k]) {
            double* g = g4 + 4 * index(corner);
            g[0] += t.gx;
            g[1] += t.gy;
            g[2] += t.gz;
        }
    }
    return (lane[0] + lane[1]) + (lane[2] + lane[3]);
}

// ---------------------------------------------------------------------------------------------
// The volume gradient per corner

// (e x f), lane by lane, the same expression as triangleLanes'.
template <class V>
[[gnu::always_inline]] inline void crossInto(V ex, V ey, V ez, V fx, V fy, V fz, V& cx, V& cy, V& cz) {
    cx = ey * fz - ez * fy;
    cy = ez * fx - ex * fz;
    cz = ex * fy - ey * fx;
}

// One particle alone (any fan): its row of g4 and x_v . G, where G = sum of the fan's
// (p - x_v) x (q - x_v) taken in order (the first term alone, then each added).
inline double vertexGradient(const VertexFans& fans, std::size_t v, const double* x, double* g4) {
    const double* pv = x + 3 * v;
    const std::array<int, 2>* pair = fans.pair.data();
    double gx = 0.0, gy = 0.0, gz = 0.0;
    for (int k = fans.start[v]; k < fans.start[v + 1]; ++k) {
        const double* p = x + 3 * index(pair[k][0]);
        const double* q = x + 3 * index(pair[k][1]);
        double cx, cy, cz;
        crossInto(p[0] - pv[0], p[1] - pv[1], p[2] - pv[2], q[0] - pv[0], q[1] - pv[1], q[2] - pv[2], cx, cy, cz);
        if (k == fans.start[v]) {
            gx = cx, gy = cy, gz = cz;
        } else {
            gx = gx + cx, gy = gy + cy, gz = gz + cz;
        }
    }
    double* g = g4 + 4 * v;
    g[0] = gx / 6.0;
    g[1] = gy / 6.0;
    g[2] = gz / 6.0;
    g[3] = 0.0;
    return (pv[0] * gx + pv[1] * gy) + pv[2] * gz;
}

inline double vertexGradients(const VertexFans& fans, int begin, int end, const double* x, double* g4) {
    const std::size_t first = index(begin), last = index(end);
    const std::uint8_t* ring6 = fans.ring6.data();
    const int* start = fans.start.data();
    const std::array<int, 2>* pair = fans.pair.data();
    const Vec4 six = splat<Vec4>(6.0);
    Vec4 lanes{};  // x_v . G, particle first + k in lane k mod 4
    std::size_t v = first;
    for (; v + 4 <= last; v += 4) {
        if (!(ring6[v] & ring6[v + 1] & ring6[v + 2] & ring6[v + 3])) {
            // A particle of the four has another fan: all four alone, in the same lanes.
            double d[4];
            for (std::size_t l = 0; l < 4; ++l) d[l] = vertexGradient(fans, v + l, x, g4);
            lanes = lanes + loadu<Vec4>(d);
            continue;
        }
        // Four particles, one per lane, each with a closed ring of six: the ring's neighbours
        // loaded once each (as p of one pair and q of the one before).
        Vec4 px, py, pz;
        rowsToColumns(x + 3 * v, px, py, pz);
        const std::array<int, 2>* r[4] = {pair + start[v], pair + start[v + 1], pair + start[v + 2], pair + start[v + 3]};
        Vec4 ex[6], ey[6], ez[6];
        for (std::size_t k = 0; k < 6; ++k) {
            Vec4 nx, ny, nz;
            toColumns(loadRow(x, index(r[0][k][0])), loadRow(x, index(r[1][k][0])), loadRow(x, index(r[2][k][0])),
                      loadRow(x, index(r[3][k][0])), nx, ny, nz);
            ex[k] = nx - px, ey[k] = ny - py, ez[k] = nz - pz;
        }
        Vec4 gx, gy, gz;
        crossInto(ex[0], ey[0], ez[0], ex[1], ey[1], ez[1], gx, gy, gz);
        for (std::size_t k = 1; k < 6; ++k) {
            const std::size_t next = k + 1 == 6 ? 0 : k + 1;
            Vec4 cx, cy, cz;
            crossInto(ex[k], ey[k], ez[k], ex[next], ey[next], ez[next], cx, cy, cz);
            gx = gx + cx, gy = gy + cy, gz = gz + cz;
        }
        lanes = lanes + ((px * gx + py * gy) + pz * gz);
        Vec4 rows[4];
        toRows(gx / six, gy / six, gz / six, rows);
        for (std::size_t l = 0; l < 4; ++l) storeu(g4 + 4 * (v + l), rows[l]);
    }
    double lane[4];
    storeu(lane, lanes);
    for (std::size_t l = 0; v < last; ++v, ++l) lane[l] += vertexGradient(fans, v, x, g4);
    return (lane[0] + lane[1]) + (lane[2] + lane[3]);
}

// ---------------------------------------------------------------------------------------------
// Unpadding

inline void unpad(const double* f4, const double* g4, double p, const double* invMass3, int begin, int end,
                  double* out) {
    // Four doubles are stored per particle; the fourth lands on the next particle's x, which
    // is written right after. The last particle of the range is done double by double (its
    // fourth double belongs to another range, or lies beyond the array).
    const Vec4 vp = splat<Vec4>(p);
    int i = begin;
    for (; i + 1 < end; ++i) {
        const std::size_t row = index(i);
        Vec4 f = loadPadded(f4, row);
        if (g4) f = f + vp * loadPadded(g4, row);
        if (invMass3) f = f * loadRow(invMass3, row);
        storeu(out + 3 * row, f);
    }
    for (; i < end; ++i)
        for (std::size_t axis = 0; axis < 3; ++axis) {
            const std::size_t k = 3 * index(i) + axis;
            const double f = g4 ? f4[4 * index(i) + axis] + p * g4[4 * index(i) + axis] : f4[4 * index(i) + axis];
            out[k] = invMass3 ? f * invMass3[k] : f;
        }
}

// ---------------------------------------------------------------------------------------------
// Stage sums

inline void stageSum(double* out, const double* y, double c, const double* k, std::size_t n) {
    const Widest vc = splat<Widest>(c);
    constexpr std::size_t W = kLanes<Widest>;
    std::size_t i = 0;
    for (; i + W <= n; i += W) storeu(out + i, loadu<Widest>(y + i) + vc * loadu<Widest>(k + i));
    for (; i < n; ++i) out[i] = y[i] + c * k[i];
}

inline void rk4Sum(double* y, double h6, const double* k1, const double* k2, const double* k3, const double* k4,
                   std::size_t n) {
    const Widest vh = splat<Widest>(h6), two = splat<Widest>(2.0);
    constexpr std::size_t W = kLanes<Widest>;
    std::size_t i = 0;
    for (; i + W <= n; i += W) {
        const Widest sum = ((loadu<Widest>(k1 + i) + two * loadu<Widest>(k2 + i)) + two * loadu<Widest>(k3 + i)) +
                           loadu<Widest>(k4 + i);
        storeu(y + i, loadu<Widest>(y + i) + vh * sum);
    }
    for (; i < n; ++i) y[i] = y[i] + h6 * (((k1[i] + 2.0 * k2[i]) + 2.0 * k3[i]) + k4[i]);
}

}  // namespace simcore::kernels::SIMCORE_SIMD_NS
