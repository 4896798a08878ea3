#include "simulation.h"

#include "jacobians.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace simcore {

// The ODE the integrators see: y = [x | v | E_damp | E_contact],
// dy/dt = [v | F/m | P_damp | P_contact] (the powers removed by damping and by contact).
class Simulation::System final : public OdeSystem {
public:
    explicit System(Simulation& sim) : m_sim(sim) {}
    StateLayout layout() const override { return {m_sim.m_n, kAux}; }
    void derivative(double /*t*/, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) override {
        if (!takeOffered(y, dydt)) compute(y, dydt, m_extras, true);
    }
    void derivative(double /*t*/, const Eigen::VectorXd& y, Eigen::VectorXd& dydt, RangeWork then) override {
        if (takeOffered(y, dydt))
            inPieces(dydt.size(), then);
        else
            compute(y, dydt, m_extras, true, &then);
    }
    // The end-of-step measurement already evaluated f at the state this step starts from:
    // the integrator's first stage takes it (counted as the evaluation it is).
    bool takeOffered(const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
        if (!m_offered) return false;
        Eigen::VectorXd* offered = std::exchange(m_offered, nullptr);
        if (&y != &m_sim.m_y) return false;
        dydt.swap(*offered);  // no copy: the two buffers trade places
        m_extras = m_sim.m_endExtras;
        m_sim.m_forces.countReusedEvaluation();
        return true;
    }
    // dy/dt at y into dydt, with the force by-products; counted as a force evaluation or not.
    // With `then`, the chunks run it on their ranges of dydt as they finish them.
    void compute(const Eigen::VectorXd& y, Eigen::VectorXd& dydt, ForceExtras& extras, bool count,
                 const RangeWork* then = nullptr) {
        const Eigen::Index n = m_sim.m_n;
        m_sim.m_forces.evaluateMotion(y.data(), y.data() + n, m_sim.m_invMass3.data(), dydt.data(),
                                      dydt.data() + n, extras, count, then);
        dydt[2 * n] = extras.dampingPower;
        dydt[2 * n + 1] = extras.contactPower;
        if (then) (*then)(2 * n, kAux);
    }
    int pieces() const override { return m_sim.m_pool ? m_sim.m_pool->threads() : 1; }
    void runPieces(TaskRef task) override {
        if (m_sim.m_pool)
            m_sim.m_pool->run(m_sim.m_pool->threads(), task);
        else
            task(0);
    }
    // Offers dy/dt at the simulation's current state to the next derivative() call (taken if
    // that call is at the current state; withdrawn either way); nullptr withdraws it.
    void offer(Eigen::VectorXd* dydt) { m_offered = dydt; }
    const ForceExtras& extras() const { return m_extras; }

    // --- Jacobians for implicit integrators (kernels in jacobians.h) ---
    bool hasForceJacobian() const override { return true; }
    void linearize(double /*t*/, const Eigen::VectorXd& y) override {
        const Eigen::Index n = m_sim.m_n;
        m_x = y.head(n);
        m_mass.resize(n);
        for (Eigen::Index k = 0; k < n; ++k)
            m_mass[k] = m_sim.m_invMass3[k] > 0.0 ? 1.0 / m_sim.m_invMass3[k] : 0.0;
        const Topology& topo = m_sim.m_body.topology;
        linearizeContact(y);
        m_gasOn = m_sim.m_forces.terms().has(Term::Gas);
        if (!m_gasOn) return;
        for (const Surface& s : topo.surfaces) {
            const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
            m_gradient[slot].setZero(n);
            addVolumeGradient(s, topo.dimension, m_x.data(), m_gradient[slot].data());
            m_volume[slot] = enclosedVolume(s, m_x.data(), topo.dimension);
        }
    }
    void forceJacobianProduct(const Eigen::VectorXd& dx, const Eigen::VectorXd& dv,
                              Eigen::VectorXd& out) override {
        out.setZero();
        const Topology& topo = m_sim.m_body.topology;
        const ForceParams& p = m_sim.m_forces.params;
        if (m_sim.m_forces.terms().has(Term::Springs))
            for (int f = 0; f < kSpringFamilyCount; ++f) {
                const auto k = static_cast<std::size_t>(f);
                addSpringJacobianProduct(topo.springs[k], p.ks[k], p.kd[k], m_x.data(), dx.data(),
                                         dv.data(), out.data());
            }
        if (m_gasOn)
            for (const Surface& s : topo.surfaces) {
                const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
                addGasJacobianProduct(s, topo.dimension, p.gasConstant[slot], m_volume[slot],
                                      m_gradient[slot], m_x.data(), dx.data(), out.data());
            }
        if (m_sim.m_forces.terms().has(Term::Pointer))
            addPointerJacobianProduct(m_sim.m_forces.pointer, p.mks, p.mkd, p.mouseRest, m_x.data(),
                                      dx.data(), dv.data(), out.data());
        if (m_contactOn) {
            out += m_contactK.cwiseProduct(dx) + m_contactD.cwiseProduct(dv);
            addBarrierProduct(dx, out);
        }
        for (Eigen::Index k = 0; k < out.size(); ++k)
            if (m_mass[k] == 0.0) out[k] = 0.0;
    }
    void forceJacobianDiagonal(Eigen::VectorXd& kdiag, Eigen::VectorXd& ddiag) override {
        kdiag.setZero();
        ddiag.setZero();
        const Topology& topo = m_sim.m_body.topology;
        const ForceParams& p = m_sim.m_forces.params;
        if (m_sim.m_forces.terms().has(Term::Springs))
            for (int f = 0; f < kSpringFamilyCount; ++f) {
                const auto k = static_cast<std::size_t>(f);
                addSpringJacobianDiagonal(topo.springs[k], p.ks[k], p.kd[k], m_x.data(),
                                          kdiag.data(), ddiag.data());
            }
        if (m_gasOn)
            for (const Surface& s : topo.surfaces) {
                const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
                addGasJacobianDiagonal(p.gasConstant[slot], m_volume[slot], m_gradient[slot], kdiag.data());
            }
        if (m_sim.m_forces.terms().has(Term::Pointer))
            addPointerJacobianDiagonal(m_sim.m_forces.pointer, p.mks, p.mkd, p.mouseRest, m_x.data(),
                                       kdiag.data(), ddiag.data());
        if (m_contactOn) {
            kdiag += m_contactK;
            ddiag += m_contactD;
            for (const ActiveBarrier& b : m_barrierActive)
                for (int a = 0; a < 3; ++a) {
                    kdiag[3 * b.inner + a] -= b.stiffness * b.normal[a] * b.normal[a];
                    kdiag[3 * b.outer + a] -= b.stiffness * b.normal[a] * b.normal[a];
                }
        }
    }
    // Contact at the linearisation point: the walls' diagonal Jacobians (addWallContactJacobian)
    // and the layer barrier's active pairs. The barrier enters by its Gauss-Newton part
    // K = -3 k q^2 n n^T on the pair (n = dq/dx_i = sqrt2 g / sqrt(|g|^2 + g0^2), +n on the inner particle, -n on the outer);
    // the curvature of q and the coupling to the fan are left out (the barrier is rarely
    // active; implicit-euler's linearisation only has to be close, not exact).
    // Extra contact stiffness may be added at a chosen design point (stability estimates).
    void linearizeContact(const Eigen::VectorXd& y) {
        const Eigen::Index n = m_sim.m_n;
        const ForceModel& forces = m_sim.m_forces;
        m_contactOn = forces.contactWalls() || forces.contactBarrier() || m_design;
        m_barrierActive.clear();
        if (!m_contactOn) return;
        // Sized once (the first linearisation), not per step.
        if (m_barrierActive.capacity() < forces.barrierPairs().size()) m_barrierActive.reserve(forces.barrierPairs().size());
        m_contactK.setZero(n);
        m_contactD.setZero(n);
        const double* x = y.data();
        const double* v = y.data() + n;
        if (forces.contactWalls())
            for (int i = 0; i < m_sim.particleCount(); ++i)
                if (!m_sim.m_body.fixed[static_cast<std::size_t>(i)] && outsideWalls(forces.contact, x + 3 * i))
                    addWallContactJacobian(forces.contact, x + 3 * i, v + 3 * i, m_contactK.data() + 3 * i,
                                           m_contactD.data() + 3 * i);
        if (m_design) {
            const ContactDesign& design = *m_design;
            for (int i : design.particles)
                for (int axis = 0; axis < 3; ++axis) {
                    if (axis == design.axis) {
                        m_contactK[3 * i + axis] -= design.stiffness;
                        m_contactD[3 * i + axis] -= design.damping;
                    } else {
                        m_contactD[3 * i + axis] -= design.friction;
                    }
                }
        }
        if (forces.contactBarrier()) {
            const LayerBarrierSet& pairs = forces.barrierPairs();
            const int dim = m_sim.m_body.topology.dimension;
            for (std::size_t k = 0; k < pairs.size(); ++k) {
                const auto g = layerBarrierNormal(pairs, k, dim, x);
                const int in = pairs.inner[k], out = pairs.outer[k];
                const double along = (x[3 * in] - x[3 * out]) * g[0] + (x[3 * in + 1] - x[3 * out + 1]) * g[1] +
                                     (x[3 * in + 2] - x[3 * out + 2]) * g[2];
                if (!(along > 0.0)) continue;
                const double g02 = 1.0 / (pairs.invRestNorm[k] * pairs.invRestNorm[k]);
                const double inv = kSqrt2 / std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + g02);
                const double q = along * inv;
                ActiveBarrier b{in, out, 3.0 * forces.contact.stiffness * q * q, {}};
                for (int a = 0; a < 3; ++a) b.normal[static_cast<std::size_t>(a)] = g[static_cast<std::size_t>(a)] * inv;
                m_barrierActive.push_back(b);
            }
        }
    }
    void addBarrierProduct(const Eigen::VectorXd& dx, Eigen::VectorXd& out) const {
        for (const ActiveBarrier& b : m_barrierActive) {
            double along = 0.0;
            for (int a = 0; a < 3; ++a) along += b.normal[static_cast<std::size_t>(a)] * (dx[3 * b.inner + a] - dx[3 * b.outer + a]);
            for (int a = 0; a < 3; ++a) {
                out[3 * b.inner + a] -= b.stiffness * along * b.normal[static_cast<std::size_t>(a)];
                out[3 * b.outer + a] += b.stiffness * along * b.normal[static_cast<std::size_t>(a)];
            }
        }
    }
    // Adds the design point's contact stiffness at every linearisation (nullopt: none).
    void setContactDesign(std::optional<ContactDesign> design) { m_design = std::move(design); }
    const Eigen::VectorXd& coordinateMass() const override { return m_mass; }
    bool distanceConstraints(DistanceConstraints& out) override {
        const Topology& topo = m_sim.m_body.topology;
        const ForceParams& p = m_sim.m_forces.params;
        const bool springs = m_sim.m_forces.terms().has(Term::Springs);
        for (int f = 0; f < kSpringFamilyCount; ++f) {
            const auto k = static_cast<std::size_t>(f);
            const SpringSet& set = topo.springs[k];
            out.families[k] = {set.a, set.b, set.rest, springs ? p.ks[k] : 0.0, springs ? p.kd[k] : 0.0};
        }
        out.inverseMass = &m_sim.m_invMass3;
        out.substeps = m_sim.m_p.time.substeps;
        return true;
    }
    bool stronglyNonlinear(double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& v1) override {
        const ForceModel& forces = m_sim.m_forces;
        if (!forces.contactWalls()) return false;
        const ContactParams& c = forces.contact;
        for (Eigen::Index k = 0; k < m_sim.m_n; ++k) {
            if (m_mass[k] == 0.0) continue;
            const auto axis = static_cast<std::size_t>(k % 3);
            const double end = y0[k] + h * v1[k];
            if (end < c.low[axis] || end > c.high[axis]) return true;
        }
        return false;
    }
    int contactVelocities(double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& v1,
                          Eigen::VectorXd& target) override {
        // The same box planes as collide(): a free coordinate that would end outside lands
        // on its wall. collide() then applies restitution to it after the step. Only with
        // contact = projection: as a force, contact is in F and its Jacobians.
        if (!m_sim.m_forces.terms().has(Term::Collisions) || !m_sim.m_contactProjection) return 0;
        // Deepest first: only coordinates that penetrate at least half as deep as the deepest
        // are marked in one pass. A particle behind another (an inner-layer particle above
        // an outer one on the floor) is then held by its springs once the front one is
        // stopped, instead of being stopped by the wall it would never have reached.
        auto penetration = [&](Eigen::Index k, double& wall) {
            const int axis = static_cast<int>(k % 3);
            const double lo = m_sim.m_boxCentre[axis] - m_sim.m_box, hi = m_sim.m_boxCentre[axis] + m_sim.m_box;
            const double end = y0[k] + h * v1[k];
            wall = end < lo ? lo : hi;
            return end < lo ? lo - end : end > hi ? end - hi : 0.0;
        };
        double deepest = 0.0, wall = 0.0;
        for (Eigen::Index k = 0; k < m_sim.m_n; ++k)
            if (m_mass[k] != 0.0 && !std::isfinite(target[k])) deepest = std::max(deepest, penetration(k, wall));
        if (deepest <= 0.0) return 0;
        int marked = 0;
        for (Eigen::Index k = 0; k < m_sim.m_n; ++k) {
            if (m_mass[k] == 0.0 || std::isfinite(target[k])) continue;
            if (penetration(k, wall) < 0.5 * deepest) continue;
            target[k] = (wall - y0[k]) / h;
            ++marked;
        }
        return marked;
    }

private:
    Simulation& m_sim;
    ForceExtras m_extras;
    // Linearisation point and its gas data (sized once, reused every step).
    Eigen::VectorXd m_x, m_mass;
    std::array<Eigen::VectorXd, 2> m_gradient;  // dV/dx of [inner, outer], 3N each
    std::array<double, 2> m_volume{};
    bool m_gasOn = false;
    Eigen::VectorXd* m_offered = nullptr;
    // Contact at the linearisation point.
    struct ActiveBarrier {
        int inner, outer;
        double stiffness;                // 3 k q^2 [N/m]
        std::array<double, 3> normal;    // g / g0
    };
    bool m_contactOn = false;
    Eigen::VectorXd m_contactK, m_contactD;  // diagonal dF/dx, dF/dv of the walls (3N)
    std::vector<ActiveBarrier> m_barrierActive;
    std::optional<ContactDesign> m_design;
};

Simulation::Simulation(const ParameterSet& params, std::string_view integrator)
    : m_params(params), m_integrator(makeIntegrator(integrator)) {
    if (!m_integrator)
        throw std::invalid_argument("unknown integrator '" + std::string(integrator) +
                                    "'; allowed: " + integratorNames());
    m_system = std::make_unique<System>(*this);
    build();
}

Simulation::~Simulation() = default;

OdeSystem& Simulation::odeSystem() { return *m_system; }

Eigen::Map<const Eigen::Matrix3Xd> Simulation::positions() const {
    return {m_y.data(), 3, particleCount()};
}
Eigen::Map<const Eigen::Matrix3Xd> Simulation::velocities() const {
    return {m_y.data() + m_n, 3, particleCount()};
}

void Simulation::build() {
    m_p = resolve(m_params);
    m_body = buildBody(m_params);
    m_scale = bodyScale(m_params, m_body);
    const Topology& topo = m_body.topology;
    const int count = topo.particleCount();
    m_n = 3 * count;
    m_forces = ForceModel(&m_body.topology, &m_body.mass, sceneTerms(m_params.kind()));
    setThreads(m_threads);
    m_boxCentre = m_body.positions.rowwise().mean();
    m_forces.prepareContact(m_body.positions.data(), m_body.fixed);

    m_invMass3.setZero(m_n);
    for (int i = 0; i < count; ++i) {
        if (m_body.fixed[static_cast<std::size_t>(i)]) continue;
        const double inv = 1.0 / m_body.mass[i];
        // 1D moves along y only (thesis 3.3: "restricted to one dimension"); 2D in the xy plane.
        m_invMass3[3 * i + 1] = inv;
        if (topo.dimension >= 2) m_invMass3[3 * i] = inv;
        if (topo.dimension == 3) m_invMass3[3 * i + 2] = inv;
    }
    applyForceParams();
    reset();
}

void Simulation::setThreads(int threads) {
    // A pool only pays when the body is split in chunks; never more threads than chunks.
    m_threads = std::max(1, threads);
    const int useful = std::min(m_threads, m_forces.chunks());
    if (useful <= 1) {
        m_pool.reset();
    } else if (!m_pool || m_pool->threads() != useful) {
        m_pool = std::make_unique<ThreadPool>(useful);
    }
    m_forces.setPool(m_pool.get());
}

void Simulation::applyForceParams() {
    m_p = resolve(m_params);
    ForceParams& p = m_forces.params;
    // The per-spring values this resolution uses (scaling.h; all factors 1 under scaling=thesis
    // and at the reference resolution).
    const auto& f = m_scale.spring;
    const Params::Forces& table = m_p.forces;
    p.ks = {table.ks * f[0], 0.0, 0.0};
    p.kd = {table.kd * f[0], 0.0, 0.0};
    if (m_params.kind() != SceneKind::Spring1d) {
        p.ks[1] = table.rks * f[1];
        p.ks[2] = table.rks * f[2];
        p.kd[1] = table.rkd * f[1];
        p.kd[2] = table.rkd * f[2];
        p.gasConstant = table.gasConstant;
    }
    const Params::World& world = m_p.world;
    p.gravity = world.gravity;
    p.mks = table.mks;
    p.mkd = table.mkd;
    p.mouseRest = table.mouseRest;
    m_box = world.box;
    m_dt = m_p.time.dt;
    // Contact (contact.h): the walls per axis the body moves along, k, and alpha from e at
    // the reference impact speed.
    m_contactProjection = world.contact == ContactModel::Projection;
    ContactParams& c = m_forces.contact;
    c.walls = c.layerBarrier = !m_contactProjection;
    c.stiffness = world.contactStiffness * m_scale.contact;
    c.alpha = dampingForRestitution(world.restitution) / world.contactSpeed;
    c.friction = world.friction;
    c.frictionSpeed = world.frictionSpeed;
    const int dims = m_body.topology.dimension;
    for (int axis = 0; axis < 3; ++axis) {
        const bool moves = axis == 1 || (axis == 0 && dims >= 2) || (axis == 2 && dims == 3);
        const double infinity = std::numeric_limits<double>::infinity();
        c.low[static_cast<std::size_t>(axis)] = moves ? m_boxCentre[axis] - m_box : -infinity;
        c.high[static_cast<std::size_t>(axis)] = moves ? m_boxCentre[axis] + m_box : infinity;
    }
}

void Simulation::reset() {
    m_endValid = false;
    const Eigen::Index n = m_n;
    m_y.setZero(2 * n + kAux);
    Eigen::Map<Eigen::Matrix3Xd>(m_y.data(), 3, particleCount()) = m_body.positions;
    const double amplitude = m_p.start.perturb;
    if (amplitude > 0.0) {
        // Seeded, so a perturbed run is repeatable; only along the axes the body moves in.
        std::mt19937_64 rng(m_p.start.seed);
        std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
        for (Eigen::Index k = 0; k < n; ++k)
            if (m_invMass3[k] != 0.0) m_y[k] += uniform(rng);
    }
    m_integrator->prepare(m_system->layout());
    m_hNext = m_hTaken = m_dt;
    m_doubling.setZero(m_y.size());
    // Held only while step doubling is on (the memory bound counts what a run holds).
    if (m_integratorOptions.stepDoubling) m_doublingError.setZero(m_y.size());
    else m_doublingError.resize(0);
    m_lastError = nullptr;
    m_endDerivative.setZero(m_y.size());
    m_lastGood = m_y;
    m_failure.reset();
    m_forces.pointer = PointerSpring{};
    m_diag = Diagnostics{};
    m_timeCarry = 0.0;
    m_diag.dt = m_dt;
    m_restartIntegrator = false;
    m_jacobianProducts = 0;
    startBookkeeping();
}

void Simulation::setState(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& v, long step,
                          double time) {
    m_diag.step = step;
    m_diag.time = time;
    setState(x, v);
}

void Simulation::setState(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& v) {
    if (x.cols() != particleCount() || v.cols() != particleCount())
        throw std::invalid_argument("state has the wrong number of particles");
    m_endValid = false;
    m_lastError = nullptr;
    Eigen::Map<Eigen::Matrix3Xd>(m_y.data(), 3, particleCount()) = x;
    Eigen::Map<Eigen::Matrix3Xd>(m_y.data() + m_n, 3, particleCount()) = v;
    m_y.tail(kAux).setZero();
    m_lastGood = m_y;
    m_failure.reset();
    m_restartIntegrator = true;
    const long step = m_diag.step;
    const double time = m_diag.time;
    m_diag = Diagnostics{};
    m_timeCarry = 0.0;
    m_diag.step = step;
    m_diag.time = time;
    startBookkeeping();
}

void Simulation::startBookkeeping() {
    measure(m_diag);
    m_diag.initialEnergy = m_diag.total();
    // Energy scale for blow-up detection: what the body could plausibly hold. Gravity over
    // the box height, every spring stretched by its rest length, the gas expanding 100-fold.
    const Topology& topo = m_body.topology;
    double scale = 1.0 + m_diag.kinetic + m_diag.springTotal();
    scale += m_body.mass.sum() * m_forces.params.gravity * 2.0 * m_box;
    for (int f = 0; f < kSpringFamilyCount; ++f) {
        const auto k = static_cast<std::size_t>(f);
        for (double rest : topo.springs[k].rest) scale += 0.5 * m_forces.params.ks[k] * rest * rest;
    }
    if (m_forces.terms().has(Term::Gas))
        scale += (m_forces.params.gasConstant[0] + m_forces.params.gasConstant[1]) * std::log(100.0);
    m_energyScale = scale;
}

void Simulation::measure(Diagnostics& d) const { measureByPasses(d, scanState()); }

void Simulation::measureByPasses(Diagnostics& d, const Scan& scan) const {
    fillDiagnostics(d, m_forces.springEnergies(m_y.data()),
                    m_forces.terms().has(Term::Gas) ? m_forces.volumes(m_y.data()) : std::array<double, 2>{},
                    m_forces.contactEnergy(m_y.data()), scan);
}

void Simulation::measureState(Diagnostics& d, const Scan& scan) {
    if (m_reuseEndForces)
        measureWithForces(d, scan);
    else
        measureByPasses(d, scan);
}

void Simulation::measureWithForces(Diagnostics& d, const Scan& scan) {
    // One uncounted force evaluation yields the energies and volumes, and f at this state,
    // which the next step's first stage takes instead of evaluating it again.
    m_system->compute(m_y, m_endDerivative, m_endExtras, false);
    fillDiagnostics(d, m_endExtras.springEnergy, m_endExtras.volume, m_endExtras.contactEnergy, scan);
}

Simulation::Scan Simulation::scanState() const {
    const double* x = m_y.data();
    const double* v = m_y.data() + m_n;
    const double* inv = m_invMass3.data();
    const bool weighs = m_forces.terms().has(Term::Gravity);
    const double g = m_forces.params.gravity;
    const double infinity = std::numeric_limits<double>::infinity();
    std::array<Scan, kPiecesMax> pieces;
    inPieces([&](int piece, int begin, int end) {
        Scan s;
        s.low.setConstant(infinity);
        s.high.setConstant(-infinity);
        // (x - x) + (v - v) is 0 for finite coordinates and NaN otherwise: summed, it tells
        // whether all are finite without a branch per coordinate.
        double nonFinite = 0.0;
        double kinetic = 0.0, gravity = 0.0, fastest2 = 0.0;
        for (int i = begin; i < end; ++i) {
            for (int axis = 0; axis < 3; ++axis) {
                const int k = 3 * i + axis;
                nonFinite += (x[k] - x[k]) + (v[k] - v[k]);
                // Only moving coordinates (not a fixed particle's, not an axis the body does
                // not move in) count for the extent.
                const bool moves = inv[k] != 0.0;
                s.low[axis] = std::min(s.low[axis], moves ? x[k] : infinity);
                s.high[axis] = std::max(s.high[axis], moves ? x[k] : -infinity);
            }
            const Eigen::Map<const Eigen::Vector3d> vi(v + 3 * i);
            const double speed2 = vi.squaredNorm();
            fastest2 = std::max(fastest2, speed2);
            if (m_body.fixed[static_cast<std::size_t>(i)]) continue;
            const double m = m_body.mass[i];
            kinetic += 0.5 * m * speed2;
            if (weighs) gravity += m * g * x[3 * i + 1];
        }
        s.finite = nonFinite == 0.0;
        s.kinetic = kinetic;
        s.gravity = gravity;
        s.fastest = std::sqrt(fastest2);
        pieces[static_cast<std::size_t>(piece)] = s;
    });
    Scan total;
    total.low.setConstant(infinity);
    total.high.setConstant(-infinity);
    total.finite = std::isfinite(m_y[2 * m_n]) && std::isfinite(m_y[2 * m_n + 1]);
    for (int piece = 0; piece < m_forces.chunks(); ++piece) {
        const Scan& s = pieces[static_cast<std::size_t>(piece)];
        total.finite = total.finite && s.finite;
        total.low = total.low.min(s.low);
        total.high = total.high.max(s.high);
        total.kinetic += s.kinetic;
        total.gravity += s.gravity;
        total.fastest = std::max(total.fastest, s.fastest);
    }
    return total;
}

void Simulation::fillDiagnostics(Diagnostics& d, const std::array<double, kSpringFamilyCount>& spring,
                                 const std::array<double, 2>& volume, double contact, const Scan& scan) const {
    const double* x = m_y.data();
    const Topology& topo = m_body.topology;
    d.kinetic = scan.kinetic;
    d.gravity = scan.gravity;
    d.spring = spring;
    d.hasGas = m_forces.terms().has(Term::Gas);
    d.gas = 0.0;
    if (d.hasGas) {
        for (const Surface& s : topo.surfaces) {
            const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
            const double c = m_forces.params.gasConstant[slot];
            d.volume[slot] = volume[slot];
            d.restVolume[slot] = s.restVolume;
            d.pressure[slot] = d.volume[slot] > 0.0 ? c / d.volume[slot] : 0.0;
            d.gas += gasEnergy(c, d.volume[slot]);
        }
    }
    d.pointer = pointerEnergy(m_forces.pointer, m_forces.params.mks, m_forces.params.mouseRest, x);
    d.removedDamping = m_y[2 * m_n];
    d.contact = contact;
    d.removedContact = m_y[2 * m_n + 1];
    d.forceEvaluations = m_forces.forceEvaluations() + m_jacobianProducts;
    const SolverCounters* counters = m_integrator->counters();
    d.hasSolverCounters = counters != nullptr;
    d.solver = counters ? *counters : SolverCounters{};
}

void Simulation::currentForces(double* f) const {
    ForceExtras extras;
    m_forces.evaluate(m_y.data(), m_y.data() + m_n, f, extras, false);
}

ForceBreakdown Simulation::forceBreakdown(int particle) const {
    ForceBreakdown out;
    if (m_breakdownForces.size() != m_n) m_breakdownForces.setZero(m_n);
    m_forces.breakdown(particle, m_y.data(), m_y.data() + m_n, m_breakdownForces.data(), out);
    return out;
}

ObservableErrors Simulation::observableErrors() {
    ObservableErrors out;
    if (!m_lastError || m_failure) return out;
    Diagnostics at, off;
    measure(at);
    m_errorScratch = m_y;
    m_y += Eigen::Map<const Eigen::VectorXd>(m_lastError, m_y.size());
    measure(off);
    m_y = m_errorScratch;  // exactly the state it was (m_y keeps its buffer: CVODE wraps it)
    for (std::size_t k = 0; k < 2; ++k) {
        out.volume[k] = std::abs(off.volume[k] - at.volume[k]);
        out.pressure[k] = std::abs(off.pressure[k] - at.pressure[k]);
    }
    out.energy = std::abs(off.total() - at.total());
    out.valid = std::isfinite(out.energy) && std::isfinite(out.volume[0] + out.volume[1]) &&
                std::isfinite(out.pressure[0] + out.pressure[1]);
    return out;
}

double Simulation::totalEnergyNow() const {
    Diagnostics d;
    measure(d);
    return d.total();
}

bool Simulation::step(double until) {
    if (m_failure) return false;
    inPieces([&](int, int begin, int end) {
        // x and v of the piece's particles; the last piece also takes the energy accounts.
        const Eigen::Index b = 3 * begin, l = 3 * (end - begin);
        m_lastGood.segment(b, l) = m_y.segment(b, l);
        m_lastGood.segment(m_n + b, l) = m_y.segment(m_n + b, l);
        if (end == particleCount()) m_lastGood.tail(kAux) = m_y.tail(kAux);
    });
    const double t0 = m_diag.time;
    // Adaptive methods take the step they proposed, shortened to land on `until`.
    double h = m_dt;
    bool clamped = false;
    if (m_integrator->adaptive()) {
        // No particle may cross more than a tenth of the box in one adaptive step: a smooth
        // free fall has a zero error estimate and would let the step grow without bound, past
        // the onset of a contact (a force that is 0 until it is touched, so the estimate
        // cannot see it coming) or, with contact = projection, through a wall between steps.
        const double fastest = velocities().colwise().norm().maxCoeff();
        h = fastest > 0.0 ? std::min(m_hNext, 0.1 * m_box / fastest) : m_hNext;
        if (until - t0 > 1e-12 * std::max(1.0, std::abs(until)) && t0 + h > until) {
            h = until - t0;
            clamped = true;
        }
    }
    m_system->offer(m_endValid ? &m_endDerivative : nullptr);
    m_endValid = false;
    if (m_restartIntegrator) {
        m_integrator->restart();
        m_restartIntegrator = false;
    }
    StepReport report = m_integrator->step(*m_system, t0, h, m_y);
    m_system->offer(nullptr);
    m_jacobianProducts += static_cast<std::uint64_t>(report.jacobianProducts);
    m_lastError = nullptr;
    if (report.failure) {
        m_failure = Failure{report.failure, m_diag.step + 1, t0};
        m_y = m_lastGood;
        return false;
    }
    if (m_integrator->adaptive())
        m_hNext = clamped && report.rejected == 0 ? std::max(m_hNext, report.hNext) : report.hNext;
    m_hTaken = report.h;
    if (m_integratorOptions.stepDoubling && !m_integrator->adaptive() && scanState().finite) {
        // Step doubling (Richardson): y_h from one step, y_h/2 from two half steps from the
        // same start; the local error of y_h is about |y_h/2 - y_h| / (1 - 2^-p) and that of
        // y_h/2 is 2^-p of it. The run keeps y_h, so switching the estimate on changes
        // nothing but the cost (the extra evaluations are counted).
        m_doubling = m_y;
        m_y = m_lastGood;
        const double half = 0.5 * report.h;
        const StepReport first = m_integrator->step(*m_system, t0, half, m_y);
        const StepReport second = first.failure ? first : m_integrator->step(*m_system, t0 + half, half, m_y);
        const double p = m_integrator->order();
        const Eigen::Index n = m_n;
        const double rms = std::sqrt((m_y.head(n) - m_doubling.head(n)).squaredNorm() /
                                     std::max(1.0, static_cast<double>(particleCount())));
        report.errorEstimate = second.failure || !std::isfinite(rms) ? -1.0 : rms / (1.0 - std::pow(2.0, -p));
        if (report.errorEstimate >= 0.0) {
            m_doublingError = (m_y - m_doubling) / (1.0 - std::pow(2.0, -p));
            m_lastError = m_doublingError.data();
        }
        m_y = m_doubling;
    }

    // Wall contacts and the layer constraint change the state outside the ODE. Whatever
    // energy they change is measured across them and booked as removed by collisions (in the
    // new diagnostics only: a step that then fails leaves the books as they were). The layer
    // constraint's normals are the outer layer's volume gradient, which the measurement of
    // the state (a force evaluation) leaves behind: it is checked after that measurement, and
    // a step it corrects is measured again.
    std::optional<double> beforeContacts;
    Scan scan = scanState();
    if (scan.finite && m_contactProjection && m_forces.terms().has(Term::Collisions)) {
        m_forces.countPostStep(Term::Collisions);
        // Most steps touch no wall: the scan's extent says so without a second pass.
        const Eigen::Array3d wallLow = m_boxCentre.array() - m_box, wallHigh = m_boxCentre.array() + m_box;
        if (((scan.low <= wallLow) || (scan.high >= wallHigh)).any() && collide(false)) {
            beforeContacts = totalEnergyNow();
            collide(true);
            m_restartIntegrator = true;
            scan = scanState();
        }
    }

    // One measurement serves the checks, the diagnostics and the energy after the contacts.
    Diagnostics next = m_diag;
    measureState(next, scan);
    if (scan.finite && m_contactProjection && m_forces.terms().has(Term::LayerConstraint)) {
        m_forces.countPostStep(Term::LayerConstraint);
        const kernels::PaddedRows normals =
            m_reuseEndForces ? m_forces.volumeGradient() : m_forces.computeVolumeGradient(m_y.data());
        if (constrainLayers(false, normals)) {
            if (!beforeContacts) beforeContacts = next.total();
            constrainLayers(true, normals);
            m_restartIntegrator = true;
            scan = scanState();
            measureState(next, scan);
        }
    }
    if (beforeContacts) next.removedCollisions += *beforeContacts - next.total();
    if (const auto problem = checkState(next, scan)) {
        m_failure = Failure{*problem, m_diag.step + 1, t0};
        m_y = m_lastGood;  // keep the last good state: nothing non-finite leaves
        return false;
    }
    m_diag = next;
    m_diag.step += 1;
    // Compensated (Kahan) sum: a million steps of 0.003 s land on the intended time, so
    // advanceTo() never takes an extra step from accumulated round-off.
    const double increment = report.h - m_timeCarry;
    m_diag.time = t0 + increment;
    m_timeCarry = (m_diag.time - t0) - increment;
    m_diag.dt = report.h;
    m_diag.errorEstimate = report.errorEstimate;
    if (m_integrator->adaptive() && report.errorEstimate >= 0.0) m_lastError = m_integrator->localError();
    m_diag.degenerateSprings = m_system->extras().degenerateSprings;
    m_endValid = m_reuseEndForces;
    return true;
}

bool Simulation::advanceTo(double tEnd) {
    // Round-off guard: a step that would end within 1e-9 dt of tEnd counts as reaching it.
    // Adaptive integrators land on tEnd exactly.
    while (!m_failure && m_diag.time < tEnd - 1e-9 * std::min(m_dt, nextStep())) step(tEnd);
    return !m_failure;
}

void Simulation::setIntegratorOptions(const IntegratorOptions& options) {
    m_integratorOptions = options;
    if (options.stepDoubling && m_doublingError.size() != m_y.size()) m_doublingError.setZero(m_y.size());
    m_integrator->setOptions(options);
}

bool Simulation::collide(bool apply) {
    // Axis-aligned box planes (thesis 4.6; MODEL.md): a particle outside is projected back
    // and its normal velocity becomes -e v_n; friction scales the tangential velocity by
    // (1 - mu). Only the axes the body moves in are bounded. Particles are independent: the
    // pieces run in parallel.
    std::array<bool, kPiecesMax> pieceAny{};
    inPieces([&](int piece, int begin, int end) {
        pieceAny[static_cast<std::size_t>(piece)] = collideRange(apply, begin, end);
    });
    return std::find(pieceAny.begin(), pieceAny.end(), true) != pieceAny.end();
}

bool Simulation::collideRange(bool apply, int begin, int end) {
    const int dims = m_body.topology.dimension;
    const double restingSpeed = 2.0 * m_forces.params.gravity * m_hTaken;
    bool any = false;
    for (int i = begin; i < end; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            const Eigen::Index k = 3 * i + axis;
            if (m_invMass3[k] == 0.0) continue;
            const double lo = m_boxCentre[axis] - m_box, hi = m_boxCentre[axis] + m_box;
            double& x = m_y[k];
            double& v = m_y[m_n + k];
            // On the wall and moving into it counts too: an implicit step lands particles
            // exactly on the wall (contacts inside its solve) and leaves restitution to here.
            const bool below = x < lo || (x == lo && v < 0.0), above = x > hi || (x == hi && v > 0.0);
            if (!below && !above) continue;
            any = true;
            if (!apply) return true;
            x = below ? lo : hi;
            // Resting contact: an approach no faster than what gravity adds in two steps is
            // stopped, not bounced. Bouncing it would make a resting body chatter, each step
            // sinking, being lifted back and bounced, pumping energy that damping then removes.
            if ((below && v < 0.0) || (above && v > 0.0))
                v = std::abs(v) <= restingSpeed ? 0.0 : -m_p.world.restitution * v;
            if (m_p.world.friction > 0.0) {
                for (int other = 0; other < dims && other < 3; ++other) {
                    const int tangent = dims == 1 ? 1 : other;
                    if (tangent == axis) continue;
                    m_y[m_n + 3 * i + tangent] *= 1.0 - m_p.world.friction;
                }
            }
        }
    }
    return any;
}

bool Simulation::constrainLayers(bool apply, kernels::PaddedRows normals) {
    // Each inner particle must stay on the inner side of the tangent plane of its paired
    // outer particle. The outer vertex normal is the direction of the outer layer's volume
    // gradient dV/dx there (normals): the area-weighted mean of the adjacent face
    // normals (3D) or the perpendicular of the neighbouring chords (2D). A violation is undone
    // symmetrically: positions and relative normal velocity are corrected with mass weights,
    // so momentum is conserved. Pairs are independent: the pieces run in parallel.
    const auto& pairs = m_body.topology.layerPairs;
    if (pairs.empty() || !normals) return false;
    double* x = m_y.data();
    double* v = m_y.data() + m_n;
    std::array<bool, kPiecesMax> pieceAny{};
    inPiecesOf(static_cast<int>(pairs.size()), [&](int piece, int begin, int end) {
        for (int k = begin; k < end; ++k) {
            const auto [in, out] = pairs[static_cast<std::size_t>(k)];
            const Eigen::Map<const Eigen::Vector3d> gradient = normals[out];
            Eigen::Map<Eigen::Vector3d> xi(x + 3 * in), xo(x + 3 * out), vi(v + 3 * in), vo(v + 3 * out);
            // The sign first (no root, no division for the pairs that are fine, nearly all).
            if (!((xi - xo).dot(gradient) > 0.0)) continue;
            const double norm = gradient.norm();
            if (norm <= 0.0) continue;
            const Eigen::Vector3d n = gradient / norm;
            const double depth = (xi - xo).dot(n);
            if (depth <= 0.0) continue;
            pieceAny[static_cast<std::size_t>(piece)] = true;
            if (!apply) return;
            const double mi = m_body.mass[in], mo = m_body.mass[out];
            const double wi = mo / (mi + mo), wo = mi / (mi + mo);
            xi -= wi * depth * n;
            xo += wo * depth * n;
            const double separating = (vi - vo).dot(n);
            if (separating > 0.0) {
                vi -= wi * separating * n;
                vo += wo * separating * n;
            }
        }
    });
    return std::find(pieceAny.begin(), pieceAny.end(), true) != pieceAny.end();
}

std::optional<std::string> Simulation::checkState(const Diagnostics& d, const Scan& scan) const {
    // Causes before symptoms: speed and energy first, then the shape they wreck. (The message
    // stream is built only on failure: nothing is allocated in a good step.)
    if (!scan.finite || !std::isfinite(d.total())) return std::string("the state became non-finite (NaN or infinity): the step is far too large for these forces");
    const double fastest = scan.fastest;
    if (fastest * m_hTaken > 2.0 * m_box) {
        std::ostringstream why;
        why << "runaway velocity: a particle moves " << fastest
            << " m/s, farther than the whole box in one step";
        return why.str();
    }
    const double held = d.kinetic + d.springTotal() + d.pointer;
    const double budget = kRunawayEnergyFactor *
                          (m_energyScale + std::abs(m_diag.workPointer) + std::abs(m_diag.workEdits));
    if (held > budget) {
        std::ostringstream why;
        why << "runaway energy: kinetic + elastic energy " << held << " J exceeds " << budget
            << " J (" << kRunawayEnergyFactor << " x the body's energy scale)";
        return why.str();
    }
    const Topology& topo = m_body.topology;
    for (const Surface& s : topo.surfaces) {
        const double volume = d.volume[static_cast<std::size_t>(layerSlot(s.layer))];
        if (volume <= kCollapsedVolumeFraction * s.restVolume) {
            std::ostringstream why;
            why << "the " << layerName(s.layer) << " layer "
                << (volume <= 0.0 ? "turned inside out" : "collapsed") << " (its "
                << (topo.dimension == 2 ? "area" : "volume") << " is " << volume
                << ", rest " << s.restVolume << ")";
            return why.str();
        }
    }
    return std::nullopt;
}

std::optional<std::string> Simulation::setParameter(std::string_view key, double value) {
    const ParamSpec* spec = findParam(key);
    if (!spec || !m_params.has(spec->id)) return ParameterSet(m_params.kind()).set(key, value);  // the message
    return setParameter(spec->id, value);
}

std::optional<std::string> Simulation::setParameter(Param id, double value) {
    ParameterSet next = m_params;
    if (auto error = next.set(id, value)) return error;
    const ParamSpec& spec = paramSpec(id);
    if (spec.isShape() || spec.group == ParamGroup::Start) {
        ParameterSet previous = m_params;
        m_params = next;
        try {
            build();
        } catch (const std::invalid_argument& e) {
            m_params = previous;
            build();
            return std::string(e.what());
        }
        return std::nullopt;
    }
    // A live edit changes the stored energy (a stiffer spring holds more for the same
    // stretch, a heavier particle more kinetic energy): book the jump as work by the edit.
    const double before = totalEnergyNow();
    m_params = next;
    m_endValid = false;
    m_restartIntegrator = true;
    if (spec.group == ParamGroup::Mass) applyMasses();
    applyForceParams();
    if (!m_failure) m_diag.workEdits += totalEnergyNow() - before;
    measure(m_diag);
    return std::nullopt;
}

void Simulation::applyMasses() {
    const Params::Shape shape = resolve(m_params).shape;
    const Topology& topo = m_body.topology;
    for (int i = 0; i < topo.particleCount(); ++i) {
        const Layer l = topo.layer[static_cast<std::size_t>(i)];
        const double m = (l == Layer::Inner   ? shape.massInner
                          : l == Layer::Outer ? shape.massOuter
                                              : shape.mass) *
                         m_scale.mass;
        m_body.mass[i] = m;
        for (int axis = 0; axis < 3; ++axis)
            if (m_invMass3[3 * i + axis] != 0.0) m_invMass3[3 * i + axis] = 1.0 / m;
    }
}

std::size_t SimulationSnapshot::bytes() const {
    return sizeof(SimulationSnapshot) + sizeof(double) * std::size_t(y.size() + endDerivative.size()) +
           sizeof(double) * integratorHistory.capacity() + integrator.capacity() +
           (failure ? failure->reason.capacity() : 0);
}

SimulationSnapshot Simulation::snapshot() const {
    SimulationSnapshot s;
    s.params = m_params;
    s.integrator = std::string(m_integrator->name());
    s.options = m_integratorOptions;
    s.integratorHistory = m_integrator->history();
    s.integratorRestorable = m_integrator->restorable();
    s.y = m_y;
    s.endValid = m_endValid;
    if (m_endValid) {
        s.endDerivative = m_endDerivative;
        s.endExtras = m_endExtras;
    }
    s.restartIntegrator = m_restartIntegrator;
    s.diag = m_diag;
    s.timeCarry = m_timeCarry;
    s.failure = m_failure;
    s.hNext = m_hNext;
    s.hTaken = m_hTaken;
    s.energyScale = m_energyScale;
    s.pointer = m_forces.pointer;
    s.counters = m_forces.counters();
    s.jacobianProducts = m_jacobianProducts;
    return s;
}

void Simulation::restore(const SimulationSnapshot& s) {
    if (s.y.size() != m_y.size()) throw std::invalid_argument("the snapshot is of another body");
    // Parameters (live edits only: a shape edit rebuilds the body, and a new run begins).
    m_params = s.params;
    applyMasses();
    applyForceParams();
    if (m_integrator->name() != s.integrator) {
        auto next = makeIntegrator(s.integrator);
        if (!next) throw std::invalid_argument("unknown integrator '" + s.integrator + "'");
        m_integrator = std::move(next);
        m_integrator->prepare(m_system->layout());
    }
    setIntegratorOptions(s.options);
    m_integrator->setHistory(s.integratorHistory);
    m_y = s.y;
    m_lastGood = s.y;
    m_endValid = s.endValid;
    if (s.endValid) {
        m_endDerivative = s.endDerivative;
        m_endExtras = s.endExtras;
    }
    // A method whose history cannot be restored starts afresh from this state.
    m_restartIntegrator = s.restartIntegrator || !s.integratorRestorable || !m_integrator->restorable();
    m_diag = s.diag;
    m_timeCarry = s.timeCarry;
    m_failure = s.failure;
    m_hNext = s.hNext;
    m_hTaken = s.hTaken;
    m_energyScale = s.energyScale;
    m_forces.pointer = s.pointer;
    m_forces.setCounters(s.counters);
    m_jacobianProducts = s.jacobianProducts;
}

std::optional<std::string> Simulation::setIntegrator(std::string_view name) {
    auto next = makeIntegrator(name);
    if (!next) return "unknown integrator '" + std::string(name) + "'; allowed: " + integratorNames();
    m_integrator = std::move(next);
    m_endValid = false;
    m_lastError = nullptr;
    m_integrator->setOptions(m_integratorOptions);
    m_integrator->prepare(m_system->layout());
    m_hNext = m_dt;
    return std::nullopt;
}

int Simulation::nearestGrabbable(const Eigen::Vector3d& point) const {
    const auto& layers = m_body.topology.layer;
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    const auto x = positions();
    for (int i = 0; i < particleCount(); ++i) {
        if (layers[static_cast<std::size_t>(i)] == Layer::Inner) continue;
        const double d = (x.col(i) - point).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    return best;
}

int Simulation::pickAlongRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                             double maxDistance) const {
    const auto& layers = m_body.topology.layer;
    const auto x = positions();
    int best = -1;
    double bestDistance = maxDistance, bestDepth = std::numeric_limits<double>::infinity();
    for (int i = 0; i < particleCount(); ++i) {
        if (layers[static_cast<std::size_t>(i)] == Layer::Inner) continue;
        const Eigen::Vector3d r = x.col(i) - origin;
        const double depth = r.dot(direction);
        if (depth < 0.0) continue;
        const double off = (r - depth * direction).norm();
        // Within the pick radius the particle nearest the eye wins (the front surface).
        if (off <= maxDistance && (depth < bestDepth - 1e-9 * (1.0 + depth))) {
            if (best < 0 || off <= bestDistance || depth < bestDepth) {
                best = i;
                bestDepth = depth;
                bestDistance = off;
            }
        }
    }
    return best;
}

void Simulation::grab(int particle, const Eigen::Vector3d& anchor) {
    if (particle < 0 || particle >= particleCount() || m_failure) return;
    // Creating the spring stores energy: that is work done by the pointer.
    const double before = m_diag.pointer;
    m_endValid = false;
    m_restartIntegrator = true;
    m_forces.pointer = PointerSpring{true, particle, anchor};
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

void Simulation::moveAnchor(const Eigen::Vector3d& anchor) {
    if (!m_forces.pointer.active || m_failure) return;
    // The anchor moves between steps; the change in the spring's energy is the pointer's work.
    const double before = m_diag.pointer;
    m_endValid = false;
    m_restartIntegrator = true;
    m_forces.pointer.anchor = anchor;
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

void Simulation::release() {
    if (!m_forces.pointer.active) return;
    const double before = m_diag.pointer;
    m_endValid = false;
    m_restartIntegrator = true;
    m_forces.pointer = PointerSpring{};
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

Simulation::ContactDesign Simulation::contactDesign() const {
    ContactDesign design;
    const ContactParams& c = m_forces.contact;
    const double g = m_forces.terms().has(Term::Gravity) ? m_forces.params.gravity : 0.0;
    // A body held by a fixed particle hangs from it: only free bodies are taken to fall.
    const bool held = std::find(m_body.fixed.begin(), m_body.fixed.end(), true) != m_body.fixed.end();
    if (m_contactProjection || !m_forces.contactWalls() || !(g > 0.0) || !(c.stiffness > 0.0) || held) return design;
    const auto x = positions();
    double lowest = std::numeric_limits<double>::infinity(), weight = 0.0;
    for (int i = 0; i < particleCount(); ++i) {
        if (m_body.fixed[static_cast<std::size_t>(i)]) continue;
        lowest = std::min(lowest, x(1, i));
        weight += m_body.mass[i] * g;
    }
    // The contact patch: the free particles within a tenth of the body's height of its lowest
    // point (measured on the default scenes, the particles touching at rest carry their
    // weight with these depths to within 10 %: docs/numerics.md).
    double highest = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < particleCount(); ++i)
        if (!m_body.fixed[static_cast<std::size_t>(i)]) highest = std::max(highest, x(1, i));
    const double band = 0.1 * (highest - lowest);
    for (int i = 0; i < particleCount(); ++i)
        if (!m_body.fixed[static_cast<std::size_t>(i)] && x(1, i) <= lowest + band) design.particles.push_back(i);
    if (design.particles.empty()) return design;
    // Rest: the weight shared by the patch (k d^3 = W / count). An impact goes deeper, but
    // only for a few steps: a step beyond the stable one there amplifies by a bounded factor,
    // while the resting contact lasts (measured: the impact depth as design point predicts
    // half the measured limits; docs/numerics.md).
    design.depth = std::cbrt(weight / (static_cast<double>(design.particles.size()) * c.stiffness));
    const double d = design.depth;
    design.stiffness = 3.0 * c.stiffness * d * d;
    design.damping = c.stiffness * d * d * d * c.alpha;
    design.friction = c.friction * c.stiffness * d * d * d / c.frictionSpeed;
    return design;
}

void Simulation::setContactDesignInJacobians(bool on) {
    m_system->setContactDesign(on ? std::optional<ContactDesign>(contactDesign()) : std::nullopt);
}

double Simulation::estimatedFastestRate() const {
    // Each particle alone, tied to fixed neighbours by its springs: m s^2 + c s + k = 0 with
    // k = sum ks and c = sum kd over its springs (springs in different directions do not all
    // act on one displacement, so this is an estimate, not a bound). |s| is sqrt(k/m) when underdamped and the fast root
    // (c + sqrt(c^2 - 4mk)) / 2m when overdamped: stiff damping limits explicit steps too.
    const Topology& topo = m_body.topology;
    Eigen::VectorXd k = Eigen::VectorXd::Zero(particleCount());
    Eigen::VectorXd c = Eigen::VectorXd::Zero(particleCount());
    for (int f = 0; f < kSpringFamilyCount; ++f) {
        const auto fam = static_cast<std::size_t>(f);
        for (std::size_t s = 0; s < topo.springs[fam].size(); ++s)
            for (int end : {topo.springs[fam].a[s], topo.springs[fam].b[s]}) {
                k[end] += m_forces.params.ks[fam];
                c[end] += m_forces.params.kd[fam];
            }
    }
    // Contact at its design point (contactDesign()) adds to the particles nearest the floor.
    const ContactDesign design = contactDesign();
    for (int i : design.particles) {
        k[i] += design.stiffness;
        c[i] += std::max(design.damping, design.friction);
    }
    double fastest = 0.0;
    for (int i = 0; i < particleCount(); ++i) {
        if (m_body.fixed[static_cast<std::size_t>(i)]) continue;
        const double m = m_body.mass[i];
        const double disc = c[i] * c[i] - 4.0 * m * k[i];
        const double rate = disc > 0.0 ? (c[i] + std::sqrt(disc)) / (2.0 * m) : std::sqrt(k[i] / m);
        fastest = std::max(fastest, rate);
    }
    return fastest;
}

}  // namespace simcore
