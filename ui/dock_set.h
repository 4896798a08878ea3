#pragma once
// DockSet: one part of the main window (docs/architecture.md, "The main window"): the docks.
// It makes each dock, places it (left column: Run, Scene | Parameters | Lesson; right column:
// Plots | Bodies, Measured under them, Energy bars and P–V | Stability map beside them;
// Timeline under the view), adds its toggle to the View menu, wires the docks to the
// controller directly (commands from the docks, rows and frames to them), opens a dock by name
// and keeps the window within a projector's 1280 px.

#include <QString>
#include <QStringList>

class QDockWidget;
class QMainWindow;
class QMenu;

namespace elui {

class SimulationController;
class SceneDock;
class ParameterDock;
class RunDock;
class PlotDock;
class EnergyBarsDock;
class PvDock;
class BodiesDock;
class StabilityMapDock;
class TimelineDock;
class LessonDock;
class MeasurePlotDock;

class DockSet {
public:
    // The docks of `window`, placed, their toggles in `viewMenu` (all but the timeline's).
    DockSet(QMainWindow* window, QMenu* viewMenu);

    // The timeline under the view (the bottom area, between the side columns), closed until
    // asked for; its toggle in `viewMenu`.
    void createTimeline(QMenu* viewMenu);
    // The docks and the controller: what a dock asks for goes to the controller; what the
    // controller brings (scenes, rows) goes to the docks.
    void connectController(SimulationController* c);
    // The timeline's commands to the controller; frames, branches and the abandoned future to
    // the timeline and the plots.
    void connectTimeline(SimulationController* c);

    // The docks `elastic-lab --docks LIST` opens, by name.
    static QStringList names();
    // The dock of a names() name, nullptr for an unknown one.
    QDockWidget* dock(const QString& name) const;
    // Shows the named dock and gives it room; false for an unknown name.
    bool open(const QString& name);
    // Tabs the docks beside the plots into the Plots dock while the window's minimum width
    // would exceed a projector's 1280 px (or the views have under 30 % of the window).
    void keepMinimumWidth();

    SceneDock* scene() const { return m_scene; }
    ParameterDock* parameters() const { return m_parameters; }
    RunDock* run() const { return m_run; }
    PlotDock* plots() const { return m_plots; }
    EnergyBarsDock* energyBars() const { return m_energyBars; }
    PvDock* pv() const { return m_pv; }
    TimelineDock* timeline() const { return m_timeline; }
    StabilityMapDock* stabilityMap() const { return m_stabilityMap; }
    BodiesDock* bodies() const { return m_bodies; }
    LessonDock* lesson() const { return m_lesson; }
    MeasurePlotDock* measured() const { return m_measured; }

private:
    QMainWindow* m_window;
    SceneDock* m_scene = nullptr;
    ParameterDock* m_parameters = nullptr;
    RunDock* m_run = nullptr;
    PlotDock* m_plots = nullptr;
    EnergyBarsDock* m_energyBars = nullptr;
    PvDock* m_pv = nullptr;
    TimelineDock* m_timeline = nullptr;
    StabilityMapDock* m_stabilityMap = nullptr;
    BodiesDock* m_bodies = nullptr;
    LessonDock* m_lesson = nullptr;
    MeasurePlotDock* m_measured = nullptr;
};

}  // namespace elui
