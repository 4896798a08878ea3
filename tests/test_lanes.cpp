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
};

QTEST_APPLESS_MAIN(TestLanes)
#include "test_lanes.moc"
