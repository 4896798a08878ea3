// elastic-lab: the GUI.
//
//   elastic-lab [FILE.json | --scene S|FILE.json] [--set key=value]... [--integrator NAME] [--compare A,B,C]
//               [--preset ID | --lesson ID] [--experiments] [--docks LIST]
//               [--screenshot FILE --after SECONDS [--travel-back SECONDS [--branch key=value]]]
//
// A scene file may also be given alone (the desktop entry's Exec=elastic-lab %f, a file manager's
// "Open with"). --screenshot runs (as fast as possible) to the given simulated time, renders the main
// window, writes the PNG and exits: used by the tests and for the README's screenshots.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <string_view>
#include <utility>

#include <cmath>

#include <QApplication>
#include <QCheckBox>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QImageWriter>
#include <QElapsedTimer>
#include <QIcon>
#include <QLocale>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTimer>

#include "elastic_lab_version.h"
#include "simcore/body.h"
#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simcore/params.h"
#include "simcore/scaling.h"
#include "simcore/scenes.h"
#include "simcore/world.h"
#include "simlab/output.h"
#include "simlab/request.h"
#include "simlab/scenefile.h"
#include "ui/export.h"
#include "ui/gl_format.h"
#include "ui/language.h"
#include "ui/lessons.h"
#include "ui/lesson_dock.h"
#include "ui/lessons_dialog.h"
#include "ui/main_window.h"
#include "ui/parameter_dock.h"
#include "ui/plot_dock.h"
#include "ui/presets.h"
#include "ui/run_dock.h"
#include "ui/simulation_controller.h"
#include "ui/stability_map_dock.h"
#include "ui/viewport.h"

namespace {

int fail(const QString& message) {
    std::fprintf(stderr, "elastic-lab: %s\n", qPrintable(message));
    return 2;
}

// A value in a message: short and escaped (simcore::quoteShort), never a 5 MB line.
QString quoted(const QString& value, std::size_t limit = 40) {
    return QString::fromStdString(simcore::quoteShort(value.toStdString(), limit));
}

// Started where no window can be shown (no DISPLAY nor WAYLAND_DISPLAY, a display that refuses
// the connection, no platform plugin), Qt ends in a fatal message of several lines whose advice
// ("Reinstalling the application may fix this problem") is wrong. Qt's messages are held while
// the application starts: on the fatal one a single line says what to do, exit 2 (bad input, as
// for every refusal); when the start succeeds, the held messages are printed as Qt would have.
QStringList g_heldMessages;
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

// "en, de, fr, es, ar": the languages built in.
QString languageCodes() {
    QStringList codes;
    for (const elui::Language& l : elui::languages()) codes << l.code;
    return codes.join(QStringLiteral(", "));
}

}  // namespace

int main(int argc, char** argv) {
    // The default format must be set before the application exists (QOpenGLWidget discipline).
    // Multisampling smooths edges; ELASTIC_LAB_MSAA=0 turns it off (software GL is faster so).
    elui::setDefaultGlFormat(qEnvironmentVariableIsSet("ELASTIC_LAB_MSAA") ? qEnvironmentVariableIntValue("ELASTIC_LAB_MSAA") : 4);

    // --help and --version print and exit: they need no display (a headless build machine runs
    // them to make the man page), so they get the offscreen platform unless one is chosen.
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg(argv[i]);
        if ((arg == "--help" || arg == "-h" || arg == "--version" || arg == "-v" || arg == "--help-all") &&
            !qEnvironmentVariableIsSet("QT_QPA_PLATFORM"))
            qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    const QtMessageHandler qtHandler = qInstallMessageHandler(startupMessageHandler);
    QApplication app(argc, argv);
    qInstallMessageHandler(qtHandler);
    for (const QString& message : std::exchange(g_heldMessages, {})) std::fprintf(stderr, "%s\n", qPrintable(message));
    QApplication::setOrganizationName(QStringLiteral("ElasticLab"));
    QApplication::setApplicationName(QStringLiteral("elastic-lab"));
    QApplication::setApplicationVersion(QString::fromLatin1(elastic_lab::kVersion));
    // Desktop integration: the installed desktop entry is named by the application id (Wayland
    // matches the window to it by this name; X11 by StartupWMClass there); the window icon is
    // the installed SVG drawn to PNG (Qt draws PNG without the SVG module).
    QGuiApplication::setDesktopFileName(QString::fromLatin1(elastic_lab::kAppId));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/elastic-lab.png")));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Elastic Lab: two-layer elastic bodies, for teaching."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("FILE.json"),
                                 QStringLiteral("A scene file to open (as --scene FILE.json; what the desktop entry passes)."),
                                 QStringLiteral("[FILE.json]"));
    const QCommandLineOption sceneOpt(QStringLiteral("scene"), QStringLiteral("Scene: %1, or a scene file (.json).").arg(elui::toQString(simcore::sceneNames())),
                                      QStringLiteral("S"), QStringLiteral("ring2d"));
    const QCommandLineOption setOpt(QStringLiteral("set"), QStringLiteral("Set a parameter (repeatable)."),
                                    QStringLiteral("key=value"));
    const QCommandLineOption integratorOpt(QStringLiteral("integrator"), QStringLiteral("Integrator."),
                                           QStringLiteral("NAME"), QStringLiteral("rk4"));
    const QCommandLineOption compareOpt(QStringLiteral("compare"),
                                        QStringLiteral("Up to three integrators side by side, comma separated."),
                                        QStringLiteral("A,B,C"));
    const QCommandLineOption presetOpt(QStringLiteral("preset"), QStringLiteral("Start from a preset."),
                                       QStringLiteral("ID"));
    const QCommandLineOption lessonOpt(QStringLiteral("lesson"),
                                       QStringLiteral("Set up a guided experiment (Help > Experiments): %1.")
                                           .arg(elui::lessonIds().join(QStringLiteral(", "))),
                                       QStringLiteral("ID"));
    const QCommandLineOption experimentsOpt(QStringLiteral("experiments"),
                                            QStringLiteral("Open the Experiments dialog (Help > Experiments) at start."));
    const QCommandLineOption shotOpt(QStringLiteral("screenshot"),
                                     QStringLiteral("Render the main window to FILE (PNG) and exit."),
                                     QStringLiteral("FILE"));
    const QCommandLineOption afterOpt(QStringLiteral("after"), QStringLiteral("Simulated time before the screenshot."),
                                      QStringLiteral("SECONDS"), QStringLiteral("0"));
    const QCommandLineOption optionsOpt(QStringLiteral("show"),
                                        QStringLiteral("Display switches, comma separated: strain, forces, velocities, normals, noparticles, "
                                                       "nofaces, nostructural, noradius, noshear, nobox, errorband, reference."),
                                        QStringLiteral("LIST"));
    const QCommandLineOption docksOpt(QStringLiteral("docks"),
                                      QStringLiteral("Open these docks, comma separated: %1.")
                                          .arg(elui::MainWindow::dockNames().join(QStringLiteral(", "))),
                                      QStringLiteral("LIST"));
    const QCommandLineOption selectOpt(QStringLiteral("select"),
                                       QStringLiteral("Show the forces on particle INDEX (as a click on it does)."),
                                       QStringLiteral("INDEX"));
    const QCommandLineOption doublingOpt(QStringLiteral("step-doubling"),
                                         QStringLiteral("Estimate the error of fixed-step methods by step doubling "
                                                        "(the Run dock's checkbox)."));
    const QCommandLineOption fpsOpt(QStringLiteral("measure-fps"),
                                    QStringLiteral("Run in real time for SECONDS of wall time, print frame rate, "
                                                   "step rate and GUI latency, exit."),
                                    QStringLiteral("SECONDS"));
    const QCommandLineOption travelOpt(QStringLiteral("travel-back"),
                                       QStringLiteral("For --screenshot: once --after is reached, travel back this many "
                                                      "simulated seconds on the timeline before the shot."),
                                       QStringLiteral("SECONDS"));
    const QCommandLineOption branchOpt(QStringLiteral("branch"),
                                       QStringLiteral("With --travel-back: branch there with key=value (a parameter, or "
                                                      "integrator=NAME), run on to --after and travel back again."),
                                       QStringLiteral("key=value"));
    const QCommandLineOption contrastOpt(QStringLiteral("high-contrast"),
                                         QStringLiteral("Start in high contrast (View > High contrast): white on black, "
                                                        "yellow focus."));
    const QCommandLineOption langOpt(QStringLiteral("lang"),
                                     QStringLiteral("The language of the window: %1 (View > Language; without it, the one "
                                                    "chosen there, else the system's).")
                                         .arg(languageCodes()),
                                     QStringLiteral("CODE"));
    const QCommandLineOption scaleOpt(QStringLiteral("ui-scale"),
                                      QStringLiteral("Presentation mode at start: every text SCALE times larger (1 to 2; "
                                                     "View > Presentation mode, Ctrl+= / Ctrl+-)."),
                                      QStringLiteral("SCALE"));
    parser.addOptions({sceneOpt, setOpt, integratorOpt, compareOpt, presetOpt, lessonOpt, experimentsOpt, shotOpt, afterOpt,
                       optionsOpt, docksOpt, fpsOpt, travelOpt, branchOpt, selectOpt, doublingOpt, scaleOpt, contrastOpt, langOpt});
    // Bad input is exit 2 with one line, as in elastic-lab-cli (process() would exit 1).
    if (!parser.parse(QApplication::arguments())) return fail(parser.errorText());
    if (parser.isSet(QStringLiteral("help"))) parser.showHelp(0);
    if (parser.isSet(QStringLiteral("version"))) parser.showVersion();
    // The language before any widget or translated text is made (ui/language.h): --lang, else
    // View > Language's choice (not for screenshots, which keep no settings), else the system's.
    const QString lang = parser.value(langOpt);
    if (!lang.isEmpty() && !elui::isLanguage(lang))
        return fail(QStringLiteral("--lang %1 is not one of %2").arg(quoted(lang), languageCodes()));
    elui::applyLanguage(elui::chooseLanguage(
        lang, parser.isSet(shotOpt) ? QString() : QSettings().value(QStringLiteral("language")).toString(),
        QLocale::system().uiLanguages()));
    // One scene, given alone (a file from the desktop) or by --scene, not both.
    const QStringList positional = parser.positionalArguments();
    if (positional.size() > 1)
        return fail(QStringLiteral("unexpected argument %1: one scene file at most; elastic-lab --help lists the options")
                        .arg(quoted(positional.at(1))));
    if (!positional.isEmpty() && parser.isSet(sceneOpt))
        return fail(QStringLiteral("%1 and --scene both choose the scene; give one").arg(quoted(positional.front())));
    const bool sceneGiven = parser.isSet(sceneOpt) || !positional.isEmpty();
    // A value-taking option given twice would silently lose one of the values.
    for (const QCommandLineOption* once : {&sceneOpt, &integratorOpt, &compareOpt, &presetOpt, &lessonOpt, &shotOpt, &afterOpt,
                                           &optionsOpt, &docksOpt, &fpsOpt, &travelOpt, &branchOpt,
                                           &selectOpt, &scaleOpt, &langOpt})
        if (parser.values(*once).size() > 1)
            return fail(QStringLiteral("--%1 is given %2 times; give it once").arg(once->names().front()).arg(parser.values(*once).size()));
    if (parser.isSet(afterOpt) && !parser.isSet(shotOpt))
        return fail(QStringLiteral("--after needs --screenshot (it is the simulated time of the screenshot)"));

    // Scene and parameters, validated by simcore's table.
    const elui::Preset* preset = nullptr;
    if (parser.isSet(presetOpt)) {
        preset = elui::findPreset(parser.value(presetOpt));
        if (!preset) return fail(QStringLiteral("unknown preset %1").arg(quoted(parser.value(presetOpt))));
    }
    // --lesson: the lesson's preset (its scene, parameters and integrators) and its docks.
    const elui::Lesson* lesson = nullptr;
    if (parser.isSet(lessonOpt)) {
        if (preset) return fail(QStringLiteral("--lesson and --preset both choose the start; give one"));
        lesson = elui::findLesson(parser.value(lessonOpt));
        if (!lesson)
            return fail(QStringLiteral("unknown lesson %1; allowed: %2")
                            .arg(quoted(parser.value(lessonOpt)), elui::lessonIds().join(QStringLiteral(", "))));
        preset = &lesson->preset;
    }
    // The scene through the front door (simlab::resolveScene), as the CLI takes it: a name or a
    // scene file (--scene or the one positional argument a file manager hands over: an existing
    // file by any name), --set (each key once), --integrator; a preset's values when no scene is given.
    const QString sceneArg = positional.isEmpty() ? parser.value(sceneOpt) : positional.front();
    simlab::SceneRequest request;
    request.scene = sceneArg.toStdString();
    request.severalBodies = true;  // the window runs scenes of several bodies (--set bodyN.key=value)
    if (preset && !sceneGiven) {
        if (std::optional<simcore::WorldSpec> presetWorld = preset->world()) {  // a lesson of several bodies
            request.scene = presetWorld->name;
            request.baseWorld = std::move(presetWorld);
        } else {
            request.base = preset->parameters();
            request.scene = simcore::sceneInfo(request.base->kind()).name;
        }
    }
    for (const QString& assignment : parser.values(setOpt)) request.set.push_back(assignment.toStdString());
    if (parser.isSet(integratorOpt)) request.integrator = parser.value(integratorOpt).toStdString();
    simlab::SceneSetup setup;
    try {
        setup = simlab::resolveScene(request);
    } catch (const simlab::RequestError& e) {
        return fail(QString::fromStdString(e.what()));
    }
    const std::optional<simlab::SceneFile>& file = setup.file;
    const std::optional<simcore::WorldSpec>& world = setup.world;
    if (world && parser.isSet(compareOpt))
        return fail(QStringLiteral("--compare takes scenes of one body (a world of several bodies runs alone, "
                                   "with one integrator)"));
    const simcore::ParameterSet& params = setup.params;
    QStringList integrators{QString::fromStdString(setup.integrator)};
    if (preset && !parser.isSet(integratorOpt) && !file) integrators = preset->integrators;
    if (parser.isSet(compareOpt)) {
        // The CLI's list rules: no empty item, none twice.
        const simcore::NameList list = simcore::parseNameList("compare", parser.value(compareOpt).toStdString());
        if (!list.error.empty()) return fail(QString::fromStdString(list.error));
        integrators.clear();
        for (const std::string& name : list.items) integrators << QString::fromStdString(name);
    }
    std::vector<std::string> lanes;
    for (const QString& name : integrators) lanes.push_back(name.toStdString());
    try {
        simlab::checkLanes(params, lanes);
    } catch (const simlab::RequestError& e) {
        return fail(QString::fromStdString(e.what()));
    }
    // --docks: the CLI's list rules, and only docks this build has (refused like any unknown name).
    QStringList docks;
    if (parser.isSet(docksOpt)) {
        const simcore::NameList list = simcore::parseNameList("docks", parser.value(docksOpt).toStdString());
        if (!list.error.empty()) return fail(QString::fromStdString(list.error));
        const QStringList known = elui::MainWindow::dockNames();
        for (const std::string& item : list.items) {
            const QString name = QString::fromStdString(item);
            if (!known.contains(name))
                return fail(QStringLiteral("unknown dock %1; allowed: %2").arg(quoted(name), known.join(QStringLiteral(", "))));
            docks << name;
        }
    }
    bool afterOk = false;
    const double after = parser.value(afterOpt).toDouble(&afterOk);
    // Finite: --after inf would never be reached and nan compares false with everything.
    if (!afterOk || !std::isfinite(after) || after < 0 || after > 1e6)
        return fail(QStringLiteral("--after needs a finite time in seconds, 0 to 1e6"));

    const bool screenshot = parser.isSet(shotOpt);
    // --travel-back, --branch: a picture of time travel.
    double travelBack = 0.0;
    if (parser.isSet(travelOpt)) {
        const auto v = simcore::parseNumber(parser.value(travelOpt).toStdString());
        if (!screenshot) return fail(QStringLiteral("--travel-back needs --screenshot"));
        if (!v || !(*v > 0.0) || !(*v <= after))
            return fail(QStringLiteral("--travel-back needs a time in seconds above 0 and at most --after"));
        travelBack = *v;
    }
    QString branchKey;
    double branchValue = 0.0;
    if (parser.isSet(branchOpt)) {
        if (travelBack <= 0.0) return fail(QStringLiteral("--branch needs --travel-back (the instant it branches at)"));
        const QString text = parser.value(branchOpt);
        const qsizetype eq = text.indexOf(QLatin1Char('='));
        branchKey = text.left(eq).trimmed();
        if (branchKey == QLatin1String("integrator")) {
            if (auto error = simcore::unknownIntegrator(text.mid(eq + 1).trimmed().toStdString()))
                return fail(QStringLiteral("--branch ") + QString::fromStdString(*error));
        } else {
            simcore::ParameterSet probe = params;
            if (auto error = probe.assign(text.toStdString())) return fail(QStringLiteral("--branch ") + QString::fromStdString(*error));
            const simcore::ParamSpec* spec = simcore::findParam(branchKey.toStdString());
            if (spec && (spec->isShape() || spec->group == simcore::ParamGroup::Start))
                return fail(QStringLiteral("--branch %1 rebuilds the body (a new run, not a branch)").arg(quoted(branchKey)));
            branchValue = probe.get(spec->id);
        }
    }
    if (screenshot) {
        // The screenshot is an output like the CLI's: never the scene file it was given, in a
        // format this build writes, and a place that can be written, all known before it runs.
        const QString shotPath = parser.value(shotOpt);
        try {
            simlab::checkOutputNamed("screenshot", shotPath.toStdString());
            simlab::checkFiles({{"scene", setup.sceneFile}}, {{"screenshot", shotPath.toStdString()}});
        } catch (const simlab::RequestError& e) {
            return fail(QString::fromStdString(e.what()));
        }
        const QByteArray suffix = QFileInfo(shotPath).suffix().toLower().toLatin1();
        if (!suffix.isEmpty() && !QImageWriter::supportedImageFormats().contains(suffix))
            return fail(QStringLiteral("--screenshot %1: this build cannot write .%2 images; use .png")
                            .arg(quoted(shotPath, 200), QString::fromLatin1(suffix)));
        const simlab::AtomicFile probe(shotPath.toStdString());  // discarded: nothing is written
        if (!probe.ok()) return fail(QStringLiteral("--screenshot ") + QString::fromStdString(probe.error()));
    }
    int selected = -1;
    if (parser.isSet(selectOpt)) {
        bool ok = false;
        selected = parser.value(selectOpt).toInt(&ok);
        if (!ok || selected < 0) return fail(QStringLiteral("--select needs a particle index, 0 or more"));
    }
    double uiScale = 1.0;
    if (parser.isSet(scaleOpt)) {
        const auto v = simcore::parseNumber(parser.value(scaleOpt).toStdString());
        if (!v || *v < 1.0 || *v > 2.0) return fail(QStringLiteral("--ui-scale needs a factor from 1 to 2"));
        uiScale = *v;
    }
    double fpsSeconds = 0.0;
    if (parser.isSet(fpsOpt)) {
        const auto v = simcore::parseNumber(parser.value(fpsOpt).toStdString());
        if (!v || *v < 1.0 || *v > 3600.0) return fail(QStringLiteral("--measure-fps needs a wall time in seconds, 1 to 3600"));
        fpsSeconds = *v;
    }
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
    if (parser.isSet(contrastOpt)) window.setHighContrast(true);
    if (uiScale != 1.0) window.setUiScale(uiScale);
    if (parser.isSet(optionsOpt)) {
        elui::ViewOptions o = window.viewOptions();
        const simcore::NameList list = simcore::parseNameList("show", parser.value(optionsOpt).toStdString());
        if (!list.error.empty()) return fail(QString::fromStdString(list.error));
        for (const std::string& item : list.items) {
            const QString s = QString::fromStdString(item);
            if (s == QLatin1String("strain")) o.strain = true;
            else if (s == QLatin1String("forces")) o.forces = true;
            else if (s == QLatin1String("velocities")) o.velocities = true;
            else if (s == QLatin1String("normals")) o.normals = true;
            else if (s == QLatin1String("noparticles")) o.particles = false;
            else if (s == QLatin1String("nofaces")) o.faces = false;
            else if (s == QLatin1String("nostructural")) o.springs[0] = false;
            else if (s == QLatin1String("noradius")) o.springs[1] = false;
            else if (s == QLatin1String("noshear")) o.springs[2] = false;
            else if (s == QLatin1String("nobox")) o.box = false;
            else if (s == QLatin1String("errorband")) window.plotDock()->setBandsShown(true);
            else if (s == QLatin1String("reference")) window.plotDock()->setReferenceShown(true);
            else return fail(QStringLiteral("unknown --show switch %1").arg(quoted(s)));
        }
        window.setViewOptions(o);
    }
    elui::SimulationController* controller = window.controller();
    if (parser.isSet(doublingOpt)) window.runDock()->findChild<QCheckBox*>(QStringLiteral("stepDoubling"))->setChecked(true);
    if (world) {
        if (file) {
            simlab::SceneFile changed = *file;
            changed.world = world;
            changed.integrator = integrators.front().toStdString();
            window.openScene(changed, integrators, sceneArg, &*file);
        } else {
            window.startWorld(*world, integrators.front());
        }
    } else if (file) {
        simlab::SceneFile changed = *file;
        changed.params = params;
        changed.integrator = integrators.front().toStdString();
        window.openScene(changed, integrators, sceneArg, &*file);
    } else {
        if (preset) controller->setStartKick(preset->kickInner, preset->kickOuter);
        window.startScene(params, integrators);
    }
    if (selected >= 0) controller->selectParticle(selected);  // after the scene: a rebuild clears it
    window.show();
    // After show(): the docks take their share of a laid-out window.
    if (lesson) {
        docks = lesson->docks + docks;
        window.lessonDock()->setLesson(lesson);
        docks << QStringLiteral("lesson");
    }
    for (const QString& dock : docks) window.openDock(dock);
    if (parser.isSet(experimentsOpt)) {
        elui::LessonsDialog* dialog = window.showLessons();
        if (lesson) dialog->selectLesson(lesson->id);
    }

    if (parser.isSet(fpsOpt)) {
        // Frames painted per wall second while the simulation runs in real time, and how late
        // a 10 ms GUI timer fires (the UI's responsiveness).
        const double seconds = fpsSeconds;
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
                            f->scene->topology.particleCount(), double(paints - paints0) / elapsed,
                            f->stepsPerSecond, f->lanes[0].diagnostics.time / elapsed, *worstLate,
                            f->fallingBehind ? "yes" : "no");
                std::fflush(stdout);
                QApplication::exit(0);
            });
        });
        return app.exec();
    }

    if (screenshot) {
        const QString path = parser.value(shotOpt);
        int exitCode = 0;
        // The grab waits for an open stability map to finish its linearisation (worker thread,
        // up to a few seconds for a large body); the two-minute guard below still holds.
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
        // Time travel: back by --travel-back; with --branch, change it there, run on to --after
        // and travel back to the branch again, so both futures are in the plots.
        const QString branchIntegrator = parser.value(branchOpt).mid(parser.value(branchOpt).indexOf(QLatin1Char('=')) + 1).trimmed();
        auto branched = std::make_shared<bool>(branchKey.isEmpty());
        const bool branchEveryBody = world.has_value();  // a world: key=value sets every body, as --set
        QObject::connect(controller, &elui::SimulationController::reachedTime, &window,
                         [=, &window] {
                             // A lesson's screenshot shows its figures: those of the run, and
                             // the ones "Measure" gives on these parameters.
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
        QObject::connect(controller, &elui::SimulationController::sceneRejected, &window,
                         [&app](const QString& m) {
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
    return app.exec();
}
