// Thread stress: the GUI's controller driven through thousands of random cycles of run,
// pause, step, parameter edits (valid and invalid), scene changes, integrator changes, pointer
// drags, reset, blocking scene captures and shutdown. Passes when nothing deadlocks or crashes,
// every frame stays finite, a capture finds every command sent before it applied, the heap in
// use stays flat across the rounds, and after the storm the controller still answers exactly.
// Run it under the tsan preset for data races (docs/reliability.md).
#include <QtTest>

#include <random>

#include <malloc.h>

#include "test_support.h"
#include "ui/sim_worker.h"
#include "ui/simulation_controller.h"

using namespace elui;

namespace {

simcore::ParameterSet smallScene(std::mt19937& rng) {
    const simcore::SceneKind kinds[] = {simcore::SceneKind::Spring1d, simcore::SceneKind::Ring2d,
                                        simcore::SceneKind::Sphere3d, simcore::SceneKind::Sphere3dLatLong};
    simcore::ParameterSet p(kinds[rng() % 4]);
    if (p.kind() == simcore::SceneKind::Sphere3d) p.set(simcore::Param::Subdivisions, double(rng() % 3));
    if (p.kind() == simcore::SceneKind::Ring2d) p.set(simcore::Param::Particles, double(3 + rng() % 40));
    return p;
}

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;  // shadow memory and quarantines: the heap figures say nothing
#else
constexpr bool kSanitized = false;
#endif

// Bytes the heap holds for the program (every arena), after the posted deletions ran. Not the
// resident set: how many pages the allocator keeps cached, per thread arena, depends on how far
// each storm got, i.e. on the machine's load; bytes in use do not.
long heapInUseKiB() {
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    QCoreApplication::processEvents();
    return static_cast<long>(mallinfo2().uordblks / 1024);
}

bool frameIsFinite(const FramePtr& frame) {
    if (!frame) return true;
    for (const LaneFrame& lane : frame->lanes) {
        for (float x : lane.positions)
            if (!std::isfinite(x)) return false;
        if (!std::isfinite(lane.diagnostics.total())) return false;
    }
    return true;
}

}  // namespace

class TestControllerStress : public QObject {
    Q_OBJECT
private slots:
    void randomCycles() {
        std::mt19937 rng(20261123);
        const QStringList integrators = {"euler", "midpoint", "rk4", "symplectic-euler", "verlet", "rk45", "implicit-euler"};
        const QStringList keys = {"ks", "kd", "mass", "gravity", "restitution", "dt", "box", "pressure", "nonsense"};
        int cycles = 0, shutdowns = 0, framesSeen = 0, captures = 0, workersDeleted = 0;
        long heapAfterWarmUp = 0;
        for (int round = 0; round < 12; ++round) {
            if (round == 4) heapAfterWarmUp = heapInUseKiB();
            auto controller = std::make_unique<SimulationController>();
            QObject::connect(controller.get(), &SimulationController::frameArrived, [&](const FramePtr& f) {
                ++framesSeen;
                QVERIFY(frameIsFinite(f));
            });
            QObject::connect(controller->worker(), &QObject::destroyed, [&] { ++workersDeleted; });
            controller->setScene(smallScene(rng));
            for (int i = 0; i < 100; ++i, ++cycles) {
                switch (rng() % 12) {
                    case 0: controller->run(); break;
                    case 1: controller->pause(); break;
                    case 2: controller->step(); break;
                    case 3: controller->reset(); break;
                    case 4: controller->setScene(smallScene(rng)); break;
                    case 5: controller->setIntegrator(integrators[int(rng() % integrators.size())]); break;
                    case 6: {
                        // Valid, out of range, and NaN values: the table refuses the bad ones.
                        const double values[] = {0.5, 2.0, 100.0, -1.0, std::nan(""), 1e12, 0.003};
                        controller->setParameter(keys[int(rng() % keys.size())], values[rng() % 7]);
                        break;
                    }
                    case 7: controller->grabAlongRay(QVector3D(0, 0, 10), QVector3D(0, 0, -1), 5.0); break;
                    case 8: controller->moveAnchor(QVector3D(float(rng() % 5) - 2.f, float(rng() % 5) - 2.f, 0)); break;
                    case 9: controller->release(); break;
                    case 10: controller->setSpeed(Speed(rng() % 4)); break;
                    case 11: QTest::qWait(int(rng() % 3)); break;
                }
                if (i % 10 == 0) QCoreApplication::processEvents();
            }
            if (round % 2 == 0) {
                // A blocking capture (as Save does) while the worker may be running flat out:
                // it runs behind every command sent, so none is left in the inbox after it.
                const SceneCapture capture = controller->captureScene();
                QCOMPARE(controller->commandsInFlight(), std::size_t(0));
                QVERIFY(capture.lanes >= 1 && !capture.text.empty());
                ++captures;
                controller->run();
                controller->setScene(smallScene(rng));
            }
            QTest::qWait(5);
            controller.reset();  // shutdown with commands still in flight
            ++shutdowns;
        }
        QVERIFY(cycles >= 1000);
        QCOMPARE(shutdowns, 12);
        QCOMPARE(workersDeleted, 12);  // each worker (owner of the simulations) went with its thread
        QCOMPARE(captures, 6);
        QVERIFY(framesSeen > 0);
        // No leak per round: eight more controllers, threads and storms after the warm-up leave
        // the heap in use where it was (slack for caches Qt fills once).
        const long grownKiB = heapInUseKiB() - heapAfterWarmUp;
        qInfo("heap in use after round 4 -> after round 12: %+ld KiB", grownKiB);
        if (!kSanitized) QVERIFY2(grownKiB <= 1024, qPrintable(QString::number(grownKiB)));

        // After the storm a fresh controller answers exactly: one step from the start state.
        SimulationController controller;
        QSignalSpy frames(&controller, &SimulationController::frameArrived);
        simcore::ParameterSet p(simcore::SceneKind::Ring2d);
        controller.setScene(p, {"rk4"});
        controller.step();
        QTRY_VERIFY_WITH_TIMEOUT(controller.latest() && controller.latest()->lanes.at(0).diagnostics.step == 1, testsupport::kHangGuardMs);
        QCOMPARE(controller.latest()->lanes.at(0).diagnostics.time, 0.003);
    }
};

QTEST_MAIN(TestControllerStress)
#include "test_controller_stress.moc"
