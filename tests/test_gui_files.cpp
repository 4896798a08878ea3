// Scene files in the GUI and the failure paths of every GUI write (offscreen: the MainWindow
// gets a placeholder instead of its GL views, everything else is the real thing).
//
//   - save -> open through the controller: identical state, bit-identical trajectory after;
//   - bad files refused with the reader's message while the running scene goes on untouched;
//   - Open shows the file's values in the docks, the title tracks the file and its changes;
//   - scene save, CSV, plot and screenshot writes into a missing folder, onto a folder, onto
//     an existing file when the disk fills up (RLIMIT_FSIZE: works as root, where permission
//     bits do not) and into a full device node of our own (never /dev/full itself): an error
//     naming the file, the old file byte-identical, no temporary file left;
//   - the recent-files list: order, cap, persistence, a missing file dropped when chosen;
//   - unsaved changes: quitting or opening another file asks Save / Discard / Cancel.
#include <QAbstractButton>
#include <QComboBox>
#include <QDir>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <csignal>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include "simcore/scenes.h"
#include "simlab/scenefile.h"
#include "simlab/scenefile.h"
#include "simlab/stability.h"
#include "test_support.h"
#include "ui/export.h"
#include "ui/main_window.h"
#include "ui/parameter_dock.h"
#include "ui/plot_dock.h"
#include "ui/presets.h"
#include "ui/recent_files.h"
#include "ui/run_dock.h"
#include "ui/scene_dock.h"
#include "ui/simulation_controller.h"

using namespace elui;

namespace {

using testsupport::waitUntil;

bool waitForFrame(const SimulationController& c, const std::function<bool(const Frame&)>& pred) {
    return waitUntil([&] { return c.latest() && pred(*c.latest()); });
}

long stepOf(const SimulationController& c) { return c.latest()->lanes[0].diagnostics.step; }

// Single steps through the controller (queued, applied between steps) until lane 0 has taken
// `count` more.
bool stepBy(SimulationController& c, int count) {
    const long target = stepOf(c) + count;
    for (int i = 0; i < count; ++i) c.step();
    return waitForFrame(c, [target](const Frame& f) { return f.lanes[0].diagnostics.step == target; });
}

simcore::ParameterSet sceneParams(const QString& scene) {
    simcore::ParameterSet p(simcore::findScene(scene.toStdString())->kind);
    p.set(simcore::Param::Ks, 900.5);
    p.set(simcore::Param::Perturb, 0.01);  // an asymmetric start: every particle moves differently
    return p;
}

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<unreadable>");
}

QString latestWarning(const QWidget& window) {
    const auto boxes = window.findChildren<QMessageBox*>();
    return boxes.isEmpty() ? QString() : boxes.back()->text();
}

// Answers the window's next "unsaved changes" box with `button`, from inside the box's own
// event loop; counts the boxes it answered into *answered.
void answerUnsavedBox(QWidget& window, QMessageBox::StandardButton button, int* answered) {
    auto* timer = new QTimer(&window);
    QObject::connect(timer, &QTimer::timeout, &window, [&window, timer, button, answered] {
        auto* box = window.findChild<QMessageBox*>(QStringLiteral("unsavedChangesBox"));
        if (!box || !box->isVisible()) return;
        timer->stop();
        timer->deleteLater();
        ++*answered;
        box->button(button)->click();
    });
    timer->start(10);
}

// A good scene file text with one piece replaced.
std::string edited(const std::string& text, const std::string& from, const std::string& to) {
    std::string out = text;
    const auto at = out.find(from);
    if (at == std::string::npos) qFatal("fixture text not found: %s", from.c_str());
    return out.replace(at, from.size(), to);
}

enum class Writer { Scene, Csv, PlotsPng, PlotsSvg, PlotsPdf, Screenshot };
enum class Failure { MissingFolder, IsAFolder, DiskFullOverExisting, ReadOnlyFolderOverExisting, FullDevice };

// Writes well over 1 KiB with the given writer; the error message or empty.
QString writeWith(Writer writer, const QString& path) {
    static const std::vector<simcore::Diagnostics> rows = [] {
        simcore::Simulation sim(simcore::ParameterSet(simcore::SceneKind::Ring2d), "rk4");
        std::vector<simcore::Diagnostics> out{sim.diagnostics()};
        for (int i = 0; i < 200; ++i) {
            sim.step();
            out.push_back(sim.diagnostics());
        }
        return out;
    }();
    switch (writer) {
        case Writer::Scene: {
            simcore::Simulation sim(simcore::ParameterSet(simcore::SceneKind::Sphere3d), "rk4");
            return writeFile(path, QByteArray::fromStdString(simlab::sceneFileText(sim, "sphere3d", true)));
        }
        case Writer::Csv: return writeCsv(path, simcore::SceneKind::Ring2d, rows);
        case Writer::PlotsPng:
        case Writer::PlotsSvg:
        case Writer::PlotsPdf: {
            PlotDock dock;
            dock.setScene(simcore::SceneKind::Ring2d);
            dock.appendRows(rows, 0, int(rows.size()));
            dock.replotNow();
            return writePlots(path, dock.plots(), dock.specs());
        }
        case Writer::Screenshot: {
            QImage image(320, 240, QImage::Format_RGB32);
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) image.setPixel(x, y, qRgb(x * 7 % 256, y * 13 % 256, (x * y) % 256));
            return writeImage(path, image);
        }
    }
    return {};
}

QString suffixOf(Writer writer) {
    switch (writer) {
        case Writer::Scene: return QStringLiteral("json");
        case Writer::Csv: return QStringLiteral("csv");
        case Writer::PlotsPng: return QStringLiteral("png");
        case Writer::PlotsSvg: return QStringLiteral("svg");
        case Writer::PlotsPdf: return QStringLiteral("pdf");
        case Writer::Screenshot: return QStringLiteral("png");
    }
    return {};
}

// Files may grow to `bytes` at most while it lives (root included); SIGXFSZ ignored so that
// a write beyond fails with EFBIG instead of killing the test.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &m_old);
        m_oldHandler = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = m_old;
        limit.rlim_cur = bytes;
        m_ok = setrlimit(RLIMIT_FSIZE, &limit) == 0;
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &m_old);
        std::signal(SIGXFSZ, m_oldHandler);
    }
    bool ok() const { return m_ok; }

private:
    rlimit m_old{};
    void (*m_oldHandler)(int) = nullptr;
    bool m_ok = false;
};

}  // namespace

Q_DECLARE_METATYPE(Writer)
Q_DECLARE_METATYPE(Failure)

class TestGuiFiles : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        // Nothing here may touch the user's settings.
        QStandardPaths::setTestModeEnabled(true);
        QCoreApplication::setOrganizationName(QStringLiteral("ElasticLabTest"));
    }

    // --- save -> open through the controller ---

    void saveOpenResumesBitIdentically_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QString>("integrator");
        QTest::newRow("ring2d rk4") << "ring2d" << "rk4";
        QTest::newRow("sphere3d rk4") << "sphere3d" << "rk4";
        QTest::newRow("sphere3d verlet") << "sphere3d" << "verlet";
        QTest::newRow("spring1d euler") << "spring1d" << "euler";
    }
    void saveOpenResumesBitIdentically() {
        QFETCH(QString, scene);
        QFETCH(QString, integrator);
        QTemporaryDir dir;
        const QString path = dir.filePath("experiment.json");

        // A paused experiment 40 steps in, saved through the worker and a real file.
        SimulationController original;
        original.setScene(sceneParams(scene), {integrator});
        QVERIFY(waitForFrame(original, [](const Frame& f) { return f.scene != nullptr; }));
        QVERIFY(stepBy(original, 40));
        const SceneCapture saved = original.captureScene();
        QCOMPARE(saved.lanes, 1);
        QCOMPARE(saved.integrator, integrator);
        QCOMPARE(writeFile(path, QByteArray::fromStdString(saved.text)), QString());
        QCOMPARE(readAll(path), QByteArray::fromStdString(saved.text));

        // Reopened in another controller: the same state, step and time.
        const simlab::SceneFileResult read = simlab::readSceneFile(path.toStdString());
        QVERIFY2(read.file, read.error.c_str());
        QVERIFY(read.file->state);
        QCOMPARE(read.file->state->step, 40L);
        SimulationController resumed;
        resumed.openScene(*read.file);
        QVERIFY(waitForFrame(resumed, [](const Frame& f) { return f.scene && f.lanes[0].diagnostics.step == 40; }));
        QVERIFY(!resumed.latest()->running);
        QCOMPARE(resumed.integrators(), QStringList{integrator});
        QCOMPARE(resumed.latest()->lanes[0].diagnostics.time, original.latest()->lanes[0].diagnostics.time);
        QCOMPARE(resumed.latest()->lanes[0].positions, original.latest()->lanes[0].positions);
        QCOMPARE(resumed.captureScene().text, saved.text);  // every double, in shortest round-trip form
        // History starts at the saved time.
        QCOMPARE(resumed.history().size(), std::size_t(1));
        QCOMPARE(resumed.history().front().step, 40L);

        // 60 more steps in both: bit-identical positions and velocities.
        QVERIFY(stepBy(original, 60));
        QVERIFY(stepBy(resumed, 60));
        const SceneCapture a = original.captureScene(), b = resumed.captureScene();
        QVERIFY(a.text.find("\"step\": 100") != std::string::npos);
        QVERIFY(a.text == b.text);
        QCOMPARE(resumed.latest()->lanes[0].positions, original.latest()->lanes[0].positions);

        // Reset goes back to t = 0 of the file's parameters.
        resumed.reset();
        QVERIFY(waitForFrame(resumed, [](const Frame& f) { return f.lanes[0].diagnostics.step == 0; }));
        QCOMPARE(resumed.latest()->lanes[0].diagnostics.time, 0.0);
    }

    void captureWhileRunningIsBetweenSteps() {
        SimulationController c;
        c.setScene(sceneParams("ring2d"), {"rk4"});
        c.run();
        QVERIFY(waitForFrame(c, [](const Frame& f) { return f.running && f.lanes[0].diagnostics.time > 0.05; }));
        for (int i = 0; i < 5; ++i) {
            const SceneCapture capture = c.captureScene();
            const simlab::SceneFileResult read = simlab::parseSceneFile(capture.text);
            QVERIFY2(read.file, read.error.c_str());
            // A step boundary: the time is exactly the step count times the fixed DT.
            const auto& s = *read.file->state;
            QCOMPARE(s.time, capture.time);
            QVERIFY(s.step > 0);
            QVERIFY(std::abs(s.time - double(s.step) * 0.003) < 1e-9);
            // The next capture only after the run has gone on: a different step boundary.
            const double t = capture.time;
            QVERIFY(waitForFrame(c, [t](const Frame& f) { return f.lanes[0].diagnostics.time > t; }));
        }
        QVERIFY(c.running());  // the run went on
    }

    void sideBySideOpensWithTheStateInEveryLane() {
        simcore::Simulation sim(sceneParams("ring2d"), "rk4");
        QVERIFY(sim.advanceTo(0.3));
        const simlab::SceneFileResult read = simlab::parseSceneFile(simlab::sceneFileText(sim, "ring2d", true));
        QVERIFY(read.file);
        SimulationController c;
        c.openScene(*read.file, {"rk4", "verlet"});
        QVERIFY(waitForFrame(c, [](const Frame& f) { return f.lanes.size() == 2; }));
        QCOMPARE(c.latest()->lanes[1].positions, c.latest()->lanes[0].positions);
        QCOMPARE(c.latest()->lanes[1].diagnostics.time, sim.time());
        // Saving side by side stores lane 0.
        const SceneCapture capture = c.captureScene();
        QCOMPARE(capture.lanes, 2);
        QCOMPARE(capture.integrator, QString("rk4"));
    }

    void unbuildableFileKeepsTheRunningScene() {
        // A state that does not fit the body (the reader checks this too; here the worker's own
        // check is exercised): refused, the old scene goes on, the controller's view restored.
        SimulationController c;
        QSignalSpy rejected(&c, &SimulationController::sceneRejected);
        c.setScene(sceneParams("ring2d"), {"midpoint"});
        c.run();
        QVERIFY(waitForFrame(c, [](const Frame& f) { return f.running && f.lanes[0].diagnostics.time > 0.05; }));
        const auto scene = c.latest()->scene;
        simlab::SceneFile file;
        file.sceneName = "sphere3d";
        file.params = simcore::ParameterSet(simcore::SceneKind::Sphere3d);
        file.state = simlab::SceneFile::State{};
        file.state->positions = Eigen::Matrix3Xd::Zero(3, 5);
        file.state->velocities = Eigen::Matrix3Xd::Zero(3, 5);
        c.openScene(file);
        QVERIFY(waitUntil([&] { return rejected.count() >= 1; }));
        QVERIFY(rejected.front().front().toString().contains("state"));
        const double t = c.latest()->lanes[0].diagnostics.time;
        QVERIFY(waitForFrame(c, [t](const Frame& f) { return f.lanes[0].diagnostics.time > t + 0.05; }));
        QCOMPARE(c.latest()->scene, scene);
        QCOMPARE(c.sceneKind(), simcore::SceneKind::Ring2d);
        QCOMPARE(c.integrators(), QStringList{"midpoint"});
    }

    // --- Open in the window ---

    void badFilesAreRefusedAndTheSceneRunsOn_data() {
        QTest::addColumn<QString>("from");
        QTest::addColumn<QString>("to");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("syntax error") << "\"kd\": 15," << "\"kd\": 15,," << "line 8";
        QTest::newRow("unknown key") << "\"ks\":" << "\"kss\":" << "kss";
        QTest::newRow("out of range") << "\"restitution\": 0.5" << "\"restitution\": 2" << "restitution";
        QTest::newRow("newer version") << QString("\"version\": %1").arg(simlab::kSceneFormatVersion)
                                       << "\"version\": 99" << "newer";
        QTest::newRow("wrong state size") << "\"positions\": [[" << "\"positions\": [[0, 0, 0], [" << "positions";
        QTest::newRow("missing file") << "" << "" << "no such file";
        QTest::newRow("a folder") << "" << "" << "not a regular file";
    }
    void badFilesAreRefusedAndTheSceneRunsOn() {
        QFETCH(QString, from);
        QFETCH(QString, to);
        QFETCH(QString, mentions);
        QTemporaryDir dir;
        QString path = dir.filePath("bad.json");
        if (QTest::currentDataTag() == QLatin1String("missing file")) {
            path = dir.filePath("missing.json");
        } else if (QTest::currentDataTag() == QLatin1String("a folder")) {
            QVERIFY(QDir(dir.path()).mkdir("folder.json"));
            path = dir.filePath("folder.json");
        } else {
            simcore::Simulation sim(simcore::ParameterSet(simcore::SceneKind::Ring2d), "rk4");
            const std::string text = edited(simlab::sceneFileText(sim, "ring2d", true), from.toStdString(), to.toStdString());
            QCOMPARE(writeFile(path, QByteArray::fromStdString(text)), QString());
        }

        MainWindow window(false);
        SimulationController* c = window.controller();
        simcore::ParameterSet params = sceneParams("sphere3d");
        window.startScene(params, {"verlet"});
        c->run();
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.running && f.lanes[0].diagnostics.time > 0.03; }));
        const auto scene = c->latest()->scene;

        const QString error = window.openSceneFile(path);
        QVERIFY2(error.contains(mentions), qPrintable(error));
        QVERIFY(error.contains(path));
        QCOMPARE(latestWarning(window), error);
        QVERIFY(window.statusBar()->currentMessage().contains(mentions));

        // The running scene is untouched and keeps running.
        const double t = c->latest()->lanes[0].diagnostics.time;
        QVERIFY(waitForFrame(*c, [t](const Frame& f) { return f.lanes[0].diagnostics.time > t + 0.03; }));
        QVERIFY(c->latest()->running);
        QCOMPARE(c->latest()->scene, scene);
        QCOMPARE(c->latest()->parameters, params);
        QCOMPARE(c->latest()->lanes[0].integrator, QString("verlet"));
        QCOMPARE(window.currentFile(), QString());
        QVERIFY(window.recentFiles().paths().isEmpty());
    }

    void refinedSceneOffersAStableDtInOneClick() {
        // A finer mesh has faster modes (issue 12): rebuilt at 96 particles the ring is unstable
        // at the default DT with rk4. The window says so before anything runs, shows what the
        // body uses per particle, and one click sets the predicted stable DT, which runs.
        simcore::ParameterSet p(simcore::SceneKind::Ring2d);
        p.set(simcore::Param::Particles, 96);
        simcore::Simulation probe(p, "rk4");
        const auto advice = simlab::stabilityAdvice(probe);
        QVERIFY(advice);
        MainWindow window(false);
        SimulationController* c = window.controller();
        window.startScene(p, {"rk4"});
        QVERIFY(waitUntil([&] { return !window.stabilityText().isEmpty(); }));
        QVERIFY(window.stabilityText().contains("dt = 0.003 s is above"));
        QVERIFY2(window.sceneDock()->bodyValuesText().contains("96 particles per layer; reference 12"),
                 qPrintable(window.sceneDock()->bodyValuesText()));
        auto* scaling = window.sceneDock()->findChild<QComboBox*>("param_scaling");
        QVERIFY(scaling);
        QCOMPARE(scaling->currentText(), QString("physical"));
        QVERIFY(window.useSuggestedDtButton()->text().contains(QString::number(advice->suggestedDt)));
        window.useSuggestedDtButton()->click();
        QVERIFY(waitUntil([&] { return c->parameters().get(simcore::Param::Dt) == advice->suggestedDt; }));
        QVERIFY(window.stabilityText().isEmpty());
        c->run();
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.lanes.front().diagnostics.time > 0.3; }));
        QVERIFY(!c->latest()->lanes.front().failure);
    }
    void openShowsTheFileInTheDocksAndTitle() {
        QTemporaryDir dir;
        const QString path = dir.filePath("squashed.json");
        simcore::ParameterSet p(simcore::SceneKind::Sphere3d);
        p.set(simcore::Param::Ks, 950);
        p.set(simcore::Param::Dt, 0.002);
        simcore::Simulation sim(p, "verlet");
        QVERIFY(sim.advanceTo(0.25));
        QCOMPARE(writeFile(path, QByteArray::fromStdString(simlab::sceneFileText(sim, "sphere3d", true))), QString());

        MainWindow window(false);
        SimulationController* c = window.controller();
        window.startScene(simcore::ParameterSet(simcore::SceneKind::Ring2d), {"rk4"});
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.scene != nullptr; }));
        QCOMPARE(window.openSceneFile(path), QString());
        QVERIFY(waitUntil([&] { return window.currentFile() == path; }));
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.scene->kind == simcore::SceneKind::Sphere3d; }));
        QCoreApplication::processEvents();

        // The docks show the file's values; the run waits at the saved time.
        QCOMPARE(window.parameterDock()->form()->field("ks")->text(), QString("950"));
        QCOMPARE(window.parameterDock()->form()->field("dt")->text(), QString("0.002"));
        QCOMPARE(window.runDock()->integratorCombo()->currentText(), QString("verlet"));
        QCOMPARE(c->latest()->lanes[0].diagnostics.time, sim.time());
        QVERIFY(!c->latest()->running);
        QVERIFY(window.windowTitle().startsWith("squashed.json[*]"));
        QVERIFY(!window.isWindowModified());
        QCOMPARE(window.recentFiles().paths(), QStringList{path});

        // Running alone does not modify; a parameter or integrator change does.
        c->run();
        QVERIFY(waitForFrame(*c, [&](const Frame& f) { return f.lanes[0].diagnostics.time > sim.time() + 0.02; }));
        QVERIFY(!window.isWindowModified());
        c->setParameter("ks", 1000);
        QVERIFY(waitUntil([&] { return window.isWindowModified(); }));
        c->setParameter("ks", 950);
        QVERIFY(waitUntil([&] { return !window.isWindowModified(); }));
        c->setIntegrator("rk4");
        QVERIFY(waitUntil([&] { return window.isWindowModified(); }));

        // Save as: the new file is current, unmodified, first in the recent list.
        const QString copy = dir.filePath("copy.json");
        QCOMPARE(window.saveSceneFile(copy), QString());
        QVERIFY(!window.isWindowModified());
        QVERIFY(window.windowTitle().startsWith("copy.json[*]"));
        QCOMPARE(window.recentFiles().paths(), (QStringList{copy, path}));
        const simlab::SceneFileResult reread = simlab::readSceneFile(copy.toStdString());
        QVERIFY2(reread.file, reread.error.c_str());
        QCOMPARE(reread.file->integrator, std::string("rk4"));
        QVERIFY(reread.file->state->time > sim.time());

        // A preset is a new experiment: no current file.
        window.applyPreset(*findPreset("ring2d"));
        QCOMPARE(window.currentFile(), QString());
        QVERIFY(waitUntil([&] { return window.windowTitle().startsWith("Elastic Lab"); }));
    }

    void unsavedChangesAreAskedAbout() {
        QTemporaryDir dir;
        const QString path = dir.filePath("ring.json");
        simcore::ParameterSet p(simcore::SceneKind::Ring2d);
        p.set(simcore::Param::Ks, 950);
        const simcore::Simulation sim(p, "rk4");
        QCOMPARE(writeFile(path, QByteArray::fromStdString(simlab::sceneFileText(sim, "ring2d", true))), QString());
        const QByteArray original = readAll(path);
        auto savedKs = [&] {
            const simlab::SceneFileResult read = simlab::readSceneFile(path.toStdString());
            return read.file ? read.file->params.get(simcore::Param::Ks) : -1.0;
        };

        MainWindow window(false);
        SimulationController* c = window.controller();
        QCOMPARE(window.openSceneFile(path), QString());
        QVERIFY(waitUntil([&] { return window.currentFile() == path && c->latest() != nullptr; }));
        int answered = 0;

        // Nothing changed: nothing to ask. (Not shown: closing through close() asks the same
        // maybeSave(); a shown window here made ThreadSanitizer report Qt's own image threads.)
        QVERIFY(window.maybeSave());
        QCOMPARE(answered, 0);

        c->setParameter("ks", 1234);
        QVERIFY(waitUntil([&] { return window.isWindowModified(); }));
        // Cancel keeps the window, the scene and the file.
        answerUnsavedBox(window, QMessageBox::Cancel, &answered);
        QVERIFY(!window.close());
        QCOMPARE(answered, 1);
        // Open asks first; Cancel: no file dialog, nothing opened.
        answerUnsavedBox(window, QMessageBox::Cancel, &answered);
        window.openSceneDialog();
        QCOMPARE(answered, 2);
        QCOMPARE(window.currentFile(), path);
        QVERIFY(window.isWindowModified());
        QCOMPARE(readAll(path), original);
        // Discard closes and leaves the file as it was.
        answerUnsavedBox(window, QMessageBox::Discard, &answered);
        QVERIFY(window.close());
        QCOMPARE(answered, 3);
        QCOMPARE(readAll(path), original);
        // Save writes the changes, and the window may go.
        answerUnsavedBox(window, QMessageBox::Save, &answered);
        QVERIFY(window.maybeSave());
        QCOMPARE(answered, 4);
        QCOMPARE(savedKs(), 1234.0);
        QVERIFY(!window.isWindowModified());
    }

    void sideBySideSavesTheFirstView() {
        QTemporaryDir dir;
        MainWindow window(false);
        SimulationController* c = window.controller();
        window.startScene(sceneParams("ring2d"), {"euler", "midpoint", "rk4"});
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.lanes.size() == 3; }));
        QVERIFY(stepBy(*c, 10));
        const QString path = dir.filePath("compare.json");
        QCOMPARE(window.saveSceneFile(path), QString());
        QVERIFY2(window.statusBar()->currentMessage().contains("first view (euler)"),
                 qPrintable(window.statusBar()->currentMessage()));
        const simlab::SceneFileResult read = simlab::readSceneFile(path.toStdString());
        QVERIFY(read.file);
        QCOMPARE(read.file->integrator, std::string("euler"));
        QCOMPARE(read.file->state->step, 10L);
    }

    void saveFailureIsReportedInTheWindow() {
        QTemporaryDir dir;
        MainWindow window(false);
        window.startScene(sceneParams("ring2d"), {"rk4"});
        QVERIFY(waitForFrame(*window.controller(), [](const Frame& f) { return f.scene != nullptr; }));
        const QString path = dir.filePath("no/such/folder/x.json");
        const QString error = window.saveSceneFile(path);
        QVERIFY(error.contains(path));
        QCOMPARE(latestWarning(window), error);
        QCOMPARE(window.currentFile(), QString());
        QVERIFY(window.recentFiles().paths().isEmpty());
    }

    // --- every GUI write, failing ---

    void failedWritesLeaveNoTrace_data() {
        QTest::addColumn<Writer>("writer");
        QTest::addColumn<Failure>("failure");
        const QList<QPair<const char*, Writer>> writers = {
            {"scene", Writer::Scene},         {"csv", Writer::Csv},           {"plots png", Writer::PlotsPng},
            {"plots svg", Writer::PlotsSvg}, {"plots pdf", Writer::PlotsPdf}, {"screenshot", Writer::Screenshot}};
        const QList<QPair<const char*, Failure>> failures = {{"missing folder", Failure::MissingFolder},
                                                             {"onto a folder", Failure::IsAFolder},
                                                             {"disk full over a file", Failure::DiskFullOverExisting},
                                                             {"read-only folder over a file", Failure::ReadOnlyFolderOverExisting},
                                                             {"full device", Failure::FullDevice}};
        for (const auto& [wname, w] : writers)
            for (const auto& [fname, f] : failures)
                QTest::newRow(qPrintable(QStringLiteral("%1, %2").arg(wname, fname))) << w << f;
    }
    void failedWritesLeaveNoTrace() {
        QFETCH(Writer, writer);
        QFETCH(Failure, failure);
        QTemporaryDir dir;
        const QString name = QStringLiteral("out.") + suffixOf(writer);
        const QByteArray old = "the previous file, which must survive\n";
        QString path;
        QString error;
        switch (failure) {
            case Failure::MissingFolder:
                path = dir.filePath("missing/" + name);
                error = writeWith(writer, path);
                QVERIFY2(error.contains("No such file or directory"), qPrintable(error));
                break;
            case Failure::IsAFolder:
                QVERIFY(QDir(dir.path()).mkdir(name));
                path = dir.filePath(name);
                error = writeWith(writer, path);
                QVERIFY2(error.contains("directory"), qPrintable(error));
                QVERIFY(QFileInfo(path).isDir());
                QVERIFY(QDir(path).isEmpty());
                break;
            case Failure::DiskFullOverExisting: {
                path = dir.filePath(name);
                QCOMPARE(writeFile(path, old), QString());
                {
                    FileSizeLimit limit(1024);
                    QVERIFY(limit.ok());
                    error = writeWith(writer, path);
                }
                QVERIFY2(error.contains("too large"), qPrintable(error));  // EFBIG's text
                QCOMPARE(readAll(path), old);
                break;
            }
            case Failure::ReadOnlyFolderOverExisting: {
                // Permission bits do not stop root (the usual test user here): then skipped,
                // the disk-full row covers a failure over an existing file.
                if (::geteuid() == 0) QSKIP("running as root: a read-only folder does not stop writes");
                path = dir.filePath(name);
                QCOMPARE(writeFile(path, old), QString());
                QVERIFY(QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner));
                error = writeWith(writer, path);
                QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
                QVERIFY2(error.contains("Permission denied"), qPrintable(error));
                QCOMPARE(readAll(path), old);
                break;
            }
            case Failure::FullDevice: {
                // Our own node of /dev/full's kind (char 1,7) in the temporary folder: a device
                // is written in place, and it must still be that device afterwards.
                path = dir.filePath(name);
                if (::mknod(QFile::encodeName(path).constData(), S_IFCHR | 0666, makedev(1, 7)) != 0)
                    QSKIP("cannot create a device node here (needs CAP_MKNOD)");
                error = writeWith(writer, path);
                QVERIFY2(error.contains("No space left on device"), qPrintable(error));
                struct stat st {};
                QCOMPARE(::stat(QFile::encodeName(path).constData(), &st), 0);
                QVERIFY(S_ISCHR(st.st_mode));
                QCOMPARE(major(st.st_rdev), 1u);
                QCOMPARE(minor(st.st_rdev), 7u);
                break;
            }
        }
        QVERIFY2(error.contains(path), qPrintable(error));
        // Nothing else in the folder: no temporary file, no half file (System: device nodes too).
        const QStringList entries =
            QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden | QDir::System);
        const QStringList expected = failure == Failure::MissingFolder ? QStringList{} : QStringList{name};
        QCOMPARE(entries, expected);
    }

    void writesSucceedOverAnExistingFile() {
        // The same writers replace an existing file completely when nothing fails.
        QTemporaryDir dir;
        for (Writer w : {Writer::Scene, Writer::Csv, Writer::PlotsPng, Writer::PlotsSvg, Writer::PlotsPdf,
                         Writer::Screenshot}) {
            const QString path = dir.filePath("out." + suffixOf(w));
            QCOMPARE(writeFile(path, "old"), QString());
            QCOMPARE(writeWith(w, path), QString());
            QVERIFY(readAll(path).size() > 1024);
        }
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 5);  // two .png share a name
    }

    // --- recent files ---

    void recentFilesKeepOrderAndCap() {
        QTemporaryDir dir;
        QSettings settings(dir.filePath("settings.ini"), QSettings::IniFormat);
        RecentFiles recent(&settings);
        QVERIFY(recent.paths().isEmpty());
        auto file = [&](int i) { return dir.filePath(QStringLiteral("s%1.json").arg(i)); };
        recent.add(file(1));
        recent.add(file(2));
        recent.add(file(3));
        QCOMPARE(recent.paths(), (QStringList{file(3), file(2), file(1)}));
        recent.add(file(1));  // reopened: to the front, once
        QCOMPARE(recent.paths(), (QStringList{file(1), file(3), file(2)}));
        for (int i = 4; i <= 12; ++i) recent.add(file(i));
        QCOMPARE(recent.paths().size(), RecentFiles::kMax);
        QCOMPARE(recent.paths().front(), file(12));
        QCOMPARE(recent.paths().back(), file(5));
        // Relative paths are stored absolute.
        const QString cwd = QDir::currentPath();
        QDir::setCurrent(dir.path());
        recent.add(QStringLiteral("s7.json"));
        QDir::setCurrent(cwd);
        QCOMPARE(recent.paths().front(), file(7));
        QCOMPARE(recent.paths().count(file(7)), 1);
        // Kept across instances (a restart).
        settings.sync();
        QSettings again(dir.filePath("settings.ini"), QSettings::IniFormat);
        QCOMPARE(RecentFiles(&again).paths(), recent.paths());
        recent.remove(file(12));
        QVERIFY(!recent.paths().contains(file(12)));
        recent.clear();
        QVERIFY(recent.paths().isEmpty());
        QCOMPARE(settings.value("recentScenes").toStringList(), QStringList{});
    }

    void recentMenuOpensAndDropsMissingFiles() {
        QTemporaryDir dir;
        MainWindow window(false);
        SimulationController* c = window.controller();
        window.startScene(sceneParams("ring2d"), {"rk4"});
        QVERIFY(waitForFrame(*c, [](const Frame& f) { return f.scene != nullptr; }));
        const QString a = dir.filePath("a.json"), b = dir.filePath("b.json");
        QCOMPARE(window.saveSceneFile(a), QString());
        QCOMPARE(window.saveSceneFile(b), QString());
        QStringList texts;
        for (QAction* action : window.recentMenu()->actions())
            if (!action->isSeparator()) texts << action->text();
        QCOMPARE(texts, (QStringList{"&1 b.json", "&2 a.json", "&Clear"}));

        // Chosen after it was deleted: a message, and it leaves the list; the scene runs on.
        QVERIFY(QFile::remove(a));
        const auto scene = c->latest()->scene;
        const QString error = window.openRecent(a);
        QVERIFY2(error.contains(a) && error.contains("no longer exists"), qPrintable(error));
        QCOMPARE(latestWarning(window), error);
        QCOMPARE(window.recentFiles().paths(), QStringList{b});
        QCOMPARE(c->latest()->scene, scene);

        // An existing one opens and moves to the front.
        QCOMPARE(window.openRecent(b), QString());
        QVERIFY(waitUntil([&] { return c->latest()->scene != scene; }));
        QCOMPARE(window.currentFile(), b);
        window.recentMenu()->actions().back()->trigger();  // Clear
        QVERIFY(window.recentFiles().paths().isEmpty());
    }
};

QTEST_MAIN(TestGuiFiles)
#include "test_gui_files.moc"
