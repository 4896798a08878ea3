// The GUI's command line (app/gui/command_line.h, issue 31): every rule main() applies before a
// window exists, checked on the code main() runs (elastic_lab_gui_start), without starting a
// process or a window. Each refusal is a simlab::RequestError with the text main() prints after
// "elastic-lab: " (test_front_door and test_gui_render check the same through the program).
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include "app/gui/command_line.h"
#include "ui/lessons.h"
#include "ui/presets.h"

using elgui::GuiCommandLine;
using elgui::GuiRequest;
using elgui::ShowSwitch;

namespace {

// The request for these arguments, or the refusal's text in `error`.
std::optional<GuiRequest> requestFor(const QStringList& args, QString* error) {
    try {
        GuiCommandLine commandLine;
        commandLine.parse(QStringList{QStringLiteral("elastic-lab")} + args);
        return commandLine.request();
    } catch (const simlab::RequestError& e) {
        *error = QString::fromStdString(e.what());
        return std::nullopt;
    }
}

}  // namespace

class TestGuiCommandLine : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        QFile scene(m_dir.filePath("ring.json"));
        QVERIFY(scene.open(QIODevice::WriteOnly));
        scene.write(R"({"format": "elastic-lab-scene", "version": 3, "scene": "ring2d", "integrator": "verlet",
                        "parameters": {"ks": 900}})");
    }

    void refusals_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QString scene = m_dir.filePath("ring.json");
        const QString shot = m_dir.filePath("shot.png");
        QTest::newRow("unknown option") << QStringList{"--bogus"} << "Unknown option 'bogus'.";
        QTest::newRow("two files") << QStringList{scene, scene} << "unexpected argument";
        QTest::newRow("file and --scene") << QStringList{scene, "--scene", "ring2d"} << "and --scene both choose the scene; give one";
        QTest::newRow("twice") << QStringList{"--integrator", "rk4", "--integrator", "euler"} << "--integrator is given 2 times; give it once";
        QTest::newRow("after alone") << QStringList{"--after", "1"} << "--after needs --screenshot";
        QTest::newRow("lang") << QStringList{"--lang", "xx"} << "--lang 'xx' is not one of";
        QTest::newRow("preset") << QStringList{"--preset", "nope"} << "unknown preset 'nope'";
        QTest::newRow("lesson and preset") << QStringList{"--lesson", elui::lessonIds().front(), "--preset", "liquid"}
                                           << "--lesson and --preset both choose the start; give one";
        QTest::newRow("lesson") << QStringList{"--lesson", "nope"} << "unknown lesson 'nope'; allowed:";
        QTest::newRow("scene") << QStringList{"--scene", "torus"} << "unknown scene 'torus'";
        QTest::newRow("set twice") << QStringList{"--set", "ks=800", "--set", "ks=900"} << "given twice";
        QTest::newRow("integrator") << QStringList{"--integrator", "rk5"} << "unknown integrator 'rk5'";
        QTest::newRow("compare empty item") << QStringList{"--compare", "rk4,,euler"} << "compare";
        QTest::newRow("compare repeat") << QStringList{"--compare", "rk4,rk4"} << "listed twice";
        QTest::newRow("compare four") << QStringList{"--compare", "rk4,euler,verlet,midpoint"} << "--compare takes one to three integrators, got 4";
        // A world side by side: each lane by the front door (simlab::checkLanes of the world):
        // xpbd's one set of springs for the whole world, and the lane count.
        QTest::newRow("world compare xpbd")
            << QStringList{"--scene", "collide2d", "--set", "body2.ks=500", "--compare", "rk4,xpbd"}
            << "xpbd takes one stiffness and damping per spring family for the whole world, and body 2's springs differ";
        QTest::newRow("world compare four") << QStringList{"--scene", "collide2d", "--compare", "rk4,euler,verlet,midpoint"}
                                            << "--compare takes one to three integrators, got 4";
        QTest::newRow("dock") << QStringList{"--docks", "timeline,nope"} << "unknown dock 'nope'; allowed:";
        QTest::newRow("after nan") << QStringList{"--screenshot", shot, "--after", "nan"} << "--after needs a finite time in seconds, 0 to 1e6";
        QTest::newRow("after big") << QStringList{"--screenshot", shot, "--after", "2e6"} << "--after needs a finite time";
        QTest::newRow("travel no shot") << QStringList{"--travel-back", "1"} << "--travel-back needs --screenshot";
        QTest::newRow("travel past") << QStringList{"--screenshot", shot, "--after", "1", "--travel-back", "2"}
                                     << "--travel-back needs a time in seconds above 0 and at most --after";
        QTest::newRow("branch alone") << QStringList{"--branch", "ks=1000"} << "--branch needs --travel-back";
        QTest::newRow("branch integrator")
            << QStringList{"--screenshot", shot, "--after", "1", "--travel-back", "0.5", "--branch", "integrator=rk5"}
            << "--branch unknown integrator 'rk5'";
        QTest::newRow("branch shape")
            << QStringList{"--screenshot", shot, "--after", "1", "--travel-back", "0.5", "--branch", "particles=30"}
            << "--branch 'particles' rebuilds the body";
        QTest::newRow("branch range")
            << QStringList{"--screenshot", shot, "--after", "1", "--travel-back", "0.5", "--branch", "ks=-1"} << "--branch ks = -1 is out of range";
        QTest::newRow("shot over scene") << QStringList{"--scene", scene, "--screenshot", scene} << "--screenshot";
        QTest::newRow("shot empty") << QStringList{"--screenshot", ""} << "--screenshot";
        QTest::newRow("shot format") << QStringList{"--screenshot", m_dir.filePath("shot.xyz")} << "this build cannot write .xyz images";
        QTest::newRow("shot folder") << QStringList{"--screenshot", m_dir.filePath("missing/shot.png")} << "--screenshot ";
        QTest::newRow("select") << QStringList{"--select", "-1"} << "--select needs a particle index, 0 or more";
        QTest::newRow("ui scale") << QStringList{"--ui-scale", "3"} << "--ui-scale needs a factor from 1 to 2";
        QTest::newRow("fps") << QStringList{"--measure-fps", "0.5"} << "--measure-fps needs a wall time in seconds, 1 to 3600";
        QTest::newRow("show") << QStringList{"--show", "strain,sparkles"} << "unknown --show switch 'sparkles'";
        QTest::newRow("show repeat") << QStringList{"--show", "strain,strain"} << "listed twice";
        QTest::newRow("echo quoted") << QStringList{"--preset", QString(300, 'x') + "\x1b]0;title\x07"} << "(310 bytes)";
    }
    void refusals() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        QString error;
        QVERIFY2(!requestFor(args, &error), qPrintable(args.join(' ')));
        QVERIFY2(error.contains(message), qPrintable(error));
        QVERIFY2(!error.contains(QChar(0x1b)) && error.size() < 600, qPrintable(error));
        QVERIFY(!QFile::exists(m_dir.filePath("shot.png")));  // nothing written by a check
    }

    void aRequestCarriesEveryValue() {
        QString error;
        const QString shot = m_dir.filePath("shot.png");
        const auto r = requestFor({"--scene", "ring2d", "--set", "ks=800", "--compare", "euler,rk4", "--docks", "timeline",
                                   "--show", "strain,nobox,errorband", "--screenshot", shot, "--after", "2",
                                   "--travel-back", "0.5", "--branch", "ks=1200", "--select", "3", "--ui-scale", "1.5",
                                   "--step-doubling", "--high-contrast", "--experiments"},
                                  &error);
        QVERIFY2(r, qPrintable(error));
        QCOMPARE(r->setup.params.get(simcore::Param::Ks), 800.0);
        QCOMPARE(r->integrators, QStringList({"euler", "rk4"}));
        QCOMPARE(r->docks, QStringList({"timeline"}));
        QCOMPARE(r->show, QList<ShowSwitch>({ShowSwitch::Strain, ShowSwitch::NoBox, ShowSwitch::ErrorBand}));
        QCOMPARE(r->screenshot, shot);
        QCOMPARE(r->after, 2.0);
        QCOMPARE(r->travelBack, 0.5);
        QCOMPARE(r->branchKey, QString("ks"));
        QCOMPARE(r->branchValue, 1200.0);
        QCOMPARE(r->selected, 3);
        QCOMPARE(r->uiScale, 1.5);
        QVERIFY(r->stepDoubling && r->highContrast && r->experiments);
        QCOMPARE(r->fpsSeconds, 0.0);
        QVERIFY(!QFile::exists(shot));  // the probe writes nothing
    }

    // --compare takes a world (issue 26): the lanes' integrators with the world's spec.
    void aWorldSideBySide() {
        QString error;
        const auto r = requestFor({"--scene", "collide2d", "--set", "body2.mass=4", "--compare", "rk4,euler,xpbd"}, &error);
        QVERIFY2(r, qPrintable(error));
        QVERIFY(r->setup.world);
        QCOMPARE(r->setup.world->bodies.size(), std::size_t{2});
        QCOMPARE(r->setup.world->bodies[1].params.get(simcore::Param::Mass), 4.0);
        QCOMPARE(r->integrators, QStringList({"rk4", "euler", "xpbd"}));
    }

    void aSceneFileGivenAloneAndAPreset() {
        QString error;
        const auto file = requestFor({m_dir.filePath("ring.json"), "--set", "kd=2"}, &error);
        QVERIFY2(file, qPrintable(error));
        QVERIFY(file->setup.file);
        QCOMPARE(file->integrators, QStringList({"verlet"}));  // the file's integrator
        QCOMPARE(file->setup.params.get(simcore::Param::Ks), 900.0);
        QCOMPARE(file->setup.params.get(simcore::Param::Kd), 2.0);
        // A lesson: its preset's scene and integrators when no scene is given.
        const QString id = elui::lessonIds().front();
        const auto lesson = requestFor({"--lesson", id}, &error);
        QVERIFY2(lesson, qPrintable(error));
        QVERIFY(lesson->lesson && lesson->preset == &lesson->lesson->preset);
        if (!lesson->setup.world) QCOMPARE(lesson->integrators, lesson->preset->integrators);
        QCOMPARE(requestFor({"--measure-fps", "2"}, &error)->fpsSeconds, 2.0);
    }
};

QTEST_MAIN(TestGuiCommandLine)
#include "test_gui_command_line.moc"
