// Rendering (needs OpenGL: runs under Xvfb on xcb). Every scene is drawn and the image is
// checked for content: the body, both layers in their colours, the springs.
#include <cmath>

#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QImage>
#include <QLabel>
#include <QMouseEvent>
#include <QProcess>
#include <QRegularExpression>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QTest>

#include "simcore/scenes.h"
#include "simcore/world.h"
#include "simlab/scenefile.h"
#include "test_support.h"
#include "ui/export.h"
#include "ui/gl_format.h"
#include "ui/main_window.h"
#include "ui/plot_series.h"
#include "ui/presets.h"
#include "ui/run_dock.h"
#include "ui/simulation_controller.h"
#include "ui/viewport.h"

using namespace elui;
using simcore::SceneKind;

Q_DECLARE_METATYPE(simcore::SceneKind)

namespace {

struct Census {
    double changed = 0;  // fraction of pixels that differ from the background
    double bluish = 0;   // inner layer colour
    double orange = 0;   // outer layer colour
    double dark = 0;     // springs, particles
    int colours = 0;
};

Census census(const QImage& image) {
    Census c;
    const QImage img = image.convertToFormat(QImage::Format_RGB32);
    const QRgb background = img.pixel(3, img.height() / 2);
    QSet<QRgb> seen;
    const double n = double(img.width()) * img.height();
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QRgb p = img.pixel(x, y);
            if (seen.size() < 5000) seen.insert(p);
            if (p != background) c.changed += 1 / n;
            const int r = qRed(p), g = qGreen(p), b = qBlue(p);
            if (b > r + 50 && b > g) c.bluish += 1 / n;
            if (r > b + 60 && r > g) c.orange += 1 / n;
            if (r + g + b < 200) c.dark += 1 / n;
        }
    c.colours = int(seen.size());
    return c;
}

bool waitForScene(MainWindow& w, SceneKind kind) {
    return testsupport::waitUntil([&] {
        const FramePtr& f = w.controller()->latest();
        return f && f->scene->kind == kind && !w.viewports().empty() && w.viewports().front()->frame() == f;
    });
}

// The newest frame has reached the first viewport (it draws that one on the next grab).
bool viewportShowsLatest(MainWindow& w) {
    return testsupport::waitUntil([&] { return w.viewports().front()->frame() == w.controller()->latest(); });
}

}  // namespace

class TestGuiRender : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QVERIFY2(Viewport::openGLAvailable(), "OpenGL 3.3 core is needed (run under xvfb-run)"); }

    void everySceneIsDrawn_data() {
        QTest::addColumn<SceneKind>("kind");
        for (const simcore::SceneInfo& s : simcore::sceneTable())
            QTest::newRow(std::string(s.name).c_str()) << s.kind;
    }
    void everySceneIsDrawn() {
        QFETCH(SceneKind, kind);
        MainWindow w(false);
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w, testsupport::kHangGuardMs));
        w.startScene(simcore::ParameterSet(kind), {"rk4"});
        QVERIFY(waitForScene(w, kind));
        Viewport* v = w.viewports().front();
        const QImage image = v->grabFramebuffer();
        QVERIFY(!image.isNull());
        const Census c = census(image);
        // Two particles on a spring cover little of the view; the layered bodies fill much of it.
        const double least = kind == SceneKind::Spring1d ? 0.004 : 0.03;
        QVERIFY2(c.changed > least, qPrintable(QString("only %1 of the pixels drawn").arg(c.changed)));
        QVERIFY2(c.colours > 20, qPrintable(QString("%1 colours").arg(c.colours)));
        QVERIFY2(c.dark > 0.001, "springs and particles are missing");
        if (simcore::hasGas(kind)) {
            // Inner (blue) and outer (orange) layers are both visible and distinct.
            QVERIFY2(c.bluish > 0.01, qPrintable(QString("inner layer: %1").arg(c.bluish)));
            QVERIFY2(c.orange > 0.01, qPrintable(QString("outer layer: %1").arg(c.orange)));
        }
        // Normals and force vectors add to the picture.
        ViewOptions more;
        more.normals = more.forces = true;
        w.setViewOptions(more);
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->latest()->lanes[0].forces.empty(), testsupport::kHangGuardMs);
        QVERIFY(viewportShowsLatest(w));
        const QImage extra = v->grabFramebuffer();
        QVERIFY(extra != image);
        // Hiding everything leaves (nearly) only the background and the box.
        ViewOptions none;
        none.springs[0] = none.springs[1] = none.springs[2] = false;
        none.faces = none.particles = none.box = false;
        w.setViewOptions(none);
        const Census empty = census(v->grabFramebuffer());
        QVERIFY2(empty.changed < 0.3 * c.changed, qPrintable(QString("%1 drawn with everything off").arg(empty.changed)));
    }

    void strainColouringChangesTheSprings() {
        MainWindow w(false);
        w.resize(1000, 700);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w, testsupport::kHangGuardMs));
        simcore::ParameterSet p(SceneKind::Ring2d);
        w.startScene(p, {"rk4"});
        QVERIFY(waitForScene(w, SceneKind::Ring2d));
        w.controller()->runUntil(0.6);  // squashed on the floor: springs strained
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->running() &&
                                     w.controller()->latest()->lanes[0].diagnostics.time > 0.59, testsupport::kHangGuardMs);
        QVERIFY(viewportShowsLatest(w));
        Viewport* v = w.viewports().front();
        ViewOptions o;
        o.faces = false;
        w.setViewOptions(o);
        const QImage plain = v->grabFramebuffer();
        o.strain = true;
        w.setViewOptions(o);
        const QImage strained = v->grabFramebuffer();
        const Census a = census(plain), b = census(strained);
        QVERIFY(plain != strained);
        QVERIFY2(b.bluish + b.orange > a.bluish + a.orange,
                 "strain colours (blue compressed, red stretched) should appear");
    }

    void sideBySideMakesOneViewPerIntegrator() {
        MainWindow w(false);
        w.resize(1500, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w, testsupport::kHangGuardMs));
        const Preset p = stabilityPresets().at(1);  // DT 0.03
        w.applyPreset(p);
        QTRY_COMPARE_WITH_TIMEOUT(int(w.viewports().size()), 3, testsupport::kHangGuardMs);
        QTRY_VERIFY_WITH_TIMEOUT(w.viewports()[2]->frame() != nullptr, testsupport::kHangGuardMs);
        for (Viewport* v : w.viewports()) {
            QTRY_VERIFY_WITH_TIMEOUT(v->isVisible() && v->width() > 100, testsupport::kHangGuardMs);
            QVERIFY(census(v->grabFramebuffer()).changed > 0.03);
        }
        QCOMPARE(w.controller()->latest()->parameters.get(simcore::Param::Dt), 0.03);
        // The Run dock's integrator is no one lane's: it shows none, and its placeholder says why.
        QComboBox* integrator = w.runDock()->integratorCombo();
        QTRY_COMPARE_WITH_TIMEOUT(integrator->currentIndex(), -1, testsupport::kHangGuardMs);
        QVERIFY(!integrator->isEnabled());
        QVERIFY(integrator->placeholderText().contains("side by side"));
        w.controller()->runUntil(2.0);
        // On the two-layer ring at DT 0.03 every explicit method blows up within a second
        // (measured with elastic-lab-cli); when all lanes have failed the run pauses by itself.
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->running() && w.controller()->latest()->lanes[2].failure, testsupport::kHangGuardMs);
        FramePtr f = w.controller()->latest();
        for (const LaneFrame& lane : f->lanes) {
            QVERIFY(lane.failure.has_value());
            for (float x : lane.positions) QVERIFY(std::isfinite(x));
        }
        // At DT 0.003 none fails, all reach the same time and they differ.
        w.applyPreset(stabilityPresets().at(0));
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest()->parameters.get(simcore::Param::Dt) == 0.003 &&
                                     !w.controller()->latest()->lanes[0].failure, testsupport::kHangGuardMs);
        w.controller()->runUntil(1.0);
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->running() &&
                                     w.controller()->latest()->lanes[0].diagnostics.time > 0.99, testsupport::kHangGuardMs);
        f = w.controller()->latest();
        for (const LaneFrame& lane : f->lanes) {
            QVERIFY(!lane.failure.has_value());
            QCOMPARE(lane.diagnostics.time, f->lanes[0].diagnostics.time);
        }
        QVERIFY(f->lanes[1].divergence > 0.0 && f->lanes[2].divergence > 0.0);
        w.singleView();
        QTRY_COMPARE_WITH_TIMEOUT(int(w.viewports().size()), 1, testsupport::kHangGuardMs);
        // One lane again: the combo is its integrator's, and editable.
        QTRY_COMPARE_WITH_TIMEOUT(integrator->currentText(), w.controller()->integrators().front(),
                                  testsupport::kHangGuardMs);
        QVERIFY(integrator->isEnabled());
    }

    void mouseDragGrabsAndPulls_data() {
        QTest::addColumn<SceneKind>("kind");
        QTest::newRow("ring2d") << SceneKind::Ring2d;
        QTest::newRow("sphere3d") << SceneKind::Sphere3d;
    }
    void distanceIsToTheLiveReferenceView() {
        // Euler fails at t = 0.98 s at DT 0.01; midpoint and rk4 run on. The distance is then
        // measured to midpoint (the first live view): rk4's view names it, midpoint's and the
        // failed view's show none (as the Run dock's "distance to view 2").
        MainWindow w(false);
        simcore::ParameterSet ring(SceneKind::Ring2d);
        QVERIFY(!ring.set(simcore::Param::Dt, 0.01));
        w.startScene(ring, {"euler", "midpoint", "rk4"});
        QTRY_COMPARE_WITH_TIMEOUT(int(w.viewports().size()), 3, testsupport::kHangGuardMs);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest() && w.controller()->latest()->lanes.size() == 3, testsupport::kHangGuardMs);
        w.controller()->runUntil(1.5);
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->running() &&
                                     w.controller()->latest()->lanes[1].diagnostics.time > 1.49, testsupport::kHangGuardMs);
        const FramePtr f = w.controller()->latest();
        QVERIFY(f->lanes[0].failure.has_value());
        QCOMPARE(f->lanes[2].divergenceReference, 1);
        QTRY_VERIFY_WITH_TIMEOUT(w.viewports()[2]->overlayText().contains("distance from midpoint"), testsupport::kHangGuardMs);
        QVERIFY2(!w.viewports()[1]->overlayText().contains("distance"), qPrintable(w.viewports()[1]->overlayText()));
        QVERIFY(!w.viewports()[0]->overlayText().contains("distance"));
        QVERIFY(w.viewports()[0]->overlayText().contains("Blew up"));
    }

    // A world side by side (issue 26): each view draws every body in its hue (body 1 orange,
    // body 2 blue) and its text gives its integrator, time, momentum and min_gap; euler's view
    // fails (bodies 1 and 2 intersect at t = 0.756 s at DT 0.006, as elastic-lab-cli run says)
    // with its own red line while rk4's runs on to the end.
    void aWorldSideBySide() {
        MainWindow w(false);
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w, testsupport::kHangGuardMs));
        simcore::WorldSpec spec = *simcore::worldScene("collide2d");
        for (const char* a : {"gravity=0", "dt=0.006"}) QVERIFY(!simcore::assignWorld(spec, a));
        w.startWorld(spec, {"euler", "rk4"});
        QTRY_COMPARE_WITH_TIMEOUT(int(w.viewports().size()), 2, testsupport::kHangGuardMs);
        w.controller()->runUntil(1.0);
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->running() && w.controller()->latest()->lanes.size() == 2 &&
                                     w.controller()->latest()->lanes[1].diagnostics.time >= 1.0 - 1e-9,
                                 testsupport::kHangGuardMs);
        const FramePtr f = w.controller()->latest();
        QVERIFY(f->lanes[0].failure && !f->lanes[1].failure);
        QVERIFY2(f->lanes[0].failure->reason.find("bodies 1 and 2 intersect") != std::string::npos,
                 f->lanes[0].failure->reason.c_str());
        QVERIFY(std::abs(f->lanes[0].failure->time - 0.756) < 1e-9);
        QTRY_VERIFY_WITH_TIMEOUT(w.viewports()[0]->frame() == f && w.viewports()[1]->frame() == f, testsupport::kHangGuardMs);
        const QString failed = w.viewports()[0]->overlayText(), live = w.viewports()[1]->overlayText();
        QVERIFY2(failed.contains("euler") && failed.contains("Blew up at t = 0.756 s") && failed.contains("bodies 1 and 2 intersect"),
                 qPrintable(failed));
        QVERIFY2(live.contains("rk4") && live.contains("t = 1.002 s") && live.contains("momentum (") &&
                     live.contains("min_gap ") && !live.contains("Blew up"),
                 qPrintable(live));
        QVERIFY(failed.contains("momentum (") && failed.contains("min_gap "));  // its last good state's
        QVERIFY(w.failureText().isEmpty());  // side by side each view says it, as for one body
        for (Viewport* v : w.viewports()) {
            const Census c = census(v->grabFramebuffer());
            QVERIFY2(c.orange > 0.002 && c.bluish > 0.002,
                     qPrintable(QString("%1: orange %2, blue %3").arg(v->objectName()).arg(c.orange).arg(c.bluish)));
        }
        // The particles too are in their body's hue (before: every body's outer layer orange and
        // inner layer blue, the two bodies alike): the top outer particle of each body in rk4's
        // view, at its centre pixel, is its body's colour.
        Viewport* v = w.viewports()[1];
        const QImage image = v->grabFramebuffer();
        const QMatrix4x4 mvp = v->camera().projection(v->size()) * v->camera().view();
        const auto& x = f->lanes[1].positions;
        for (std::size_t k = 0; k < f->scene->bodies.size(); ++k) {
            const auto& b = f->scene->bodies[k];
            int top = -1;
            for (int i = b.first; i < b.first + b.count; ++i)
                if (f->scene->topology.layer[std::size_t(i)] == simcore::Layer::Outer &&
                    (top < 0 || x[3 * std::size_t(i) + 1] > x[3 * std::size_t(top) + 1]))
                    top = i;
            const QVector3D ndc = mvp.map(QVector3D(float(x[3 * std::size_t(top)]), float(x[3 * std::size_t(top) + 1]), 0.0f));
            const QPoint at(int((ndc.x() + 1) * 0.5 * image.width()), int((1 - ndc.y()) * 0.5 * image.height()));
            const QColor seen = image.pixelColor(at), hue = bodyColor(int(k));
            QVERIFY2(std::abs(seen.red() - hue.red()) + std::abs(seen.green() - hue.green()) + std::abs(seen.blue() - hue.blue()) < 60,
                     qPrintable(QString("body %1's top particle at (%2, %3) is %4, its hue %5")
                                    .arg(k + 1).arg(at.x()).arg(at.y()).arg(seen.name(), hue.name())));
        }
    }

    void mouseDragGrabsAndPulls() {
        QFETCH(SceneKind, kind);
        MainWindow w(false);
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w, testsupport::kHangGuardMs));
        simcore::ParameterSet p(kind);
        p.set(simcore::Param::Gravity, 0.0);
        w.startScene(p, {"rk4"});
        QVERIFY(waitForScene(w, kind));
        Viewport* v = w.viewports().front();
        const FramePtr f = w.controller()->latest();
        // The topmost outer particle, projected to the widget.
        int top = -1;
        const auto& x = f->lanes[0].positions;
        for (int i = 0; i < f->scene->topology.particleCount(); ++i)
            if (f->scene->topology.layer[std::size_t(i)] == simcore::Layer::Outer &&
                (top < 0 || x[3 * std::size_t(i) + 1] > x[3 * std::size_t(top) + 1]))
                top = i;
        QVERIFY(top >= 0);
        const QMatrix4x4 mvp = v->camera().projection(v->size()) * v->camera().view();
        const QVector3D ndc = mvp.map(QVector3D(x[3 * std::size_t(top)], x[3 * std::size_t(top) + 1], x[3 * std::size_t(top) + 2]));
        const QPointF at((ndc.x() + 1) * 0.5 * v->width(), (1 - ndc.y()) * 0.5 * v->height());
        auto send = [v](QEvent::Type type, QPointF pos, Qt::MouseButtons buttons) {
            QMouseEvent e(type, pos, v->mapToGlobal(pos), Qt::LeftButton, buttons, Qt::NoModifier);
            QApplication::sendEvent(v, &e);
        };
        send(QEvent::MouseButtonPress, at, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest()->lanes[0].pointer.active, testsupport::kHangGuardMs);
        const int grabbed = w.controller()->latest()->lanes[0].pointer.particle;
        QCOMPARE(grabbed, top);  // the particle under the cursor, not another one
        send(QEvent::MouseMove, at + QPointF(0, -120), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest()->lanes[0].pointer.anchor.y() > x[3 * std::size_t(top) + 1] + 0.3, testsupport::kHangGuardMs);
        w.controller()->run();
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest()->lanes[0].diagnostics.time > 0.3, testsupport::kHangGuardMs);
        // Pulled up: the particle followed the anchor.
        QVERIFY(w.controller()->latest()->lanes[0].positions[3 * std::size_t(top) + 1] > x[3 * std::size_t(top) + 1] + 0.05);
        QVERIFY(w.controller()->latest()->lanes[0].diagnostics.workPointer != 0.0);
        send(QEvent::MouseButtonRelease, at + QPointF(0, -120), Qt::NoButton);
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->latest()->lanes[0].pointer.active, testsupport::kHangGuardMs);
        w.controller()->pause();
    }

    void keyboardChoosesGrabsAndDrags() {
        // Issue 30: without a mouse. With focus (a frame shows it) the arrow keys choose a
        // particle (its forces shown as for a click), Enter grabs it, the arrows drag it, Enter
        // lets go.
        MainWindow w(false);
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w, testsupport::kHangGuardMs));
        simcore::ParameterSet p(SceneKind::Ring2d);
        p.set(simcore::Param::Gravity, 0.0);
        w.startScene(p, {"rk4"});
        QVERIFY(waitForScene(w, SceneKind::Ring2d));
        Viewport* v = w.viewports().front();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w, testsupport::kHangGuardMs));
        v->setFocus(Qt::TabFocusReason);
        QTRY_VERIFY_WITH_TIMEOUT(v->hasFocus(), testsupport::kHangGuardMs);
        QVERIFY(v->findChild<QWidget*>(QStringLiteral("focusFrame"))->isVisible());
        const FramePtr f = w.controller()->latest();
        int top = -1;
        const auto& x = f->lanes[0].positions;
        for (int i = 0; i < f->scene->topology.particleCount(); ++i)
            if (f->scene->topology.layer[std::size_t(i)] == simcore::Layer::Outer &&
                (top < 0 || x[3 * std::size_t(i) + 1] > x[3 * std::size_t(top) + 1]))
                top = i;
        for (int i = 0; i <= top; ++i) QTest::keyClick(v, Qt::Key_Right);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest()->lanes[0].breakdown &&
                                     w.controller()->latest()->lanes[0].breakdown->particle == top,
                                 testsupport::kHangGuardMs);
        QTest::keyClick(v, Qt::Key_Left);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest()->lanes[0].breakdown->particle == top - 1 ||
                                     (top == 0 && w.controller()->latest()->lanes[0].breakdown->particle ==
                                                      f->scene->topology.particleCount() - 1),
                                 testsupport::kHangGuardMs);
        QTest::keyClick(v, Qt::Key_Right);
        QTest::keyClick(v, Qt::Key_Return);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest()->lanes[0].pointer.active, testsupport::kHangGuardMs);
        QCOMPARE(w.controller()->latest()->lanes[0].pointer.particle, top);
        for (int i = 0; i < 15; ++i) QTest::keyClick(v, Qt::Key_Up);  // 120 pixels up
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest()->lanes[0].pointer.anchor.y() > x[3 * std::size_t(top) + 1] + 0.3,
                                 testsupport::kHangGuardMs);
        QTest::keyClick(v, Qt::Key_Return);
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->latest()->lanes[0].pointer.active, testsupport::kHangGuardMs);
        QTest::keyClick(v, Qt::Key_Escape);
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->latest()->lanes[0].breakdown, testsupport::kHangGuardMs);
        v->clearFocus();
        QTRY_VERIFY_WITH_TIMEOUT(!v->findChild<QWidget*>(QStringLiteral("focusFrame"))->isVisible(),
                                 testsupport::kHangGuardMs);
    }

    void clickShowsTheForcesOnAParticle_data() { mouseDragGrabsAndPulls_data(); }
    void clickShowsTheForcesOnAParticle() {
        // Issue 16: a click (no drag) on a particle selects it; every frame then carries its
        // free-body diagram, drawn as arrows and listed in a panel, updating while it runs; a
        // click away from the body clears it. The grab of the press is let go at the release.
        QFETCH(SceneKind, kind);
        MainWindow w(false);
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w, testsupport::kHangGuardMs));
        w.startScene(simcore::ParameterSet(kind), {"rk4"});
        QVERIFY(waitForScene(w, kind));
        Viewport* v = w.viewports().front();
        auto* panel = v->findChild<QLabel*>("forcesPanel");
        QVERIFY(panel && panel->isHidden());
        const FramePtr f = w.controller()->latest();
        int top = -1;
        const auto& x = f->lanes[0].positions;
        for (int i = 0; i < f->scene->topology.particleCount(); ++i)
            if (f->scene->topology.layer[std::size_t(i)] == simcore::Layer::Outer &&
                (top < 0 || x[3 * std::size_t(i) + 1] > x[3 * std::size_t(top) + 1]))
                top = i;
        const QMatrix4x4 mvp = v->camera().projection(v->size()) * v->camera().view();
        const QVector3D ndc = mvp.map(QVector3D(x[3 * std::size_t(top)], x[3 * std::size_t(top) + 1], x[3 * std::size_t(top) + 2]));
        const QPointF at((ndc.x() + 1) * 0.5 * v->width(), (1 - ndc.y()) * 0.5 * v->height());
        auto click = [v](QPointF pos) {
            QMouseEvent press(QEvent::MouseButtonPress, pos, v->mapToGlobal(pos), Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(v, &press);
            QMouseEvent release(QEvent::MouseButtonRelease, pos, v->mapToGlobal(pos), Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
            QApplication::sendEvent(v, &release);
        };
        // Paused, the body does not move: what the click changes in the GL image outside the
        // panel is the arrows and the ring around the particle.
        const QImage before = v->grabFramebuffer().convertToFormat(QImage::Format_RGB32);

        click(at);
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest()->lanes[0].breakdown.has_value(), testsupport::kHangGuardMs);
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->latest()->lanes[0].pointer.active, testsupport::kHangGuardMs);
        const simcore::ForceBreakdown first = *w.controller()->latest()->lanes[0].breakdown;
        QCOMPARE(first.particle, top);
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        double scale = 0.0;
        for (const Eigen::Vector3d& p : first.part) {
            sum += p;
            scale += p.norm();
        }
        QVERIFY(scale > 0.0 && (sum - first.total).norm() <= 1e-12 * scale);
        QTRY_VERIFY_WITH_TIMEOUT(panel->isVisible(), testsupport::kHangGuardMs);
        QVERIFY(panel->text().contains(QString("Forces on particle %1").arg(top)));
        for (const char* term : {"gravity", "structural springs", "gas (outer)", "total"}) QVERIFY2(panel->text().contains(term), term);
        QVERIFY(panel->text().contains(" N"));
        QVERIFY(panel->text().contains("arrows: 1 m ="));
        QVERIFY(viewportShowsLatest(w));
        const QImage after = v->grabFramebuffer().convertToFormat(QImage::Format_RGB32);
        QCOMPARE(after.size(), before.size());
        int changed = 0;
        for (int py = 0; py < after.height(); ++py)
            for (int px = 0; px < after.width(); ++px)
                if (!panel->geometry().contains(px, py) && after.pixel(px, py) != before.pixel(px, py)) ++changed;
        QVERIFY2(changed > 200, qPrintable(QString("%1 pixels changed").arg(changed)));

        // While it runs the diagram follows the particle.
        w.controller()->run();
        QTRY_VERIFY_WITH_TIMEOUT(w.controller()->latest()->lanes[0].diagnostics.time > 0.2, testsupport::kHangGuardMs);
        w.controller()->pause();
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->latest()->running, testsupport::kHangGuardMs);
        const auto& later = w.controller()->latest()->lanes[0].breakdown;
        QVERIFY(later && later->particle == top);
        QVERIFY(later->total != first.total);

        // A click away from the body clears it.
        click(QPointF(6, v->height() - 6));
        QTRY_VERIFY_WITH_TIMEOUT(!w.controller()->latest()->lanes[0].breakdown.has_value(), testsupport::kHangGuardMs);
        QTRY_VERIFY_WITH_TIMEOUT(panel->isHidden(), testsupport::kHangGuardMs);
    }

    void screenshotFromTheCommandLine() {
        QTemporaryDir dir;
        const QString path = dir.filePath("shot.png");
        QProcess p;
        p.start(ELASTIC_LAB_GUI, {"--scene", "sphere3d", "--set", "subdivisions=1", "--integrator", "verlet",
                                  "--screenshot", path, "--after", "0.5"});
        QVERIFY(testsupport::waitForExit(p));
        QCOMPARE(p.exitCode(), 0);
        const QImage image(path);
        QVERIFY(!image.isNull());
        QVERIFY(image.width() >= 800);
        QVERIFY(census(image).colours > 50);
        // The energy docks open for a screenshot (issue 16).
        QProcess docks;
        const QString docksShot = dir.filePath("docks.png");
        docks.start(ELASTIC_LAB_GUI, {"--scene", "ring2d", "--docks", "energy-bars,pv", "--screenshot", docksShot,
                                      "--after", "0.3"});
        QVERIFY(testsupport::waitForExit(docks));
        QVERIFY2(docks.exitCode() == 0, docks.readAllStandardError().constData());
        QVERIFY(!QImage(docksShot).isNull());
        // The stability map opens for a screenshot too, which waits for its linearisation.
        QProcess map;
        const QString mapShot = dir.filePath("map.png");
        map.start(ELASTIC_LAB_GUI, {"--scene", "ring2d", "--docks", "stability-map", "--screenshot", mapShot,
                                    "--after", "0.1"});
        QVERIFY(testsupport::waitForExit(map));
        QVERIFY2(map.exitCode() == 0, map.readAllStandardError().constData());
        const QImage mapImage(mapShot);
        QVERIFY(!mapImage.isNull());
        // The region's fill (light green, ui/stability_map_dock.cpp) is in the picture.
        int fill = 0;
        for (int y = 0; y < mapImage.height(); ++y)
            for (int x = 0; x < mapImage.width(); ++x) fill += mapImage.pixelColor(x, y) == QColor(196, 232, 190);
        QVERIFY2(fill > 2000, qPrintable(QString("%1 pixels of the region's fill").arg(fill)));
        // Bad input is refused with a message, before any window.
        QProcess bad;
        bad.start(ELASTIC_LAB_GUI, {"--scene", "ring2d", "--set", "ks=-3", "--screenshot", path});
        QVERIFY(testsupport::waitForExit(bad));
        QCOMPARE(bad.exitCode(), 2);
        QVERIFY(bad.readAllStandardError().contains("ks"));
        // --after must be finite (inf was never reached, nan compared false with everything).
        for (const char* after : {"nan", "inf", "-1"}) {
            QProcess refused;
            refused.start(ELASTIC_LAB_GUI, {"--screenshot", path, "--after", after});
            QVERIFY(testsupport::waitForExit(refused));
            QCOMPARE(refused.exitCode(), 2);
            QVERIFY(refused.readAllStandardError().contains("--after needs a finite time"));
        }
    }

    void timelineScreenshot() {
        // Time travel for a picture (issue 16): run, travel back, branch with another DT, run
        // on and travel back to the branch; the timeline dock is open. Bad combinations refused.
        QTemporaryDir dir;
        const QString path = dir.filePath("timeline.png");
        QProcess p;
        p.start(ELASTIC_LAB_GUI, {"--scene", "ring2d", "--docks", "timeline", "--after", "0.4", "--travel-back", "0.2",
                                  "--branch", "dt=0.006", "--screenshot", path});
        QVERIFY(testsupport::waitForExit(p));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QVERIFY(!QImage(path).isNull());
        const std::vector<std::pair<QStringList, QByteArray>> refused = {
            {{"--scene", "ring2d", "--travel-back", "0.2"}, "--travel-back needs --screenshot"},
            {{"--screenshot", path, "--after", "0.1", "--travel-back", "0.2"}, "at most --after"},
            {{"--screenshot", path, "--after", "0.4", "--branch", "dt=0.006"}, "--branch needs --travel-back"},
            {{"--screenshot", path, "--after", "0.4", "--travel-back", "0.2", "--branch", "particles=30"}, "rebuilds"},
            {{"--screenshot", path, "--after", "0.4", "--travel-back", "0.2", "--branch", "integrator=rk9"}, "rk9"},
        };
        for (const auto& [args, message] : refused) {
            QProcess bad;
            bad.start(ELASTIC_LAB_GUI, args);
            QVERIFY(testsupport::waitForExit(bad));
            QCOMPARE(bad.exitCode(), 2);
            QVERIFY2(bad.readAllStandardError().contains(message), message.constData());
        }
    }

    void commandLineFollowsTheCliRules() {
        // Issue 18: the GUI's command line refuses what elastic-lab-cli refuses, with exit 2 and
        // one line, before any window: unknown options, values given twice, lists with empty or
        // repeated items, unknown integrators, --after without a screenshot, a screenshot that
        // would replace the scene file or cannot be written, and a runaway --measure-fps.
        QTemporaryDir dir;
        const QString scene = dir.filePath("exp.json"), shot = dir.filePath("shot.png");
        simcore::Simulation sim(simcore::ParameterSet(simcore::SceneKind::Ring2d), "rk4");
        QCOMPARE(elui::writeFile(scene, QByteArray::fromStdString(simlab::sceneFileText(sim, "ring2d", true))), QString());
        QVERIFY(QFile::link(scene, dir.filePath("link.png")));
        const QList<QPair<QStringList, QString>> refusals = {
            {{"--bogus"}, "bogus"},
            // A plain argument is a scene (the desktop entry's %f): one at most, not beside --scene.
            {{"stray"}, "unknown scene 'stray'"},
            {{scene, scene}, "one scene file at most"},
            {{scene, "--scene", "ring2d"}, "both choose the scene"},
            {{"--after", "1"}, "--after needs --screenshot"},
            {{"--screenshot", shot, "--after", "1", "--after", "2"}, "--after is given 2 times"},
            {{"--compare", "rk4,,euler"}, "item 2 is empty"},
            {{"--compare", "rk4,rk4"}, "'rk4' is listed twice"},
            {{"--compare", "rk4,euler,midpoint,verlet"}, "one to three integrators"},
            {{"--integrator", "leapfrog"}, "unknown integrator 'leapfrog'"},
            {{"--set", "ks=-3"}, "--set ks"},
            {{"--show", "strain,strain"}, "listed twice"},
            // Docks this build does not have are refused like any unknown name (issue 16).
            {{"--docks", "no-such-dock"}, "unknown dock 'no-such-dock'; allowed: energy-bars, pv, stability-map, timeline"},
            {{"--docks", "energy-bars,no-such-dock"}, "unknown dock 'no-such-dock'; allowed: energy-bars, pv, stability-map, timeline"},
            {{"--docks", "pv,pv"}, "listed twice"},
            {{"--docks", "pv,"}, "is empty"},
            {{"--docks", "pv", "--docks", "energy-bars"}, "--docks is given 2 times"},
            {{"--measure-fps", "inf"}, "--measure-fps needs"},
            {{"--select", "-1"}, "--select needs a particle index"},
            {{"--select", "top"}, "--select needs a particle index"},
            {{"--scene", scene, "--screenshot", dir.filePath("link.png")}, "is the same file as --scene"},
            {{"--screenshot", dir.filePath("shot.xyz")}, "cannot write .xyz"},
            {{"--screenshot", dir.filePath("missing/shot.png")}, "missing/shot.png"},
            {{"--scene", QString(5000, 'x') + ".json"}, "(5005 bytes)"},
        };
        for (const auto& [args, mentions] : refusals) {
            QProcess refused;
            refused.start(ELASTIC_LAB_GUI, args);
            QVERIFY(testsupport::waitForExit(refused));
            QCOMPARE(refused.exitCode(), 2);
            QString err = QString::fromUtf8(refused.readAllStandardError());
            err.remove(QRegularExpression("QStandardPaths: [^\\n]*\\n"));  // Qt's own note when XDG_RUNTIME_DIR is unset
            QVERIFY2(err.contains(mentions), qPrintable(args.join(' ').left(200) + ": " + err));
            QCOMPARE(err.trimmed().count('\n'), 0);
        }
        QVERIFY(!QFileInfo::exists(shot));
        QCOMPARE(QFileInfo(dir.filePath("link.png")).symLinkTarget(), scene);  // the scene file untouched
        // Without a display: one line saying what to do, exit 2 (not Qt's abort advising to
        // reinstall), both with no display at all and with one that cannot be reached.
        for (const QString& display : {QString(), QStringLiteral(":9999")}) {
            QProcess headless;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}) env.remove(QString::fromLatin1(name));
            if (!display.isEmpty()) env.insert(QStringLiteral("DISPLAY"), display);
            headless.setProcessEnvironment(env);
            headless.start(ELASTIC_LAB_GUI, {"--scene", "ring2d"});
            QVERIFY(testsupport::waitForExit(headless));
            QCOMPARE(headless.exitStatus(), QProcess::NormalExit);
            QCOMPARE(headless.exitCode(), 2);
            QString err = QString::fromUtf8(headless.readAllStandardError());
            err.remove(QRegularExpression("QStandardPaths: [^\\n]*\\n"));
            QVERIFY2(err.startsWith("elastic-lab: no display") && err.contains("xvfb-run -a elastic-lab"), qPrintable(err));
            QVERIFY2(err.contains(display.isEmpty() ? QStringLiteral("not set") : display), qPrintable(err));
            QCOMPARE(err.trimmed().count('\n'), 0);
        }
        QProcess version;
        version.start(ELASTIC_LAB_GUI, {"--version"});
        QVERIFY(testsupport::waitForExit(version));
        QCOMPARE(version.exitCode(), 0);
        QVERIFY(version.readAllStandardOutput().startsWith("elastic-lab "));
    }

    void sceneFileOnTheCommandLine() {
        // --scene takes a scene file too: a ring saved at t = 0.3 s resumes and runs to 0.5 s.
        QTemporaryDir dir;
        const QString scene = dir.filePath("ring.json"), shot = dir.filePath("shot.png");
        simcore::Simulation sim(simcore::ParameterSet(simcore::SceneKind::Ring2d), "midpoint");
        QVERIFY(sim.advanceTo(0.3));
        QCOMPARE(elui::writeFile(scene, QByteArray::fromStdString(simlab::sceneFileText(sim, "ring2d", true))),
                 QString());
        QProcess p;
        p.start(ELASTIC_LAB_GUI, {"--scene", scene, "--set", "kd=20", "--screenshot", shot, "--after", "0.5"});
        QVERIFY(testsupport::waitForExit(p));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QVERIFY(census(QImage(shot)).colours > 20);
        // The same file given alone, as the desktop entry (Exec=elastic-lab %f) passes it.
        QVERIFY(QFile::remove(shot));
        QProcess alone;
        alone.start(ELASTIC_LAB_GUI, {scene, "--screenshot", shot, "--after", "0.4"});
        QVERIFY(testsupport::waitForExit(alone));
        QVERIFY2(alone.exitCode() == 0, alone.readAllStandardError().constData());
        QVERIFY(census(QImage(shot)).colours > 20);
        // Refused before any window: a bad file (naming the key), a missing one, and a --set
        // that changes the body's shape under a saved state.
        QFile file(scene);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray broken = file.readAll().replace("\"kd\"", "\"kdd\"");
        file.close();
        const QString bad = dir.filePath("bad.json");
        QCOMPARE(elui::writeFile(bad, broken), QString());
        const QList<QPair<QStringList, QString>> refusals = {
            {{"--scene", bad}, "kdd"},
            {{"--scene", dir.filePath("missing.json")}, "missing.json"},
            {{"--scene", scene, "--set", "particles=20"}, "no longer fits"},
        };
        for (const auto& [args, mentions] : refusals) {
            QProcess refused;
            refused.start(ELASTIC_LAB_GUI, args + QStringList{"--screenshot", shot});
            QVERIFY(testsupport::waitForExit(refused));
            QCOMPARE(refused.exitCode(), 2);
            const QByteArray err = refused.readAllStandardError();
            QVERIFY2(err.contains(mentions.toUtf8()), err.constData());
        }
    }
};

int main(int argc, char** argv) {
    setDefaultGlFormat();
    QApplication app(argc, argv);
    TestGuiRender test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_gui_render.moc"
