#pragma once
// MainWindow: the lab, wired by parts (docs/architecture.md, "The main window"). The
// constructor is the recipe:
//   MainMenus (actions, menus) -> createCentral (Banners, views) -> DockSet -> connectController
//   -> the timeline -> the class controls -> readSettings
// Every dock has an objectName and a View-menu toggle; the layout is kept with saveState().

#include <memory>
#include <optional>
#include <vector>

#include <QMainWindow>

#include "ui/dock_set.h"
#include "ui/frame.h"
#include "ui/recent_files.h"
#include "ui/view_options.h"

class QAction;
class QDockWidget;
class QHBoxLayout;
class QLabel;
class QPushButton;
class QFrame;
class QMenu;
class QToolBar;

namespace elui {

class SimulationController;
class Viewport;
class MainMenus;
class Banners;
class SceneDock;
class ParameterDock;
class RunDock;
class PlotDock;
class EnergyBarsDock;
class PvDock;
class BodiesDock;
class StabilityMapDock;
class FailureBanner;
class TimelineDock;
struct Preset;
struct Lesson;
class LessonsDialog;
class LessonDock;
class MeasurePlotDock;
struct Tracked;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // useSettings = false: neither read nor write QSettings (tests, screenshots).
    explicit MainWindow(bool useSettings = true, QWidget* parent = nullptr);
    ~MainWindow() override;

    SimulationController* controller() const { return m_controller; }
    const std::vector<Viewport*>& viewports() const { return m_viewports; }
    SceneDock* sceneDock() const { return m_docks->scene(); }
    ParameterDock* parameterDock() const { return m_docks->parameters(); }
    RunDock* runDock() const { return m_docks->run(); }
    PlotDock* plotDock() const { return m_docks->plots(); }
    EnergyBarsDock* energyBarsDock() const { return m_docks->energyBars(); }
    PvDock* pvDock() const { return m_docks->pv(); }
    TimelineDock* timelineDock() const { return m_docks->timeline(); }
    StabilityMapDock* stabilityMapDock() const { return m_docks->stabilityMap(); }
    BodiesDock* bodiesDock() const { return m_docks->bodies(); }
    LessonDock* lessonDock() const { return m_docks->lesson(); }
    MeasurePlotDock* measureDock() const { return m_docks->measured(); }
    // The view's right-click menu for a particle (-1: none under the cursor): plot its height or
    // speed, its layer centre's height, the body's centre-of-mass height or speed, the layers'
    // separation; the force and velocity arrows and the ruler. The caller shows it.
    QMenu* viewContextMenu(int particle);
    // Adds a quantity to the Measured dock and shows it.
    void plotQuantity(const elui::Tracked& quantity);
    QMenu* lessonsMenu() const;
    // The docks `elastic-lab --docks LIST` opens, by name: "energy-bars", "pv", "stability-map",
    // "timeline", "lesson".
    static QStringList dockNames();
    // Shows the named dock (hidden ones are closed by default); false for an unknown name.
    bool openDock(const QString& name);
    // The dock of a dockNames() name, nullptr for an unknown one.
    QDockWidget* dock(const QString& name) const;
    const ViewOptions& viewOptions() const { return m_options; }
    void setViewOptions(const ViewOptions& options);
    QString failureText() const;
    // View > High contrast (docs/accessibility.md): the palette, the banners and the views.
    void setHighContrast(bool on);
    bool highContrast() const;
    FailureBanner* failureBanner() const;
    // The pre-run stability warning after a rebuild (empty when none is shown), and its
    // one-click remedy: the button that sets the suggested DT.
    QString stabilityText() const;
    QPushButton* useSuggestedDtButton() const;
    // The scene file the window is about (empty: none yet), and the recent-files list.
    QString currentFile() const { return m_currentFile; }
    const RecentFiles& recentFiles() const { return m_recent; }
    QMenu* recentMenu() const;
    // Presentation mode (View menu, Ctrl+= / Ctrl+-): the whole UI's text at `scale` (1 = normal,
    // 1.25 .. 2; ui_scale.h), and the large Run/Pause, Step, Back, Reset bar shown above 1.
    void setUiScale(double scale);
    QToolBar* classControls() const;
    QAction* presentationAction() const;
    // `wanted` moved and shrunk into `available` (a screen's available geometry): the window
    // opens, and restores its saved geometry, within the screen it is on.
    static QRect fitWithin(const QRect& wanted, const QRect& available);

public slots:
    void startScene(const simcore::ParameterSet& params, const QStringList& integrators);
    // A scene of several bodies (simcore::World), one world per integrator (side by side with
    // more than one); the Bodies dock opens.
    void startWorld(const simcore::WorldSpec& spec, const QStringList& integrators = {QStringLiteral("rk4")});
    // Scene files. Each returns the error shown to the user (non-blocking message box and
    // status bar), or empty on success; a refused file leaves the running scene as it is.
    QString openSceneFile(const QString& path);
    QString openRecent(const QString& path);  // a file that has gone is dropped from the list
    QString saveSceneFile(const QString& path);
    // A scene file already read (e.g. by main()): integrators empty = the file's own. The file
    // becomes the window's current file once its scene runs. onDisk: what the file holds when
    // `file` was changed after reading (main()'s --set), so the title marks it modified.
    void openScene(const simlab::SceneFile& file, const QStringList& integrators, const QString& path,
                   const simlab::SceneFile* onDisk = nullptr);
    void openSceneDialog();  // asks first when the current file has unsaved changes
    // Whether the window may drop its scene (quit, open another file): true when nothing is
    // unsaved; otherwise asks Save / Discard / Cancel (window-modal) and says whether to go on
    // (Save: only when the save worked).
    bool maybeSave();
    void saveScene();  // to the current file, or Save as when there is none
    void saveSceneAs();
    void applyPreset(const elui::Preset& preset);
    // A guided experiment (Help > Experiments): its preset, then its docks.
    void applyLesson(const elui::Lesson& lesson);
    // Help > Experiments: the one lessons dialog of this window, shown and raised.
    LessonsDialog* showLessons();
    void exportCsv();
    void exportPlots();
    void saveViewportScreenshot();
    void showHelp();
    void chooseSideBySide();
    // These integrators side by side from the start of the current scene (one body or a world),
    // each lane checked by the front door first (simlab::checkLanes): its refusal, shown to the
    // user, or empty when the views start.
    QString sideBySide(const QStringList& integrators);
    void singleView();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    friend class MainMenus;  // its actions call the helpers below (status, the current file, ...)

    void createCentral();
    void connectController();
    void readSettings();
    void writeSettings();

    void onFrame(const FramePtr& frame);
    void rebuildViewports(int count);
    void rebuildFromSceneDock(const simcore::ParameterSet& shape);
    void status(const QString& text);
    // A warning in a window-modal message box that does not block (the run goes on), and in
    // the status bar.
    void warn(const QString& title, const QString& text);
    void setCurrentFile(const QString& path, const simcore::ParameterSet& saved, const QString& integrator);
    void updateTitle(const Frame& frame);
    void adoptOpenedFile();
    void showWorldMode(bool world);  // what a world has and has not (menus, docks)
    // The scene of several bodies running now (its spec with the edits made), or none.
    std::optional<simcore::WorldSpec> runningWorld() const;

    SimulationController* m_controller = nullptr;
    bool m_useSettings = true;
    ViewOptions m_options;

    // The parts: the actions and menus, the banners above the views, the docks.
    std::unique_ptr<MainMenus> m_menus;
    std::unique_ptr<Banners> m_banners;
    std::unique_ptr<DockSet> m_docks;

    // Central area: the banners above a row of one to three viewports.
    QHBoxLayout* m_viewRow = nullptr;
    QWidget* m_noGl = nullptr;
    std::vector<Viewport*> m_viewports;

    bool m_worldShown = false;  // the last frame was a world's
    simcore::ParameterSet m_shownParams;
    bool m_paramsShown = false;

    // Scene file: the path, and the parameters and integrator it holds (what "modified" is
    // measured against). An open waits in m_pending until its scene runs.
    QString m_currentFile;
    simcore::ParameterSet m_savedParams;
    QString m_savedIntegrator;
    struct PendingOpen {
        QString path;
        simcore::ParameterSet params;
        QString integrator;
        bool hasState = false;
        double time = 0.0;
    };
    std::optional<PendingOpen> m_pending;
    RecentFiles m_recent;

    LessonsDialog* m_lessonsDialog = nullptr;
    bool m_highContrastWanted = false;  // from the settings, applied once the window is built
};

}  // namespace elui
