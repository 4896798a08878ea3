// Time travel (issue 16): the recorder's checkpoints and re-simulation, the memory budget,
// and, through the GUI's controller, scrubbing and branching.
#include <QAction>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QtTest>
#include <cstring>
#include <map>
#include <vector>

#include "sim_test_support.h"
#include "simcore/simulation.h"
#include "simcore/timeline.h"
#include "test_support.h"
#include "ui/main_window.h"
#include "ui/plot_dock.h"
#include "ui/sim_worker.h"
#include "ui/simulation_controller.h"
#include "ui/timeline_dock.h"

using namespace simcore;
using elui::FramePtr;
using elui::SimulationController;

namespace {

using testsupport::params;

bool sameBits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), sizeof(double) * std::size_t(a.size())) == 0;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// The diagnostics a replay must reproduce exactly.
bool sameDiagnostics(const Diagnostics& a, const Diagnostics& b) {
    return a.step == b.step && sameBits(a.time, b.time) && sameBits(a.dt, b.dt) &&
           sameBits(a.kinetic, b.kinetic) && sameBits(a.total(), b.total()) &&
           sameBits(a.energyDrift(), b.energyDrift()) &&
           sameBits(a.removedDamping, b.removedDamping) && sameBits(a.workPointer, b.workPointer) &&
           a.forceEvaluations == b.forceEvaluations;
}

// A ring with gravity, gas, damping, walls in reach and the pointer holding a particle: every
// part of the state a step reads is in play.
ParameterSet ringParams() {
    return params(SceneKind::Ring2d, {{"dt", 0.002}, {"perturb", 0.05}, {"box", 2.2}});
}

struct Recorded {
    std::vector<Eigen::VectorXd> states;  // moment i: state after i steps
    std::vector<Diagnostics> diagnostics;
};

// Runs `steps` steps, recording every moment in `recorder` and in the returned copy.
Recorded runRecorded(Simulation& sim, TimelineRecorder& recorder, int steps) {
    Recorded r;
    recorder.clear();
    recorder.record(0, {&sim});
    r.states.push_back(sim.state());
    r.diagnostics.push_back(sim.diagnostics());
    for (int i = 1; i <= steps; ++i) {
        sim.step();
        recorder.record(i, {&sim});
        r.states.push_back(sim.state());
        r.diagnostics.push_back(sim.diagnostics());
    }
    return r;
}

// Moment `index` re-simulated in sim from the recorder's checkpoint before it.
bool replayTo(Simulation& sim, const TimelineRecorder& recorder, long index) {
    const TimelineCheckpoint* c = recorder.checkpointFor(index);
    if (!c || c->lanes.size() != 1) return false;
    sim.restore(c->lanes.front());
    for (long i = c->index; i < index; ++i) sim.step();
    return true;
}

// --- through the GUI's controller ---

bool sameFrame(const elui::Frame& a, const elui::Frame& b) {
    if (a.lanes.size() != b.lanes.size()) return false;
    for (std::size_t i = 0; i < a.lanes.size(); ++i) {
        const elui::LaneFrame &x = a.lanes[i], &y = b.lanes[i];
        if (x.integrator != y.integrator || x.positions != y.positions ||
            !sameDiagnostics(x.diagnostics, y.diagnostics))
            return false;
    }
    return a.parameters == b.parameters;
}

// Every command sent so far has been applied and the frame it published has arrived.
void settle(SimulationController& c) {
    const quint64 serial = (c.captureScene(), c.worker()->publishedSerial());
    QVERIFY(testsupport::waitUntil([&] { return c.latest() && c.latest()->serial >= serial; }));
}

// Steps to moment `moment` one step at a time, keeping every frame by its moment.
void stepTo(SimulationController& c, long moment, std::map<long, FramePtr>& frames) {
    while (c.latest()->timeline.moment < moment) {
        c.step();
        settle(c);
        frames[c.latest()->timeline.moment] = c.latest();
    }
}

FramePtr scrubbed(SimulationController& c, long moment) {
    c.scrubTo(moment);
    settle(c);
    return c.latest();
}

}  // namespace

class TestTimeline : public QObject {
    Q_OBJECT
private slots:
    void scrubbedStateEqualsOriginal_data() {
        QTest::addColumn<QString>("integrator");
        for (const char* name :
             {"rk4", "rk45", "symplectic-euler", "verlet", "implicit-euler", "xpbd"})
            QTest::newRow(name) << QString::fromLatin1(name);
    }
    void scrubbedStateEqualsOriginal() {
        // Every moment between checkpoints, across checkpoint boundaries, re-simulated in the
        // simulation that ran on (its integrator's state is then that of the end of the run)
        // and in a fresh one: the state and the diagnostics equal the original bit for bit.
        QFETCH(QString, integrator);
        ParameterSet p = ringParams();
        // xpbd: an odd substep count, so its sweep direction at a step's start alternates
        // (its history matters).
        if (integrator == QLatin1String("xpbd")) p.set(simcore::Param::Substeps, 3.0);
        Simulation sim(p, integrator.toStdString());
        sim.grab(3, sim.positions().col(3) + Eigen::Vector3d(0.3, 0.2, 0.0));
        TimelineRecorder recorder(TimelineRecorder::kDefaultBudget, 16);
        const Recorded original = runRecorded(sim, recorder, 120);
        QVERIFY(!sim.failed());
        QCOMPARE(recorder.checkpointCount(), std::size_t(120 / 16 + 1));
        QCOMPARE(recorder.last(), 120L);
        Simulation fresh(p, integrator.toStdString());
        for (long index : {0L, 1L, 15L, 16L, 17L, 31L, 32L, 77L, 119L, 120L, 5L}) {
            for (Simulation* target : {&sim, &fresh}) {
                QVERIFY(replayTo(*target, recorder, index));
                QVERIFY2(sameBits(target->state(), original.states[std::size_t(index)]),
                         qPrintable(QStringLiteral("state differs at moment %1").arg(index)));
                QVERIFY2(sameDiagnostics(target->diagnostics(),
                                         original.diagnostics[std::size_t(index)]),
                         qPrintable(QStringLiteral("diagnostics differ at moment %1").arg(index)));
            }
        }
        // Running on from a scrubbed moment without a change is the original future.
        QVERIFY(replayTo(sim, recorder, 40));
        for (int i = 41; i <= 120; ++i) sim.step();
        QVERIFY(sameBits(sim.state(), original.states.back()));
    }

    void restoreTakesBackLiveEdits() {
        // The snapshot carries the parameters and the integrator: an edit made after it (a
        // heavier body, another method) is undone by restoring it.
        const ParameterSet p = ringParams();
        Simulation sim(p, "rk4");
        TimelineRecorder recorder(TimelineRecorder::kDefaultBudget, 8);
        const Recorded original = runRecorded(sim, recorder, 40);
        QVERIFY(!sim.setParameter("mass_outer", 3.0 * p.get(simcore::Param::MassOuter)));
        QVERIFY(!sim.setParameter("dt", 0.001));
        QVERIFY(!sim.setIntegrator("rk45"));
        for (int i = 0; i < 30; ++i) sim.step();
        QVERIFY(replayTo(sim, recorder, 37));
        QCOMPARE(QString::fromLatin1(sim.integrator().name().data()), QStringLiteral("rk4"));
        QCOMPARE(sim.parameters().get(simcore::Param::Dt), 0.002);
        QVERIFY(sameBits(sim.state(), original.states[37]));
        sim.step();
        sim.step();
        sim.step();
        QVERIFY(sameBits(sim.state(), original.states[40]));
        QVERIFY(sameDiagnostics(sim.diagnostics(), original.diagnostics[40]));
    }

    void branchDivergesOnlyAfterItsInstant() {
        // Branch at moment 50 with another DT: up to and at 50 the run is the original, the
        // first step after it is not.
        Simulation sim(ringParams(), "rk4");
        TimelineRecorder recorder(TimelineRecorder::kDefaultBudget, 16);
        const Recorded original = runRecorded(sim, recorder, 100);
        QVERIFY(replayTo(sim, recorder, 50));
        QVERIFY(sameBits(sim.state(), original.states[50]));
        recorder.truncateAfter(50);
        QCOMPARE(recorder.last(), 50L);
        QVERIFY(recorder.checkpoints().back().index <= 50);
        QVERIFY(!sim.setParameter("dt", 0.0005));
        sim.step();
        recorder.record(51, {&sim});
        QVERIFY(!sameBits(sim.state(), original.states[51]));
        // The moments before the branch are still the original ones.
        Simulation fresh(ringParams(), "rk4");
        for (long index : {10L, 49L, 50L}) {
            QVERIFY(replayTo(fresh, recorder, index));
            QVERIFY(sameBits(fresh.state(), original.states[std::size_t(index)]));
        }
    }

    void memoryStaysWithinTheBudget() {
        // A long run in a small budget: the checkpoints never hold more than the budget, the
        // start is kept, the interval doubles, and a moment far back is still exact.
        const ParameterSet p = ringParams();
        Simulation sim(p, "rk4");
        const std::size_t perCheckpoint = sim.snapshot().bytes();
        const std::size_t budget = 40 * perCheckpoint;
        TimelineRecorder recorder(budget, 4);
        recorder.record(0, {&sim});
        std::vector<Eigen::VectorXd> kept;
        kept.push_back(sim.state());
        for (long i = 1; i <= 3000; ++i) {
            QVERIFY(sim.step());
            recorder.record(i, {&sim});
            QVERIFY2(recorder.bytes() <= budget,
                     qPrintable(QStringLiteral("over budget at moment %1").arg(i)));
            if (i == 1234 || i == 2999) kept.push_back(sim.state());
        }
        QVERIFY(recorder.thinnings() >= 3);
        QVERIFY(recorder.interval() >= 32);
        QCOMPARE(recorder.checkpoints().front().index, 0L);
        QVERIFY(recorder.checkpointCount() >= 10);
        // Every moment stays reachable, from an evenly thinned set of checkpoints.
        for (std::size_t k = 1; k < recorder.checkpointCount(); ++k)
            QCOMPARE(recorder.checkpoints()[k].index % recorder.interval(), 0L);
        Simulation fresh(p, "rk4");
        QVERIFY(replayTo(fresh, recorder, 0));
        QVERIFY(sameBits(fresh.state(), kept[0]));
        QVERIFY(replayTo(fresh, recorder, 1234));
        QVERIFY(sameBits(fresh.state(), kept[1]));
        QVERIFY(replayTo(fresh, recorder, 2999));
        QVERIFY(sameBits(fresh.state(), kept[2]));
    }

    void cvodeIsRecordedAtEveryMoment() {
        // CVODE's history cannot be restored: every moment is a checkpoint of its own, and a
        // restored moment is the recorded state exactly.
        const ParameterSet p = params(SceneKind::Ring2d, {{"dt", 0.005}, {"perturb", 0.05}});
        Simulation sim(p, "cvode-bdf");
        QVERIFY(!sim.integrator().restorable());
        TimelineRecorder recorder(TimelineRecorder::kDefaultBudget, 16);
        const Recorded original = runRecorded(sim, recorder, 30);
        QCOMPARE(recorder.checkpointCount(), std::size_t(31));
        QVERIFY(!recorder.checkpoints().back().exact);
        for (long index : {3L, 17L, 30L}) {
            const TimelineCheckpoint* c = recorder.checkpointFor(index);
            QVERIFY(c);
            QCOMPARE(c->index, index);
            sim.restore(c->lanes.front());
            QVERIFY(sameBits(sim.state(), original.states[std::size_t(index)]));
            QVERIFY(sameDiagnostics(sim.diagnostics(), original.diagnostics[std::size_t(index)]));
        }
        // And it runs on from there (restarted).
        QVERIFY(sim.step());
        QVERIFY(sim.diagnostics().step == original.diagnostics[30].step + 1);
    }

    void controllerScrubbedFrameEqualsRecordedFrame_data() {
        QTest::addColumn<QStringList>("integrators");
        QTest::newRow("rk45") << QStringList{"rk45"};
        QTest::newRow("side by side") << QStringList{"rk4", "rk45", "verlet"};
    }
    void controllerScrubbedFrameEqualsRecordedFrame() {
        // Run (with a parameter edit and an integrator change in the past), then scrub back
        // and forth: every frame shown is the frame the run published at that moment.
        QFETCH(QStringList, integrators);
        SimulationController c;
        c.setTimelineBudget(std::size_t(256) << 20);
        c.setScene(ringParams(), integrators);
        settle(c);
        std::map<long, FramePtr> frames{{0L, c.latest()}};
        stepTo(c, 20, frames);
        c.setParameter(QStringLiteral("gravity"), 4.0);
        settle(c);
        frames[20] = c.latest();  // moment 20 with its edit
        stepTo(c, 27, frames);
        if (integrators.size() == 1) {
            c.setIntegrator(QStringLiteral("rk4"));
            settle(c);
            frames[27] = c.latest();
        }
        stepTo(c, 45, frames);
        QCOMPARE(c.latest()->timeline.last, 45L);
        QVERIFY(c.latest()->timeline.interval > 0 && c.latest()->timeline.checkpoints >= 2);
        for (long m :
             {44L, 0L, 1L, 15L, 16L, 17L, 19L, 20L, 21L, 26L, 27L, 28L, 33L, 32L, 45L, 3L}) {
            const FramePtr f = scrubbed(c, m);
            QCOMPARE(f->timeline.moment, m);
            QVERIFY(!f->running);
            QVERIFY2(sameFrame(*f, *frames.at(m)),
                     qPrintable(QStringLiteral("moment %1 differs").arg(m)));
        }
        // One step back at a time, and to the ends.
        scrubbed(c, 30);
        c.scrubBy(-1);
        settle(c);
        QVERIFY(sameFrame(*c.latest(), *frames.at(29)));
        c.scrubToEnd();
        settle(c);
        QCOMPARE(c.latest()->timeline.moment, 45L);
        QVERIFY(sameFrame(*c.latest(), *frames.at(45)));
        c.scrubToStart();
        settle(c);
        QVERIFY(sameFrame(*c.latest(), *frames.at(0)));
        // By simulated time: the first moment at or after it.
        c.scrubToTime(frames.at(33)->lanes[0].diagnostics.time);
        settle(c);
        QCOMPARE(c.latest()->timeline.moment, 33L);
        QVERIFY(sameFrame(*c.latest(), *frames.at(33)));
        c.scrubToTime(0.5 * (frames.at(9)->lanes[0].diagnostics.time +
                             frames.at(10)->lanes[0].diagnostics.time));
        settle(c);
        QCOMPARE(c.latest()->timeline.moment, 10L);
        // Scrubbing alone branches nothing: the plots' history is untouched.
        QVERIFY(c.abandoned().empty());
        QCOMPARE(c.latest()->timeline.last, 45L);
    }

    void controllerBranchDivergesOnlyAfterItsInstant() {
        // Branch at moment 30 with another DT: the moments up to 30 stay the original ones,
        // the first step after it differs, and the old future is the abandoned history.
        SimulationController c;
        c.setScene(ringParams(), {"rk4"});
        settle(c);
        std::map<long, FramePtr> frames{{0L, c.latest()}};
        stepTo(c, 60, frames);
        const std::vector<Diagnostics> original = c.history();
        QSignalSpy branched(&c, &SimulationController::historyBranched);
        QVERIFY(sameFrame(*scrubbed(c, 30), *frames.at(30)));
        QVERIFY(c.latest()->timeline.scrubbed());
        c.setParameter(QStringLiteral("dt"), 0.001);
        settle(c);
        QCOMPARE(c.latest()->timeline.last, 30L);  // the future is forgotten by the worker
        QCOMPARE(branched.count(), 1);
        const double instant = frames.at(30)->lanes[0].diagnostics.time;
        // The abandoned future: the rows after the instant, as they were.
        QVERIFY(!c.abandoned().empty());
        QCOMPARE(c.abandoned().front().time, frames.at(31)->lanes[0].diagnostics.time);
        QVERIFY(sameDiagnostics(c.abandoned().back(), original.back()));
        QCOMPARE(c.history().back().time, instant);
        c.step();
        settle(c);
        const FramePtr next = c.latest();
        QCOMPARE(next->timeline.moment, 31L);
        QCOMPARE(next->lanes[0].diagnostics.time, instant + 0.001);
        QVERIFY(next->lanes[0].positions != frames.at(31)->lanes[0].positions);
        QCOMPARE(c.history().back().time, instant + 0.001);
        // Before and at the instant the timeline is the original run.
        for (long m : {5L, 29L}) QVERIFY(sameFrame(*scrubbed(c, m), *frames.at(m)));
        // ... and at 30 too, with the edit made there (DT 0.001); the branch's own moment
        // replays too.
        const FramePtr at = scrubbed(c, 30);
        QCOMPARE(at->lanes[0].positions, frames.at(30)->lanes[0].positions);
        QCOMPARE(at->parameters.get(simcore::Param::Dt), 0.001);
        QVERIFY(sameFrame(*scrubbed(c, 31), *next));
        // Clear removes the faint line.
        c.clearAbandoned();
        QVERIFY(c.abandoned().empty());
    }

    void controllerKeepsTheBudget() {
        // A small budget shared by three lanes: thinned, never above it, all moments reachable.
        SimulationController c;
        c.setScene(ringParams(), {"rk4", "midpoint", "verlet"});
        settle(c);
        Simulation probe(ringParams(), "rk4");
        const std::size_t budget = 3 * 30 * probe.snapshot().bytes();
        c.setTimelineBudget(budget);
        c.runUntil(2.0);
        QVERIFY(testsupport::waitUntil([&] {
            return c.latest() && !c.latest()->running &&
                   c.latest()->lanes[0].diagnostics.time >= 2.0 - 1e-9;
        }));
        settle(c);
        const elui::TimelineInfo t = c.latest()->timeline;
        QVERIFY(t.last >= 999);
        QVERIFY2(t.bytes <= budget, qPrintable(QStringLiteral("%1 > %2").arg(t.bytes).arg(budget)));
        QVERIFY(t.interval >= 32);
        const FramePtr end = c.latest();
        QCOMPARE(scrubbed(c, 777)->timeline.moment, 777L);
        QVERIFY(sameFrame(*scrubbed(c, t.last), *end));
    }

    void plotCursorReadsThePlottedValues() {
        // The cursor line's values are the plot's own data at the cursor; the abandoned future
        // is drawn in graphs of its own.
        elui::PlotDock dock;
        dock.setScene(SceneKind::Ring2d);
        Simulation sim(ringParams(), "rk4");
        std::vector<Diagnostics> rows{sim.diagnostics()};
        for (int i = 0; i < 50; ++i) {
            sim.step();
            rows.push_back(sim.diagnostics());
        }
        dock.appendRows(rows, 0, int(rows.size()));
        const QString energy = QStringLiteral("energy");
        QVERIFY(dock.plotIds().contains(energy));
        dock.setCursor(rows[20].time, true);
        QVERIFY(dock.cursorVisible());
        const int total = int(dock.seriesNames(energy).indexOf(QStringLiteral("total")));
        QVERIFY(total >= 0);
        QCOMPARE(dock.valueAt(energy, total, rows[20].time), rows[20].total());
        QCOMPARE(dock.valueAt(energy, total, 0.5 * (rows[20].time + rows[21].time)),
                 rows[20].total());
        QVERIFY(dock.cursorText(energy).contains(QString::number(rows[20].total(), 'g', 6)));
        QVERIFY(dock.cursorText(energy).contains(
            QStringLiteral("t = %1 s").arg(rows[20].time, 0, 'f', 4)));
        QCOMPARE(dock.abandonedPointCount(energy, total), 0);
        dock.setAbandoned({rows.begin() + 30, rows.end()});
        QCOMPARE(dock.abandonedPointCount(energy, total), 21);
        QCOMPARE(dock.pointCount(energy, total), 51);  // the series themselves are untouched
        dock.setHistory({rows.begin(), rows.begin() + 30});
        QCOMPARE(dock.pointCount(energy, total), 30);
        QCOMPARE(dock.abandonedPointCount(energy, total), 21);
    }

    void timelineDockDrivesTheController() {
        // The slider asks for moments; the frame that comes back sets it.
        SimulationController c;
        elui::TimelineDock dock;
        QObject::connect(&dock, &elui::TimelineDock::scrubRequested, &c,
                         &SimulationController::scrubTo);
        QObject::connect(&c, &SimulationController::frameArrived, &dock,
                         &elui::TimelineDock::showFrame);
        c.setScene(ringParams(), {"rk4"});
        settle(c);
        std::map<long, FramePtr> frames{{0L, c.latest()}};
        stepTo(c, 12, frames);
        QCOMPARE(dock.slider()->maximum(), 12);
        QCOMPARE(dock.slider()->value(), 12);
        dock.slider()->setValue(7);
        settle(c);
        QCOMPARE(c.latest()->timeline.moment, 7L);
        QVERIFY(sameFrame(*c.latest(), *frames.at(7)));
        QCOMPARE(dock.slider()->value(), 7);
        QVERIFY(dock.info()->text().contains(QStringLiteral("checkpoints")));
    }

    void windowKeysTravelAndBranch() {
        // In the window: Shift+S, Home and End travel (opening the dock), the plots' cursor
        // follows while back in time, a branch leaves the abandoned future in the plots, and
        // the dock's Clear removes it.
#if defined(__SANITIZE_THREAD__)
        // A shown window makes Qt Gui convert its backing image on Qt's own pool threads,
        // invisible to ThreadSanitizer in Debian's uninstrumented Qt (as in test_gui_plots).
        QSKIP("Qt's threaded image conversion is invisible to ThreadSanitizer");
#endif
        elui::MainWindow window(false);
        window.startScene(ringParams(), {"rk4"});
        window.show();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        SimulationController& c = *window.controller();
        settle(c);
        std::map<long, FramePtr> frames{{0L, c.latest()}};
        stepTo(c, 20, frames);
        QVERIFY(window.timelineDock()->isHidden());
        QVERIFY(!window.plotDock()->cursorVisible());
        auto key = [&](QKeyCombination k) {
            QTest::keyClick(&window, k.key(), k.keyboardModifiers());
            settle(c);
        };
        key(Qt::SHIFT | Qt::Key_S);
        QVERIFY(window.timelineDock()->isVisible());
        QCOMPARE(c.latest()->timeline.moment, 19L);
        QVERIFY(sameFrame(*c.latest(), *frames.at(19)));
        QTRY_VERIFY_WITH_TIMEOUT(window.plotDock()->cursorVisible(), testsupport::kHangGuardMs);
        QCOMPARE(window.plotDock()->cursorTime(), frames.at(19)->lanes[0].diagnostics.time);
        key(Qt::Key_Home);
        QCOMPARE(c.latest()->timeline.moment, 0L);
        key(Qt::Key_End);
        QCOMPARE(c.latest()->timeline.moment, 20L);
        QTRY_VERIFY_WITH_TIMEOUT(!window.plotDock()->cursorVisible(), testsupport::kHangGuardMs);
        // Branch at 10 with another DT: the plots keep the old future as the abandoned one.
        c.scrubTo(10);
        settle(c);
        c.setParameter(QStringLiteral("dt"), 0.001);
        c.step();
        settle(c);
        const QString energy = QStringLiteral("energy");
        QTRY_COMPARE_WITH_TIMEOUT(window.plotDock()->abandonedPointCount(energy, 0), 10,
                                  testsupport::kHangGuardMs);
        QCOMPARE(window.plotDock()->pointCount(energy, 0),
                 12);  // moments 0..10 and the branch's first
        QVERIFY(window.timelineDock()->clearButton()->isEnabled());
        window.timelineDock()->clearButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(window.plotDock()->abandonedPointCount(energy, 0), 0,
                                  testsupport::kHangGuardMs);
        QVERIFY(c.abandoned().empty());
        QVERIFY(!window.timelineDock()->clearButton()->isEnabled());
    }
};

QTEST_MAIN(TestTimeline)
#include "test_timeline.moc"
