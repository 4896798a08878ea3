#include "simcore/forces.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <unordered_map>

#include "simcore/parallel.h"

namespace simcore {

std::string_view termName(Term term) {
    switch (term) {
        case Term::Gravity: return "gravity";
        case Term::Springs: return "springs";
        case Term::Gas: return "gas";
        case Term::Pointer: return "pointer";
        case Term::Collisions: return "collisions";
        case Term::LayerConstraint: return "layer-constraint";
        case Term::Count: break;
    }
    return "?";
}

std::string_view forcePartName(ForcePart part) {
    switch (part) {
        case ForcePart::Gravity: return "gravity";
        case ForcePart::Structural: return "structural springs";
        case ForcePart::Radius: return "radius springs";
        case ForcePart::Shear: return "shear springs";
        case ForcePart::GasInner: return "gas (inner)";
        case ForcePart::GasOuter: return "gas (outer)";
        case ForcePart::Walls: return "wall contact";
        case ForcePart::Barrier: return "layer barrier";
        case ForcePart::Mouse: return "mouse spring";
        case ForcePart::BodyContact: return "contact from other bodies";
        case ForcePart::SelfContact: return "self-contact";
        case ForcePart::Count: break;
    }
    return "?";
}

void addGravity(const Eigen::VectorXd& mass, double g, double* f) {
    const Eigen::Index n = mass.size();
    for (Eigen::Index i = 0; i < n; ++i) f[3 * i + 1] -= mass[i] * g;
}

double addSprings(const SpringSet& springs, double stiffness, double damping, const double* x, const double* v,
                  double* f, int& degenerate) {
    // Spring i-j: d = x_j - x_i, L = |d|, u = d/L,
    //   F_i = [stiffness (L - L0) + damping (v_j - v_i).u] u,  F_j = -F_i.
    // The damper's power damping * ((v_j - v_i).u)^2 is what it removes from the body.
    double power = 0.0;
    const std::size_t count = springs.size();
    const int* ia = springs.a.data();
    const int* ib = springs.b.data();
    const double* rest = springs.rest.data();
    for (std::size_t s = 0; s < count; ++s) {
        const int i = 3 * ia[s], j = 3 * ib[s];
        const double dx = x[j] - x[i], dy = x[j + 1] - x[i + 1], dz = x[j + 2] - x[i + 2];
        const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (length < kDegenerateLength) {
            ++degenerate;  // no direction: contributes nothing rather than a NaN
            continue;
        }
        const double inv = 1.0 / length;
        const double ux = dx * inv, uy = dy * inv, uz = dz * inv;
        const double closing = (v[j] - v[i]) * ux + (v[j + 1] - v[i + 1]) * uy + (v[j + 2] - v[i + 2]) * uz;
        const double magnitude = stiffness * (length - rest[s]) + damping * closing;
        power += damping * closing * closing;
        const double fx = magnitude * ux, fy = magnitude * uy, fz = magnitude * uz;
        f[i] += fx;
        f[i + 1] += fy;
        f[i + 2] += fz;
        f[j] -= fx;
        f[j + 1] -= fy;
        f[j + 2] -= fz;
    }
    return power;
}

double addGas(const Surface& surface, int dimension, double c, const double* x, double* f) {
    const double volume = enclosedVolume(surface, x, dimension);
    if (!(volume > 0.0)) return volume;  // inside out: the caller reports the failure
    const double pressure = c / volume;
    if (dimension == 2) {
        // Edge a->b with the interior on its left: outward normal * length = (dy, -dx).
        // dA/dx_a summed over both edges of a vertex equals P*L*n/2 from each edge.
        const double half = 0.5 * pressure;
        for (auto [a, b] : surface.edges) {
            const double dx = x[3 * b] - x[3 * a], dy = x[3 * b + 1] - x[3 * a + 1];
            f[3 * a] += half * dy;
            f[3 * a + 1] -= half * dx;
            f[3 * b] += half * dy;
            f[3 * b + 1] -= half * dx;
        }
        return volume;
    }
    // Triangle abc: area * normal = (b-a)x(c-a)/2; each corner gets P*A*n/3, i.e.
    // P/6 * (b-a)x(c-a). Summed over a closed surface this is exactly P * dV/dx.
    const double sixth = pressure / 6.0;
    for (auto [a, b, c3] : surface.triangles) {
        Eigen::Map<const Eigen::Vector3d> xa(x + 3 * a), xb(x + 3 * b), xc(x + 3 * c3);
        const Eigen::Vector3d g = sixth * (xb - xa).cross(xc - xa);
        for (int k : {a, b, c3}) {
            f[3 * k] += g.x();
            f[3 * k + 1] += g.y();
            f[3 * k + 2] += g.z();
        }
    }
    return volume;
}

bool pointerForce(const PointerSpring& pointer, double mks, double mkd, double rest,
                  const double* x, const double* v, double* force, double& power) {
    // A spring from the particle p to the anchor r_m (which does not move during a step):
    // d = r_m - x_p, F_p = [mks (L - rest) - mkd v_p.u] u.
    if (!pointer.active || pointer.particle < 0) return false;
    const int p = 3 * pointer.particle;
    const Eigen::Vector3d d = pointer.anchor - Eigen::Vector3d(x[p], x[p + 1], x[p + 2]);
    const double length = d.norm();
    if (length < kDegenerateLength) return false;
    const Eigen::Vector3d u = d / length;
    const double closing = -(v[p] * u.x() + v[p + 1] * u.y() + v[p + 2] * u.z());
    const double magnitude = mks * (length - rest) + mkd * closing;
    for (int axis = 0; axis < 3; ++axis) force[axis] = magnitude * u[axis];
    power = mkd * closing * closing;
    return true;
}

double addPointer(const PointerSpring& pointer, double mks, double mkd, double rest,
                  const double* x, const double* v, double* f) {
    double force[3], power = 0.0;
    if (!pointerForce(pointer, mks, mkd, rest, x, v, force, power)) return 0.0;
    for (int axis = 0; axis < 3; ++axis) f[3 * pointer.particle + axis] += force[axis];
    return power;
}

double springEnergy(const SpringSet& springs, double stiffness, const double* x) {
    double energy = 0.0;
    for (std::size_t s = 0; s < springs.size(); ++s) {
        const int i = 3 * springs.a[s], j = 3 * springs.b[s];
        const double dx = x[j] - x[i], dy = x[j + 1] - x[i + 1], dz = x[j + 2] - x[i + 2];
        const double stretch = std::sqrt(dx * dx + dy * dy + dz * dz) - springs.rest[s];
        energy += stretch * stretch;
    }
    return 0.5 * stiffness * energy;
}

double gasEnergy(double c, double volume) {
    // E = -c ln V, so that -dE/dx = (c/V) dV/dx = P dV/dx: the gas force.
    return volume > 0.0 ? -c * std::log(volume) : 0.0;
}

double pointerEnergy(const PointerSpring& pointer, double mks, double rest, const double* x) {
    if (!pointer.active || pointer.particle < 0) return 0.0;
    const int p = 3 * pointer.particle;
    const double stretch =
        (pointer.anchor - Eigen::Vector3d(x[p], x[p + 1], x[p + 2])).norm() - rest;
    return 0.5 * mks * stretch * stretch;
}

double partialVolume(const Surface& surface, int dimension, const double* x, std::size_t begin,
                     std::size_t end) {
    double sum = 0.0;
    if (dimension == 2) {
        for (std::size_t e = begin; e < end; ++e) {
            const double* pa = x + 3 * surface.edges[e][0];
            const double* pb = x + 3 * surface.edges[e][1];
            sum += pa[0] * pb[1] - pb[0] * pa[1];
        }
        return sum;
    }
    double lane[4] = {0.0, 0.0, 0.0, 0.0};  // independent add chains (see sumLanes)
    for (std::size_t t = begin; t < end; ++t) {
        const double* a = x + 3 * surface.triangles[t][0];
        const double* b = x + 3 * surface.triangles[t][1];
        const double* c = x + 3 * surface.triangles[t][2];
        lane[(t - begin) & 3] += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                                 a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return sum + (lane[0] + lane[1]) + (lane[2] + lane[3]);
}

ForceModel::ForceModel(const Topology* topology, const Eigen::VectorXd* mass, TermSet terms)
    : m_topology(topology), m_mass(mass), m_terms(terms) {
    m_chunks = chunksFor(topology->springCount());
    partition();
    const auto n4 = static_cast<std::size_t>(4 * topology->particleCount());
    m_force4 = kernels::AlignedBuffer(n4);
    if (terms.has(Term::Gas)) {
        m_gradient4 = kernels::AlignedBuffer(n4);
        // Per corner only when each particle lies on at most one surface, of its own layer
        // (each owned range then sums into one layer's volume).
        std::vector<int> on(static_cast<std::size_t>(topology->particleCount()), -1);
        bool own = topology->dimension == 3;
        for (std::size_t s = 0; own && s < topology->surfaces.size(); ++s) {
            const Surface& surface = topology->surfaces[s];
            for (const auto& tri : surface.triangles)
                for (int p : tri) {
                    int& seen = on[static_cast<std::size_t>(p)];
                    own = own && (seen < 0 || seen == static_cast<int>(s)) &&
                          layerSlot(topology->layer[static_cast<std::size_t>(p)]) == layerSlot(surface.layer);
                    seen = static_cast<int>(s);
                }
        }
        if (own) m_fans = kernels::vertexFans(*topology);
    }
}

void ForceModel::partition() {
    // Ownership: a layered body's vertex k belongs to chunk c when perLayer * c / chunks <= k <
    // perLayer * (c + 1) / chunks (in both layers, so radius and most shear springs stay inside
    // one chunk). A spring or face whose particles all belong to one chunk goes to that chunk's
    // list; the rest, few with the Z-order numbering, to the shared list, evaluated after the
    // chunks by one thread. The chunks write disjoint particles of f directly: no per-thread
    // buffers, no reduction.
    const Topology& topo = *m_topology;
    const int n = topo.particleCount();
    const bool layered = !topo.layerPairs.empty();
    const int perLayer = layered ? n / 2 : n;
    auto owner = [&](int p) { return ownerOf(p); };
    m_ownedRanges = {};
    if (m_chunks == 1) {
        // One range per layer: the gas scaling reads one pressure per range.
        m_ownedRanges[0].push_back({0, perLayer});
        if (layered) m_ownedRanges[0].push_back({perLayer, n});
    } else {
        for (int c = 0; c < m_chunks; ++c) {
            const int begin = static_cast<int>(static_cast<long>(perLayer) * c / m_chunks);
            const int end = static_cast<int>(static_cast<long>(perLayer) * (c + 1) / m_chunks);
            m_ownedRanges[static_cast<std::size_t>(c)].push_back({begin, end});
            if (layered) m_ownedRanges[static_cast<std::size_t>(c)].push_back({perLayer + begin, perLayer + end});
        }
    }
    for (auto& part : m_parts) part = Part{};
    // Edge quads first (partitionQuads); the springs not in a quad go to their owners' lists.
    const std::array<std::vector<bool>, kSpringFamilyCount> inQuad = partitionQuads();
    for (int fam = 0; fam < kSpringFamilyCount; ++fam) {
        const SpringSet& springs = topo.springs[static_cast<std::size_t>(fam)];
        for (std::size_t k = 0; k < springs.size(); ++k) {
            if (inQuad[static_cast<std::size_t>(fam)][k]) continue;
            const int oa = owner(springs.a[k]), ob = owner(springs.b[k]);
            Part& part = m_parts[static_cast<std::size_t>(oa == ob ? oa : kChunks)];
            part.springs[static_cast<std::size_t>(fam)].add(springs.a[k], springs.b[k], springs.rest[k]);
        }
    }
    if (layered)
        for (Part& part : m_parts) {
            const SpringSet& radius = part.springs[static_cast<std::size_t>(SpringFamily::Radius)];
            bool run = radius.size() > 0;
            for (std::size_t k = 0; run && k < radius.size(); ++k)
                run = radius.a[k] == radius.a[0] + static_cast<int>(k) && radius.b[k] == radius.a[k] + perLayer;
            part.radiusRun = run;
        }
    partitionSurfaces();
}

// Edge quads (see kernels::QuadSet): an inner structural spring (a, b) whose outer copy (A, B)
// and shear springs (A, b), (B, a) all exist goes, with them, into one quad, in the part of the
// chunk that owns a and b (or the shared part). Returns which springs of each family are in one.
std::array<std::vector<bool>, kSpringFamilyCount> ForceModel::partitionQuads() {
    const Topology& topo = *m_topology;
    const int n = topo.particleCount();
    const bool layered = !topo.layerPairs.empty();
    const int perLayer = layered ? n / 2 : n;
    auto owner = [&](int p) { return ownerOf(p); };
    std::array<std::vector<bool>, kSpringFamilyCount> inQuad;
    for (int fam = 0; fam < kSpringFamilyCount; ++fam)
        inQuad[static_cast<std::size_t>(fam)].assign(topo.springs[static_cast<std::size_t>(fam)].size(), false);
    if (layered) {
        const SpringSet& structural = topo.family(SpringFamily::Structural);
        const SpringSet& shear = topo.family(SpringFamily::Shear);
        auto key = [n](int i, int j) { return static_cast<std::uint64_t>(i) * static_cast<std::uint64_t>(n) + static_cast<std::uint64_t>(j); };
        std::unordered_map<std::uint64_t, std::size_t> structuralAt, shearAt;
        for (std::size_t k = 0; k < structural.size(); ++k) structuralAt.emplace(key(structural.a[k], structural.b[k]), k);
        for (std::size_t k = 0; k < shear.size(); ++k) shearAt.emplace(key(shear.a[k], shear.b[k]), k);
        auto& usedStructural = inQuad[static_cast<std::size_t>(SpringFamily::Structural)];
        auto& usedShear = inQuad[static_cast<std::size_t>(SpringFamily::Shear)];
        for (std::size_t k = 0; k < structural.size(); ++k) {
            const int a = structural.a[k], b = structural.b[k];
            if (a >= perLayer || b >= perLayer) continue;
            const int A = a + perLayer, B = b + perLayer;
            const auto outer = structuralAt.find(key(A, B));
            const auto shearAb = shearAt.find(key(A, b)), shearBa = shearAt.find(key(B, a));
            if (outer == structuralAt.end() || shearAb == shearAt.end() || shearBa == shearAt.end()) continue;
            if (usedStructural[outer->second] || usedShear[shearAb->second] || usedShear[shearBa->second]) continue;
            usedStructural[k] = usedStructural[outer->second] = true;
            usedShear[shearAb->second] = usedShear[shearBa->second] = true;
            // a and A share an owner, as do b and B: the quad is a chunk's when a's and b's are one.
            const int oa = owner(a), ob = owner(b);
            kernels::QuadSet& quads = m_parts[static_cast<std::size_t>(oa == ob ? oa : kChunks)].quads;
            quads.a.push_back(a);
            quads.b.push_back(b);
            quads.rest.push_back({structural.rest[k], structural.rest[outer->second], shear.rest[shearAb->second],
                                  shear.rest[shearBa->second]});
        }
    }
    return inQuad;
}

// Each closed surface's faces (3D triangles, 2D edges) to the chunk owning all their corners,
// or to the shared part.
void ForceModel::partitionSurfaces() {
    const Topology& topo = *m_topology;
    auto owner = [&](int p) { return ownerOf(p); };
    for (const Surface& surface : topo.surfaces) {
        for (auto& part : m_parts) {
            part.surfaces.push_back(Surface{});
            part.surfaces.back().layer = surface.layer;
        }
        for (const auto& tri : surface.triangles) {
            const int o = owner(tri[0]);
            const bool same = owner(tri[1]) == o && owner(tri[2]) == o;
            m_parts[static_cast<std::size_t>(same ? o : kChunks)].surfaces.back().triangles.push_back(tri);
        }
        for (const auto& edge : surface.edges) {
            const int o = owner(edge[0]);
            m_parts[static_cast<std::size_t>(owner(edge[1]) == o ? o : kChunks)].surfaces.back().edges.push_back(edge);
        }
    }
}

int ForceModel::ownerOf(int particle) const {
    if (m_chunks == 1) return 0;
    const int n = m_topology->particleCount();
    const int perLayer = m_topology->layerPairs.empty() ? n : n / 2;
    // The chunk whose range [perLayer * c / chunks, perLayer * (c + 1) / chunks) holds it.
    const long k = particle % perLayer;
    return static_cast<int>((static_cast<long>(m_chunks) * (k + 1) + perLayer - 1) / perLayer - 1);
}

void ForceModel::prepareContact(const double* restPositions, const std::vector<bool>& fixed) {
    const Topology& topo = *m_topology;
    m_contactFree.assign(static_cast<std::size_t>(topo.particleCount()), 1);
    for (std::size_t i = 0; i < fixed.size() && i < m_contactFree.size(); ++i) m_contactFree[i] = fixed[i] ? 0 : 1;
    m_barrierAll.clear();
    for (Part& part : m_parts) part.barrier.clear();
    const Surface* outer = topo.surface(Layer::Outer);
    if (!outer || topo.layerPairs.empty()) return;
    // Each outer vertex's fan: the oriented triangles (o, b, c) around it (3D), or its
    // (previous, next) neighbours along the ring (2D).
    const auto n = static_cast<std::size_t>(topo.particleCount());
    std::vector<std::vector<std::array<int, 2>>> fans(n);
    if (topo.dimension == 2) {
        std::vector<int> previous(n, -1), next(n, -1);
        for (auto [a, b] : outer->edges) {
            next[static_cast<std::size_t>(a)] = b;
            previous[static_cast<std::size_t>(b)] = a;
        }
        for (std::size_t o = 0; o < n; ++o)
            if (previous[o] >= 0 && next[o] >= 0) fans[o].push_back({previous[o], next[o]});
    } else {
        for (auto [a, b, c] : outer->triangles) {
            fans[static_cast<std::size_t>(a)].push_back({b, c});
            fans[static_cast<std::size_t>(b)].push_back({c, a});
            fans[static_cast<std::size_t>(c)].push_back({a, b});
        }
    }
    auto add = [&](LayerBarrierSet& set, int in, int out, double invNorm) {
        set.inner.push_back(in);
        set.outer.push_back(out);
        set.invRestNorm.push_back(invNorm);
        for (const auto& f : fans[static_cast<std::size_t>(out)]) set.fan.push_back(f);
        set.fanStart.push_back(static_cast<int>(set.fan.size()));
    };
    for (auto [in, out] : topo.layerPairs) {
        if (fans[static_cast<std::size_t>(out)].empty()) continue;
        add(m_barrierAll, in, out, 1.0);
        const std::size_t k = m_barrierAll.size() - 1;
        const auto g = layerBarrierNormal(m_barrierAll, k, topo.dimension, restPositions);
        const double norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (!(norm > 0.0)) {  // a degenerate rest fan: no barrier for this pair
            m_barrierAll.inner.pop_back();
            m_barrierAll.outer.pop_back();
            m_barrierAll.invRestNorm.pop_back();
            m_barrierAll.fan.resize(static_cast<std::size_t>(m_barrierAll.fanStart[k]));
            m_barrierAll.fanStart.pop_back();
            continue;
        }
        m_barrierAll.invRestNorm[k] = 1.0 / norm;
        // A chunk evaluates the pair when it owns every particle the pair touches: then its
        // outer vertex's gradient is complete after the chunk's own faces, and the forces land
        // on its own particles only. The shared part takes the rest.
        const int o = ownerOf(out);
        bool own = ownerOf(in) == o;
        for (const auto& [b, c] : fans[static_cast<std::size_t>(out)]) own = own && ownerOf(b) == o && ownerOf(c) == o;
        add(m_parts[static_cast<std::size_t>(own ? o : kChunks)].barrier, in, out, 1.0 / norm);
    }
}

double ForceModel::contactEnergy(const double* x) {
    double energy = 0.0;
    if (contactWalls())
        for (int i = 0; i < m_topology->particleCount(); ++i)
            if (m_contactFree.empty() || m_contactFree[static_cast<std::size_t>(i)]) energy += wallContactEnergy(contact, x + 3 * i);
    if (contactBarrier()) {
        const double* g4 = computeVolumeGradient(x).data();
        for (std::size_t k = 0; k < m_barrierAll.size(); ++k) {
            const double q = layerBarrierDepth(m_barrierAll, k, x, g4);
            if (q > 0.0) energy += 0.25 * contact.stiffness * q * q * q * q;
        }
    }
    return energy;
}

std::size_t ForceModel::quadCount() const {
    std::size_t count = 0;
    for (const Part& part : m_parts) count += part.quads.size();
    return count;
}

int ForceModel::radiusRuns() const {
    return static_cast<int>(std::count_if(m_parts.begin(), m_parts.end(), [](const Part& p) { return p.radiusRun; }));
}

std::size_t ForceModel::sharedElements() const {
    const Part& shared = m_parts[kChunks];
    std::size_t count = shared.springs[0].size() + shared.springs[1].size() + shared.springs[2].size() +
                        4 * shared.quads.size();
    for (const Surface& s : shared.surfaces) count += s.triangles.size() + s.edges.size();
    return count;
}

void ForceModel::accumulatePart(const Part& part, const double* x, const double* v, double* f4, double* g4,
                                Sums& sums) const {
    using kernels::kBlock;
    if (m_terms.has(Term::Springs)) {
        const int perLayer = m_topology->particleCount() / 2;
        constexpr auto kStructural = static_cast<std::size_t>(SpringFamily::Structural);
        constexpr auto kShear = static_cast<std::size_t>(SpringFamily::Shear);
        for (std::size_t b0 = 0; b0 < part.quads.size(); b0 += kBlock) {
            const kernels::QuadSums block = kernels::quadBlock(
                part.quads, b0, std::min(part.quads.size(), b0 + kBlock), perLayer,
                {params.stiffness[kStructural], params.stiffness[kShear]}, {params.damping[kStructural], params.damping[kShear]}, x, v,
                f4, sums.degenerate);
            sums.power += block.power;
            sums.stretch2[kStructural] += block.stretch2[0];
            sums.stretch2[kShear] += block.stretch2[1];
        }
        for (int fam = 0; fam < kSpringFamilyCount; ++fam) {
            const auto k = static_cast<std::size_t>(fam);
            const SpringSet& s = part.springs[k];
            const bool run = part.radiusRun && fam == static_cast<int>(SpringFamily::Radius);
            for (std::size_t b0 = 0; b0 < s.size(); b0 += kBlock) {
                const std::size_t b1 = std::min(s.size(), b0 + kBlock);
                const kernels::SpringSums block =
                    run ? kernels::springRunBlock(s, b0, b1, perLayer, params.stiffness[k], params.damping[k], x, v, f4,
                                                  sums.degenerate)
                        : kernels::springBlock(s, b0, b1, params.stiffness[k], params.damping[k], x, v, f4, sums.degenerate);
                sums.power += block.power;
                sums.stretch2[k] += block.stretch2;
            }
        }
    }
    if (m_terms.has(Term::Gas)) accumulateGas(part, x, g4, sums);
}

void ForceModel::accumulateGas(const Part& part, const double* x, double* g4, Sums& sums) const {
    using kernels::kBlock;
    if (!m_fans.empty()) {
        // Per corner: a chunk writes its own particles' rows whole (the shared part has none).
        const auto chunk = static_cast<std::size_t>(&part - m_parts.data());
        if (chunk >= static_cast<std::size_t>(m_chunks)) return;
        for (auto [begin, end] : m_ownedRanges[chunk]) {
            if (begin == end) continue;
            const auto slot = static_cast<std::size_t>(layerSlot(m_topology->layer[static_cast<std::size_t>(begin)]));
            sums.volume[slot] += kernels::vertexGradients(m_fans, begin, end, x, g4);
        }
        return;
    }
    for (const Surface& s : part.surfaces) {
        // The unscaled gradient dV/dx goes to g4; P = c / V is known only once every part's
        // volume is summed, and scales it afterwards.
        double& sum = sums.volume[static_cast<std::size_t>(layerSlot(s.layer))];
        for (auto [a, b] : s.edges) {
            // 2D edge a->b, interior on the left: dA/dx = (dy, -dx)/2 to each end.
            const double dx = x[3 * b] - x[3 * a], dy = x[3 * b + 1] - x[3 * a + 1];
            sum += x[3 * a] * x[3 * b + 1] - x[3 * b] * x[3 * a + 1];
            g4[4 * a] += 0.5 * dy;
            g4[4 * a + 1] -= 0.5 * dx;
            g4[4 * b] += 0.5 * dy;
            g4[4 * b + 1] -= 0.5 * dx;
        }
        for (std::size_t b0 = 0; b0 < s.triangles.size(); b0 += kBlock)
            sum += kernels::triangleBlock(s, b0, std::min(s.triangles.size(), b0 + kBlock), x, g4);
    }
}

void ForceModel::clearGradient(int chunk) {
    double* g4 = m_gradient4.data();
    for (auto [begin, end] : m_ownedRanges[static_cast<std::size_t>(chunk)]) std::fill(g4 + 4 * begin, g4 + 4 * end, 0.0);
}

kernels::PaddedRows ForceModel::computeVolumeGradient(const double* x) {
    if (!m_terms.has(Term::Gas)) return kernels::PaddedRows();
    finishMotion();  // a held-back last stage reads the gradient about to be overwritten
    std::array<Sums, kChunks + 1> sums{};
    double* g4 = m_gradient4.data();
    runChunks([&](int c) {
        if (m_fans.empty()) clearGradient(c);
        accumulateGas(m_parts[static_cast<std::size_t>(c)], x, g4, sums[static_cast<std::size_t>(c)]);
    });
    accumulateGas(m_parts[kChunks], x, g4, sums[kChunks]);
    return kernels::PaddedRows(g4);
}

std::pair<std::size_t, std::size_t> ForceModel::range(std::size_t count, int chunk, int chunks) {
    const auto c = static_cast<std::size_t>(chunk), n = static_cast<std::size_t>(chunks);
    return {count * c / n, count * (c + 1) / n};
}

template <class F>
void ForceModel::runChunks(F&& task) {
    if (m_pool && m_chunks > 1) {
        m_pool->run(m_chunks, task);
    } else {
        for (int c = 0; c < m_chunks; ++c) task(c);
    }
}

void ForceModel::countTerms() {
    ++m_forceEvaluations;
    for (Term t : {Term::Gravity, Term::Springs, Term::Gas})
        if (m_terms.has(t)) ++m_evaluations[static_cast<std::size_t>(t)];
    if (m_terms.has(Term::Pointer) && pointer.active) ++m_evaluations[static_cast<std::size_t>(Term::Pointer)];
    if (contactWalls()) ++m_evaluations[static_cast<std::size_t>(Term::Collisions)];
    if (contactBarrier()) ++m_evaluations[static_cast<std::size_t>(Term::LayerConstraint)];
}

std::array<double, 2> ForceModel::volumes(const double* x) {
    // Both layers in one dispatch; partial sums combined in chunk order (deterministic).
    const Topology& topo = *m_topology;
    const int dim = topo.dimension;
    std::array<std::array<double, 2>, kChunks> partial{};
    runChunks([&](int c) {
        for (const Surface& s : topo.surfaces) {
            const std::size_t count = dim == 2 ? s.edges.size() : s.triangles.size();
            auto [begin, end] = range(count, c, m_chunks);
            partial[static_cast<std::size_t>(c)][static_cast<std::size_t>(layerSlot(s.layer))] =
                partialVolume(s, dim, x, begin, end);
        }
    });
    std::array<double, 2> volume{};
    for (std::size_t slot = 0; slot < 2; ++slot) {
        double sum = 0.0;
        for (int c = 0; c < m_chunks; ++c) sum += partial[static_cast<std::size_t>(c)][slot];
        volume[slot] = dim == 2 ? 0.5 * sum : sum / 6.0;
    }
    return volume;
}

std::array<double, kSpringFamilyCount> ForceModel::springEnergies(const double* x) {
    std::array<std::array<double, kSpringFamilyCount>, kChunks> partial{};
    runChunks([&](int c) {
        for (int fam = 0; fam < kSpringFamilyCount; ++fam) {
            const SpringSet& s = m_topology->springs[static_cast<std::size_t>(fam)];
            auto [begin, end] = range(s.size(), c, m_chunks);
            double sum = 0.0;
            std::array<double, kernels::kBlock> squared;  // on the stack: nothing allocated
            for (std::size_t b0 = begin; b0 < end; b0 += kernels::kBlock) {
                const std::size_t b1 = std::min(end, b0 + kernels::kBlock);
                for (std::size_t k = b0; k < b1; ++k) {
                    const int i = 3 * s.a[k], j = 3 * s.b[k];
                    const double dx = x[j] - x[i], dy = x[j + 1] - x[i + 1], dz = x[j + 2] - x[i + 2];
                    const double stretch = std::sqrt(dx * dx + dy * dy + dz * dz) - s.rest[k];
                    squared[k - b0] = stretch * stretch;
                }
                sum += kernels::sumLanes(squared.data(), b1 - b0);
            }
            partial[static_cast<std::size_t>(c)][static_cast<std::size_t>(fam)] = sum;
        }
    });
    std::array<double, kSpringFamilyCount> energy{};
    for (int fam = 0; fam < kSpringFamilyCount; ++fam) {
        double sum = 0.0;
        for (int c = 0; c < m_chunks; ++c) sum += partial[static_cast<std::size_t>(c)][static_cast<std::size_t>(fam)];
        energy[static_cast<std::size_t>(fam)] = 0.5 * params.stiffness[static_cast<std::size_t>(fam)] * sum;
    }
    return energy;
}

void ForceModel::evaluate(const double* x, const double* v, double* f, ForceExtras& extras, bool count) {
    evaluateInto(x, v, nullptr, nullptr, f, extras, count, nullptr);
}

void ForceModel::evaluateMotion(const double* x, const double* v, const double* invMass3, double* xdot,
                                double* a, ForceExtras& extras, bool count, const RangeWork* then) {
    evaluateInto(x, v, invMass3, xdot, a, extras, count, then);
}

void ForceModel::evaluateMotionDeferred(const double* x, const double* v, const double* invMass3, double* xdot,
                                        double* a, ForceExtras& extras, bool count, const TaskRef* beside) {
    evaluateInto(x, v, invMass3, xdot, a, extras, count, nullptr, true, beside);
}

bool ForceModel::finishMotion(const RangeWork* then, bool xdot) {
    if (!m_pending.held) return false;
    m_pending.held = false;
    if (!xdot) m_pending.xdot = nullptr;
    lastStage(m_pending, then);
    return true;
}

// Kept whole: the hot path, one force evaluation in its three stages (the chunks' terms, the
// shared elements and the sums in a fixed order, the pressures and the pointer for the last
// stage, which lastStage runs now or later) over the same padded buffers and per-chunk sums;
// read top to bottom it is the algorithm of docs/architecture.md.
void ForceModel::evaluateInto(const double* x, const double* v, const double* invMass3, double* xdot,
                              double* out, ForceExtras& extras, bool count, const RangeWork* then, bool defer,
                              const TaskRef* beside) {
    finishMotion();  // a held-back last stage first: its buffers are about to be overwritten
    const Topology& topo = *m_topology;
    extras = ForceExtras{};
    if (count) countTerms();

    // Stage 1: each chunk starts its own particles at their weight (0, -m g, 0) and adds its
    // own springs, and for the gas its faces' volume and unscaled gradient dV/dx (P = c/V
    // needs the whole volume). Forces and gradients collect in padded buffers (4 doubles per
    // particle).
    const bool gas = m_terms.has(Term::Gas);
    const double g = m_terms.has(Term::Gravity) ? params.gravity : 0.0;
    const double* mass = m_mass->data();
    double* f4 = m_force4.data();
    double* g4 = m_gradient4.data();
    std::array<Sums, kChunks + 1> sums{};  // per chunk, then the shared part
    const bool walls = contactWalls(), barrier = contactBarrier();
    const std::uint8_t* contactFree = m_contactFree.empty() ? nullptr : m_contactFree.data();
    // Layered bodies own their particles in pairs of ranges, inner [b, e) and outer [b + n, e + n):
    // with the barrier on, one pass over each pair of ranges after the chunk's own faces finds
    // both whether any particle is beyond a wall and whether any pair may be beyond its plane
    // (one read of x and g instead of two). Otherwise the walls get their own pass.
    const auto& ranges = m_ownedRanges;
    const bool paired = barrier && topo.layerPairs.size() * 2 == static_cast<std::size_t>(topo.particleCount());
    auto wallForces = [&](Sums& mine, int begin, int end) {
        for (int i = begin; i < end; ++i)
            if (outsideWalls(contact, x + 3 * i) && (!contactFree || contactFree[i]))
                mine.contactEnergy += wallContact(contact, x + 3 * i, v + 3 * i, f4 + 4 * i, mine.contactPower);
    };
    runChunks([&](int c) {
        const auto k = static_cast<std::size_t>(c);
        Sums& mine = sums[k];
        for (auto [begin, end] : ranges[k]) {
            for (int i = begin; i < end; ++i) {
                double* fi = f4 + 4 * i;
                fi[0] = fi[2] = fi[3] = 0.0;
                fi[1] = 0.0 - mass[i] * g;
            }
            // Wall contact: a branch-free pass says whether any particle of the range is
            // beyond a wall (nearly always none); only then the contact pass.
            if (walls && !paired && anyOutsideWalls(contact, x, begin, end)) wallForces(mine, begin, end);
        }
        if (gas && m_fans.empty()) clearGradient(c);
        accumulatePart(m_parts[k], x, v, f4, g4, mine);
        if (paired) {
            const int perLayer = topo.particleCount() / 2;
            bool beyond = false;
            for (auto [begin, end] : ranges[k]) {
                if (begin >= perLayer) continue;  // the outer ranges, scanned with their inner ones
                const PairScan scan = scanPairedRanges(contact, x, g4, begin, end, perLayer);
                beyond = beyond || scan.beyondPlane;
                if (walls && scan.outsideWalls) {
                    wallForces(mine, begin, end);
                    wallForces(mine, begin + perLayer, end + perLayer);
                }
            }
            if (beyond)
                mine.contactEnergy +=
                    layerBarrierForces(m_parts[k].barrier, topo.dimension, contact.stiffness, x, g4, f4, false);
        } else if (barrier) {
            mine.contactEnergy += layerBarrierForces(m_parts[k].barrier, topo.dimension, contact.stiffness, x, g4, f4);
        }
        if (beside) (*beside)(c);
    });
    // Stage 2: the elements shared between chunks, on this thread, in a fixed order.
    accumulatePart(m_parts[kChunks], x, v, f4, g4, sums[kChunks]);
    if (barrier)
        sums[kChunks].contactEnergy +=
            layerBarrierForces(m_parts[kChunks].barrier, topo.dimension, contact.stiffness, x, g4, f4);
    // Sums in a fixed order (chunk 0, chunk 1, shared), whatever the number of threads.
    std::array<double, 2> volumeSum{};
    std::array<double, kSpringFamilyCount> stretch2{};
    auto add = [&](const Sums& part) {
        extras.dampingPower += part.power;
        extras.degenerateSprings += part.degenerate;
        extras.contactEnergy += part.contactEnergy;
        extras.contactPower += part.contactPower;
        for (std::size_t slot = 0; slot < 2; ++slot) volumeSum[slot] += part.volume[slot];
        for (std::size_t fam = 0; fam < stretch2.size(); ++fam) stretch2[fam] += part.stretch2[fam];
    };
    for (int c = 0; c < m_chunks; ++c) add(sums[static_cast<std::size_t>(c)]);
    add(sums[kChunks]);
    for (std::size_t fam = 0; fam < stretch2.size(); ++fam)
        extras.springEnergy[fam] = 0.5 * params.stiffness[fam] * stretch2[fam];
    // The pressures P = c / V of each layer, and what stage 3 (lastStage) needs.
    LastStage last;
    last.v = v;
    last.invMass3 = invMass3;
    last.xdot = xdot;
    last.out = out;
    if (gas) {
        for (const Surface& s : topo.surfaces) {
            const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
            // The sums are 2A (2D), 6V (3D, by faces) or 18V (3D, per corner: each face thrice).
            const double volume = topo.dimension == 2 ? 0.5 * volumeSum[slot]
                                  : m_fans.empty()    ? volumeSum[slot] / 6.0
                                                      : volumeSum[slot] / 18.0;
            extras.volume[slot] = volume;
            last.pressure[slot] = volume > 0.0 ? params.gasConstant[slot] / volume : 0.0;
            extras.pressure[slot] = last.pressure[slot];
        }
    }
    // The mouse spring acts on one particle: its total is redone with the pointer's force
    // added before the division by the mass. Taken now: x and v may be overwritten once the
    // chunks hand their ranges to `then`.
    double pointerF[3], pointerPower = 0.0;
    last.pulled = m_terms.has(Term::Pointer) &&
                          pointerForce(pointer, params.mks, params.mkd, params.mouseRest, x, v, pointerF, pointerPower)
                      ? pointer.particle
                      : -1;
    if (last.pulled >= 0) {
        const int pulled = last.pulled;
        const double p = last.pressure[static_cast<std::size_t>(layerSlot(topo.layer[static_cast<std::size_t>(pulled)]))];
        for (int axis = 0; axis < 3; ++axis) {
            const int k = 3 * pulled + axis;
            const double total = (gas ? f4[4 * pulled + axis] + p * g4[4 * pulled + axis] : f4[4 * pulled + axis]) + pointerF[axis];
            last.pointerOut[static_cast<std::size_t>(axis)] = invMass3 ? total * invMass3[k] : total;
        }
        extras.dampingPower += pointerPower;
    }
    if (defer) {
        last.held = true;
        m_pending = last;
        return;
    }
    lastStage(last, then);
}

// Stage 3: f = F + P dV/dx with P = c / V of each layer (V <= 0: no force; the simulation
// reports the layer as inside out), unpadded into the caller's 3-per-particle layout, and
// xdot = v.
void ForceModel::lastStage(const LastStage& last, const RangeWork* then) {
    const Topology& topo = *m_topology;
    const bool gas = m_terms.has(Term::Gas);
    const double* f4 = m_force4.data();
    const double* g4 = m_gradient4.data();
    const auto n3 = static_cast<std::ptrdiff_t>(3 * topo.particleCount());
    runChunks([&](int c) {
        for (auto [rangeBegin, rangeEnd] : m_ownedRanges[static_cast<std::size_t>(c)]) {
            // Each owned range lies in one layer (see partition()).
            const double p = last.pressure[static_cast<std::size_t>(layerSlot(topo.layer[static_cast<std::size_t>(rangeBegin)]))];
            // In blocks of kStageBlock particles, so that `then` finds the rows just written
            // still in the L1 cache (element-wise work: the blocks change no bit).
            for (int begin = rangeBegin; begin < rangeEnd; begin += kStageBlock) {
                const int end = std::min(rangeEnd, begin + kStageBlock);
                kernels::unpad(f4, gas ? g4 : nullptr, p, last.invMass3, begin, end, last.out);
                if (begin <= last.pulled && last.pulled < end)
                    std::copy(last.pointerOut.begin(), last.pointerOut.end(), last.out + 3 * last.pulled);
                if (last.xdot) std::copy(last.v + 3 * begin, last.v + 3 * end, last.xdot + 3 * begin);
                if (then) {
                    // Without xdot, a's range hands over x's and v's (BodyOde::derivativeMotion).
                    const std::ptrdiff_t first = 3 * begin, length = 3 * (end - begin);
                    if (last.xdot) (*then)(first, length);
                    (*then)(n3 + first, length);
                }
            }
        }
    });
}

void ForceModel::breakdown(int particle, const double* x, const double* v, double* f, ForceBreakdown& out) {
    out = ForceBreakdown{};
    out.particle = particle;
    if (particle < 0 || particle >= m_topology->particleCount()) return;
    const TermSet terms = m_terms;
    const ForceParams full = params;
    const bool walls = contactWalls(), barrier = contactBarrier();  // of the full set
    ForceExtras extras;
    auto force = [&] { return Eigen::Vector3d(f[3 * particle], f[3 * particle + 1], f[3 * particle + 2]); };
    evaluate(x, v, f, extras, false);
    out.total = force();
    // Each part: the model's own terms narrowed to `keep`, the parameters edited by `edit`.
    auto only = [&](ForcePart part, std::initializer_list<Term> keep, auto edit) {
        TermSet narrowed;
        for (Term t : keep) narrowed.set(t, terms.has(t));
        m_terms = narrowed;
        params = full;
        edit(params);
        evaluate(x, v, f, extras, false);
        out[part] = force();
    };
    auto none = [](ForceParams&) {};
    const auto slot = [](ForcePart p) { return static_cast<std::size_t>(p); };
    out.present[slot(ForcePart::Gravity)] = terms.has(Term::Gravity);
    if (terms.has(Term::Gravity)) only(ForcePart::Gravity, {Term::Gravity}, none);
    for (int fam = 0; fam < kSpringFamilyCount; ++fam) {
        const auto part = static_cast<ForcePart>(static_cast<int>(ForcePart::Structural) + fam);
        out.present[slot(part)] = terms.has(Term::Springs) && m_topology->springs[static_cast<std::size_t>(fam)].size() > 0;
        if (!out.has(part)) continue;
        only(part, {Term::Springs}, [fam](ForceParams& p) {
            for (int other = 0; other < kSpringFamilyCount; ++other)
                if (other != fam) p.stiffness[static_cast<std::size_t>(other)] = p.damping[static_cast<std::size_t>(other)] = 0.0;
        });
    }
    for (const Surface& s : m_topology->surfaces) {
        const int layer = layerSlot(s.layer);
        const ForcePart part = layer == 0 ? ForcePart::GasInner : ForcePart::GasOuter;
        out.present[slot(part)] = terms.has(Term::Gas);
        if (!out.has(part)) continue;
        only(part, {Term::Gas}, [layer](ForceParams& p) { p.gasConstant[static_cast<std::size_t>(1 - layer)] = 0.0; });
    }
    out.present[slot(ForcePart::Walls)] = walls;
    if (walls) only(ForcePart::Walls, {Term::Collisions}, none);
    out.present[slot(ForcePart::Barrier)] = barrier;
    // The barrier needs the gas term's volume gradient, not its pressure: nRT = 0 in both layers.
    if (barrier)
        only(ForcePart::Barrier, {Term::Gas, Term::LayerConstraint}, [](ForceParams& p) { p.gasConstant = {0.0, 0.0}; });
    out.present[slot(ForcePart::Mouse)] = terms.has(Term::Pointer);
    if (terms.has(Term::Pointer)) only(ForcePart::Mouse, {Term::Pointer}, none);
    m_terms = terms;
    params = full;
}

void ForceModel::evaluateReference(const double* x, const double* v, double* f, ForceExtras& extras) {
    const Topology& topo = *m_topology;
    std::fill(f, f + 3 * topo.particleCount(), 0.0);
    extras = ForceExtras{};
    countTerms();
    if (m_terms.has(Term::Gravity)) addGravity(*m_mass, params.gravity, f);
    if (m_terms.has(Term::Springs))
        for (int fam = 0; fam < kSpringFamilyCount; ++fam) {
            const auto k = static_cast<std::size_t>(fam);
            extras.dampingPower += addSprings(topo.springs[k], params.stiffness[k], params.damping[k], x, v, f,
                                              extras.degenerateSprings);
        }
    if (m_terms.has(Term::Gas))
        for (const Surface& s : topo.surfaces) {
            const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
            const double volume = addGas(s, topo.dimension, params.gasConstant[slot], x, f);
            extras.volume[slot] = volume;
            extras.pressure[slot] = volume > 0.0 ? params.gasConstant[slot] / volume : 0.0;
        }
    if (m_terms.has(Term::Pointer) && pointer.active)
        extras.dampingPower += addPointer(pointer, params.mks, params.mkd, params.mouseRest, x, v, f);
    if (contactWalls())
        for (int i = 0; i < topo.particleCount(); ++i)
            if (m_contactFree.empty() || m_contactFree[static_cast<std::size_t>(i)])
                extras.contactEnergy += wallContact(contact, x + 3 * i, v + 3 * i, f + 3 * i, extras.contactPower);
    if (contactBarrier()) {
        // The barrier reads g = dV/dx from a padded buffer and writes padded forces.
        const double* g4 = computeVolumeGradient(x).data();
        std::vector<double> f4(static_cast<std::size_t>(4 * topo.particleCount()), 0.0);
        extras.contactEnergy += layerBarrierForces(m_barrierAll, topo.dimension, contact.stiffness, x, g4, f4.data());
        for (int i = 0; i < topo.particleCount(); ++i)
            for (int a = 0; a < 3; ++a) f[3 * i + a] += f4[static_cast<std::size_t>(4 * i + a)];
    }
}

}  // namespace simcore
