#include "ui/main_menus.h"

#include <algorithm>

#include <QAction>
#include <QActionGroup>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QToolBar>
#include <QTranslator>

#include "simcore/scenes.h"
#include "simcore/world.h"
#include "simlab/request.h"
#include "ui/language.h"
#include "ui/lessons.h"
#include "ui/main_window.h"
#include "ui/parameter_dock.h"
#include "ui/presets.h"
#include "ui/simulation_controller.h"
#include "ui/studies_dialog.h"
#include "ui/timeline_dock.h"
#include "ui/ui_scale.h"
#include "ui/viewport.h"

namespace elui {

MainMenus::MainMenus(MainWindow* window) : m_window(window) {
    createFileActions();
    createRunActions();
    createViewActions();
    createHelpActions();
    createFileMenu();
    QMenu* sim = m_simulationMenu = m_window->menuBar()->addMenu(tr("&Simulation"));
    sim->addAction(m_runPause);
    sim->addAction(m_step);
    sim->addAction(m_reset);
    createViewMenu();
    createSceneMenus();
    createStudiesMenu();
    createLessonsAndHelpMenus();
}

void MainMenus::createFileActions() {
    MainWindow* w = m_window;
    m_openScene = new QAction(tr("&Open scene..."), w);
    m_openScene->setShortcut(QKeySequence::Open);
    m_openScene->setToolTip(tr("A scene file (.json): scene, parameters, integrator and, if saved, the exact state"));
    QObject::connect(m_openScene, &QAction::triggered, w, &MainWindow::openSceneDialog);
    m_saveScene = new QAction(tr("&Save scene"), w);
    m_saveScene->setShortcut(QKeySequence::Save);
    m_saveScene->setToolTip(tr("Scene, every parameter, the integrator and the exact current state"));
    QObject::connect(m_saveScene, &QAction::triggered, w, &MainWindow::saveScene);
    m_saveSceneAs = new QAction(tr("Save scene &as..."), w);
    m_saveSceneAs->setShortcut(Qt::CTRL | Qt::SHIFT | Qt::Key_S);
    QObject::connect(m_saveSceneAs, &QAction::triggered, w, &MainWindow::saveSceneAs);
    m_exportCsv = new QAction(tr("Export &Data (CSV, Excel)..."), w);
    m_exportCsv->setToolTip(tr("The time series of this run, with the same columns as elastic-lab-cli run --csv"));
    QObject::connect(m_exportCsv, &QAction::triggered, w, &MainWindow::exportCsv);
    m_exportPlots = new QAction(tr("Export &plots (PNG, SVG, PDF)..."), w);
    QObject::connect(m_exportPlots, &QAction::triggered, w, &MainWindow::exportPlots);
    m_screenshot = new QAction(tr("Save &viewport screenshot..."), w);
    QObject::connect(m_screenshot, &QAction::triggered, w, &MainWindow::saveViewportScreenshot);
    m_quit = new QAction(tr("&Quit"), w);
    m_quit->setShortcut(QKeySequence::Quit);
    QObject::connect(m_quit, &QAction::triggered, w, &QWidget::close);
}

void MainMenus::createRunActions() {
    MainWindow* w = m_window;
    SimulationController* c = w->controller();
    m_runPause = new QAction(tr("&Run / Pause"), w);
    m_runPause->setShortcut(Qt::Key_Space);
    QObject::connect(m_runPause, &QAction::triggered, w, [c] {
        if (c->running()) c->pause();
        else c->run();
    });
    m_step = new QAction(tr("&Step"), w);
    m_step->setShortcut(Qt::Key_S);
    QObject::connect(m_step, &QAction::triggered, c, &SimulationController::step);
    m_reset = new QAction(tr("R&eset"), w);
    m_reset->setShortcut(Qt::CTRL | Qt::Key_R);
    QObject::connect(m_reset, &QAction::triggered, c, &SimulationController::reset);
    m_resetView = new QAction(tr("Reset &view"), w);
    m_resetView->setShortcut(Qt::CTRL | Qt::Key_0);  // Home / End travel the timeline
    QObject::connect(m_resetView, &QAction::triggered, w, [w] {
        for (Viewport* v : w->viewports()) v->resetView();
    });
}

void MainMenus::createViewActions() {
    MainWindow* w = m_window;
    // Presentation mode: the whole UI's text larger for a projector (ui_scale.h).
    m_presentation = new QAction(tr("&Presentation mode"), w);
    m_presentation->setCheckable(true);
    m_presentation->setShortcut(Qt::Key_F5);
    m_presentation->setToolTip(tr("Everything %1x larger, with large Run, Step, Back and Reset buttons: for a projector")
                                   .arg(kPresentationScale));
    QObject::connect(m_presentation, &QAction::triggered, w,
                     [w](bool on) { w->setUiScale(on ? std::max(kPresentationScale, uiScale()) : 1.0); });
    m_zoomIn = new QAction(tr("&Larger text"), w);
    // Ctrl+= (no Shift needed) and Ctrl++; not also QKeySequence::ZoomIn, which is Ctrl++ here:
    // a sequence given twice is ambiguous and triggers nothing.
    m_zoomIn->setShortcuts({QKeySequence(Qt::CTRL | Qt::Key_Equal), QKeySequence(Qt::CTRL | Qt::Key_Plus)});
    QObject::connect(m_zoomIn, &QAction::triggered, w, [w] { w->setUiScale(nextUiScale(uiScale(), +1)); });
    m_zoomOut = new QAction(tr("S&maller text"), w);
    m_zoomOut->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Minus));
    QObject::connect(m_zoomOut, &QAction::triggered, w, [w] { w->setUiScale(nextUiScale(uiScale(), -1)); });

    struct Toggle {
        QString text;
        bool ViewOptions::*flag;
        int family;
    };
    const std::vector<Toggle> toggles = {
        {tr("Structural springs"), nullptr, 0}, {tr("Radius springs"), nullptr, 1},
        {tr("Shear springs"), nullptr, 2},      {tr("Faces"), &ViewOptions::faces, -1},
        {tr("Particles"), &ViewOptions::particles, -1}, {tr("Normals"), &ViewOptions::normals, -1},
        {tr("Force vectors"), &ViewOptions::forces, -1}, {tr("Velocity vectors"), &ViewOptions::velocities, -1},
        {tr("Ruler (drag to measure)"), &ViewOptions::ruler, -1}, {tr("Colour springs by strain"), &ViewOptions::strain, -1},
        {tr("Collision box"), &ViewOptions::box, -1},
    };
    for (const Toggle& t : toggles) {
        auto* a = new QAction(t.text, w);
        a->setCheckable(true);
        a->setChecked(t.flag ? w->viewOptions().*(t.flag) : w->viewOptions().springs[t.family]);
        a->setObjectName(QStringLiteral("toggle_") + t.text);
        const auto flag = t.flag;
        const int family = t.family;
        QObject::connect(a, &QAction::toggled, w, [w, flag, family](bool on) {
            ViewOptions o = w->viewOptions();
            if (flag) o.*flag = on;
            else o.springs[family] = on;
            w->setViewOptions(o);
        });
        m_displayToggles.push_back(a);
    }

    m_sideBySide = new QAction(tr("&Side by side..."), w);
    QObject::connect(m_sideBySide, &QAction::triggered, w, &MainWindow::chooseSideBySide);
    m_single = new QAction(tr("Single &view"), w);
    QObject::connect(m_single, &QAction::triggered, w, &MainWindow::singleView);
}

void MainMenus::createHelpActions() {
    MainWindow* w = m_window;
    m_help = new QAction(tr("Elastic Lab &help"), w);
    m_help->setShortcut(QKeySequence::HelpContents);
    QObject::connect(m_help, &QAction::triggered, w, &MainWindow::showHelp);
    m_lessons = new QAction(tr("Lesson &texts (Experiments)..."), w);
    m_lessons->setToolTip(tr("Guided experiments: a scene set up in one click, what to change, what to look at, "
                             "the measured answer"));
    QObject::connect(m_lessons, &QAction::triggered, w, &MainWindow::showLessons);
    m_about = new QAction(tr("&About"), w);
    QObject::connect(m_about, &QAction::triggered, w, [w] {
        QMessageBox::about(w, tr("About Elastic Lab"),
                           tr("Elastic Lab: the dynamics of two-layer elastic bodies, for teaching."));
    });
}

void MainMenus::createFileMenu() {
    QMenu* file = m_window->menuBar()->addMenu(tr("&File"));
    file->setToolTipsVisible(true);
    file->addAction(m_openScene);
    m_recentMenu = file->addMenu(tr("Open &recent"));
    m_recentMenu->setObjectName(QStringLiteral("recentMenu"));
    m_recentMenu->setToolTipsVisible(true);
    fillRecentMenu();
    file->addAction(m_saveScene);
    file->addAction(m_saveSceneAs);
    file->addSeparator();
    file->addAction(m_exportCsv);
    file->addAction(m_exportPlots);
    file->addAction(m_screenshot);
    file->addSeparator();
    file->addAction(m_quit);
}

void MainMenus::createViewMenu() {
    m_viewMenu = m_window->menuBar()->addMenu(tr("&View"));  // dock toggles are added by DockSet
    for (QAction* a : m_displayToggles) m_viewMenu->addAction(a);
    m_viewMenu->addAction(m_resetView);
    // High contrast: black, white and yellow for the whole window (docs/accessibility.md).
    m_highContrast = m_viewMenu->addAction(tr("&High contrast"));
    m_highContrast->setObjectName(QStringLiteral("highContrast"));
    m_highContrast->setCheckable(true);
    m_highContrast->setToolTip(tr("White text on black, yellow highlight and focus: for low vision and projectors"));
    QObject::connect(m_highContrast, &QAction::toggled, m_window, &MainWindow::setHighContrast);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_presentation);
    m_viewMenu->addAction(m_zoomIn);
    m_viewMenu->addAction(m_zoomOut);
    m_viewMenu->addSeparator();
    createLanguageMenu();
    m_viewMenu->addSeparator();
}

void MainMenus::createSceneMenus() {
    MainWindow* w = m_window;
    QMenu* compare = w->menuBar()->addMenu(tr("&Compare"));
    compare->addAction(m_sideBySide);
    compare->addAction(m_single);
    compare->addSeparator();
    for (const Preset& p : stabilityPresets())
        compare->addAction(p.title, w, [w, p] { w->applyPreset(p); });

    QMenu* presets = w->menuBar()->addMenu(tr("&Presets"));
    for (const Preset& p : teachingPresets()) {
        QAction* a = presets->addAction(p.title, w, [w, p] { w->applyPreset(p); });
        a->setToolTip(p.description);
    }
    // Scenes of several bodies (simcore::World): bodies that meet bodies.
    QMenu* worlds = presets->addMenu(tr("Several &bodies"));
    worlds->setObjectName(QStringLiteral("worldsMenu"));
    worlds->setToolTipsVisible(true);
    for (const simcore::WorldSceneInfo& info : simcore::worldSceneTable()) {
        const QString name = toQString(info.name);
        QAction* a = worlds->addAction(name, w, [w, name] {
            w->setCurrentFile({}, simcore::ParameterSet{}, {});
            w->startWorld(*simcore::worldScene(name.toStdString()));
            w->status(tr("%1: several bodies. The Bodies dock shows momentum and min_gap; Parameters has a body "
                         "selector. Press Run (Space).").arg(name));
        });
        a->setToolTip(toQString(info.description));
    }
    presets->setToolTipsVisible(true);
}

void MainMenus::createStudiesMenu() {
    MainWindow* w = m_window;
    SimulationController* c = w->controller();
    // A scene of several bodies is studied whole where simlab studies one (work-precision,
    // refinement, the stability scan: the CLI's study, study --refine and stability); the rest
    // is refused by simlab's own check, in its words.
    m_studiesMenu = w->menuBar()->addMenu(tr("S&tudies"));
    m_studiesMenu->addAction(tr("&Work-precision study..."), w, [w, c] {
        auto* d = new WorkPrecisionDialog(c->parameters(), w, w->runningWorld());
        d->setAttribute(Qt::WA_DeleteOnClose);
        d->show();
    });
    m_studiesMenu->addAction(tr("&Refinement study..."), w, [w, c] {
        auto* d = new RefinementDialog(c->parameters(), w, w->runningWorld());
        d->setAttribute(Qt::WA_DeleteOnClose);
        d->show();
    });
    m_studiesMenu->addAction(tr("&Stability scan..."), w, [w, c] {
        auto* d = new StabilityDialog(c->parameters(), w, w->runningWorld());
        d->setAttribute(Qt::WA_DeleteOnClose);
        d->show();
    });
    m_studiesMenu->addAction(tr("&Long-time energy..."), w, [w, c] {
        if (const std::optional<simcore::WorldSpec> world = w->runningWorld()) {
            simlab::ConservationSpec spec;
            spec.params = c->parameters();
            spec.world = world;
            try {
                simlab::checkConservation(spec);  // refuses a world: conservation studies one body
            } catch (const simlab::RequestError& e) {
                w->warn(tr("Long-time energy"), QString::fromStdString(e.what()));
                return;
            }
        }
        auto* d = new ConservationDialog(c->parameters(), w);
        d->setAttribute(Qt::WA_DeleteOnClose);
        d->show();
    });
}

void MainMenus::createLessonsAndHelpMenus() {
    MainWindow* w = m_window;
    // Lessons: each guided experiment set up in one click, and their texts.
    m_lessonsMenu = w->menuBar()->addMenu(tr("&Lessons"));
    for (const Lesson& l : lessons())
        m_lessonsMenu->addAction(l.title, w, [w, id = l.id] {
            if (const Lesson* lesson = findLesson(id)) w->applyLesson(*lesson);
        });
    m_lessonsMenu->addSeparator();
    m_lessonsMenu->addAction(m_lessons);

    QMenu* help = w->menuBar()->addMenu(tr("&Help"));
    help->addAction(m_help);
    help->addAction(m_lessons);
    help->addAction(m_about);
}

void MainMenus::createLanguageMenu() {
    // View > Language: the choice is kept in the settings and applies at the next start (every
    // dock, plot and dialog is built in its language; the running experiment is not torn down
    // for it). The menu says so, in the language chosen as well as in this one.
    QMenu* menu = m_viewMenu->addMenu(tr("&Language"));
    menu->setObjectName(QStringLiteral("languageMenu"));
    auto* group = new QActionGroup(menu);
    const QString saved = m_window->m_useSettings ? QSettings().value(QStringLiteral("language")).toString() : QString();
    auto add = [&](const QString& code, const QString& text) {
        QAction* a = menu->addAction(text);
        a->setObjectName(QStringLiteral("language-") + code);
        a->setCheckable(true);
        a->setData(code);
        a->setChecked(code == (saved.isEmpty() ? QStringLiteral("system") : saved));
        group->addAction(a);
        QObject::connect(a, &QAction::triggered, m_window, [this, code] { chooseLanguage(code); });
    };
    add(QStringLiteral("system"), tr("System language"));
    menu->addSeparator();
    for (const Language& l : languages()) add(l.code, l.nativeName);
    menu->addSeparator();
    QAction* note = menu->addAction(tr("Applies at the next start (now: %1)")
                                        .arg(QLocale(currentLanguage()).nativeLanguageName()));
    note->setEnabled(false);
}

void MainMenus::chooseLanguage(const QString& code) {
    if (m_window->m_useSettings) QSettings().setValue(QStringLiteral("language"), code);
    const QString target = code == QLatin1String("system")
                               ? elui::chooseLanguage({}, {}, QLocale::system().uiLanguages())
                               : code;
    // The sentence in the language chosen too: a student who picked it by mistake can read it.
    const char* const sentence = QT_TR_NOOP("The language changes when Elastic Lab starts again.");
    QString text = tr(sentence);
    QTranslator other;
    if (target != currentLanguage() && target != QLatin1String("en") &&
        other.load(QStringLiteral(":/i18n/elastic-lab_%1.qm").arg(target)))
        text += QStringLiteral("\n\n") + other.translate("elui::MainWindow", sentence);
    else if (target == QLatin1String("en") && currentLanguage() != QLatin1String("en"))
        text += QStringLiteral("\n\n") + QString::fromLatin1(sentence);
    m_window->status(tr("Language: %1 at the next start").arg(QLocale(target).nativeLanguageName()));
    auto* box = new QMessageBox(QMessageBox::Information, tr("Language"), text, QMessageBox::Ok, m_window);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setObjectName(QStringLiteral("languageNote"));
    box->open();
}

void MainMenus::fillRecentMenu() {
    MainWindow* w = m_window;
    m_recentMenu->clear();
    const QStringList paths = w->m_recent.paths();
    for (int i = 0; i < paths.size(); ++i) {
        const QFileInfo info(paths[i]);
        QAction* a = m_recentMenu->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(info.fileName()));
        a->setToolTip(paths[i]);
        a->setData(paths[i]);
        const QString path = paths[i];
        QObject::connect(a, &QAction::triggered, w, [w, path] {
            if (w->maybeSave()) w->openRecent(path);
        });
    }
    if (paths.isEmpty()) m_recentMenu->addAction(tr("(none)"))->setEnabled(false);
    m_recentMenu->addSeparator();
    QAction* clear = m_recentMenu->addAction(tr("&Clear"), w, [this, w] {
        w->m_recent.clear();
        fillRecentMenu();
    });
    clear->setEnabled(!paths.isEmpty());
}

void MainMenus::addTimelineActions(TimelineDock* timeline) {
    MainWindow* w = m_window;
    SimulationController* c = w->controller();
    auto travel = [this, w, timeline](const QString& text, const QKeySequence& key, auto command) {
        auto* a = new QAction(text, w);
        a->setShortcut(key);
        QObject::connect(a, &QAction::triggered, w, [timeline, command] {
            timeline->show();
            command();
        });
        m_simulationMenu->addAction(a);
        return a;
    };
    m_simulationMenu->addSeparator();
    m_stepBack = travel(tr("Step &back"), QKeySequence(Qt::SHIFT | Qt::Key_S), [c] { c->scrubBy(-1); });
    travel(tr("Timeline s&tart"), QKeySequence(Qt::Key_Home), [c] { c->scrubToStart(); });
    travel(tr("Timeline &newest"), QKeySequence(Qt::Key_End), [c] { c->scrubToEnd(); });
    m_simulationMenu->addAction(tr("&Clear abandoned future"), c, &SimulationController::clearAbandoned);
}

void MainMenus::addClassControls() {
    // Large Run/Pause, Step, Back and Reset across the top, shown in presentation mode: the
    // buttons a teacher presses in front of the class, readable and easy to hit.
    m_classControls = new QToolBar(tr("Class controls"), m_window);
    m_classControls->setObjectName(QStringLiteral("classControls"));
    m_classControls->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_classControls->setMovable(false);
    for (QAction* a : {m_runPause, m_step, m_stepBack, m_reset}) m_classControls->addAction(a);
    m_window->addToolBar(Qt::TopToolBarArea, m_classControls);
    m_classControls->hide();
    m_classControls->toggleViewAction()->setVisible(false);  // it follows presentation mode
}

void MainMenus::setRunning(bool running) { m_runPause->setText(running ? tr("&Pause") : tr("&Run")); }

}  // namespace elui
