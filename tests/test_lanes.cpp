// The worker's simulations side by side (ui/lanes.h): built from one parameter set, stepped
// to one common time, given the same kick, edits and mouse input, and shown lane by lane.
#include <QTest>

#include <cmath>

#include "ui/lanes.h"

using namespace elui;

namespace {

constexpr double kDt = 0.002;

simcore::ParameterSet ring() {
    simcore::ParameterSet p(simcore::SceneKind::Ring2d);
    p.set(simcore::Param::Dt, kDt);
    return p;
}

// Lanes built for these integrators (the test fails on a refusal).
Lanes lanesOf(const QStringList& integrators) {
    Lanes lanes;
    std::optional<std::string> error;
    lanes.adopt(lanes.build(ring(), integrators, error));
    if (error) qFatal("%s", error->c_str());
    lanes.syncCommonTime();
    return lanes;
}

}  // namespace

class TestLanes : public QObject {
    Q_OBJECT
private slots:
    void buildsOneLanePerIntegrator() {
        Lanes lanes = lanesOf({"rk4", "rk45", "symplectic-euler"});
        QCOMPARE(lanes.size(), std::size_t(3));
        QCOMPARE(integratorName(lanes.front()), QString("rk4"));
        QCOMPARE(lanes.views().size(), std::size_t(3));
        QCOMPARE(lanes.views()[1]->parameters().get(simcore::Param::Dt), kDt);
    }

    void anImpossibleSceneIsRefusedAndChangesNothing() {
        Lanes lanes = lanesOf({"rk4"});
        std::optional<std::string> error;
        QVERIFY(lanes.build(ring(), {"rk4", "no-such-method"}, error).empty());
        QVERIFY(error && !error->empty());
        QCOMPARE(lanes.size(), std::size_t(1));
        // No integrator: no lane, and nothing to refuse.
        error.reset();
        QVERIFY(lanes.build(ring(), {}, error).empty());
        QVERIFY(!error);
    }

    void sideBySideEveryLaneReachesTheCommonTime() {
        Lanes lanes = lanesOf({"rk4", "rk45"});
        for (int i = 0; i < 5; ++i) lanes.stepAll(-1.0);
        QVERIFY(std::abs(lanes.commonTime() - 5 * kDt) < 1e-12);
        for (const simcore::Simulation* lane : lanes.views())
            QVERIFY(std::abs(lane->time() - lanes.commonTime()) < 1e-12);
        // A run-until target off the DT grid: the fixed-step lane (rk4) takes whole steps, so
        // the common clock stops on the first tick past the target and the adaptive lane
        // (rk45) lands there too: both at the same time, and still together afterwards (the
        // distance between them is measured at one time, not across a part of a step).
        const double tick = lanes.commonTime() + kDt;
        const double until = lanes.commonTime() + kDt / 4;
        lanes.stepAll(until);
        QVERIFY(std::abs(lanes.commonTime() - tick) < 1e-12);
        QVERIFY(lanes.commonTime() >= until);
        for (const simcore::Simulation* lane : lanes.views())
            QVERIFY2(std::abs(lane->time() - lanes.commonTime()) < 1e-12,
                     qPrintable(QString("lane at %1, common time %2").arg(lane->time()).arg(lanes.commonTime())));
        lanes.stepAll(-1.0);
        for (const simcore::Simulation* lane : lanes.views())
            QVERIFY(std::abs(lane->time() - (tick + kDt)) < 1e-12);
        QVERIFY(!lanes.allFailed());
        QVERIFY(!lanes.stopped());
        QVERIFY(lanes.restorable());
    }

    void adaptiveLanesStopOnTheTarget() {
        // Every lane adaptive: each can land on the target, so the common time stops on it.
        Lanes lanes = lanesOf({"rk45", "cvode-adams"});
        lanes.stepAll(-1.0);
        const double until = lanes.commonTime() + kDt / 4;
        lanes.stepAll(until);
        QCOMPARE(lanes.commonTime(), until);
        for (const simcore::Simulation* lane : lanes.views()) QVERIFY(std::abs(lane->time() - until) < 1e-12);
    }

    void oneLaneStepsOnItsOwn() {
        Lanes lanes = lanesOf({"rk4"});
        lanes.stepAll(-1.0);
        lanes.stepAll(-1.0);
        QCOMPARE(lanes.front().stepCount(), 2L);
        QCOMPARE(lanes.commonTime(), lanes.front().time());
    }

    void theKickGoesToEveryLaneByLayer() {
        Lanes lanes = lanesOf({"rk4", "rk45"});
        lanes.setKick(0.5, -0.25);
        lanes.applyKick();
        for (const simcore::Simulation* lane : lanes.views()) {
            const auto v = lane->velocities();
            const auto& layer = lane->topology().layer;
            for (Eigen::Index i = 0; i < v.cols(); ++i) {
                const double expected = layer[std::size_t(i)] == simcore::Layer::Inner ? 0.5 : -0.25;
                QCOMPARE(v(0, i), expected);
                QCOMPARE(v(1, i), 0.0);
            }
        }
        // No kick: the velocities stay as they are.
        lanes.setKick(0.0, 0.0);
        lanes.stepAll(-1.0);
        const Eigen::Matrix3Xd before = lanes.front().velocities();
        lanes.applyKick();
        QVERIFY(lanes.front().velocities() == before);
    }

    void editsAndInputGoToEveryLane() {
        Lanes lanes = lanesOf({"rk4", "rk45"});
        lanes.setParameter(simcore::Param::Gravity, 2.5);
        lanes.setStepDoubling(true);
        QVERIFY(lanes.stepDoubling());
        const Eigen::Vector3d anchor(0.25, 0.5, 0.0);
        lanes.grab(3, anchor);
        for (const simcore::Simulation* lane : lanes.views()) {
            QCOMPARE(lane->parameters().get(simcore::Param::Gravity), 2.5);
            QVERIFY(lane->integratorOptions().stepDoubling);
            QVERIFY(lane->pointer().active);
            QCOMPARE(lane->pointer().particle, 3);
        }
        lanes.moveAnchor(Eigen::Vector3d(1.0, 0.0, 0.0));
        for (const simcore::Simulation* lane : lanes.views()) QCOMPARE(lane->pointer().anchor.x(), 1.0);
        lanes.release();
        for (const simcore::Simulation* lane : lanes.views()) QVERIFY(!lane->pointer().active);
    }

    void laneZeroRefusingChangesNoLane() {
        Lanes lanes = lanesOf({"rk4", "rk45"});
        const double particles = lanes.front().parameters().get(simcore::Param::Particles);
        QVERIFY(lanes.trySetParameter(simcore::Param::Particles, -7.0).has_value());
        for (const simcore::Simulation* lane : lanes.views())
            QCOMPARE(lane->parameters().get(simcore::Param::Particles), particles);
        // Accepted: every lane is rebuilt with it.
        QVERIFY(!lanes.trySetParameter(simcore::Param::Particles, particles + 2));
        for (const simcore::Simulation* lane : lanes.views())
            QCOMPARE(lane->parameters().get(simcore::Param::Particles), particles + 2);
    }

    void framesShowEveryLane() {
        Lanes lanes = lanesOf({"rk4", "rk45"});
        lanes.setKick(0.5, -0.25);
        lanes.applyKick();
        for (int i = 0; i < 20; ++i) lanes.stepAll(-1.0);
        const int n = lanes.front().particleCount();
        std::vector<LaneFrame> frames = lanes.laneFrames(false, -1);
        QCOMPARE(frames.size(), std::size_t(2));
        QCOMPARE(frames[1].integrator, QString("rk45"));
        QCOMPARE(frames[0].positions.size(), std::size_t(3 * n));
        QCOMPARE(frames[0].positions[3], float(lanes.front().positions()(0, 1)));
        QCOMPARE(frames[0].divergence, 0.0);
        QVERIFY(frames[1].divergence > 0.0);  // two methods part (slightly)
        QVERIFY(frames[0].forces.empty());
        QVERIFY(!frames[0].breakdown);
        QCOMPARE(frames[1].diagnostics.time, lanes.commonTime());
        // Force vectors and the selected particle's breakdown only when asked for.
        frames = lanes.laneFrames(true, 2);
        QCOMPARE(frames[1].forces.size(), std::size_t(3 * n));
        QVERIFY(frames[1].breakdown.has_value());
        QVERIFY(!lanes.laneFrames(false, n).front().breakdown);  // out of range: none
    }

    // Precision float (issue 27): lane 0 steps on the float path, the lane holds the float
    // state after every step with its ledger going on, the shadow double run gives the
    // distance, and any change restarts the float run from the lane.
    void floatPrecisionStepsTheFloatPath() {
        simcore::ParameterSet p = ring();
        p.set(simcore::Param::Gravity, 0.0);  // free flight: the float path has no walls
        Lanes lanes;
        std::optional<std::string> error;
        lanes.adopt(lanes.build(p, {"rk4"}, error));
        QVERIFY(!error);
        lanes.setKick(0.5, -0.25);  // the ring moves (and reaches no wall in these steps)
        lanes.applyKick();
        for (int i = 0; i < 100; ++i) lanes.stepAll(-1.0);  // double first: the float run starts mid-run
        // What the lane must hold: the float path from the same state, and double.
        simcore::Simulation twin(lanes.front().parameters(), "rk4");
        twin.restore(lanes.front().snapshot());
        simcore::FloatSimulation single(twin);
        const simcore::Diagnostics before = lanes.front().diagnostics();
        QVERIFY(before.removedDamping > 1e-6);  // a ledger with something in it
        lanes.setFloatWanted(true);
        QVERIFY(!lanes.floatActive());
        for (int i = 0; i < 40; ++i) {
            lanes.stepAll(-1.0);
            single.step();
            twin.step();
        }
        QVERIFY(lanes.floatActive());
        QCOMPARE(lanes.front().stepCount(), single.stepCount());
        QCOMPARE(lanes.front().time(), single.time());
        QCOMPARE(lanes.commonTime(), single.time());
        const Eigen::VectorXd y = single.state();
        const Eigen::Index n3 = 3 * lanes.front().particleCount();
        QVERIFY(lanes.front().positions().reshaped() == y.head(n3));                  // the float run's bits
        QVERIFY(lanes.front().velocities().reshaped() == y.segment(n3, n3));
        QVERIFY(lanes.front().positions() != twin.positions());                       // not double's
        // The shadow is the double run from the same state: the distance is theirs.
        const double distance = std::sqrt((lanes.front().positions() - twin.positions()).colwise().squaredNorm().mean());
        QCOMPARE(lanes.floatDistance(), distance);
        QVERIFY2(distance > 0.0 && distance < 1e-5, qPrintable(QString::number(distance)));
        // The ledger goes on: the lane's drift is its drift before plus the float run's own.
        const double drift = lanes.front().diagnostics().energyDrift();
        const double expected = before.energyDrift() + single.diagnostics().energyDrift();
        QVERIFY2(std::abs(drift - expected) < 1e-9 * (1.0 + std::abs(single.diagnostics().total())),
                 qPrintable(QString("%1 vs %2").arg(drift).arg(expected)));
        QVERIFY(lanes.front().diagnostics().forceEvaluations > before.forceEvaluations);
        // The frames show the lane's (float) positions.
        QCOMPARE(lanes.laneFrames(false, -1).front().positions[0], float(y[0]));

        // An edit restarts the float run from the lane (and its shadow with it).
        lanes.setParameter(simcore::Param::Gravity, 5.0);
        QVERIFY(!lanes.floatActive());
        QCOMPARE(lanes.floatDistance(), -1.0);
        lanes.stepAll(-1.0);
        QVERIFY(lanes.floatActive());
        QVERIFY(lanes.floatDistance() < distance);  // one step from a common state
        // A held particle steps in double (the float path has no pointer).
        lanes.grab(0, lanes.front().positions().col(0));
        lanes.stepAll(-1.0);
        QVERIFY(!lanes.floatActive());
        lanes.release();
        lanes.stepAll(-1.0);
        QVERIFY(lanes.floatActive());
        // Double again.
        lanes.setFloatWanted(false);
        lanes.stepAll(-1.0);
        QVERIFY(!lanes.floatActive());
        QCOMPARE(lanes.floatRoundoff(), 0.0);
    }

    void floatPrecisionOnABigBodyShowsTheRoundOffEstimate() {
        // Above Lanes::kShadowParticles no shadow runs: the estimate eps X sqrt(n) instead.
        simcore::ParameterSet p(simcore::SceneKind::Sphere3d);
        p.set(simcore::Param::Subdivisions, 5);  // 20,484 particles
        p.set(simcore::Param::Scaling, 1.0);     // the thesis's per-particle body (stable at 3 ms)
        p.set(simcore::Param::Gravity, 0.0);
        p.set(simcore::Param::Dt, 0.003);
        Lanes lanes;
        std::optional<std::string> error;
        lanes.adopt(lanes.build(p, {"rk4"}, error));
        QVERIFY(!error);
        lanes.setFloatWanted(true);
        for (int i = 0; i < 4; ++i) lanes.stepAll(-1.0);
        QVERIFY(lanes.floatActive());
        QCOMPARE(lanes.floatDistance(), -1.0);
        const double x = lanes.front().positions().cwiseAbs().maxCoeff();
        QCOMPARE(lanes.floatRoundoff(), std::ldexp(1.0, -24) * x * 2.0);  // sqrt(4 steps) = 2
        // Side by side the lanes step in double.
        Lanes pair = lanesOf({"rk4", "euler"});
        pair.setFloatWanted(true);
        pair.stepAll(-1.0);
        QVERIFY(!pair.floatActive());
    }
};

QTEST_APPLESS_MAIN(TestLanes)
#include "test_lanes.moc"
