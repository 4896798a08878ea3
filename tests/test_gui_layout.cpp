// The window on a projector (issue 25): laid out on the screen it runs on (xvfb-run with a
// 1280x800 and a 1920x1080 screen: two CTest entries), in every configuration a class meets —
// the default scenes, every lesson with its docks, three views side by side with the energy
// bars, every dock open, presentation mode — nothing is cut off: the window fits the screen
// (no dock forces it wider), every visible dock lies inside the window with room for its title,
// every plot has room for its axes, the Run dock's readout has room for its text, every view is
// inside. Each layout is also written as a PNG (ELASTIC_LAB_SHOT_DIR, or layout-shots/ in the
// working directory) to be looked at.
#include <algorithm>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTabBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>

#include "qcustomplot.h"
#include "simcore/world.h"
#include "test_support.h"
#include "ui/compare_dialog.h"
#include "ui/energy_bars_dock.h"
#include "ui/gl_format.h"
#include "ui/language.h"
#include "ui/lessons.h"
#include "ui/main_window.h"
#include "ui/plot_ticks.h"
#include "ui/presets.h"
#include "ui/run_dock.h"
#include "ui/simulation_controller.h"
#include "ui/ui_scale.h"
#include "ui/viewport.h"

using namespace elui;
using simcore::SceneKind;

namespace {

QRect screenArea() { return QGuiApplication::primaryScreen()->availableGeometry(); }

// Lets posted layout requests and the docks' deferred sizing run.
void settle() {
    for (int i = 0; i < 6; ++i) {
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        QCoreApplication::processEvents();
    }
}

// A widget's rectangle in its window's coordinates.
QRect inWindow(const QWidget* w) { return QRect(w->mapTo(w->window(), QPoint(0, 0)), w->size()); }

// Whether a widget is actually on screen (shown, not on a hidden tab).
bool onScreen(const QWidget* w) { return w->isVisible() && !w->visibleRegion().isEmpty(); }

QString shotDir() {
    const QString dir = qEnvironmentVariableIsSet("ELASTIC_LAB_SHOT_DIR") ? qEnvironmentVariable("ELASTIC_LAB_SHOT_DIR")
                                                                            : QDir::currentPath() + "/layout-shots";
    QDir().mkpath(dir);
    return dir;
}

// Every check of "nothing is cut off", as messages (empty: all good).
QStringList cutOff(MainWindow& w) {
    QStringList problems;
    const QRect window = w.rect();
    const QRect screen = screenArea();
    if (w.minimumSizeHint().width() > screen.width() || w.minimumSizeHint().height() > screen.height()) {
        QStringList parts;  // who asks for the room
        for (QDockWidget* dock : w.findChildren<QDockWidget*>())
            if (dock->isVisible())
                parts << QString("%1 %2x%3").arg(dock->objectName()).arg(dock->minimumSizeHint().width()).arg(dock->minimumSizeHint().height());
        parts << QString("central %1x%2").arg(w.centralWidget()->minimumSizeHint().width()).arg(w.centralWidget()->minimumSizeHint().height());
        problems << QString("the window needs %1x%2 px, the screen has %3x%4 (%5)")
                        .arg(w.minimumSizeHint().width()).arg(w.minimumSizeHint().height())
                        .arg(screen.width()).arg(screen.height()).arg(parts.join(", "));
    }
    if (!screen.contains(w.frameGeometry()))
        problems << QString("window %1,%2 %3x%4 outside the screen")
                        .arg(w.frameGeometry().x()).arg(w.frameGeometry().y())
                        .arg(w.frameGeometry().width()).arg(w.frameGeometry().height());
    for (QDockWidget* dock : w.findChildren<QDockWidget*>()) {
        // A dock that is open (not closed, not floating) is on screen, or a tab behind one
        // that is: Qt parks a tab group's hidden tabs outside the window, and once parked the
        // Plots dock of every single-body window, tabbed at start with the closed Bodies dock,
        // drew nothing (an empty right third of the window; no check here saw it).
        if (dock->isVisible() && !dock->isFloating() && !onScreen(dock)) {
            const QList<QDockWidget*> tabs = w.tabifiedDockWidgets(dock);
            if (std::none_of(tabs.begin(), tabs.end(), [](const QDockWidget* t) { return onScreen(t); }))
                problems << dock->objectName() + " is open but not on screen, nor a tab behind a dock that is";
        }
        if (!onScreen(dock)) continue;
        const QRect r = inWindow(dock);
        if (!window.contains(r)) problems << dock->objectName() + " reaches outside the window";
        // Its title: a tab of its own when tabbed, else the title bar (text plus the float and
        // close buttons, about two text heights).
        const QFontMetrics fm(dock->font());
        const int title = fm.horizontalAdvance(dock->windowTitle()) + 2 * fm.height();
        if (r.width() < title) problems << QString("%1 is %2 px wide, its title needs %3").arg(dock->objectName()).arg(r.width()).arg(title);
        if (r.height() < 3 * fm.height()) problems << dock->objectName() + " is too low to show anything";
        // A dock's scrolled content fits its width (it may scroll down, never sideways: the
        // Bodies dock in French had its readout, buttons and legends cut at the window's edge).
        // Also in presentation mode (the Parameters dock's Contact rows needed 350 px of the 306
        // px it has at 1.5x until a row too wide put its field under its label).
        for (QScrollArea* scroll : dock->findChildren<QScrollArea*>())
            if (onScreen(scroll) && scroll->widget() && scroll->widget()->minimumSizeHint().width() > scroll->viewport()->width())
                problems << QString("%1's content needs %2 px, it has %3").arg(dock->objectName())
                                .arg(scroll->widget()->minimumSizeHint().width()).arg(scroll->viewport()->width());
    }
    for (QCustomPlot* plot : w.findChildren<QCustomPlot*>()) {
        if (!onScreen(plot)) continue;
        plot->replot();
        const QRect r = inWindow(plot);
        const QString name = plot->objectName().isEmpty() ? plot->parentWidget()->objectName() : plot->objectName();
        // In a scroll area (the Plots dock on a short screen) a plot is scrolled into view.
        const bool scrolls = plot->parentWidget() && plot->parentWidget()->parentWidget() &&
                             qobject_cast<QScrollArea*>(plot->parentWidget()->parentWidget()->parentWidget());
        if (!scrolls && !window.contains(r)) problems << name + " reaches outside the window";
        const QRect axes = plot->axisRect()->rect();
        // The axes' own area: wide and high enough for a curve (labels and ticks around it).
        if (axes.width() < 60 || axes.height() < 40)
            problems << QString("%1: axes %2x%3 px").arg(name).arg(axes.width()).arg(axes.height());
        if (!scrolls && !plot->visibleRegion().boundingRect().contains(axes))
            problems << name + ": the axes are partly hidden";
        for (QCPAxis* axis : plot->axisRect()->axes())
            if (axis->visible() && axis->tickLabels() && tickLabelsOverlap(axis))
                problems << name + ": tick labels overlap";
    }
    QLabel* readout = w.runDock()->readout();
    if (onScreen(w.runDock())) {
        // The readout's text fits its label (the dock scrolls no further).
        if (readout->width() < readout->sizeHint().width())
            problems << QString("readout %1 px wide, its text needs %2").arg(readout->width()).arg(readout->sizeHint().width());
        if (!window.contains(inWindow(readout))) problems << "the readout reaches outside the window";
    }
    for (Viewport* v : w.viewports()) {
        if (!window.contains(inWindow(v))) problems << v->objectName() + " reaches outside the window";
        if (v->width() < 150 || v->height() < 120)
            problems << QString("%1 is %2x%3 px").arg(v->objectName()).arg(v->width()).arg(v->height());
    }
    return problems;
}

struct Setup {
    QString name;
    std::function<void(MainWindow&)> apply;
    double scale = 1.0;
    QString language = QStringLiteral("en");  // applied before the window is made
};

Preset presetById(const QString& id) {
    for (const Preset& p : teachingPresets())
        if (p.id == id) return p;
    for (const Preset& p : stabilityPresets())
        if (p.id == id) return p;
    return {};
}

std::vector<Setup> setups() {
    std::vector<Setup> out;
    out.push_back({"ring", [](MainWindow& w) { w.applyPreset(presetById("ring2d")); }});
    out.push_back({"sphere", [](MainWindow& w) { w.applyPreset(presetById("sphere3d")); }});
    for (const Lesson& lesson : lessons())
        out.push_back({"lesson-" + lesson.id, [lesson](MainWindow& w) { w.applyLesson(lesson); }});
    out.push_back({"three-views-energy-bars", [](MainWindow& w) {
                       w.startScene(simcore::ParameterSet(SceneKind::Ring2d), {"euler", "midpoint", "rk4"});
                       w.openDock("energy-bars");
                   }});
    out.push_back({"every-dock", [](MainWindow& w) {
                       w.startScene(simcore::ParameterSet(SceneKind::Sphere3d), {"rk4"});
                       for (const QString& d : MainWindow::dockNames()) w.openDock(d);
                   }});
    out.push_back({"presentation-ring", [](MainWindow& w) { w.applyPreset(presetById("ring2d")); }, kPresentationScale});
    // A scene of several bodies with its Bodies dock (its table, readout and add-a-body form) in
    // French, then two views of it side by side with the dock opened by name as --docks bodies
    // does (its share of the right column: 350 px; 334 px for its content) in the languages
    // whose words are longest.
    out.push_back({"world-bodies-fr", [](MainWindow& w) { w.startWorld(*simcore::worldScene("collide2d")); }, 1.0, "fr"});
    for (const char* lang : {"fr", "de", "es"})
        out.push_back({QStringLiteral("world-side-by-side-bodies-") + lang, [](MainWindow& w) {
                           w.startWorld(*simcore::worldScene("collide3d"), {"rk4", "euler"});
                           w.openDock("bodies");
                       }, 1.0, lang});
    // Three views, the Run dock, the lesson and the energy bars in 1280 px at the presentation size
    // (1.5x; at 2x they need ~1430 px: docs/gui.md, Known limits).
    out.push_back({"presentation-energy-drift", [](MainWindow& w) { w.applyLesson(*findLesson("energy-drift")); },
                   1.5});
    return out;
}

}  // namespace

class TestGuiLayout : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QVERIFY2(Viewport::openGLAvailable(), "OpenGL 3.3 core is needed (run under xvfb-run)");
        qInfo("screen: %dx%d", screenArea().width(), screenArea().height());
#if defined(__SANITIZE_ADDRESS__)
        // The suite runs three times in CI: the second screen's layouts once, in Release.
        if (screenArea().width() > 1280) QSKIP("the 1920 x 1080 layouts run in Release only");
#endif
    }
    void cleanup() {
        setUiScale(1.0);
        applyLanguage(QStringLiteral("en"));
    }

    void fitWithinKeepsTheWindowOnTheScreen() {
        const QRect screen(0, 0, 1280, 800);
        QCOMPARE(MainWindow::fitWithin(QRect(100, 50, 1500, 900), screen), QRect(0, 0, 1280, 800));
        QCOMPARE(MainWindow::fitWithin(QRect(900, 600, 800, 600), screen), QRect(480, 200, 800, 600));
        QCOMPARE(MainWindow::fitWithin(QRect(-300, -40, 800, 600), screen), QRect(0, 0, 800, 600));
        QCOMPARE(MainWindow::fitWithin(QRect(10, 20, 800, 600), screen), QRect(10, 20, 800, 600));
        // A screen that does not start at the origin (a second monitor, a panel on the left).
        QCOMPARE(MainWindow::fitWithin(QRect(0, 0, 1920, 1080), QRect(1280, 32, 1920, 1048)), QRect(1280, 32, 1920, 1048));
    }

    void windowOpensWithinTheScreen() {
        MainWindow w(false);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY2(screenArea().contains(w.frameGeometry()), "the window opens within the available screen");
        // As large as 1500 x 900 where the screen has room.
        QCOMPARE(w.width(), std::min(1500, screenArea().width()));
        QCOMPARE(w.height(), std::min(900, screenArea().height()));
    }

    void savedGeometryIsRestoredWithinTheScreen() {
        // Geometry saved on a larger screen (2400 x 1400 at 300, 200) comes back within this one.
        QTemporaryDir dir;
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir.path());
        QCoreApplication::setOrganizationName("elastic-lab-layout-test");
        QCoreApplication::setApplicationName("layout");
        {
            MainWindow big(false);
            big.setGeometry(300, 200, 2400, 1400);
            big.show();
            QVERIFY(QTest::qWaitForWindowExposed(&big));
            QSettings().setValue("geometry", big.saveGeometry());
        }
        MainWindow w(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY2(screenArea().contains(w.frameGeometry()),
                 qPrintable(QString("restored at %1,%2 %3x%4").arg(w.x()).arg(w.y()).arg(w.width()).arg(w.height())));
        QSettings().clear();
    }

    void nothingIsCutOff_data() {
        QTest::addColumn<int>("index");
        const auto all = setups();
        for (int i = 0; i < int(all.size()); ++i) QTest::newRow(qPrintable(all[std::size_t(i)].name)) << i;
    }

    void nothingIsCutOff() {
        QFETCH(int, index);
        const Setup setup = setups()[std::size_t(index)];
        applyLanguage(setup.language);
        MainWindow w(false);
        w.setUiScale(setup.scale);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        setup.apply(w);
        QVERIFY(testsupport::waitUntil([&] {
            const FramePtr& f = w.controller()->latest();
            return f && !w.viewports().empty() && w.viewports().front()->frame() == f;
        }));
        // A few steps, so plots, bars and readout hold numbers of a running body.
        w.controller()->runUntil(0.2);
        QVERIFY(testsupport::waitUntil([&] {
            const FramePtr& f = w.controller()->latest();
            return f && !f->running && f->lanes.front().diagnostics.time >= 0.2 - 1e-9;
        }));
        settle();
        const QStringList problems = cutOff(w);
        const QString size = QString("%1x%2").arg(screenArea().width()).arg(screenArea().height());
        w.grab().save(shotDir() + "/layout-" + size + "-" + setup.name + ".png");
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join("; ")));
        if (setup.scale > 1.0) {
            QVERIFY(w.classControls()->isVisible());
            QVERIFY(inWindow(w.classControls()).width() <= w.width());
        }
    }

    void presentationModeScalesTheText() {
        MainWindow w(false);
        w.show();
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));  // the shortcuts act in the active window
        const double base = QApplication::font().pointSizeF();
        QCustomPlot* plot = w.findChild<QCustomPlot*>("plot_energy");
        QVERIFY(plot);
        const double tick = plot->xAxis->tickLabelFont().pointSizeF();
        const QLabel* readout = w.runDock()->readout();
        const double readoutSize = readout->font().pointSizeF();
        QVERIFY(!w.classControls()->isVisible());
        // View > Presentation mode: 1.5x everything, the large controls shown.
        w.presentationAction()->trigger();
        settle();
        QCOMPARE(uiScale(), kPresentationScale);
        QCOMPARE(QApplication::font().pointSizeF(), base * kPresentationScale);
        QCOMPARE(plot->xAxis->tickLabelFont().pointSizeF(), tick * kPresentationScale);
        QCOMPARE(readout->font().pointSizeF(), readoutSize * kPresentationScale);
        QVERIFY(w.classControls()->isVisible());
        QCOMPARE(w.classControls()->actions().size(), 4);  // Run/Pause, Step, Back, Reset
        QVERIFY(w.classControls()->font().pointSizeF() > QApplication::font().pointSizeF());
        // Ctrl+= and Ctrl+- step through 1.25 .. 2 and back.
        QTest::keyClick(&w, Qt::Key_Equal, Qt::ControlModifier);
        QCOMPARE(uiScale(), 1.75);
        QTest::keyClick(&w, Qt::Key_Equal, Qt::ControlModifier);
        QTest::keyClick(&w, Qt::Key_Equal, Qt::ControlModifier);
        QCOMPARE(uiScale(), 2.0);
        // A plot made at 2x (a new scene's plots) has 2x fonts too, and comes back with the rest.
        w.startScene(simcore::ParameterSet(SceneKind::Spring1d), {"rk4"});
        QVERIFY(testsupport::waitUntil([&] { return w.controller()->latest() && w.controller()->latest()->scene->kind == SceneKind::Spring1d; }));
        settle();
        QCustomPlot* fresh = w.findChild<QCustomPlot*>("plot_energy");
        QVERIFY(fresh);
        QCOMPARE(fresh->xAxis->tickLabelFont().pointSizeF(), tick * 2.0);
        for (int i = 0; i < 5; ++i) QTest::keyClick(&w, Qt::Key_Minus, Qt::ControlModifier);
        QCOMPARE(uiScale(), 1.0);
        QCOMPARE(QApplication::font().pointSizeF(), base);
        QCOMPARE(w.findChild<QCustomPlot*>("plot_energy")->xAxis->tickLabelFont().pointSizeF(), tick);
        QVERIFY(!w.classControls()->isVisible());
        QVERIFY(!w.presentationAction()->isChecked());
    }
};

int main(int argc, char** argv) {
    setDefaultGlFormat();
    QApplication app(argc, argv);
    TestGuiLayout test;
    return QTest::qExec(&test, argc, argv);
}
#include "test_gui_layout.moc"
