#pragma once
// MainMenus: one part of the main window (docs/architecture.md, "The main window"): its
// actions, its menu bar (File, Simulation, View, Compare, Presets, Studies, Lessons, Help) and
// the presentation mode's class controls. Each action is connected here to what it does on the
// window or its controller; the window keeps only this part.
//
// The texts stay in the window's translation context (Q_DECLARE_TR_FUNCTIONS), so the
// translations (translations/*.ts) read them where they were.

#include <vector>

#include <QCoreApplication>
#include <QString>

class QAction;
class QMenu;
class QToolBar;

namespace elui {

class MainWindow;
class TimelineDock;

class MainMenus {
    Q_DECLARE_TR_FUNCTIONS(elui::MainWindow)

public:
    // The actions and the menu bar of `window` (the actions are its children).
    explicit MainMenus(MainWindow* window);

    // Time travel in the Simulation menu: Step back (Shift+S), Timeline start (Home) and newest
    // (End), each showing `timeline` first, and Clear abandoned future.
    void addTimelineActions(TimelineDock* timeline);
    // The large Run/Pause, Step, Back and Reset bar across the top, hidden until presentation mode.
    void addClassControls();
    // File > Open recent from the window's recent files.
    void fillRecentMenu();
    // Run / Pause says what pressing it does.
    void setRunning(bool running);

    QAction* presentation() const { return m_presentation; }
    QAction* highContrast() const { return m_highContrast; }
    QAction* sideBySide() const { return m_sideBySide; }
    QMenu* viewMenu() const { return m_viewMenu; }
    QMenu* lessonsMenu() const { return m_lessonsMenu; }
    QMenu* recentMenu() const { return m_recentMenu; }
    QToolBar* classControls() const { return m_classControls; }
    // View's display toggles (springs, faces, particles, arrows, ruler, ...), in menu order.
    const std::vector<QAction*>& displayToggles() const { return m_displayToggles; }

private:
    void createFileActions();
    void createRunActions();
    void createViewActions();
    void createHelpActions();
    void createFileMenu();
    void createViewMenu();
    void createLanguageMenu();
    void chooseLanguage(const QString& code);  // View > Language: kept for the next start
    void createSceneMenus();                   // Compare, Presets (and Several bodies)
    void createStudiesMenu();
    void createLessonsAndHelpMenus();

    MainWindow* m_window;
    QAction* m_openScene = nullptr;
    QAction* m_saveScene = nullptr;
    QAction* m_saveSceneAs = nullptr;
    QAction* m_exportCsv = nullptr;
    QAction* m_exportPlots = nullptr;
    QAction* m_screenshot = nullptr;
    QAction* m_quit = nullptr;
    QAction* m_runPause = nullptr;
    QAction* m_step = nullptr;
    QAction* m_reset = nullptr;
    QAction* m_resetView = nullptr;
    QAction* m_stepBack = nullptr;
    QAction* m_presentation = nullptr;
    QAction* m_zoomIn = nullptr;
    QAction* m_zoomOut = nullptr;
    QAction* m_sideBySide = nullptr;
    QAction* m_single = nullptr;
    QAction* m_help = nullptr;
    QAction* m_lessons = nullptr;
    QAction* m_highContrast = nullptr;
    QAction* m_about = nullptr;
    std::vector<QAction*> m_displayToggles;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    QMenu* m_simulationMenu = nullptr;
    QMenu* m_studiesMenu = nullptr;
    QMenu* m_lessonsMenu = nullptr;
    QToolBar* m_classControls = nullptr;
};

}  // namespace elui
