// The stability map dock (issue 16): it shows the region and the body's DT·λ, its margin in
// words follows DT and the integrator, "Try it" marks the measured limit, and the main window
// opens it by name (--docks stability-map).
#include <QtTest>

#include <complex>

#include <QPushButton>

#include "qcustomplot.h"
#include "ui/lessons.h"
#include "ui/main_window.h"
#include "ui/simulation_controller.h"
#include "simlab/stability.h"
#include "ui/stability_map_dock.h"
#include "simlab/stability_region.h"
#include "test_support.h"
#include "ui/main_window.h"
#include "ui/simulation_controller.h"
#include "ui/stability_map_dock.h"

using namespace elui;
using simcore::ParameterSet;
using simcore::SceneKind;
using Complex = std::complex<double>;

namespace {

ParameterSet spring(double dt) {
    ParameterSet p(SceneKind::Spring1d);
    if (p.set(simcore::Param::Dt, dt)) qFatal("dt");
    return p;
}

// Sets the state and waits for the result it asks for.
void showState(StabilityMapDock& dock, const ParameterSet& p, const QString& integrator) {
    dock.setState(p, integrator);
    QVERIFY(testsupport::waitUntil([&] {
        return !dock.computing() && dock.dt() == p.get(simcore::Param::Dt) && dock.integrator() == integrator &&
               dock.marginText().startsWith(integrator + ":");
    }));
}

}  // namespace

class TestGuiStabilityMap : public QObject {
    Q_OBJECT
private slots:
    void stabilityMapHasEqualScales() {
        // Both axes of the complex plane have the same units per pixel in a dock of any shape,
        // as drawn: Euler's disc is a circle.
        for (const QSize size : {QSize(300, 700), QSize(700, 320), QSize(420, 420)}) {
            StabilityMapDock map;
            map.resize(size);
            map.show();
            map.setState(simcore::ParameterSet(SceneKind::Spring1d), "euler");
            QVERIFY(testsupport::waitUntil([&] { return !map.computing() && map.resultSerial() > 0; }));
            QCustomPlot* plot = map.plot();
            plot->replot();
            const QRect rect = plot->axisRect()->rect();
            const double px = plot->xAxis->range().size() / rect.width(), py = plot->yAxis->range().size() / rect.height();
            QVERIFY2(std::abs(px / py - 1.0) < 0.01, qPrintable(QString("%1x%2: %3 vs %4 per pixel").arg(size.width()).arg(size.height()).arg(px).arg(py)));
        }
    }

    void showsTheRegionAndThePointsAndFollowsDt() {
        StabilityMapDock dock;
        dock.resize(420, 520);
        dock.show();
        showState(dock, spring(0.001), "rk4");
        // The fixed spring: one free coordinate, the pair lambda = -c/2 ± i sqrt(w^2 - c^2/4).
        QCOMPARE(dock.pointCount(), 2);
        QVERIFY(dock.boundaryPointCount() > 200);
        const simlab::LinearModes modes = simlab::linearModes(spring(0.001));
        for (int i = 0; i < 2; ++i) {
            const Complex z = dock.point(i);
            double nearest = 1e300;
            for (const Complex& l : modes.eigenvalues) nearest = std::min(nearest, std::abs(z - 0.001 * l));
            QVERIFY2(nearest < 1e-12, qPrintable(QString("point %1 + %2i").arg(z.real()).arg(z.imag())));
        }
        QVERIFY2(dock.marginText().contains("DT can grow"), qPrintable(dock.marginText()));
        QVERIFY(dock.methodText().contains("exact spectrum"));
        const double before = dock.marginFactor();
        const QString text = dock.marginText();
        // Twice the step: every point twice as far out, half the margin, new words.
        showState(dock, spring(0.002), "rk4");
        QVERIFY(std::abs(dock.marginFactor() * 2.0 / before - 1.0) < 1e-6);
        QVERIFY(dock.marginText() != text);
        QVERIFY(std::abs(dock.point(0) - 2.0 * 0.001 * modes.eigenvalues[0]) < 1e-12 ||
                std::abs(dock.point(0) - 2.0 * 0.001 * modes.eigenvalues[1]) < 1e-12);
        // Beyond the limit.
        showState(dock, spring(0.2), "rk4");
        QVERIFY2(dock.marginText().contains("already outside"), qPrintable(dock.marginText()));
        // Another integrator: another region and other words.
        const int rk4Boundary = dock.boundaryPointCount();
        showState(dock, spring(0.2), "implicit-euler");
        QVERIFY2(dock.marginText().contains("No DT limit"), qPrintable(dock.marginText()));
        QVERIFY(dock.boundaryPointCount() != rk4Boundary);
        QVERIFY(dock.methodText().contains("A-stable"));
        // A stiffer spring moves the points (the body is linearised again).
        ParameterSet stiff = spring(0.001);
        QVERIFY(!stiff.set(simcore::Param::Ks, 3200.0));
        showState(dock, stiff, "rk4");
        QVERIFY(dock.marginFactor() < 0.6 * before);
        // No fixed region: the points still, and what holds in words.
        showState(dock, spring(0.001), "cvode-bdf");
        QCOMPARE(dock.boundaryPointCount(), 0);
        QCOMPARE(dock.pointCount(), 2);
        QVERIFY(!dock.tryButton()->isEnabled());
    }

    void tryItMarksTheMeasuredLimit() {
        StabilityMapDock dock;
        dock.resize(420, 520);
        dock.show();
        showState(dock, spring(0.001), "rk4");
        QVERIFY(dock.tryButton()->isEnabled());
        QVERIFY(!dock.measuredMark());
        const double predicted = dock.marginFactor() * 0.001;
        QTest::mouseClick(dock.tryButton(), Qt::LeftButton);
        QVERIFY(dock.scanning());
        QCOMPARE(dock.tryButton()->text(), QStringLiteral("Cancel"));
        QVERIFY(testsupport::waitUntil([&] { return !dock.scanning(); }));
        QVERIFY(dock.measuredMark().has_value());
        QVERIFY2(dock.measuredText().startsWith("Measured"), qPrintable(dock.measuredText()));
        // The mark: the limiting mode at the measured DT, on the same ray as its dot, within
        // 10 % of where the region's boundary crosses that ray.
        const Complex mark = *dock.measuredMark();
        const Complex z = dock.point(0).imag() > 0 ? dock.point(0) : dock.point(1);
        QVERIFY(std::abs(mark / std::abs(mark) - z / std::abs(z)) < 1e-9);
        const double measured = std::abs(mark) / std::abs(z) * 0.001;
        QVERIFY2(measured > 0.9 * predicted && measured < 1.1 * predicted,
                 qPrintable(QString("measured %1 s, predicted %2 s").arg(measured).arg(predicted)));
        // It holds whatever DT is: kept when DT changes, dropped when the body changes.
        showState(dock, spring(0.002), "rk4");
        QVERIFY(dock.measuredMark().has_value());
        ParameterSet soft = spring(0.002);
        QVERIFY(!soft.set(simcore::Param::Ks, 400.0));
        showState(dock, soft, "rk4");
        QVERIFY(!dock.measuredMark().has_value());
        // Verlet names no limiting mode (its margin is the step matrix's): the cross marks the
        // fastest mode at the measured DT.
        showState(dock, spring(0.001), "verlet");
        QVERIFY(dock.tryButton()->isEnabled());
        QTest::mouseClick(dock.tryButton(), Qt::LeftButton);
        QVERIFY(testsupport::waitUntil([&] { return !dock.scanning(); }));
        QVERIFY(dock.measuredMark().has_value());
        QVERIFY2(dock.measuredText().contains("fastest mode"), qPrintable(dock.measuredText()));
    }

    void largeBodiesUseTheIterativeEstimate() {
        // 700 + 700 particles, 2800 free coordinates: beyond the dense limit (1200), the points
        // are Arnoldi's Ritz values and the dock says so.
        StabilityMapDock dock;
        dock.resize(420, 520);
        dock.show();
        ParameterSet p(SceneKind::Ring2d);
        QVERIFY(!p.set(simcore::Param::Particles, 700));
        showState(dock, p, "rk4");
        QVERIFY2(dock.methodText().contains("Arnoldi"), qPrintable(dock.methodText()));
        QCOMPARE(dock.pointCount(), 80);
        QVERIFY(dock.marginText().startsWith("rk4: DT"));
    }

    void mainWindowOpensTheDockAndFeedsIt() {
#if defined(__SANITIZE_THREAD__)
        // As test_gui_plots' energy docks: a shown main window makes Qt Gui convert its backing
        // image on Qt's own pool threads, which ThreadSanitizer cannot see synchronised.
        QSKIP("Qt's threaded image conversion is invisible to ThreadSanitizer");
#endif
        MainWindow window(false);
        QVERIFY(MainWindow::dockNames().contains("stability-map"));
        QVERIFY(window.stabilityMapDock()->isHidden());
        window.show();
        window.startScene(ParameterSet(SceneKind::Ring2d), {"rk4"});
        QVERIFY(window.openDock("stability-map"));
        StabilityMapDock* dock = window.stabilityMapDock();
        QVERIFY(dock->isVisible());
        QTRY_VERIFY_WITH_TIMEOUT(dock->pointCount() > 0 && !dock->computing(), testsupport::kHangGuardMs);
        const double dt = window.controller()->parameters().get(simcore::Param::Dt);
        QTRY_COMPARE_WITH_TIMEOUT(dock->dt(), dt, testsupport::kHangGuardMs);
        const QString text = dock->marginText();
        window.controller()->setParameter("dt", dt / 2.0);
        QTRY_VERIFY_WITH_TIMEOUT(dock->dt() == dt / 2.0 && dock->marginText() != text, testsupport::kHangGuardMs);
        window.controller()->setIntegrator("verlet");
        QTRY_VERIFY_WITH_TIMEOUT(dock->marginText().startsWith("verlet:"), testsupport::kHangGuardMs);
    }

    // Side by side (issue 25): every view on one picture; the view with the smallest margin is
    // the filled one. The stiff-springs lesson (implicit Euler beside rk4 at ks = 1e6, DT 0.01)
    // must show rk4, the view that turns red, not implicit Euler.
    void sideBySideMapsEveryView() {
        const Lesson* lesson = findLesson("stiff-springs");
        QVERIFY(lesson);
        const ParameterSet p = lesson->preset.parameters();
        MainWindow window(false);
        window.show();
        QVERIFY(window.openDock("stability-map"));
        window.applyLesson(*lesson);
        StabilityMapDock* dock = window.stabilityMapDock();
        QVERIFY(testsupport::waitUntil([&] {
            return dock->resultSerial() > 0 && !dock->computing() && !dock->overlaidIntegrators().isEmpty();
        }));
        QCOMPARE(lesson->preset.integrators, (QStringList{"implicit-euler", "rk4"}));
        QCOMPARE(dock->primaryIntegrator(), QString("rk4"));
        QCOMPARE(dock->overlaidIntegrators(), QStringList{"implicit-euler"});
        QVERIFY(dock->overlayCurveCount() >= 1);
        QVERIFY(dock->marginFactor() < 1.0);  // rk4 is outside at DT 0.01
        const QString text = dock->marginText();
        QVERIFY2(text.startsWith("View 2, rk4 (filled): DT is already outside"), qPrintable(text));
        QVERIFY2(text.contains("View 1, implicit-euler (dashed): No DT limit"), qPrintable(text));
        // rk4's figure is the one verdict's.
        const double limit = simlab::stabilityVerdict(simlab::stabilityModes(p), "rk4", p.get(simcore::Param::Dt)).limit;
        QVERIFY(std::abs(dock->marginFactor() * p.get(simcore::Param::Dt) / limit - 1.0) < 1e-9);
        // One view again: no overlay.
        StabilityMapDock alone;
        alone.resize(420, 520);
        alone.show();
        showState(alone, p, "implicit-euler");
        QCOMPARE(alone.primaryIntegrator(), QString("implicit-euler"));
        QCOMPARE(alone.overlayCurveCount(), 0);
    }
};

QTEST_MAIN(TestGuiStabilityMap)
#include "test_gui_stability_map.moc"
