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

void Simulation::startBookkeeping() {
    measure(m_diag);
    m_diag.initialEnergy = m_diag.total();
    // Energy scale for blow-up detection: what the body could plausibly hold. Gravity over
    // the box height, every spring stretched by its rest length, the gas expanding 100-fold.
    const Topology& topo = m_body.topology;
    double scale = 1.0 + m_diag.kinetic + m_diag.springTotal();
    scale += m_body.mass.sum() * m_forces.params.gravity * 2.0 * m_p.world.box;
    for (int f = 0; f < kSpringFamilyCount; ++f) {
        const auto k = static_cast<std::size_t>(f);
        for (double rest : topo.springs[k].rest) scale += 0.5 * m_forces.params.stiffness[k] * rest * rest;
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
    if (!m_reuseEndForces) {
        measureByPasses(d, scan);
        return;
    }
    // One uncounted force evaluation yields the energies and volumes, and f at this state,
    // which the next step's first stage takes instead of evaluating it again.
    const ForceExtras& extras = m_ode->measureEnd(m_y);
    fillDiagnostics(d, extras.springEnergy, extras.volume, extras.contactEnergy, scan);
}

void Simulation::setReuseEndForces(bool on) {
    m_reuseEndForces = on;
    m_ode->dropEnd();
}

void Simulation::setProfiling(bool on) {
    m_profiling = on;
    m_profile = StepProfile{};
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
    if (m_profiling) ++m_profile.steps;
    StepWork w(m_diag, until);
    // The stages in their order (Stage); each returns false when the step ends there.
    return inStage(Stage::Save, [&] { return save(); }) &&
           inStage(Stage::Size, [&] { return size(w); }) &&
           inStage(Stage::Integrate, [&] { return integrate(w); }) &&
           inStage(Stage::Scan, [&] { return scan(w); }) &&
           inStage(Stage::Collide, [&] { return collide(w); }) &&
           inStage(Stage::Measure, [&] { return measure(w); }) &&
           inStage(Stage::Constrain, [&] { return constrain(w); }) &&
           inStage(Stage::Check, [&] { return check(w); }) &&
           inStage(Stage::Commit, [&] { return commit(w); });
}

bool Simulation::save() {
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
    m_ode->offerEnd();
    if (m_restartIntegrator) {
        m_integrator->restart();
        m_restartIntegrator = false;
    }
    w.report = usesStepDoubling() ? m_doubling.step(*m_integrator, *m_ode, w.t0, w.h, m_y)
                                  : m_integrator->step(*m_ode, w.t0, w.h, m_y);
    m_ode->withdrawEnd();
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
    w.scan = scanState();
    return true;
}

bool Simulation::measure(StepWork& w) {
    // One measurement serves the checks, the diagnostics and the energy after the contacts.
    // (w.next starts as a copy of the run's diagnostics: the accumulated accounts go on.)
    measureState(w.next, w.scan);
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

std::optional<std::string> Simulation::checkState(const Diagnostics& d, const Scan& scan) const {
    // Causes before symptoms: speed and energy first, then the shape they wreck. (The message
    // stream is built only on failure: nothing is allocated in a good step.)
    if (!scan.finite || !std::isfinite(d.total())) return std::string("the state became non-finite (NaN or infinity): the step is far too large for these forces");
    const double fastest = scan.fastest;
    if (fastest * m_hTaken > 2.0 * m_p.world.box) {
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
    s.endValid = m_ode->endValid();
    if (s.endValid) {
        s.endDerivative = m_ode->endDerivative();
        s.endExtras = m_ode->endExtras();
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
    m_p = resolve(m_params);
    applyMasses();
    applyForceParams();
    if (m_integrator->name() != s.integrator) {
        auto next = makeIntegrator(s.integrator);
        if (!next) throw std::invalid_argument("unknown integrator " + quoteShort(s.integrator));
        m_integrator = std::move(next);
        m_integrator->prepare(m_ode->layout());
    }
    setIntegratorOptions(s.options);
    m_integrator->setHistory(s.integratorHistory);
    m_y = s.y;
    m_lastGood = s.y;
    if (s.endValid)
        m_ode->restoreEnd(m_y, s.endDerivative, s.endExtras);
    else
        m_ode->dropEnd();
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
    if (!next) return "unknown integrator " + quoteShort(name) + "; allowed: " + integratorNames();
    m_integrator = std::move(next);
    m_ode->dropEnd();
    m_lastError = nullptr;
    m_integrator->setOptions(m_integratorOptions);
    m_integrator->prepare(m_ode->layout());
    m_hNext = m_p.time.dt;
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
    return simcore::pickAlongRay(m_body.topology.layer, positions().data(), origin, direction, maxDistance);
}

void Simulation::grab(int particle, const Eigen::Vector3d& anchor) {
    if (particle < 0 || particle >= particleCount() || m_failure) return;
    // Creating the spring stores energy: that is work done by the pointer.
    const double before = m_diag.pointer;
    m_ode->dropEnd();
    m_restartIntegrator = true;
    m_forces.pointer = PointerSpring{true, particle, anchor};
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

void Simulation::moveAnchor(const Eigen::Vector3d& anchor) {
    if (!m_forces.pointer.active || m_failure) return;
    // The anchor moves between steps; the change in the spring's energy is the pointer's work.
    const double before = m_diag.pointer;
    m_ode->dropEnd();
    m_restartIntegrator = true;
    m_forces.pointer.anchor = anchor;
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

void Simulation::release() {
    if (!m_forces.pointer.active) return;
    const double before = m_diag.pointer;
    m_ode->dropEnd();
    m_restartIntegrator = true;
    m_forces.pointer = PointerSpring{};
    measure(m_diag);
    m_diag.workPointer += m_diag.pointer - before;
}

double Simulation::estimatedFastestRate() const {
    // Each particle alone, tied to fixed neighbours by its springs: m s^2 + c s + k = 0 with
    // k = sum of stiffness and c = sum of damping over its springs (springs in different directions do not all
    // act on one displacement, so this is an estimate, not a bound). |s| is sqrt(k/m) when underdamped and the fast root
    // (c + sqrt(c^2 - 4mk)) / 2m when overdamped: stiff damping limits explicit steps too.
    const Topology& topo = m_body.topology;
    Eigen::VectorXd k = Eigen::VectorXd::Zero(particleCount());
    Eigen::VectorXd c = Eigen::VectorXd::Zero(particleCount());
    for (int f = 0; f < kSpringFamilyCount; ++f) {
        const auto fam = static_cast<std::size_t>(f);
        for (std::size_t s = 0; s < topo.springs[fam].size(); ++s)
            for (int end : {topo.springs[fam].a[s], topo.springs[fam].b[s]}) {
                k[end] += m_forces.params.stiffness[fam];
                c[end] += m_forces.params.damping[fam];
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
