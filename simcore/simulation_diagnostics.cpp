// What a one-body simulation measures (simulation.h): the scan of a state (finiteness, extent,
// kinetic and gravity energy, fastest speed), the diagnostics (energies per part, volumes,
// pressures, counters), the energy scale and the checks a step's end state must pass, the
// error bands of the last step's estimate, and the fastest rate of the stability estimates.
#include "simcore/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "simcore/failure_texts.h"
#include "simcore/internal/body_ode.h"
#include "simcore/scan_kernels.h"

namespace simcore {

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

void Simulation::measureState(Diagnostics& d, Scan& scan, bool scanToo) {
    if (!m_reuseEndForces) {
        if (scanToo) scan = scanState();
        measureByPasses(d, scan);
        return;
    }
    // One uncounted force evaluation yields the energies and volumes, and f at this state,
    // which the next step's first stage takes instead of evaluating it again. With scanToo,
    // the scan's pieces run in the evaluation's own pool run (each chunk's task scans piece c
    // as inPieces would: the same ranges, combined in the same order, so the same bits).
    std::array<Scan, kPiecesMax> pieces;
    auto scanPieces = [&](int piece) {
        const int n = particleCount(), count = m_forces.chunks();
        pieces[static_cast<std::size_t>(piece)] = scanPiece(n * piece / count, n * (piece + 1) / count);
    };
    const TaskRef beside(scanPieces);
    const ForceExtras& extras = m_ode->measureEnd(m_y, scanToo ? &beside : nullptr);
    if (scanToo) scan = combineScans(pieces);
    fillDiagnostics(d, extras.springEnergy, extras.volume, extras.contactEnergy, scan);
}

Simulation::Scan Simulation::scanState() const {
    std::array<Scan, kPiecesMax> pieces;
    inPieces([&](int piece, int begin, int end) { pieces[static_cast<std::size_t>(piece)] = scanPiece(begin, end); });
    return combineScans(pieces);
}

Simulation::Scan Simulation::scanPiece(int begin, int end) const {
    // Four particles at a time (scan_kernels.h), the energies summed in particle order. A
    // fixed particle is the one whose y does not move (inverseMasses: a free particle moves
    // along y in every dimension).
    const kernels::StateScan k =
        kernels::scanState(m_y.data(), m_y.data() + m_n, m_invMass3.data(), m_body.mass.data(),
                           m_forces.terms().has(Term::Gravity), m_forces.params.gravity, begin, end);
    Scan s;
    s.finite = k.finite;
    s.low = Eigen::Array3d(k.low[0], k.low[1], k.low[2]);
    s.high = Eigen::Array3d(k.high[0], k.high[1], k.high[2]);
    s.kinetic = k.kinetic;
    s.gravity = k.gravity;
    s.fastest = std::sqrt(k.fastest2);
    return s;
}

Simulation::Scan Simulation::combineScans(const std::array<Scan, kPiecesMax>& pieces) const {
    const double infinity = std::numeric_limits<double>::infinity();
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

std::optional<std::string> Simulation::checkState(const Diagnostics& d, const Scan& scan) const {
    // Causes before symptoms: speed and energy first, then the shape they wreck. (The message
    // stream is built only on failure: nothing is allocated in a good step.)
    if (!scan.finite || !std::isfinite(d.total())) return failure_text::nonFinite();
    const double fastest = scan.fastest;
    if (fastest * m_hTaken > 2.0 * m_p.world.box) return failure_text::runawayVelocity(fastest);
    const double held = d.kinetic + d.springTotal() + d.pointer;
    const double budget = kRunawayEnergyFactor *
                          (m_energyScale + std::abs(m_diag.workPointer) + std::abs(m_diag.workEdits));
    if (held > budget) return failure_text::runawayEnergy(held, budget, kRunawayEnergyFactor);
    const Topology& topo = m_body.topology;
    for (const Surface& s : topo.surfaces) {
        const double volume = d.volume[static_cast<std::size_t>(layerSlot(s.layer))];
        if (volume <= kCollapsedVolumeFraction * s.restVolume)
            return failure_text::layerLost(std::nullopt, s.layer, topo.dimension, volume, s.restVolume);
    }
    return std::nullopt;
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
