// The simulation controller and its worker thread: commands, frames, the clock, shutdown.
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#include <atomic>
#include <cmath>

#include "test_support.h"
#include "simcore/world.h"
#include "ui/sim_worker.h"
#include "ui/simulation_controller.h"

using namespace elui;

namespace {

simcore::ParameterSet ring(double dt = 0.003) {
    simcore::ParameterSet p(simcore::SceneKind::Ring2d);
    p.set(simcore::Param::Dt, dt);
    return p;
}

// Processes events until the newest frame satisfies pred (false only on a hang).
template <class Pred>
bool waitFor(SimulationController& c, Pred pred) {
    return testsupport::waitUntil([&] { return c.latest() && pred(*c.latest()); });
}

// A wall clock the test moves by hand (seconds; read on the worker thread).
struct ManualClock {
    std::atomic<double> now{1000.0};
    WallClock reader() {
        return [this] { return now.load(); };
    }
};

// Every command sent so far has been applied, and the frame the last of them published has
// arrived here: a worker round trip, no waiting on the clock.
void settle(SimulationController& c) {
    const quint64 serial = (c.captureScene(), c.worker()->publishedSerial());
    testsupport::waitUntil([&] { return c.latest() && c.latest()->serial >= serial; });
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
        // Nothing runs while paused: commands keep the worker's event loop turning (a live
        // timer would tick in between), and every frame they publish shows the same step.
        for (int i = 0; i < 20; ++i) {
            c.setSpeed(i % 2 ? Speed::Quarter : Speed::RealTime);
            settle(c);
            QCOMPARE(c.latest()->lanes[0].diagnostics.step, steps);
        }
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
            return f.parameters.get(simcore::Param::Ks) == 1234.0 && f.lanes[0].diagnostics.dt == 0.001;
        }));
        QVERIFY(c.latest()->running);  // a live edit does not stop the run
        QCOMPARE(c.latest()->parameters.get(simcore::Param::Ks), 1234.0);
        // The same table validates: out of range and keys the scene lacks are refused.
        c.setParameter("ks", -1.0);
        c.setParameter("length", 2.0);  // a 1D key
        QVERIFY(testsupport::waitUntil([&] { return rejected.count() == 2; }));
        QVERIFY(rejected.at(0).at(1).toString().contains("out of range"));
        QCOMPARE(rejected.at(1).at(0).toString(), QString("length"));
        QCOMPARE(c.latest()->parameters.get(simcore::Param::Ks), 1234.0);
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
        // Real time: simulated seconds follow wall seconds, whatever the frame rate. The wall
        // is a clock this test moves, so the check holds on any machine, however busy.
        ManualClock wall;
        SimulationController c(wall.reader());
        c.setScene(ring(), {"rk4"});
        QVERIFY(waitFor(c, [](const Frame& f) { return f.scene != nullptr; }));
        c.run();
        settle(c);
        QCOMPARE(c.latest()->lanes[0].diagnostics.time, 0.0);  // no wall time has passed
        const double dt = 0.003;
        wall.now = wall.now + 1.2;
        // The next ticks catch up with the clock: 1.2 s, within one step, and no further.
        QVERIFY(waitFor(c, [dt](const Frame& f) { return f.lanes[0].diagnostics.time > 1.2 - dt; }));
        settle(c);
        QVERIFY2(c.latest()->lanes[0].diagnostics.time <= 1.2 + dt + 1e-9,
                 qPrintable(QString("ran ahead of the clock: %1 s").arg(c.latest()->lanes[0].diagnostics.time)));
        QVERIFY(!c.latest()->fallingBehind);
        QCOMPARE(c.latest()->wallSeconds, 1.2);
        // A quarter of real time: 2 wall seconds are half a simulated second.
        c.setSpeed(Speed::Quarter);
        QVERIFY(waitFor(c, [](const Frame& f) { return f.speed == Speed::Quarter; }));
        const double t1 = c.latest()->lanes[0].diagnostics.time;
        wall.now = wall.now + 2.0;
        QVERIFY(waitFor(c, [t1, dt](const Frame& f) { return f.lanes[0].diagnostics.time > t1 + 0.5 - dt; }));
        settle(c);
        QVERIFY(c.latest()->lanes[0].diagnostics.time <= t1 + 0.5 + dt + 1e-9);
        // Paused, the clock stops counting: the wall time run so far stays 3.2 s.
        c.pause();
        QVERIFY(waitFor(c, [](const Frame& f) { return !f.running; }));
        wall.now = wall.now + 100.0;
        settle(c);
        QCOMPARE(c.latest()->wallSeconds, 3.2);
    }

    void fallingBehindIsSaidAndForgiven() {
        // A machine too slow for real time: the clock runs on while a tick steps (here every
        // reading of the clock takes 50 ms). The worker says it is falling behind and restarts
        // the clock where it is instead of piling up a debt it would later rush through.
        std::atomic<double> now{0.0};
        std::atomic<bool> slow{false};
        SimulationController c([&] {
            if (slow) now = now + 0.05;
            return now.load();
        });
        c.setScene(ring(), {"rk4"});
        QVERIFY(waitFor(c, [](const Frame& f) { return f.scene != nullptr; }));
        slow = true;
        c.run();
        QVERIFY(waitFor(c, [](const Frame& f) { return f.running && f.fallingBehind; }));
        c.pause();
        QVERIFY(waitFor(c, [](const Frame& f) { return !f.running; }));
        // Simulated time lags the wall (that is what falling behind means) ...
        QVERIFY(c.latest()->lanes[0].diagnostics.time < c.latest()->wallSeconds);
        // ... and back on a fast machine the run keeps real time again.
        slow = false;
        c.run();
        settle(c);
        const double t0 = c.latest()->lanes[0].diagnostics.time;
        now = now + 0.3;
        QVERIFY(waitFor(c, [t0](const Frame& f) { return f.lanes[0].diagnostics.time > t0 + 0.3 - 0.003; }));
        settle(c);
        QVERIFY(c.latest()->lanes[0].diagnostics.time <= t0 + 0.3 + 0.003 + 1e-9);
        QVERIFY(!c.latest()->fallingBehind);
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
        // The GUI is busy (processes no events) while the worker publishes six more frames.
        QElapsedTimer guard;
        guard.start();
        while (c.worker()->publishedSerial() < before + 6 && guard.elapsed() < testsupport::kHangGuardMs)
            QThread::msleep(1);
        QVERIFY(testsupport::waitUntil([&] { return frames.count() >= 1; }));
        // The first frame delivered is the newest, not the next in a backlog.
        QVERIFY2(frames.at(0).at(0).value<FramePtr>()->serial >= before + 6,
                 "frames published meanwhile were skipped, not queued");
        c.pause();
    }

    void blowUpPausesAndKeepsTheLastGoodState() {
        SimulationController c;
        QSignalSpy failed(&c, &SimulationController::runFailed);
        c.setScene(ring(0.3), {"euler"});
        c.setSpeed(Speed::AsFastAsPossible);
        c.run();
        QVERIFY(testsupport::waitUntil([&] { return failed.count() == 1; }));
        QVERIFY(waitFor(c, [](const Frame& f) { return !f.running && f.lanes[0].failure.has_value(); }));
        QVERIFY(finite(c.latest()->lanes[0]));
        QVERIFY(!failed.at(0).at(0).toString().isEmpty());
        // The failure banner's check starts from a recorded state before the failure.
        const auto& start = c.latest()->lanes[0].stretchStart;
        QVERIFY(start);
        QVERIFY(!start->failure);
        QVERIFY(start->diag.time < c.latest()->lanes[0].failure->time);
        // Run refuses to continue a failed run; reset clears it.
        c.run();
        settle(c);
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
        QVERIFY(testsupport::waitUntil([&] { return grabbed.count() == 1; }));
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

    // A scene of several bodies on the worker thread (sim_worker_world.cpp), no window shown:
    // run, a body's parameter edited while it runs, the mouse on body 2, a step, a reset, and
    // the thread joined — the commands and frames ThreadSanitizer checks for a world (the
    // window's own test, test_gui_world, shows docks whose replots TSan cannot follow in Qt).
    void aWorldOnTheWorkerThread() {
        SimulationController c;
        simcore::WorldSpec spec = *simcore::worldScene("collide2d");
        QVERIFY(!simcore::assignWorld(spec, "gravity=0"));
        c.setWorld(spec);
        QVERIFY(waitFor(c, [](const Frame& f) { return f.world != nullptr; }));
        c.run();
        c.setWorldBody(1);
        c.setParameter(simcore::Param::Mass, 4.0);  // body 2 only, while it runs
        QVERIFY(waitFor(c, [](const Frame& f) {
            return f.world && f.worldSpec->bodies[1].params.get(simcore::Param::Mass) == 4.0 && f.world->time > 0.05;
        }));
        c.pause();
        settle(c);
        QCOMPARE(c.latest()->worldSpec->bodies[0].params.get(simcore::Param::Mass), 1.0);
        // The mouse on body 2's first particle, pulled up for a few steps.
        const Frame& f = *c.latest();
        int outer = f.scene->bodies[1].first;
        while (f.scene->topology.layer[std::size_t(outer)] != simcore::Layer::Outer) ++outer;
        const QVector3D at(f.lanes[0].positions[3 * std::size_t(outer)], f.lanes[0].positions[3 * std::size_t(outer) + 1], 0.0f);
        c.grabAlongRay(at + QVector3D(0, 0, 10), QVector3D(0, 0, -1), 0.05);
        c.moveAnchor(at + QVector3D(0, 0.5f, 0));
        for (int i = 0; i < 5; ++i) c.step();
        settle(c);
        QVERIFY(c.latest()->lanes[0].pointer.active);
        c.release();
        c.reset();
        settle(c);
        QCOMPARE(c.latest()->world->step, 0L);
        QCOMPARE(c.latest()->world->bodies.size(), std::size_t{2});
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
        delete c;  // while running flat out (a hang here is caught by CTest's time-out)
        QCOMPARE(destroyed, 1);  // the worker (and its simulation) went with the thread
        QVERIFY(joinedFirst);
    }
};

QTEST_GUILESS_MAIN(TestGuiController)
#include "test_gui_controller.moc"
