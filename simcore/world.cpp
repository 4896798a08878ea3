#include "simcore/world.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "simcore/contact.h"
#include "simcore/failure_texts.h"
#include "simcore/integrator_table.h"
#include "simcore/internal/compensated_time.h"
#include "simcore/internal/world_body.h"
#include "simcore/internal/world_ode.h"
#include "simcore/scenes.h"

namespace simcore {

namespace {

// The shortest rest edge of a body's outer layer [m].
double shortestOuterEdge(const Body& body) {
    const Surface* outer = body.topology.surface(Layer::Outer);
    double shortest = std::numeric_limits<double>::infinity();
    if (!outer) return shortest;
    auto edge = [&](int a, int b) { shortest = std::min(shortest, (body.positions.col(a) - body.positions.col(b)).norm()); };
    for (auto [a, b] : outer->edges) edge(a, b);
    for (auto [a, b, c] : outer->triangles) {
        edge(a, b);
        edge(b, c);
        edge(c, a);
    }
    return shortest;
}

}  // namespace

World::World(const WorldSpec& spec, std::string_view integrator)
    : World(std::make_shared<const WorldSpec>(spec), integrator) {}

World::World(std::shared_ptr<const WorldSpec> shared, std::string_view integrator)
    : m_spec(std::move(shared)), m_integrator(makeIntegrator(integrator)) {
    const WorldSpec& spec = *m_spec;
    if (!m_integrator)
        throw std::invalid_argument("unknown integrator '" + std::string(integrator) + "'; allowed: " + integratorNames());
    if (auto error = validateWorld(spec)) throw std::invalid_argument(*error);
    int first = 0;
    for (const WorldBodySpec& b : spec.bodies) {
        m_bodies.push_back(std::make_unique<WorldBody>(b.params, b.position, b.velocity, first, Eigen::Vector3d::Zero()));
        first += m_bodies.back()->count();
    }
    m_n = 3 * Eigen::Index{first};
    for (const auto& b : m_bodies) {
        const auto& layer = b->body().topology.layer;
        m_layers.insert(m_layers.end(), layer.begin(), layer.end());
    }
    const WorldBody& lead = *m_bodies.front();
    m_dimension = lead.body().topology.dimension;
    m_dt = lead.params().time.dt;
    m_box = lead.params().world.box;
    // Body-body contact: the walls' constants (contact.h), the skin a quarter of the shortest
    // outer edge (so that no two elements of one outer layer that are not neighbours are
    // within it at rest), at most 0.1 m.
    std::vector<ContactPairs::Layer> layers;
    double shortest = 0.4;
    double scale = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < m_bodies.size(); ++k) {
        const WorldBody& b = *m_bodies[k];
        layers.push_back({static_cast<int>(k), m_dimension, b.first(), b.body().topology.surface(Layer::Outer)});
        shortest = std::min(shortest, shortestOuterEdge(b.body()));
        scale = std::min(scale, b.scale().contact);
    }
    m_pairs = ContactPairs(layers);
    const Params::World& world = lead.params().world;
    m_contact.skin = 0.25 * shortest;
    m_contact.stiffness = world.contactStiffness * scale;
    m_contact.alpha = dampingForRestitution(world.restitution) / world.contactSpeed;
    m_contact.friction = world.friction;
    m_contact.frictionSpeed = world.frictionSpeed;
    m_ode = std::make_unique<WorldOde>(m_bodies, m_pairs, m_contact, lead.params().time.substeps);
    if (m_integrator->name() == "xpbd")
        if (auto refusal = m_ode->xpbdRefusal()) throw std::invalid_argument(*refusal);
    reset();
}

World::~World() = default;

const Body& World::body(int k) const { return m_bodies[static_cast<std::size_t>(k)]->body(); }
int World::firstParticle(int k) const { return m_bodies[static_cast<std::size_t>(k)]->first(); }
int World::bodyParticles(int k) const { return m_bodies[static_cast<std::size_t>(k)]->count(); }

Eigen::Map<const Eigen::Matrix3Xd> World::positions(int k) const {
    const WorldBody& b = *m_bodies[static_cast<std::size_t>(k)];
    return {m_y.data() + 3 * b.first(), 3, b.count()};
}

Eigen::Map<const Eigen::Matrix3Xd> World::velocities(int k) const {
    const WorldBody& b = *m_bodies[static_cast<std::size_t>(k)];
    return {m_y.data() + m_n + 3 * b.first(), 3, b.count()};
}

void World::setIntegratorOptions(const IntegratorOptions& options) {
    m_options = options;
    m_integrator->setOptions(options);
    if (options.stepDoubling) m_doubling.prepare(m_y.size());
    else m_doubling.release();
}

void World::reset() {
    if (m_held >= 0) m_bodies[static_cast<std::size_t>(bodyOf(m_held))]->forces().pointer = PointerSpring{};
    m_held = -1;
    m_y.setZero(2 * m_n + WorldOde::kAux);
    m_rate.setZero(m_y.size());
    for (const auto& b : m_bodies) {
        const Eigen::Index at = 3 * Eigen::Index{b->first()}, nb = 3 * Eigen::Index{b->count()};
        Eigen::Map<Eigen::Matrix3Xd>(m_y.data() + at, 3, b->count()) = b->body().positions;
        perturbStart(b->params().start, b->inverseMass3(), m_y.data() + at);
        for (Eigen::Index k = 0; k < nb; ++k)
            m_y[m_n + at + k] = b->inverseMass3()[k] != 0.0 ? b->startVelocity()[k % 3] : 0.0;
    }
    m_integrator->prepare(m_ode->layout());
    if (m_options.stepDoubling) m_doubling.prepare(m_y.size());
    m_hNext = m_dt;
    m_jacobianProducts = 0;
    m_failure.reset();
    m_lastError = nullptr;
    m_timeCarry = 0.0;
    m_diag = WorldDiagnostics{};
    m_diag.dt = m_dt;
    measure(m_diag);
    m_diag.initialEnergy = m_diag.total();
    m_lastGood = m_y;
}

OdeSystem& World::odeSystem() { return *m_ode; }

void World::setContactDesignInJacobians(bool on) {
    for (std::size_t k = 0; k < m_bodies.size(); ++k) {
        WorldBody& b = *m_bodies[k];
        b.ode().setContactDesign(on ? std::optional<ContactDesign>(contactDesignOf(
                                          b.forces(), b.body(), b.contactProjection(), positions(static_cast<int>(k))))
                                    : std::nullopt);
    }
}

int World::bodyOf(int particle) const {
    for (std::size_t k = 0; k < m_bodies.size(); ++k)
        if (particle >= m_bodies[k]->first() && particle < m_bodies[k]->first() + m_bodies[k]->count())
            return static_cast<int>(k);
    return -1;
}

void World::setState(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& v, long step, double time) {
    if (x.cols() != particleCount() || v.cols() != particleCount())
        throw std::invalid_argument("the state has " + std::to_string(x.cols()) + " particles; the world has " +
                                    std::to_string(particleCount()));
    m_y.head(m_n) = Eigen::Map<const Eigen::VectorXd>(x.data(), m_n);
    m_y.segment(m_n, m_n) = Eigen::Map<const Eigen::VectorXd>(v.data(), m_n);
    m_y.tail(WorldOde::kAux).setZero();
    m_integrator->prepare(m_ode->layout());
    m_lastError = nullptr;
    m_failure.reset();
    m_timeCarry = 0.0;
    m_diag = WorldDiagnostics{};
    m_diag.dt = m_dt;
    m_diag.step = step;
    m_diag.time = time;
    measure(m_diag);
    m_diag.initialEnergy = m_diag.total();
    m_lastGood = m_y;
}


void World::fail(std::string reason, double t0) {
    m_failure = std::move(reason);
    m_lastError = nullptr;
    m_failedStep = m_diag.step + 1;
    m_failedTime = t0;
    m_y = m_lastGood;
}

bool World::step(double until) {
    if (m_failure) return false;
    const double t0 = m_diag.time;
    m_lastGood = m_y;
    const bool adaptive = m_integrator->adaptive();
    const bool doubling = m_options.stepDoubling && !adaptive;
    double h = m_dt;
    bool clamped = false;
    if (adaptive) {
        // As Simulation::size: no particle crosses a tenth of the box in one adaptive step.
        const double fastest = fastestSpeed();
        h = fastest > 0.0 ? std::min(m_hNext, 0.1 * m_box / fastest) : m_hNext;
        if (until - t0 > 1e-12 * std::max(1.0, std::abs(until)) && t0 + h > until) {
            h = until - t0;
            clamped = true;
        }
    }
    StepReport report;
    bool halved = false;
    for (;;) {
        report = doubling ? m_doubling.step(*m_integrator, *m_ode, t0, h, m_y) : m_integrator->step(*m_ode, t0, h, m_y);
        m_lastError = doubling ? m_doubling.localError() : nullptr;
        if (report.failure) {
            fail(report.failure, t0);
            return false;
        }
        if (!m_y.allFinite()) {
            fail(failure_text::nonFinite(), t0);
            return false;
        }
        // Nothing passes through: a step that ends with two elements crossing does not stand.
        const std::array<int, 2> crossing = m_pairs.intersecting(m_y.data(), 0.0);
        if (crossing[0] < 0) break;
        if (adaptive && 0.5 * report.h >= m_options.minStep) {
            m_y = m_lastGood;
            h = 0.5 * report.h;
            halved = true;
            m_integrator->restart();
            continue;
        }
        fail(failure_text::layersCrossed(std::size_t(crossing[0] + 1), std::size_t(crossing[1] + 1), report.h), t0);
        return false;
    }
    if (adaptive) {
        m_hNext = clamped && report.rejected == 0 ? std::max(m_hNext, report.hNext) : report.hNext;
        if (halved) m_hNext = std::min(m_hNext, report.h);
    }
    WorldDiagnostics next = m_diag;
    measure(next);
    if (std::optional<std::string> why = endFailure(next, report.h)) {
        fail(std::move(*why), t0);
        return false;
    }
    m_diag = std::move(next);
    m_diag.step += 1;
    m_diag.time = advanceTime(t0, report.h, m_timeCarry);
    m_diag.dt = report.h;
    m_diag.errorEstimate = report.errorEstimate;
    if (adaptive && report.errorEstimate >= 0.0) m_lastError = m_integrator->localError();
    m_jacobianProducts += static_cast<std::uint64_t>(report.jacobianProducts);
    m_diag.forceEvaluations = m_bodies.front()->forces().forceEvaluations() + m_jacobianProducts;
    return true;
}

bool World::advanceTo(double tEnd) {
    while (!m_failure && m_diag.time < tEnd - 1e-9 * std::min(m_dt, m_hNext)) step(tEnd);
    return !m_failure;
}

}  // namespace simcore
