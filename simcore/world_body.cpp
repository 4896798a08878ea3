#include "simcore/internal/world_body.h"

#include <limits>
#include <random>

#include "simcore/contact.h"
#include "simcore/scaling.h"
#include "simcore/scenes.h"

namespace simcore {

bool configureForces(ForceModel& forces, const ParameterSet& set, const Params& p, const BodyScale& scale,
                     int dimension, const Eigen::Vector3d& boxCentre) {
    ForceParams& fp = forces.params;
    // The per-spring values this resolution uses (scaling.h; all factors 1 under scaling=thesis
    // and at the reference resolution).
    const auto& f = scale.spring;
    const Params::Forces& table = p.forces;
    fp.stiffness = {table.ks * f[0], 0.0, 0.0};
    fp.damping = {table.kd * f[0], 0.0, 0.0};
    if (set.kind() != SceneKind::Spring1d) {
        fp.stiffness[1] = table.rks * f[1];
        fp.stiffness[2] = table.rks * f[2];
        fp.damping[1] = table.rkd * f[1];
        fp.damping[2] = table.rkd * f[2];
        fp.gasConstant = table.gasConstant;
    }
    const Params::World& world = p.world;
    fp.gravity = world.gravity;
    fp.mks = table.mks;
    fp.mkd = table.mkd;
    fp.mouseRest = table.mouseRest;
    // Contact (contact.h): the walls per axis the body moves along, k, and alpha from e at
    // the reference impact speed.
    const bool projection = world.contact == ContactModel::Projection;
    ContactParams& c = forces.contact;
    c.walls = c.layerBarrier = !projection;
    c.stiffness = world.contactStiffness * scale.contact;
    c.alpha = dampingForRestitution(world.restitution) / world.contactSpeed;
    c.friction = world.friction;
    c.frictionSpeed = world.frictionSpeed;
    for (int axis = 0; axis < 3; ++axis) {
        const bool moves = axis == 1 || (axis == 0 && dimension >= 2) || (axis == 2 && dimension == 3);
        const double infinity = std::numeric_limits<double>::infinity();
        c.low[static_cast<std::size_t>(axis)] = moves ? boxCentre[axis] - world.box : -infinity;
        c.high[static_cast<std::size_t>(axis)] = moves ? boxCentre[axis] + world.box : infinity;
    }
    return projection;
}

Eigen::VectorXd inverseMasses(const Body& body) {
    const int count = body.topology.particleCount();
    Eigen::VectorXd inv3 = Eigen::VectorXd::Zero(3 * Eigen::Index{count});
    for (int i = 0; i < count; ++i) {
        if (body.fixed[static_cast<std::size_t>(i)]) continue;
        const double inv = 1.0 / body.mass[i];
        // 1D moves along y only (thesis 3.3: "restricted to one dimension"); 2D in the xy plane.
        inv3[3 * i + 1] = inv;
        if (body.topology.dimension >= 2) inv3[3 * i] = inv;
        if (body.topology.dimension == 3) inv3[3 * i + 2] = inv;
    }
    return inv3;
}

void perturbStart(const Params::Start& start, const Eigen::VectorXd& inverseMass3, double* x) {
    const double amplitude = start.perturb;
    if (!(amplitude > 0.0)) return;
    // Seeded, so a perturbed run is repeatable; only along the axes the body moves in.
    std::mt19937_64 rng(start.seed);
    std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
    for (Eigen::Index k = 0; k < inverseMass3.size(); ++k)
        if (inverseMass3[k] != 0.0) x[k] += uniform(rng);
}

WorldBody::WorldBody(const ParameterSet& params, const Eigen::Vector3d& position, const Eigen::Vector3d& velocity,
                     int first, const Eigen::Vector3d& boxCentre)
    : m_params(params), m_velocity(velocity), m_p(resolve(params)), m_first(first) {
    ScaledBody scaled = buildScaledBody(params, m_p);
    m_body = std::move(scaled.body);
    m_scale = scaled.scale;
    // Placed: its centroid at the start position.
    const Eigen::Vector3d shift = position - centroid(m_body.positions);
    m_body.positions.colwise() += shift;
    m_forces = ForceModel(&m_body.topology, &m_body.mass, sceneTerms(params.kind()));
    m_forces.prepareContact(m_body.positions.data(), m_body.fixed);
    m_invMass3 = inverseMasses(m_body);
    m_ode = std::make_unique<BodyOde>(m_body, m_forces, m_invMass3);
    m_contactProjection =
        configureForces(m_forces, params, m_p, m_scale, m_body.topology.dimension, boxCentre);
    m_ode->configure(m_contactProjection, m_p.time.substeps);
    m_totalMass = 0.0;
    for (int i = 0; i < count(); ++i)
        if (!m_body.fixed[static_cast<std::size_t>(i)]) m_totalMass += m_body.mass[i];
    const Eigen::Index n = 3 * Eigen::Index{count()};
    m_y.setZero(2 * n + BodyOde::kAux);
    m_dydt.setZero(2 * n + BodyOde::kAux);
    for (auto& s : m_scratch) s.setZero(n);
}

const Eigen::VectorXd& WorldBody::gather(const Eigen::VectorXd& y, Eigen::Index n) {
    const Eigen::Index nb = 3 * Eigen::Index{count()}, at = 3 * Eigen::Index{m_first};
    m_y.head(nb) = y.segment(at, nb);
    m_y.segment(nb, nb) = y.segment(n + at, nb);
    m_y.tail(BodyOde::kAux).setZero();
    return m_y;
}

}  // namespace simcore
