#pragma once
// The hot loops of the force evaluation (internal to simcore; ForceModel drives them).
//
// Each kernel works on one block of springs or triangles and adds its results into a padded
// particle buffer: 4 doubles per particle (x, y, z, 0), 32-byte aligned, so that a particle's
// force is one aligned 256-bit load and store. Positions and velocities are read in the
// state's own layout (3 doubles per particle).
//
// Each kernel is written once (force_kernels_body.h) over the width-generic vectors of simd.h
// and compiled once per instruction set; the widest one the CPU has is picked at load time:
//  - portable: no intrinsics, GCC vector extensions only (the baseline target's vectors:
//    SSE2 on x86-64, NEON on AArch64);
//  - AVX2 (x86-64): four springs or triangles at a time, loaded as rows and transposed in
//    registers with AVX2 shuffles, transposed back and added;
//  - AVX-512: the edge quads two at a time and the radius runs eight at a time, eight lanes
//    wide (the other kernels are AVX2's: eight-wide triangles measured slower).
// All do the same operations in the same order (no FMA: each operation rounds alone), and the
// sums a block returns (damping power, stretch, volume) are defined lane by lane (see QuadSums,
// sumLanes), so the sets' results are bit-identical (tested).

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "simcore/body.h"

namespace simcore {
// A spring shorter than this has no direction: it adds no force (never a NaN) and is counted
// as degenerate (docs/model.md, "Forces").
inline constexpr double kDegenerateLength = 1e-12;  // [m]
}  // namespace simcore

namespace simcore::kernels {

// Springs or triangles per block (the unit of ForceModel's loops and of the lane sums).
inline constexpr std::size_t kBlock = 256;

// Sum of v[0..n) in four interleaved lanes (v[k] into lane k mod 4, the remainder into lane 0,
// then (l0 + l1) + (l2 + l3)): independent add chains in an order fixed by n alone.
double sumLanes(const double* v, std::size_t n);

// The implementations, from the plainest to the widest.
enum class KernelSet { Portable, Avx2, Avx512 };
const char* kernelSetName(KernelSet set);
// The widest implementation this build and this CPU can run.
KernelSet widestKernels();
// Selects `wanted`, or the widest available one below it, for every thread; returns the one
// now in use. Meant for tests and benchmarks comparing them (the default is the widest).
KernelSet useKernels(KernelSet wanted);
KernelSet kernelsInUse();

// Sums over a block of springs, each in four interleaved lanes (see sumLanes).
struct SpringSums {
    double power = 0.0;     // damping power damping * (dv.u)^2 [W]
    double stretch2 = 0.0;  // (L - L0)^2, for the elastic energy stiffness/2 (L - L0)^2 [m^2]
};

// Springs [begin, end) of a set: adds F to the first particle and -F to the second in f4,
// where F = [stiffness (L - L0) + damping (dv.u)] u. Counts springs shorter than kDegenerateLength into
// `degenerate` (they get no force, but their stretch still counts).
SpringSums springBlock(const SpringSet& springs, std::size_t begin, std::size_t end, double stiffness,
                       double damping, const double* x, const double* v, double* f4, int& degenerate);

// The same for springs [begin, end) that form a run: spring k joins particle
// a[begin] + (k - begin) to that particle + n (the radius springs of a two-layer body, in
// order). The AVX-512 kernel reads and writes such runs as whole rows, eight at a time.
SpringSums springRunBlock(const SpringSet& springs, std::size_t begin, std::size_t end, int n, double stiffness,
                          double damping, const double* x, const double* v, double* f4, int& degenerate);

// Edge quads of a two-layer body: for a mesh edge (a, b) of the inner layer and its copy
// (A, B) = (a + n, b + n) in the outer layer, the four springs over the same four particles,
// one per lane: structural inner (a, b), structural outer (A, B), shear (A, b) and (B, a).
// Evaluated together they load 8 particle rows instead of 16 and update 4 force rows
// instead of 8. rest holds the four rest lengths of each quad in that order.
struct QuadSet {
    std::vector<int> a, b;
    std::vector<std::array<double, 4>> rest;
    std::size_t size() const { return a.size(); }
};

// Sums over a block of quads. Quad j of the block (j = q - begin) adds lane l's damping power
// and squared stretch into accumulator [j % 2][l], in order; lane l's sum is then
// [0][l] + [1][l]. power = (l0 + l1) + (l2 + l3); lanes 0-1 are the structural springs,
// lanes 2-3 the shear springs.
struct QuadSums {
    double power = 0.0;  // damping power of all four [W]
    std::array<double, 2> stretch2{};  // (L - L0)^2 of [structural, shear] springs [m^2]
};

// Quads [begin, end): adds each spring's force as springBlock does, per particle in the fixed
// order a += F0 - F3, b -= F0 + F2, A += F1 + F2, B += F3 - F1. Each lane's sums run over the
// quads in order; structural = lane 0 + lane 1, shear = lane 2 + lane 3. stiffness, damping: [structural,
// shear]; n: particles per layer.
QuadSums quadBlock(const QuadSet& quads, std::size_t begin, std::size_t end, int n,
                   std::array<double, 2> stiffness, std::array<double, 2> damping, const double* x,
                   const double* v, double* f4, int& degenerate);

// Triangles [begin, end) of a closed surface: adds the volume gradient (b-a)x(c-a)/6 to each
// corner in g4 and returns the sum of x_a.(x_b x x_c) (six times their share of the volume),
// summed in lanes like springBlock.
double triangleBlock(const Surface& surface, std::size_t begin, std::size_t end, const double* x,
                     double* g4);

// Each particle's fan on a closed 3D surface: the triangles around it, each turned so that the
// particle comes first, (v, p, q), kept as the pair (p, q) in the order of a walk around v
// (q of one pair is p of the next) where the fan closes.
struct VertexFans {
    std::vector<int> start;                   // particle v's pairs: [start[v], start[v + 1])
    std::vector<std::array<int, 2>> pair;
    std::vector<std::uint8_t> ring6;          // 1: six pairs that close in order (most vertices)
    bool empty() const { return start.empty(); }
};
// The fans of a topology's surfaces (3D; empty otherwise).
VertexFans vertexFans(const Topology& topology);

// The volume gradient gathered per corner: for particles [begin, end), row v of g4 is
// *written* (not added to) with dV/dx_v = (sum over the fan, in order, of (p - x_v) x (q - x_v)) / 6:
// the same terms triangleBlock adds, each triangle's cross product taken from the corner that
// receives it and summed in a row in registers, one store per particle instead of one
// read-modify-write per triangle and corner. Returns the sum of x_v . (6 dV/dx_v) in four
// interleaved lanes (particle begin + k in lane k mod 4): three times x_a.(x_b x x_c) of each
// triangle whose corners are all in the range, i.e. 18 times their volume.
double vertexGradients(const VertexFans& fans, int begin, int end, const double* x, double* g4);

// Particles [begin, end) from the padded buffers to the 3-per-particle layout:
// out = f4 + p g4 (without g4 when it is nullptr), times invMass3 when that is given.
void unpad(const double* f4, const double* g4, double p, const double* invMass3, int begin, int end,
           double* out);

// The explicit integrators' element-wise stage sums over n doubles, compiled per instruction
// set like the kernels above (the integrators' own file is built for the baseline target): the
// same operations in the same order as the plain loops, so the same bits.
// out = y + c k (out may be y).
void stageSum(double* out, const double* y, double c, const double* k, std::size_t n);
// RK4's last sum: y += h6 (((k1 + 2 k2) + 2 k3) + k4).
void rk4Sum(double* y, double h6, const double* k1, const double* k2, const double* k3, const double* k4,
            std::size_t n);

// Read access by particle to a padded buffer (4 doubles per particle, see above), so that code
// outside the kernels need not know the layout: rows[i] is particle i's (x, y, z).
class PaddedRows {
public:
    PaddedRows() = default;
    explicit PaddedRows(const double* data) : m_data(data) {}
    explicit operator bool() const { return m_data != nullptr; }
    Eigen::Map<const Eigen::Vector3d> operator[](int particle) const {
        return Eigen::Map<const Eigen::Vector3d>(m_data + 4 * static_cast<std::ptrdiff_t>(particle));
    }
    // The buffer itself, for the passes that work on the padded rows (kernels, contact).
    const double* data() const { return m_data; }

private:
    const double* m_data = nullptr;
};

// A buffer of doubles aligned to 64 bytes (a cache line), zero-filled.
class AlignedBuffer {
public:
    AlignedBuffer() = default;
    explicit AlignedBuffer(std::size_t count);
    AlignedBuffer(const AlignedBuffer& other);
    AlignedBuffer& operator=(const AlignedBuffer& other);
    AlignedBuffer(AlignedBuffer&&) noexcept = default;
    AlignedBuffer& operator=(AlignedBuffer&&) noexcept = default;
    double* data() { return m_data.get(); }
    const double* data() const { return m_data.get(); }
    std::size_t size() const { return m_size; }

private:
    struct Free {
        void operator()(double* p) const;
    };
    std::unique_ptr<double, Free> m_data;
    std::size_t m_size = 0;
};

}  // namespace simcore::kernels
