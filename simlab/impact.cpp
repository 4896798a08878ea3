#include "simlab/impact.h"

#include <algorithm>
#include <cmath>

#include "simcore/simulation.h"

namespace simlab {

using simcore::Param;
using simcore::ParameterSet;
using simcore::SceneKind;
using simcore::Simulation;

namespace {

// Steps until one second after the body first touched the floor and then until no particle
// is below it (weightless, no other wall near: the centre of mass then moves uniformly, so a
// body still ringing from the impact is measured by its momentum, not by a vibrating point);
// returns the centre-of-mass vertical velocity then, or NaN when the run failed or the body
// is still on the floor at maxTime.
double reboundVelocity(Simulation& sim, double maxTime, double* deepest, std::string& note) {
    const double floor = sim.boxCentre().y() - sim.boxHalfSize();
    const Eigen::VectorXd& mass = sim.body().mass;
    double touchedAt = -1.0;
    while (sim.time() < maxTime) {
        if (!sim.step()) {
            note = sim.failure()->reason;
            return std::nan("");
        }
        const double lowest = sim.positions().row(1).minCoeff();
        if (lowest <= floor) {
            if (touchedAt < 0.0) touchedAt = sim.time();
            if (deepest) *deepest = std::max(*deepest, floor - lowest);
        } else if (touchedAt >= 0.0 && sim.time() >= touchedAt + 1.0) {
            return (sim.velocities().row(1) * mass)(0) / mass.sum();
        }
    }
    note = "still on the floor at the end";
    return std::nan("");
}

}  // namespace

ImpactRow measureImpact(const ParameterSet& params, const std::string& integrator, double speed) {
    ImpactRow row;
    row.speed = speed;
    row.dt = std::min(params.get(Param::Dt), 3e-4 / speed);
    // A particle alone: the 1D scene with no spring, both particles free, weightless.
    {
        ParameterSet p(SceneKind::Spring1d);
        for (Param id : {Param::Contact, Param::Restitution, Param::ContactStiffness, Param::ContactSpeed,
                         Param::Friction, Param::FrictionSpeed})
            p.set(id, params.get(id));
        const double mass = params.kind() == SceneKind::Spring1d ? params.get(Param::Mass) : params.get(Param::MassOuter);
        for (auto [id, value] : {std::pair{Param::Ks, 0.0}, {Param::Kd, 0.0}, {Param::Gravity, 0.0},
                                 {Param::FixedEnd, 0.0}, {Param::Box, 1.0}, {Param::Mass, mass}, {Param::Dt, row.dt}})
            p.set(id, value);
        Simulation sim(p, integrator);
        Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, 2);
        v(1, 1) = -speed;
        Eigen::Matrix3Xd x = sim.positions();
        x(1, 1) = sim.boxCentre().y() - sim.boxHalfSize() + 1e-3;  // 1 mm above the floor
        sim.setState(x, v);
        // Only particle 1 moves towards the floor (particle 0 rests mid-box).
        const double floor = sim.boxCentre().y() - sim.boxHalfSize();
        bool touched = false;
        row.particle = -1.0;
        while (sim.time() < 10.0) {
            if (!sim.step()) break;
            touched = touched || sim.positions()(1, 1) <= floor;
            if (touched && sim.positions()(1, 1) > floor) {
                row.particle = sim.velocities()(1, 1) / speed;
                break;
            }
        }
    }
    // The body: weightless, lowest point 1 mm above the floor, all of it moving down.
    {
        ParameterSet p = params;
        p.set(Param::Gravity, 0.0);
        p.set(Param::Box, 100.0);  // no other wall within reach while the rebound is measured
        p.set(Param::Dt, row.dt);
        Simulation sim(p, integrator);
        Eigen::Matrix3Xd x = sim.positions();
        const double floor = sim.boxCentre().y() - sim.boxHalfSize();
        x.row(1).array() += floor + 1e-3 - x.row(1).minCoeff();
        Eigen::Matrix3Xd v = Eigen::Matrix3Xd::Zero(3, x.cols());
        v.row(1).setConstant(-speed);
        sim.setState(x, v);
        const double up = reboundVelocity(sim, 10.0, &row.depth, row.note);
        row.body = std::isfinite(up) ? up / speed : -1.0;
    }
    return row;
}

}  // namespace simlab
