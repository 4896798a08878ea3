// The simulation controller and its worker thread: commands, frames, the clock, shutdown.
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <cmath>

#include "sim_worker.h"
#include "simulation_controller.h"

using namespace elui;

namespace {

simcore::ParameterSet ring(double dt = 0.003) {
    simcore::ParameterSet p(simcore::SceneKind::Ring2d);
    p.set("dt", dt);
    return p;
}

// Processes events until the newest frame satisfies pred (or the timeout passes).
template <class Pred>
bool waitFor(SimulationController& c, Pred pred, int timeoutMs = 8000) {
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < timeoutMs) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        if (c.latest() && pred(*c.latest())) return true;
        QThread::msleep(2);
    }
    return false;
}

bool finite(const LaneFrame& lane) {
    for (float v : lane.positions)
        if (!std::isfinite(v)) return false;
    return true;
}

}  // namespace

class TestGuiController : public QObject {
    Q_OBJECT
private slots:
    void firstFrameIsPausedAtRest() {
        SimulationController c;
        QSignalSpy frames(&c, &SimulationController::frameArrived);
        QSignalSpy scenes(&c, &SimulationController::sceneChanged);
        c.setScene(ring(), {"rk4"});
        QVERIFY(waitFor(c, [](const Frame& f) { return f.scene != nullptr; }));
        const Frame& f = *c.latest();
        QVERIFY(!f.running);
        QCOMPARE(f.lanes.size(), std::size_t(1));
        QCOMPARE(f.lanes[0].integrator, QString("rk4"));
        QCOMPARE(f.lanes[0].diagnostics.step, 0L);
        QCOMPARE(f.scene->topology.particleCount(), 24);
        QCOMPARE(f.lanes[0].positions.size(), std::size_t(3 * 24));
        QVERIFY(frames.count() >= 1);
        QCOMPARE(scenes.count(), 1);
        QCOMPARE(c.history().size(), std::size_t(1));  // the start row
    }

    void runAdvancesAndPauseStops() {
        SimulationController c;
        c.setScene(ring(), {"rk4"});
        c.run();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.running && f.lanes[0].diagnostics.time > 0.1; }));
        c.pause();
        QVERIFY(waitFor(c, [](const Frame& f) { return !f.running; }));
        const long steps = c.latest()->lanes[0].diagnostics.step;
        QTest::qWait(250);
        QCOMPARE(c.latest()->lanes[0].diagnostics.step, steps);  // nothing runs while paused
        // Every recorded step is in the history (dt 3 ms >= the 1 ms row interval).
        QCOMPARE(long(c.history().size()), steps + 1);
        QCOMPARE(c.history().back().step, steps);
    }

    void singleStepIsOneStep() {
        SimulationController c;
        c.setScene(ring(0.002), {"euler"});
        QVERIFY(waitFor(c, [](const Frame& f) { return f.scene != nullptr; }));
        for (int i = 1; i <= 3; ++i) {
            c.step();
            QVERIFY(waitFor(c, [i](const Frame& f) { return f.lanes[0].diagnostics.step == i; }));
            QVERIFY(!c.latest()->running);
            QCOMPARE(c.latest()->lanes[0].diagnostics.time, 0.002 * i);
        }
    }

    void resetReturnsToTheStart() {
        SimulationController c;
        c.setScene(ring(), {"rk4"});
        QVERIFY(waitFor(c, [](const Frame& f) { return f.scene != nullptr; }));
        const std::vector<float> start = c.latest()->lanes[0].positions;
        c.run();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.lanes[0].diagnostics.time > 0.2; }));
        QVERIFY(c.latest()->lanes[0].positions != start);  // it fell
        QSignalSpy reset(&c, &SimulationController::historyReset);
        c.pause();
        c.reset();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.lanes[0].diagnostics.step == 0 && !f.running; }));
        QCOMPARE(c.latest()->lanes[0].positions, start);
        QVERIFY(reset.count() >= 1);
        QCOMPARE(c.history().size(), std::size_t(1));
    }

    void parameterEditsApplyBetweenSteps() {
        SimulationController c;
        QSignalSpy rejected(&c, &SimulationController::parameterRejected);
        c.setScene(ring(), {"rk4"});
        c.run();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.lanes[0].diagnostics.time > 0.05; }));
        c.setParameter("ks", 1234.0);
        c.setParameter("dt", 0.001);
        QVERIFY(waitFor(c, [](const Frame& f) {
            return f.parameters.get("ks") == 1234.0 && f.lanes[0].diagnostics.dt == 0.001;
        }));
        QVERIFY(c.latest()->running);  // a live edit does not stop the run
        QCOMPARE(c.latest()->parameters.get("ks"), 1234.0);
        // The same table validates: out of range and keys the scene lacks are refused.
        c.setParameter("ks", -1.0);
        c.setParameter("length", 2.0);  // a 1D key
        QTRY_COMPARE_WITH_TIMEOUT(rejected.count(), 2, 5000);
        QVERIFY(rejected.at(0).at(1).toString().contains("out of range"));
        QCOMPARE(rejected.at(1).at(0).toString(), QString("length"));
        QCOMPARE(c.latest()->parameters.get("ks"), 1234.0);
        c.pause();
    }

    void shapeKeyRebuildsTheBody() {
        SimulationController c;
        QSignalSpy scenes(&c, &SimulationController::sceneChanged);
        c.setScene(ring(), {"rk4"});
        QVERIFY(waitFor(c, [](const Frame& f) { return f.scene != nullptr; }));
        c.setParameter("particles", 20);
        QVERIFY(waitFor(c, [](const Frame& f) { return f.scene->topology.particleCount() == 40; }));
        QCOMPARE(scenes.count(), 2);
        QCOMPARE(c.latest()->lanes[0].positions.size(), std::size_t(120));
    }

    void clockIsHonest() {
        // Real time: simulated seconds follow wall seconds, whatever the frame rate.
        SimulationController c;
        c.setScene(ring(), {"rk4"});
        QVERIFY(waitFor(c, [](const Frame& f) { return f.scene != nullptr; }));
        QElapsedTimer wall;
        c.run();
        wall.start();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.lanes[0].diagnostics.time > 0.01; }));
        const double t0 = c.latest()->lanes[0].diagnostics.time;
        const double w0 = double(wall.elapsed()) * 1e-3;
        QTest::qWait(1200);
        const double simulated = c.latest()->lanes[0].diagnostics.time - t0;
        const double elapsed = double(wall.elapsed()) * 1e-3 - w0;
        QVERIFY2(simulated > 0.6 * elapsed && simulated < 1.15 * elapsed,
                 qPrintable(QString("simulated %1 s in %2 s wall").arg(simulated).arg(elapsed)));
        // A quarter of real time.
        c.setSpeed(Speed::Quarter);
        QVERIFY(waitFor(c, [](const Frame& f) { return f.speed == Speed::Quarter; }));
        const double t1 = c.latest()->lanes[0].diagnostics.time;
        wall.restart();
        QTest::qWait(1200);
        const double quarter = c.latest()->lanes[0].diagnostics.time - t1;
        const double elapsed2 = double(wall.elapsed()) * 1e-3;
        QVERIFY2(quarter > 0.15 * elapsed2 && quarter < 0.3 * elapsed2,
                 qPrintable(QString("quarter speed: %1 s in %2 s wall").arg(quarter).arg(elapsed2)));
        c.pause();
    }

    void newestFrameWinsWhenTheGuiLags() {
        SimulationController c;
        c.setScene(ring(), {"rk4"});
        c.setSpeed(Speed::AsFastAsPossible);
        c.run();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.running; }));
        QSignalSpy frames(&c, &SimulationController::frameArrived);
        const quint64 before = c.latest()->serial;
        QThread::msleep(400);  // the GUI is busy: the worker keeps publishing into the slot
        QCoreApplication::processEvents();
        QCOMPARE(frames.count(), 1);  // one frame delivered, not a backlog
        QVERIFY2(c.latest()->serial > before + 5, "frames published meanwhile were skipped, not queued");
        c.pause();
    }

    void blowUpPausesAndKeepsTheLastGoodState() {
        SimulationController c;
        QSignalSpy failed(&c, &SimulationController::runFailed);
        c.setScene(ring(0.3), {"euler"});
        c.setSpeed(Speed::AsFastAsPossible);
        c.run();
        QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, 10000);
        QVERIFY(waitFor(c, [](const Frame& f) { return !f.running && f.lanes[0].failure.has_value(); }));
        QVERIFY(finite(c.latest()->lanes[0]));
        QVERIFY(!failed.at(0).at(0).toString().isEmpty());
        QVERIFY(c.latest()->explicitDtLimit > 0.0 && c.latest()->explicitDtLimit < 0.3);
        // Run refuses to continue a failed run; reset clears it.
        c.run();
        QTest::qWait(100);
        QVERIFY(!c.latest()->running);
        c.reset();
        QVERIFY(waitFor(c, [](const Frame& f) { return !f.lanes[0].failure.has_value(); }));
    }

    void sideBySideSharesStartAndMouse() {
        SimulationController c;
        c.setScene(ring(0.01), {"euler", "midpoint", "rk4"});
        QVERIFY(waitFor(c, [](const Frame& f) { return f.lanes.size() == 3; }));
        const Frame& f0 = *c.latest();
        QCOMPARE(f0.lanes[1].positions, f0.lanes[0].positions);
        QCOMPARE(f0.lanes[2].positions, f0.lanes[0].positions);
        QCOMPARE(f0.lanes[2].integrator, QString("rk4"));
        // Grab from above the ring's top (particle on the outer layer): every lane holds it.
        QSignalSpy grabbed(&c, &SimulationController::grabbed);
        c.grabAlongRay(QVector3D(0, 2, 50), QVector3D(0, 0, -1), 0.3);
        QTRY_COMPARE_WITH_TIMEOUT(grabbed.count(), 1, 5000);
        const int particle = grabbed.at(0).at(0).toInt();
        QVERIFY(particle >= 12);  // outer layer
        QVERIFY(waitFor(c, [particle](const Frame& f) {
            for (const auto& lane : f.lanes)
                if (!lane.pointer.active || lane.pointer.particle != particle) return false;
            return true;
        }));
        c.moveAnchor(QVector3D(1, 3, 0));
        c.setSpeed(Speed::AsFastAsPossible);
        c.run();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.lanes[0].diagnostics.time > 0.5; }));
        c.pause();
        QVERIFY(waitFor(c, [](const Frame& f) { return !f.running; }));
        const Frame& f = *c.latest();
        // The same simulated time in every lane, and they have drifted apart.
        QCOMPARE(f.lanes[1].diagnostics.time, f.lanes[0].diagnostics.time);
        QVERIFY(f.lanes[1].divergence > 0.0);
        QVERIFY(f.lanes[2].divergence > 0.0);
        QCOMPARE(f.lanes[0].divergence, 0.0);
        QCOMPARE(f.lanes[2].pointer.anchor.y(), 3.0);
    }

    void errorEstimateIsReported() {
        SimulationController c;
        c.setScene(ring(), {"rk4"});
        QVERIFY(waitFor(c, [](const Frame& f) { return f.scene != nullptr; }));
        c.step();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.lanes[0].diagnostics.step == 1; }));
        QVERIFY(c.latest()->lanes[0].diagnostics.errorEstimate < 0);  // off by default
        c.setStepDoubling(true);
        c.step();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.lanes[0].diagnostics.step == 2; }));
        QVERIFY(c.latest()->lanes[0].diagnostics.errorEstimate >= 0);
        // rk45 always estimates; switching integrator keeps the run going from where it is.
        c.setStepDoubling(false);
        c.setIntegrator("rk45");
        c.step();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.lanes[0].integrator == "rk45" && f.lanes[0].diagnostics.step == 3; }));
        QVERIFY(c.latest()->lanes[0].diagnostics.errorEstimate >= 0);
    }

    void shutdownJoinsTheThread() {
        auto* c = new SimulationController;
        c->setScene(ring(), {"rk4"});
        c->setSpeed(Speed::AsFastAsPossible);
        c->run();
        QVERIFY(waitFor(*c, [](const Frame& f) { return f.running; }));
        QThread* thread = c->workerThread();
        QVERIFY(thread->isRunning());
        // Observed from this thread only: the worker is destroyed here, and at that moment its
        // thread must have finished. (A slot on QThread::finished would run on the worker
        // thread, and its slot object be freed here, ordered only by QThread::wait(), which
        // ThreadSanitizer cannot see in an uninstrumented Qt: it reported that, now and then.)
        int destroyed = 0;
        bool joinedFirst = false;
        connect(c->worker(), &QObject::destroyed, this, [&] {
            ++destroyed;
            joinedFirst = thread->isFinished();
        }, Qt::DirectConnection);
        QElapsedTimer t;
        t.start();
        delete c;  // while running flat out
        QVERIFY(t.elapsed() < 2000);
        QCOMPARE(destroyed, 1);  // the worker (and its simulation) went with the thread
        QVERIFY(joinedFirst);
    }
};

QTEST_GUILESS_MAIN(TestGuiController)
#include "test_gui_controller.moc"
