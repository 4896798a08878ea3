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
#include <QMenu>
#include <QTableWidget>
#include <QToolButton>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTextDocument>

#include "simcore/integrator_table.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/stability.h"
#include "simlab/conservation.h"
#include "test_support.h"
#include "ui/energy_bars_dock.h"
#include "ui/help_dialog.h"
#include "ui/lesson_dock.h"
#include "ui/lesson_measures.h"
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

// Every stated answer, by lesson and key, measured on the lesson's own preset by the table the
// Lesson dock's "Measure" uses (ui/lesson_measures.h).
QMap<QString, QMap<QString, std::function<double()>>> measurements() {
    QMap<QString, QMap<QString, std::function<double()>>> m;
    for (const Lesson& l : lessons()) {
        const ParameterSet p = l.preset.parameters();
        const auto table = lessonMeasures(l.id);
        for (auto it = table.begin(); it != table.end(); ++it) m[l.id][it.key()] = [p, f = it.value()] { return f(p); };
    }
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
            if (l.preset.world()) {  // a scene of several bodies: its --set, checked
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

    void textValuesAgreeWithThePreset() {
        // Every value "What to do" names is marked; a setting is what the preset sets, every
        // value the preset sets is named, a value to try passes the parameter table, and the
        // lesson says until when to run.
        static const QRegularExpression marked("<span class=\"(?:setting|try|until)\"[^>]*>[^<]*</span>");
        static const QRegularExpression bare("(=|\\bto)\\s*(<[^>]+>\\s*)*[0-9]");
        for (const Lesson& l : lessons()) {
            const QString html = l.html();
            const ParameterSet preset = l.preset.parameters();
            QStringList named;
            for (const LessonValue& v : lessonValues(html)) {
                QVERIFY2(v.valid, qPrintable(l.id + ": " + v.key + " is not a number"));
                const simcore::ParamSpec* spec = simcore::findParam(v.key.toStdString());
                QVERIFY2(spec && preset.has(spec->id), qPrintable(l.id + ": unknown key " + v.key));
                if (v.kind == "setting") {
                    QVERIFY2(qFuzzyCompare(preset.get(spec->id), v.value),
                             qPrintable(QStringLiteral("%1: the text says %2 = %3, the preset sets %4")
                                            .arg(l.id, v.key).arg(v.value).arg(preset.get(spec->id))));
                    named << v.key;
                } else {
                    const auto error = simcore::validateValue(*spec, v.value);
                    QVERIFY2(!error, qPrintable(l.id + ": " + QString::fromStdString(error.value_or(""))));
                    QVERIFY2(preset.get(spec->id) != v.value, qPrintable(l.id + ": try " + v.key + " is the preset's"));
                }
            }
            for (const auto& [id, value] : l.preset.values) {
                const QString key = QString::fromUtf8(simcore::paramSpec(id).key.data(), qsizetype(simcore::paramSpec(id).key.size()));
                QVERIFY2(named.contains(key), qPrintable(l.id + ": the preset sets " + key + ", the text does not say"));
            }
            QString todo = lessonSection(html, "What to do");
            QVERIFY(!todo.isEmpty());
            todo.replace(marked, "#");
            const QRegularExpressionMatch left = bare.match(todo);
            QVERIFY2(!left.hasMatch(), qPrintable(l.id + ": an unmarked value: " + todo.mid(left.capturedStart(), 40)));
            const QList<double> until = lessonUntil(html);
            QVERIFY2(!until.isEmpty(), qPrintable(l.id + ": no <span class=\"until\">"));
            for (double t : until) QVERIFY2(t > 0.0 && t <= 10.0, qPrintable(l.id));
        }
        // The checks can fail: a setting off the preset, an unmarked value.
        const QString planted = "<h3>What to do</h3><p>DT = <span class=\"setting\" data-key=\"dt\">0.01</span>, "
                                "then set ks to 5</p><h3>What to look at</h3>";
        QCOMPARE(lessonValues(planted).size(), 1);
        QCOMPARE(lessonValues(planted).front().value, 0.01);
        QVERIFY(bare.match(lessonSection(planted, "What to do").replace(marked, "#")).hasMatch());
    }

    void refineSphereBehavesAsItsTextSays() {
        // Step 1 and 2 run the lesson's time at its DT without a warning or a failure; at three
        // subdivisions the pre-run check warns, the run at the lesson's DT blows up, and the
        // suggested DT runs.
        const Lesson& l = lesson("refine-sphere");
        const ParameterSet p = l.preset.parameters();
        const double until = lessonUntil(l.html()).front();
        for (int level : {1, 2}) {
            const ParameterSet q = with(p, {{"subdivisions", double(level)}});
            QVERIFY2(!simlab::stabilityAdvice(Simulation(q, "rk4")), qPrintable(QString::number(level)));
            QCOMPARE(lessonFailureTime(q, "rk4", until), -1.0);
        }
        const ParameterSet fine = with(p, {{"subdivisions", 3}});
        const auto advice = simlab::stabilityAdvice(Simulation(fine, "rk4"));
        QVERIFY(advice);
        QVERIFY(lessonFailureTime(fine, "rk4", 1.0) > 0.0);
        QCOMPARE(lessonFailureTime(with(fine, {{"dt", advice->suggestedDt}}), "rk4", 0.3), -1.0);
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
        const auto measure = measurements().value(id).value(key);
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

    void helpFiguresAreMeasured() {
        // Help states the limits and the order the app measures, with the code that measures
        // them: a figure in Help that the measurement no longer gives fails here.
        QString error;
        const auto stated = lessonAnswers(HelpDialog::html(), &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const auto table = helpMeasures();
        QCOMPARE(stated.keys(), table.keys());
        const ParameterSet ring(simcore::SceneKind::Ring2d);
        for (auto it = stated.begin(); it != stated.end(); ++it) {
            const double measured = table.value(it.key())(ring);
            const double off = std::abs(measured - it->value) / std::abs(it->value);
            QVERIFY2(off <= it->relativeTolerance, qPrintable(QStringLiteral("Help says %1 = %2, measured %3")
                                                                  .arg(it.key()).arg(it->value).arg(measured)));
        }
        // Damped Verlet is not called second order without the damped figure beside it.
        QVERIFY(HelpDialog::html().contains("2 (1 damped)"));
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

    void lessonsHaveTheirOwnMenu() {
        MainWindow window(false);
        QMenu* menu = window.lessonsMenu();
        QVERIFY(menu);
        QVERIFY(window.menuBar()->actions().contains(menu->menuAction()));
        QCOMPARE(menu->menuAction()->text(), QString("&Lessons"));
        QStringList titles;
        for (QAction* a : menu->actions())
            if (!a->isSeparator()) titles << a->text();
        for (const Lesson& l : lessons()) QVERIFY2(titles.contains(l.title), qPrintable(l.title));
        QVERIFY(titles.last().contains("Experiments"));  // the texts
        for (QAction* a : menu->actions())
            if (a->text() == lesson("pv-isotherm").title) a->trigger();
        QVERIFY(waitForLesson(window, lesson("pv-isotherm")));
        QVERIFY(!window.lessonDock()->isHidden());
        QCOMPARE(window.lessonDock()->lessonId(), QString("pv-isotherm"));
        QCOMPARE(window.lessonDock()->untilTime(), lessonUntil(lesson("pv-isotherm").html()).front());
        QCOMPARE(window.lessonDock()->answerTable()->rowCount(), int(lessonAnswers(lesson("pv-isotherm").html()).size()));
    }

    void theLessonDockReadsTheAnswersOffTheRun_data() {
        QTest::addColumn<QString>("id");
        for (const char* id : {"energy-drift", "heavy-inner", "pv-isotherm", "restitution"}) QTest::newRow(id) << QString(id);
    }

    void theLessonDockReadsTheAnswersOffTheRun() {
        // "Run until t = ..." with the lesson's time, a stopwatch over the run, and every answer
        // the run shows read off it: within the text's tolerance of what the text expects.
        QFETCH(QString, id);
        const Lesson& l = lesson(id);
        MainWindow window(false);
        window.applyLesson(l);
        QVERIFY(waitForLesson(window, l));
        LessonDock* dock = window.lessonDock();
        QCOMPARE(dock->lessonId(), id);
        dock->stopwatchButton()->click();  // start at t = 0
        QVERIFY(dock->stopwatchRunning());
        const double until = dock->untilTime();
        auto runUntil = [&] {
            dock->runUntilButton()->click();
            return testsupport::waitUntil([&] {
                const FramePtr f = window.controller()->latest();
                return f && !window.controller()->running() &&
                       (f->lanes[0].diagnostics.time >= until - 1e-9 || f->lanes[0].failure);
            });
        };
        QVERIFY(runUntil());
        // The answers the run shows; restitution's second (e = 0.2) after the lesson's second
        // step: the value to try typed, Reset, run again.
        QStringList fromRun;
        for (const QString& key : lessonAnswers(l.html()).keys())
            if (dock->readFromRun(key)) fromRun << key;
        QVERIFY2(!fromRun.isEmpty(), qPrintable(id));
        const auto filled = [&](const QStringList& keys) {
            return testsupport::waitUntil([&] {
                for (const QString& key : keys)
                    if (!std::isfinite(dock->got(key))) return false;
                return true;
            });
        };
        // The lesson's second step: the value to try typed, Reset, run again; the first run's
        // figure stays beside the second's.
        const auto secondStep = [&](simcore::Param param, double value) {
            dock->stopwatchButton()->click();  // stop
            dock->stopwatchButton()->click();  // and on again over the second run
            window.controller()->setParameter(param, value);
            window.controller()->reset();
            return testsupport::waitUntil([&] {
                const FramePtr f = window.controller()->latest();
                return f && f->parameters.get(param) == value && f->lanes[0].diagnostics.time == 0.0;
            }) && runUntil();
        };
        double firstTime = -1.0;
        if (id == "restitution") {
            QVERIFY(filled({"liftoff-e0.9"}));
            QVERIFY(!std::isfinite(dock->got("liftoff-e0.2")));
            firstTime = window.controller()->latest()->lanes[0].diagnostics.time;
            QVERIFY(secondStep(simcore::Param::Restitution, 0.2));
        } else if (id == "heavy-inner") {
            QVERIFY(filled({"sag"}));
            QVERIFY(!std::isfinite(dock->got("collapse-time")));
            firstTime = window.controller()->latest()->lanes[0].diagnostics.time;
            QVERIFY(secondStep(simcore::Param::MassInner, 10.0));
        }
        QVERIFY(filled(fromRun));
        const auto stated = lessonAnswers(l.html());
        for (const QString& key : fromRun) {
            const double off = std::abs(dock->got(key) - stated.value(key).value) / std::abs(stated.value(key).value);
            QVERIFY2(dock->gotFromRun(key) && off <= stated.value(key).relativeTolerance,
                     qPrintable(QStringLiteral("%1/%2: expected %3, the run gave %4")
                                    .arg(id, key).arg(stated.value(key).value).arg(dock->got(key))));
        }
        // The table says it too.
        QString table;
        for (int r = 0; r < dock->answerTable()->rowCount(); ++r)
            for (int c = 0; c < 3; ++c) table += dock->answerTable()->item(r, c)->text() + " | ";
        for (const QString& key : fromRun) QVERIFY2(table.contains(QString::number(dock->got(key), 'g', 4)), qPrintable(table));
        // The stopwatch ran with the simulated clock (over both runs for a second step: the
        // reading held at the reset, plus the second run): stopped now, it reads that time.
        dock->stopwatchButton()->click();
        const double t = window.controller()->latest()->lanes[0].diagnostics.time;
        const double expected = firstTime > 0 ? firstTime + t : t;
        QVERIFY2(std::abs(dock->stopwatch() - expected) < 1e-9,
                 qPrintable(QString("%1 vs %2").arg(dock->stopwatch()).arg(expected)));
        QVERIFY(!dock->stopwatchRunning());
    }

    void measureFillsTheScanFigures() {
        // What the run cannot show (the stability scan's limit) is measured on the parameters in
        // use by "Measure", on a worker thread, with the same code as the test's re-measurement.
        const Lesson& l = lesson("euler-limit");
        MainWindow window(false);
        window.applyLesson(l);
        QVERIFY(waitForLesson(window, l));
        LessonDock* dock = window.lessonDock();
        QVERIFY(!dock->readFromRun("dt-stable"));
        QVERIFY(dock->readFromRun("blowup-time"));
        QVERIFY(!std::isfinite(dock->got("dt-stable")));
        dock->measureButton()->click();
        QVERIFY(testsupport::waitUntil([&] { return std::isfinite(dock->got("dt-stable")) && !dock->measuring(); }));
        QVERIFY(!dock->gotFromRun("dt-stable"));
        const auto stated = lessonAnswers(l.html());
        for (const QString& key : {QStringLiteral("dt-stable"), QStringLiteral("dt-predicted")})
            QVERIFY2(std::abs(dock->got(key) - stated.value(key).value) <= stated.value(key).relativeTolerance * stated.value(key).value,
                     qPrintable(key + ": " + QString::number(dock->got(key))));
        QVERIFY(dock->measureButton()->isEnabled());
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
