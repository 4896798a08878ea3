#pragma once
// Bodies: topology (who is connected to whom, rest lengths, closed surfaces) and the start
// state, built procedurally for each scene (thesis ch. 3, docs/model.md "Bodies").
//
// Particle numbering: 1D has particles 0 (top) and 1. Layered bodies store the inner layer
// first, [0, n), then the outer layer, [n, 2n), vertex k of one layer paired with vertex k
// of the other. Positions are always 3-vectors (z = 0 in 1D and 2D).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "simcore/params.h"

namespace simcore {

enum class Layer : std::uint8_t { Single, Inner, Outer };
enum class SpringFamily : std::uint8_t { Structural, Radius, Shear };
inline constexpr int kSpringFamilyCount = 3;

std::string_view layerName(Layer layer);            // "single", "inner", "outer"
std::string_view springFamilyName(SpringFamily f);  // "structural", "radius", "shear"

// Springs of one family as parallel arrays (index pairs + rest lengths): the hot loop
// streams through them.
struct SpringSet {
    std::vector<int> a;          // first particle of each spring
    std::vector<int> b;          // second particle
    std::vector<double> rest;    // rest length L0 [m]
    std::size_t size() const { return a.size(); }
    void add(int i, int j, double restLength) {
        a.push_back(i);
        b.push_back(j);
        rest.push_back(restLength);
    }
};

// A closed layer that encloses gas: a counter-clockwise polygon (2D) or an outward-oriented
// triangle mesh (3D).
struct Surface {
    Layer layer = Layer::Outer;
    std::vector<std::array<int, 2>> edges;      // 2D: (a, b) with the interior on the left
    std::vector<std::array<int, 3>> triangles;  // 3D: (a, b, c), normal (b-a)x(c-a) outward
    double restVolume = 0.0;                    // area [m^2] in 2D, volume [m^3] in 3D
};

struct Topology {
    int dimension = 3;                       // 1, 2 or 3: which plane the body lives in
    std::vector<Layer> layer;                // per particle
    std::array<SpringSet, kSpringFamilyCount> springs;
    std::vector<Surface> surfaces;           // inner first (if any), then outer
    std::vector<std::array<int, 2>> layerPairs;  // (inner, outer) particle pairs
    // Triangles drawn to fill the 2D ring between layers (display only; no physics).
    std::vector<std::array<int, 3>> fillTriangles;

    int particleCount() const { return static_cast<int>(layer.size()); }
    std::size_t springCount() const {
        return springs[0].size() + springs[1].size() + springs[2].size();
    }
    const SpringSet& family(SpringFamily f) const { return springs[static_cast<int>(f)]; }
    const Surface* surface(Layer l) const {
        for (const Surface& s : surfaces)
            if (s.layer == l) return &s;
        return nullptr;
    }
};

// Everything a body starts with: topology, start positions, masses.
struct Body {
    Topology topology;
    Eigen::Matrix3Xd positions;  // 3 x N [m], the rest shape (before any perturbation)
    Eigen::VectorXd mass;        // per particle [kg]
    std::vector<bool> fixed;     // a fixed particle never moves (infinite mass)
};

// The outer-layer particle (or either 1D particle) of `x` (3 x N, `layers` per particle) nearest
// a ray (origin, unit direction) within maxDistance of it; nearest the origin among those
// (the front surface); -1 when none is. The mouse's pick, for one body or a world.
int pickAlongRay(const std::vector<Layer>& layers, const double* x, const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& direction, double maxDistance);

struct RingShape {
    int particles = 12;
    double radiusInner = 1.5;
    double radiusOuter = 2.0;
};
struct SphereShape {
    int subdivisions = 2;
    double radiusInner = 1.5;
    double radiusOuter = 2.0;
};
struct LatLongShape {
    int slices = 8;
    int stacks = 4;
    double radiusInner = 1.5;
    double radiusOuter = 2.0;
};
struct SpringShape {
    double restLength = 1.0;
    double initialLength = 1.5;
    bool fixedEnd = true;
};

// Unit-sphere meshes (one layer), exposed for tests and the viewport.
struct TriangleMesh {
    Eigen::Matrix3Xd vertices;
    std::vector<std::array<int, 3>> triangles;
};
TriangleMesh subdividedOctahedron(int level);
TriangleMesh latLongSphere(int slices, int stacks);
// Renumbers a mesh's vertices along a space-filling (Z-order) curve for memory locality, and
// remaps its triangles and, if given, an edge list (kept sorted, a < b).
void renumberForLocality(TriangleMesh& mesh, std::vector<std::array<int, 2>>* edges);
// Unique undirected edges (a < b) of a triangle mesh, sorted.
std::vector<std::array<int, 2>> meshEdges(const std::vector<std::array<int, 3>>& triangles);

Body buildSpring1d(const SpringShape& shape, double mass);
Body buildRing2d(const RingShape& shape, double massInner, double massOuter);
Body buildSphere3d(const SphereShape& shape, double massInner, double massOuter);
Body buildLatLongSphere(const LatLongShape& shape, double massInner, double massOuter);
// Latitude/longitude structural edges exclude the quads' diagonals; see body.cpp.

// How large the body a scene describes is, counted from its shape parameters without building
// it: particles (both layers), springs (all families) and gas faces (triangles in 3D, edges in
// 2D). Equal to the built body's counts (tested).
struct BodySize {
    long long particles = 0;
    long long springs = 0;
    long long faces = 0;
};
BodySize bodySize(const ParameterSet& params);

// The stated memory limit of one simulation, and an upper bound of what a body of a given size
// takes with the most memory-hungry integrator (implicit Euler): state, integrator stages, force
// buffers, topology and the chunked spring copy. Measured live heap is 0.6-0.9 of this bound
// (tested); see docs/reliability.md.
inline constexpr double kMemoryLimitBytes = 1024.0 * 1024.0 * 1024.0;
double memoryBoundBytes(const BodySize& size);
// The same for a given integrator: the CVODE methods (cvode-bdf, cvode-adams) hold about 40
// more state-sized vectors (the Nordsieck history up to order 5 or 12, CVODE's work vectors,
// GMRES's Krylov basis, the preconditioner's CG vectors): measured 1.1-1.3 kB more per
// particle than this bound; the others are within it.
double memoryBoundBytes(const BodySize& size, std::string_view integrator);

// Checks what no single parameter can: radius_inner below radius_outer, and a resolution whose
// memory bound stays within kMemoryLimitBytes (with `integrator`'s own needs when one is named:
// the CVODE methods hold more). The message says what is allowed.
std::optional<std::string> validateShape(const ParameterSet& params, std::string_view integrator = {});

// The body of a scene's shape as the table's values describe it, per particle and per spring
// (unscaled: scaling.h's buildBody makes the body a scene's parameters describe). The shape is
// not checked (validateShape does that).
Body buildShape(SceneKind kind, const Params::Shape& shape);

// Exact enclosed measure of a closed layer at the given positions: shoelace area (2D) or
// divergence-theorem volume V = sum x_a.(x_b x x_c)/6 (3D).
double enclosedVolume(const Surface& surface, const double* positions, int dimension);

// The mean of the columns of positions (3 x N): the body's centroid [m]. Summed column by
// column in order, so every target gives the same bits: Eigen's vectorised rowwise().mean()
// adds in an order set by the target's vector layout (x86-64 and AArch64 builds differed in
// the last bits of the x coordinate; scripts/check-aarch64.sh).
Eigen::Vector3d centroid(const Eigen::Matrix3Xd& positions);

}  // namespace simcore
