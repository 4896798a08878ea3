// One stability verdict (issue 25): the pre-run banner, the failure banner, the stability
// map, the CLI's `stability` and (in test_python) Python give the same figure for one body,
// each method its own; the failure banner tells numerics (a smaller step runs through) from
// physics (the body collapses at every step: heavy-inner with mass_inner = 10).
#include <QtTest>

#include <cmath>

#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QTemporaryDir>

#include "cli_process.h"
#include "ui/failure_banner.h"
#include "ui/lessons.h"
#include "ui/main_window.h"
#include "ui/simulation_controller.h"
#include "simlab/stability.h"
#include "ui/stability_map_dock.h"
#include "simlab/stability_region.h"
#include "test_support.h"

using namespace elui;
using simcore::Param;
using simcore::ParameterSet;
using simcore::SceneKind;

namespace {

ParameterSet sphere2(double dt) {
    ParameterSet p(SceneKind::Sphere3d);
    if (p.set(Param::Subdivisions, 2) || p.set(Param::Dt, dt)) qFatal("sphere");
    return p;
}

ParameterSet stiffRing(double dt) {
    ParameterSet p(SceneKind::Ring2d);
    if (p.set(Param::Ks, 1e6) || p.set(Param::Dt, dt)) qFatal("ring");
    return p;
}

double verdictLimit(const ParameterSet& p, const std::string& integrator) {
    return simlab::stabilityVerdict(simlab::stabilityModes(p), integrator, p.get(Param::Dt)).limit;
}

// The `predicted` column of `elastic-lab-cli stability` for each integrator (its CSV, full precision).
std::map<QString, double> cliPredicted(const QStringList& sets, const QString& integrators) {
    QTemporaryDir dir;
    const QString csv = dir.filePath("st.csv");
    QStringList args = {"stability", "--integrators", integrators, "--duration", "0.02", "--hmin", "0.001",
                        "--quiet", "--csv", csv};
    args += sets;
    const CliResult r = runCli(args);
    if (r.code != 0) qWarning("%s", qPrintable(r.err));
    std::map<QString, double> out;
    QFile f(csv);
    if (!f.open(QIODevice::ReadOnly)) return out;
    const QStringList lines = QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
    for (int i = 1; i < lines.size(); ++i) {
        const QStringList cells = lines[i].split(',');
        out[cells[0]] = cells[3] == "inf" ? INFINITY : cells[3].toDouble();
    }
    return out;
}

bool close(double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); }

}  // namespace

class TestStabilityVerdict : public QObject {
    Q_OBJECT
private slots:
    // The level-2 sphere at DT 0.01 (the case: nothing / 0.0063 / 0.00888 before).
    void everyDoorGivesTheSameFigure() {
        const ParameterSet p = sphere2(0.01);
        const double rk4 = verdictLimit(p, "rk4");
        const double euler = verdictLimit(p, "euler");
        QVERIFY(rk4 > 0.005 && rk4 < 0.01);  // DT 0.01 is above it: the pre-run banner must speak
        QVERIFY(euler > 0.0 && euler < 0.8 * rk4);  // each method its own region
        // Arnoldi on this 396-coordinate body: the exact dense spectrum gives the same figure.
        const simlab::LinearModes exact = simlab::linearModes(p, 100000, 100000);
        QVERIFY(std::abs(simlab::predictedStableStep("rk4", exact) / rk4 - 1.0) < 1e-6);
        // Pre-run banner (simlab's advice): the figure, printed as every door prints it.
        const auto advice = simlab::stabilityAdvice(simcore::Simulation(p, "rk4"));
        QVERIFY(advice);
        QVERIFY2(advice->message.find(simlab::limitText(rk4) + " s") != std::string::npos, advice->message.c_str());
        QCOMPARE(advice->suggestedDt, simlab::roundDownTwoDigits(0.9 * rk4));
        // Euler at 0.009 is told its own limit, not the rk4-like one.
        const ParameterSet p9 = sphere2(0.009);
        const auto eulerAdvice = simlab::stabilityAdvice(simcore::Simulation(p9, "euler"));
        QVERIFY(eulerAdvice);
        QVERIFY2(eulerAdvice->message.find(simlab::limitText(euler) + " s") != std::string::npos,
                 eulerAdvice->message.c_str());
        QVERIFY(eulerAdvice->message.find(simlab::limitText(rk4)) == std::string::npos);
        QVERIFY(!simlab::stabilityAdvice(simcore::Simulation(sphere2(0.0085), "rk4")));  // below rk4's limit
        // The map's margin.
        const simlab::LinearModes modes = simlab::stabilityModes(p);
        for (const char* name : {"rk4", "euler"}) {
            const auto margin = simlab::stepMargin(name, modes, simlab::spectrumPoints(modes), 0.01);
            QVERIFY(close(margin.factor * 0.01, verdictLimit(p, name)));
        }
        // The failure banner's check (its verdict on the failed step).
        simcore::Simulation sim(p, "rk4");
        const auto check = simlab::checkFailure(sim.snapshot(), simcore::Failure{"test", 3, 0.03});
        QCOMPARE(check.verdict.limit, rk4);
        // The CLI, linearised at the rest shape although its trials start perturbed.
        const auto cli = cliPredicted({"--scene", "sphere3d", "--set", "subdivisions=2", "--set", "dt=0.01"},
                                      "rk4,euler");
        QCOMPARE(cli.size(), std::size_t(2));
        QVERIFY2(close(cli.at("rk4"), rk4), qPrintable(QString::number(cli.at("rk4"), 'g', 17)));
        QVERIFY(close(cli.at("euler"), euler));
    }

    // The same body in the GUI: pre-run banner, map and failure banner name one figure.
    void theWindowSaysItOnce() {
        const ParameterSet p = stiffRing(0.01);
        const double rk4 = verdictLimit(p, "rk4");
        const QString figure = QString::fromStdString(simlab::limitText(rk4));
        MainWindow w(false);
        w.resize(1280, 800);
        w.show();
        w.openDock("stability-map");
        w.startScene(p, {"rk4"});
        QVERIFY(testsupport::waitUntil([&] { return !w.stabilityText().isEmpty(); }));
        QVERIFY2(w.stabilityText().contains(figure + " s"), qPrintable(w.stabilityText()));
        StabilityMapDock* map = w.stabilityMapDock();
        QVERIFY(testsupport::waitUntil([&] { return map->resultSerial() > 0 && !map->computing() && map->dt() == 0.01; }));
        QVERIFY(close(map->marginFactor() * 0.01, rk4));
        QVERIFY2(map->marginText().contains(QString::number(rk4, 'g', 3)), qPrintable(map->marginText()));
        // Run anyway: it blows up; the banner checks at a smaller step and gives the same figure.
        w.controller()->setSpeed(Speed::AsFastAsPossible);
        w.controller()->run();
        FailureBanner* banner = w.failureBanner();
        QVERIFY(testsupport::waitUntil([&] { return !banner->isHidden() && !banner->checking() && banner->check(); }));
        QVERIFY(banner->check()->checked);
        QVERIFY(!banner->check()->physical);
        QVERIFY2(w.failureText().contains(figure + " s"), qPrintable(w.failureText()));
        QVERIFY(!w.failureText().contains("Halve"));
        QVERIFY(banner->smallerDtButton()->isVisibleTo(banner));
        QVERIFY(banner->check()->workingDt > 0.0 && banner->check()->workingDt <= 0.0025);
        // The step offered is one that ran through: the banner's button sets it.
        QSignalSpy asked(banner, &FailureBanner::setDtAndReset);
        banner->smallerDtButton()->click();
        QCOMPARE(asked.count(), 1);
        QCOMPARE(asked.at(0).at(0).toDouble(), banner->check()->workingDt);
    }

    // heavy-inner with mass_inner = 10: the inner layer collapses at t ~ 0.91 s at any step.
    void theBodyItselfCollapses() {
        const Lesson* lesson = findLesson("heavy-inner");
        QVERIFY(lesson);
        ParameterSet p = lesson->preset.parameters();
        QVERIFY(!p.set(Param::MassInner, 10.0));
        MainWindow w(false);
        w.resize(1280, 800);
        w.show();
        const int width = w.width();
        w.startScene(p, lesson->preset.integrators);
        w.controller()->setSpeed(Speed::AsFastAsPossible);
        w.controller()->run();
        FailureBanner* banner = w.failureBanner();
        QVERIFY(testsupport::waitUntil([&] { return !banner->isHidden() && !banner->checking() && banner->check(); }));
        const simlab::FailureCheck& check = *banner->check();
        QVERIFY(check.checked);
        QVERIFY(check.physical);
        QVERIFY(check.rerunDt <= p.get(Param::Dt) / 4.0);
        QVERIFY(std::abs(check.rerunFailure->time - 0.91) < 0.05);
        QVERIFY2(w.failureText().contains("The body itself collapses — no step size will save it"),
                 qPrintable(w.failureText()));
        // Only remedies that work: no DT button, no integrator button.
        QVERIFY(!banner->smallerDtButton()->isVisibleTo(banner));
        QVERIFY(!banner->implicitButton()->isVisibleTo(banner));
        QVERIFY(banner->resetButton()->isVisibleTo(banner));
        // Laid out in lines across the view: the text spans the banner, a few lines high, and
        // the window did not widen.
        QVERIFY(testsupport::waitUntil([&] { return banner->label()->width() > 0.9 * (banner->width() - 20); }));
        const int lineHeight = banner->label()->fontMetrics().lineSpacing();
        QVERIFY2(banner->label()->height() <= 8 * lineHeight,
                 qPrintable(QString("%1 px for lines of %2").arg(banner->label()->height()).arg(lineHeight)));
        QCOMPARE(w.width(), width);
    }
};

QTEST_MAIN(TestStabilityVerdict)
#include "test_stability_verdict.moc"
