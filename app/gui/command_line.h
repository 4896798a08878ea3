#pragma once
// The GUI's command line (issue 31): parsed and checked before any window exists, through the same
// front door as the CLI and Python (simlab/request.h): the scene by simlab::resolveScene, the
// lanes by simlab::checkLanes, the screenshot as an output by simlab::checkFiles and
// checkOutputNamed, every echoed value by simlab::quoted. A refusal is a simlab::RequestError
// whose text main() prints after "elastic-lab: " with exit status 2, as the CLI does after
// "error: ". docs/gui.md lists the options; docs/reliability.md the rules and their tests.
//
// Two stages, because lessons are read in the window's language: parse() (options, repeats,
// --lang), then, once the language is applied, request() (everything else).

#include <optional>

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>
#include <QStringList>

#include "simlab/request.h"

namespace elui {
struct Preset;
struct Lesson;
}  // namespace elui

namespace elgui {

// A display switch of --show, each applied to the window's view options or its plots.
enum class ShowSwitch {
    Strain, Forces, Velocities, Normals, NoParticles, NoFaces, NoStructural, NoRadius, NoShear, NoBox, ErrorBand, Reference
};

// What the window is asked to do, every value checked.
struct GuiRequest {
    simlab::SceneSetup setup;              // the scene, parameters, integrator (and a scene file or world)
    QString sceneArg;                      // the scene as given (a name or a file's path)
    const elui::Preset* preset = nullptr;  // --preset, or the lesson's
    const elui::Lesson* lesson = nullptr;  // --lesson
    QStringList integrators;               // one lane per integrator (1-3)
    QStringList docks;                     // --docks (known names)
    QList<ShowSwitch> show;                // --show
    QString screenshot;                    // --screenshot FILE, or empty
    double after = 0.0;                    // --after [s]
    double travelBack = 0.0;               // --travel-back [s], 0: none
    QString branchKey;                     // --branch key (a parameter, or "integrator"), or empty
    double branchValue = 0.0;              // its value (a parameter)
    QString branchIntegrator;              // its value (integrator=NAME)
    int selected = -1;                     // --select, -1: none
    double uiScale = 1.0;                  // --ui-scale
    double fpsSeconds = 0.0;               // --measure-fps [s], 0: not asked
    bool experiments = false;              // --experiments
    bool stepDoubling = false;             // --step-doubling
    bool floatPrecision = false;           // --precision float (the Run dock's Precision)
    bool highContrast = false;             // --high-contrast
};

class GuiCommandLine {
public:
    GuiCommandLine();
    // Stage 1: the options themselves (unknown ones, stray words, a value given twice, --after
    // without --screenshot, --lang). --help and --version print and end the process (exit 0).
    // Throws simlab::RequestError.
    void parse(const QStringList& arguments);
    // --lang as given (checked), or empty.
    QString language() const;
    bool screenshot() const;
    // Stage 2, after the language is applied: the whole request. Throws simlab::RequestError.
    GuiRequest request() const;

private:
    QCommandLineParser m_parser;
    QCommandLineOption m_scene, m_set, m_integrator, m_compare, m_preset, m_lesson, m_experiments, m_screenshot, m_after,
        m_show, m_docks, m_select, m_doubling, m_precision, m_fps, m_travel, m_branch, m_contrast, m_lang, m_scale;

    void start(GuiRequest& r) const;
    void resolve(GuiRequest& r) const;
    void lanesAndDocks(GuiRequest& r) const;
    void timeTravel(GuiRequest& r) const;
    void screenshotFile(GuiRequest& r) const;
    void numbers(GuiRequest& r) const;
    void showSwitches(GuiRequest& r) const;
};

// "en, de, fr, es, ar": the languages built in.
QString languageCodes();

}  // namespace elgui
