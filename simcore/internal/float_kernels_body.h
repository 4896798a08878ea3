// The float path's wide kernels (simcore/float_path.cpp), written once for both widths and
// included twice there: with SIMCORE_FLOAT_WIDTH 8 under `#pragma GCC target("avx2")` inside
// namespace avx2 (eight lanes: two quads, eight springs, faces or face pairs per register) and
// with SIMCORE_FLOAT_WIDTH 16 under `#pragma GCC target("avx512f,avx2")` inside namespace
// avx512 (sixteen lanes: four quads per register). No include guard on purpose.
//
// Each kernel is the scalar code's operations lane for lane (float_path.cpp: springForce,
// quadScalar, faceScalar, facePairScalar; no fused multiply-add: simcore builds with
// -ffp-contract=off, and + - * / on the vector types are the plain IEEE operations), and
// adds its results to the rows one spring, quad, face or pair at a time in the scalar order,
// so every width gives the same bits (a spring's end difference is one subtraction per
// component whether taken on rows before the transpose, as the quads and springs do since stop
// 45, or on columns after). The lane sums (eight double lanes) see their elements in
// the scalar order: element k of a block goes to lane (k - begin) % 8, the first eight of a
// block of sixteen before the last eight. A block's rest goes to the narrower code (sixteen to
// eight, eight to the scalar functions), whose lanes are the same because the rest begins a
// multiple of the width after `begin`.
//
// The includer provides, in the enclosing namespace: LaneSums, SpringArrays, QuadArrays,
// springScalar, quadScalar, faceScalar, facePairScalar, and for width 16 the width-8 copy in
// namespace avx2.

#if SIMCORE_FLOAT_WIDTH == 8
using V = __m256;
#elif SIMCORE_FLOAT_WIDTH == 16
using V = __m512;
#else
#error "SIMCORE_FLOAT_WIDTH must be 8 or 16"
#endif
constexpr int kWidth = SIMCORE_FLOAT_WIDTH;

[[gnu::always_inline]] inline V splat(float s) {
#if SIMCORE_FLOAT_WIDTH == 8
    return _mm256_set1_ps(s);
#else
    return _mm512_set1_ps(s);
#endif
}
[[gnu::always_inline]] inline V load(const float* p) {
#if SIMCORE_FLOAT_WIDTH == 8
    return _mm256_loadu_ps(p);
#else
    return _mm512_loadu_ps(p);
#endif
}
[[gnu::always_inline]] inline V squareRoot(V v) {
#if SIMCORE_FLOAT_WIDTH == 8
    return _mm256_sqrt_ps(v);
#else
    return _mm512_sqrt_ps(v);
#endif
}
// value where len >= bound, else +0 (the scalar code's `ok ? value : 0.0f`).
[[gnu::always_inline]] inline V whereAtLeast(V len, V bound, V value) {
#if SIMCORE_FLOAT_WIDTH == 8
    return _mm256_and_ps(_mm256_cmp_ps(len, bound, _CMP_GE_OQ), value);
#else
    return _mm512_maskz_mov_ps(_mm512_cmp_ps_mask(len, bound, _CMP_GE_OQ), value);
#endif
}
// a[0..3] repeated over the register.
[[gnu::always_inline]] inline V repeat4(const std::array<float, 4>& a) {
    alignas(64) float lanes[kWidth];
    for (int l = 0; l < kWidth; ++l) lanes[l] = a[static_cast<std::size_t>(l % 4)];
    return load(lanes);
}

// Rows of kWidth particles (rows idx[0..kWidth-1] of p) in four registers: 128-bit lane j of
// register k holds row 4 j + k (width 8: rows k and k + 4).
[[gnu::always_inline]] inline void gatherRows(const float* p, const int* idx, V* r) {
    auto at = [&](int k) __attribute__((always_inline)) {
        return _mm_loadu_ps(p + 4 * static_cast<std::ptrdiff_t>(idx[k]));
    };
    for (int k = 0; k < 4; ++k) {
#if SIMCORE_FLOAT_WIDTH == 8
        r[k] = _mm256_insertf128_ps(_mm256_castps128_ps256(at(k)), at(k + 4), 1);
#else
        __m512 g = _mm512_castps128_ps512(at(k));
        g = _mm512_insertf32x4(g, at(k + 4), 1);
        g = _mm512_insertf32x4(g, at(k + 8), 2);
        r[k] = _mm512_insertf32x4(g, at(k + 12), 3);
#endif
    }
}

// Four registers of rows (as gatherRows') transposed in each 128-bit lane to x, y, z columns:
// lane 4 j + k of a column is row k of 128-bit lane j.
[[gnu::always_inline]] inline void columnsOf(const V* r, V& cx, V& cy, V& cz) {
#if SIMCORE_FLOAT_WIDTH == 8
    const V t0 = _mm256_unpacklo_ps(r[0], r[1]), t1 = _mm256_unpackhi_ps(r[0], r[1]);
    const V t2 = _mm256_unpacklo_ps(r[2], r[3]), t3 = _mm256_unpackhi_ps(r[2], r[3]);
    cx = _mm256_shuffle_ps(t0, t2, 0x44);
    cy = _mm256_shuffle_ps(t0, t2, 0xEE);
    cz = _mm256_shuffle_ps(t1, t3, 0x44);
#else
    const V t0 = _mm512_unpacklo_ps(r[0], r[1]), t1 = _mm512_unpackhi_ps(r[0], r[1]);
    const V t2 = _mm512_unpacklo_ps(r[2], r[3]), t3 = _mm512_unpackhi_ps(r[2], r[3]);
    cx = _mm512_shuffle_ps(t0, t2, 0x44);
    cy = _mm512_shuffle_ps(t0, t2, 0xEE);
    cz = _mm512_shuffle_ps(t1, t3, 0x44);
#endif
}

// The x, y, z columns of kWidth particles' rows (rows idx[0..kWidth-1] of p; lane l is row
// idx[l]).
[[gnu::always_inline]] inline void columns(const float* p, const int* idx, V& cx, V& cy, V& cz) {
    V r[4];
    gatherRows(p, idx, r);
    columnsOf(r, cx, cy, cz);
}

// The columns of the differences row(second[l]) - row(first[l]), subtracted as rows (the same
// operation per component as in columns, with no permutation of the columns after).
[[gnu::always_inline]] inline void differenceColumns(const float* p, const int* first, const int* second, V& cx, V& cy, V& cz) {
    V from[4], to[4];
    gatherRows(p, first, from);
    gatherRows(p, second, to);
    for (int k = 0; k < 4; ++k) to[k] = to[k] - from[k];
    columnsOf(to, cx, cy, cz);
}

// Three columns back to rows (x, y, z, 0) in four registers, as gatherRows lays them out.
[[gnu::always_inline]] inline void rowRegisters(V cx, V cy, V cz, V* r) {
#if SIMCORE_FLOAT_WIDTH == 8
    const V zero = _mm256_setzero_ps();
    const V t0 = _mm256_unpacklo_ps(cx, cy), t1 = _mm256_unpackhi_ps(cx, cy);
    const V t2 = _mm256_unpacklo_ps(cz, zero), t3 = _mm256_unpackhi_ps(cz, zero);
    r[0] = _mm256_shuffle_ps(t0, t2, 0x44);
    r[1] = _mm256_shuffle_ps(t0, t2, 0xEE);
    r[2] = _mm256_shuffle_ps(t1, t3, 0x44);
    r[3] = _mm256_shuffle_ps(t1, t3, 0xEE);
#else
    const V zero = _mm512_setzero_ps();
    const V t0 = _mm512_unpacklo_ps(cx, cy), t1 = _mm512_unpackhi_ps(cx, cy);
    const V t2 = _mm512_unpacklo_ps(cz, zero), t3 = _mm512_unpackhi_ps(cz, zero);
    r[0] = _mm512_shuffle_ps(t0, t2, 0x44);
    r[1] = _mm512_shuffle_ps(t0, t2, 0xEE);
    r[2] = _mm512_shuffle_ps(t1, t3, 0x44);
    r[3] = _mm512_shuffle_ps(t1, t3, 0xEE);
#endif
}

// The 128-bit rows of four registers: out[4 j + k] is lane j of r[k].
[[gnu::always_inline]] inline void split(const V* r, __m128* out) {
    for (int k = 0; k < 4; ++k) {
#if SIMCORE_FLOAT_WIDTH == 8
        out[k] = _mm256_castps256_ps128(r[k]);
        out[4 + k] = _mm256_extractf128_ps(r[k], 1);
#else
        out[k] = _mm512_castps512_ps128(r[k]);
        out[4 + k] = _mm512_extractf32x4_ps(r[k], 1);
        out[8 + k] = _mm512_extractf32x4_ps(r[k], 2);
        out[12 + k] = _mm512_extractf32x4_ps(r[k], 3);
#endif
    }
}

// kWidth rows (x, y, z, 0) from three columns: rows[j] is lane j's.
[[gnu::always_inline]] inline void rows(V cx, V cy, V cz, __m128* out) {
    V r[4];
    rowRegisters(cx, cy, cz, r);
    split(r, out);
}

[[gnu::always_inline]] inline void addRow128(float* f4, int i, __m128 r) {
    float* p = f4 + 4 * static_cast<std::ptrdiff_t>(i);
    _mm_storeu_ps(p, _mm_add_ps(_mm_loadu_ps(p), r));
}
[[gnu::always_inline]] inline void subRow128(float* f4, int i, __m128 r) {
    float* p = f4 + 4 * static_cast<std::ptrdiff_t>(i);
    _mm_storeu_ps(p, _mm_sub_ps(_mm_loadu_ps(p), r));
}

// The eight double lanes of a LaneSums in registers: add(v) adds v's first eight elements to
// lanes 0-7, then (width 16) its last eight.
struct Lanes {
#if SIMCORE_FLOAT_WIDTH == 8
    __m256d lo, hi;
    explicit Lanes(const LaneSums& sums) : lo(_mm256_loadu_pd(sums.lane.data())), hi(_mm256_loadu_pd(sums.lane.data() + 4)) {}
    void add(V v) {
        lo = _mm256_add_pd(lo, _mm256_cvtps_pd(_mm256_castps256_ps128(v)));
        hi = _mm256_add_pd(hi, _mm256_cvtps_pd(_mm256_extractf128_ps(v, 1)));
    }
    // Two registers whose element k belong together: lane l takes first[l], then second[l].
    void addPair(V first, V second) {
        add(first);
        add(second);
    }
    void store(LaneSums& sums) const {
        _mm256_storeu_pd(sums.lane.data(), lo);
        _mm256_storeu_pd(sums.lane.data() + 4, hi);
    }
#else
    __m512d sum;
    explicit Lanes(const LaneSums& sums) : sum(_mm512_loadu_pd(sums.lane.data())) {}
    static __m512d half(V v, int h) {
        return _mm512_cvtps_pd(h == 0 ? _mm512_castps512_ps256(v) : _mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(v), 1)));
    }
    void add(V v) {
        sum = _mm512_add_pd(sum, half(v, 0));
        sum = _mm512_add_pd(sum, half(v, 1));
    }
    // Lane l takes first[l], second[l], then first[l + 8], second[l + 8].
    void addPair(V first, V second) {
        sum = _mm512_add_pd(sum, half(first, 0));
        sum = _mm512_add_pd(sum, half(second, 0));
        sum = _mm512_add_pd(sum, half(first, 1));
        sum = _mm512_add_pd(sum, half(second, 1));
    }
    void store(LaneSums& sums) const { _mm512_storeu_pd(sums.lane.data(), sum); }
#endif
};

// kWidth springs' forces (0 where degenerate) and damping powers from their end differences d
// (positions) and w (velocities): springForce's operations.
struct SpringForces {
    V fx, fy, fz, power;
};
[[gnu::always_inline]] inline SpringForces springForces(V dx, V dy, V dz, V wx, V wy, V wz, V stiffness, V damping, V rest) {
    const V len2 = (dx * dx + dy * dy) + dz * dz;
    const V len = squareRoot(len2);
    const V inv = len * (splat(1.0f) / len2);
    const V dvu = ((wx * dx + wy * dy) + wz * dz) * inv;
    const V scale = (stiffness * (len - rest) + damping * dvu) * inv;
    const V bound = splat(static_cast<float>(kDegenerateLength));
    return {whereAtLeast(len, bound, scale * dx), whereAtLeast(len, bound, scale * dy), whereAtLeast(len, bound, scale * dz),
            whereAtLeast(len, bound, (damping * dvu) * dvu)};
}

void springs(const SpringArrays& s, std::size_t begin, std::size_t end, float stiffnessScalar, float dampingScalar, const float* x,
             const float* v, float* f4, LaneSums& power) {
    const V stiffness = splat(stiffnessScalar), damping = splat(dampingScalar);
    Lanes sums(power);
    std::size_t k = begin;
    for (; k + kWidth <= end; k += kWidth) {
        const int* ia = s.a.data() + k;
        const int* ib = s.b.data() + k;
        V dx, dy, dz, wx, wy, wz;
        differenceColumns(x, ia, ib, dx, dy, dz);
        differenceColumns(v, ia, ib, wx, wy, wz);
        const SpringForces f = springForces(dx, dy, dz, wx, wy, wz, stiffness, damping, load(s.rest.data() + k));
        __m128 r[kWidth];
        rows(f.fx, f.fy, f.fz, r);
        for (int j = 0; j < kWidth; ++j) {
            addRow128(f4, ia[j], r[j]);
            subRow128(f4, ib[j], r[j]);
        }
        sums.add(f.power);
    }
    sums.store(power);
#if SIMCORE_FLOAT_WIDTH == 16
    avx2::springs(s, k, end, stiffnessScalar, dampingScalar, x, v, f4, power);
#else
    for (; k < end; ++k) springScalar(s, begin, k, stiffnessScalar, dampingScalar, x, v, f4, power);
#endif
}

// kWidth / 4 quads per register (lanes 4 j .. 4 j + 3: quad q + j's springs in quadScalar's
// order), two such groups computed before either is added, so that the core overlaps their
// square root and division chains; the rows are still updated quad by quad in order.
void quads(const QuadArrays& set, std::size_t begin, std::size_t end, int n, const std::array<float, 4>& stiffness4,
           const std::array<float, 4>& damping4, const float* x, const float* v, float* f4, LaneSums& power) {
    constexpr std::size_t perGroup = kWidth / 4;
    const V stiffness = repeat4(stiffness4), damping = repeat4(damping4);
    Lanes sums(power);
    // One group: its particles (a, b, A, B per quad) and their row updates.
    struct Group {
        int ids[kWidth];
        V corner[4];  // per corner (a, b, A, B): 128-bit lane j is quad q + j's row
        V power;
    };
    auto compute = [&](std::size_t q, Group& g) __attribute__((always_inline)) {
        // Lane 4 j + l: spring l of quad q + j, from first ends (a, A, A, B) to second ends
        // (b, B, b, a).
        int first[kWidth], second[kWidth];
        for (std::size_t j = 0; j < perGroup; ++j) {
            const int a = set.a[q + j], b = set.b[q + j];
            g.ids[4 * j] = a;
            g.ids[4 * j + 1] = b;
            g.ids[4 * j + 2] = a + n;
            g.ids[4 * j + 3] = b + n;
            const int from[4] = {a, a + n, a + n, b + n}, to[4] = {b, b + n, b, a};
            for (std::size_t l = 0; l < 4; ++l) {
                first[4 * j + l] = from[l];
                second[4 * j + l] = to[l];
            }
        }
        V DX, DY, DZ, WX, WY, WZ;
        differenceColumns(x, first, second, DX, DY, DZ);
        differenceColumns(v, first, second, WX, WY, WZ);
        const SpringForces f = springForces(DX, DY, DZ, WX, WY, WZ, stiffness, damping, load(set.rest.data() + 4 * q));
        // The four springs' rows of each quad, then per corner (a, b, A, B): F0 - F3, F0 + F2,
        // F1 + F2, F3 - F1 (quadScalar's sums), as rows.
        V r[4];
        rowRegisters(f.fx, f.fy, f.fz, r);
        g.corner[0] = r[0] - r[3];
        g.corner[1] = r[0] + r[2];
        g.corner[2] = r[1] + r[2];
        g.corner[3] = r[3] - r[1];
        g.power = f.power;
    };
    auto apply = [&](const Group& g) __attribute__((always_inline)) {
        // Each row read from the group's memory (a load, not an extraction: the shuffle port is
        // the kernel's busiest).
        auto row = [&](int corner, std::size_t j) __attribute__((always_inline)) {
            return _mm_loadu_ps(reinterpret_cast<const float*>(&g.corner[corner]) + 4 * j);
        };
        for (std::size_t j = 0; j < perGroup; ++j) {
            addRow128(f4, g.ids[4 * j], row(0, j));
            subRow128(f4, g.ids[4 * j + 1], row(1, j));
            addRow128(f4, g.ids[4 * j + 2], row(2, j));
            addRow128(f4, g.ids[4 * j + 3], row(3, j));
        }
        sums.add(g.power);
    };
    std::size_t q = begin;
    Group g1, g2;
    for (; q + 2 * perGroup <= end; q += 2 * perGroup) {
        compute(q, g1);
        compute(q + perGroup, g2);
        apply(g1);
        apply(g2);
    }
    for (; q + perGroup <= end; q += perGroup) {
        compute(q, g1);
        apply(g1);
    }
    sums.store(power);
    for (; q < end; ++q) quadScalar(set, begin, q, n, stiffness4, damping4, x, v, f4, power);
}

[[gnu::always_inline]] inline void cross(V ex, V ey, V ez, V hx, V hy, V hz, V& gx, V& gy, V& gz) {
    gx = ey * hz - ez * hy;
    gy = ez * hx - ex * hz;
    gz = ex * hy - ey * hx;
}
[[gnu::always_inline]] inline V dot(V ax, V ay, V az, V gx, V gy, V gz) { return (ax * gx + ay * gy) + az * gz; }

// corners: the faces' corner indices as three columns (a, b, c) of `stride` each.
void faces(const std::vector<std::array<int, 3>>& list, const int* corners, std::size_t stride, std::size_t begin,
           std::size_t end, const float* x, float* g4, LaneSums& volume) {
    Lanes sums(volume);
    std::size_t k = begin;
    for (; k + kWidth <= end; k += kWidth) {
        const int* ia = corners + k;
        const int* ib = corners + stride + k;
        const int* ic = corners + 2 * stride + k;
        V ax, ay, az, bx, by, bz, cx, cy, cz, gx, gy, gz;
        columns(x, ia, ax, ay, az);
        columns(x, ib, bx, by, bz);
        columns(x, ic, cx, cy, cz);
        cross(bx - ax, by - ay, bz - az, cx - ax, cy - ay, cz - az, gx, gy, gz);
        __m128 r[kWidth];
        rows(gx, gy, gz, r);
        for (int j = 0; j < kWidth; ++j) {
            addRow128(g4, ia[j], r[j]);
            addRow128(g4, ib[j], r[j]);
            addRow128(g4, ic[j], r[j]);
        }
        sums.add(dot(ax, ay, az, gx, gy, gz));
    }
    sums.store(volume);
#if SIMCORE_FLOAT_WIDTH == 16
    avx2::faces(list, corners, stride, k, end, x, g4, volume);
#else
    for (; k < end; ++k) faceScalar(list, 3, begin, k, x, g4, volume);
#endif
}

// kWidth face pairs at a time (facePairScalar's operations); corners: four columns (a, b, c, d)
// of `stride` each.
void facePairs(const int* corners, std::size_t stride, std::size_t begin, std::size_t end, const float* x, float* g4,
               LaneSums& volume) {
    Lanes sums(volume);
    std::size_t k = begin;
    for (; k + kWidth <= end; k += kWidth) {
        const int* ia = corners + k;
        const int* ib = corners + stride + k;
        const int* ic = corners + 2 * stride + k;
        const int* id = corners + 3 * stride + k;
        V ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz;
        columns(x, ia, ax, ay, az);
        columns(x, ib, bx, by, bz);
        columns(x, ic, cx, cy, cz);
        columns(x, id, dx, dy, dz);
        V g1x, g1y, g1z, g2x, g2y, g2z;
        cross(bx - ax, by - ay, bz - az, cx - ax, cy - ay, cz - az, g1x, g1y, g1z);
        cross(ax - bx, ay - by, az - bz, dx - bx, dy - by, dz - bz, g2x, g2y, g2z);
        __m128 rows1[kWidth], rows2[kWidth];
        rows(g1x, g1y, g1z, rows1);
        rows(g2x, g2y, g2z, rows2);
        for (int j = 0; j < kWidth; ++j) {
            const __m128 both = _mm_add_ps(rows1[j], rows2[j]);
            addRow128(g4, ia[j], both);
            addRow128(g4, ib[j], both);
            addRow128(g4, ic[j], rows1[j]);
            addRow128(g4, id[j], rows2[j]);
        }
        sums.addPair(dot(ax, ay, az, g1x, g1y, g1z), dot(bx, by, bz, g2x, g2y, g2z));
    }
    sums.store(volume);
#if SIMCORE_FLOAT_WIDTH == 16
    avx2::facePairs(corners, stride, k, end, x, g4, volume);
#else
    for (; k < end; ++k) facePairScalar(corners, stride, begin, k, x, g4, volume);
#endif
}
