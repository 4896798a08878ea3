// simcore's wide-vector layer (internal to simcore; only force_kernels.cpp includes it).
//
// Deliberately without an include guard: force_kernels.cpp includes it once per instruction
// set, each time inside a `#pragma GCC target` region and with
//   SIMCORE_SIMD_ISA  0 (generic: GCC vector extensions only, no intrinsics), 2 (AVX2) or
//                     3 (AVX-512F with AVX2),
//   SIMCORE_SIMD_NS   the namespace this copy goes into (simcore::simd::<ns>),
// so that every copy's functions carry that set's target and no two copies share a name.
//
// Vec4 and Vec8 are GCC vector types of four and eight doubles: + - * / and comparisons work
// lane by lane with the operators (each operation rounded alone: simcore builds with
// -ffp-contract=off, so never a fused multiply-add), on any target GCC supports (SSE2 pairs on
// baseline x86-64, NEON on AArch64). What the operators cannot say is here: square root,
// loads of 3-double rows, and the transposes between particle rows (x, y, z[, 0]) and lane
// columns; those have a generic version and, where it pays, an AVX2 or AVX-512 one. Every
// version computes the same numbers: a transpose only moves doubles, and sqrt is correctly
// rounded everywhere.
//
// Kernels are written once over these (force_kernels_body.h); the widest vector a set has is
// `Widest` (Vec8 for AVX-512, else Vec4). Vec8 and its helpers exist only in the AVX-512 copy.

#ifndef SIMCORE_SIMD_ISA
#error "simd.h is included by force_kernels.cpp with SIMCORE_SIMD_ISA and SIMCORE_SIMD_NS defined"
#endif

namespace simcore::simd::SIMCORE_SIMD_NS {

// (Plain vector types, not __m256d: its may_alias attribute would be dropped as a template
// argument.)
using Vec4 = double __attribute__((vector_size(32)));
using Vec8 = double __attribute__((vector_size(64)));
#if SIMCORE_SIMD_ISA >= 3
using Widest = Vec8;
#else
using Widest = Vec4;
#endif

// A padded particle row (x, y, z, 0) in place: 32-byte aligned, and it may alias the doubles
// around it (as __m256d may).
using Row = double __attribute__((vector_size(32), may_alias, aligned(32)));

template <class V>
inline constexpr std::size_t kLanes = sizeof(V) / sizeof(double);

// Per-lane comparison results: all ones (-1) where true.
template <class V>
using Mask = decltype(V{} < V{});

template <class V>
[[gnu::always_inline]] inline V splat(double s) {
    if constexpr (std::is_same_v<V, double>) {
        return s;
    } else {
        V r;
        for (std::size_t l = 0; l < kLanes<V>; ++l) r[l] = s;
        return r;
    }
}
template <class V>
[[gnu::always_inline]] inline V loadu(const double* p) {
    V r;
    std::memcpy(&r, p, sizeof r);
    return r;
}
template <class V>
[[gnu::always_inline]] inline void storeu(double* p, V v) {
    std::memcpy(p, &v, sizeof v);
}

// Adds (subtracts) a row into padded row p of f4.
[[gnu::always_inline]] inline void addRow(double* f4, std::size_t p, Vec4 row) {
    Row* at = reinterpret_cast<Row*>(f4 + 4 * p);
    *at = *at + row;
}
[[gnu::always_inline]] inline void subRow(double* f4, std::size_t p, Vec4 row) {
    Row* at = reinterpret_cast<Row*>(f4 + 4 * p);
    *at = *at - row;
}
[[gnu::always_inline]] inline Vec4 loadPadded(const double* f4, std::size_t p) {
    return *reinterpret_cast<const Row*>(f4 + 4 * p);
}

// Counts true lanes of a comparison into per-lane counters (or a bool into an int: the same
// code over V = double, for the last few elements of a block).
template <class M>
[[gnu::always_inline]] inline void countTrue(M& count, M isTrue) {
    count -= isTrue;
}
[[gnu::always_inline]] inline void countTrue(int& count, bool isTrue) { count += isTrue; }
template <class M>
[[gnu::always_inline]] inline int laneTotal(M count) {
    long long total = 0;
    for (std::size_t l = 0; l < sizeof(M) / sizeof(long long); ++l) total += count[l];
    return static_cast<int>(total);
}

[[gnu::always_inline]] inline double sqrt(double v) { return __builtin_sqrt(v); }

#if SIMCORE_SIMD_ISA == 0
// ---------------------------------------------------------------------------------------------
// Generic: GCC lowers these element moves to the target's shuffles.

[[gnu::always_inline]] inline Vec4 sqrt(Vec4 v) {
    return Vec4{__builtin_sqrt(v[0]), __builtin_sqrt(v[1]), __builtin_sqrt(v[2]), __builtin_sqrt(v[3])};
}

// (x, y, z, 0) of particle p from a 3-per-particle array; the fourth double is not read.
[[gnu::always_inline]] inline Vec4 loadRow(const double* a, std::size_t p) {
    const double* r = a + 3 * p;
    return Vec4{r[0], r[1], r[2], 0.0};
}

// Four rows to three columns X = (x0 x1 x2 x3) and so on (the fourth doubles are ignored).
[[gnu::always_inline]] inline void toColumns(Vec4 r0, Vec4 r1, Vec4 r2, Vec4 r3, Vec4& X, Vec4& Y, Vec4& Z) {
    X = Vec4{r0[0], r1[0], r2[0], r3[0]};
    Y = Vec4{r0[1], r1[1], r2[1], r3[1]};
    Z = Vec4{r0[2], r1[2], r2[2], r3[2]};
}

// Three columns to four rows (x, y, z, 0).
[[gnu::always_inline]] inline void toRows(Vec4 X, Vec4 Y, Vec4 Z, Vec4 (&r)[4]) {
    for (int l = 0; l < 4; ++l) r[l] = Vec4{X[l], Y[l], Z[l], 0.0};
}

// Four consecutive rows (x, y, z) of a 3-per-particle array (12 doubles) to columns.
[[gnu::always_inline]] inline void rowsToColumns(const double* at, Vec4& X, Vec4& Y, Vec4& Z) {
    X = Vec4{at[0], at[3], at[6], at[9]};
    Y = Vec4{at[1], at[4], at[7], at[10]};
    Z = Vec4{at[2], at[5], at[8], at[11]};
}

#else
// ---------------------------------------------------------------------------------------------
// AVX2 (also in the AVX-512 copy, for its four-lane kernels)

[[gnu::always_inline]] inline Vec4 sqrt(Vec4 v) { return _mm256_sqrt_pd(v); }

[[gnu::always_inline]] inline Vec4 loadRow(const double* a, std::size_t p) {
    return _mm256_maskload_pd(a + 3 * p, _mm256_setr_epi64x(-1, -1, -1, 0));
}

[[gnu::always_inline]] inline void toColumns(Vec4 r0, Vec4 r1, Vec4 r2, Vec4 r3, Vec4& X, Vec4& Y, Vec4& Z) {
    const __m256d t0 = _mm256_unpacklo_pd(r0, r1);  // x0 x1 z0 z1
    const __m256d t1 = _mm256_unpackhi_pd(r0, r1);  // y0 y1 w0 w1
    const __m256d t2 = _mm256_unpacklo_pd(r2, r3);  // x2 x3 z2 z3
    const __m256d t3 = _mm256_unpackhi_pd(r2, r3);  // y2 y3 w2 w3
    X = _mm256_permute2f128_pd(t0, t2, 0x20);
    Y = _mm256_permute2f128_pd(t1, t3, 0x20);
    Z = _mm256_permute2f128_pd(t0, t2, 0x31);
}

[[gnu::always_inline]] inline void toRows(Vec4 X, Vec4 Y, Vec4 Z, Vec4 (&r)[4]) {
    const __m256d zero = _mm256_setzero_pd();
    const __m256d t0 = _mm256_unpacklo_pd(X, Y);     // x0 y0 x2 y2
    const __m256d t1 = _mm256_unpackhi_pd(X, Y);     // x1 y1 x3 y3
    const __m256d t2 = _mm256_unpacklo_pd(Z, zero);  // z0 0 z2 0
    const __m256d t3 = _mm256_unpackhi_pd(Z, zero);  // z1 0 z3 0
    r[0] = _mm256_permute2f128_pd(t0, t2, 0x20);
    r[1] = _mm256_permute2f128_pd(t1, t3, 0x20);
    r[2] = _mm256_permute2f128_pd(t0, t2, 0x31);
    r[3] = _mm256_permute2f128_pd(t1, t3, 0x31);
}

// Three loads, blends, then one permute per column.
[[gnu::always_inline]] inline void rowsToColumns(const double* at, Vec4& X, Vec4& Y, Vec4& Z) {
    const __m256d r0 = _mm256_loadu_pd(at);      // x0 y0 z0 x1
    const __m256d r1 = _mm256_loadu_pd(at + 4);  // y1 z1 x2 y2
    const __m256d r2 = _mm256_loadu_pd(at + 8);  // z2 x3 y3 z3
    X = _mm256_permute4x64_pd(_mm256_blend_pd(_mm256_blend_pd(r0, r1, 0b0100), r2, 0b0010), 0x6c);  // x0 x3 x2 x1
    Y = _mm256_permute_pd(_mm256_blend_pd(_mm256_blend_pd(r0, r1, 0b1001), r2, 0b0100), 0b0101);     // y1 y0 y3 y2
    Z = _mm256_permute4x64_pd(_mm256_blend_pd(_mm256_blend_pd(r0, r1, 0b0010), r2, 0b1001), 0xc6);  // z2 z1 z0 z3
}

#endif

#if SIMCORE_SIMD_ISA >= 3
// ---------------------------------------------------------------------------------------------
// AVX-512: eight lanes

[[gnu::always_inline]] inline Vec8 sqrt(Vec8 v) { return _mm512_sqrt_pd(v); }
[[gnu::always_inline]] inline Vec4 low(Vec8 v) { return _mm512_castpd512_pd256(v); }
[[gnu::always_inline]] inline Vec4 high(Vec8 v) { return _mm512_extractf64x4_pd(v, 1); }

// Eight consecutive rows (x, y, z) of a 3-per-particle array (three loads) to columns in
// natural order.
[[gnu::always_inline]] inline void rowsToColumns(const double* at, Vec8& X, Vec8& Y, Vec8& Z) {
    const __m512d r0 = _mm512_loadu_pd(at), r1 = _mm512_loadu_pd(at + 8), r2 = _mm512_loadu_pd(at + 16);
    // Indices 0-7 pick from the first operand, 8-15 from the second.
    const __m512d x01 = _mm512_permutex2var_pd(r0, _mm512_setr_epi64(0, 3, 6, 9, 12, 15, 0, 0), r1);
    const __m512d y01 = _mm512_permutex2var_pd(r0, _mm512_setr_epi64(1, 4, 7, 10, 13, 0, 0, 0), r1);
    const __m512d z01 = _mm512_permutex2var_pd(r0, _mm512_setr_epi64(2, 5, 8, 11, 14, 0, 0, 0), r1);
    X = _mm512_permutex2var_pd(x01, _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 10, 13), r2);
    Y = _mm512_permutex2var_pd(y01, _mm512_setr_epi64(0, 1, 2, 3, 4, 8, 11, 14), r2);
    Z = _mm512_permutex2var_pd(z01, _mm512_setr_epi64(0, 1, 2, 3, 4, 9, 12, 15), r2);
}

// Columns in natural order to padded rows, two per register: r[j] = [row 2j | row 2j+1].
[[gnu::always_inline]] inline void columnsToRowPairs(Vec8 X, Vec8 Y, Vec8 Z, Vec8 (&r)[4]) {
    const __m512d zero = _mm512_setzero_pd();
    const __m512d t0 = _mm512_unpacklo_pd(X, Y);     // x0 y0 | x2 y2 | x4 y4 | x6 y6
    const __m512d t1 = _mm512_unpackhi_pd(X, Y);     // x1 y1 | x3 y3 | x5 y5 | x7 y7
    const __m512d t2 = _mm512_unpacklo_pd(Z, zero);  // z0 0 | z2 0 | z4 0 | z6 0
    const __m512d t3 = _mm512_unpackhi_pd(Z, zero);  // z1 0 | z3 0 | z5 0 | z7 0
    const __m512i first = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11);
    const __m512i second = _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15);
    const __m512d even02 = _mm512_permutex2var_pd(t0, first, t2);   // [row 0 | row 2]
    const __m512d odd13 = _mm512_permutex2var_pd(t1, first, t3);    // [row 1 | row 3]
    const __m512d even46 = _mm512_permutex2var_pd(t0, second, t2);  // [row 4 | row 6]
    const __m512d odd57 = _mm512_permutex2var_pd(t1, second, t3);   // [row 5 | row 7]
    r[0] = _mm512_shuffle_f64x2(even02, odd13, 0x44);  // [row 0 | row 1]
    r[1] = _mm512_shuffle_f64x2(even02, odd13, 0xee);  // [row 2 | row 3]
    r[2] = _mm512_shuffle_f64x2(even46, odd57, 0x44);
    r[3] = _mm512_shuffle_f64x2(even46, odd57, 0xee);
}

// Block layout (the edge quads' eight lanes): a register holds two groups of four lanes, in
// the order (0, 1, 0', 1', 2, 3, 2', 3') where j is lane j of the first group and j' of the
// second: row registers [row j of group 0 | row j of group 1] transposed with 128-bit pieces
// kept together.
[[gnu::always_inline]] inline void toColumns(Vec8 r0, Vec8 r1, Vec8 r2, Vec8 r3, Vec8& X, Vec8& Y, Vec8& Z) {
    const __m512d t0 = _mm512_unpacklo_pd(r0, r1);  // x0 x1 z0 z1 | x0' x1' z0' z1'
    const __m512d t1 = _mm512_unpackhi_pd(r0, r1);  // y0 y1 w0 w1 | y0' y1' w0' w1'
    const __m512d t2 = _mm512_unpacklo_pd(r2, r3);  // x2 x3 z2 z3 | x2' x3' z2' z3'
    const __m512d t3 = _mm512_unpackhi_pd(r2, r3);  // y2 y3 w2 w3 | y2' y3' w2' w3'
    X = _mm512_shuffle_f64x2(t0, t2, 0x88);  // 128-bit pieces 0, 2 of t0, then 0, 2 of t2
    Y = _mm512_shuffle_f64x2(t1, t3, 0x88);
    Z = _mm512_shuffle_f64x2(t0, t2, 0xdd);  // pieces 1, 3 of t0, then 1, 3 of t2
}
[[gnu::always_inline]] inline void toRows(Vec8 X, Vec8 Y, Vec8 Z, Vec8 (&r)[4]) {
    const __m512d zero = _mm512_setzero_pd();
    const __m512i first = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11);
    const __m512i second = _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15);
    const __m512d t0 = _mm512_unpacklo_pd(X, Y);     // x0 y0 x0' y0' | x2 y2 x2' y2'
    const __m512d t1 = _mm512_unpackhi_pd(X, Y);     // x1 y1 x1' y1' | x3 y3 x3' y3'
    const __m512d t2 = _mm512_unpacklo_pd(Z, zero);  // z0 0 z0' 0 | z2 0 z2' 0
    const __m512d t3 = _mm512_unpackhi_pd(Z, zero);  // z1 0 z1' 0 | z3 0 z3' 0
    r[0] = _mm512_permutex2var_pd(t0, first, t2);
    r[1] = _mm512_permutex2var_pd(t1, first, t3);
    r[2] = _mm512_permutex2var_pd(t0, second, t2);
    r[3] = _mm512_permutex2var_pd(t1, second, t3);
}
#endif

// ---------------------------------------------------------------------------------------------
// Width-generic pieces over V = Vec4 or Vec8.
//
// Row blocks: a V holds kLanes<V> / 4 padded rows, [row of group 0 | row of group 1]; four
// row blocks transpose (toColumns) to columns in block layout (plain lane order for Vec4).

template <class V>
inline constexpr std::size_t kGroups = kLanes<V> / 4;

// Rows p[0], p[1].. of a 3-per-particle array as a row block.
template <class V>
[[gnu::always_inline]] inline V loadRows(const double* a, const std::size_t* p);
template <>
[[gnu::always_inline]] inline Vec4 loadRows<Vec4>(const double* a, const std::size_t* p) {
    return loadRow(a, p[0]);
}
// The same for rows that are not the last of their array (the inner layer's, whose last row
// is followed by the outer layer's first): one plain load per row instead of a masked one. The
// fourth double (the next particle's x) is read but never used: the transposes to columns
// drop it.
template <class V>
[[gnu::always_inline]] inline V loadInnerRows(const double* a, const std::size_t* p);
template <>
[[gnu::always_inline]] inline Vec4 loadInnerRows<Vec4>(const double* a, const std::size_t* p) {
#if SIMCORE_SIMD_ISA >= 2
    return _mm256_loadu_pd(a + 3 * p[0]);
#else
    return loadRow(a, p[0]);
#endif
}
// Group g's row of a row block.
[[gnu::always_inline]] inline Vec4 rowOf(Vec4 v, std::size_t) { return v; }

// Four doubles from each of src[0], src[1].. in block layout.
template <class V>
[[gnu::always_inline]] inline V blockLanes(const double* const* src);
template <>
[[gnu::always_inline]] inline Vec4 blockLanes<Vec4>(const double* const* src) {
    return loadu<Vec4>(src[0]);
}

// Accumulators of the quads' lanes, by the parity of the quad: a Vec4 holds one quad (two
// registers: even, odd), a Vec8 a pair (one register). Adds them to four-lane even and odd sums.
[[gnu::always_inline]] inline void addParities(Vec4 (&sums)[2], const Vec4 (&acc)[2]) {
    sums[0] = sums[0] + acc[0];
    sums[1] = sums[1] + acc[1];
}

// Adds lanes into four-lane sums: lanes 0-3, then 4-7.
[[gnu::always_inline]] inline Vec4 addLanes(Vec4 sum, Vec4 v) { return sum + v; }

// Columns of kLanes consecutive springs' forces: added to rows p.., subtracted from rows q..,
// row by row (a Vec8: pair by pair).
[[gnu::always_inline]] inline void addSubRows(double* f4, std::size_t p, std::size_t q, Vec4 X, Vec4 Y, Vec4 Z) {
    Vec4 rows[4];
    toRows(X, Y, Z, rows);
    for (std::size_t l = 0; l < 4; ++l) {
        addRow(f4, p + l, rows[l]);
        subRow(f4, q + l, rows[l]);
    }
}

#if SIMCORE_SIMD_ISA >= 3
template <>
[[gnu::always_inline]] inline Vec8 loadRows<Vec8>(const double* a, const std::size_t* p) {
    return _mm512_insertf64x4(_mm512_castpd256_pd512(loadRow(a, p[0])), loadRow(a, p[1]), 1);
}
template <>
[[gnu::always_inline]] inline Vec8 loadInnerRows<Vec8>(const double* a, const std::size_t* p) {
    return _mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_loadu_pd(a + 3 * p[0])), _mm256_loadu_pd(a + 3 * p[1]), 1);
}
[[gnu::always_inline]] inline Vec4 rowOf(Vec8 v, std::size_t group) { return group == 0 ? low(v) : high(v); }
template <>
[[gnu::always_inline]] inline Vec8 blockLanes<Vec8>(const double* const* src) {
    return _mm512_permutex2var_pd(_mm512_castpd256_pd512(_mm256_loadu_pd(src[0])),
                                  _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11),
                                  _mm512_castpd256_pd512(_mm256_loadu_pd(src[1])));
}
[[gnu::always_inline]] inline void addParities(Vec4 (&sums)[2], const Vec8 (&acc)[1]) {
    // Lanes (0, 1, 0', 1', 2, 3, 2', 3') to the even and odd quads' four lanes.
    sums[0] = sums[0] + low(_mm512_permutexvar_pd(_mm512_setr_epi64(0, 1, 4, 5, 0, 0, 0, 0), acc[0]));
    sums[1] = sums[1] + low(_mm512_permutexvar_pd(_mm512_setr_epi64(2, 3, 6, 7, 0, 0, 0, 0), acc[0]));
}
[[gnu::always_inline]] inline Vec4 addLanes(Vec4 sum, Vec8 v) { return (sum + low(v)) + high(v); }
[[gnu::always_inline]] inline void addSubRows(double* f4, std::size_t p, std::size_t q, Vec8 X, Vec8 Y, Vec8 Z) {
    Vec8 rows[4];
    columnsToRowPairs(X, Y, Z, rows);
    for (std::size_t j = 0; j < 4; ++j) {
        double* at = f4 + 4 * (p + 2 * j);
        storeu(at, loadu<Vec8>(at) + rows[j]);
        double* bt = f4 + 4 * (q + 2 * j);
        storeu(bt, loadu<Vec8>(bt) - rows[j]);
    }
}
#endif

}  // namespace simcore::simd::SIMCORE_SIMD_NS
