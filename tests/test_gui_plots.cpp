// Plot data per scene (only the quantities a scene has), and the file exports.
#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

#include "export.h"
#include "main_window.h"
#include "output.h"
#include "plot_dock.h"
#include "scenes.h"
#include "simulation_controller.h"
#include "studies_dialog.h"
#include "test_support.h"

#include <QComboBox>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>

#include "run_dock.h"
#include "scene_dock.h"
#include "qcustomplot.h"

using namespace elui;
using simcore::SceneKind;

Q_DECLARE_METATYPE(simcore::SceneKind)

namespace {
std::vector<simcore::Diagnostics> runRows(SceneKind kind, int steps) {
    simcore::Simulation sim(simcore::ParameterSet(kind), "rk4");
    std::vector<simcore::Diagnostics> rows{sim.diagnostics()};
    for (int i = 0; i < steps; ++i) {
        sim.step();
        rows.push_back(sim.diagnostics());
    }
    return rows;
}
}  // namespace

class TestGuiPlots : public QObject {
    Q_OBJECT
private slots:
    void onlyTheQuantitiesTheSceneHas_data() {
        QTest::addColumn<SceneKind>("kind");
        for (const simcore::SceneInfo& s : simcore::sceneTable())
            QTest::newRow(std::string(s.name).c_str()) << s.kind;
    }
    void onlyTheQuantitiesTheSceneHas() {
        QFETCH(SceneKind, kind);
        PlotDock dock;
        dock.setScene(kind);
        const bool gas = simcore::hasGas(kind);
        const QStringList expected = gas ? QStringList{"volume", "pressure", "energy"} : QStringList{"energy"};
        QCOMPARE(dock.plotIds(), expected);
        QCOMPARE(dock.seriesNames("energy").contains("gas"), gas);
        QVERIFY(dock.seriesNames("energy").contains("total"));
        QVERIFY(dock.seriesNames("energy").contains("removed"));
        if (gas) QCOMPARE(dock.seriesNames("volume"), (QStringList{"inner", "outer"}));

        const auto rows = runRows(kind, 40);
        dock.appendRows(rows, 0, 10);
        dock.appendRows(rows, 10, int(rows.size()) - 10);
        for (const QString& id : dock.plotIds())
            for (int s = 0; s < dock.seriesNames(id).size(); ++s) QCOMPARE(dock.pointCount(id, s), 41);
        const simcore::Diagnostics& last = rows.back();
        QCOMPARE(dock.lastValue("energy", 0), last.kinetic);
        QCOMPARE(dock.lastValue("energy", int(dock.seriesNames("energy").indexOf("total"))), last.total());
        if (gas) {
            QCOMPARE(dock.lastValue("volume", 1), last.volume[1]);
            QCOMPARE(dock.lastValue("pressure", 0), last.pressure[0]);
        }
        dock.clear();
        QCOMPARE(dock.pointCount("energy", 0), 0);
    }

    void mainWindowFollowsTheScene() {
        // Offscreen there is no OpenGL: the window must still work, with a placeholder view.
        MainWindow window(false);
        QVERIFY(window.viewports().empty());
        simcore::ParameterSet p(SceneKind::Spring1d);
        window.startScene(p, {"rk4"});
        QTRY_VERIFY_WITH_TIMEOUT(window.controller()->latest() &&
                                     window.controller()->latest()->scene->kind == SceneKind::Spring1d, testsupport::kHangGuardMs);
        QTRY_COMPARE_WITH_TIMEOUT(window.plotDock()->plotIds(), QStringList{"energy"}, testsupport::kHangGuardMs);
        window.controller()->step();
        window.controller()->step();
        QTRY_COMPARE_WITH_TIMEOUT(window.plotDock()->pointCount("energy", 0), 3, testsupport::kHangGuardMs);
        window.startScene(simcore::ParameterSet(SceneKind::Sphere3d), {"rk4"});
        QTRY_COMPARE_WITH_TIMEOUT(window.plotDock()->plotIds(), (QStringList{"volume", "pressure", "energy"}), testsupport::kHangGuardMs);
        QTRY_COMPARE_WITH_TIMEOUT(window.plotDock()->pointCount("volume", 0), 1, testsupport::kHangGuardMs);
    }

    void sceneDockRebuildsKeepingEdits() {
        MainWindow window(false);
        window.startScene(simcore::ParameterSet(SceneKind::Ring2d), {"rk4"});
        QTRY_VERIFY_WITH_TIMEOUT(window.controller()->latest() != nullptr, testsupport::kHangGuardMs);
        window.controller()->setParameter("ks", 500.0);
        QTRY_COMPARE_WITH_TIMEOUT(window.controller()->parameters().get("ks"), 500.0, testsupport::kHangGuardMs);
        // Choose the sphere, level 1, and rebuild from the dock.
        SceneDock* dock = window.sceneDock();
        dock->sceneCombo()->setCurrentIndex(dock->sceneCombo()->findText("sphere3d"));
        auto* subdivisions = dock->findChild<QLineEdit*>("param_subdivisions");
        QVERIFY(subdivisions);
        subdivisions->setText("1");
        emit subdivisions->editingFinished();
        QTest::mouseClick(dock->findChild<QPushButton*>("rebuildButton"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(window.controller()->latest()->scene->kind == SceneKind::Sphere3d, testsupport::kHangGuardMs);
        const FramePtr f = window.controller()->latest();
        QCOMPARE(f->scene->topology.particleCount(), 2 * 18);  // 4 * 4^1 + 2 per layer
        QCOMPARE(f->parameters.get("ks"), 500.0);            // the edit carried over
        QTRY_COMPARE_WITH_TIMEOUT(window.plotDock()->plotIds(), (QStringList{"volume", "pressure", "energy"}), testsupport::kHangGuardMs);
    }

    void layoutIsSavedAndRestored() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        {
            MainWindow window(true);
            window.show();
            window.plotDock()->hide();
            window.close();  // writes the settings
        }
        {
            MainWindow window(true);
            window.show();
            QVERIFY(window.plotDock()->isHidden());
            QVERIFY(!window.runDock()->isHidden());
        }
        QSettings().clear();
    }

    void csvHasTheCliColumns() {
        QTemporaryDir dir;
        const auto rows = runRows(SceneKind::Ring2d, 5);
        const QString path = dir.filePath("run.csv");
        QCOMPARE(writeCsv(path, SceneKind::Ring2d, rows), QString());
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().split('\n');
        const auto columns = simcore::timeSeriesColumns(SceneKind::Ring2d);
        QCOMPARE(lines[0] + '\n', QByteArray::fromStdString(simcore::csvHeader(columns)));
        QCOMPARE(lines[3] + '\n', QByteArray::fromStdString(simcore::csvRow(columns, rows[2])));
        QCOMPARE(lines.size(), 1 + 6 + 1);  // header, 6 rows, trailing newline
        // 1D: no gas columns.
        QCOMPARE(writeCsv(path, SceneKind::Spring1d, runRows(SceneKind::Spring1d, 2)), QString());
        QVERIFY(f.seek(0) || true);
        f.close();
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(!f.readLine().contains("volume"));
        // An unwritable path leaves an error, not a half file.
        QVERIFY(!writeCsv("/nonexistent-dir/x.csv", SceneKind::Ring2d, rows).isEmpty());
    }

    void workPrecisionStudyRunsOnAThread() {
        // simcore's study (the CLI's code) behind the dialog: rows, table, plot and orders.
        simcore::ParameterSet p(SceneKind::Spring1d);
        WorkPrecisionDialog dialog(p);
        dialog.setSteps("0.01 0.005 0.0025");
        dialog.setDuration(0.5);
        QSignalSpy finished(&dialog, &StudyDialogBase::finished);
        dialog.start();
        QVERIFY(dialog.busy());
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, testsupport::kHangGuardMs);
        const auto& rows = dialog.result().rows;
        QCOMPARE(int(rows.size()), 4 * 3);  // euler, midpoint, rk4, verlet x 3 steps
        QCOMPARE(dialog.table()->rowCount(), 12);
        QCOMPARE(dialog.plot()->graphCount(), 2 * 4);  // error vs run time and vs DT, per integrator
        // RK4's error falls far faster with DT than Euler's.
        auto err = [&](const char* name, double dt) {
            for (const auto& r : rows)
                if (r.item.integrator == name && std::abs(r.dt - dt) < 1e-12) return r.errorMax;
            return -1.0;
        };
        QVERIFY(err("rk4", 0.0025) < err("euler", 0.0025) * 1e-3);
        if (qEnvironmentVariableIsSet("ELASTIC_LAB_SHOT_DIR"))
            dialog.grab().save(qEnvironmentVariable("ELASTIC_LAB_SHOT_DIR") + "/study.png");
    }

    void refinementStudyRunsAndCancels() {
        // simcore's refinement study (the CLI's code) behind the dialog. A long study (a sphere
        // up to level 4 over 5 s: minutes) cancelled at once keeps nothing: the reference, which
        // runs first, was cut short. A weightless ring then runs a short study to the end.
        simcore::ParameterSet sphere(SceneKind::Sphere3d);
        RefinementDialog dialog(sphere);
        dialog.setLevels("2 3 4");
        dialog.setDuration(5.0);
        QSignalSpy finished(&dialog, &StudyDialogBase::finished);
        dialog.start();
        QVERIFY(dialog.busy());
        dialog.cancel();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, testsupport::kHangGuardMs);
        QVERIFY(!dialog.busy());
        QVERIFY(dialog.result().cancelled);
        QVERIFY(dialog.result().rows.empty());

        simcore::ParameterSet ring(SceneKind::Ring2d);
        ring.set("gravity", 0.0);
        RefinementDialog small(ring);
        small.setLevels("12 24 48");
        small.setDuration(0.1);
        QSignalSpy smallFinished(&small, &StudyDialogBase::finished);
        small.start();
        QTRY_COMPARE_WITH_TIMEOUT(smallFinished.count(), 1, testsupport::kHangGuardMs);
        const auto& rows = small.result().rows;
        QCOMPARE(int(rows.size()), 3);
        QCOMPARE(small.table()->rowCount(), 3);
        QVERIFY(rows[2].reference && rows[2].errorVolume == 0.0);
        QVERIFY(rows[0].errorVolume > rows[1].errorVolume && rows[1].errorVolume > 0.0);
        QCOMPARE(small.plot()->graphCount(), 2 * 2);  // mesh and step, volume and centre of mass
        QVERIFY(small.plot()->graph(0)->dataCount() == 2 && small.plot()->graph(1)->dataCount() > 0);
        if (qEnvironmentVariableIsSet("ELASTIC_LAB_SHOT_DIR"))
            small.grab().save(qEnvironmentVariable("ELASTIC_LAB_SHOT_DIR") + "/refinement.png");
        // Refused before any work: a scene without a mesh to refine, a step that is no number.
        RefinementDialog spring(simcore::ParameterSet(SceneKind::Spring1d));
        spring.start();
        QVERIFY(!spring.busy());
        small.setStep("fast");
        small.start();
        QVERIFY(!small.busy());
        QCOMPARE(smallFinished.count(), 1);
    }

    void stabilityScanCancels() {
        // A long scan (a sphere for 3 s per trial, seconds in Release) stops within one step of
        // Cancel, keeps only whole rows, and can run again.
        simcore::ParameterSet sphere(SceneKind::Sphere3d);
        sphere.set("subdivisions", 1);
        StabilityDialog dialog(sphere);
        dialog.setDuration(3.0);
        QSignalSpy finished(&dialog, &StudyDialogBase::finished);
        dialog.start();
        QVERIFY(dialog.busy());
        dialog.cancel();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, testsupport::kHangGuardMs);
        QVERIFY(!dialog.busy());
        QVERIFY(dialog.rows().empty());  // the scan in progress was cut short: no partial row
        // The dialog runs again afterwards, here a short scan to the end: one row per integrator.
        StabilityDialog small(simcore::ParameterSet(SceneKind::Spring1d));
        small.setDuration(0.2);
        QSignalSpy smallFinished(&small, &StudyDialogBase::finished);
        small.start();
        QTRY_COMPARE_WITH_TIMEOUT(smallFinished.count(), 1, testsupport::kHangGuardMs);
        QCOMPARE(int(small.rows().size()), 4);
        for (const auto& row : small.rows()) QVERIFY(row.stable > 0.0 && row.unstable > row.stable);
    }

    void stabilityScanFindsTheLimits() {
        StabilityDialog dialog(simcore::ParameterSet(SceneKind::Spring1d));
        dialog.setDuration(1.0);
        QSignalSpy finished(&dialog, &StudyDialogBase::finished);
        dialog.start();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, testsupport::kHangGuardMs);
        QCOMPARE(int(dialog.rows().size()), 4);
        QCOMPARE(dialog.table()->rowCount(), 4);
        QCOMPARE(dialog.plot()->graphCount(), 2);  // measured and predicted
        double euler = 0, rk4 = 0;
        for (const auto& r : dialog.rows()) {
            if (r.integrator == "euler") euler = r.stable;
            if (r.integrator == "rk4") rk4 = r.stable;
        }
        QVERIFY2(rk4 > euler, "RK4 is stable at larger steps than explicit Euler");
        if (qEnvironmentVariableIsSet("ELASTIC_LAB_SHOT_DIR"))
            dialog.grab().save(qEnvironmentVariable("ELASTIC_LAB_SHOT_DIR") + "/stability.png");
    }

    void plotExports() {
        QTemporaryDir dir;
        PlotDock dock;
        dock.setScene(SceneKind::Ring2d);
        const auto rows = runRows(SceneKind::Ring2d, 30);
        dock.appendRows(rows, 0, int(rows.size()));
        dock.replotNow();
        const QList<QPair<QString, QByteArray>> formats = {
            {"p.png", QByteArray("\x89PNG")}, {"p.svg", QByteArray("<?xml")}, {"p.pdf", QByteArray("%PDF")}};
        for (const auto& [name, magic] : formats) {
            const QString path = dir.filePath(name);
            QCOMPARE(writePlots(path, dock.plots(), dock.specs()), QString());
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QByteArray data = f.readAll();
            QVERIFY2(data.startsWith(magic), qPrintable(name));
            QVERIFY(data.size() > 1000);
            if (name.endsWith("svg")) QVERIFY(data.count("<polyline") == 2 + 2 + 8);  // energy: 8 lines with contact
        }
    }
};

QTEST_MAIN(TestGuiPlots)
#include "test_gui_plots.moc"
