#include "simcore/body.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace simcore {

std::string_view layerName(Layer layer) {
    switch (layer) {
        case Layer::Single: return "single";
        case Layer::Inner: return "inner";
        case Layer::Outer: return "outer";
    }
    return "?";
}

std::string_view springFamilyName(SpringFamily f) {
    switch (f) {
        case SpringFamily::Structural: return "structural";
        case SpringFamily::Radius: return "radius";
        case SpringFamily::Shear: return "shear";
    }
    return "?";
}

namespace {

double distance(const Eigen::Matrix3Xd& p, int i, int j) { return (p.col(j) - p.col(i)).norm(); }

SpringSet& springsOf(Topology& t, SpringFamily f) { return t.springs[static_cast<int>(f)]; }

// Stacks a unit-sphere layer twice (inner scaled to r_in, outer to r_out) and adds the
// springs shared by every two-layer 3D body: structural on the given edges of each layer,
// one radius spring per vertex, two shear springs per edge (out_a, in_b) and (out_b, in_a).
Body twoLayerSphere(const TriangleMesh& mesh, const std::vector<std::array<int, 2>>& edges,
                    double rIn, double rOut, double massInner, double massOuter) {
    if (!(rIn < rOut)) throw std::invalid_argument("radius_inner must be below radius_outer");
    const int n = static_cast<int>(mesh.vertices.cols());
    Body body;
    Topology& t = body.topology;
    t.dimension = 3;
    body.positions.resize(3, 2 * n);
    body.positions.leftCols(n) = mesh.vertices * rIn;
    body.positions.rightCols(n) = mesh.vertices * rOut;
    t.layer.assign(static_cast<std::size_t>(2 * n), Layer::Inner);
    std::fill(t.layer.begin() + n, t.layer.end(), Layer::Outer);
    body.mass.resize(2 * n);
    body.mass.head(n).setConstant(massInner);
    body.mass.tail(n).setConstant(massOuter);
    body.fixed.assign(static_cast<std::size_t>(2 * n), false);

    const auto& p = body.positions;
    for (int layerOffset : {0, n})
        for (auto [a, b] : edges)
            springsOf(t, SpringFamily::Structural)
                .add(layerOffset + a, layerOffset + b,
                     distance(p, layerOffset + a, layerOffset + b));
    for (int v = 0; v < n; ++v) {
        springsOf(t, SpringFamily::Radius).add(v, n + v, distance(p, v, n + v));
        t.layerPairs.push_back({v, n + v});
    }
    for (auto [a, b] : edges) {
        springsOf(t, SpringFamily::Shear).add(n + a, b, distance(p, n + a, b));
        springsOf(t, SpringFamily::Shear).add(n + b, a, distance(p, n + b, a));
    }
    for (Layer l : {Layer::Inner, Layer::Outer}) {
        Surface s;
        s.layer = l;
        const int offset = l == Layer::Inner ? 0 : n;
        s.triangles.reserve(mesh.triangles.size());
        for (auto [a, b, c] : mesh.triangles) s.triangles.push_back({a + offset, b + offset, c + offset});
        s.restVolume = enclosedVolume(s, p.data(), 3);
        t.surfaces.push_back(std::move(s));
    }
    return body;
}

// Interleaves the bits of three 10-bit integers (a Morton / Z-order code).
std::uint32_t mortonCode(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    auto spread = [](std::uint32_t v) {
        v = (v | (v << 16)) & 0x030000FFu;
        v = (v | (v << 8)) & 0x0300F00Fu;
        v = (v | (v << 4)) & 0x030C30C3u;
        v = (v | (v << 2)) & 0x09249249u;
        return v;
    };
    return spread(x) | (spread(y) << 1) | (spread(z) << 2);
}

}  // namespace

void renumberForLocality(TriangleMesh& mesh, std::vector<std::array<int, 2>>* edges) {
    // Sort vertices along a Z-order curve of their positions, so that particles near in space
    // are near in memory and a spring's two ends usually share cache lines.
    const Eigen::Index n = mesh.vertices.cols();
    std::vector<std::pair<std::uint32_t, int>> keyed(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
        const Eigen::Vector3d q = (mesh.vertices.col(i).array() + 1.0) * 0.5 * 1023.0;
        keyed[static_cast<std::size_t>(i)] = {
            mortonCode(static_cast<std::uint32_t>(q.x()), static_cast<std::uint32_t>(q.y()),
                       static_cast<std::uint32_t>(q.z())),
            static_cast<int>(i)};
    }
    std::stable_sort(keyed.begin(), keyed.end());
    std::vector<int> newIndex(static_cast<std::size_t>(n));
    Eigen::Matrix3Xd sorted(3, n);
    for (Eigen::Index k = 0; k < n; ++k) {
        const int old = keyed[static_cast<std::size_t>(k)].second;
        newIndex[static_cast<std::size_t>(old)] = static_cast<int>(k);
        sorted.col(k) = mesh.vertices.col(old);
    }
    mesh.vertices = sorted;
    for (auto& tri : mesh.triangles)
        for (int& v : tri) v = newIndex[static_cast<std::size_t>(v)];
    // Triangles in the order of their lowest vertex, so the gas loop walks memory forward too.
    std::stable_sort(mesh.triangles.begin(), mesh.triangles.end(), [](const auto& a, const auto& b) {
        return std::min({a[0], a[1], a[2]}) < std::min({b[0], b[1], b[2]});
    });
    if (edges) {
        for (auto& e : *edges) {
            e = {newIndex[static_cast<std::size_t>(e[0])], newIndex[static_cast<std::size_t>(e[1])]};
            if (e[0] > e[1]) std::swap(e[0], e[1]);
        }
        std::sort(edges->begin(), edges->end());
    }
}

std::vector<std::array<int, 2>> meshEdges(const std::vector<std::array<int, 3>>& triangles) {
    std::vector<std::array<int, 2>> edges;
    edges.reserve(triangles.size() * 3);
    for (const auto& tri : triangles)
        for (int k = 0; k < 3; ++k) {
            int a = tri[static_cast<std::size_t>(k)], b = tri[static_cast<std::size_t>((k + 1) % 3)];
            edges.push_back({std::min(a, b), std::max(a, b)});
        }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

TriangleMesh subdividedOctahedron(int level) {
    if (level < 0 || level > 9) throw std::invalid_argument("subdivision level out of range");
    std::vector<Eigen::Vector3d> v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                      {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    // Counter-clockwise seen from outside: (b-a)x(c-a) points away from the centre.
    std::vector<std::array<int, 3>> tris = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                            {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int l = 0; l < level; ++l) {
        // Each triangle splits in four at its edge midpoints, projected back onto the sphere;
        // a midpoint shared by two triangles is created once.
        std::map<std::pair<int, int>, int> midpoint;
        auto mid = [&](int a, int b) {
            auto key = std::minmax(a, b);
            auto [it, inserted] = midpoint.try_emplace({key.first, key.second}, 0);
            if (inserted) {
                it->second = static_cast<int>(v.size());
                v.push_back((v[static_cast<std::size_t>(a)] + v[static_cast<std::size_t>(b)]).normalized());
            }
            return it->second;
        };
        std::vector<std::array<int, 3>> next;
        next.reserve(tris.size() * 4);
        for (auto [a, b, c] : tris) {
            const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            next.push_back({a, ab, ca});
            next.push_back({ab, b, bc});
            next.push_back({ca, bc, c});
            next.push_back({ab, bc, ca});
        }
        tris.swap(next);
    }
    TriangleMesh mesh;
    mesh.vertices.resize(3, static_cast<Eigen::Index>(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) mesh.vertices.col(static_cast<Eigen::Index>(i)) = v[i];
    mesh.triangles = std::move(tris);
    return mesh;
}

TriangleMesh latLongSphere(int slices, int stacks) {
    if (slices < 3 || stacks < 2) throw std::invalid_argument("lat/long sphere needs slices >= 3, stacks >= 2");
    // Vertex 0 is the north pole (+y), then (stacks-1) rings of `slices` vertices from north
    // to south, then the south pole. Angles in radians (the 2007 code passed degrees).
    const int rings = stacks - 1;
    const int n = 2 + slices * rings;
    TriangleMesh mesh;
    mesh.vertices.resize(3, n);
    mesh.vertices.col(0) = Eigen::Vector3d(0, 1, 0);
    for (int r = 0; r < rings; ++r) {
        const double theta = std::numbers::pi * (r + 1) / stacks;  // polar angle from +y
        for (int s = 0; s < slices; ++s) {
            const double phi = 2.0 * std::numbers::pi * s / slices;
            mesh.vertices.col(1 + r * slices + s) =
                Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::cos(theta),
                                -std::sin(theta) * std::sin(phi));
        }
    }
    const int south = n - 1;
    mesh.vertices.col(south) = Eigen::Vector3d(0, -1, 0);
    auto ring = [&](int r, int s) { return 1 + r * slices + (s % slices); };
    for (int s = 0; s < slices; ++s) mesh.triangles.push_back({0, ring(0, s), ring(0, s + 1)});
    for (int r = 0; r + 1 < rings; ++r)
        for (int s = 0; s < slices; ++s) {
            // The quad (r,s) (r,s+1) (r+1,s+1) (r+1,s) is planar; two triangles cover it.
            mesh.triangles.push_back({ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)});
            mesh.triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)});
        }
    for (int s = 0; s < slices; ++s)
        mesh.triangles.push_back({south, ring(rings - 1, s + 1), ring(rings - 1, s)});
    return mesh;
}

Body buildSpring1d(const SpringShape& shape, double mass) {
    Body body;
    Topology& t = body.topology;
    t.dimension = 1;
    body.positions.resize(3, 2);
    body.positions.col(0) = Eigen::Vector3d(0, 0, 0);
    body.positions.col(1) = Eigen::Vector3d(0, -shape.initialLength, 0);
    t.layer = {Layer::Single, Layer::Single};
    body.mass = Eigen::VectorXd::Constant(2, mass);
    body.fixed = {shape.fixedEnd, false};
    springsOf(t, SpringFamily::Structural).add(0, 1, shape.restLength);
    return body;
}

Body buildRing2d(const RingShape& shape, double massInner, double massOuter) {
    if (!(shape.radiusInner < shape.radiusOuter))
        throw std::invalid_argument("radius_inner must be below radius_outer");
    const int n = shape.particles;
    Body body;
    Topology& t = body.topology;
    t.dimension = 2;
    body.positions.resize(3, 2 * n);
    for (int i = 0; i < n; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / n;
        const Eigen::Vector3d dir(std::cos(angle), std::sin(angle), 0.0);
        body.positions.col(i) = shape.radiusInner * dir;
        body.positions.col(n + i) = shape.radiusOuter * dir;
    }
    t.layer.assign(static_cast<std::size_t>(2 * n), Layer::Inner);
    std::fill(t.layer.begin() + n, t.layer.end(), Layer::Outer);
    body.mass.resize(2 * n);
    body.mass.head(n).setConstant(massInner);
    body.mass.tail(n).setConstant(massOuter);
    body.fixed.assign(static_cast<std::size_t>(2 * n), false);

    const auto& p = body.positions;
    auto next = [n](int i) { return (i + 1) % n; };
    auto prev = [n](int i) { return (i + n - 1) % n; };
    for (int i = 0; i < n; ++i) springsOf(t, SpringFamily::Structural).add(i, next(i), distance(p, i, next(i)));
    for (int i = 0; i < n; ++i)
        springsOf(t, SpringFamily::Structural).add(n + i, n + next(i), distance(p, n + i, n + next(i)));
    for (int i = 0; i < n; ++i) {
        springsOf(t, SpringFamily::Radius).add(i, n + i, distance(p, i, n + i));
        t.layerPairs.push_back({i, n + i});
    }
    // Shear-left (out_i, in_{i-1}) and shear-right (out_i, in_{i+1}). With n = 3 and fewer
    // this would still be distinct pairs; n >= 3 is enforced by the parameter table.
    for (int i = 0; i < n; ++i) springsOf(t, SpringFamily::Shear).add(n + i, prev(i), distance(p, n + i, prev(i)));
    for (int i = 0; i < n; ++i) springsOf(t, SpringFamily::Shear).add(n + i, next(i), distance(p, n + i, next(i)));

    for (Layer l : {Layer::Inner, Layer::Outer}) {
        Surface s;
        s.layer = l;
        const int offset = l == Layer::Inner ? 0 : n;
        for (int i = 0; i < n; ++i) s.edges.push_back({offset + i, offset + next(i)});
        s.restVolume = enclosedVolume(s, p.data(), 2);
        t.surfaces.push_back(std::move(s));
    }
    for (int i = 0; i < n; ++i) {
        t.fillTriangles.push_back({i, n + i, n + next(i)});
        t.fillTriangles.push_back({i, n + next(i), next(i)});
    }
    return body;
}

Body buildSphere3d(const SphereShape& shape, double massInner, double massOuter) {
    TriangleMesh mesh = subdividedOctahedron(shape.subdivisions);
    renumberForLocality(mesh, nullptr);
    const auto edges = meshEdges(mesh.triangles);
    return twoLayerSphere(mesh, edges, shape.radiusInner, shape.radiusOuter, massInner, massOuter);
}

Body buildLatLongSphere(const LatLongShape& shape, double massInner, double massOuter) {
    TriangleMesh mesh = latLongSphere(shape.slices, shape.stacks);
    // Structural springs run along rings and meridians only (the quads' diagonals are faces
    // for the gas, not springs): the lat/long body is the thesis's "non-uniform" sphere.
    const int slices = shape.slices, rings = shape.stacks - 1;
    const int south = static_cast<int>(mesh.vertices.cols()) - 1;
    auto ring = [&](int r, int s) { return 1 + r * slices + (s % slices); };
    std::vector<std::array<int, 2>> edges;
    for (int s = 0; s < slices; ++s) {
        edges.push_back({0, ring(0, s)});
        for (int r = 0; r < rings; ++r) {
            edges.push_back({std::min(ring(r, s), ring(r, s + 1)), std::max(ring(r, s), ring(r, s + 1))});
            if (r + 1 < rings) edges.push_back({ring(r, s), ring(r + 1, s)});
        }
        edges.push_back({ring(rings - 1, s), south});
    }
    renumberForLocality(mesh, &edges);
    return twoLayerSphere(mesh, edges, shape.radiusInner, shape.radiusOuter, massInner, massOuter);
}

BodySize bodySize(const ParameterSet& params) {
    switch (params.kind()) {
        case SceneKind::Spring1d: return {2, 1, 0};
        case SceneKind::Ring2d: {
            // per layer n particles and n gas edges; springs: 2n structural, n radius, 2n shear
            const long long n = params.getInt(Param::Particles);
            return {2 * n, 5 * n, 2 * n};
        }
        case SceneKind::Sphere3d: {
            // per layer V = 4*4^L + 2, E = 12*4^L, F = 8*4^L; springs: 2E structural, V radius, 2E shear
            const long long q = 1LL << (2 * params.getInt(Param::Subdivisions));
            const long long v = 4 * q + 2, e = 12 * q, f = 8 * q;
            return {2 * v, 4 * e + v, 2 * f};
        }
        case SceneKind::Sphere3dLatLong: {
            // per layer V = 2 + slices(stacks-1), E = slices(2 stacks - 1), F = 2 slices(stacks-1)
            const long long s = params.getInt(Param::Slices), k = params.getInt(Param::Stacks);
            const long long v = 2 + s * (k - 1), e = s * (2 * k - 1), f = 2 * s * (k - 1);
            return {2 * v, 4 * e + v, 2 * f};
        }
    }
    throw std::invalid_argument("unknown scene kind");
}

double memoryBoundBytes(const BodySize& size) {
    // Bytes per particle, spring and face, rounded up from the live heap measured with each
    // integrator (implicit Euler needs the most: its conjugate-gradient vectors).
    constexpr double kPerParticle = 1060.0, kPerSpring = 80.0, kPerFace = 48.0;
    return kPerParticle * double(size.particles) + kPerSpring * double(size.springs) +
           kPerFace * double(size.faces);
}

double memoryBoundBytes(const BodySize& size, std::string_view integrator) {
    constexpr double kCvodePerParticle = 1400.0;
    const bool cvode = integrator.substr(0, 6) == "cvode-";
    return memoryBoundBytes(size) + (cvode ? kCvodePerParticle * double(size.particles) : 0.0);
}

std::optional<std::string> validateShape(const ParameterSet& params, std::string_view integrator) {
    if (params.kind() != SceneKind::Spring1d &&
        !(params.get(Param::RadiusInner) < params.get(Param::RadiusOuter))) {
        std::ostringstream os;
        os << "radius_inner (" << params.get(Param::RadiusInner) << " m) must be below radius_outer ("
           << params.get(Param::RadiusOuter) << " m)";
        return os.str();
    }
    const BodySize size = bodySize(params);
    const double bytes = memoryBoundBytes(size, integrator);
    if (bytes <= kMemoryLimitBytes) return std::nullopt;
    std::string resolution;
    switch (params.kind()) {
        case SceneKind::Ring2d: resolution = "particles=" + std::to_string(params.getInt(Param::Particles)); break;
        case SceneKind::Sphere3d: resolution = "subdivisions=" + std::to_string(params.getInt(Param::Subdivisions)); break;
        case SceneKind::Sphere3dLatLong:
            resolution = "slices=" + std::to_string(params.getInt(Param::Slices)) +
                         ", stacks=" + std::to_string(params.getInt(Param::Stacks));
            break;
        case SceneKind::Spring1d: break;
    }
    // The largest body of this kind within the limit, at its ratio of springs and faces per particle.
    const double perParticle = bytes / double(size.particles);
    std::ostringstream os;
    os.precision(3);
    os << "resolution too large: " << resolution << " gives " << size.particles << " particles and "
       << size.springs << " springs, needing up to " << bytes / (1024.0 * 1024.0 * 1024.0)
       << " GiB; the limit is " << kMemoryLimitBytes / (1024.0 * 1024.0 * 1024.0)
       << " GiB per simulation (about " << static_cast<long long>(kMemoryLimitBytes / perParticle)
       << " particles for this scene" << (integrator.starts_with("cvode-") ? " with " + std::string(integrator) : std::string())
       << ")";
    return os.str();
}

Body buildShape(SceneKind kind, const Params::Shape& s) {
    switch (kind) {
        case SceneKind::Spring1d:
            return buildSpring1d({s.length, s.initialLength, s.fixedEnd}, s.mass);
        case SceneKind::Ring2d:
            return buildRing2d({s.particles, s.radiusInner, s.radiusOuter}, s.massInner, s.massOuter);
        case SceneKind::Sphere3d:
            return buildSphere3d({s.subdivisions, s.radiusInner, s.radiusOuter}, s.massInner, s.massOuter);
        case SceneKind::Sphere3dLatLong:
            return buildLatLongSphere({s.slices, s.stacks, s.radiusInner, s.radiusOuter}, s.massInner, s.massOuter);
    }
    throw std::invalid_argument("unknown scene kind");
}

double enclosedVolume(const Surface& surface, const double* positions, int dimension) {
    double sum = 0.0;
    if (dimension == 2) {
        for (auto [a, b] : surface.edges) {
            const double* pa = positions + 3 * a;
            const double* pb = positions + 3 * b;
            sum += pa[0] * pb[1] - pb[0] * pa[1];
        }
        return 0.5 * sum;
    }
    for (auto [a, b, c] : surface.triangles) {
        Eigen::Map<const Eigen::Vector3d> xa(positions + 3 * a), xb(positions + 3 * b),
            xc(positions + 3 * c);
        sum += xa.dot(xb.cross(xc));
    }
    return sum / 6.0;
}

Eigen::Vector3d centroid(const Eigen::Matrix3Xd& positions) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (Eigen::Index i = 0; i < positions.cols(); ++i) sum += positions.col(i);
    return sum / static_cast<double>(positions.cols());
}

int pickAlongRay(const std::vector<Layer>& layers, const double* x, const Eigen::Vector3d& origin,
                 const Eigen::Vector3d& direction, double maxDistance) {
    int best = -1;
    double bestDistance = maxDistance, bestDepth = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < layers.size(); ++i) {
        if (layers[i] == Layer::Inner) continue;
        const Eigen::Vector3d r = Eigen::Map<const Eigen::Vector3d>(x + 3 * i) - origin;
        const double depth = r.dot(direction);
        if (depth < 0.0) continue;
        const double off = (r - depth * direction).norm();
        // Within the pick radius the particle nearest the eye wins (the front surface).
        if (off <= maxDistance && (depth < bestDepth - 1e-9 * (1.0 + depth))) {
            if (best < 0 || off <= bestDistance || depth < bestDepth) {
                best = static_cast<int>(i);
                bestDepth = depth;
                bestDistance = off;
            }
        }
    }
    return best;
}

}  // namespace simcore
