// What a one-body scene has in the window, for a scene of several bodies (issue 26): the
// timeline (scrub back to any moment, bit for bit, through a live edit and the mouse; resume
// from it as a branch), forces on a click (the contact from the other body its own arrow),
// step doubling and the energy plot's error band, and the CSV export of the run so far.
#include <cmath>

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "simcore/world.h"
#include "simlab/output.h"
#include "gui_world_support.h"
#include "test_support.h"
#include "ui/bodies_dock.h"
#include "ui/main_window.h"
#include "ui/simulation_controller.h"
#include "ui/world_export.h"

using namespace elui;
using testsupport::waitUntil;

using worldtest::scene;
using worldtest::waitForFrame;

namespace {

// Steps once and waits for the frame of that step (paused).
const Frame& stepTo(SimulationController& c, long step) {
    c.step();
    if (!waitForFrame(c, [step](const Frame& f) { return f.world && f.world->step == step && !f.running; }))
        qFatal("no frame of step %ld", step);
    return *c.latest();
}

}  // namespace

class TestGuiWorldTools : public QObject {
    Q_OBJECT
private slots:
    // Scrubbing a world shows the moment as it was, bit for bit: re-simulated from a checkpoint
    // through a live edit of body 2 (the world built again) and the mouse; a step from a
    // scrubbed moment is a branch (the future after it is forgotten).
    void timelineOfAWorld() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        window.startWorld(scene("collide2d", {"gravity=0"}));
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world != nullptr; }));
        QCOMPARE(c->latest()->timeline.last, 0L);
        for (long k = 1; k < 50; ++k) c->step();
        stepTo(*c, 50);
        // At moment 50 (between checkpoints 48 and 64): body 2 four times as heavy, and the
        // mouse on body 2's first particle, its anchor moved two steps later.
        c->setWorldBody(1);
        c->setParameter(simcore::Param::Mass, 4.0);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.worldSpec->bodies[1].params.get(simcore::Param::Mass) == 4.0; }));
        const auto frame50 = c->latest();
        const Frame& f50 = *frame50;
        int grabbed = f50.scene->bodies[1].first;  // body 2's first outer particle (the mouse takes those)
        while (f50.scene->topology.layer[std::size_t(grabbed)] != simcore::Layer::Outer) ++grabbed;
        const QVector3D p(f50.lanes[0].positions[3 * std::size_t(grabbed)], f50.lanes[0].positions[3 * std::size_t(grabbed) + 1], 0.0f);
        QSignalSpy grabs(c, &SimulationController::grabbed);
        c->grabAlongRay(p + QVector3D(0, 0, 10), QVector3D(0, 0, -1), 0.05);
        QVERIFY(waitUntil([&] { return grabs.count() == 1; }));
        stepTo(*c, 51);
        stepTo(*c, 52);
        c->moveAnchor(p + QVector3D(0.5f, 1.0f, 0.0f));
        std::vector<std::vector<float>> seen(71);
        std::vector<double> energy(71);
        for (long k = 53; k <= 70; ++k) {
            const Frame& f = stepTo(*c, k);
            seen[std::size_t(k)] = f.lanes[0].positions;
            energy[std::size_t(k)] = f.world->total();
        }
        c->release();
        // On through the impact (about 1 s).
        c->runUntil(1.3);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return !f.running && f.world->time >= 1.3 - 1e-9; }));
        const long last = c->latest()->timeline.last;
        QVERIFY(last > 400);
        QCOMPARE(c->latest()->timeline.moment, last);
        QVERIFY(c->latest()->world->minGap < 0.2);  // they met

        BodiesDock* bodies = window.bodiesDock();
        QVERIFY(waitUntil([&] { return bodies->plottedPoints() > 10; }));
        const int points = bodies->plottedPoints();
        // The edit's energy is the edit's: the drift did not jump by the 144 J body 2's kinetic
        // energy gained with its mass (0.5 (96 - 24) kg (2 m/s)^2).
        QVERIFY2(std::abs(c->latest()->world->energyDrift()) < 10.0, qPrintable(QString::number(c->latest()->world->energyDrift())));
        // Back to the start: body 2 as it was, before the edit; the Bodies dock keeps its curves.
        c->scrubToStart();
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.timeline.moment == 0; }));
        QCOMPARE(c->latest()->world->step, 0L);
        QCOMPARE(c->latest()->worldSpec->bodies[1].params.get(simcore::Param::Mass), 1.0);
        QVERIFY(!c->latest()->lanes[0].pointer.active);
        // Moment 55 from checkpoint 48: the edit and the grab at 50 and the move at 52 replayed.
        for (long k : {55L, 68L, 53L, 69L}) {
            c->scrubTo(k);
            QVERIFY(waitForFrame(*c, [k](const Frame& f) { return f.timeline.moment == k; }));
            const Frame& f = *c->latest();
            QCOMPARE(f.world->step, k);
            QVERIFY2(f.lanes[0].positions == seen[std::size_t(k)], qPrintable(QString("moment %1").arg(k)));
            QCOMPARE(f.world->total(), energy[std::size_t(k)]);
            QCOMPARE(f.worldSpec->bodies[1].params.get(simcore::Param::Mass), 4.0);
            QVERIFY(f.lanes[0].pointer.active);
            QCOMPARE(f.lanes[0].pointer.particle, grabbed);
            QCOMPARE(f.timeline.last, last);
        }
        // By time, as --travel-back does: the first moment at or after it.
        c->scrubToTime(1.0);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world->time >= 1.0 - 1e-9 && f.world->time < 1.0 + 0.0031; }));
        // A step from moment 60 is a branch: the future after it is forgotten.
        c->scrubTo(60);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.timeline.moment == 60; }));
        QCOMPARE(bodies->plottedPoints(), points);
        stepTo(*c, 61);
        QCOMPARE(c->latest()->timeline.last, 61L);
        QCOMPARE(c->latest()->timeline.moment, 61L);
        // The Bodies dock's curves end at the branch.
        QVERIFY(waitUntil([&] { return bodies->plottedPoints() < points; }));
        QVERIFY(bodies->lastValue("gap", 0) > 0.0);
    }

    // A click on a particle of a world: its body's own parts, the contact from the other body
    // as its own part, self-contact as its own; the parts sum to the total, which is the force
    // the world's ODE applies (the force vectors); the other body is pushed the other way.
    void forcesOnAClick() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        window.startWorld(scene("collide2d", {"gravity=1"}));
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world != nullptr; }));
        // Into the impact: the rings touch (pairs within the skin).
        c->runUntil(1.05);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return !f.running && f.world->time >= 1.05 - 1e-9; }));
        QVERIFY(c->latest()->world->contactPairsActive > 0);
        c->setForcesWanted(true);
        // Body 1's outer particle farthest along +x (facing body 2), and body 2's facing it.
        const auto frame = c->latest();  // held: newer frames replace the controller's
        const Frame& f = *frame;
        auto facing = [&](int body, double sign) {
            const SceneData::BodySlice& s = f.scene->bodies[std::size_t(body)];
            int best = -1;
            for (int i = s.first; i < s.first + s.count; ++i)
                if (f.scene->topology.layer[std::size_t(i)] == simcore::Layer::Outer &&
                    (best < 0 || sign * f.lanes[0].positions[3 * std::size_t(i)] > sign * f.lanes[0].positions[3 * std::size_t(best)]))
                    best = i;
            return best;
        };
        for (const auto& [body, sign] : {std::pair{0, 1.0}, std::pair{1, -1.0}}) {
            const int p = facing(body, sign);
            c->selectParticle(p);
            QVERIFY(waitForFrame(*c, [p](const Frame& g) {
                return g.lanes[0].breakdown && g.lanes[0].breakdown->particle == p && !g.lanes[0].forces.empty();
            }));
            const simcore::ForceBreakdown& b = *c->latest()->lanes[0].breakdown;
            using P = simcore::ForcePart;
            QVERIFY(b.has(P::BodyContact) && b.has(P::SelfContact) && b.has(P::Gravity) && b.has(P::Structural));
            // The other body pushes it back along x, harder than anything else along x.
            QVERIFY2(-sign * b[P::BodyContact].x() > 0.0, qPrintable(QString::number(b[P::BodyContact].x())));
            QCOMPARE(b[P::Gravity].y(), -f.worldSpec->bodies[std::size_t(body)].params.get(simcore::Param::Mass) *
                                            f.worldSpec->bodies[std::size_t(body)].params.get(simcore::Param::Gravity));
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            for (int k = 0; k < simcore::kForcePartCount; ++k)
                if (b.present[std::size_t(k)]) sum += b.part[std::size_t(k)];
            QVERIFY2((sum - b.total).norm() <= 1e-9 * b.total.norm() + 1e-12, qPrintable(QString::number((sum - b.total).norm())));
            // The total is the ODE's force on it (float in the frame).
            const std::vector<float>& forces = c->latest()->lanes[0].forces;
            for (int a = 0; a < 3; ++a)
                QVERIFY(std::abs(double(forces[3 * std::size_t(p) + std::size_t(a)]) - b.total[a]) <= 1e-5 * b.total.norm() + 1e-9);
        }
        c->selectParticle(-1);
        QVERIFY(waitForFrame(*c, [](const Frame& g) { return !g.lanes[0].breakdown; }));
    }

    // Step doubling on a world: every step gets its error estimate and the energy plot's rows
    // their band; switched on at a moment of the timeline, so a branch from before it has none.
    void stepDoublingAndBands() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        window.startWorld(scene("collide3d", {"gravity=0", "subdivisions=1"}));
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world != nullptr; }));
        for (long k = 1; k <= 10; ++k) stepTo(*c, k);
        QVERIFY(c->latest()->world->errorEstimate < 0.0);  // rk4 alone has none
        c->setErrorBandsWanted(true);
        c->setStepDoubling(true);
        for (long k = 11; k <= 20; ++k) stepTo(*c, k);
        QVERIFY(c->latest()->world->errorEstimate > 0.0);
        QVERIFY(waitUntil([&] { return !c->history().empty() && c->history().back().step == 20; }));
        const simcore::Diagnostics& row = c->history().back();
        QVERIFY(row.errors.valid);
        QVERIFY(row.errors.energy > 0.0 && row.errors.energy < 1e-3 * std::abs(row.total()));
        QVERIFY(!c->history()[5].errors.valid);
        // Back before step doubling was on, and on from there: none again.
        c->scrubTo(5);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.timeline.moment == 5; }));
        stepTo(*c, 6);
        QVERIFY(c->latest()->world->errorEstimate < 0.0);
        // On again from here: the estimate is back.
        c->setStepDoubling(true);
        for (long k = 7; k <= 8; ++k) stepTo(*c, k);
        QVERIFY(c->latest()->world->errorEstimate > 0.0);
    }

    // File > Export Data for a world: the columns and numbers of elastic-lab-cli run --csv for
    // it (simlab::worldColumns on a World run alone to the same steps), the abandoned future
    // of a branch left out.
    void csvOfTheRunSoFar() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        const simcore::WorldSpec spec = scene("collide2d", {"gravity=0", "body2.mass=2"});
        window.startWorld(spec);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world != nullptr; }));
        c->runUntil(0.3);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return !f.running && f.world->time >= 0.3 - 1e-9; }));
        const long steps = c->latest()->world->step;
        QTemporaryDir dir;
        const QString path = dir.filePath("world.csv");
        int rows = 0;
        QCOMPARE(writeWorldCsv(path, *c, &rows), QString());
        QCOMPARE(long(rows), steps + 1);  // dt = 3 ms: every step is a row, and the start
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray written = file.readAll();
        // The CLI's table of the same world.
        simcore::World world(spec, "rk4");
        const auto columns = simlab::worldColumns(world);
        std::string expected = simlab::csvHeader(columns) + simlab::csvRow(columns, world.diagnostics());
        for (long k = 0; k < steps; ++k) {
            QVERIFY(world.step());
            expected += simlab::csvRow(columns, world.diagnostics());
        }
        QCOMPARE(written, QByteArray::fromStdString(expected));
        QVERIFY(written.startsWith("step,t,dt,energy_kinetic"));
        QVERIFY(written.contains(",volume_outer_2,") && written.contains(",min_gap\n"));
        // A branch at step 50: the rows after it are the abandoned future, not in the export.
        c->scrubTo(50);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.timeline.moment == 50; }));
        stepTo(*c, 51);
        QCOMPARE(writeWorldCsv(path, *c, &rows), QString());
        QCOMPARE(rows, 52);
        // One body: nothing of a world to export.
        window.startScene(simcore::ParameterSet(simcore::SceneKind::Ring2d), {"rk4"});
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world == nullptr; }));
        QVERIFY(!writeWorldCsv(path, *c).isEmpty());
    }
};

QTEST_MAIN(TestGuiWorldTools)
#include "test_gui_world_tools.moc"
