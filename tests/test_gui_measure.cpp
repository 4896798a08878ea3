// Measuring in the view (issue 25): a right-click on a particle or the body plots its height,
// speed, centre-of-mass height and speed or the layers' separation against time (the Measured
// dock), velocity arrows beside the force arrows, and a ruler that measures a distance in the
// view's plane. Needs OpenGL: runs under Xvfb on xcb.
#include <cmath>
#include <cstdio>
#include <memory>

#include <QAction>
#include <QApplication>
#include <QMenu>
#include <QMouseEvent>
#include <QTest>

#include "test_support.h"
#include "ui/camera.h"
#include "ui/main_window.h"
#include "ui/measure_plot_dock.h"
#include "ui/simulation_controller.h"
#include "ui/tracked.h"
#include "ui/viewport.h"

using namespace elui;
using simcore::SceneKind;

namespace {

bool waitForScene(MainWindow& w, SceneKind kind) {
    return testsupport::waitUntil([&] {
        const FramePtr& f = w.controller()->latest();
        return f && f->scene->kind == kind && !w.viewports().empty() && w.viewports().front()->frame() == f;
    });
}

bool runTo(MainWindow& w, double t) {
    w.controller()->runUntil(t);
    return testsupport::waitUntil([&] {
        const FramePtr f = w.controller()->latest();
        return !w.controller()->running() && f && f->lanes[0].diagnostics.time >= t - 1e-9 &&
               w.viewports().front()->frame() == f;
    });
}

QAction* actionNamed(QMenu* menu, const QString& text) {
    for (QAction* a : menu->actions())
        if (a->text() == text) return a;
    return nullptr;
}

// Pixels of the velocity arrows' colour (a clear blue: 0.05, 0.45, 0.75).
int velocityBlue(const QImage& image) {
    const QImage img = image.convertToFormat(QImage::Format_RGB32);
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QRgb p = img.pixel(x, y);
            if (qRed(p) < 50 && qGreen(p) > 85 && qGreen(p) < 145 && qBlue(p) > 160 && qBlue(p) < 225) ++n;
        }
    return n;
}

void mouse(QWidget* w, QEvent::Type type, Qt::MouseButton button, const QPointF& at) {
    const Qt::MouseButtons held = type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::MouseButtons(button);
    QMouseEvent e(type, at, w->mapToGlobal(at), button, held, Qt::NoModifier);
    QCoreApplication::sendEvent(w, &e);
}

// A shown window running the default ring, its first view drawn.
std::unique_ptr<MainWindow> ringWindow() {
    auto w = std::make_unique<MainWindow>(false);
    w->resize(1200, 800);
    w->show();
    if (!QTest::qWaitForWindowExposed(w.get(), testsupport::kHangGuardMs)) return nullptr;
    w->startScene(simcore::ParameterSet(SceneKind::Ring2d), {"rk4"});
    if (!waitForScene(*w, SceneKind::Ring2d)) return nullptr;
    return w;
}

}  // namespace

class TestGuiMeasure : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY2(Viewport::openGLAvailable(), "OpenGL 3.3 core is needed (run under xvfb-run)"); }

    void rightClickPlotsWhatIsUnderTheCursor() {
        const auto window = ringWindow();
        QVERIFY(window);
        MainWindow& w = *window;
        Viewport* v = w.viewports().front();
        // The particle under a pixel: particle 5 drawn where its position projects.
        const FramePtr f0 = w.controller()->latest();
        const int target = 5;
        const QMatrix4x4 mvp = v->camera().projection(v->size()) * v->camera().view();
        const auto& x = f0->lanes[0].positions;
        const QVector3D ndc = mvp.map(QVector3D(x[3 * target], x[3 * target + 1], x[3 * target + 2]));
        const QPointF pixel((ndc.x() + 1) * 0.5 * v->width(), (1 - ndc.y()) * 0.5 * v->height());
        QCOMPARE(v->particleAt(pixel), target);
        QCOMPARE(v->particleAt(QPointF(2, 2)), -1);  // a corner of the view: nothing

        // A right click (no drag) asks for the menu of that particle.
        int asked = -2;
        connect(v, &Viewport::contextRequested, this, [&](const QPoint&, int particle) { asked = particle; },
                Qt::SingleShotConnection);
        mouse(v, QEvent::MouseButtonPress, Qt::RightButton, pixel);
        mouse(v, QEvent::MouseButtonRelease, Qt::RightButton, pixel);
        QCOMPARE(asked, target);
        // The menu (as the click shows it; closed here) offers the particle, its layer and the body.
        QApplication::processEvents();
        for (QMenu* open : w.findChildren<QMenu*>("viewContextMenu")) open->close();
        QMenu* menu = w.viewContextMenu(target);
        for (const QString& text : {QStringLiteral("Plot its height"), QStringLiteral("Plot its speed"),
                                    QStringLiteral("Plot the centre-of-mass height"),
                                    QStringLiteral("Plot the centre-of-mass speed"),
                                    QStringLiteral("Plot the layers' separation")})
            QVERIFY2(actionNamed(menu, text), qPrintable(text));
        const bool outer = f0->scene->topology.layer[target] == simcore::Layer::Outer;
        QVERIFY(actionNamed(menu, outer ? "Plot the outer layer's centre height" : "Plot the inner layer's centre height"));
        QVERIFY(actionNamed(menu, "Velocity vectors"));
        QVERIFY(actionNamed(menu, "Ruler (drag to measure)"));
        actionNamed(menu, "Plot its height")->trigger();
        actionNamed(menu, "Plot its speed")->trigger();
        actionNamed(menu, "Plot the centre-of-mass height")->trigger();
        actionNamed(menu, "Plot the layers' separation")->trigger();
        actionNamed(menu, "Plot its height")->trigger();  // twice: one curve
        delete menu;
        MeasurePlotDock* dock = w.measureDock();
        QVERIFY(!dock->isHidden());
        QCOMPARE(int(dock->quantities().size()), 4);

        // Single steps (the dock samples the frames shown; one frame per step here, whatever the
        // machine's speed): a point per step, and the last values are the last frame's own,
        // computed independently here.
        const int before = std::max(0, dock->pointCount(0));  // -1: no curve before the first frame
        for (int k = 1; k <= 8; ++k) {
            w.controller()->step();
            QVERIFY(testsupport::waitUntil([&] { return dock->pointCount(0) >= before + k; }));
        }
        QVERIFY(testsupport::waitUntil([&] { return w.viewports().front()->frame() == w.controller()->latest(); }));
        const FramePtr f = w.controller()->latest();
        QCOMPARE(dock->curveNames(), (QStringList{"height of particle 5", "speed of particle 5",
                                                  "centre-of-mass height", "layers' separation"}));
        for (int c = 0; c < 4; ++c) QVERIFY2(dock->pointCount(c) >= 8, qPrintable(QString::number(dock->pointCount(c))));
        const LaneFrame& lane = f->lanes[0];
        const double floor = f->scene->boxCentre.y() - f->parameters.get(simcore::Param::Box);
        QVERIFY(std::abs(dock->lastValue(0) - (lane.positions[3 * target + 1] - floor)) < 1e-5);
        const double speed = std::hypot(lane.velocities[3 * target], lane.velocities[3 * target + 1], lane.velocities[3 * target + 2]);
        QVERIFY(std::abs(dock->lastValue(1) - speed) < 1e-5);
        QVERIFY(speed > 0.0);  // falling
        // The centre of mass with the masses (equal here: the plain mean) and its height.
        double yMean = 0.0;
        for (int i = 0; i < f->scene->topology.particleCount(); ++i) yMean += lane.positions[3 * std::size_t(i) + 1];
        yMean /= f->scene->topology.particleCount();
        QVERIFY2(std::abs(dock->lastValue(2) - (yMean - floor)) < 1e-4,
                 qPrintable(QString("%1 vs %2").arg(dock->lastValue(2)).arg(yMean - floor)));
        QVERIFY(dock->lastValue(2) < 2.5);  // the centre started 2.5 m above the floor and falls
        QVERIFY(dock->lastValue(3) >= 0.0);
        // A reset clears the curves; the quantities stay.
        w.controller()->reset();
        QVERIFY(testsupport::waitUntil([&] { return dock->pointCount(0) <= 1; }));
        QCOMPARE(int(dock->quantities().size()), 4);
        dock->removeAll();
        QVERIFY(dock->curveNames().isEmpty());
    }

    void velocityArrowsAreDrawn() {
        const auto window = ringWindow();
        QVERIFY(window);
        MainWindow& w = *window;
        QVERIFY(runTo(w, 0.25));  // falling: every particle moves
        Viewport* v = w.viewports().front();
        ViewOptions o;
        w.setViewOptions(o);
        const int without = velocityBlue(v->grabFramebuffer());
        o.velocities = true;
        w.setViewOptions(o);
        const int with = velocityBlue(v->grabFramebuffer());
        QVERIFY2(with > without + 200, qPrintable(QString("%1 blue pixels with arrows, %2 without").arg(with).arg(without)));
        // Beside the force arrows, not instead of them.
        o.forces = true;
        w.setViewOptions(o);
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->latest()->lanes[0].forces.empty(), testsupport::kHangGuardMs);
        QVERIFY(testsupport::waitUntil([&] { return v->frame() == w.controller()->latest(); }));
        QVERIFY(velocityBlue(v->grabFramebuffer()) > without + 200);
    }

    void theRulerMeasuresInTheViewPlane() {
        const auto window = ringWindow();
        QVERIFY(window);
        MainWindow& w = *window;
        Viewport* v = w.viewports().front();
        ViewOptions o;
        o.ruler = true;
        w.setViewOptions(o);
        // Drag 200 px to the right and 100 px up: in 2D the view is orthographic, so the ruler
        // is (200, 100) px times the world size of a pixel.
        const QPointF a(300, 400), b(500, 300);
        mouse(v, QEvent::MouseButtonPress, Qt::LeftButton, a);
        QTest::mouseMove(v, b.toPoint());
        mouse(v, QEvent::MouseMove, Qt::LeftButton, b);
        mouse(v, QEvent::MouseButtonRelease, Qt::LeftButton, b);
        const double perPixel = v->camera().worldPerPixel(v->size());
        const double expected = std::hypot(200.0, 100.0) * perPixel;
        QVERIFY2(std::abs(v->rulerLength() - expected) < 1e-3 * expected,
                 qPrintable(QString("%1 vs %2").arg(v->rulerLength()).arg(expected)));
        QVERIFY2(v->rulerText().startsWith(QString::number(expected, 'f', 3) + " m"), qPrintable(v->rulerText()));
        QVERIFY(v->rulerText().contains(QString("Δx %1").arg(200 * perPixel, 0, 'f', 3)));
        // The ruler took the drag: nothing was grabbed, and the body is not pulled.
        QVERIFY(!w.controller()->latest()->lanes[0].pointer.active);
        // Off: the label goes.
        o.ruler = false;
        w.setViewOptions(o);
        QVERIFY(v->rulerText().isEmpty());
    }

    void documentationPicture() {
        // docs/gui.md's picture (with ELASTIC_LAB_SHOT_DIR set): the Measured dock after a
        // run with three quantities, velocity arrows, a ruler across the ring, and the
        // right-click menu as a separate image (a popup is a window of its own).
        if (!qEnvironmentVariableIsSet("ELASTIC_LAB_SHOT_DIR")) QSKIP("set ELASTIC_LAB_SHOT_DIR to write the picture");
        const QString dir = qEnvironmentVariable("ELASTIC_LAB_SHOT_DIR");
        const auto window = ringWindow();
        QVERIFY(window);
        MainWindow& w = *window;
        w.resize(1500, 900);
        Tracked height, speed, centre;
        height.kind = Tracked::Kind::ParticleHeight;
        height.particle = 15;
        speed.kind = Tracked::Kind::ParticleSpeed;
        speed.particle = 15;
        centre.kind = Tracked::Kind::CentreHeight;
        for (const Tracked& t : {height, speed, centre}) w.plotQuantity(t);
        // Step by step (a point per step on a loaded machine too) to t = 2 s.
        while (w.controller()->latest()->lanes[0].diagnostics.time < 2.0) {
            const quint64 serial = w.controller()->latest()->serial;
            w.controller()->step();
            QVERIFY(testsupport::waitUntil([&] { return w.viewports().front()->frame()->serial > serial; }));
        }
        ViewOptions o;
        o.velocities = true;
        o.ruler = true;
        w.setViewOptions(o);
        Viewport* v = w.viewports().front();
        const QPointF a(v->width() * 0.22, v->height() * 0.80), b(v->width() * 0.78, v->height() * 0.80);
        mouse(v, QEvent::MouseButtonPress, Qt::LeftButton, a);
        mouse(v, QEvent::MouseMove, Qt::LeftButton, b);
        mouse(v, QEvent::MouseButtonRelease, Qt::LeftButton, b);
        QTest::qWait(300);
        QVERIFY(w.grab().save(dir + "/measuring-window.png"));
        QMenu* menu = w.viewContextMenu(15);
        menu->popup(v->mapToGlobal(QPoint(int(v->width() * 0.6), int(v->height() * 0.35))));
        QTest::qWait(200);
        QVERIFY(menu->grab().save(dir + "/measuring-menu.png"));
        std::printf("menu at %d,%d in the window\n", v->mapTo(&w, QPoint(int(v->width() * 0.6), int(v->height() * 0.35))).x(),
                    v->mapTo(&w, QPoint(int(v->width() * 0.6), int(v->height() * 0.35))).y());
        delete menu;
    }
};

QTEST_MAIN(TestGuiMeasure)
#include "test_gui_measure.moc"
