#include "simcore/scaling.h"

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace simcore {

namespace {

// The parameters that set a scene's resolution (its Shape keys other than the radii).
bool isResolution(Param id) {
    return id == Param::Particles || id == Param::Subdivisions || id == Param::Slices || id == Param::Stacks;
}

double meanRest(const SpringSet& springs) {
    double sum = 0.0;
    for (double r : springs.rest) sum += r;
    return springs.size() ? sum / static_cast<double>(springs.size()) : 0.0;
}

// Sums of cos^2 and sin^2 of the angle between each spring of a family (at rest) and the
// radial direction at its midpoint (from the body's centre): how much of its stiffness acts
// across the layers (radial) and along them (tangential, i.e. in shear).
struct Orientation {
    double radial = 0.0, tangential = 0.0;
};
Orientation orientation(const Body& body, SpringFamily family) {
    const SpringSet& s = body.topology.family(family);
    const Eigen::Vector3d centre = centroid(body.positions);
    Orientation o;
    for (std::size_t k = 0; k < s.size(); ++k) {
        const Eigen::Vector3d a = body.positions.col(s.a[k]), b = body.positions.col(s.b[k]);
        const Eigen::Vector3d d = (b - a).normalized(), r = (0.5 * (a + b) - centre).normalized();
        const double c = d.dot(r);
        o.radial += c * c;
        o.tangential += 1.0 - c * c;
    }
    return o;
}

int particlesPerLayer(const Topology& topology) {
    return topology.dimension == 1 ? topology.particleCount() : topology.particleCount() / 2;
}

}  // namespace

Scaling scalingOf(const ParameterSet& params) {
    if (!params.has(Param::Scaling)) return Scaling::Thesis;
    return params.get(Param::Scaling) == 1.0 ? Scaling::Thesis : Scaling::Physical;
}

ParameterSet referenceShape(const ParameterSet& params) {
    ParameterSet reference = params;
    for (const ParamSpec* spec : parametersFor(params.kind()))
        if (isResolution(spec->id)) reference.clear(spec->id);
    return reference;
}

std::string resolutionText(const ParameterSet& params) {
    std::string text;
    for (const ParamSpec* spec : parametersFor(params.kind())) {
        if (!isResolution(spec->id)) continue;
        if (!text.empty()) text += ", ";
        text += std::string(spec->key) + "=" + std::to_string(params.getInt(spec->id));
    }
    return text;
}

BodyScale bodyScale(const ParameterSet& params, const Body& body) {
    return bodyScale(params, resolve(params).shape, body);
}

BodyScale bodyScale(const ParameterSet& params, const Params::Shape& shape, const Body& body) {
    BodyScale scale;
    if (scalingOf(params) == Scaling::Thesis) return scale;
    // At the reference resolution every factor is 1 by definition (no arithmetic at all).
    bool atReference = true;
    for (const ParamSpec* spec : parametersFor(params.kind()))
        if (isResolution(spec->id) && params.get(spec->id) != spec->defaultFor(params.kind()))
            atReference = false;
    if (atReference) return scale;

    // The reference body: this shape at the scene's default resolution, unscaled.
    const ParameterSet referenceParams = referenceShape(params);
    Params::Shape referenceShape = shape;
    referenceShape.particles = referenceParams.getInt(Param::Particles);
    referenceShape.subdivisions = referenceParams.getInt(Param::Subdivisions);
    referenceShape.slices = referenceParams.getInt(Param::Slices);
    referenceShape.stacks = referenceParams.getInt(Param::Stacks);
    const Body reference = buildShape(params.kind(), referenceShape);
    const Topology& topology = body.topology;

    const double n = particlesPerLayer(topology), nRef = particlesPerLayer(reference.topology);
    scale.mass = nRef / n;
    scale.contact = nRef / n;
    const auto structural = static_cast<std::size_t>(SpringFamily::Structural);
    if (topology.dimension == 2) {
        // A chain: EA = k L0 is the ring's material constant.
        scale.spring[structural] =
            meanRest(reference.topology.springs[structural]) / meanRest(topology.springs[structural]);
    }  // 3D: a membrane's k per spring does not change with uniform refinement.
    // Between the layers each family keeps the stiffness it is there for: the radius springs
    // their radial stiffness sum k cos^2 (= k * count: they are radial), the shear springs
    // their tangential stiffness sum k sin^2, which carries the inner layer's weight on the
    // body's sides and couples the layers in bending. A shear spring spans one mesh cell
    // across the fixed thickness t, so it turns radial as the cell shrinks (sin^2 ~ h^2 / t^2):
    // kept in shear, it stiffens the radial direction (docs/numerics.md, "Resolution").
    const auto radius = static_cast<std::size_t>(SpringFamily::Radius);
    const auto shear = static_cast<std::size_t>(SpringFamily::Shear);
    if (topology.springs[radius].size())
        scale.spring[radius] = orientation(reference, SpringFamily::Radius).radial /
                               orientation(body, SpringFamily::Radius).radial;
    if (topology.springs[shear].size())
        scale.spring[shear] = orientation(reference, SpringFamily::Shear).tangential /
                              orientation(body, SpringFamily::Shear).tangential;
    return scale;
}

ScaledBody buildScaledBody(const ParameterSet& params, const Params& resolved) {
    if (auto error = validateShape(params)) throw std::invalid_argument(*error);
    ScaledBody scaled{buildShape(params.kind(), resolved.shape), {}};
    scaled.scale = bodyScale(params, resolved.shape, scaled.body);
    // scaling=physical: each layer keeps its total mass when refined.
    if (scaled.scale.mass != 1.0) scaled.body.mass *= scaled.scale.mass;
    return scaled;
}

Body buildBody(const ParameterSet& params) { return buildScaledBody(params, resolve(params)).body; }

BodyValues bodyValues(const ParameterSet& params, const Body& body) {
    const Topology& topology = body.topology;
    BodyValues v;
    v.scale = bodyScale(params, body);
    v.particlesPerLayer = particlesPerLayer(topology);
    // Counted from the reference shape's parameters, without building it (bodySize).
    v.referenceParticlesPerLayer = params.has(Param::Scaling)
                                       ? static_cast<int>(bodySize(referenceShape(params)).particles / 2)
                                       : v.particlesPerLayer;
    const bool layered = topology.dimension > 1;
    v.massInner = (layered ? params.get(Param::MassInner) : params.get(Param::Mass)) * v.scale.mass;
    v.massOuter = (layered ? params.get(Param::MassOuter) : params.get(Param::Mass)) * v.scale.mass;
    v.layerMassInner = layered ? v.massInner * v.particlesPerLayer : 0.0;
    v.layerMassOuter = v.massOuter * v.particlesPerLayer;
    for (int f = 0; f < kSpringFamilyCount; ++f) {
        const auto k = static_cast<std::size_t>(f);
        const bool structural = f == static_cast<int>(SpringFamily::Structural);
        v.stiffness[k] = (structural ? params.get(Param::Ks) : layered ? params.get(Param::Rks) : 0.0) * v.scale.spring[k];
        v.damping[k] = (structural ? params.get(Param::Kd) : layered ? params.get(Param::Rkd) : 0.0) * v.scale.spring[k];
        v.springs[k] = static_cast<int>(topology.springs[k].size());
    }
    v.contactStiffness = params.get(Param::ContactStiffness) * v.scale.contact;
    return v;
}

BodyValues bodyValues(const ParameterSet& params) { return bodyValues(params, buildBody(params)); }

std::string bodyValuesText(const ParameterSet& params, const BodyValues& v) {
    char line[400];
    std::ostringstream os;
    const bool layered = params.kind() != SceneKind::Spring1d;
    if (!layered) {
        std::snprintf(line, sizeof line, "per particle %.6g kg; spring %.6g N/m, %.6g N*s/m", v.massOuter,
                      v.stiffness[0], v.damping[0]);
        return line;
    }
    const bool physical = scalingOf(params) == Scaling::Physical;
    std::snprintf(line, sizeof line, "scaling=%s, %s (%d particles per layer; reference %d).\n",
                  physical ? "physical" : "thesis", resolutionText(params).c_str(), v.particlesPerLayer,
                  v.referenceParticlesPerLayer);
    os << line;
    std::snprintf(line, sizeof line,
                  "per particle: inner %.6g kg, outer %.6g kg (layers %.6g kg and %.6g kg); contact %.6g N/m^3.\n",
                  v.massInner, v.massOuter, v.layerMassInner, v.layerMassOuter, v.contactStiffness);
    os << line;
    std::snprintf(line, sizeof line,
                  "per spring: structural %.6g N/m, %.6g N*s/m (%d); radius %.6g N/m, %.6g N*s/m (%d); "
                  "shear %.6g N/m, %.6g N*s/m (%d).",
                  v.stiffness[0], v.damping[0], v.springs[0], v.stiffness[1], v.damping[1], v.springs[1], v.stiffness[2], v.damping[2], v.springs[2]);
    os << line;
    return os.str();
}

}  // namespace simcore
