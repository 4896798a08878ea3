#include "ui/lesson_measures.h"

#include <map>
#include <memory>
#include <mutex>

#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/conservation.h"
#include "simlab/impact.h"
#include "simlab/stability.h"
#include "simlab/study.h"
#include "ui/body_measures.h"
#include "ui/lessons.h"

namespace elui {

using simcore::ParameterSet;
using simcore::Simulation;

namespace {

ParameterSet with(ParameterSet p, std::initializer_list<std::pair<const char*, double>> values) {
    for (const auto& [key, value] : values) p.set(key, value);
    return p;
}

// Runs `steps` steps (or until the run fails).
std::unique_ptr<Simulation> runSteps(const ParameterSet& p, const std::string& integrator, long steps) {
    auto sim = std::make_unique<Simulation>(p, integrator);
    while (sim->diagnostics().step < steps)
        if (!sim->step()) break;
    return sim;
}

// `elastic-lab-cli stability`'s row for one integrator (perturb 0.01 m unless the set has one).
simlab::StabilityRow scan(const ParameterSet& p, const std::string& integrator) {
    simlab::StabilitySpec spec;
    spec.params = p;
    spec.integrators = {integrator};
    // The one verdict's linearisation, as the CLI's (the trials start perturbed).
    return simlab::scanIntegrator(spec, integrator, simlab::stabilityModes(p));
}

// The row of a run with the smallest inner area: 0 its area, 1 its pressure, 2 its time.
double squash(const ParameterSet& p, int what) {
    Simulation sim(p, "rk4");
    simcore::Diagnostics least = sim.diagnostics();
    while (sim.diagnostics().step < 1000 && sim.step())
        if (sim.diagnostics().volume[0] < least.volume[0]) least = sim.diagnostics();
    return what == 0 ? least.volume[0] : what == 1 ? least.pressure[0] : least.time;
}

}  // namespace

double lessonFailureTime(const ParameterSet& p, const std::string& integrator, double until) {
    Simulation sim(p, integrator);
    while (sim.time() < until)
        if (!sim.step()) return sim.failure()->time;
    return -1.0;
}

double lessonLiftOffTime(const ParameterSet& p, const std::string& integrator, double until) {
    Simulation sim(p, integrator);
    bool landed = false;
    while (sim.time() < until && sim.step()) {
        if (sim.diagnostics().contact > 0.0) landed = true;
        else if (landed) return sim.time();
    }
    return -1.0;
}

// Kept whole: a table, lesson after lesson, each answer beside the elastic-lab-cli command that
// measures it, read top to bottom.
QMap<QString, LessonMeasure> lessonMeasures(const QString& id) {
    QMap<QString, LessonMeasure> m;
    if (id == QLatin1String("euler-limit")) {
        // `stability --scene ring2d --integrators euler`; `run ... --dt 0.009 --set perturb=0.01`.
        m["dt-stable"] = [](const ParameterSet& p) { return scan(p, "euler").stable; };
        m["dt-predicted"] = [](const ParameterSet& p) { return scan(p, "euler").predicted; };
        m["blowup-time"] = [](const ParameterSet& p) { return lessonFailureTime(with(p, {{"dt", 0.009}}), "euler", 2.0); };
    } else if (id == QLatin1String("energy-drift")) {
        // `run --scene ring2d --integrator I --dt 0.003 --duration 3` (1000 steps).
        for (const char* integrator : {"euler", "midpoint", "rk4"})
            m[QStringLiteral("drift-") + integrator] = [integrator](const ParameterSet& p) {
                return runSteps(p, integrator, 1000)->diagnostics().energyDrift();
            };
        m["rk4-ratio"] = [](const ParameterSet& p) {
            const double dt = p.get(simcore::Param::Dt);
            return runSteps(p, "rk4", 1000)->diagnostics().energyDrift() /
                   runSteps(with(p, {{"dt", dt / 2}}), "rk4", 2000)->diagnostics().energyDrift();
        };
    } else if (id == QLatin1String("heavy-inner")) {
        // `run --scene sphere3d --set subdivisions=2 --set mass_inner=5 --duration 3 --state`.
        m["sag"] = [](const ParameterSet& p) { return layerSag(*runSteps(p, "rk4", 1000)); };
        m["collapse-time"] = [](const ParameterSet& p) {
            return lessonFailureTime(with(p, {{"mass_inner", 10.0}}), "rk4", 3.0);
        };
    } else if (id == QLatin1String("refine-sphere")) {
        // `stability --scene sphere3d --set subdivisions=L --integrators rk4`, and the pre-run
        // advice the banner shows at level 3 with the lesson's DT.
        for (int level : {1, 2, 3})
            m[QStringLiteral("dt-level%1").arg(level)] = [level](const ParameterSet& p) {
                return scan(with(p, {{"subdivisions", double(level)}}), "rk4").stable;
            };
        m["suggested-level3"] = [](const ParameterSet& p) {
            const Simulation sim(with(p, {{"subdivisions", 3}}), "rk4");
            const auto advice = simlab::stabilityAdvice(sim);
            return advice ? advice->suggestedDt : -1.0;
        };
    } else if (id == QLatin1String("pv-isotherm")) {
        // `run --scene ring2d --duration 3 --csv`: the row with the smallest inner area.
        m["min-area"] = [](const ParameterSet& p) { return squash(p, 0); };
        m["max-pressure"] = [](const ParameterSet& p) { return squash(p, 1); };
        m["squash-time"] = [](const ParameterSet& p) { return squash(p, 2); };
    } else if (id == QLatin1String("restitution")) {
        // `run ... --csv` (energy_contact 0: in the air); `restitution --speeds 1,3`.
        for (const double e : {0.9, 0.2})
            m[QStringLiteral("liftoff-e%1").arg(e)] = [e](const ParameterSet& p) {
                return lessonLiftOffTime(with(p, {{"restitution", e}}), "rk4", 3.0);
            };
        m["particle-e0.9"] = [](const ParameterSet& p) {
            return simlab::measureImpact(with(p, {{"restitution", 0.9}}), "rk4", 3.0).particle;
        };
        m["body-e0.9"] = [](const ParameterSet& p) {
            return simlab::measureImpact(with(p, {{"restitution", 0.9}}), "rk4", 3.0).body;
        };
        m["body-e0.2"] = [](const ParameterSet& p) {
            return simlab::measureImpact(with(p, {{"restitution", 0.2}}), "rk4", 3.0).body;
        };
        m["particle-1mps"] = [](const ParameterSet& p) {
            return simlab::measureImpact(with(p, {{"restitution", 0.9}}), "rk4", 1.0).particle;
        };
    } else if (id == QLatin1String("stiff-springs")) {
        // `stability --scene ring2d --set ks=1e6 --integrators rk4`; `run ... implicit-euler
        // --dt 0.01 --duration 3` (300 steps).
        m["rk4-limit"] = [](const ParameterSet& p) { return scan(p, "rk4").stable; };
        m["implicit-drift"] = [](const ParameterSet& p) {
            return runSteps(p, "implicit-euler", 300)->diagnostics().energyDrift();
        };
    } else if (id == QLatin1String("why-symplectic")) {
        // `conservation --scene spring1d --dt 0.01 --periods 10000 (and 100) --integrators
        // verlet,yoshida4,rk4`: rows 0, 1, 2 are verlet, yoshida4, rk4.
        auto run = [](const ParameterSet& p, double periods) {
            simlab::ConservationSpec spec;
            spec.params = p;
            spec.integrators = {"verlet", "yoshida4", "rk4"};
            spec.periods = periods;
            spec.dt = p.get(simcore::Param::Dt);
            return simlab::runConservation(spec);
        };
        m["verlet-error"] = [run](const ParameterSet& p) { return run(p, 10000.0).rows[0].finalError; };
        m["yoshida4-error"] = [run](const ParameterSet& p) { return run(p, 10000.0).rows[1].finalError; };
        m["rk4-error"] = [run](const ParameterSet& p) { return run(p, 10000.0).rows[2].finalError; };
        m["verlet-growth"] = [run](const ParameterSet& p) {
            return run(p, 10000.0).rows[0].finalError / run(p, 100.0).rows[0].finalError;
        };
        m["rk4-growth"] = [run](const ParameterSet& p) {
            return run(p, 10000.0).rows[2].finalError / run(p, 100.0).rows[2].finalError;
        };
        m["rk4-alpha"] = [run](const ParameterSet& p) { return run(p, 10000.0).rows[2].alpha; };
    } else {
        return worldLessonMeasures(id);
    }
    return m;
}

namespace {

// A lesson of several bodies: its world as set up, with the values of `p` (the first body's, as
// the Parameters dock shows them) given to the first body (a world parameter to every body),
// run `steps` steps with rk4. The last run is kept: a lesson's answers read one run.
simcore::WorldDiagnostics lessonWorld(const QString& id, const ParameterSet& p, long steps) {
    static std::mutex lock;
    static std::map<std::pair<std::string, long>, std::pair<ParameterSet, simcore::WorldDiagnostics>> done;
    const std::lock_guard guard(lock);
    const auto key = std::make_pair(id.toStdString(), steps);
    if (auto it = done.find(key); it != done.end() && it->second.first == p) return it->second.second;
    simcore::WorldSpec spec = *findLesson(id)->preset.world();
    for (const simcore::ParamSpec* s : simcore::parametersFor(p.kind())) {
        if (!p.isExplicit(s->id)) continue;
        for (std::size_t k = 0; k < spec.bodies.size(); ++k)
            if (k == 0 || simcore::isWorldParameter(s->id)) (void)spec.bodies[k].params.set(s->id, p.get(s->id));
    }
    simcore::World world(spec, "rk4");
    while (world.stepCount() < steps && world.step()) {
    }
    done[key] = {p, world.diagnostics()};
    return world.diagnostics();
}

}  // namespace

QMap<QString, LessonMeasure> worldLessonMeasures(const QString& id) {
    QMap<QString, LessonMeasure> m;
    if (id == QLatin1String("balloons-collide")) {
        // `run --scene collide2d --set gravity=0 --set body2.mass=4 --duration 2.4` (800 steps):
        // the centres' velocities after the impact, the pair's restitution, what they keep.
        const auto run = [id](const ParameterSet& p) { return lessonWorld(id, p, 800); };
        m["v1-after"] = [run](const ParameterSet& p) { return run(p).bodies[0].velocity.x(); };
        m["v2-after"] = [run](const ParameterSet& p) { return run(p).bodies[1].velocity.x(); };
        m["momentum"] = [run](const ParameterSet& p) { return run(p).momentum.x(); };
        m["restitution"] = [run](const ParameterSet& p) {
            const simcore::WorldDiagnostics d = run(p);
            return (d.bodies[1].velocity.x() - d.bodies[0].velocity.x()) / (2.0 - (-2.0));  // started at +-2 m/s
        };
        m["ke-kept"] = [run](const ParameterSet& p) {
            double before = 0.0, after = 0.0;
            for (const simcore::BodyDiagnostics& b : run(p).bodies) {
                before += 0.5 * b.mass * 4.0;
                after += 0.5 * b.mass * b.velocity.squaredNorm();
            }
            return after / before;
        };
    } else if (id == QLatin1String("soft-stack")) {
        // `run --scene stack3d --set subdivisions=1 --set pressure=300 --set kd=40 --set rkd=120
        // --duration 5` (1667 steps): each body's outer volume over its rest volume, the bottom
        // outer pressure over the top one's.
        const auto flattened = [id](const ParameterSet& p, std::size_t body) {
            const simcore::BodyDiagnostics b = lessonWorld(id, p, 1667).bodies[body];
            return b.volume[1] / b.restVolume[1];
        };
        m["bottom-volume"] = [flattened](const ParameterSet& p) { return flattened(p, 0); };
        m["middle-volume"] = [flattened](const ParameterSet& p) { return flattened(p, 1); };
        m["top-volume"] = [flattened](const ParameterSet& p) { return flattened(p, 2); };
        m["pressure-ratio"] = [id](const ParameterSet& p) {
            const simcore::WorldDiagnostics d = lessonWorld(id, p, 1667);
            return d.bodies[0].pressure[1] / d.bodies[2].pressure[1];
        };
    }
    return m;
}

QMap<QString, LessonMeasure> helpMeasures() {
    QMap<QString, LessonMeasure> m;
    // `elastic-lab-cli stability --scene ring2d --integrators euler,midpoint,rk4` (2 s, 0.01 m).
    for (const char* integrator : {"euler", "midpoint", "rk4"})
        m[QStringLiteral("limit-") + integrator] = [integrator](const ParameterSet& p) {
            return scan(p, integrator).stable;
        };
    // `elastic-lab-cli study --scene spring1d --integrators verlet --dts 0.005,0.0025,0.00125,
    // 0.000625 --duration 2`: damped velocity Verlet's fitted order (the closed form is the
    // reference).
    m["order-verlet-damped"] = [](const ParameterSet&) {
        simlab::StudySpec spec;
        spec.params = ParameterSet(simcore::SceneKind::Spring1d);
        spec.integrators = {"verlet"};
        spec.dts = {0.005, 0.0025, 0.00125, 0.000625};
        spec.duration = 2.0;
        const simlab::StudyResult result = simlab::runStudy(spec);
        const auto fits = simlab::fitOrders(result.rows, result.reference.estimatedError);
        return fits.empty() ? 0.0 : fits.front().order;
    };
    return m;
}

}  // namespace elui
