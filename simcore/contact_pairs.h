#pragma once
// Contact pairs: the outer layers of several bodies against each other, and each outer layer
// against its own elements that share no particle with it (self-contact) (docs/model.md "Several
// bodies"). Free of any world: it reads positions and velocities as flat arrays (3 per
// particle, world numbering) and adds forces into a flat array.
//
// Elements. 2D: particle-segment. 3D: particle-triangle and edge-edge. A pair is kept when
// its two elements belong to different bodies, or to one body and share no particle and no
// particle next to one (a particle's neighbours on its outer layer): elements that close
// in the rest shape are held apart by the springs, not by contact.
//
// The force. For the distance d between the closest points of a pair, below the skin d^:
//
//     U(d)  = k/4 (d^ - d)^4 d^/d                                   [J]
//     -U'   = k d^/4 (d^ - d)^3 (3 d + d^) / d^2                    along n [N]
//
//   * U, U', U'' and U''' vanish at d = d^ (the factor (d^ - d)^4): the integrators see a
//     right-hand side as smooth at the onset as the wall's k d^4/4 (contact.h), and keep
//     their order through an impact.
//   * U grows without bound as d -> 0 (the factor d^/d): a barrier. Two surfaces cannot meet
//     while the trajectory is followed; a step too long to follow it is caught by the step's
//     check (an exact intersection test, World).
//   * Damping and friction are the wall's (contact.h): f_n = -U' phi(alpha u) with u the
//     approach rate, and F_t = -mu f_n v_t / sqrt(|v_t|^2 + eps^2) on the relative tangential
//     velocity. Their power is booked as removed by contact.
//   * The pair's force is applied equal and opposite, to each element's particles by the
//     barycentric weights of the closest points: the forces of a pair sum to zero, and their
//     normal parts act along the line through the closest points, so total linear and
//     angular momentum change only by round-off (friction, tangential at two points d apart,
//     exerts a torque of at most mu f_n d).
//   * By the envelope theorem grad d = n at the particle and -w_i n at the element's
//     particles, so the normal force is exactly -grad U: the contact energy U is part of the
//     ledger, and the ledger closes.
//
// The broad phase: a uniform grid of cells at least as large as the largest element plus
// twice the query radius, rebuilt from sorted (cell, element) keys at every evaluation: every
// element lies in at most 2 cells per axis, every query box too, so each query visits at most
// 8 cells and the cost is linear in the number of elements (no loop over all pairs). A pair
// found in several cells is counted once (the cell holding the low corner of the overlap of
// the two boxes counts it).

#include <array>
#include <cstdint>
#include <vector>

#include "simcore/body.h"
#include "simcore/contact.h"

namespace simcore {

// The constants of body-body contact (World fills them from the world's parameters).
struct PairContactParams {
    double skin = 0.1;           // d^: the distance below which the force acts [m]
    double stiffness = 0.0;      // k [N/m^3]
    double alpha = 0.0;          // Hunt-Crossley coefficient [s/m] (contact.h)
    double friction = 0.0;       // Coulomb mu
    double frictionSpeed = 0.5;  // eps [m/s]
};

// U(d) and -U'(d) of the barrier (0 at and beyond the skin).
double pairPotential(const PairContactParams& c, double d);
double pairForceMagnitude(const PairContactParams& c, double d);

// What one evaluation of the pair forces adds up.
struct PairSums {
    double energy = 0.0;   // sum of U [J]
    double power = 0.0;    // power removed by damping and friction [W], >= 0
    int pairs = 0;         // pairs within the skin
};

// The closest pair found by a gap query.
struct GapReport {
    double gap = 0.0;           // [m]; +infinity when nothing is within reach
    int bodyA = -1, bodyB = -1; // the bodies of the two elements (equal: self-contact)
};

class ContactPairs {
public:
    // One body's outer layer in the world's particle numbering.
    struct Layer {
        int body = 0;                       // 0-based body number
        int dimension = 3;
        int firstParticle = 0;              // the body's particle 0 in the world
        const Surface* outer = nullptr;     // the body's outer surface (body-local numbering)
    };
    ContactPairs() = default;
    // Collects the elements of the given outer layers and their neighbourhoods.
    explicit ContactPairs(const std::vector<Layer>& layers);

    int dimension() const { return m_dimension; }
    std::size_t vertexCount() const { return m_vertex.size(); }
    std::size_t faceCount() const { return m_faces.size(); }  // segments (2D) or triangles (3D)
    std::size_t edgeCount() const { return m_edges.size(); }  // 3D: unique edges

    // Which pairs: all, those of two bodies, or those within one body (self-contact).
    enum class Which { All, BetweenBodies, Self };
    // Adds the pair forces at positions x and velocities v (3 per world particle) into f and
    // returns the sums (of the pairs `which` takes; the free-body diagram splits them).
    PairSums addForces(const PairContactParams& c, const double* x, const double* v, double* f,
                       Which which = Which::All);
    // The contact energy alone [J].
    double energy(const PairContactParams& c, const double* x);
    // Whether any pair is within `reach` of each other (the force is on when reach = skin).
    bool anyWithin(double reach, const double* x);
    // The smallest distance between two bodies' outer surfaces and between non-adjacent
    // elements of one outer surface: exact, by queries of growing reach (from `start`,
    // doubled until something is found or the reach is `limit`).
    GapReport minimumGap(const double* x, double start, double limit);
    // Exact intersection test at x: 2D two segments that cross, 3D an edge that crosses a
    // triangle, over the pairs within `reach` of each other (the broad phase's cells). Returns
    // the two bodies, or {-1, -1} when nothing intersects.
    std::array<int, 2> intersecting(const double* x, double reach);

    // The pairs within reach, for tests: every (vertex, face) and (edge, edge) pair the broad
    // phase hands to the narrow phase, as element indices.
    struct Candidate {
        int kind;  // 0: vertex-face, 1: edge-edge
        int a, b;
    };
    std::vector<Candidate> candidates(const double* x, double reach);
    // The same found by a loop over all pairs (the reference for the broad phase's test).
    std::vector<Candidate> candidatesByAllPairs(const double* x, double reach) const;

private:
    // Grid of element boxes for one element list (faces or edges).
    struct Grid {
        double cell = 1.0;
        std::vector<std::pair<std::uint64_t, int>> keys;  // (cell key, element), sorted
        std::vector<std::array<double, 6>> boxes;         // per element: low xyz, high xyz
    };
    template <class Elements>
    void buildGrid(Grid& grid, const Elements& elements, const double* x, double reach);
    // Calls visit(element) for every element whose box, grown by reach, meets [lo, hi], once.
    template <class Visit>
    void query(const Grid& grid, const std::array<double, 3>& lo, const std::array<double, 3>& hi, Visit&& visit) const;
    bool adjacentVertexFace(int vertex, int face) const;
    bool adjacentEdges(int e1, int e2) const;
    bool neighbours(int p, int q) const;  // p == q or p, q joined by an outer edge
    // Visits every kept pair within reach: onVertexFace(vertex, face), onEdgeEdge(e1, e2).
    template <class VF, class EE>
    void forPairs(const double* x, double reach, VF&& onVertexFace, EE&& onEdgeEdge);

    int m_dimension = 3;
    std::vector<int> m_vertex;                      // world particle of each outer vertex
    std::vector<int> m_vertexBody;
    std::vector<std::array<int, 3>> m_faces;        // world particles (2D: [a, b, -1])
    std::vector<int> m_faceBody;
    std::vector<std::array<int, 2>> m_edges;        // 3D: world particles
    std::vector<int> m_edgeBody;
    // Outer-layer neighbours of each world particle (CSR over the world's particles).
    std::vector<int> m_neighbourStart, m_neighbour;
    Grid m_faceGrid, m_edgeGrid;
};

// Closest points. Point p to triangle (a, b, c): the barycentric weights of the closest point.
std::array<double, 3> closestOnTriangle(const double* p, const double* a, const double* b, const double* c);
// Point p to segment (a, b): the parameter t of the closest point a + t (b - a), in [0, 1].
double closestOnSegment(const double* p, const double* a, const double* b);
// Segment (a, b) to segment (c, d): parameters (s, t) of the closest points.
std::array<double, 2> closestSegmentSegment(const double* a, const double* b, const double* c, const double* d);
// Exact tests: 2D segments that cross or touch (z ignored), 3D a segment that meets a triangle.
bool segmentsIntersect2d(const double* a, const double* b, const double* c, const double* d);
bool segmentIntersectsTriangle(const double* p, const double* q, const double* a, const double* b, const double* c);
// Triangles that meet (one's edge through the other, either way).
bool trianglesIntersect(const double* const tri1[3], const double* const tri2[3]);

}  // namespace simcore
