#include "simlab/gallery.h"

#include <cmath>
#include <cstdio>

#include "simcore/simulation.h"
#include "simlab/stability.h"

namespace simlab {

using simcore::Param;
using simcore::ParameterSet;
using simcore::SceneKind;
using simcore::Simulation;

namespace {

using Sets = std::vector<std::pair<Param, double>>;

GalleryCase make(std::string name, std::string description, SceneKind scene, Sets set, std::string integrator,
                 double duration, bool stable, std::string reason = "") {
    GalleryCase c;
    c.name = std::move(name);
    c.description = std::move(description);
    c.scene = scene;
    c.set = std::move(set);
    c.integrator = std::move(integrator);
    c.duration = duration;
    c.expectStable = stable;
    c.expectReason = std::move(reason);
    return c;
}

// Kept whole: a table, one case (or one loop of cases) after another, read top to bottom.
std::vector<GalleryCase> buildCases() {
    std::vector<GalleryCase> cases;
    const auto ring = SceneKind::Ring2d;
    // --- stiff springs: KS 1e5 - 1e7 with small masses ---
    cases.push_back(make("stiff-1e5-rk4-small-step", "KS=RKS=1e5, mass 0.1 kg, rk4 at dt 1e-4 (below its limit)", ring,
                         {{Param::Ks, 1e5}, {Param::Rks, 1e5}, {Param::Mass, 0.1}, {Param::Dt, 1e-4}}, "rk4", 0.5, true));
    {
        GalleryCase c = make("stiff-1e5-rk4-too-large", "KS=RKS=1e5, mass 0.1 kg, rk4 at dt 0.003: detected", ring,
                             {{Param::Ks, 1e5}, {Param::Rks, 1e5}, {Param::Mass, 0.1}, {Param::Dt, 0.003}}, "rk4", 0.5, false, "runaway");
        c.expectWarning = true;
        cases.push_back(c);
    }
    {
        GalleryCase c = make("stiff-1e6-rk4-fails", "KS 1e6 at dt 0.01: every explicit method fails; rk4 shown", ring,
                             {{Param::Ks, 1e6}, {Param::Dt, 0.01}}, "rk4", 1.0, false, "runaway");
        c.expectWarning = true;
        cases.push_back(c);
    }
    {
        GalleryCase c = make("stiff-1e6-implicit", "KS 1e6 at dt 0.01: implicit-euler stays stable", ring,
                             {{Param::Ks, 1e6}, {Param::Dt, 0.01}}, "implicit-euler", 5.0, true);
        c.lossAllowed = true;
        c.driftTolerance = 0.1;
        cases.push_back(c);
    }
    {
        GalleryCase c = make("stiff-1e7-light-implicit", "KS=RKS=1e7, mass 0.01 kg at dt 0.01: implicit-euler", ring,
                             {{Param::Ks, 1e7}, {Param::Rks, 1e7}, {Param::Mass, 0.01}, {Param::Dt, 0.01}}, "implicit-euler", 2.0, true);
        c.lossAllowed = true;
        c.driftTolerance = 0.1;
        cases.push_back(c);
    }
    {
        GalleryCase c = make("stiff-1e7-light-euler-fails", "KS=RKS=1e7, mass 0.01 kg at dt 0.01: euler", ring,
                             {{Param::Ks, 1e7}, {Param::Rks, 1e7}, {Param::Mass, 0.01}, {Param::Dt, 0.01}}, "euler", 1.0, false, "runaway");
        c.expectWarning = true;
        cases.push_back(c);
    }
    // --- the thesis's stability experiment (§7.2.2) on the two-layer ring, thesis defaults ---
    // Outcomes measured on this model (docs/model.md): the two-layer ring's highest mode is far
    // above the single ring's ~55 rad/s, so even rk4 fails at DT 0.03.
    struct Thesis {
        const char* integrator;
        double dt;
        bool stable;
        const char* reason;
    };
    const Thesis thesis[] = {
        {"euler", 0.003, true, ""},           {"euler", 0.03, false, "runaway"},
        {"euler", 0.3, false, "runaway"},     {"midpoint", 0.003, true, ""},
        {"midpoint", 0.03, false, ""},        {"midpoint", 0.3, false, "runaway"},
        {"rk4", 0.003, true, ""},             {"rk4", 0.03, false, "runaway"},
        {"rk4", 0.3, false, "runaway"},       {"symplectic-euler", 0.003, true, ""},
        {"symplectic-euler", 0.03, false, "runaway"}, {"symplectic-euler", 0.3, false, "runaway"},
        {"verlet", 0.003, true, ""},          {"verlet", 0.03, false, "runaway"},
        {"verlet", 0.3, false, "runaway"},    {"rk45", 0.003, true, ""},
        {"rk45", 0.03, true, ""},             {"rk45", 0.3, true, ""},
        {"implicit-euler", 0.003, true, ""},  {"implicit-euler", 0.03, true, ""},
        {"implicit-euler", 0.3, true, ""},
    };
    for (const Thesis& t : thesis) {
        char name[64];
        std::snprintf(name, sizeof name, "thesis-dt%g-%s", t.dt, t.integrator);
        char text[160];
        std::snprintf(text, sizeof text, "thesis defaults, two-layer ring, DT %g, %s%s", t.dt, t.integrator,
                      std::string(t.integrator) == "rk45" ? " (adaptive: dt is only its first step)" : "");
        GalleryCase c = make(name, text, ring, {{Param::Dt, t.dt}}, t.integrator, 5.0, t.stable, t.reason);
        c.expectWarning = !t.stable;
        if (std::string(t.integrator) == "implicit-euler") c.lossAllowed = true, c.driftTolerance = 0.1;
        // First order at 0.003: explicit Euler gains ~27% of the energy scale over 5 s (its
        // growth on every oscillating mode), symplectic Euler loses ~13%; both finish.
        if (std::string(t.integrator) == "euler") c.driftTolerance = 0.5;
        if (std::string(t.integrator) == "symplectic-euler") c.driftTolerance = 0.25;
        cases.push_back(c);
    }
    // --- docs/model.md's single pressurised ring (w ~ 55 rad/s): the two layers decoupled
    // (RKS = RKD = 0), weightless, perturbed. Euler fails at DT 0.03 but not 0.003, midpoint
    // and rk4 survive 0.03, no explicit method survives 0.3. ---
    const Sets single = {{Param::Rks, 0.0}, {Param::Rkd, 0.0}, {Param::Gravity, 0.0}, {Param::Perturb, 0.01}};
    auto singleRing = [&](const char* integrator, double dt, bool stable) {
        Sets set = single;
        set.emplace_back(Param::Dt, dt);
        char name[64], text[160];
        std::snprintf(name, sizeof name, "single-rings-dt%g-%s", dt, integrator);
        std::snprintf(text, sizeof text, "decoupled single rings (docs/model.md, w ~ 55 rad/s), DT %g, %s", dt, integrator);
        GalleryCase c = make(name, text, ring, set, integrator, 3.0, stable, "");
        // The energy scale here is only the perturbation's (~1.4 J): midpoint's start-up error
        // of 0.94 J then stays constant (checked to 30 s), i.e. bounded.
        c.driftTolerance = 1.0;
        return c;
    };
    cases.push_back(singleRing("euler", 0.003, true));
    cases.push_back(singleRing("euler", 0.03, false));
    cases.push_back(singleRing("midpoint", 0.03, true));
    cases.push_back(singleRing("rk4", 0.03, true));
    cases.push_back(singleRing("rk4", 0.3, false));
    // --- mass ratio 100:1 ---
    // A 100 kg inner particle weighs 981 N against 700 N/m radius springs: the inner layer
    // sinks through and collapses. Physics, detected with its reason, whatever the method.
    cases.push_back(make("heavy-inner-collapses-rk4", "inner 100 kg, outer 1 kg per particle, gravity on: the inner "
                         "layer collapses under its weight (detected)", ring,
                         {{Param::MassInner, 100.0}, {Param::MassOuter, 1.0}, {Param::Dt, 0.003}}, "rk4", 3.0, false, "collapsed"));
    cases.push_back(make("heavy-inner-weightless-rk4", "inner 100 kg, outer 1 kg, no gravity, perturbed: rk4 at dt 0.003",
                         ring, {{Param::MassInner, 100.0}, {Param::MassOuter, 1.0}, {Param::Gravity, 0.0}, {Param::Perturb, 0.05}, {Param::Dt, 0.003}},
                         "rk4", 3.0, true));
    {
        // Mass ratio 100:1 the other way: 10 g outer particles make the fastest mode 10x faster.
        GalleryCase c = make("light-outer-rk4-fails", "inner 1 kg, outer 0.01 kg: rk4 at dt 0.003 is above its limit",
                             ring, {{Param::MassInner, 1.0}, {Param::MassOuter, 0.01}, {Param::Dt, 0.003}}, "rk4", 2.0, false, "");
        c.expectWarning = true;
        cases.push_back(c);
    }
    {
        GalleryCase c = make("light-outer-implicit", "inner 1 kg, outer 0.01 kg: implicit-euler at dt 0.003", ring,
                             {{Param::MassInner, 1.0}, {Param::MassOuter, 0.01}, {Param::Dt, 0.003}}, "implicit-euler", 2.0, true);
        c.lossAllowed = true;
        c.driftTolerance = 0.1;
        cases.push_back(c);
    }
    // --- pressure extremes ---
    cases.push_back(make("pressure-high-rk4", "nRT = 2000 J (100x the default), rk4 at dt 0.001", ring,
                         {{Param::Pressure, 2000.0}, {Param::Dt, 0.001}}, "rk4", 2.0, true));
    // The ring bursts into the walls at ~130 m/s: the contact force's stiffness and damping at
    // that depth (k d^3 alpha ~ 1e5 1/s per particle) need dt 0.00025; the projection of the
    // thesis program took any impact in one step (contact = force since issue 11).
    cases.push_back(make("pressure-extreme-rk4", "nRT = 1e5 J (5000x): the ring inflates into the walls, rk4 at dt 0.00025",
                         ring, {{Param::Pressure, 1e5}, {Param::Dt, 0.00025}}, "rk4", 2.0, true));
    {
        GalleryCase c = make("pressure-extreme-implicit", "nRT = 1e5 J, implicit-euler at dt 0.003", ring,
                             {{Param::Pressure, 1e5}, {Param::Dt, 0.003}}, "implicit-euler", 2.0, true);
        c.lossAllowed = true;
        c.driftTolerance = 0.1;
        cases.push_back(c);
    }
    // Without gas the 2D ring's springs alone cannot hold it up on the floor: it folds.
    cases.push_back(make("pressure-zero-collapses-rk4", "no gas (nRT = 0): the 2D ring folds on the floor (detected)",
                         ring, {{Param::Pressure, 0.0}, {Param::Dt, 0.003}}, "rk4", 3.0, false, "collapsed"));
    cases.push_back(make("pressure-zero-weightless-rk4", "no gas, no gravity, perturbed: rk4 at dt 0.003", ring,
                         {{Param::Pressure, 0.0}, {Param::Gravity, 0.0}, {Param::Perturb, 0.05}, {Param::Dt, 0.003}}, "rk4", 3.0, true));
    cases.push_back(make("pressure-zero-3d-rk4", "3D sphere without gas, rk4 at dt 0.003", SceneKind::Sphere3d,
                         {{Param::Pressure, 0.0}, {Param::Subdivisions, 1.0}, {Param::Dt, 0.003}}, "rk4", 2.0, true));
    // --- high-speed impact ---
    {
        GalleryCase c = make("impact-5mps-rk4", "launched at 5 m/s onto the floor (1.6x the default drop speed), rk4 at dt 0.001", ring,
                             {{Param::Dt, 0.001}}, "rk4", 1.0, true);
        c.launch = Eigen::Vector3d(0.0, -5.0, 0.0);
        cases.push_back(c);
    }
    {
        GalleryCase c = make("impact-30mps-rk4", "launched at 30 m/s onto the floor: crushed (detected; already at 10 m/s the inner layer folds)", ring,
                             {{Param::Dt, 0.001}}, "rk4", 1.0, false, "inner layer");
        c.launch = Eigen::Vector3d(0.0, -30.0, 0.0);
        cases.push_back(c);
    }
    {
        GalleryCase c = make("impact-300mps-rk4", "launched at 300 m/s onto the floor, rk4 at dt 0.003: detected",
                             ring, {{Param::Dt, 0.003}}, "rk4", 1.0, false, "");
        c.launch = Eigen::Vector3d(0.0, -300.0, 0.0);
        cases.push_back(c);
    }
    {
        GalleryCase c = make("impact-10mps-implicit", "launched at 10 m/s, implicit-euler at dt 0.01: survives where rk4 folds, by numerical damping", ring,
                             {{Param::Dt, 0.01}}, "implicit-euler", 1.0, true);
        c.launch = Eigen::Vector3d(0.0, -10.0, 0.0);
        c.lossAllowed = true;
        c.driftTolerance = 0.1;
        cases.push_back(c);
    }
    // --- nearly coincident particles ---
    cases.push_back(make("near-coincident-layers", "radius_inner 1.999, radius_outer 2: radius springs 1 mm long, rk4",
                         ring, {{Param::RadiusInner, 1.999}, {Param::Dt, 0.001}}, "rk4", 1.0, true));
    cases.push_back(make("near-coincident-spring1d", "1D spring of rest length 1 um starting at 1 um, rk4 at dt 1e-4",
                         SceneKind::Spring1d, {{Param::Length, 1e-6}, {Param::InitialLength, 1e-6}, {Param::Dt, 1e-4}}, "rk4", 0.5,
                         true));
    // --- restitution extremes ---
    // e = 0 as a contact force would need unbounded damping (alpha = zeta(e) / v_ref with
    // zeta -> infinity, docs/numerics.md): perfectly inelastic walls are the projection's.
    cases.push_back(make("restitution-0", "perfectly inelastic walls (e = 0, contact = projection), rk4 at dt 0.003", ring,
                         {{Param::Restitution, 0.0}, {Param::Dt, 0.003}, {Param::Contact, 1.0}}, "rk4", 3.0, true));
    cases.push_back(make("restitution-1", "perfectly elastic walls (e = 1), rk4 at dt 0.003", ring,
                         {{Param::Restitution, 1.0}, {Param::Dt, 0.003}}, "rk4", 3.0, true));
    // --- production solvers (issue 13): CVODE's BDF and XPBD on the two kinds of stiffness ---
    // Dissipative stiffness (overdamped springs: real eigenvalues down to -2 kd / m): BDF's
    // steps follow the slow motion (measured at atol = rtol = 1e-4: 80 steps, 6,903 force
    // evaluations with the Jacobian products, against rk45's 329,791). BDF wins.
    cases.push_back(make("stiff-dissipative-cvode-bdf",
                         "KS=KD=RKS=RKD=1e4, weightless, perturbed: cvode-bdf takes steps of the slow motion", ring,
                         {{Param::Ks, 1e4}, {Param::Kd, 1e4}, {Param::Rks, 1e4}, {Param::Rkd, 1e4}, {Param::Gravity, 0.0}, {Param::Perturb, 0.1}},
                         "cvode-bdf", 2.0, true));
    // Oscillatory stiffness (stiff, lightly damped springs: eigenvalues near the imaginary
    // axis): to be accurate BDF must follow every oscillation, and BDF 3-5 are not stable on
    // the imaginary axis, so it gains nothing (measured at 1e-4: 21,459 force evaluations and
    // products against rk45's 7,602). BDF loses.
    cases.push_back(make("stiff-oscillatory-cvode-bdf",
                         "KS=RKS=1e6, weightless, perturbed 0.05: cvode-bdf must resolve the oscillation", ring,
                         {{Param::Ks, 1e6}, {Param::Rks, 1e6}, {Param::Gravity, 0.0}, {Param::Perturb, 0.05}}, "cvode-bdf", 0.5, true));
    {
        // The same stiff ring at a game's DT 1/60 (RK4 fails: stiff-1e6-rk4-fails): XPBD with
        // its default 8 substeps stays stable, dissipating (one-sided drift).
        GalleryCase c = make("stiff-1e6-xpbd-60hz", "KS=RKS=1e6, weightless, perturbed 0.05, xpbd at dt 1/60 (8 substeps)",
                             ring, {{Param::Ks, 1e6}, {Param::Rks, 1e6}, {Param::Gravity, 0.0}, {Param::Perturb, 0.05}, {Param::Dt, 1.0 / 60.0}},
                             "xpbd", 5.0, true);
        c.lossAllowed = true;
        cases.push_back(c);
    }
    return cases;
}

}  // namespace

const std::vector<GalleryCase>& galleryCases() {
    static const std::vector<GalleryCase> cases = buildCases();
    return cases;
}

const GalleryCase* findGalleryCase(const std::string& name) {
    for (const GalleryCase& c : galleryCases())
        if (c.name == name) return &c;
    return nullptr;
}

ParameterSet galleryParameters(const GalleryCase& c) {
    ParameterSet p(c.scene);
    for (const auto& [id, value] : c.set)
        if (auto error = p.set(id, value)) throw std::invalid_argument("gallery case " + c.name + ": " + *error);
    return p;
}

GalleryOutcome runGalleryCase(const GalleryCase& c) {
    GalleryOutcome o;
    Simulation sim(galleryParameters(c), c.integrator);
    o.warned = preRunStabilityWarning(sim).has_value();
    if (c.launch.squaredNorm() > 0.0) {
        const Eigen::Matrix3Xd x = sim.positions();
        Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, sim.particleCount());
        for (int i = 0; i < sim.particleCount(); ++i)
            if (!sim.body().fixed[static_cast<std::size_t>(i)]) v.col(i) = c.launch;
        sim.setState(x, v);
    }
    o.energyScale = convertibleEnergy(sim);
    // Bounded: at most duration / dt steps for fixed-step methods; rk45 is capped too.
    const long maxSteps = 2000000;
    while (sim.time() < c.duration - 1e-9 * sim.dt() && sim.stepCount() < maxSteps) {
        if (!sim.step(c.duration)) break;
        o.maxDrift = std::max(o.maxDrift, std::abs(sim.diagnostics().energyDrift()));
    }
    o.finite = sim.state().allFinite();
    o.failed = sim.failed();
    o.time = sim.time();
    o.drift = sim.diagnostics().energyDrift();
    if (o.failed) o.reason = sim.failure()->reason;
    const double gain = std::max(0.0, o.drift);
    const double measure = c.lossAllowed ? gain : o.maxDrift;
    const bool withinTolerance = measure <= c.driftTolerance * o.energyScale;
    const bool reasonOk = c.expectReason.empty() || o.reason.find(c.expectReason) != std::string::npos;
    const bool reached = sim.time() >= c.duration - 1e-9 * sim.dt();
    if (c.expectStable)
        o.asExpected = o.finite && !o.failed && reached && withinTolerance;
    else
        o.asExpected = o.finite && o.failed && !o.reason.empty() && reasonOk;
    if (c.expectWarning && !o.warned) o.asExpected = false;
    char line[600];
    if (o.failed)
        std::snprintf(line, sizeof line, "failed at t = %.4g s (%s)%s; expected %s", sim.failure()->time,
                      o.reason.c_str(), o.warned ? " [pre-run warning given]" : "",
                      c.expectStable ? "stable" : "a detected failure");
    else
        std::snprintf(line, sizeof line,
                      "stable to t = %.4g s, energy drift %.3g J (max |drift| %.3g J, tolerance %.3g J%s)%s; expected %s",
                      o.time, o.drift, o.maxDrift, c.driftTolerance * o.energyScale, c.lossAllowed ? " on gains" : "",
                      o.warned ? " [pre-run warning given]" : "", c.expectStable ? "stable" : "a detected failure");
    o.summary = line;
    return o;
}

}  // namespace simlab
