#include "simcore/internal/body_ode.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "simcore/internal/jacobians.h"
#include "simcore/parallel.h"

namespace simcore {

namespace {
// to = from over n doubles, with streaming stores where `to` is 16-byte aligned: the saved
// state is read only when a step fails, so its lines need not be fetched into the cache
// first. The fence orders the stores before the pool's join publishes them.
void streamCopy(double* to, const double* from, Eigen::Index n) {
    Eigen::Index i = 0;
#if defined(__SSE2__)
    for (; i < n && (reinterpret_cast<std::uintptr_t>(to + i) & 15) != 0; ++i) to[i] = from[i];
    for (; i + 2 <= n; i += 2) _mm_stream_pd(to + i, _mm_loadu_pd(from + i));
    for (; i < n; ++i) to[i] = from[i];
    _mm_sfence();
#else
    std::copy(from, from + n, to);
#endif
}
}  // namespace

void BodyOde::derivative(double /*t*/, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    if (!takeOffered(y, dydt, nullptr)) compute(y, dydt, m_extras, true);
}

void BodyOde::derivative(double /*t*/, const Eigen::VectorXd& y, Eigen::VectorXd& dydt, RangeWork then) {
    if (!takeOffered(y, dydt, &then)) compute(y, dydt, m_extras, true, &then);
}

void BodyOde::derivativeMotion(double /*t*/, const Eigen::VectorXd& y, Eigen::VectorXd& dydt, RangeWork then) {
    if (!takeOffered(y, dydt, &then, false)) compute(y, dydt, m_extras, true, &then, false);
}

bool BodyOde::takeOffered(const Eigen::VectorXd& y, Eigen::VectorXd& dydt, const RangeWork* then, bool xdot) {
    // Offered to one call only: a first stage elsewhere than at the measured state withdraws it.
    Eigen::VectorXd* saveTo = std::exchange(m_saveTo, nullptr);
    const bool offered = std::exchange(m_offered, false);
    if (!offered || &y != m_endAt) {
        if (saveTo) *saveTo = *m_endAt;  // not written yet (offerEnd's contract)
        return false;
    }
    // The save rides on the pool run below: each range of y copied before `then` writes it
    // (without xdot, a range of v hands over x's range too: derivativeMotion).
    const Eigen::Index n = positions();
    auto saving = [&y, saveTo, caller = then, xdot, n](Eigen::Index begin, Eigen::Index length) {
        streamCopy(saveTo->data() + begin, y.data() + begin, length);
        if (!xdot && begin < 2 * n)
            streamCopy(saveTo->data() + begin - n, y.data() + begin - n, std::min(length, 2 * n - begin));
        if (caller) (*caller)(begin, length);
    };
    const RangeWork savingWork(saving);
    if (saveTo) then = &savingWork;
    dydt.swap(m_end);  // no copy: the two buffers trade places (the cache is spent)
    m_extras = m_endExtras;
    m_forces.countReusedEvaluation();
    // The measurement's last stage, held back until now, writes its xdot and a (in the buffer
    // dydt now holds) and runs `then` on them in the same pool run; when it was already written
    // (a restored cache, or written for a checkpoint), `then` alone.
    if (m_forces.finishMotion(then, xdot)) {
        if (then) (*then)(2 * n, kAux);
    } else if (then) {
        const Eigen::Index from = xdot ? 0 : n;
        inPieces(dydt.size() - from, [&](Eigen::Index b, Eigen::Index l) { (*then)(from + b, l); });
    }
    return true;
}

void BodyOde::compute(const Eigen::VectorXd& y, Eigen::VectorXd& dydt, ForceExtras& extras, bool count,
                      const RangeWork* then, bool xdot) {
    const Eigen::Index n = positions();
    m_forces.evaluateMotion(y.data(), y.data() + n, m_invMass.data(), xdot ? dydt.data() : nullptr,
                            dydt.data() + n, extras, count, then);
    dydt[2 * n] = extras.dampingPower;
    dydt[2 * n + 1] = extras.contactPower;
    if (then) (*then)(2 * n, kAux);
}

int BodyOde::pieces() const { return m_forces.pool() ? m_forces.pool()->threads() : 1; }

void BodyOde::runPieces(TaskRef task) {
    if (ThreadPool* pool = m_forces.pool())
        pool->run(pool->threads(), task);
    else
        task(0);
}

const ForceExtras& BodyOde::measureEnd(const Eigen::VectorXd& y, const TaskRef* beside) {
    // Its last stage (the unpadding of a = F/m and xdot = v) is held back: the next step's
    // first stage runs it in its own pool run (takeOffered), one run per step fewer.
    const Eigen::Index n = positions();
    m_forces.evaluateMotionDeferred(y.data(), y.data() + n, m_invMass.data(), m_end.data(), m_end.data() + n,
                                    m_endExtras, false, beside);
    m_end[2 * n] = m_endExtras.dampingPower;
    m_end[2 * n + 1] = m_endExtras.contactPower;
    m_endAt = &y;
    return m_endExtras;
}

const Eigen::VectorXd& BodyOde::endDerivative() const {
    m_forces.finishMotion();
    return m_end;
}

void BodyOde::restoreEnd(const Eigen::VectorXd& y, const Eigen::VectorXd& derivative, const ForceExtras& extras) {
    m_forces.dropMotion();
    m_end = derivative;
    m_endExtras = extras;
    m_endAt = &y;
    m_endValid = true;
}

void BodyOde::linearize(double /*t*/, const Eigen::VectorXd& y) {
    const Eigen::Index n = positions();
    m_x = y.head(n);
    m_mass.resize(n);
    for (Eigen::Index k = 0; k < n; ++k) m_mass[k] = m_invMass[k] > 0.0 ? 1.0 / m_invMass[k] : 0.0;
    const Topology& topo = m_body.topology;
    linearizeContact(y);
    m_gasOn = m_forces.terms().has(Term::Gas);
    if (!m_gasOn) return;
    for (const Surface& s : topo.surfaces) {
        const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
        m_gradient[slot].setZero(n);
        addVolumeGradient(s, topo.dimension, m_x.data(), m_gradient[slot].data());
        m_volume[slot] = enclosedVolume(s, m_x.data(), topo.dimension);
    }
}

void BodyOde::forceJacobianProduct(const Eigen::VectorXd& dx, const Eigen::VectorXd& dv, Eigen::VectorXd& out) {
    out.setZero();
    const Topology& topo = m_body.topology;
    const ForceParams& p = m_forces.params;
    if (m_forces.terms().has(Term::Springs))
        for (int f = 0; f < kSpringFamilyCount; ++f) {
            const auto k = static_cast<std::size_t>(f);
            addSpringJacobianProduct(topo.springs[k], p.stiffness[k], p.damping[k], m_x.data(), dx.data(), dv.data(), out.data());
        }
    if (m_gasOn)
        for (const Surface& s : topo.surfaces) {
            const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
            addGasJacobianProduct(s, topo.dimension, p.gasConstant[slot], m_volume[slot], m_gradient[slot],
                                  m_x.data(), dx.data(), out.data());
        }
    if (m_forces.terms().has(Term::Pointer))
        addPointerJacobianProduct(m_forces.pointer, p.mks, p.mkd, p.mouseRest, m_x.data(), dx.data(), dv.data(),
                                  out.data());
    if (m_contactOn) {
        out += m_contactK.cwiseProduct(dx) + m_contactD.cwiseProduct(dv);
        addBarrierProduct(dx, out);
    }
    for (Eigen::Index k = 0; k < out.size(); ++k)
        if (m_mass[k] == 0.0) out[k] = 0.0;
}

void BodyOde::forceJacobianDiagonal(Eigen::VectorXd& kdiag, Eigen::VectorXd& ddiag) {
    kdiag.setZero();
    ddiag.setZero();
    const Topology& topo = m_body.topology;
    const ForceParams& p = m_forces.params;
    if (m_forces.terms().has(Term::Springs))
        for (int f = 0; f < kSpringFamilyCount; ++f) {
            const auto k = static_cast<std::size_t>(f);
            addSpringJacobianDiagonal(topo.springs[k], p.stiffness[k], p.damping[k], m_x.data(), kdiag.data(), ddiag.data());
        }
    if (m_gasOn)
        for (const Surface& s : topo.surfaces) {
            const auto slot = static_cast<std::size_t>(layerSlot(s.layer));
            addGasJacobianDiagonal(p.gasConstant[slot], m_volume[slot], m_gradient[slot], kdiag.data());
        }
    if (m_forces.terms().has(Term::Pointer))
        addPointerJacobianDiagonal(m_forces.pointer, p.mks, p.mkd, p.mouseRest, m_x.data(), kdiag.data(),
                                   ddiag.data());
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
// K = -3 k q^2 n n^T on the pair (n = dq/dx_i = sqrt2 g / sqrt(|g|^2 + g0^2), +n on the inner
// particle, -n on the outer); the curvature of q and the coupling to the fan are left out (the
// barrier is rarely active; implicit-euler's linearisation only has to be close, not exact).
// Extra contact stiffness may be added at a chosen design point (stability estimates).
void BodyOde::linearizeContact(const Eigen::VectorXd& y) {
    const Eigen::Index n = positions();
    m_contactOn = m_forces.contactWalls() || m_forces.contactBarrier() || m_design;
    m_barrierActive.clear();
    if (!m_contactOn) return;
    // Sized once (the first linearisation), not per step.
    if (m_barrierActive.capacity() < m_forces.barrierPairs().size())
        m_barrierActive.reserve(m_forces.barrierPairs().size());
    m_contactK.setZero(n);
    m_contactD.setZero(n);
    const double* x = y.data();
    const double* v = y.data() + n;
    if (m_forces.contactWalls())
        for (int i = 0; i < m_body.topology.particleCount(); ++i)
            if (!m_body.fixed[static_cast<std::size_t>(i)] && outsideWalls(m_forces.contact, x + 3 * i))
                addWallContactJacobian(m_forces.contact, x + 3 * i, v + 3 * i, m_contactK.data() + 3 * i,
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
    if (m_forces.contactBarrier()) {
        const LayerBarrierSet& pairs = m_forces.barrierPairs();
        const int dim = m_body.topology.dimension;
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            const auto g = layerBarrierNormal(pairs, k, dim, x);
            const int in = pairs.inner[k], out = pairs.outer[k];
            const double along = (x[3 * in] - x[3 * out]) * g[0] + (x[3 * in + 1] - x[3 * out + 1]) * g[1] +
                                 (x[3 * in + 2] - x[3 * out + 2]) * g[2];
            if (!(along > 0.0)) continue;
            const double g02 = 1.0 / (pairs.invRestNorm[k] * pairs.invRestNorm[k]);
            const double inv = kSqrt2 / std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] + g02);
            const double q = along * inv;
            ActiveBarrier b{in, out, 3.0 * m_forces.contact.stiffness * q * q, {}};
            for (int a = 0; a < 3; ++a) b.normal[static_cast<std::size_t>(a)] = g[static_cast<std::size_t>(a)] * inv;
            m_barrierActive.push_back(b);
        }
    }
}

void BodyOde::addBarrierProduct(const Eigen::VectorXd& dx, Eigen::VectorXd& out) const {
    for (const ActiveBarrier& b : m_barrierActive) {
        double along = 0.0;
        for (int a = 0; a < 3; ++a)
            along += b.normal[static_cast<std::size_t>(a)] * (dx[3 * b.inner + a] - dx[3 * b.outer + a]);
        for (int a = 0; a < 3; ++a) {
            out[3 * b.inner + a] -= b.stiffness * along * b.normal[static_cast<std::size_t>(a)];
            out[3 * b.outer + a] += b.stiffness * along * b.normal[static_cast<std::size_t>(a)];
        }
    }
}

bool BodyOde::distanceConstraints(DistanceConstraints& out) {
    const Topology& topo = m_body.topology;
    const ForceParams& p = m_forces.params;
    const bool springs = m_forces.terms().has(Term::Springs);
    for (int f = 0; f < kSpringFamilyCount; ++f) {
        const auto k = static_cast<std::size_t>(f);
        const SpringSet& set = topo.springs[k];
        out.families[k] = {set.a, set.b, set.rest, springs ? p.stiffness[k] : 0.0, springs ? p.damping[k] : 0.0};
    }
    out.inverseMass = &m_invMass;
    out.substeps = m_substeps;
    return true;
}

bool BodyOde::stronglyNonlinear(double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& v1) {
    if (!m_forces.contactWalls()) return false;
    const ContactParams& c = m_forces.contact;
    for (Eigen::Index k = 0; k < positions(); ++k) {
        if (m_mass[k] == 0.0) continue;
        const auto axis = static_cast<std::size_t>(k % 3);
        const double end = y0[k] + h * v1[k];
        if (end < c.low[axis] || end > c.high[axis]) return true;
    }
    return false;
}

int BodyOde::contactVelocities(double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& v1,
                               Eigen::VectorXd& target) {
    // The box planes of the projection (Simulation's collide stage; the force model's wall
    // planes, which are the box on every axis a coordinate with mass moves along): a free
    // coordinate that would end outside lands on its wall, and the collide stage then applies
    // restitution to it after the step. Only with contact = projection: as a force, contact is
    // in F and its Jacobians.
    if (!m_forces.terms().has(Term::Collisions) || !m_contactProjection) return 0;
    const ContactParams& c = m_forces.contact;
    // Deepest first: only coordinates that penetrate at least half as deep as the deepest
    // are marked in one pass. A particle behind another (an inner-layer particle above
    // an outer one on the floor) is then held by its springs once the front one is
    // stopped, instead of being stopped by the wall it would never have reached.
    auto penetration = [&](Eigen::Index k, double& wall) {
        const auto axis = static_cast<std::size_t>(k % 3);
        const double lo = c.low[axis], hi = c.high[axis];
        const double end = y0[k] + h * v1[k];
        wall = end < lo ? lo : hi;
        return end < lo ? lo - end : end > hi ? end - hi : 0.0;
    };
    const Eigen::Index n = positions();
    double deepest = 0.0, wall = 0.0;
    for (Eigen::Index k = 0; k < n; ++k)
        if (m_mass[k] != 0.0 && !std::isfinite(target[k])) deepest = std::max(deepest, penetration(k, wall));
    if (deepest <= 0.0) return 0;
    int marked = 0;
    for (Eigen::Index k = 0; k < n; ++k) {
        if (m_mass[k] == 0.0 || std::isfinite(target[k])) continue;
        if (penetration(k, wall) < 0.5 * deepest) continue;
        target[k] = (wall - y0[k]) / h;
        ++marked;
    }
    return marked;
}

}  // namespace simcore
