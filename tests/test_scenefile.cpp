// Scene files: save -> load gives the identical state and trajectory; bad files are refused
// with a message naming the key (and the line for syntax errors).
#include <QtTest>

#include <QProcess>
#include <QTemporaryDir>

#include <sys/stat.h>

#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simlab/scenefile.h"
#include "test_support.h"

using namespace simcore;
using namespace simlab;

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
        p.set(simcore::Param::Ks, 900.5);
        p.set(simcore::Param::Perturb, 0.01);
        p.set(simcore::Param::Restitution, 0.3);
        Simulation original(p, integrator.toStdString());
        QVERIFY(original.advanceTo(0.5));
        const std::string text = sceneFileText(original, scene.toStdString(), true);

        const SceneFileResult read = parseSceneFile(text);
        QVERIFY2(read.file, read.error.c_str());
        QCOMPARE(read.file->sceneName, scene.toStdString());
        QCOMPARE(read.file->integrator, integrator.toStdString());
        for (const ParamSpec* spec : parametersFor(p.kind()))
            QCOMPARE(read.file->params.get(spec->id), p.get(spec->id));
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
    // Scenes of several bodies (version 4): each body's kind, start and parameters and the
    // world's exact state come back, and the run goes on bit for bit.
    void worldRoundTripIsExact_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("integrator");
        QTest::newRow("collide2d rk4") << "collide2d" << "rk4";
        QTest::newRow("collide2d rk45 (next step saved)") << "collide2d" << "rk45";
        QTest::newRow("collide3d verlet") << "collide3d" << "verlet";
    }
    void worldRoundTripIsExact() {
        QFETCH(QString, scene);
        QFETCH(QString, integrator);
        WorldSpec spec = *worldScene(scene.toStdString());
        for (const char* assignment : {"gravity=0", "body2.mass=4", "body1.ks=900.5", "offset=0.3", "body2.velocity_y=0.25"})
            QVERIFY(!assignWorld(spec, assignment));
        if (scene == "collide3d") QVERIFY(!assignWorld(spec, "subdivisions=1"));
        World original(spec, integrator.toStdString());
        QVERIFY(original.advanceTo(0.05));
        const std::string text = sceneFileText(original, true);

        const SceneFileResult read = parseSceneFile(text);
        QVERIFY2(read.file, read.error.c_str());
        QVERIFY(read.file->world);
        QCOMPARE(read.file->sceneName, scene.toStdString());
        QCOMPARE(read.file->integrator, integrator.toStdString());
        const WorldSpec& back = *read.file->world;
        QCOMPARE(back.bodies.size(), spec.bodies.size());
        for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
            QCOMPARE(back.bodies[k].params.kind(), spec.bodies[k].params.kind());
            QVERIFY(back.bodies[k].position == spec.bodies[k].position);
            QVERIFY(back.bodies[k].velocity == spec.bodies[k].velocity);
            for (const ParamSpec* p : parametersFor(spec.bodies[k].params.kind()))
                QCOMPARE(back.bodies[k].params.get(p->id), spec.bodies[k].params.get(p->id));
        }
        World resumed(back, read.file->integrator);
        QVERIFY(!applyState(resumed, *read.file->state));
        const Eigen::Index n = 6 * original.particleCount();
        QVERIFY(resumed.state().head(n) == original.state().head(n));
        QCOMPARE(resumed.stepCount(), original.stepCount());
        QCOMPARE(resumed.time(), original.time());
        for (int i = 0; i < 40; ++i) {
            QVERIFY(original.step());
            QVERIFY(resumed.step());
        }
        QVERIFY(resumed.state().head(n) == original.state().head(n));  // bit for bit
        // The text of the reloaded world is the text saved; the as-read writer keeps the file's own.
        World reread(back, read.file->integrator);
        QVERIFY(!applyState(reread, *read.file->state));
        QCOMPARE(sceneFileText(reread, true), text);
        const SceneFileResult again = parseSceneFile(sceneFileText(*read.file));
        QVERIFY2(again.file && again.file->world, again.error.c_str());
        QVERIFY(again.file->state->positions == read.file->state->positions);
        QCOMPARE(again.file->world->bodies[1].params.get(Param::Mass), 4.0);
    }
    // A world scene's name alone loads it as built in; top-level values apply to every body.
    void worldByNameTakesCommonValues() {
        const SceneFileResult read = parseSceneFile(
            R"({"format": "elastic-lab-scene", "version": 4, "scene": "stack3d", "parameters": {"gravity": 5, "mass": 2}})");
        QVERIFY2(read.file && read.file->world, read.error.c_str());
        QCOMPARE(read.file->world->bodies.size(), std::size_t{3});
        for (const WorldBodySpec& b : read.file->world->bodies) {
            QCOMPARE(b.params.get(Param::Gravity), 5.0);
            QCOMPARE(b.params.get(Param::Mass), 2.0);
        }
    }
    void worldRefusals_data() {
        QTest::addColumn<QString>("from");
        QTest::addColumn<QString>("to");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("unknown kind") << "\"ring2d\", \"position\": [3" << "\"torus\", \"position\": [3"
                                      << "body2.kind: unknown body kind 'torus'";
        QTest::newRow("unknown body key") << "{\"mass\": 4}" << "{\"mas\": 4}" << "body2.'mas'";
        QTest::newRow("out of range") << "{\"mass\": 4}" << "{\"mass\": -1}" << "body2.mass";
        QTest::newRow("world key in a body") << "{\"mass\": 4}" << "{\"gravity\": 1}" << "body2.gravity: a world parameter";
        QTest::newRow("key in no body") << "\"gravity\": 0" << "\"gravity\": 0, \"subdivisions\": 2" << "subdivisions";
        QTest::newRow("unknown entry key") << "\"velocity\": [2" << "\"speed\": [2" << "in body1";
        QTest::newRow("overlap") << "[3, 0, 0]" << "[0.5, 0, 0]" << "bodies 1 and 2 overlap";
        QTest::newRow("outside the box") << "[3, 0, 0]" << "[9.5, 0, 0]" << "body2 sticks out of the box";
        QTest::newRow("3D among 2D") << "\"ring2d\", \"position\": [3" << "\"sphere3d\", \"position\": [3"
                                     << "body2: a 3D body in a 2D world";
        QTest::newRow("z of a 2D body") << "[-3, 0, 0]" << "[-3, 0, 1]" << "body1.position";
        QTest::newRow("bad vector") << "[-3, 0, 0]" << "[-3, 0]" << "body1.position: expected [x, y, z]";
        QTest::newRow("no bodies") << "\"bodies\": [{" << "\"bodies\": [], \"x\": [{" << "bodies";
        QTest::newRow("bodies before version 4") << "\"version\": 4" << "\"version\": 3" << "version 4";
        QTest::newRow("newer version") << "\"version\": 4" << "\"version\": 5" << "newer";
    }
    void worldRefusals() {
        QFETCH(QString, from);
        QFETCH(QString, to);
        QFETCH(QString, mentions);
        const std::string good = R"({"format": "elastic-lab-scene", "version": 4, "scene": "mine", "integrator": "rk4",
 "parameters": {"gravity": 0, "box": 10},
 "bodies": [{"kind": "ring2d", "position": [-3, 0, 0], "velocity": [2, 0, 0]},
            {"kind": "ring2d", "position": [3, 0, 0], "velocity": [-2, 0, 0], "parameters": {"mass": 4}}]})";
        QVERIFY2(parseSceneFile(good).file, parseSceneFile(good).error.c_str());
        const SceneFileResult bad = parseSceneFile(withLine(good, from.toStdString(), to.toStdString()));
        QVERIFY(!bad.file);
        QVERIFY2(QString::fromStdString(bad.error).contains(mentions), bad.error.c_str());
    }
    void worldStateRefusals() {
        WorldSpec spec = *worldScene("collide2d");
        World world(spec, "rk4");
        const std::string text = sceneFileText(world, true);
        // Body 2's positions one row short.
        const auto at = text.rfind("\"positions\": [[");
        const auto row = text.find("], [", at);
        std::string cut = text;
        cut.erase(row + 1, text.find(']', row + 4) - row);
        const SceneFileResult bad = parseSceneFile(cut);
        QVERIFY(!bad.file);
        QVERIFY2(QString::fromStdString(bad.error).contains("body2.positions has 23 rows; the body has 24"),
                 bad.error.c_str());
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
        // Duplicate keys (issue 18): refused with the key and the line of the second one.
        QTest::newRow("duplicate parameter") << "\"kd\": 15," << "\"kd\": 15,\n    \"kd\": 16," << "duplicate key 'kd' at line 9";
        QTest::newRow("duplicate top key") << "\"integrator\": \"rk4\"," << "\"integrator\": \"rk4\", \"integrator\": \"euler\","
                                           << "duplicate key 'integrator' at line 5";
        QTest::newRow("duplicate state key") << "\"time\":" << "\"step\": 0, \"time\":" << "duplicate key 'step'";
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
    void longBadValuesAreQuotedShort() {
        // A 5 MB value is quoted by a short, escaped prefix and its length, never whole.
        const std::string huge(5'000'000, 'x');
        ParameterSet p(SceneKind::Ring2d);
        const auto error = p.setFromText("ks", huge + "\x01");
        QVERIFY(error);
        QVERIFY2(error->size() < 200, error->c_str());
        QVERIFY(error->find("(5000001 bytes)") != std::string::npos);
        const SceneFileResult read = parseSceneFile("{\"" + huge + "\": 1}");
        QVERIFY(!read.file);
        QVERIFY2(read.error.size() < 300, read.error.substr(0, 300).c_str());
        QCOMPARE(quoteShort("a\nb'"), std::string("'a\\x0ab\\x27'"));
    }
    void onlyRegularFilesOfBoundedSizeAreRead() {
        // A directory, a FIFO (no writer: it must not wait), a device that never ends: each is
        // refused by what it is, at once.
        QTemporaryDir dir;
        const std::string folder = dir.path().toStdString();
        QVERIFY(readSceneFile(folder).error.find("is a directory") != std::string::npos);
        const std::string fifo = folder + "/scene.fifo";
        QCOMPARE(::mkfifo(fifo.c_str(), 0600), 0);
        const SceneFileResult fromFifo = readSceneFile(fifo);
        QVERIFY2(fromFifo.error.find("is not a regular file (a FIFO)") != std::string::npos, fromFifo.error.c_str());
        const SceneFileResult zero = readSceneFile("/dev/zero");
        QVERIFY2(zero.error.find("is not a regular file (a character device)") != std::string::npos, zero.error.c_str());
        QVERIFY(readSceneFile(folder + "/missing.json").error.find("No such file") != std::string::npos);
        // Beyond the bound: a sparse file (no disk used) one byte over 256 MiB.
        const std::string big = folder + "/big.json";
        {
            QFile f(QString::fromStdString(big));
            QVERIFY(f.open(QIODevice::WriteOnly));
            QVERIFY(f.resize(kMaxSceneFileBytes + 1));
        }
        const SceneFileResult tooBig = readSceneFile(big);
        QVERIFY2(tooBig.error.find("a scene file is at most 268435456 bytes") != std::string::npos, tooBig.error.c_str());
    }
    void olderMinimalFileLoads() {
        // Version 1 with only what is required: every parameter takes its default.
        const SceneFileResult read = parseSceneFile(R"({"format": "elastic-lab-scene", "version": 1, "scene": "sphere3d"})");
        QVERIFY2(read.file, read.error.c_str());
        QCOMPARE(read.file->params.get(simcore::Param::Ks), 800.0);
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
