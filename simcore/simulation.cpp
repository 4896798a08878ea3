#include "simcore/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "simcore/integrator_table.h"
#include "simcore/internal/body_ode.h"
#include "simcore/internal/compensated_time.h"
#include "simcore/internal/world_body.h"

namespace simcore {

Simulation::Simulation(const ParameterSet& params, std::string_view integrator)
    : m_params(params), m_integrator(makeIntegrator(integrator)) {
    if (!m_integrator)
        throw std::invalid_argument("unknown integrator " + quoteShort(integrator) + "; allowed: " + integratorNames());
    m_ode = std::make_unique<BodyOde>(m_body, m_forces, m_invMass3);
    build();
}

Simulation::~Simulation() = default;

OdeSystem& Simulation::odeSystem() { return *m_ode; }

std::string_view stageName(Stage stage) {
    switch (stage) {
        case Stage::Save: return "save";
        case Stage::Size: return "size";
        case Stage::Integrate: return "integrate";
        case Stage::Scan: return "scan";
        case Stage::Collide: return "collide";
        case Stage::Measure: return "measure";
        case Stage::Constrain: return "constrain";
        case Stage::Check: return "check";
        case Stage::Commit: return "commit";
        case Stage::Count: break;
    }
    return "?";
}

double StepProfile::total() const {
    double sum = 0.0;
    for (double t : seconds) sum += t;
    return sum;
}

Eigen::Map<const Eigen::Matrix3Xd> Simulation::positions() const {
    return {m_y.data(), 3, particleCount()};
}
Eigen::Map<const Eigen::Matrix3Xd> Simulation::velocities() const {
    return {m_y.data() + m_n, 3, particleCount()};
}

void Simulation::build() {
    m_p = resolve(m_params);
    ScaledBody scaled = buildScaledBody(m_params, m_p);
    m_body = std::move(scaled.body);
    m_scale = scaled.scale;
    m_n = 3 * m_body.topology.particleCount();
    m_forces = ForceModel(&m_body.topology, &m_body.mass, sceneTerms(m_params.kind()));
    setThreads(m_threads);
    m_boxCentre = centroid(m_body.positions);
    m_forces.prepareContact(m_body.positions.data(), m_body.fixed);

    m_invMass3 = inverseMasses(m_body);
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
    m_contactProjection =
        configureForces(m_forces, m_params, m_p, m_scale, m_body.topology.dimension, m_boxCentre);
    m_ode->configure(m_contactProjection, m_p.time.substeps);
}

void Simulation::reset() {
    const Eigen::Index n = m_n;
    m_y.setZero(2 * n + BodyOde::kAux);
    Eigen::Map<Eigen::Matrix3Xd>(m_y.data(), 3, particleCount()) = m_body.positions;
    perturbStart(m_p.start, m_invMass3, m_y.data());
    m_integrator->prepare(m_ode->layout());
    m_hNext = m_hTaken = m_p.time.dt;
    // Held only while step doubling is on (the memory bound counts what a run holds).
    if (m_integratorOptions.stepDoubling) m_doubling.prepare(m_y.size());
    else m_doubling.release();
    m_lastError = nullptr;
    m_ode->prepareEnd(m_y.size());
    m_lastGood = m_y;
    m_failure.reset();
    m_forces.pointer = PointerSpring{};
    m_diag = Diagnostics{};
    m_timeCarry = 0.0;
    m_diag.dt = m_p.time.dt;
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
    m_ode->dropEnd();
    m_lastError = nullptr;
    Eigen::Map<Eigen::Matrix3Xd>(m_y.data(), 3, particleCount()) = x;
    Eigen::Map<Eigen::Matrix3Xd>(m_y.data() + m_n, 3, particleCount()) = v;
    m_y.tail(BodyOde::kAux).setZero();
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

void Simulation::setReuseEndForces(bool on) {
    m_reuseEndForces = on;
    m_ode->dropEnd();
}

void Simulation::setProfiling(bool on) {
    m_profiling = on;
    m_profile = StepProfile{};
}

bool Simulation::step(double until) {
    if (m_failure) return false;
    if (m_profiling) ++m_profile.steps;
    StepWork w(m_diag, until);
    // The stages in their order (Stage); each returns false when the step ends there.
    return inStage(Stage::Save, [&] { return save(w); }) &&
           inStage(Stage::Size, [&] { return size(w); }) &&
           inStage(Stage::Integrate, [&] { return integrate(w); }) &&
           inStage(Stage::Scan, [&] { return scan(w); }) &&
           inStage(Stage::Collide, [&] { return collide(w); }) &&
           inStage(Stage::Measure, [&] { return measure(w); }) &&
           inStage(Stage::Constrain, [&] { return constrain(w); }) &&
           inStage(Stage::Check, [&] { return check(w); }) &&
           inStage(Stage::Commit, [&] { return commit(w); });
}

bool Simulation::save(StepWork& w) {
    // Later, in the first stage's pool run, when that stage takes the kept end-of-step
    // forces (BodyOde::offerEnd): integrators that evaluate at y before writing it.
    w.saveLater = m_reuseEndForces && m_ode->endValid() && !usesStepDoubling() && m_integrator->startsAtState();
    if (w.saveLater) return true;
    inPieces([&](int, int begin, int end) {
        // x and v of the piece's particles; the last piece also takes the energy accounts.
        const Eigen::Index b = 3 * begin, l = 3 * (end - begin);
        m_lastGood.segment(b, l) = m_y.segment(b, l);
        m_lastGood.segment(m_n + b, l) = m_y.segment(m_n + b, l);
        if (end == particleCount()) m_lastGood.tail(BodyOde::kAux) = m_y.tail(BodyOde::kAux);
    });
    return true;
}

bool Simulation::size(StepWork& w) {
    // Adaptive methods take the step they proposed, shortened to land on `until`.
    w.h = m_p.time.dt;
    w.clamped = false;
    if (!m_integrator->adaptive()) return true;
    // No particle may cross more than a tenth of the box in one adaptive step: a smooth free
    // fall has a zero error estimate and would let the step grow without bound, past the
    // onset of a contact (a force that is 0 until it is touched, so the estimate cannot see
    // it coming) or, with contact = projection, through a wall between steps.
    const double fastest = velocities().colwise().norm().maxCoeff();
    w.h = fastest > 0.0 ? std::min(m_hNext, 0.1 * m_p.world.box / fastest) : m_hNext;
    if (w.until - w.t0 > 1e-12 * std::max(1.0, std::abs(w.until)) && w.t0 + w.h > w.until) {
        w.h = w.until - w.t0;
        w.clamped = true;
    }
    return true;
}

bool Simulation::integrate(StepWork& w) {
    m_ode->offerEnd(w.saveLater ? &m_lastGood : nullptr);
    if (m_restartIntegrator) {
        m_integrator->restart();
        m_restartIntegrator = false;
    }
    w.report = usesStepDoubling() ? m_doubling.step(*m_integrator, *m_ode, w.t0, w.h, m_y)
                                  : m_integrator->step(*m_ode, w.t0, w.h, m_y);
    if (m_ode->withdrawEnd())
        throw std::logic_error(std::string(m_integrator->name()) + " wrote its state before evaluating it (startsAtState)");
    m_jacobianProducts += static_cast<std::uint64_t>(w.report.jacobianProducts);
    m_lastError = usesStepDoubling() ? m_doubling.localError() : nullptr;
    if (w.report.failure) {
        fail(w.report.failure, w);
        return false;
    }
    if (m_integrator->adaptive())
        m_hNext = w.clamped && w.report.rejected == 0 ? std::max(m_hNext, w.report.hNext) : w.report.hNext;
    m_hTaken = w.report.h;
    return true;
}

bool Simulation::scan(StepWork& w) {
    // Only the projection's collide stage reads the scan before the measurement: otherwise
    // the measurement's force evaluation takes it in its first pool run.
    w.scanLater = m_reuseEndForces && !(m_contactProjection && m_forces.terms().has(Term::Collisions));
    if (!w.scanLater) w.scan = scanState();
    return true;
}

bool Simulation::measure(StepWork& w) {
    // One measurement serves the checks, the diagnostics and the energy after the contacts.
    // (w.next starts as a copy of the run's diagnostics: the accumulated accounts go on.)
    measureState(w.next, w.scan, w.scanLater);
    return true;
}

bool Simulation::check(StepWork& w) {
    // Whatever energy the contact stages changed is measured across them and booked as
    // removed by collisions (in the new diagnostics only: a step that fails leaves the books
    // as they were).
    if (w.beforeContacts) w.next.removedCollisions += *w.beforeContacts - w.next.total();
    if (auto problem = checkState(w.next, w.scan)) {
        fail(std::move(*problem), w);
        return false;
    }
    return true;
}

bool Simulation::commit(StepWork& w) {
    m_diag = w.next;
    m_diag.step += 1;
    m_diag.time = advanceTime(w.t0, w.report.h, m_timeCarry);
    m_diag.dt = w.report.h;
    m_diag.errorEstimate = w.report.errorEstimate;
    if (m_integrator->adaptive() && w.report.errorEstimate >= 0.0) m_lastError = m_integrator->localError();
    m_diag.degenerateSprings = m_ode->extras().degenerateSprings;
    if (m_reuseEndForces) m_ode->keepEnd();
    return true;
}

void Simulation::fail(std::string reason, const StepWork& w) {
    m_failure = Failure{std::move(reason), m_diag.step + 1, w.t0};
    m_y = m_lastGood;  // keep the last good state: nothing non-finite leaves
}

bool Simulation::advanceTo(double tEnd) {
    // Round-off guard: a step that would end within 1e-9 dt of tEnd counts as reaching it.
    // Adaptive integrators land on tEnd exactly.
    while (!m_failure && m_diag.time < tEnd - 1e-9 * std::min(m_p.time.dt, nextStep())) step(tEnd);
    return !m_failure;
}

void Simulation::setIntegratorOptions(const IntegratorOptions& options) {
    m_integratorOptions = options;
    if (options.stepDoubling && !m_doubling.ready(m_y.size())) m_doubling.prepare(m_y.size());
    m_integrator->setOptions(options);
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
    m_p = resolve(m_params);
    m_ode->dropEnd();
    m_restartIntegrator = true;
    if (spec.group == ParamGroup::Mass) applyMasses();
    applyForceParams();
    if (!m_failure) m_diag.workEdits += totalEnergyNow() - before;
    measure(m_diag);
    return std::nullopt;
}

void Simulation::applyMasses() {
    const Params::Shape& shape = m_p.shape;
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

std::optional<std::string> Simulation::setIntegrator(std::string_view name) {
    auto next = makeIntegrator(name);
    if (!next) return "unknown integrator " + quoteShort(name) + "; allowed: " + integratorNames();
    m_integrator = std::move(next);
    m_ode->dropEnd();
    m_lastError = nullptr;
    m_integrator->setOptions(m_integratorOptions);
    m_integrator->prepare(m_ode->layout());
    m_hNext = m_p.time.dt;
    return std::nullopt;
}

}  // namespace simcore
