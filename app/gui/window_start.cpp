#include "app/gui/window_start.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <string_view>
#include <utility>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QIcon>
#include <QLocale>
#include <QSettings>
#include <QTimer>

#include "app/gui/command_line.h"
#include "elastic_lab_version.h"
#include "simcore/body.h"
#include "simcore/world.h"
#include "simlab/scenefile.h"
#include "ui/export.h"
#include "ui/gl_format.h"
#include "ui/language.h"
#include "ui/lesson_dock.h"
#include "ui/lessons.h"
#include "ui/lessons_dialog.h"
#include "ui/main_window.h"
#include "ui/plot_dock.h"
#include "ui/presets.h"
#include "ui/run_dock.h"
#include "ui/simulation_controller.h"
#include "ui/stability_map_dock.h"
#include "ui/viewport.h"

namespace elgui {

int fail(const QString& message) {
    std::fprintf(stderr, "elastic-lab: %s\n", qPrintable(message));
    return 2;
}

void beforeApplication(int argc, char** argv) {
    // Multisampling smooths edges; ELASTIC_LAB_MSAA=0 turns it off (software GL is faster so).
    elui::setDefaultGlFormat(qEnvironmentVariableIsSet("ELASTIC_LAB_MSAA") ? qEnvironmentVariableIntValue("ELASTIC_LAB_MSAA") : 4);
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg(argv[i]);
        if ((arg == "--help" || arg == "-h" || arg == "--version" || arg == "-v" || arg == "--help-all") &&
            !qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
    }
}

// --- Qt's start-up messages --------------------------------------------------------------------

namespace {

// Started where no window can be shown (no DISPLAY nor WAYLAND_DISPLAY, a display that refuses
// the connection, no platform plugin), Qt ends in a fatal message of several lines whose advice
// ("Reinstalling the application may fix this problem") is wrong. Qt's messages are held while
// the application starts: on the fatal one a single line says what to do, exit 2 (bad input, as
// for every refusal); when the start succeeds, the held messages are printed as Qt would have.
QStringList g_heldMessages;
QtMessageHandler g_qtHandler = nullptr;

void startupMessageHandler(QtMsgType type, const QMessageLogContext&, const QString& message) {
    if (type != QtFatalMsg) {
        g_heldMessages << message;
        return;
    }
    const QByteArray display = qgetenv("DISPLAY"), wayland = qgetenv("WAYLAND_DISPLAY");
    const QString where = display.isEmpty() && wayland.isEmpty()
                              ? QStringLiteral("DISPLAY and WAYLAND_DISPLAY are not set")
                              : QStringLiteral("display '%1' cannot be reached")
                                    .arg(QString::fromLocal8Bit(display.isEmpty() ? wayland : display));
    std::fprintf(stderr,
                 "elastic-lab: no display to open the window on (%s); start it from a desktop session, or without "
                 "a screen as xvfb-run -a elastic-lab ..., or use elastic-lab-cli for headless runs\n",
                 qPrintable(where));
    std::fflush(stderr);
    std::_Exit(2);
}

}  // namespace

HeldStartupMessages::HeldStartupMessages() { g_qtHandler = qInstallMessageHandler(startupMessageHandler); }

HeldStartupMessages::~HeldStartupMessages() { release(); }

void HeldStartupMessages::release() {
    if (!std::exchange(m_held, false)) return;
    qInstallMessageHandler(g_qtHandler);
    for (const QString& message : std::exchange(g_heldMessages, {})) std::fprintf(stderr, "%s\n", qPrintable(message));
}

void describeApplication() {
    QApplication::setOrganizationName(QStringLiteral("ElasticLab"));
    QApplication::setApplicationName(QStringLiteral("elastic-lab"));
    QApplication::setApplicationVersion(QString::fromLatin1(elastic_lab::kVersion));
    // Desktop integration: the installed desktop entry is named by the application id (Wayland
    // matches the window to it by this name; X11 by StartupWMClass there); the window icon is
    // the installed SVG drawn to PNG (Qt draws PNG without the SVG module).
    QGuiApplication::setDesktopFileName(QString::fromLatin1(elastic_lab::kAppId));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/elastic-lab.png")));
}

void applyLanguage(const GuiCommandLine& commandLine) {
    elui::applyLanguage(elui::chooseLanguage(
        commandLine.language(), commandLine.screenshot() ? QString() : QSettings().value(QStringLiteral("language")).toString(),
        QLocale::system().uiLanguages()));
}

// --- the window ---------------------------------------------------------------------------------

namespace {

void applyShowSwitches(elui::MainWindow& window, const QList<ShowSwitch>& show) {
    if (show.isEmpty()) return;
    elui::ViewOptions o = window.viewOptions();
    for (ShowSwitch s : show) {
        switch (s) {
        case ShowSwitch::Strain: o.strain = true; break;
        case ShowSwitch::Forces: o.forces = true; break;
        case ShowSwitch::Velocities: o.velocities = true; break;
        case ShowSwitch::Normals: o.normals = true; break;
        case ShowSwitch::NoParticles: o.particles = false; break;
        case ShowSwitch::NoFaces: o.faces = false; break;
        case ShowSwitch::NoStructural: o.springs[0] = false; break;
        case ShowSwitch::NoRadius: o.springs[1] = false; break;
        case ShowSwitch::NoShear: o.springs[2] = false; break;
        case ShowSwitch::NoBox: o.box = false; break;
        case ShowSwitch::ErrorBand: window.plotDock()->setBandsShown(true); break;
        case ShowSwitch::Reference: window.plotDock()->setReferenceShown(true); break;
        }
    }
    window.setViewOptions(o);
}

// The scene the request resolved: a world, a scene file (with its overrides), or a built-in
// scene (a preset's start kick too).
void startScene(elui::MainWindow& window, const GuiRequest& r) {
    const std::optional<simlab::SceneFile>& file = r.setup.file;
    if (r.setup.world) {
        if (file) {
            simlab::SceneFile changed = *file;
            changed.world = r.setup.world;
            changed.integrator = r.integrators.front().toStdString();
            window.openScene(changed, r.integrators, r.sceneArg, &*file);
        } else {
            window.startWorld(*r.setup.world, r.integrators);
        }
    } else if (file) {
        simlab::SceneFile changed = *file;
        changed.params = r.setup.params;
        changed.integrator = r.integrators.front().toStdString();
        window.openScene(changed, r.integrators, r.sceneArg, &*file);
    } else {
        if (r.preset) window.controller()->setStartKick(r.preset->kickInner, r.preset->kickOuter);
        window.startScene(r.setup.params, r.integrators);
    }
}

// After show(): the docks take their share of a laid-out window.
void openDocks(elui::MainWindow& window, const GuiRequest& r) {
    QStringList docks = r.docks;
    if (r.lesson) {
        docks = r.lesson->docks + docks;
        window.lessonDock()->setLesson(r.lesson);
        docks << QStringLiteral("lesson");
    }
    for (const QString& dock : docks) window.openDock(dock);
    if (r.experiments) {
        elui::LessonsDialog* dialog = window.showLessons();
        if (r.lesson) dialog->selectLesson(r.lesson->id);
    }
}

// --measure-fps: frames painted per wall second while the simulation runs in real time, and how
// late a 10 ms GUI timer fires (the UI's responsiveness); printed, then exit 0.
int measureFps(QApplication& app, elui::MainWindow& window, double seconds) {
    elui::SimulationController* controller = window.controller();
    // Shared by the lambdas below and freed with the last of them.
    auto wall = std::make_shared<QElapsedTimer>();
    auto* probe = new QTimer(&window);
    auto worstLate = std::make_shared<double>(0.0);
    auto last = std::make_shared<qint64>(0);
    QObject::connect(probe, &QTimer::timeout, &window, [=] {
        const qint64 now = wall->nsecsElapsed();
        if (*last > 0) *worstLate = std::max(*worstLate, double(now - *last) * 1e-6 - 10.0);
        *last = now;
    });
    QTimer::singleShot(1500, &window, [=, &window] {
        controller->run();
        wall->start();
        probe->start(10);
        const quint64 paints0 = window.viewports().empty() ? 0 : window.viewports().front()->paintCount();
        QTimer::singleShot(int(seconds * 1000), &window, [=, &window] {
            const double elapsed = double(wall->nsecsElapsed()) * 1e-9;
            const quint64 paints = window.viewports().empty() ? 0 : window.viewports().front()->paintCount();
            const elui::FramePtr f = controller->latest();
            std::printf("particles %d, frames/s %.1f, steps/s %.0f, simulated/wall %.3f, worst GUI timer delay "
                        "%.1f ms, falling behind %s\n",
                        f->scene->topology.particleCount(), double(paints - paints0) / elapsed, f->stepsPerSecond,
                        f->lanes[0].diagnostics.time / elapsed, *worstLate, f->fallingBehind ? "yes" : "no");
            std::fflush(stdout);
            QApplication::exit(0);
        });
    });
    return app.exec();
}

// --screenshot: runs to --after (time travel and a branch on the way), renders the window and
// writes the image; exit 0, 1 when the image cannot be written, 2 when the worker refuses the
// scene, 3 after two minutes of wall time.
int takeScreenshot(QApplication& app, elui::MainWindow& window, const GuiRequest& r) {
    elui::SimulationController* controller = window.controller();
    const QString path = r.screenshot;
    int exitCode = 0;
    // The grab waits for an open stability map to finish its linearisation (worker thread, up to
    // a few seconds for a large body); the two-minute guard below still holds.
    std::function<void()> grabWhenReady = [&window, &app, path, &exitCode, &grabWhenReady] {
        const elui::StabilityMapDock* map = window.stabilityMapDock();
        // ... and for a lesson's "Measure" (below) to fill its figures.
        if ((map->isVisible() && map->computing()) || window.lessonDock()->measuring()) {
            QTimer::singleShot(50, &window, grabWhenReady);
            return;
        }
        QApplication::processEvents();
        const QString error = elui::writeImage(path, window.grab().toImage());
        if (!error.isEmpty()) {
            std::fprintf(stderr, "elastic-lab: %s\n", qPrintable(error));
            exitCode = 1;
        }
        app.exit(exitCode);
    };
    auto shoot = [&window, &grabWhenReady] {
        // Let the last frame reach the viewports and be painted, then grab the window.
        QTimer::singleShot(400, &window, grabWhenReady);
    };
    // Time travel: back by --travel-back; with --branch, change it there, run on to --after and
    // travel back to the branch again, so both futures are in the plots.
    auto branched = std::make_shared<bool>(r.branchKey.isEmpty());
    const double after = r.after, travelBack = r.travelBack, branchValue = r.branchValue;
    const QString branchKey = r.branchKey, branchIntegrator = r.branchIntegrator;
    const elui::Lesson* lesson = r.lesson;
    const bool branchEveryBody = r.setup.world.has_value();  // a world: key=value sets every body, as --set
    QObject::connect(controller, &elui::SimulationController::reachedTime, &window, [=, &window] {
        // A lesson's screenshot shows its figures: those of the run, and the ones "Measure"
        // gives on these parameters.
        if (lesson) window.lessonDock()->measure();
        if (travelBack <= 0.0) return shoot();
        controller->scrubToTime(after - travelBack);
        if (!*branched) {
            *branched = true;
            if (branchKey == QLatin1String("integrator")) {
                controller->setIntegrator(branchIntegrator);
            } else {
                if (branchEveryBody) controller->setWorldBody(-1);
                controller->setParameter(branchKey, branchValue);
            }
            controller->runUntil(after);
            return;
        }
        controller->captureScene();  // the worker has shown that moment
        shoot();
    });
    QObject::connect(controller, &elui::SimulationController::runFailed, &window, shoot);
    QObject::connect(controller, &elui::SimulationController::sceneRejected, &window, [&app](const QString& m) {
        std::fprintf(stderr, "elastic-lab: %s\n", qPrintable(m));
        app.exit(2);
    });
    if (after > 0) controller->runUntil(after);
    else QTimer::singleShot(300, &window, shoot);
    // Never hang: give up after two minutes of wall time.
    QTimer::singleShot(120000, &app, [&app] {
        std::fprintf(stderr, "elastic-lab: screenshot timed out\n");
        app.exit(3);
    });
    return app.exec();
}

}  // namespace

int runWindow(QApplication& app, const GuiRequest& r) {
    const bool screenshot = !r.screenshot.isEmpty();
    // Interactive on a CPU renderer (Mesa llvmpipe): no multisampling, it costs more than half
    // the frame rate. Screenshots keep it (quality over speed); ELASTIC_LAB_MSAA decides if set.
    // Not only the views: the window composes its widgets and the views' images with OpenGL in
    // a surface of the default format, which had kept 4x samples (every frame rasterised the
    // whole window four times over: docs/performance.md, "The GUI on a school PC").
    if (!screenshot && !qEnvironmentVariableIsSet("ELASTIC_LAB_MSAA") && elui::Viewport::openGLAvailable() &&
        elui::Viewport::softwareRenderer()) {
        elui::setDefaultGlFormat(0);
        elui::Viewport::setSamples(0);
    }
    elui::MainWindow window(!screenshot);
    if (r.highContrast) window.setHighContrast(true);
    if (r.uiScale != 1.0) window.setUiScale(r.uiScale);
    applyShowSwitches(window, r.show);
    if (r.stepDoubling) window.runDock()->findChild<QCheckBox*>(QStringLiteral("stepDoubling"))->setChecked(true);
    if (r.floatPrecision) window.runDock()->precisionCombo()->setCurrentIndex(1);
    startScene(window, r);
    if (r.selected >= 0) window.controller()->selectParticle(r.selected);  // after the scene: a rebuild clears it
    window.show();
    openDocks(window, r);
    if (r.fpsSeconds > 0.0) return measureFps(app, window, r.fpsSeconds);
    if (screenshot) return takeScreenshot(app, window, r);
    return app.exec();
}

}  // namespace elgui
