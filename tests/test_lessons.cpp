// Guided experiments (Help > Experiments): every lesson's preset reaches the window, its text has
// the required sections, and every answer it states is measured again here with simcore and
// compared with the number written in the text (ui/lessons.h: <span class="answer" ...>).
//
// The measurements are those of the elastic-lab-cli commands the texts give, run on the
// lesson's own preset parameters: a lesson whose preset, text or physics drifts apart fails.
// Each is short (well under a second in Release); the sanitizer suites run them unchanged.

#include <cmath>
#include <cstring>
#include <functional>
#include <map>

#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QUrl>
#include <QMenuBar>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTextDocument>

#include "simcore/integrator_table.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/impact.h"
#include "simlab/stability.h"
#include "simlab/conservation.h"
#include "test_support.h"
#include "ui/energy_bars_dock.h"
#include "ui/lessons.h"
#include "ui/lessons_dialog.h"
#include "ui/main_window.h"
#include "ui/pv_dock.h"
#include "ui/simulation_controller.h"

using namespace elui;
using simcore::ParameterSet;
using simcore::Simulation;

namespace {

const Lesson& lesson(const QString& id) {
    const Lesson* l = findLesson(id);
    if (!l) qFatal("no lesson %s", qPrintable(id));
    return *l;
}

ParameterSet with(ParameterSet p, std::initializer_list<std::pair<const char*, double>> values) {
    for (const auto& [key, value] : values)
        if (auto error = p.set(key, value)) qFatal("%s", error->c_str());
    return p;
}

// Runs `steps` steps (or until the run fails) and returns the simulation.
std::unique_ptr<Simulation> runSteps(const ParameterSet& p, const std::string& integrator, long steps) {
    auto sim = std::make_unique<Simulation>(p, integrator);
    while (sim->diagnostics().step < steps)
        if (!sim->step()) break;
    return sim;
}

// The simulated time at which a run fails (the start of the failing step), or -1.
double failureTime(const ParameterSet& p, const std::string& integrator, double until) {
    Simulation sim(p, integrator);
    while (sim.time() < until)
        if (!sim.step()) return sim.failure()->time;
    return -1.0;
}

// `elastic-lab-cli stability`'s row for one integrator on these parameters (perturb 0.01 m).
simlab::StabilityRow scan(const ParameterSet& p, const std::string& integrator) {
    simlab::StabilitySpec spec;
    spec.params = p;
    spec.integrators = {integrator};
    // The one verdict's linearisation, as the CLI's (the trials start perturbed).
    return simlab::scanIntegrator(spec, integrator, simlab::stabilityModes(p));
}

// Mean height of the outer layer's particles minus that of the inner layer's [m].
double sag(const Simulation& sim) {
    double inner = 0.0, outer = 0.0;
    int ni = 0, no = 0;
    const auto& layer = sim.topology().layer;
    for (Eigen::Index i = 0; i < sim.positions().cols(); ++i) {
        if (layer[std::size_t(i)] == simcore::Layer::Inner) inner += sim.positions()(1, i), ++ni;
        else outer += sim.positions()(1, i), ++no;
    }
    return outer / no - inner / ni;
}

using Measure = std::function<double()>;

// Every stated answer, by lesson and key, measured as the lesson's CLI command measures it.
QMap<QString, QMap<QString, Measure>> measurements() {
    QMap<QString, QMap<QString, Measure>> m;

    // 1. `stability --scene ring2d --integrators euler`; `run ... --dt 0.009 --set perturb=0.01`.
    const ParameterSet euler = lesson("euler-limit").preset.parameters();
    m["euler-limit"]["dt-stable"] = [=] { return scan(euler, "euler").stable; };
    m["euler-limit"]["dt-predicted"] = [=] { return scan(euler, "euler").predicted; };
    m["euler-limit"]["blowup-time"] = [=] { return failureTime(with(euler, {{"dt", 0.009}}), "euler", 2.0); };

    // 2. `run --scene ring2d --integrator I --dt 0.003 --duration 3` (1000 steps).
    const ParameterSet drift = lesson("energy-drift").preset.parameters();
    for (const char* integrator : {"euler", "midpoint", "rk4"})
        m["energy-drift"][QStringLiteral("drift-") + integrator] = [=] {
            return runSteps(drift, integrator, 1000)->diagnostics().energyDrift();
        };
    m["energy-drift"]["rk4-ratio"] = [=] {
        return runSteps(drift, "rk4", 1000)->diagnostics().energyDrift() /
               runSteps(with(drift, {{"dt", 0.0015}}), "rk4", 2000)->diagnostics().energyDrift();
    };

    // 3. `run --scene sphere3d --set subdivisions=2 --set mass_inner=5 --duration 3 --state`.
    const ParameterSet heavy = lesson("heavy-inner").preset.parameters();
    m["heavy-inner"]["sag"] = [=] { return sag(*runSteps(heavy, "rk4", 1000)); };
    m["heavy-inner"]["collapse-time"] = [=] { return failureTime(with(heavy, {{"mass_inner", 10.0}}), "rk4", 3.0); };

    // 4. `stability --scene sphere3d --set subdivisions=L --integrators rk4`, and the pre-run
    // advice the banner shows at level 3 with the lesson's DT.
    const ParameterSet sphere = lesson("refine-sphere").preset.parameters();
    for (int level : {1, 2, 3})
        m["refine-sphere"][QStringLiteral("dt-level%1").arg(level)] = [=] {
            return scan(with(sphere, {{"subdivisions", level}}), "rk4").stable;
        };
    m["refine-sphere"]["suggested-level3"] = [=] {
        const Simulation sim(with(sphere, {{"subdivisions", 3}}), "rk4");
        const auto advice = simlab::stabilityAdvice(sim);
        return advice ? advice->suggestedDt : -1.0;
    };

    // 5. `run --scene ring2d --duration 3 --csv`: the row with the smallest inner area.
    const ParameterSet ring = lesson("pv-isotherm").preset.parameters();
    auto squash = [=](int what) {
        Simulation sim(ring, "rk4");
        simcore::Diagnostics least = sim.diagnostics();
        while (sim.diagnostics().step < 1000 && sim.step())
            if (sim.diagnostics().volume[0] < least.volume[0]) least = sim.diagnostics();
        return what == 0 ? least.volume[0] : what == 1 ? least.pressure[0] : least.time;
    };
    m["pv-isotherm"]["min-area"] = [=] { return squash(0); };
    m["pv-isotherm"]["max-pressure"] = [=] { return squash(1); };
    m["pv-isotherm"]["squash-time"] = [=] { return squash(2); };

    // 6. `restitution --scene ring2d --set restitution=E --speeds 1,3`.
    const ParameterSet bounce = lesson("restitution").preset.parameters();
    m["restitution"]["particle-e0.9"] = [=] { return simlab::measureImpact(bounce, "rk4", 3.0).particle; };
    m["restitution"]["body-e0.9"] = [=] { return simlab::measureImpact(bounce, "rk4", 3.0).body; };
    m["restitution"]["body-e0.2"] = [=] {
        return simlab::measureImpact(with(bounce, {{"restitution", 0.2}}), "rk4", 3.0).body;
    };
    m["restitution"]["particle-1mps"] = [=] { return simlab::measureImpact(bounce, "rk4", 1.0).particle; };

    // 7. `stability --scene ring2d --set ks=1e6 --integrators rk4`; `run ... implicit-euler
    // --dt 0.01 --duration 3` (300 steps).
    const ParameterSet stiff = lesson("stiff-springs").preset.parameters();
    m["stiff-springs"]["rk4-limit"] = [=] { return scan(stiff, "rk4").stable; };
    m["stiff-springs"]["implicit-drift"] = [=] {
        return runSteps(stiff, "implicit-euler", 300)->diagnostics().energyDrift();
    };

    // 8. `conservation --scene spring1d --dt 0.01 --periods 10000 (and 100) --integrators
    // verlet,yoshida4,rk4`: each study runs once per test run, shared by the answers that read it.
    const ParameterSet spring = lesson("why-symplectic").preset.parameters();
    auto longRun = [=](double periods) {
        return [=]() -> const simlab::ConservationResult& {
            static std::map<double, simlab::ConservationResult> done;
            if (!done.count(periods)) {
                simlab::ConservationSpec spec;
                spec.params = spring;
                spec.integrators = {"verlet", "yoshida4", "rk4"};
                spec.periods = periods;
                spec.dt = spring.get(simcore::Param::Dt);
                done[periods] = simlab::runConservation(spec);
            }
            return done[periods];
        };
    };
    const auto long10000 = longRun(10000.0), long100 = longRun(100.0);
    m["why-symplectic"]["verlet-error"] = [=] { return long10000().rows[0].finalError; };
    m["why-symplectic"]["yoshida4-error"] = [=] { return long10000().rows[1].finalError; };
    m["why-symplectic"]["rk4-error"] = [=] { return long10000().rows[2].finalError; };
    m["why-symplectic"]["verlet-growth"] = [=] { return long10000().rows[0].finalError / long100().rows[0].finalError; };
    m["why-symplectic"]["rk4-growth"] = [=] { return long10000().rows[2].finalError / long100().rows[2].finalError; };
    m["why-symplectic"]["rk4-alpha"] = [=] { return long10000().rows[2].alpha; };

    // 9. `run --scene collide2d --set gravity=0 --set body2.mass=4 --duration 2.4` (800 steps).
    const auto worldAt = [](const Lesson& l, long steps) {
        return [spec = *l.preset.world(), steps]() -> simcore::WorldDiagnostics {
            simcore::World world(spec, "rk4");
            while (world.stepCount() < steps)
                if (!world.step()) qFatal("the lesson's world failed: %s", world.failure()->c_str());
            return world.diagnostics();
        };
    };
    const auto balloons = worldAt(lesson("balloons-collide"), 800);
    m["balloons-collide"]["v1-after"] = [=] { return balloons().bodies[0].velocity.x(); };
    m["balloons-collide"]["v2-after"] = [=] { return balloons().bodies[1].velocity.x(); };
    m["balloons-collide"]["momentum"] = [=] { return balloons().momentum.x(); };
    m["balloons-collide"]["restitution"] = [=] {
        const auto d = balloons();
        return (d.bodies[1].velocity.x() - d.bodies[0].velocity.x()) / (2.0 - (-2.0));
    };
    m["balloons-collide"]["ke-kept"] = [=] {
        const auto d = balloons();
        double before = 0.0, after = 0.0;
        for (const auto& b : d.bodies) {
            before += 0.5 * b.mass * 4.0;
            after += 0.5 * b.mass * b.velocity.squaredNorm();
        }
        return after / before;
    };

    // 10. `run --scene stack3d --set subdivisions=1 --set pressure=300 --set kd=40 --set rkd=120
    // --duration 5` (1667 steps), run once and shared by its answers.
    const auto stackRun = worldAt(lesson("soft-stack"), 1667);
    const auto stack = [=]() -> const simcore::WorldDiagnostics& {
        static const simcore::WorldDiagnostics done = stackRun();
        return done;
    };
    const auto flattened = [=](int body) {
        const simcore::BodyDiagnostics& b = stack().bodies[std::size_t(body)];
        return b.volume[1] / b.restVolume[1];
    };
    m["soft-stack"]["bottom-volume"] = [=] { return flattened(0); };
    m["soft-stack"]["middle-volume"] = [=] { return flattened(1); };
    m["soft-stack"]["top-volume"] = [=] { return flattened(2); };
    m["soft-stack"]["pressure-ratio"] = [=] { return stack().bodies[0].pressure[1] / stack().bodies[2].pressure[1]; };
    return m;
}

bool waitForLesson(MainWindow& w, const Lesson& l) {
    return testsupport::waitUntil([&] {
        const FramePtr f = w.controller()->latest();
        return f && f->parameters == l.preset.parameters() && int(f->lanes.size()) == l.preset.integrators.size() &&
               (f->world != nullptr) == l.preset.world().has_value() &&
               (!f->worldSpec || f->worldSpec->bodies.size() == l.preset.world()->bodies.size());
    });
}

}  // namespace

class TestLessons : public QObject {
    Q_OBJECT
private slots:
    void lessonsAreCompleteAndDistinct() {
        const QList<Lesson> all = lessons();
        QVERIFY2(all.size() >= 6, "issue 16 asks for at least six lessons");
        QStringList ids;
        for (const Lesson& l : all) {
            QVERIFY2(!ids.contains(l.id), qPrintable(l.id));
            ids << l.id;
            QCOMPARE(findLesson(l.id)->title, l.title);
            QVERIFY(!l.preset.integrators.isEmpty() && l.preset.integrators.size() <= 3);
            // Valid presets: the scene exists, every value passes the parameter table.
            if (const auto world = l.preset.world()) {  // a scene of several bodies: its --set, checked
                simcore::WorldSpec spec = *simcore::worldScene(l.preset.scene.toStdString());
                for (const QString& a : l.preset.worldSet)
                    QVERIFY2(!simcore::assignWorld(spec, a.toStdString()), qPrintable(l.id + ": " + a));
                QVERIFY2(!simcore::validateWorld(spec), qPrintable(l.id));
                QCOMPARE(l.preset.integrators.size(), 1);  // a world runs alone
            }
            QVERIFY2(simcore::findScene(l.preset.scene.toStdString()) || l.preset.world(), qPrintable(l.id));
            ParameterSet p(l.preset.parameters().kind());
            for (const auto& [id, value] : l.preset.values) {
                const auto error = p.set(id, value);
                QVERIFY2(!error, qPrintable(l.id + ": " + QString::fromUtf8(simcore::paramSpec(id).key.data()) + ": " +
                                            QString::fromStdString(error.value_or(""))));
            }
            for (const QString& name : l.preset.integrators)
                QVERIFY2(!simcore::unknownIntegrator(name.toStdString()), qPrintable(l.id + ": " + name));
            // Every dock a lesson names exists in this window.
            for (const QString& dock : l.docks)
                QVERIFY2(MainWindow::dockNames().contains(dock), qPrintable(l.id + ": dock " + dock));
        }
        {
            MainWindow window(false);
            for (const QString& name : MainWindow::dockNames()) QVERIFY2(window.dock(name), qPrintable(name));
            QCOMPARE(window.dock("no-such-dock"), nullptr);
        }
        QCOMPARE(lessonIds(), ids);
        QCOMPARE(findLesson("no-such-lesson"), nullptr);
    }

    void textsHaveTheSectionsAndMarkedAnswers() {
        for (const Lesson& l : lessons()) {
            const QString html = l.html();
            QVERIFY2(!html.isEmpty(), qPrintable(l.id + ": no text in :/lessons/"));
            QVERIFY2(html.contains("<h2>" + l.title.toHtmlEscaped() + "</h2>"), qPrintable(l.id + ": title"));
            QCOMPARE(lessonSections(html), lessonSectionTitles());
            // Half a page: read in a minute or two in front of the class.
            QTextDocument doc;
            doc.setHtml(html);
            const qsizetype words = doc.toPlainText().split(QRegularExpression("\\s+"), Qt::SkipEmptyParts).size();
            QVERIFY2(words >= 150 && words <= 400, qPrintable(l.id + ": " + QString::number(words) + " words"));
            QString error;
            const auto answers = lessonAnswers(html, &error);
            QVERIFY2(error.isEmpty(), qPrintable(l.id + ": " + error));
            QVERIFY2(!answers.isEmpty(), qPrintable(l.id + ": no marked answer"));
            // The answer names the command that measures it, inside "The measured answer".
            const qsizetype from = html.indexOf("<h3>The measured answer</h3>");
            const qsizetype to = html.indexOf("<h3>Why</h3>");
            QVERIFY(from >= 0 && to > from);
            const QString answerSection = html.mid(from, to - from);
            QVERIFY2(answerSection.contains("<pre>elastic-lab-cli "), qPrintable(l.id + ": no CLI command"));
            QCOMPARE(html.count("class=\"answer\""), answers.size());
            for (const QString& key : answers.keys())
                QVERIFY2(answerSection.contains("data-key=\"" + key + "\""), qPrintable(l.id + ": " + key));
        }
    }

    void answerParserRefusesMalformedMarks() {
        QString error;
        auto parse = [&](const QString& html) {
            error.clear();
            return lessonAnswers(html, &error);
        };
        auto a = parse("<span class=\"answer\" data-key=\"x\" data-tol=\"0.02\">&minus;1.5</span>");
        QVERIFY(!error.isEmpty());  // an entity is not a number
        a = parse(QStringLiteral("<span class=\"answer\" data-key=\"x\" data-tol=\"0.02\">\u22121.5</span>"));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(a.value("x").value, -1.5);
        QCOMPARE(a.value("x").relativeTolerance, 0.02);
        parse("<span class=\"answer\" data-key=\"x\" data-tol=\"0.02\">1</span>"
              "<span class=\"answer\" data-key=\"x\" data-tol=\"0.02\">2</span>");
        QVERIFY(error.contains("twice"));
        parse("<span class=\"answer\" data-key=\"x\" data-tol=\"0\">1</span>");
        QVERIFY(error.contains("tolerance"));
        parse("<span class=\"answer\" data-key=\"x\" data-tol=\"0.5\">1</span>");
        QVERIFY(error.contains("tolerance"));
        QCOMPARE(lessonSections("<h3>Goal</h3><p>x</p><h3 id=a>Why</h3>"), (QStringList{"Goal", "Why"}));
    }

    void everyAnswerIsMeasured() {
        // The table below and the texts name the same answers: a new answer needs a measurement.
        const auto table = measurements();
        QStringList ids;
        for (const Lesson& l : lessons()) {
            ids << l.id;
            QVERIFY2(table.contains(l.id), qPrintable(l.id));
            QStringList stated = lessonAnswers(l.html()).keys();
            QStringList measured = table.value(l.id).keys();
            stated.sort();
            measured.sort();
            QCOMPARE(stated, measured);
        }
        QStringList tableIds = table.keys();
        tableIds.sort();
        ids.sort();
        QCOMPARE(tableIds, ids);
    }

    void measuredAnswersHold_data() {
        QTest::addColumn<QString>("id");
        QTest::addColumn<QString>("key");
        for (const Lesson& l : lessons())
            for (const QString& key : lessonAnswers(l.html()).keys())
                QTest::newRow(qPrintable(l.id + "/" + key)) << l.id << key;
    }

    void measuredAnswersHold() {
        QFETCH(QString, id);
        QFETCH(QString, key);
        const LessonAnswer stated = lessonAnswers(lesson(id).html()).value(key);
        const Measure measure = measurements().value(id).value(key);
        QVERIFY(measure);
        const double measured = measure();
        QVERIFY2(std::isfinite(measured), qPrintable(QString::number(measured)));
        const double off = std::abs(measured - stated.value) / std::abs(stated.value);
        QVERIFY2(off <= stated.relativeTolerance,
                 qPrintable(QStringLiteral("%1/%2: the text says %3, measured %4 (%5 % off, tolerance %6 %)")
                                .arg(id, key)
                                .arg(stated.value)
                                .arg(measured, 0, 'g', 6)
                                .arg(100 * off, 0, 'g', 3)
                                .arg(100 * stated.relativeTolerance)));
    }

    void theCommandsInTheTextsAreAccepted() {
        // Each elastic-lab-cli line of a lesson runs: 0, or 3 where the lesson shows a run
        // failing; never 2 (an option renamed or a value refused).
        QTemporaryDir dir;
        for (const Lesson& l : lessons()) {
            static const QRegularExpression pre("<pre>(.*?)</pre>", QRegularExpression::DotMatchesEverythingOption);
            for (auto it = pre.globalMatch(l.html()); it.hasNext();) {
                for (const QString& line : it.next().captured(1).split('\n')) {
                    if (!line.startsWith("elastic-lab-cli ")) continue;
                    QStringList args = line.mid(int(strlen("elastic-lab-cli "))).split(' ', Qt::SkipEmptyParts);
                    args << "--quiet";
                    if (args.front() == "restitution") args.removeLast();  // it has no --quiet
                    QProcess p;
                    p.setWorkingDirectory(dir.path());
                    p.start(ELASTIC_LAB_CLI, args);
                    QVERIFY(testsupport::waitForExit(p));
                    QVERIFY2(p.exitStatus() == QProcess::NormalExit && (p.exitCode() == 0 || p.exitCode() == 3),
                             qPrintable(l.id + ": " + line + " -> " + QString::number(p.exitCode()) + " " +
                                        QString::fromUtf8(p.readAllStandardError())));
                }
            }
        }
    }

    void commandLineLessons() {
        // `elastic-lab --lesson ID`: a bad id is refused by the --preset rules (exit 2, one
        // line), naming the lessons.
        auto gui = [](const QStringList& args, QString* err) {
            QProcess p;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert("QT_QPA_PLATFORM", "offscreen");
            p.setProcessEnvironment(env);
            p.start(ELASTIC_LAB_GUI, args);
            if (!testsupport::waitForExit(p)) return -1;
            *err = QString::fromUtf8(p.readAllStandardError());
            return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
        };
        QString err;
        QCOMPARE(gui({"--lesson", "no-such-lesson"}, &err), 2);
        QVERIFY2(err.contains("unknown lesson") && err.contains(lessonIds().join(", ")), qPrintable(err));
        QCOMPARE(gui({"--lesson", lessonIds().front(), "--preset", "ring2d"}, &err), 2);
        QVERIFY2(err.contains("--preset"), qPrintable(err));
        QCOMPARE(gui({"--lesson", "a", "--lesson", "b"}, &err), 2);
        QCOMPARE(gui({"--help"}, &err), 0);
        // A good id starts the lesson's scene: --measure-fps prints the body's particle count.
        // Not under TSan: the shown window's image work runs in Qt's own pool threads, whose
        // uninstrumented handovers TSan reports (exit 66), as in test_gui_plots.
#ifndef __SANITIZE_THREAD__
        {
            const Lesson& l = lesson("refine-sphere");
            QProcess p;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert("QT_QPA_PLATFORM", "offscreen");
            p.setProcessEnvironment(env);
            p.start(ELASTIC_LAB_GUI, {"--lesson", l.id, "--measure-fps", "1"});
            QVERIFY(testsupport::waitForExit(p));
            QCOMPARE(p.exitCode(), 0);
            const QString out = QString::fromUtf8(p.readAllStandardOutput());
            const Simulation sim(l.preset.parameters(), "rk4");
            QVERIFY2(out.startsWith(QStringLiteral("particles %1,").arg(sim.topology().particleCount())), qPrintable(out));
        }
#endif
    }

    void presetsReachTheWindow() {
        MainWindow window(false);
        for (const Lesson& l : lessons()) {
            window.applyLesson(l);
            QVERIFY2(waitForLesson(window, l), qPrintable(l.id));
            const FramePtr f = window.controller()->latest();
            for (std::size_t i = 0; i < f->lanes.size(); ++i)
                QCOMPARE(f->lanes[i].integrator, l.preset.integrators.at(int(i)));
            QCOMPARE(window.controller()->integrators(), l.preset.integrators);
            for (const auto& [id, value] : l.preset.values) QCOMPARE(f->parameters.get(id), value);
            for (const QString& dock : l.docks)
                QVERIFY2(window.dock(dock) && !window.dock(dock)->isHidden(), qPrintable(l.id + ": " + dock));
            QVERIFY(window.currentFile().isEmpty());
        }
    }

    void theDialogSetsUpTheChosenLesson() {
#if defined(__SANITIZE_THREAD__)
        // A shown window makes Qt Gui convert its backing image on Qt's own pool threads, ordered
        // where ThreadSanitizer cannot see (as in test_gui_plots): checked in Release and ASan.
        QSKIP("Qt's threaded image conversion is invisible to ThreadSanitizer");
#endif
        MainWindow window(false);
        // Help > Experiments is in the Help menu.
        QAction* action = nullptr;
        for (QAction* menu : window.menuBar()->actions())
            if (menu->menu() && menu->text().contains("Help"))
                for (QAction* a : menu->menu()->actions())
                    if (a->text().contains("Experiments")) action = a;
        QVERIFY(action);
        action->trigger();
        LessonsDialog* dialog = window.findChild<LessonsDialog*>();
        QVERIFY(dialog && dialog->isVisible());
        QCOMPARE(window.showLessons(), dialog);  // one dialog, raised again
        QCOMPARE(dialog->currentId(), lessons().front().id);
        for (const Lesson& l : lessons()) {
            dialog->selectLesson(l.id);
            QCOMPARE(dialog->currentId(), l.id);
            QVERIFY(dialog->browser()->toPlainText().contains("The measured answer"));
            QVERIFY(dialog->browser()->toPlainText().contains(l.title));
            // Links to docs/ point into the source tree, to files that exist.
            const QString html = LessonsDialog::displayHtml(l);
            QVERIFY(!html.contains("href=\"docs/"));
            static const QRegularExpression href("href=\"(file://[^\"]+)\"");
            for (auto it = href.globalMatch(html); it.hasNext();) {
                const QString path = QUrl(it.next().captured(1)).toLocalFile();
                QVERIFY2(QFileInfo::exists(path), qPrintable(l.id + ": " + path));
            }
        }
        // "Set up this experiment" applies the selected one.
        const Lesson& chosen = lesson("stiff-springs");
        dialog->selectLesson(chosen.id);
        dialog->setUpButton()->click();
        QVERIFY(waitForLesson(window, chosen));
        QCOMPARE(window.controller()->integrators(), chosen.preset.integrators);
        for (const QString& id : {QStringLiteral("energy-drift"), QStringLiteral("pv-isotherm")}) {
            dialog->selectLesson(id);
            dialog->setUpButton()->click();
            QVERIFY(waitForLesson(window, lesson(id)));
            QVERIFY(!lesson(id).docks.isEmpty());
            for (const QString& dock : lesson(id).docks) QVERIFY2(!window.dock(dock)->isHidden(), qPrintable(dock));
        }
    }
};

QTEST_MAIN(TestLessons)
#include "test_lessons.moc"
