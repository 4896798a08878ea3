#pragma once
// MainWindow: the lab. The constructor is the recipe:
//   createActions -> createMenus -> createCentral -> createDocks -> connectController -> readSettings
// Every dock has an objectName and a View-menu toggle; the layout is kept with saveState().

#include <vector>

#include <QMainWindow>

#include "frame.h"
#include "view_options.h"

class QAction;
class QHBoxLayout;
class QLabel;
class QFrame;
class QMenu;

namespace elui {

class SimulationController;
class Viewport;
class SceneDock;
class ParameterDock;
class RunDock;
class PlotDock;
struct Preset;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    // useSettings = false: neither read nor write QSettings (tests, screenshots).
    explicit MainWindow(bool useSettings = true, QWidget* parent = nullptr);
    ~MainWindow() override;

    SimulationController* controller() const { return m_controller; }
    const std::vector<Viewport*>& viewports() const { return m_viewports; }
    SceneDock* sceneDock() const { return m_sceneDock; }
    ParameterDock* parameterDock() const { return m_parameterDock; }
    RunDock* runDock() const { return m_runDock; }
    PlotDock* plotDock() const { return m_plotDock; }
    const ViewOptions& viewOptions() const { return m_options; }
    void setViewOptions(const ViewOptions& options);
    QString failureText() const;

public slots:
    void startScene(const simcore::ParameterSet& params, const QStringList& integrators);
    void applyPreset(const elui::Preset& preset);
    void exportCsv();
    void exportPlots();
    void saveViewportScreenshot();
    void showHelp();
    void chooseSideBySide();
    void singleView();

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createMenus();
    void createCentral();
    void createDocks();
    void connectController();
    void readSettings();
    void writeSettings();

    void onFrame(const FramePtr& frame);
    void rebuildViewports(int count);
    void rebuildFromSceneDock(const simcore::ParameterSet& shape);
    void showFailure(const FramePtr& frame);
    void status(const QString& text);

    SimulationController* m_controller = nullptr;
    bool m_useSettings = true;
    ViewOptions m_options;

    // Central area: failure banner above a row of one to three viewports.
    QFrame* m_banner = nullptr;
    QLabel* m_bannerText = nullptr;
    QHBoxLayout* m_viewRow = nullptr;
    QWidget* m_noGl = nullptr;
    std::vector<Viewport*> m_viewports;

    SceneDock* m_sceneDock = nullptr;
    ParameterDock* m_parameterDock = nullptr;
    RunDock* m_runDock = nullptr;
    PlotDock* m_plotDock = nullptr;

    simcore::ParameterSet m_shownParams;
    bool m_paramsShown = false;
    bool m_failureShown = false;

    // Actions.
    QAction* m_exportCsv = nullptr;
    QAction* m_exportPlots = nullptr;
    QAction* m_screenshot = nullptr;
    QAction* m_quit = nullptr;
    QAction* m_runPause = nullptr;
    QAction* m_step = nullptr;
    QAction* m_reset = nullptr;
    QAction* m_resetView = nullptr;
    QAction* m_sideBySide = nullptr;
    QAction* m_single = nullptr;
    QAction* m_help = nullptr;
    QAction* m_about = nullptr;
    std::vector<QAction*> m_displayToggles;
    QMenu* m_viewMenu = nullptr;
    QMenu* m_studiesMenu = nullptr;
};

}  // namespace elui
