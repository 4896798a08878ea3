#include "simcore/world.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "simcore/contact.h"
#include "simcore/integrator_table.h"
#include "simcore/internal/compensated_time.h"
#include "simcore/internal/world_body.h"
#include "simcore/internal/world_ode.h"
#include "simcore/scenes.h"

namespace simcore {

namespace {

// clang-format off
constexpr std::array kWorldScenes = {
    WorldSceneInfo{"collide2d", "2D: two two-layer rings thrown at each other head-on (offset: their centres apart "
                                "across the line of approach)"},
    WorldSceneInfo{"collide3d", "3D: two two-layer spheres thrown at each other head-on (offset: their centres "
                                "apart across the line of approach)"},
    WorldSceneInfo{"stack3d", "3D: three spheres dropped one above the other onto the floor"},
};
// clang-format on

std::string number(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

std::string bodyName(std::size_t k) { return "body" + std::to_string(k + 1); }

void setAll(WorldSpec& spec, Param id, double value) {
    for (auto& b : spec.bodies) (void)b.params.set(id, value);
}

// The start vector keys: (which vector, axis).
std::optional<std::pair<int, int>> startVector(std::string_view key) {
    constexpr std::array<std::string_view, 6> keys = {"position_x", "position_y", "position_z",
                                                      "velocity_x", "velocity_y", "velocity_z"};
    for (std::size_t k = 0; k < keys.size(); ++k)
        if (keys[k] == key) return std::pair<int, int>{static_cast<int>(k / 3), static_cast<int>(k % 3)};
    return std::nullopt;
}

int dimensionOf(SceneKind kind) {
    switch (kind) {
        case SceneKind::Spring1d: return 1;
        case SceneKind::Ring2d: return 2;
        default: return 3;
    }
}

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

std::span<const WorldSceneInfo> worldSceneTable() { return kWorldScenes; }

std::optional<WorldSpec> worldScene(std::string_view name) {
    WorldSpec spec;
    spec.name = std::string(name);
    if (name == "collide2d" || name == "collide3d") {
        const SceneKind kind = name == "collide2d" ? SceneKind::Ring2d : SceneKind::Sphere3d;
        for (int k = 0; k < 2; ++k) {
            WorldBodySpec b;
            b.params = ParameterSet(kind);
            const double side = k == 0 ? -1.0 : 1.0;
            b.position = Eigen::Vector3d(3.0 * side, 0.0, 0.0);
            b.velocity = Eigen::Vector3d(-2.0 * side, 0.0, 0.0);
            spec.bodies.push_back(b);
        }
        // Weightless bodies at 2 m/s stay clear of the walls for well over 2 s.
        setAll(spec, Param::Box, 10.0);
        return spec;
    }
    if (name == "stack3d") {
        for (int k = 0; k < 3; ++k) {
            WorldBodySpec b;
            b.params = ParameterSet(SceneKind::Sphere3d);
            b.position = Eigen::Vector3d(0.0, -4.8 + 4.3 * k, 0.0);
            spec.bodies.push_back(b);
        }
        setAll(spec, Param::Box, 7.0);
        return spec;
    }
    return std::nullopt;
}

bool isWorldParameter(Param id) {
    switch (paramSpec(id).group) {
        case ParamGroup::Environment:
        case ParamGroup::Contact:
        case ParamGroup::Pointer:
        case ParamGroup::Time: return true;
        default: return false;
    }
}

bool isStartVectorKey(std::string_view key) { return startVector(key).has_value(); }

std::optional<std::string> assignWorld(WorldSpec& spec, std::string_view assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string_view::npos)
        return "expected bodyN.key=value or key=value, got " + quoteShort(assignment);
    std::string_view lhs = assignment.substr(0, eq);
    const std::string_view text = assignment.substr(eq + 1);
    const std::size_t count = spec.bodies.size();
    // bodyN. prefix: one body, numbered from 1.
    std::optional<std::size_t> only;
    if (lhs.starts_with("body")) {
        const auto dot = lhs.find('.');
        const std::string_view digits = lhs.substr(4, dot == std::string_view::npos ? std::string_view::npos : dot - 4);
        const bool numeric = !digits.empty() && digits.size() <= 6 &&
                             std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (numeric && dot != std::string_view::npos) {
            const auto n = static_cast<std::size_t>(std::stoul(std::string(digits)));
            lhs = lhs.substr(dot + 1);
            if (n < 1 || n > count)
                return "body" + std::to_string(n) + "." + std::string(lhs.substr(0, 40)) + ": the scene has " +
                       std::to_string(count) + " bodies (body1 to body" + std::to_string(count) + ")";
            only = n - 1;
        }
    }
    // The key as typed when it is a plain name, else quoted (and cut) for the message.
    const bool plain = lhs.size() <= 40 && std::all_of(lhs.begin(), lhs.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    });
    const std::string key = plain ? std::string(lhs) : quoteShort(lhs);
    const std::string where = only ? bodyName(*only) + "." + key : key;
    if (lhs == "offset") {
        if (only) return where + ": offset belongs to the scene, not to one body; set it without a prefix";
        if (count != 2 || !(spec.name == "collide2d" || spec.name == "collide3d"))
            return "offset: only collide2d and collide3d have it (their centres apart across the line of approach)";
        const auto value = parseNumber(text);
        if (!value || std::abs(*value) > 1e3) return "offset: " + quoteShort(text) + " is not a number in [-1000, 1000] m";
        spec.bodies[0].position.y() = -0.5 * *value;
        spec.bodies[1].position.y() = 0.5 * *value;
        return std::nullopt;
    }
    if (const auto vector = startVector(lhs)) {
        const auto value = parseNumber(text);
        if (!value || std::abs(*value) > 1e6)
            return where + ": " + quoteShort(text) + " is not a number in [-1e6, 1e6] " +
                   (vector->first == 0 ? "m" : "m/s");
        for (std::size_t k = 0; k < count; ++k) {
            if (only && k != *only) continue;
            if (vector->second == 2 && dimensionOf(spec.bodies[k].params.kind()) < 3 && *value != 0.0)
                return bodyName(k) + "." + std::string(lhs) + ": a 2D body moves in the xy plane (z stays 0)";
            Eigen::Vector3d& v = vector->first == 0 ? spec.bodies[k].position : spec.bodies[k].velocity;
            v[vector->second] = *value;
        }
        return std::nullopt;
    }
    const ParamSpec* param = findParam(lhs);
    if (!param) {
        const std::string message = *ParameterSet(spec.bodies.front().params.kind()).set(lhs, 0.0);
        return (only ? bodyName(*only) + ": " : std::string()) + message +
               " position_x position_y position_z velocity_x velocity_y velocity_z";
    }
    if (only && isWorldParameter(param->id))
        return where + ": " + std::string(param->key) +
               " is a world parameter, shared by every body; set it without a body prefix";
    bool any = false;
    for (std::size_t k = 0; k < count; ++k) {
        if (only && k != *only) continue;
        ParameterSet& set = spec.bodies[k].params;
        if (!set.has(param->id)) {
            if (only) return bodyName(k) + ": " + *set.setFromText(lhs, text);
            continue;
        }
        if (auto error = set.setFromText(lhs, text)) return (count > 1 ? bodyName(k) + ": " : std::string()) + *error;
        any = true;
    }
    if (!any) return std::string(lhs) + ": no body of this scene has it";
    return std::nullopt;
}

std::optional<std::string> validateWorld(const WorldSpec& spec) {
    const std::size_t count = spec.bodies.size();
    if (count < 1) return std::string("a world needs at least one body");
    if (count > static_cast<std::size_t>(kMaxBodies))
        return "the scene has " + std::to_string(count) + " bodies; at most " + std::to_string(kMaxBodies);
    const int dimension = dimensionOf(spec.bodies.front().params.kind());
    for (std::size_t k = 0; k < count; ++k) {
        const ParameterSet& set = spec.bodies[k].params;
        if (dimensionOf(set.kind()) == 1)
            return bodyName(k) + ": a spring1d body cannot share a world (bodies are two-layer rings or spheres)";
        if (dimensionOf(set.kind()) != dimension)
            return bodyName(k) + ": a " + std::to_string(dimensionOf(set.kind())) + "D body in a " +
                   std::to_string(dimension) + "D world (every body of a world lives in the same space)";
        if (auto error = validateShape(set)) return bodyName(k) + ": " + *error;
        if (resolve(set).world.contact == ContactModel::Projection)
            return bodyName(k) +
                   ": contact = projection is the one-body thesis program; a world of several bodies takes "
                   "contact = force (bodies meet through a force in the ODE)";
    }
    const double box = resolve(spec.bodies.front().params).world.box;
    auto radius = [&](std::size_t k) { return resolve(spec.bodies[k].params).shape.radiusOuter; };
    for (std::size_t k = 0; k < count; ++k) {
        const Eigen::Vector3d& p = spec.bodies[k].position;
        for (int axis = 0; axis < dimension; ++axis)
            if (std::abs(p[axis]) + radius(k) > box)
                return bodyName(k) + " sticks out of the box at the start: outer radius " + number(radius(k)) +
                       " m around " + "xyz"[axis] + " = " + number(p[axis]) + " m, walls at +-" + number(box) + " m";
    }
    // The contact skin is at most 0.1 m (World): bodies closer than that at the start would
    // start inside each other's barrier.
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t j = i + 1; j < count; ++j) {
            const double apart = (spec.bodies[i].position - spec.bodies[j].position).norm();
            if (apart < radius(i) + radius(j) + 0.1)
                return "bodies " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                       " overlap at the start: centres " + number(apart) + " m apart, outer radii " +
                       number(radius(i)) + " m and " + number(radius(j)) + " m (at least 0.1 m between them)";
        }
    return std::nullopt;
}

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

int World::pickAlongRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double maxDistance) const {
    return simcore::pickAlongRay(m_layers, m_y.data(), origin, direction, maxDistance);
}

Eigen::Vector3d World::anchor() const {
    if (m_held < 0) return Eigen::Vector3d::Zero();
    return m_bodies[static_cast<std::size_t>(bodyOf(m_held))]->forces().pointer.anchor;
}

// The pointer spring of body k becomes `pointer`: the change of its energy is the pointer's
// work (as Simulation::grab); the method restarts (the force changed between steps).
void World::pointerChanged(const PointerSpring& pointer, int body) {
    if (m_failure) return;
    const double before = m_diag.pointer;
    m_bodies[static_cast<std::size_t>(body)]->forces().pointer = pointer;
    m_integrator->restart();
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

void World::grab(int particle, const Eigen::Vector3d& anchor) {
    const int body = bodyOf(particle);
    if (body < 0 || m_failure) return;
    if (m_held >= 0) release();
    pointerChanged(PointerSpring{true, particle - m_bodies[static_cast<std::size_t>(body)]->first(), anchor}, body);
    m_held = particle;
}

void World::moveAnchor(const Eigen::Vector3d& anchor) {
    if (m_held < 0) return;
    const int body = bodyOf(m_held);
    PointerSpring pointer = m_bodies[static_cast<std::size_t>(body)]->forces().pointer;
    pointer.anchor = anchor;
    pointerChanged(pointer, body);
}

void World::release() {
    if (m_held < 0) return;
    const int body = bodyOf(m_held);
    m_held = -1;
    pointerChanged(PointerSpring{}, body);
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

ForceBreakdown World::forceBreakdown(int particle) {
    ForceBreakdown out;
    const int k = bodyOf(particle);
    if (k < 0) return out;
    WorldBody& b = *m_bodies[static_cast<std::size_t>(k)];
    const Eigen::Index at = 3 * Eigen::Index{b.first()};
    m_breakdownScratch.setZero(m_n);
    b.forces().breakdown(particle - b.first(), m_y.data() + at, m_y.data() + m_n + at, m_breakdownScratch.data(), out);
    out.particle = particle;
    // The pairs' parts, as WorldOde adds them to the bodies' forces.
    auto pairs = [&](ForcePart part, ContactPairs::Which which) {
        m_breakdownScratch.setZero(m_n);
        m_pairs.addForces(m_contact, m_y.data(), m_y.data() + m_n, m_breakdownScratch.data(), which);
        out[part] = m_breakdownScratch.segment<3>(3 * Eigen::Index{particle});
        out.present[static_cast<std::size_t>(part)] = true;
        out.total += out[part];
    };
    if (bodyCount() > 1) pairs(ForcePart::BodyContact, ContactPairs::Which::BetweenBodies);
    pairs(ForcePart::SelfContact, ContactPairs::Which::Self);
    return out;
}

void World::currentForces(double* f) {
    Eigen::VectorXd rate(m_y.size());
    m_ode->compute(m_y, rate, false);
    const Eigen::VectorXd& mass = m_ode->coordinateMass();
    for (Eigen::Index k = 0; k < m_n; ++k) f[k] = mass.size() == m_n ? mass[k] * rate[m_n + k] : 0.0;
}

double World::energyErrorBand() {
    if (!m_lastError || m_failure) return -1.0;
    WorldDiagnostics at, off;
    measure(at);
    m_errorScratch = m_y;
    m_y += Eigen::Map<const Eigen::VectorXd>(m_lastError, m_y.size());
    measure(off);
    m_y = m_errorScratch;  // exactly the state it was (m_y keeps its buffer)
    const double band = std::abs(off.total() - at.total());
    return std::isfinite(band) ? band : -1.0;
}

std::size_t WorldSnapshot::bytes() const {
    return sizeof(WorldSnapshot) + sizeof(double) * (std::size_t(y.size()) + integratorHistory.capacity()) +
           sizeof(BodyDiagnostics) * diag.bodies.capacity() + sizeof(ForceModel::Counters) * counters.capacity() +
           integrator.capacity() + (failure ? failure->capacity() : 0);
}

WorldSnapshot World::snapshot() const {
    WorldSnapshot s;
    s.spec = m_spec;
    s.integrator = std::string(m_integrator->name());
    s.options = m_options;
    s.integratorHistory = m_integrator->history();
    s.integratorRestorable = m_integrator->restorable();
    s.y = m_y;
    s.diag = m_diag;
    s.timeCarry = m_timeCarry;
    s.hNext = m_hNext;
    s.failure = m_failure;
    s.failedStep = m_failedStep;
    s.failedTime = m_failedTime;
    s.held = m_held;
    s.anchor = anchor();
    for (const auto& b : m_bodies) s.counters.push_back(b->forces().counters());
    s.jacobianProducts = m_jacobianProducts;
    return s;
}

void World::restore(const WorldSnapshot& s, bool sameSpecOnly) {
    if (sameSpecOnly && s.spec != m_spec) throw std::invalid_argument("the snapshot is of another world");
    if (s.y.size() != m_y.size() || s.counters.size() != m_bodies.size())
        throw std::invalid_argument("the snapshot is of a world of other bodies");
    const bool sameMethod = m_integrator->name() == s.integrator;
    setIntegratorOptions(s.options);
    if (sameMethod) m_integrator->setHistory(s.integratorHistory);
    else m_integrator->prepare(m_ode->layout());
    if (!sameMethod || !s.integratorRestorable || !m_integrator->restorable()) m_integrator->restart();
    m_y = s.y;
    m_lastGood = s.y;
    m_lastError = nullptr;
    m_timeCarry = s.timeCarry;
    m_hNext = sameMethod ? s.hNext : m_dt;
    m_failure = s.failure;
    m_failedStep = s.failedStep;
    m_failedTime = s.failedTime;
    for (std::size_t k = 0; k < m_bodies.size(); ++k) {
        m_bodies[k]->forces().pointer = PointerSpring{};
        m_bodies[k]->forces().setCounters(s.counters[k]);
    }
    m_held = s.held;
    if (m_held >= 0) {
        const int body = bodyOf(m_held);
        m_bodies[static_cast<std::size_t>(body)]->forces().pointer =
            PointerSpring{true, m_held - m_bodies[static_cast<std::size_t>(body)]->first(), s.anchor};
    }
    m_jacobianProducts = s.jacobianProducts;
    m_diag = s.diag;
    if (!sameSpecOnly) {  // this world's values (gravity, gas ...) at the same state
        // What the edit added to the energy (a mass, a gas constant, gravity ...) is the
        // edit's, as one body's W_edits: the drift goes on where it was.
        const double before = m_diag.total();
        measure(m_diag);
        m_diag.initialEnergy += m_diag.total() - before;
        m_diag.forceEvaluations += m_jacobianProducts;
    }
}

void World::measure(WorldDiagnostics& d) {
    const double* x = m_y.data();
    const double* v = m_y.data() + m_n;
    d.bodies.resize(m_bodies.size());
    d.kinetic = d.gravity = d.gas = d.contact = d.pointer = 0.0;
    d.spring = {};
    d.momentum.setZero();
    d.angularMomentum.setZero();
    // One uncounted evaluation of the world: the bodies' energies and volumes, the pairs' energy.
    m_ode->compute(m_y, m_rate, false);
    for (std::size_t k = 0; k < m_bodies.size(); ++k) {
        WorldBody& b = *m_bodies[k];
        BodyDiagnostics& out = d.bodies[k];
        const ForceExtras& extras = m_ode->extras()[k];
        for (std::size_t f = 0; f < 3; ++f) d.spring[f] += extras.springEnergy[f];
        d.contact += extras.contactEnergy;
        const bool gas = b.forces().terms().has(Term::Gas);
        out.volume = out.restVolume = out.pressure = {};
        if (gas)
            for (const Surface& s : b.body().topology.surfaces) {
                const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
                out.volume[slot] = extras.volume[slot];
                out.restVolume[slot] = s.restVolume;
                out.pressure[slot] = extras.pressure[slot];
                d.gas += gasEnergy(b.forces().params.gasConstant[slot], extras.volume[slot]);
            }
        const double g = b.forces().terms().has(Term::Gravity) ? b.forces().params.gravity : 0.0;
        Eigen::Vector3d moment = Eigen::Vector3d::Zero(), momentum = Eigen::Vector3d::Zero();
        double mass = 0.0, kinetic = 0.0;
        for (int i = 0; i < b.count(); ++i) {
            if (b.body().fixed[static_cast<std::size_t>(i)]) continue;
            const int w = b.first() + i;
            const double m = b.body().mass[i];
            const Eigen::Map<const Eigen::Vector3d> xi(x + 3 * w), vi(v + 3 * w);
            mass += m;
            moment += m * xi;
            momentum += m * vi;
            kinetic += 0.5 * m * vi.squaredNorm();
            d.gravity += m * g * xi.y();
            d.angularMomentum += xi.cross(m * vi);
        }
        out.mass = mass;
        out.kinetic = kinetic;
        out.com = mass > 0.0 ? Eigen::Vector3d(moment / mass) : Eigen::Vector3d::Zero();
        out.velocity = mass > 0.0 ? Eigen::Vector3d(momentum / mass) : Eigen::Vector3d::Zero();
        d.kinetic += kinetic;
        d.momentum += momentum;
        const PointerSpring& pointer = b.forces().pointer;
        if (pointer.active)
            d.pointer += pointerEnergy(pointer, b.forces().params.mks, b.forces().params.mouseRest, x + 3 * b.first());
    }
    d.contactPairs = m_ode->pairSums().energy;
    d.contact += d.contactPairs;
    const GapReport gap = m_pairs.minimumGap(x, m_contact.skin, gapRange());
    d.minGap = std::min(gap.gap, gapRange());
    d.minGapBodies = gap.gap < gapRange() ? std::array<int, 2>{gap.bodyA, gap.bodyB} : std::array<int, 2>{-1, -1};
    d.removedDamping = m_y[2 * m_n];
    d.removedContact = m_y[2 * m_n + 1];
    d.forceEvaluations = m_bodies.front()->forces().forceEvaluations();
    d.contactPairsActive = m_ode->pairSums().pairs;
}

void World::fail(std::string reason, double t0) {
    m_failure = std::move(reason);
    m_lastError = nullptr;
    m_failedStep = m_diag.step + 1;
    m_failedTime = t0;
    m_y = m_lastGood;
}

double World::fastestSpeed() const {
    double fastest = 0.0;
    for (Eigen::Index i = 0; i < m_n / 3; ++i) fastest = std::max(fastest, m_y.segment(m_n + 3 * i, 3).norm());
    return fastest;
}

std::optional<std::string> World::endFailure(const WorldDiagnostics& next, double h) const {
    // Checks: speed, then the shapes.
    const double fastest = fastestSpeed();
    if (fastest * h > 2.0 * m_box || !std::isfinite(next.total())) {
        std::ostringstream why;
        why << "runaway velocity: a particle moves " << fastest << " m/s, farther than the whole box in one step";
        return why.str();
    }
    for (std::size_t k = 0; k < m_bodies.size(); ++k)
        for (const Surface& s : m_bodies[k]->body().topology.surfaces) {
            const double volume = next.bodies[k].volume[static_cast<std::size_t>(layerSlot(s.layer))];
            if (volume <= 0.01 * s.restVolume) {
                std::ostringstream why;
                why << "body " << k + 1 << ": the " << layerName(s.layer) << " layer "
                    << (volume <= 0.0 ? "turned inside out" : "collapsed") << " (its "
                    << (m_dimension == 2 ? "area" : "volume") << " is " << volume << ", rest " << s.restVolume << ")";
                return why.str();
            }
        }
    return std::nullopt;
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
            fail("the state became non-finite (NaN or infinity): the step is far too large for these forces", t0);
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
        std::ostringstream why;
        if (crossing[0] == crossing[1])
            why << "body " << crossing[0] + 1 << "'s outer layer passed through itself";
        else
            why << "bodies " << crossing[0] + 1 << " and " << crossing[1] + 1 << " intersect (their outer layers crossed)";
        why << " in a step of " << report.h << " s: the step is too large for this impact (a smaller dt, or an "
            << "adaptive integrator, which halves such a step)";
        fail(why.str(), t0);
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
