// Scenes of several bodies in the window (issue 26), offscreen: the frames carry every body,
// the Parameters dock edits one body (or all), the Bodies dock reads momentum and min_gap and
// plots per body, a body is added and removed, the mouse drags a particle of any body, the
// Studies menu on a world, and side by side: a world per view with its own integrator.
#include <cmath>

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTableWidget>
#include <QTest>

#include "simcore/world.h"
#include "simlab/stability.h"
#include "gui_world_support.h"
#include "test_support.h"
#include "ui/bodies_dock.h"
#include "ui/language.h"
#include "ui/lesson_dock.h"
#include "ui/main_window.h"
#include "ui/parameter_dock.h"
#include "ui/plot_dock.h"
#include "ui/simulation_controller.h"
#include "ui/stability_map_dock.h"
#include "ui/studies_dialog.h"
#include "simlab/request.h"

using namespace elui;
using testsupport::waitUntil;

using worldtest::scene;
using worldtest::waitForFrame;

class TestGuiWorld : public QObject {
    Q_OBJECT
private slots:
    void aWorldInTheWindow() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        window.startWorld(scene("collide2d", {"gravity=0", "body2.mass=4"}));
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world != nullptr; }));
        const Frame& first = *c->latest();
        // Every body's particles in the one lane, the scene split by body.
        QCOMPARE(first.scene->bodies.size(), std::size_t{2});
        const int particles = first.scene->bodies[1].first + first.scene->bodies[1].count;
        QCOMPARE(int(first.lanes[0].positions.size()), 3 * particles);
        QCOMPARE(first.scene->topology.particleCount(), particles);
        QCOMPARE(first.worldSpec->bodies.size(), std::size_t{2});
        // The Plots dock has the world's energy, not one body's volume; the Bodies dock opened.
        QVERIFY(!window.plotDock()->plotIds().contains(QStringLiteral("volume")));
        QVERIFY(window.plotDock()->plotIds().contains(QStringLiteral("energy")));
        BodiesDock* bodies = window.bodiesDock();
        QVERIFY(waitUntil([&] { return bodies->isVisible() && bodies->readoutText().contains("momentum"); }));
        QCOMPARE(bodies->table()->rowCount(), 2);
        QCOMPARE(bodies->seriesNames("volume"),
                 QStringList({"body1 inner", "body1 outer", "body2 inner", "body2 outer"}));
        // The stability map maps the whole world: every body's eigenvalues, as simlab's verdict.
        StabilityMapDock* map = window.stabilityMapDock();
        QVERIFY(window.openDock(QStringLiteral("stability-map")));
        QVERIFY(waitUntil([&] { return map->shownBodies() == 2 && map->pointCount() > 0 && !map->computing(); }));
        const simlab::LinearModes expected = simlab::stabilityModes(*first.worldSpec);
        QCOMPARE(map->modes()->freeCoordinates, expected.freeCoordinates);
        QCOMPARE(map->modes()->eigenvalues.size(), expected.eigenvalues.size());
        QVERIFY(map->methodText().contains(QStringLiteral("(2 bodies)")));

        // Run: momentum stays -144 kg m/s through the impact (24 particles of 1 kg at +2 m/s,
        // 24 of 4 kg at -2 m/s), min_gap shrinks below the range and stays above 0.
        c->runUntil(1.2);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return !f.running && f.world && f.world->time >= 1.2 - 1e-9; }));
        QVERIFY(waitUntil([&] { return bodies->plottedPoints() >= 2; }));
        QVERIFY(std::abs(bodies->lastValue("momentum", 0) + 144.0) < 1e-8);
        const simcore::WorldDiagnostics& d = *c->latest()->world;
        QVERIFY(d.minGap > 0.0 && d.minGap < 0.2);
        QVERIFY(std::abs(d.momentum.x() + 144.0) < 1e-8);
        QVERIFY(!c->history().empty());
        QCOMPARE(c->history().back().time, d.time);  // the Plots dock's rows are the world's totals
        QCOMPARE(c->history().back().total(), d.total());
    }

    // The Lesson dock reads a world as a world (momentum, the gap, each body's velocity and
    // outer area), not as one body on the floor (it showed "nan" and "0.000 m above the
    // floor"); the Bodies dock's numbers in the window's language.
    void theLessonDockAndTheBodiesDockReadAWorld() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        window.lessonDock()->show();
        window.startWorld(scene("collide2d", {"gravity=0", "body2.mass=4"}));
        c->runUntil(1.2);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return !f.running && f.world && f.world->time >= 1.2 - 1e-9; }));
        QVERIFY(waitUntil([&] { return window.lessonDock()->readout()->text().contains("body2: centre velocity"); }));
        const QString text = window.lessonDock()->readout()->text();
        QVERIFY2(text.contains("total momentum <b>(-144, "), qPrintable(text));
        QVERIFY2(text.contains("smallest gap 0.09"), qPrintable(text));
        QVERIFY2(!text.contains("nan") && !text.contains("floor"), qPrintable(text));
        // German: a decimal comma in the Bodies dock's readout (min_gap about 0.09 m).
        struct BackToEnglish {
            ~BackToEnglish() { applyLanguage(QStringLiteral("en")); }
        } backToEnglish;  // also when a check fails, for the tests after this one
        applyLanguage(QStringLiteral("de"));
        c->runUntil(1.3);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return !f.running && f.world && f.world->time >= 1.3 - 1e-9; }));
        QVERIFY(waitUntil([&] { return window.bodiesDock()->readoutText().contains("0,0"); }));
        QVERIFY2(!window.bodiesDock()->readoutText().contains("0.0"), qPrintable(window.bodiesDock()->readoutText()));
    }

    // A Bodies dock shown after a run (closed, or behind the Plots tab, while it ran) puts the
    // points it took in view at once: before, its axes stayed empty until the next frame.
    void theBodiesDockShowsARunItMissed() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        window.startWorld(scene("collide2d", {"gravity=0"}));
        BodiesDock* bodies = window.bodiesDock();
        QVERIFY(waitUntil([&] { return bodies->isVisible(); }));
        bodies->hide();
        c->runUntil(0.5);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return !f.running && f.world && f.world->time >= 0.5 - 1e-9; }));
        QVERIFY(waitUntil([&] { return bodies->plottedPoints() >= 2; }));
        const double end = c->latest()->world->time;
        QVERIFY(bodies->shownTimeEnd("momentum") != end);  // hidden: not redrawn
        bodies->toggleViewAction()->trigger();  // View > Bodies: shown and in front
        QVERIFY(bodies->isVisible() && !bodies->visibleRegion().isEmpty());
        for (const char* id : {"momentum", "gap", "volume", "pressure"})
            QVERIFY2(waitUntil([&] { return bodies->shownTimeEnd(id) == end; }), id);
    }

    void parametersPerBody() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        window.startWorld(scene("collide2d", {"gravity=0"}));
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world != nullptr; }));
        ParameterDock* dock = window.findChild<ParameterDock*>();
        QComboBox* selector = dock->bodySelector();
        QVERIFY(waitUntil([&] { return selector->isVisibleTo(dock) && selector->count() == 3; }));
        QCOMPARE(selector->itemText(1), QStringLiteral("body2 (ring2d)"));
        QCOMPARE(selector->itemText(2), QStringLiteral("every body"));
        // body2's mass: only body 2 changes, and the run goes on from where it was.
        c->runUntil(0.1);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return !f.running && f.world && f.world->time >= 0.1 - 1e-9; }));
        const double t = c->latest()->world->time;
        selector->setCurrentIndex(1);
        emit selector->activated(1);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.worldBody == 1; }));
        QLineEdit* mass = dock->form()->field("mass");
        QVERIFY(mass);
        mass->setText("4");
        emit mass->editingFinished();
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.worldSpec->bodies[1].params.get(simcore::Param::Mass) == 4.0; }));
        QCOMPARE(c->latest()->worldSpec->bodies[0].params.get(simcore::Param::Mass), 1.0);
        QCOMPARE(c->latest()->world->time, t);
        QCOMPARE(c->latest()->world->bodies[1].mass, 96.0);
        // A world parameter goes to every body whatever is chosen.
        window.controller()->setParameter(simcore::Param::Gravity, 2.0);
        QVERIFY(waitForFrame(*c, [](const Frame& f) {
            return f.worldSpec->bodies[0].params.get(simcore::Param::Gravity) == 2.0 &&
                   f.worldSpec->bodies[1].params.get(simcore::Param::Gravity) == 2.0;
        }));
        // A body the world refuses (overlapping body 1) is rejected by name, nothing changes.
        QSignalSpy rejected(c, &SimulationController::parameterRejected);
        c->setParameter(simcore::Param::Mass, -1.0);
        QVERIFY(waitUntil([&] { return rejected.count() == 1; }));
        QVERIFY2(rejected.at(0).at(1).toString().contains("body2"), qPrintable(rejected.at(0).at(1).toString()));
    }

    void addRemoveAndDrag() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        window.startWorld(scene("collide3d", {"gravity=0", "subdivisions=1"}));
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world != nullptr; }));
        BodiesDock* bodies = window.bodiesDock();
        QVERIFY(waitUntil([&] { return bodies->addKind()->count() == 2; }));  // the 3D kinds
        bodies->addField("position_y")->setText("5");
        bodies->addField("velocity_y")->setText("-1");
        bodies->addButton()->click();
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world && f.world->bodies.size() == 3; }));
        QCOMPARE(c->latest()->worldSpec->bodies[2].position.y(), 5.0);
        QCOMPARE(c->latest()->worldSpec->bodies[2].velocity.y(), -1.0);
        // One that overlaps is refused with the world's reason; the world stays.
        bodies->addField("position_y")->setText("0");
        QSignalSpy status(window.statusBar(), &QStatusBar::messageChanged);
        bodies->addButton()->click();
        QVERIFY(waitUntil([&] { return status.count() >= 1; }));
        QVERIFY2(status.last().at(0).toString().contains("overlap"), qPrintable(status.last().at(0).toString()));
        QCOMPARE(c->latest()->world->bodies.size(), std::size_t{3});
        QVERIFY(waitUntil([&] { return bodies->table()->rowCount() == 3; }));
        bodies->table()->selectRow(0);
        bodies->removeButton()->click();
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world && f.world->bodies.size() == 2; }));
        QCOMPARE(c->latest()->worldSpec->bodies[1].position.y(), 5.0);  // the added one is body 2 now

        // The mouse on body 2 (first particle of body 2, from straight above along -z... it is
        // picked along a ray through it): a spring pulls it, and only it.
        const Frame& f = *c->latest();
        const int first2 = f.scene->bodies[1].first;
        int top = first2;
        for (int i = first2; i < first2 + f.scene->bodies[1].count; ++i)
            if (f.scene->topology.layer[std::size_t(i)] == simcore::Layer::Outer &&
                f.lanes[0].positions[3 * std::size_t(i) + 2] > f.lanes[0].positions[3 * std::size_t(top) + 2])
                top = i;
        const QVector3D at(f.lanes[0].positions[3 * std::size_t(top)], f.lanes[0].positions[3 * std::size_t(top) + 1],
                           f.lanes[0].positions[3 * std::size_t(top) + 2]);
        QSignalSpy grabbed(c, &SimulationController::grabbed);
        c->grabAlongRay(at + QVector3D(0, 0, 10), QVector3D(0, 0, -1), 0.05);
        QVERIFY(waitUntil([&] { return grabbed.count() == 1; }));
        QCOMPARE(grabbed.at(0).at(0).toInt(), top);
        c->moveAnchor(at + QVector3D(0, 0, 2));
        for (int i = 0; i < 30; ++i) c->step();
        QVERIFY(waitForFrame(*c, [](const Frame& g) { return g.world && g.world->step >= 30; }));
        QVERIFY(c->latest()->lanes[0].pointer.active);
        QCOMPARE(c->latest()->lanes[0].pointer.particle, top);
        QVERIFY(c->latest()->world->bodies[1].velocity.z() > 0.01);  // pulled up along z
        QVERIFY(std::abs(c->latest()->world->bodies[0].velocity.z()) < 1e-9);
        c->release();
        QVERIFY(waitForFrame(*c, [](const Frame& g) { return !g.lanes[0].pointer.active; }));
    }

    // The Studies menu takes a world where simlab does (work-precision, refinement, the
    // stability scan: the CLI's study, study --refine and stability of the whole world) and
    // refuses long-time energy with simlab's own words.
    void theStudiesMenuOnAWorld() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        QAction* worlds = nullptr;
        for (QAction* a : window.menuBar()->actions())
            if (a->menu())
                for (QAction* b : a->menu()->actions())
                    if (b->menu() && b->menu()->objectName() == "worldsMenu") worlds = b;
        QVERIFY(worlds);
        QStringList names;
        for (QAction* a : worlds->menu()->actions()) names << a->text();
        QCOMPARE(names, QStringList({"collide2d", "collide3d", "stack3d"}));
        worlds->menu()->actions().at(0)->trigger();
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world != nullptr; }));
        QVERIFY(c->isWorld());
        QMenu* studies = nullptr;
        for (QAction* a : window.menuBar()->actions())
            if (a->menu() && a->text().contains("tudies")) studies = a->menu();
        QVERIFY(studies);
        // Work-precision, refinement and the stability scan open on the world.
        for (int i = 0; i < 3; ++i) {
            studies->actions().at(i)->trigger();
            const auto dialogs = window.findChildren<StudyDialogBase*>();
            QCOMPARE(dialogs.size(), qsizetype(i + 1));
            const QLabel* label = dialogs.back()->findChild<QLabel*>("studyScene");
            QVERIFY2(label && label->text().contains("collide2d") && label->text().contains("2 bodies"),
                     qPrintable(label ? label->text() : QString()));
        }
        QVERIFY(window.findChild<QMessageBox*>() == nullptr);
        // Long-time energy is one body's in simlab: its refusal, in its words.
        studies->actions().at(3)->trigger();
        QVERIFY(waitUntil([&] { return window.findChild<QMessageBox*>() != nullptr; }));
        const QString refusal = window.findChild<QMessageBox*>()->text();
        simlab::ConservationSpec spec;
        spec.world = *c->latest()->worldSpec;
        QString expected;
        try {
            simlab::checkConservation(spec);
        } catch (const simlab::RequestError& e) {
            expected = QString::fromStdString(e.what());
        }
        QVERIFY(expected.contains("is a scene of several bodies"));
        QCOMPARE(refusal, expected);
        QVERIFY(window.findChildren<ConservationDialog*>().isEmpty());
        // The work-precision dialog studies the whole world: its rows are simlab's runStudy of the
        // world's spec (the CLI's study --scene collide2d), not body 1's alone.
        auto* wp = window.findChildren<WorkPrecisionDialog*>().front();
        wp->setChosenIntegrators({"euler", "midpoint"});
        wp->setSteps("0.002 0.001");
        wp->setDuration(0.02);
        wp->setRepeats(1);
        QSignalSpy finished(wp, &StudyDialogBase::finished);
        wp->start();
        QVERIFY(waitUntil([&] { return finished.count() == 1; }));
        simlab::StudySpec direct;
        direct.params = c->parameters();
        direct.world = *c->latest()->worldSpec;
        direct.integrators = {"euler", "midpoint"};
        direct.dts = {0.002, 0.001};
        direct.duration = 0.02;
        direct.repeat = 1;
        const simlab::StudyResult want = simlab::runStudy(direct);
        const auto& got = wp->result().rows;
        QCOMPARE(got.size(), want.rows.size());
        for (std::size_t i = 0; i < got.size(); ++i) {
            QVERIFY(got[i].ok);
            QCOMPARE(got[i].errorMax, want.rows[i].errorMax);
        }
        direct.world.reset();  // body 1 alone is another study
        QVERIFY(simlab::runStudy(direct).rows.front().errorMax != got.front().errorMax);
        // Back to one body: the map maps again, the Bodies dock says what it is for.
        window.startScene(simcore::ParameterSet(simcore::SceneKind::Ring2d), {"rk4"});
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world == nullptr && f.scene && !f.scene->isWorld(); }));
        QVERIFY(window.openDock(QStringLiteral("stability-map")));
        QVERIFY(waitUntil([&] { return window.stabilityMapDock()->shownBodies() == 0 && window.stabilityMapDock()->pointCount() > 0; }));
        QVERIFY(window.plotDock()->plotIds().contains(QStringLiteral("volume")));
    }

    // Side by side for a world: the same world in each view with its own integrator, every body
    // in each view, each view's momentum and min_gap (its text: test_gui_render); the front door
    // checks each lane; the timeline holds every view's world; back to a single view.
    void aWorldSideBySide() {
        MainWindow window(false);
        window.show();
        SimulationController* c = window.controller();
        window.startWorld(scene("collide2d", {"gravity=0", "body2.mass=4"}));
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.world != nullptr; }));
        QAction* sideBySide = nullptr;
        for (QAction* a : window.findChildren<QAction*>())
            if (a->text() == "&Side by side...") sideBySide = a;
        QVERIFY(sideBySide && sideBySide->isEnabled());
        QCOMPARE(window.sideBySide({"rk4", "euler"}), QString());
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.lanes.size() == 2 && f.world; }));
        QCOMPARE(c->integrators(), QStringList({"rk4", "euler"}));
        c->runUntil(1.2);
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return !f.running && f.lanes.size() == 2 && f.lanes[0].diagnostics.time >= 1.2 - 1e-9; }));
        const FramePtr end = c->latest();
        const int particles = end->scene->bodies[1].first + end->scene->bodies[1].count;
        QCOMPARE(end->lanes[0].integrator, QString("rk4"));
        QCOMPARE(end->lanes[1].integrator, QString("euler"));
        for (const LaneFrame& lane : end->lanes) {
            QVERIFY(lane.world && !lane.failure);
            QCOMPARE(int(lane.positions.size()), 3 * particles);  // every body in every view
            QCOMPARE(lane.diagnostics.time, end->lanes[0].diagnostics.time);  // one clock
            QVERIFY(std::abs(lane.world->momentum.x() + 144.0) < 1e-8);  // each conserves it
            QVERIFY(lane.world->minGap > 0.0 && lane.world->minGap < 0.2);  // through the impact
        }
        QCOMPARE(end->world, end->lanes[0].world);
        QVERIFY(end->lanes[1].divergence > 1e-6);  // euler is not rk4
        QVERIFY(end->lanes[0].world->minGap != end->lanes[1].world->minGap);
        // The plots get the other view's rows, at the common times.
        QCOMPARE(c->viewHistory().size(), std::size_t{1});
        QVERIFY(!c->viewHistory()[0].empty());
        QCOMPARE(c->viewHistory()[0].back().time, end->lanes[1].diagnostics.time);
        // The timeline records both worlds: back and forward again, bit for bit in each view.
        c->scrubBy(-7);
        QVERIFY(waitForFrame(*c, [&](const Frame& f) { return f.timeline.moment == end->timeline.moment - 7; }));
        QVERIFY(c->latest()->lanes[1].positions != end->lanes[1].positions);
        c->scrubToEnd();
        QVERIFY(waitForFrame(*c, [&](const Frame& f) { return f.timeline.moment == end->timeline.moment; }));
        for (int v = 0; v < 2; ++v) QVERIFY(c->latest()->lanes[std::size_t(v)].positions == end->lanes[std::size_t(v)].positions);
        // The front door checks each lane: xpbd needs one set of springs for the whole world.
        window.startWorld(scene("collide2d", {"gravity=0", "body2.ks=500"}), {"rk4", "euler"});
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.lanes.size() == 2 && f.world && f.lanes[0].diagnostics.time == 0.0 &&
                                                             f.worldSpec->bodies[1].params.get(simcore::Param::Ks) == 500.0; }));
        const QString refusal = window.sideBySide({"rk4", "xpbd"});
        QVERIFY2(refusal.contains("xpbd takes one stiffness and damping per spring family for the whole world"), qPrintable(refusal));
        QCOMPARE(c->integrators(), QStringList({"rk4", "euler"}));
        // One view again: the world alone with the first view's integrator.
        window.singleView();
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.lanes.size() == 1 && f.world; }));
        QCOMPARE(c->latest()->lanes[0].integrator, QString("rk4"));
        QCOMPARE(c->latest()->worldSpec->bodies[1].params.get(simcore::Param::Ks), 500.0);
    }

};

QTEST_MAIN(TestGuiWorld)
#include "test_gui_world.moc"
