// Scene files: save -> load gives the identical state and trajectory; bad files are refused
// with a message naming the key (and the line for syntax errors).
#include <QtTest>

#include <QProcess>
#include <QTemporaryDir>

#include "scenefile.h"
#include "simulation.h"
#include "test_support.h"

using namespace simcore;

namespace {

QString runCli(const QStringList& args, int* code) {
    QProcess p;
    p.start(ELASTIC_LAB_CLI, args);
    testsupport::waitForExit(p);
    *code = p.exitCode();
    return QString::fromUtf8(p.readAllStandardError());
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

std::string withLine(const std::string& text, const std::string& from, const std::string& to) {
    std::string out = text;
    const auto at = out.find(from);
    if (at == std::string::npos) qFatal("fixture text not found: %s", from.c_str());
    return out.replace(at, from.size(), to);
}

}  // namespace

class TestSceneFile : public QObject {
    Q_OBJECT
private slots:
    void roundTripIsExact_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("integrator");
        QTest::newRow("spring1d euler") << "spring1d" << "euler";
        QTest::newRow("ring2d rk4") << "ring2d" << "rk4";
        QTest::newRow("sphere3d verlet") << "sphere3d" << "verlet";
        QTest::newRow("latlong midpoint") << "sphere3d-latlong" << "midpoint";
        QTest::newRow("ring2d rk45 (next step saved)") << "ring2d" << "rk45";
    }
    void roundTripIsExact() {
        QFETCH(QString, scene);
        QFETCH(QString, integrator);
        ParameterSet p(findScene(scene.toStdString())->kind);
        p.set("ks", 900.5);
        p.set("perturb", 0.01);
        p.set("restitution", 0.3);
        Simulation original(p, integrator.toStdString());
        QVERIFY(original.advanceTo(0.5));
        const std::string text = sceneFileText(original, scene.toStdString(), true);

        const SceneFileResult read = parseSceneFile(text);
        QVERIFY2(read.file, read.error.c_str());
        QCOMPARE(read.file->sceneName, scene.toStdString());
        QCOMPARE(read.file->integrator, integrator.toStdString());
        for (const ParamSpec* spec : parametersFor(p.kind()))
            QCOMPARE(read.file->params.get(spec->key), p.get(spec->key));
        Simulation resumed(read.file->params, read.file->integrator);
        QVERIFY(!applyState(resumed, *read.file->state));
        QCOMPARE(resumed.state().head(6 * resumed.particleCount()), original.state().head(6 * original.particleCount()));
        QCOMPARE(resumed.time(), original.time());
        QCOMPARE(resumed.stepCount(), original.stepCount());
        for (int i = 0; i < 300; ++i) {
            QVERIFY(original.step());
            QVERIFY(resumed.step());
        }
        // Identical trajectory, bit for bit.
        QVERIFY(resumed.state().head(6 * resumed.particleCount()) == original.state().head(6 * original.particleCount()));
        // And the text of the reloaded scene is the text that was saved.
        Simulation reread(read.file->params, read.file->integrator);
        applyState(reread, *read.file->state);
        QCOMPARE(sceneFileText(reread, scene.toStdString(), true), text);
    }
    void refusesBadFiles_data() {
        QTest::addColumn<QString>("from");
        QTest::addColumn<QString>("to");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("unknown top key") << "\"integrator\"" << "\"integrater\"" << "integrater";
        QTest::newRow("unknown parameter") << "\"ks\":" << "\"kss\":" << "kss";
        QTest::newRow("key of another scene") << "\"ks\":" << "\"subdivisions\":" << "subdivisions";
        QTest::newRow("wrong type") << "\"kd\": 15" << "\"kd\": \"15\"" << "kd";
        QTest::newRow("out of range") << "\"restitution\": 0.5" << "\"restitution\": 2" << "restitution";
        QTest::newRow("zero mass") << "\"mass\": 1" << "\"mass\": 0" << "mass";
        QTest::newRow("newer version") << QString("\"version\": %1").arg(kSceneFormatVersion) << "\"version\": 99"
                                       << "newer";
        QTest::newRow("next step not positive") << "\"step\":" << "\"next_step\": 0, \"step\":" << "next_step";
        QTest::newRow("unknown scene") << "\"ring2d\"" << "\"torus\"" << "torus";
        QTest::newRow("unknown integrator") << "\"rk4\"" << "\"rk7\"" << "rk7";
        QTest::newRow("syntax error names the line") << "\"kd\": 15," << "\"kd\": 15,," << "line 8";
        QTest::newRow("nan is not JSON") << "\"kd\": 15" << "\"kd\": NaN" << "line 8";
        QTest::newRow("state of wrong size") << "\"positions\": [[" << "\"positions\": [[0, 0, 0], [" << "positions";
        QTest::newRow("unknown state key") << "\"time\":" << "\"clock\":" << "clock";
        QTest::newRow("crossed radii") << "\"radius_inner\": 1.5" << "\"radius_inner\": 2.5" << "radius_inner (2.5 m) must be below";
    }
    void refusesBadFiles() {
        QFETCH(QString, from);
        QFETCH(QString, to);
        QFETCH(QString, mentions);
        Simulation sim(ParameterSet(SceneKind::Ring2d), "rk4");
        const std::string good = sceneFileText(sim, "ring2d", true);
        QVERIFY(parseSceneFile(good).file);
        const SceneFileResult read = parseSceneFile(withLine(good, from.toStdString(), to.toStdString()));
        QVERIFY(!read.file);
        QVERIFY2(QString::fromStdString(read.error).contains(mentions), read.error.c_str());
    }
    void olderMinimalFileLoads() {
        // Version 1 with only what is required: every parameter takes its default.
        const SceneFileResult read = parseSceneFile(R"({"format": "elastic-lab-scene", "version": 1, "scene": "sphere3d"})");
        QVERIFY2(read.file, read.error.c_str());
        QCOMPARE(read.file->params.get("ks"), 800.0);
        QCOMPARE(read.file->integrator, std::string("rk4"));
        QVERIFY(!read.file->state);
    }
    void cliSavesAndResumes() {
        // 0.6 s in one run equals 0.3 s, saved, then 0.3 s more from the file.
        QTemporaryDir dir;
        const QString scene = dir.filePath("half.json"), whole = dir.filePath("whole.csv"),
                      resumed = dir.filePath("resumed.csv");
        int code = -1;
        runCli({"run", "--scene", "ring2d", "--set", "perturb=0.01", "--duration", "0.6", "--state", whole}, &code);
        QCOMPARE(code, 0);
        runCli({"run", "--scene", "ring2d", "--set", "perturb=0.01", "--duration", "0.3", "--save-scene", scene}, &code);
        QCOMPARE(code, 0);
        QString err = runCli({"run", "--scene", scene, "--duration", "0.3", "--state", resumed}, &code);
        QVERIFY2(code == 0, qPrintable(err));
        QCOMPARE(readAll(resumed), readAll(whole));
        err = runCli({"run", "--scene", dir.filePath("missing.json")}, &code);
        QCOMPARE(code, 2);
        QVERIFY(err.contains("missing.json"));
    }
};

QTEST_GUILESS_MAIN(TestSceneFile)
#include "test_scenefile.moc"
