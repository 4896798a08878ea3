#include "simcore/contact_pairs.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>

namespace simcore {

namespace {

using Vec = std::array<double, 3>;

Vec at(const double* x) { return {x[0], x[1], x[2]}; }
Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Cell coordinates packed into one key (21 bits per axis, biased; far-away coordinates are
// clamped, which only makes distinct cells share a key: more candidates, never fewer).
constexpr std::int64_t kBias = 1 << 20;
std::int64_t cellOf(double coordinate, double cell) {
    const double c = std::floor(coordinate / cell);
    return static_cast<std::int64_t>(std::clamp(c, -double(kBias - 1), double(kBias - 1)));
}
std::uint64_t keyOf(std::int64_t i, std::int64_t j, std::int64_t k) {
    return (static_cast<std::uint64_t>(i + kBias) << 42) | (static_cast<std::uint64_t>(j + kBias) << 21) |
           static_cast<std::uint64_t>(k + kBias);
}

// Orientation of d against the plane (a, b, c): the sign of (b - a) x (c - a) . (d - a).
double orient3(const double* a, const double* b, const double* c, const double* d) {
    const Vec ab = sub(at(b), at(a)), ac = sub(at(c), at(a)), ad = sub(at(d), at(a));
    return dot(cross(ab, ac), ad);
}
double orient2(const double* a, const double* b, const double* c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// One pair's force: the relative position r = sum w_k x_k (the vector between the closest
// points), its velocity sum w_k v_k, and the force F added to particle k as w_k F.
template <int N>
void pairForce(const PairContactParams& c, const std::array<int, N>& particle, const std::array<double, N>& w,
               const double* x, const double* v, double* f, PairSums& sums) {
    Vec r{}, vr{};
    for (int k = 0; k < N; ++k)
        for (int a = 0; a < 3; ++a) {
            r[static_cast<std::size_t>(a)] += w[static_cast<std::size_t>(k)] * x[3 * particle[static_cast<std::size_t>(k)] + a];
            vr[static_cast<std::size_t>(a)] += w[static_cast<std::size_t>(k)] * v[3 * particle[static_cast<std::size_t>(k)] + a];
        }
    const double d = std::sqrt(dot(r, r));
    if (!(d < c.skin) || !(d > 0.0)) return;
    const Vec n{r[0] / d, r[1] / d, r[2] / d};
    const double elastic = pairForceMagnitude(c, d);
    const double approach = -dot(n, vr);  // > 0: closing
    const double u = c.alpha * approach;
    const double normal = elastic * contactPhi(u);
    Vec force{normal * n[0], normal * n[1], normal * n[2]};
    double power = elastic * contactPhiMinusOne(u) * approach;
    if (c.friction > 0.0) {
        const double vn = dot(n, vr);
        const Vec vt{vr[0] - vn * n[0], vr[1] - vn * n[1], vr[2] - vn * n[2]};
        const double slip2 = dot(vt, vt);
        const double scale = c.friction * normal / std::sqrt(slip2 + c.frictionSpeed * c.frictionSpeed);
        for (int a = 0; a < 3; ++a) force[static_cast<std::size_t>(a)] -= scale * vt[static_cast<std::size_t>(a)];
        power += scale * slip2;
    }
    for (int k = 0; k < N; ++k)
        for (int a = 0; a < 3; ++a)
            f[3 * particle[static_cast<std::size_t>(k)] + a] += w[static_cast<std::size_t>(k)] * force[static_cast<std::size_t>(a)];
    sums.energy += pairPotential(c, d);
    sums.power += power;
    ++sums.pairs;
}


// The vector between the closest points of vertex p and a face (2D segment, 3D triangle).
Vec vertexFaceGap(int dimension, int p, const std::array<int, 3>& fc, const double* x) {
    Vec closest{};
    if (dimension == 2) {
        const double t = closestOnSegment(x + 3 * p, x + 3 * fc[0], x + 3 * fc[1]);
        for (int a = 0; a < 3; ++a) closest[static_cast<std::size_t>(a)] = (1.0 - t) * x[3 * fc[0] + a] + t * x[3 * fc[1] + a];
    } else {
        const auto w = closestOnTriangle(x + 3 * p, x + 3 * fc[0], x + 3 * fc[1], x + 3 * fc[2]);
        for (int a = 0; a < 3; ++a)
            closest[static_cast<std::size_t>(a)] = w[0] * x[3 * fc[0] + a] + w[1] * x[3 * fc[1] + a] + w[2] * x[3 * fc[2] + a];
    }
    return sub(at(x + 3 * p), closest);
}

// The same for two edges.
Vec edgeEdgeGap(const std::array<int, 2>& a, const std::array<int, 2>& b, const double* x) {
    const auto st = closestSegmentSegment(x + 3 * a[0], x + 3 * a[1], x + 3 * b[0], x + 3 * b[1]);
    Vec r{};
    for (int k = 0; k < 3; ++k)
        r[static_cast<std::size_t>(k)] = (1.0 - st[0]) * x[3 * a[0] + k] + st[0] * x[3 * a[1] + k] -
                                         (1.0 - st[1]) * x[3 * b[0] + k] - st[1] * x[3 * b[1] + k];
    return r;
}

double length(const Vec& r) { return std::sqrt(dot(r, r)); }

}  // namespace

double pairPotential(const PairContactParams& c, double d) {
    if (!(d < c.skin)) return 0.0;
    if (!(d > 0.0)) return std::numeric_limits<double>::infinity();
    const double q = c.skin - d;
    return 0.25 * c.stiffness * q * q * q * q * c.skin / d;
}

double pairForceMagnitude(const PairContactParams& c, double d) {
    if (!(d < c.skin)) return 0.0;
    if (!(d > 0.0)) return std::numeric_limits<double>::infinity();
    const double q = c.skin - d;
    return 0.25 * c.stiffness * c.skin * q * q * q * (3.0 * d + c.skin) / (d * d);
}

std::array<double, 3> closestOnTriangle(const double* p, const double* a, const double* b, const double* c) {
    // Ericson, Real-Time Collision Detection 5.1.5: the Voronoi regions of the triangle.
    const Vec ab = sub(at(b), at(a)), ac = sub(at(c), at(a)), ap = sub(at(p), at(a));
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
    const Vec bp = sub(at(p), at(b));
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        const double t = d1 / (d1 - d3);
        return {1.0 - t, t, 0.0};
    }
    const Vec cp = sub(at(p), at(c));
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        const double t = d2 / (d2 - d6);
        return {1.0 - t, 0.0, t};
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        return {0.0, 1.0 - t, t};
    }
    const double denominator = 1.0 / (va + vb + vc);
    const double v = vb * denominator, w = vc * denominator;
    return {1.0 - v - w, v, w};
}

double closestOnSegment(const double* p, const double* a, const double* b) {
    const Vec ab = sub(at(b), at(a));
    const double length2 = dot(ab, ab);
    if (!(length2 > 0.0)) return 0.0;
    return std::clamp(dot(sub(at(p), at(a)), ab) / length2, 0.0, 1.0);
}

std::array<double, 2> closestSegmentSegment(const double* a, const double* b, const double* c, const double* d) {
    // Ericson 5.1.9.
    const Vec d1 = sub(at(b), at(a)), d2 = sub(at(d), at(c)), r = sub(at(a), at(c));
    const double aa = dot(d1, d1), ee = dot(d2, d2), ff = dot(d2, r);
    double s = 0.0, t = 0.0;
    if (!(aa > 0.0) && !(ee > 0.0)) return {0.0, 0.0};
    if (!(aa > 0.0)) return {0.0, std::clamp(ff / ee, 0.0, 1.0)};
    const double cc = dot(d1, r);
    if (!(ee > 0.0)) return {std::clamp(-cc / aa, 0.0, 1.0), 0.0};
    const double bb = dot(d1, d2), denominator = aa * ee - bb * bb;
    s = denominator > 0.0 ? std::clamp((bb * ff - cc * ee) / denominator, 0.0, 1.0) : 0.0;
    t = (bb * s + ff) / ee;
    if (t < 0.0) {
        t = 0.0;
        s = std::clamp(-cc / aa, 0.0, 1.0);
    } else if (t > 1.0) {
        t = 1.0;
        s = std::clamp((bb - cc) / aa, 0.0, 1.0);
    }
    return {s, t};
}

bool segmentsIntersect2d(const double* a, const double* b, const double* c, const double* d) {
    const double o1 = orient2(a, b, c), o2 = orient2(a, b, d), o3 = orient2(c, d, a), o4 = orient2(c, d, b);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
    // Collinear touching cases.
    auto on = [](const double* p, const double* q, const double* r) {
        return std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) && std::min(p[1], q[1]) <= r[1] &&
               r[1] <= std::max(p[1], q[1]);
    };
    return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) ||
           (o4 == 0 && on(c, d, b));
}

bool segmentIntersectsTriangle(const double* p, const double* q, const double* a, const double* b, const double* c) {
    const double sp = orient3(a, b, c, p), sq = orient3(a, b, c, q);
    if ((sp > 0 && sq > 0) || (sp < 0 && sq < 0)) return false;
    if (sp == 0 && sq == 0) return false;  // coplanar: left to the edges of the other triangle
    const double s1 = orient3(p, q, a, b), s2 = orient3(p, q, b, c), s3 = orient3(p, q, c, a);
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
}

bool trianglesIntersect(const double* const t1[3], const double* const t2[3]) {
    for (int e = 0; e < 3; ++e) {
        if (segmentIntersectsTriangle(t1[e], t1[(e + 1) % 3], t2[0], t2[1], t2[2])) return true;
        if (segmentIntersectsTriangle(t2[e], t2[(e + 1) % 3], t1[0], t1[1], t1[2])) return true;
    }
    return false;
}

ContactPairs::ContactPairs(const std::vector<Layer>& layers) {
    int particles = 0;
    for (const Layer& l : layers) {
        m_dimension = l.dimension;
        int highest = -1;
        for (const auto& e : l.outer->edges) highest = std::max({highest, e[0], e[1]});
        for (const auto& t : l.outer->triangles) highest = std::max({highest, t[0], t[1], t[2]});
        particles = std::max(particles, l.firstParticle + highest + 1);
    }
    std::vector<std::vector<int>> adjacent(static_cast<std::size_t>(particles));
    auto link = [&](int a, int b) {
        auto& la = adjacent[static_cast<std::size_t>(a)];
        if (std::find(la.begin(), la.end(), b) == la.end()) la.push_back(b);
        auto& lb = adjacent[static_cast<std::size_t>(b)];
        if (std::find(lb.begin(), lb.end(), a) == lb.end()) lb.push_back(a);
    };
    for (const Layer& l : layers) {
        const int o = l.firstParticle;
        std::vector<int> seen;
        auto vertex = [&](int p) {
            if (std::find(seen.begin(), seen.end(), p) != seen.end()) return;
            seen.push_back(p);
        };
        if (l.dimension == 2) {
            for (auto [a, b] : l.outer->edges) {
                m_faces.push_back({o + a, o + b, -1});
                m_faceBody.push_back(l.body);
                link(o + a, o + b);
                vertex(o + a);
            }
        } else {
            for (auto [a, b, c] : l.outer->triangles) {
                m_faces.push_back({o + a, o + b, o + c});
                m_faceBody.push_back(l.body);
                link(o + a, o + b);
                link(o + b, o + c);
                link(o + c, o + a);
                vertex(o + a);
                vertex(o + b);
                vertex(o + c);
            }
            for (auto [a, b] : meshEdges(l.outer->triangles)) {
                m_edges.push_back({o + a, o + b});
                m_edgeBody.push_back(l.body);
            }
        }
        std::sort(seen.begin(), seen.end());
        for (int p : seen) {
            m_vertex.push_back(p);
            m_vertexBody.push_back(l.body);
        }
    }
    m_neighbourStart.assign(static_cast<std::size_t>(particles) + 1, 0);
    for (std::size_t p = 0; p < adjacent.size(); ++p) {
        m_neighbourStart[p + 1] = m_neighbourStart[p] + static_cast<int>(adjacent[p].size());
        m_neighbour.insert(m_neighbour.end(), adjacent[p].begin(), adjacent[p].end());
    }
}

bool ContactPairs::neighbours(int p, int q) const {
    if (p == q) return true;
    const auto s = static_cast<std::size_t>(p);
    for (int k = m_neighbourStart[s]; k < m_neighbourStart[s + 1]; ++k)
        if (m_neighbour[static_cast<std::size_t>(k)] == q) return true;
    return false;
}

bool ContactPairs::adjacentVertexFace(int vertex, int face) const {
    const auto& f = m_faces[static_cast<std::size_t>(face)];
    for (int q : f)
        if (q >= 0 && neighbours(vertex, q)) return true;
    return false;
}

bool ContactPairs::adjacentEdges(int e1, int e2) const {
    for (int p : m_edges[static_cast<std::size_t>(e1)])
        for (int q : m_edges[static_cast<std::size_t>(e2)])
            if (neighbours(p, q)) return true;
    return false;
}

template <class Elements>
void ContactPairs::buildGrid(Grid& grid, const Elements& elements, const double* x, double reach) {
    grid.boxes.resize(elements.size());
    double largest = 0.0;
    for (std::size_t e = 0; e < elements.size(); ++e) {
        std::array<double, 6> box{};
        for (int a = 0; a < 3; ++a) {
            box[static_cast<std::size_t>(a)] = std::numeric_limits<double>::infinity();
            box[static_cast<std::size_t>(a + 3)] = -std::numeric_limits<double>::infinity();
        }
        for (int p : elements[e]) {
            if (p < 0) continue;
            for (int a = 0; a < 3; ++a) {
                box[static_cast<std::size_t>(a)] = std::min(box[static_cast<std::size_t>(a)], x[3 * p + a]);
                box[static_cast<std::size_t>(a + 3)] = std::max(box[static_cast<std::size_t>(a + 3)], x[3 * p + a]);
            }
        }
        for (int a = 0; a < 3; ++a)
            largest = std::max(largest, box[static_cast<std::size_t>(a + 3)] - box[static_cast<std::size_t>(a)]);
        grid.boxes[e] = box;
    }
    // Every element and every query box (an element's grown by reach, or a point's) spans at
    // most two cells per axis.
    grid.cell = std::max(largest + 2.0 * reach, 1e-9);
    if (!std::isfinite(grid.cell)) grid.cell = 1.0;  // a non-finite state: the step's checks fail it
    grid.keys.clear();
    for (std::size_t e = 0; e < elements.size(); ++e) {
        const auto& box = grid.boxes[e];
        if (!std::isfinite(box[0] + box[1] + box[2] + box[3] + box[4] + box[5])) continue;
        const std::int64_t i0 = cellOf(box[0], grid.cell), i1 = cellOf(box[3], grid.cell);
        const std::int64_t j0 = cellOf(box[1], grid.cell), j1 = cellOf(box[4], grid.cell);
        const std::int64_t k0 = cellOf(box[2], grid.cell), k1 = cellOf(box[5], grid.cell);
        for (std::int64_t i = i0; i <= i1; ++i)
            for (std::int64_t j = j0; j <= j1; ++j)
                for (std::int64_t k = k0; k <= k1; ++k) grid.keys.emplace_back(keyOf(i, j, k), static_cast<int>(e));
    }
    std::sort(grid.keys.begin(), grid.keys.end());
}

template <class Visit>
void ContactPairs::query(const Grid& grid, const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                         Visit&& visit) const {
    const std::int64_t i0 = cellOf(lo[0], grid.cell), i1 = cellOf(hi[0], grid.cell);
    const std::int64_t j0 = cellOf(lo[1], grid.cell), j1 = cellOf(hi[1], grid.cell);
    const std::int64_t k0 = cellOf(lo[2], grid.cell), k1 = cellOf(hi[2], grid.cell);
    for (std::int64_t i = i0; i <= i1; ++i)
        for (std::int64_t j = j0; j <= j1; ++j)
            for (std::int64_t k = k0; k <= k1; ++k) {
                const std::uint64_t key = keyOf(i, j, k);
                auto it = std::lower_bound(grid.keys.begin(), grid.keys.end(), std::pair<std::uint64_t, int>{key, INT_MIN});
                for (; it != grid.keys.end() && it->first == key; ++it) {
                    const auto& box = grid.boxes[static_cast<std::size_t>(it->second)];
                    bool meets = true;
                    std::array<double, 3> corner{};
                    for (int a = 0; a < 3; ++a) {
                        const auto s = static_cast<std::size_t>(a);
                        meets = meets && box[s] <= hi[s] && lo[s] <= box[s + 3];
                        corner[s] = std::max(box[s], lo[s]);
                    }
                    // Counted once: in the cell of the low corner of the two boxes' overlap.
                    if (meets && keyOf(cellOf(corner[0], grid.cell), cellOf(corner[1], grid.cell),
                                       cellOf(corner[2], grid.cell)) == key)
                        visit(it->second);
                }
            }
}

template <class VF, class EE>
void ContactPairs::forPairs(const double* x, double reach, VF&& onVertexFace, EE&& onEdgeEdge) {
    buildGrid(m_faceGrid, m_faces, x, reach);
    for (std::size_t i = 0; i < m_vertex.size(); ++i) {
        const int p = m_vertex[i];
        const std::array<double, 3> lo{x[3 * p] - reach, x[3 * p + 1] - reach, x[3 * p + 2] - reach};
        const std::array<double, 3> hi{x[3 * p] + reach, x[3 * p + 1] + reach, x[3 * p + 2] + reach};
        query(m_faceGrid, lo, hi, [&](int face) {
            if (m_faceBody[static_cast<std::size_t>(face)] == m_vertexBody[i] && adjacentVertexFace(p, face)) return;
            onVertexFace(static_cast<int>(i), face);
        });
    }
    if (m_edges.empty()) return;
    buildGrid(m_edgeGrid, m_edges, x, reach);
    for (std::size_t e = 0; e < m_edges.size(); ++e) {
        const auto& box = m_edgeGrid.boxes[e];
        const std::array<double, 3> lo{box[0] - reach, box[1] - reach, box[2] - reach};
        const std::array<double, 3> hi{box[3] + reach, box[4] + reach, box[5] + reach};
        query(m_edgeGrid, lo, hi, [&](int other) {
            if (other <= static_cast<int>(e)) return;
            if (m_edgeBody[e] == m_edgeBody[static_cast<std::size_t>(other)] && adjacentEdges(static_cast<int>(e), other))
                return;
            onEdgeEdge(static_cast<int>(e), other);
        });
    }
}

PairSums ContactPairs::addForces(const PairContactParams& c, const double* x, const double* v, double* f,
                                 Which which) {
    PairSums sums;
    auto takes = [which](int bodyA, int bodyB) {
        return which == Which::All || (which == Which::Self) == (bodyA == bodyB);
    };
    forPairs(
        x, c.skin,
        [&](int i, int face) {
            if (!takes(m_vertexBody[static_cast<std::size_t>(i)], m_faceBody[static_cast<std::size_t>(face)])) return;
            const int p = m_vertex[static_cast<std::size_t>(i)];
            const auto& fc = m_faces[static_cast<std::size_t>(face)];
            if (m_dimension == 2) {
                const double t = closestOnSegment(x + 3 * p, x + 3 * fc[0], x + 3 * fc[1]);
                pairForce<3>(c, {p, fc[0], fc[1]}, {1.0, -(1.0 - t), -t}, x, v, f, sums);
            } else {
                const auto w = closestOnTriangle(x + 3 * p, x + 3 * fc[0], x + 3 * fc[1], x + 3 * fc[2]);
                pairForce<4>(c, {p, fc[0], fc[1], fc[2]}, {1.0, -w[0], -w[1], -w[2]}, x, v, f, sums);
            }
        },
        [&](int e1, int e2) {
            if (!takes(m_edgeBody[static_cast<std::size_t>(e1)], m_edgeBody[static_cast<std::size_t>(e2)])) return;
            const auto& a = m_edges[static_cast<std::size_t>(e1)];
            const auto& b = m_edges[static_cast<std::size_t>(e2)];
            const auto st = closestSegmentSegment(x + 3 * a[0], x + 3 * a[1], x + 3 * b[0], x + 3 * b[1]);
            pairForce<4>(c, {a[0], a[1], b[0], b[1]}, {1.0 - st[0], st[0], -(1.0 - st[1]), -st[1]}, x, v, f, sums);
        });
    return sums;
}

double ContactPairs::energy(const PairContactParams& c, const double* x) {
    double sum = 0.0;
    forPairs(
        x, c.skin,
        [&](int i, int face) {
            sum += pairPotential(c, length(vertexFaceGap(m_dimension, m_vertex[static_cast<std::size_t>(i)],
                                                         m_faces[static_cast<std::size_t>(face)], x)));
        },
        [&](int e1, int e2) {
            sum += pairPotential(c, length(edgeEdgeGap(m_edges[static_cast<std::size_t>(e1)],
                                                       m_edges[static_cast<std::size_t>(e2)], x)));
        });
    return sum;
}

GapReport ContactPairs::minimumGap(const double* x, double start, double limit) {
    GapReport best;
    best.gap = std::numeric_limits<double>::infinity();
    auto consider = [&](double d, int bodyA, int bodyB) {
        if (d < best.gap) best = GapReport{d, bodyA, bodyB};
    };
    for (double reach = start; reach > 0.0; reach *= 2.0) {
        forPairs(
            x, reach,
            [&](int i, int face) {
                consider(length(vertexFaceGap(m_dimension, m_vertex[static_cast<std::size_t>(i)],
                                              m_faces[static_cast<std::size_t>(face)], x)),
                         m_vertexBody[static_cast<std::size_t>(i)], m_faceBody[static_cast<std::size_t>(face)]);
            },
            [&](int e1, int e2) {
                consider(length(edgeEdgeGap(m_edges[static_cast<std::size_t>(e1)], m_edges[static_cast<std::size_t>(e2)], x)),
                         m_edgeBody[static_cast<std::size_t>(e1)], m_edgeBody[static_cast<std::size_t>(e2)]);
            });
        // Every pair closer than reach was visited: a gap below it is the smallest there is.
        if (best.gap < reach || reach >= limit) break;
    }
    return best;
}

std::array<int, 2> ContactPairs::intersecting(const double* x, double reach) {
    buildGrid(m_faceGrid, m_faces, x, reach);
    std::array<int, 2> found{-1, -1};
    for (std::size_t f = 0; f < m_faces.size() && found[0] < 0; ++f) {
        const auto& box = m_faceGrid.boxes[f];
        const std::array<double, 3> lo{box[0] - reach, box[1] - reach, box[2] - reach};
        const std::array<double, 3> hi{box[3] + reach, box[4] + reach, box[5] + reach};
        const auto& a = m_faces[f];
        query(m_faceGrid, lo, hi, [&](int other) {
            if (found[0] >= 0 || other <= static_cast<int>(f)) return;
            const auto& b = m_faces[static_cast<std::size_t>(other)];
            const int bodyA = m_faceBody[f], bodyB = m_faceBody[static_cast<std::size_t>(other)];
            if (bodyA == bodyB) {
                // Elements that share a particle touch there by construction.
                for (int p : a)
                    for (int q : b)
                        if (p >= 0 && p == q) return;
            }
            bool meet = false;
            if (m_dimension == 2) {
                meet = segmentsIntersect2d(x + 3 * a[0], x + 3 * a[1], x + 3 * b[0], x + 3 * b[1]);
            } else {
                const double* t1[3] = {x + 3 * a[0], x + 3 * a[1], x + 3 * a[2]};
                const double* t2[3] = {x + 3 * b[0], x + 3 * b[1], x + 3 * b[2]};
                meet = trianglesIntersect(t1, t2);
            }
            if (meet) found = {bodyA, bodyB};
        });
    }
    return found;
}

bool ContactPairs::anyWithin(double reach, const double* x) {
    const GapReport gap = minimumGap(x, reach, reach);
    return gap.gap < reach;
}

std::vector<ContactPairs::Candidate> ContactPairs::candidates(const double* x, double reach) {
    std::vector<Candidate> out;
    forPairs(
        x, reach, [&](int i, int face) { out.push_back({0, i, face}); },
        [&](int e1, int e2) { out.push_back({1, e1, e2}); });
    return out;
}

std::vector<ContactPairs::Candidate> ContactPairs::candidatesByAllPairs(const double* x, double reach) const {
    // Boxes of every element grown by reach against each query, with the same exclusions.
    auto boxOf = [&](auto const& element) {
        std::array<double, 6> box{};
        for (int a = 0; a < 3; ++a) {
            box[static_cast<std::size_t>(a)] = std::numeric_limits<double>::infinity();
            box[static_cast<std::size_t>(a + 3)] = -std::numeric_limits<double>::infinity();
        }
        for (int p : element) {
            if (p < 0) continue;
            for (int a = 0; a < 3; ++a) {
                box[static_cast<std::size_t>(a)] = std::min(box[static_cast<std::size_t>(a)], x[3 * p + a]);
                box[static_cast<std::size_t>(a + 3)] = std::max(box[static_cast<std::size_t>(a + 3)], x[3 * p + a]);
            }
        }
        return box;
    };
    auto meets = [&](const std::array<double, 6>& a, const std::array<double, 6>& b) {
        for (std::size_t k = 0; k < 3; ++k)
            if (a[k] - reach > b[k + 3] || b[k] > a[k + 3] + reach) return false;
        return true;
    };
    std::vector<Candidate> out;
    for (std::size_t i = 0; i < m_vertex.size(); ++i) {
        const int p = m_vertex[i];
        const std::array<double, 6> point{x[3 * p], x[3 * p + 1], x[3 * p + 2], x[3 * p], x[3 * p + 1], x[3 * p + 2]};
        for (std::size_t f = 0; f < m_faces.size(); ++f) {
            if (m_faceBody[f] == m_vertexBody[i] && adjacentVertexFace(p, static_cast<int>(f))) continue;
            if (meets(point, boxOf(m_faces[f]))) out.push_back({0, static_cast<int>(i), static_cast<int>(f)});
        }
    }
    for (std::size_t e = 0; e < m_edges.size(); ++e)
        for (std::size_t o = e + 1; o < m_edges.size(); ++o) {
            if (m_edgeBody[e] == m_edgeBody[o] && adjacentEdges(static_cast<int>(e), static_cast<int>(o))) continue;
            if (meets(boxOf(m_edges[e]), boxOf(m_edges[o]))) out.push_back({1, static_cast<int>(e), static_cast<int>(o)});
        }
    return out;
}

}  // namespace simcore
