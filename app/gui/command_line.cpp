#include "app/gui/command_line.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include <QFileInfo>
#include <QImageWriter>

#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simcore/params.h"
#include "simcore/scenes.h"
#include "simcore/world.h"
#include "simlab/output.h"
#include "ui/language.h"
#include "ui/lessons.h"
#include "ui/main_window.h"
#include "ui/presets.h"

namespace elgui {

namespace {

[[noreturn]] void refuse(const QString& message) { throw simlab::RequestError(message.toStdString()); }

// A value in a message: the front door's helper (short and escaped, never a 5 MB line).
QString quoted(const QString& value, std::size_t limit = 40) {
    return QString::fromStdString(simlab::quoted(value.toStdString(), limit));
}

// A list option by the CLI's rules (no empty item, none twice).
QStringList nameList(const char* option, const QString& text) {
    const simcore::NameList list = simcore::parseNameList(option, text.toStdString());
    if (!list.error.empty()) refuse(QString::fromStdString(list.error));
    QStringList out;
    for (const std::string& item : list.items) out << QString::fromStdString(item);
    return out;
}

}  // namespace

QString languageCodes() {
    QStringList codes;
    for (const elui::Language& l : elui::languages()) codes << l.code;
    return codes.join(QStringLiteral(", "));
}

GuiCommandLine::GuiCommandLine()
    : m_scene(QStringLiteral("scene"),
              QStringLiteral("Scene: %1, or a scene file (.json).").arg(QString::fromStdString(simcore::sceneNames())),
              QStringLiteral("S"), QStringLiteral("ring2d")),
      m_set(QStringLiteral("set"), QStringLiteral("Set a parameter (repeatable)."), QStringLiteral("key=value")),
      m_integrator(QStringLiteral("integrator"), QStringLiteral("Integrator."), QStringLiteral("NAME"), QStringLiteral("rk4")),
      m_compare(QStringLiteral("compare"), QStringLiteral("Up to three integrators side by side, comma separated."),
                QStringLiteral("A,B,C")),
      m_preset(QStringLiteral("preset"), QStringLiteral("Start from a preset."), QStringLiteral("ID")),
      m_lesson(QStringLiteral("lesson"),
               QStringLiteral("Set up a guided experiment (Help > Experiments): %1.").arg(elui::lessonIds().join(QStringLiteral(", "))),
               QStringLiteral("ID")),
      m_experiments(QStringLiteral("experiments"), QStringLiteral("Open the Experiments dialog (Help > Experiments) at start.")),
      m_screenshot(QStringLiteral("screenshot"), QStringLiteral("Render the main window to FILE (PNG) and exit."),
                   QStringLiteral("FILE")),
      m_after(QStringLiteral("after"), QStringLiteral("Simulated time before the screenshot."), QStringLiteral("SECONDS"),
              QStringLiteral("0")),
      m_show(QStringLiteral("show"),
             QStringLiteral("Display switches, comma separated: strain, forces, velocities, normals, noparticles, "
                            "nofaces, nostructural, noradius, noshear, nobox, errorband, reference."),
             QStringLiteral("LIST")),
      m_docks(QStringLiteral("docks"),
              QStringLiteral("Open these docks, comma separated: %1.").arg(elui::MainWindow::dockNames().join(QStringLiteral(", "))),
              QStringLiteral("LIST")),
      m_select(QStringLiteral("select"), QStringLiteral("Show the forces on particle INDEX (as a click on it does)."),
               QStringLiteral("INDEX")),
      m_doubling(QStringLiteral("step-doubling"),
                 QStringLiteral("Estimate the error of fixed-step methods by step doubling (the Run dock's checkbox).")),
      m_precision(QStringLiteral("precision"),
                  QStringLiteral("double, or float: the float32 path (the Run dock's Precision; euler, midpoint, rk4, "
                                 "symplectic-euler, verlet; one view of one body)."),
                  QStringLiteral("P"), QStringLiteral("double")),
      m_fps(QStringLiteral("measure-fps"),
            QStringLiteral("Run in real time for SECONDS of wall time, print frame rate, step rate and GUI latency, exit."),
            QStringLiteral("SECONDS")),
      m_travel(QStringLiteral("travel-back"),
               QStringLiteral("For --screenshot: once --after is reached, travel back this many simulated seconds on the "
                              "timeline before the shot."),
               QStringLiteral("SECONDS")),
      m_branch(QStringLiteral("branch"),
               QStringLiteral("With --travel-back: branch there with key=value (a parameter, or integrator=NAME), run on to "
                              "--after and travel back again."),
               QStringLiteral("key=value")),
      m_contrast(QStringLiteral("high-contrast"),
                 QStringLiteral("Start in high contrast (View > High contrast): white on black, yellow focus.")),
      m_lang(QStringLiteral("lang"),
             QStringLiteral("The language of the window: %1 (View > Language; without it, the one chosen there, else the "
                            "system's).")
                 .arg(languageCodes()),
             QStringLiteral("CODE")),
      m_scale(QStringLiteral("ui-scale"),
              QStringLiteral("Presentation mode at start: every text SCALE times larger (1 to 2; View > Presentation mode, "
                             "Ctrl+= / Ctrl+-)."),
              QStringLiteral("SCALE")) {
    m_parser.setApplicationDescription(QStringLiteral("Elastic Lab: two-layer elastic bodies, for teaching."));
    m_parser.addHelpOption();
    m_parser.addVersionOption();
    m_parser.addPositionalArgument(QStringLiteral("FILE.json"),
                                   QStringLiteral("A scene file to open (as --scene FILE.json; what the desktop entry passes)."),
                                   QStringLiteral("[FILE.json]"));
    m_parser.addOptions({m_scene, m_set, m_integrator, m_compare, m_preset, m_lesson, m_experiments, m_screenshot, m_after,
                         m_show, m_docks, m_fps, m_travel, m_branch, m_select, m_doubling, m_precision, m_scale, m_contrast,
                         m_lang});
}

void GuiCommandLine::parse(const QStringList& arguments) {
    // Bad input is a refusal with one line, as in elastic-lab-cli (process() would exit 1).
    if (!m_parser.parse(arguments)) refuse(m_parser.errorText());
    if (m_parser.isSet(QStringLiteral("help"))) m_parser.showHelp(0);
    if (m_parser.isSet(QStringLiteral("version"))) m_parser.showVersion();
    const QString lang = m_parser.value(m_lang);
    if (!lang.isEmpty() && !elui::isLanguage(lang))
        refuse(QStringLiteral("--lang %1 is not one of %2").arg(quoted(lang), languageCodes()));
    // One scene, given alone (a file from the desktop) or by --scene, not both.
    const QStringList positional = m_parser.positionalArguments();
    if (positional.size() > 1)
        refuse(QStringLiteral("unexpected argument %1: one scene file at most; elastic-lab --help lists the options")
                   .arg(quoted(positional.at(1))));
    if (!positional.isEmpty() && m_parser.isSet(m_scene))
        refuse(QStringLiteral("%1 and --scene both choose the scene; give one").arg(quoted(positional.front())));
    // A value-taking option given twice would silently lose one of the values.
    for (const QCommandLineOption* once : {&m_scene, &m_integrator, &m_compare, &m_preset, &m_lesson, &m_screenshot, &m_after,
                                           &m_show, &m_docks, &m_fps, &m_travel, &m_branch, &m_select, &m_precision, &m_scale, &m_lang})
        if (m_parser.values(*once).size() > 1)
            refuse(QStringLiteral("--%1 is given %2 times; give it once").arg(once->names().front()).arg(m_parser.values(*once).size()));
    if (m_parser.isSet(m_after) && !m_parser.isSet(m_screenshot))
        refuse(QStringLiteral("--after needs --screenshot (it is the simulated time of the screenshot)"));
}

QString GuiCommandLine::language() const { return m_parser.value(m_lang); }

bool GuiCommandLine::screenshot() const { return m_parser.isSet(m_screenshot); }

GuiRequest GuiCommandLine::request() const {
    GuiRequest r;
    start(r);
    resolve(r);
    lanesAndDocks(r);
    timeTravel(r);
    if (screenshot()) screenshotFile(r);
    numbers(r);
    showSwitches(r);
    r.experiments = m_parser.isSet(m_experiments);
    r.stepDoubling = m_parser.isSet(m_doubling);
    r.highContrast = m_parser.isSet(m_contrast);
    return r;
}

// --preset or --lesson (the lesson's preset: its scene, parameters and integrators, and its docks).
void GuiCommandLine::start(GuiRequest& r) const {
    if (m_parser.isSet(m_preset)) {
        r.preset = elui::findPreset(m_parser.value(m_preset));
        if (!r.preset) refuse(QStringLiteral("unknown preset %1").arg(quoted(m_parser.value(m_preset))));
    }
    if (m_parser.isSet(m_lesson)) {
        if (r.preset) refuse(QStringLiteral("--lesson and --preset both choose the start; give one"));
        r.lesson = elui::findLesson(m_parser.value(m_lesson));
        if (!r.lesson)
            refuse(QStringLiteral("unknown lesson %1; allowed: %2")
                       .arg(quoted(m_parser.value(m_lesson)), elui::lessonIds().join(QStringLiteral(", "))));
        r.preset = &r.lesson->preset;
    }
}

// The scene through the front door (simlab::resolveScene), as the CLI takes it: a name or a
// scene file (--scene or the one positional argument a file manager hands over: an existing
// file by any name), --set (each key once), --integrator; a preset's values when no scene is given.
void GuiCommandLine::resolve(GuiRequest& r) const {
    const QStringList positional = m_parser.positionalArguments();
    const bool sceneGiven = m_parser.isSet(m_scene) || !positional.isEmpty();
    r.sceneArg = positional.isEmpty() ? m_parser.value(m_scene) : positional.front();
    simlab::SceneRequest request;
    request.scene = r.sceneArg.toStdString();
    request.severalBodies = true;  // the window runs scenes of several bodies (--set bodyN.key=value)
    if (r.preset && !sceneGiven) {
        if (std::optional<simcore::WorldSpec> presetWorld = r.preset->world()) {  // a lesson of several bodies
            request.scene = presetWorld->name;
            request.baseWorld = std::move(presetWorld);
        } else {
            request.base = r.preset->parameters();
            request.scene = simcore::sceneInfo(request.base->kind()).name;
        }
    }
    for (const QString& assignment : m_parser.values(m_set)) request.set.push_back(assignment.toStdString());
    if (m_parser.isSet(m_integrator)) request.integrator = m_parser.value(m_integrator).toStdString();
    r.setup = simlab::resolveScene(request);
}

// --compare (the CLI's list rules; each lane's integrator and memory by simlab::checkLanes, for a
// world every body's with each integrator as run builds it) and
// --docks (only docks this build has, refused like any unknown name).
void GuiCommandLine::lanesAndDocks(GuiRequest& r) const {
    r.integrators = {QString::fromStdString(r.setup.integrator)};
    if (r.preset && !m_parser.isSet(m_integrator) && !r.setup.file) r.integrators = r.preset->integrators;
    if (m_parser.isSet(m_compare)) r.integrators = nameList("compare", m_parser.value(m_compare));
    std::vector<std::string> lanes;
    for (const QString& name : r.integrators) lanes.push_back(name.toStdString());
    if (r.setup.world) simlab::checkLanes(*r.setup.world, lanes);
    else simlab::checkLanes(r.setup.params, lanes);
    // --precision: the front door's check, as the CLI's run (every view's integrator).
    for (const std::string& name : lanes) simlab::checkPrecision(r.setup, m_parser.value(m_precision).toStdString(), name);
    r.floatPrecision = m_parser.value(m_precision) == QLatin1String("float");
    if (m_parser.isSet(m_docks)) {
        const QStringList known = elui::MainWindow::dockNames();
        for (const QString& name : nameList("docks", m_parser.value(m_docks))) {
            if (!known.contains(name))
                refuse(QStringLiteral("unknown dock %1; allowed: %2").arg(quoted(name), known.join(QStringLiteral(", "))));
            r.docks << name;
        }
    }
}

// --after, --travel-back, --branch: a picture of time travel.
void GuiCommandLine::timeTravel(GuiRequest& r) const {
    bool afterOk = false;
    r.after = m_parser.value(m_after).toDouble(&afterOk);
    // Finite: --after inf would never be reached and nan compares false with everything.
    if (!afterOk || !std::isfinite(r.after) || r.after < 0 || r.after > 1e6)
        refuse(QStringLiteral("--after needs a finite time in seconds, 0 to 1e6"));
    if (m_parser.isSet(m_travel)) {
        const auto v = simcore::parseNumber(m_parser.value(m_travel).toStdString());
        if (!screenshot()) refuse(QStringLiteral("--travel-back needs --screenshot"));
        if (!v || !(*v > 0.0) || !(*v <= r.after))
            refuse(QStringLiteral("--travel-back needs a time in seconds above 0 and at most --after"));
        r.travelBack = *v;
    }
    if (!m_parser.isSet(m_branch)) return;
    if (r.travelBack <= 0.0) refuse(QStringLiteral("--branch needs --travel-back (the instant it branches at)"));
    const QString text = m_parser.value(m_branch);
    const qsizetype eq = text.indexOf(QLatin1Char('='));
    r.branchKey = text.left(eq).trimmed();
    if (r.branchKey == QLatin1String("integrator")) {
        r.branchIntegrator = text.mid(eq + 1).trimmed();
        if (auto error = simcore::unknownIntegrator(r.branchIntegrator.toStdString()))
            refuse(QStringLiteral("--branch ") + QString::fromStdString(*error));
        return;
    }
    simcore::ParameterSet probe = r.setup.params;
    if (auto error = probe.assign(text.toStdString())) refuse(QStringLiteral("--branch ") + QString::fromStdString(*error));
    const simcore::ParamSpec* spec = simcore::findParam(r.branchKey.toStdString());
    if (spec && (spec->isShape() || spec->group == simcore::ParamGroup::Start))
        refuse(QStringLiteral("--branch %1 rebuilds the body (a new run, not a branch)").arg(quoted(r.branchKey)));
    r.branchValue = probe.get(spec->id);
}

// The screenshot is an output like the CLI's: never the scene file it was given, in a format this
// build writes, and a place that can be written, all known before it runs.
void GuiCommandLine::screenshotFile(GuiRequest& r) const {
    const QString path = m_parser.value(m_screenshot);
    simlab::checkOutputNamed("screenshot", path.toStdString());
    simlab::checkFiles({{"scene", r.setup.sceneFile}}, {{"screenshot", path.toStdString()}});
    const QByteArray suffix = QFileInfo(path).suffix().toLower().toLatin1();
    if (!suffix.isEmpty() && !QImageWriter::supportedImageFormats().contains(suffix))
        refuse(QStringLiteral("--screenshot %1: this build cannot write .%2 images; use .png")
                   .arg(quoted(path, 200), QString::fromLatin1(suffix)));
    const simlab::AtomicFile probe(path.toStdString());  // discarded: nothing is written
    if (!probe.ok()) refuse(QStringLiteral("--screenshot ") + QString::fromStdString(probe.error()));
    r.screenshot = path;
}

// --select, --ui-scale, --measure-fps.
void GuiCommandLine::numbers(GuiRequest& r) const {
    if (m_parser.isSet(m_select)) {
        bool ok = false;
        r.selected = m_parser.value(m_select).toInt(&ok);
        if (!ok || r.selected < 0) refuse(QStringLiteral("--select needs a particle index, 0 or more"));
    }
    if (m_parser.isSet(m_scale)) {
        const auto v = simcore::parseNumber(m_parser.value(m_scale).toStdString());
        if (!v || *v < 1.0 || *v > 2.0) refuse(QStringLiteral("--ui-scale needs a factor from 1 to 2"));
        r.uiScale = *v;
    }
    if (m_parser.isSet(m_fps)) {
        const auto v = simcore::parseNumber(m_parser.value(m_fps).toStdString());
        if (!v || *v < 1.0 || *v > 3600.0) refuse(QStringLiteral("--measure-fps needs a wall time in seconds, 1 to 3600"));
        r.fpsSeconds = *v;
    }
}

// --show: the CLI's list rules, each switch known.
void GuiCommandLine::showSwitches(GuiRequest& r) const {
    if (!m_parser.isSet(m_show)) return;
    static const std::pair<const char*, ShowSwitch> names[] = {
        {"strain", ShowSwitch::Strain},           {"forces", ShowSwitch::Forces},     {"velocities", ShowSwitch::Velocities},
        {"normals", ShowSwitch::Normals},         {"noparticles", ShowSwitch::NoParticles}, {"nofaces", ShowSwitch::NoFaces},
        {"nostructural", ShowSwitch::NoStructural}, {"noradius", ShowSwitch::NoRadius}, {"noshear", ShowSwitch::NoShear},
        {"nobox", ShowSwitch::NoBox},             {"errorband", ShowSwitch::ErrorBand}, {"reference", ShowSwitch::Reference}};
    for (const QString& item : nameList("show", m_parser.value(m_show))) {
        const auto found = std::find_if(std::begin(names), std::end(names), [&](const auto& n) { return item == QLatin1String(n.first); });
        if (found == std::end(names)) refuse(QStringLiteral("unknown --show switch %1").arg(quoted(item)));
        r.show << found->second;
    }
}

}  // namespace elgui
