#include "ui/main_window.h"

#include "ui/bodies_dock.h"
#include "simcore/world.h"

#include <algorithm>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenuBar>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QTranslator>
#include <QVBoxLayout>

#include "simcore/scenes.h"
#include "ui/accessibility.h"
#include "ui/compare_dialog.h"
#include "ui/energy_bars_dock.h"
#include "ui/export.h"
#include "ui/world_export.h"
#include "ui/failure_banner.h"
#include "ui/help_dialog.h"
#include "ui/language.h"
#include "ui/lessons.h"
#include "ui/lesson_dock.h"
#include "ui/lessons_dialog.h"
#include "ui/measure_plot_dock.h"
#include "ui/parameter_dock.h"
#include "ui/plot_dock.h"
#include "ui/presets.h"
#include "ui/pv_dock.h"
#include "ui/run_dock.h"
#include "ui/scene_dock.h"
#include "ui/simulation_controller.h"
#include "ui/stability_map_dock.h"
#include "ui/studies_dialog.h"
#include "ui/timeline_dock.h"
#include "ui/ui_scale.h"
#include "ui/viewport.h"

namespace elui {

MainWindow::MainWindow(bool useSettings, QWidget* parent)
    : QMainWindow(parent), m_useSettings(useSettings), m_recent(useSettings ? new QSettings(this) : nullptr) {
    setWindowTitle(tr("Elastic Lab"));
    m_controller = new SimulationController(this);
    createActions();
    createMenus();
    createCentral();
    createDocks();
    connectController();
    createTimeline();
    createClassControls();
    readSettings();
    // Screen readers get plain-text descriptions of every control (docs/accessibility.md).
    installToolTipDescriptions();
    if (m_highContrastWanted) setHighContrast(true);
}

MainWindow::~MainWindow() {
    // Stop the worker before the viewports go: no frame may arrive at a half-destroyed window.
    delete m_controller;
    m_controller = nullptr;
}

void MainWindow::createActions() {
    m_openScene = new QAction(tr("&Open scene..."), this);
    m_openScene->setShortcut(QKeySequence::Open);
    m_openScene->setToolTip(tr("A scene file (.json): scene, parameters, integrator and, if saved, the exact state"));
    connect(m_openScene, &QAction::triggered, this, &MainWindow::openSceneDialog);
    m_saveScene = new QAction(tr("&Save scene"), this);
    m_saveScene->setShortcut(QKeySequence::Save);
    m_saveScene->setToolTip(tr("Scene, every parameter, the integrator and the exact current state"));
    connect(m_saveScene, &QAction::triggered, this, &MainWindow::saveScene);
    m_saveSceneAs = new QAction(tr("Save scene &as..."), this);
    m_saveSceneAs->setShortcut(Qt::CTRL | Qt::SHIFT | Qt::Key_S);
    connect(m_saveSceneAs, &QAction::triggered, this, &MainWindow::saveSceneAs);
    m_exportCsv = new QAction(tr("Export &Data (CSV, Excel)..."), this);
    m_exportCsv->setToolTip(tr("The time series of this run, with the same columns as elastic-lab-cli run --csv"));
    connect(m_exportCsv, &QAction::triggered, this, &MainWindow::exportCsv);
    m_exportPlots = new QAction(tr("Export &plots (PNG, SVG, PDF)..."), this);
    connect(m_exportPlots, &QAction::triggered, this, &MainWindow::exportPlots);
    m_screenshot = new QAction(tr("Save &viewport screenshot..."), this);
    connect(m_screenshot, &QAction::triggered, this, &MainWindow::saveViewportScreenshot);
    m_quit = new QAction(tr("&Quit"), this);
    m_quit->setShortcut(QKeySequence::Quit);
    connect(m_quit, &QAction::triggered, this, &QWidget::close);

    m_runPause = new QAction(tr("&Run / Pause"), this);
    m_runPause->setShortcut(Qt::Key_Space);
    connect(m_runPause, &QAction::triggered, this, [this] {
        if (m_controller->running()) m_controller->pause();
        else m_controller->run();
    });
    m_step = new QAction(tr("&Step"), this);
    m_step->setShortcut(Qt::Key_S);
    connect(m_step, &QAction::triggered, this, [this] { m_controller->step(); });
    m_reset = new QAction(tr("R&eset"), this);
    m_reset->setShortcut(Qt::CTRL | Qt::Key_R);
    connect(m_reset, &QAction::triggered, this, [this] { m_controller->reset(); });
    m_resetView = new QAction(tr("Reset &view"), this);
    m_resetView->setShortcut(Qt::CTRL | Qt::Key_0);  // Home / End travel the timeline
    connect(m_resetView, &QAction::triggered, this, [this] {
        for (Viewport* v : m_viewports) v->resetView();
    });

    // Presentation mode: the whole UI's text larger for a projector (ui_scale.h).
    m_presentation = new QAction(tr("&Presentation mode"), this);
    m_presentation->setCheckable(true);
    m_presentation->setShortcut(Qt::Key_F5);
    m_presentation->setToolTip(tr("Everything %1x larger, with large Run, Step, Back and Reset buttons: for a projector")
                                   .arg(kPresentationScale));
    connect(m_presentation, &QAction::triggered, this,
            [this](bool on) { setUiScale(on ? std::max(kPresentationScale, uiScale()) : 1.0); });
    m_zoomIn = new QAction(tr("&Larger text"), this);
    // Ctrl+= (no Shift needed) and Ctrl++; not also QKeySequence::ZoomIn, which is Ctrl++ here:
    // a sequence given twice is ambiguous and triggers nothing.
    m_zoomIn->setShortcuts({QKeySequence(Qt::CTRL | Qt::Key_Equal), QKeySequence(Qt::CTRL | Qt::Key_Plus)});
    connect(m_zoomIn, &QAction::triggered, this, [this] { setUiScale(nextUiScale(uiScale(), +1)); });
    m_zoomOut = new QAction(tr("S&maller text"), this);
    m_zoomOut->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Minus));
    connect(m_zoomOut, &QAction::triggered, this, [this] { setUiScale(nextUiScale(uiScale(), -1)); });

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
        auto* a = new QAction(t.text, this);
        a->setCheckable(true);
        a->setChecked(t.flag ? m_options.*(t.flag) : m_options.springs[t.family]);
        a->setObjectName(QStringLiteral("toggle_") + t.text);
        const auto flag = t.flag;
        const int family = t.family;
        connect(a, &QAction::toggled, this, [this, flag, family](bool on) {
            ViewOptions o = m_options;
            if (flag) o.*flag = on;
            else o.springs[family] = on;
            setViewOptions(o);
        });
        m_displayToggles.push_back(a);
    }

    m_sideBySide = new QAction(tr("&Side by side..."), this);
    connect(m_sideBySide, &QAction::triggered, this, &MainWindow::chooseSideBySide);
    m_single = new QAction(tr("Single &view"), this);
    connect(m_single, &QAction::triggered, this, &MainWindow::singleView);
    m_help = new QAction(tr("Elastic Lab &help"), this);
    m_help->setShortcut(QKeySequence::HelpContents);
    connect(m_help, &QAction::triggered, this, &MainWindow::showHelp);
    m_lessons = new QAction(tr("Lesson &texts (Experiments)..."), this);
    m_lessons->setToolTip(tr("Guided experiments: a scene set up in one click, what to change, what to look at, "
                             "the measured answer"));
    connect(m_lessons, &QAction::triggered, this, &MainWindow::showLessons);
    m_about = new QAction(tr("&About"), this);
    connect(m_about, &QAction::triggered, this, [this] {
        QMessageBox::about(this, tr("About Elastic Lab"),
                           tr("Elastic Lab: the dynamics of two-layer elastic bodies, for teaching."));
    });
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
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

    QMenu* sim = m_simulationMenu = menuBar()->addMenu(tr("&Simulation"));
    sim->addAction(m_runPause);
    sim->addAction(m_step);
    sim->addAction(m_reset);

    m_viewMenu = menuBar()->addMenu(tr("&View"));  // dock toggles are added in createDocks()
    for (QAction* a : m_displayToggles) m_viewMenu->addAction(a);
    m_viewMenu->addAction(m_resetView);
    // High contrast: black, white and yellow for the whole window (docs/accessibility.md).
    m_highContrast = m_viewMenu->addAction(tr("&High contrast"));
    m_highContrast->setObjectName(QStringLiteral("highContrast"));
    m_highContrast->setCheckable(true);
    m_highContrast->setToolTip(tr("White text on black, yellow highlight and focus: for low vision and projectors"));
    connect(m_highContrast, &QAction::toggled, this, &MainWindow::setHighContrast);
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(m_presentation);
    m_viewMenu->addAction(m_zoomIn);
    m_viewMenu->addAction(m_zoomOut);
    m_viewMenu->addSeparator();
    createLanguageMenu();
    m_viewMenu->addSeparator();

    QMenu* compare = menuBar()->addMenu(tr("&Compare"));
    compare->addAction(m_sideBySide);
    compare->addAction(m_single);
    compare->addSeparator();
    for (const Preset& p : stabilityPresets())
        compare->addAction(p.title, this, [this, p] { applyPreset(p); });

    QMenu* presets = menuBar()->addMenu(tr("&Presets"));
    for (const Preset& p : teachingPresets()) {
        QAction* a = presets->addAction(p.title, this, [this, p] { applyPreset(p); });
        a->setToolTip(p.description);
    }
    // Scenes of several bodies (simcore::World): bodies that meet bodies.
    QMenu* worlds = presets->addMenu(tr("Several &bodies"));
    worlds->setObjectName(QStringLiteral("worldsMenu"));
    worlds->setToolTipsVisible(true);
    for (const simcore::WorldSceneInfo& w : simcore::worldSceneTable()) {
        const QString name = toQString(w.name);
        QAction* a = worlds->addAction(name, this, [this, name] {
            setCurrentFile({}, simcore::ParameterSet{}, {});
            startWorld(*simcore::worldScene(name.toStdString()));
            status(tr("%1: several bodies. The Bodies dock shows momentum and min_gap; Parameters has a body "
                      "selector. Press Run (Space).").arg(name));
        });
        a->setToolTip(toQString(w.description));
    }
    presets->setToolTipsVisible(true);

    m_studiesMenu = menuBar()->addMenu(tr("S&tudies"));
    m_studiesMenu->addAction(tr("&Work-precision study..."), this, [this] {
        if (refuseForWorld(tr("Work-precision studies"))) return;
        auto* d = new WorkPrecisionDialog(m_controller->parameters(), this);
        d->setAttribute(Qt::WA_DeleteOnClose);
        d->show();
    });
    m_studiesMenu->addAction(tr("&Refinement study..."), this, [this] {
        if (refuseForWorld(tr("Refinement studies"))) return;
        auto* d = new RefinementDialog(m_controller->parameters(), this);
        d->setAttribute(Qt::WA_DeleteOnClose);
        d->show();
    });
    m_studiesMenu->addAction(tr("&Stability scan..."), this, [this] {
        if (refuseForWorld(tr("Stability scans"))) return;
        auto* d = new StabilityDialog(m_controller->parameters(), this);
        d->setAttribute(Qt::WA_DeleteOnClose);
        d->show();
    });
    m_studiesMenu->addAction(tr("&Long-time energy..."), this, [this] {
        if (refuseForWorld(tr("Long-time energy studies"))) return;
        auto* d = new ConservationDialog(m_controller->parameters(), this);
        d->setAttribute(Qt::WA_DeleteOnClose);
        d->show();
    });

    // Lessons: each guided experiment set up in one click, and their texts.
    m_lessonsMenu = menuBar()->addMenu(tr("&Lessons"));
    for (const Lesson& l : lessons())
        m_lessonsMenu->addAction(l.title, this, [this, id = l.id] {
            if (const Lesson* lesson = findLesson(id)) applyLesson(*lesson);
        });
    m_lessonsMenu->addSeparator();
    m_lessonsMenu->addAction(m_lessons);

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_help);
    help->addAction(m_lessons);
    help->addAction(m_about);
}

void MainWindow::createCentral() {
    auto* central = new QWidget(this);
    auto* layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);

    m_banner = new FailureBanner(central);
    connect(m_banner, &FailureBanner::setDtAndReset, this, [this](double dt) {
        m_controller->setParameter(simcore::Param::Dt, dt);
        m_controller->reset();
    });
    connect(m_banner, &FailureBanner::useImplicitAndReset, this, [this] {
        m_controller->setIntegrator(QStringLiteral("implicit-euler"));
        m_controller->reset();
    });
    connect(m_banner, &FailureBanner::resetRequested, this, [this] { m_controller->reset(); });
    layout->addWidget(m_banner);

    m_stabilityBanner = new QFrame(central);
    m_stabilityBanner->setObjectName(QStringLiteral("stabilityBanner"));
    m_stabilityBanner->setStyleSheet(
        QStringLiteral("#stabilityBanner { background: #fdf0d5; border-bottom: 2px solid #d68910; }"));
    // The text in lines across the view, the buttons in a row under it (FailureBanner's layout).
    auto* stabilityColumn = new QVBoxLayout(m_stabilityBanner);
    stabilityColumn->setContentsMargins(10, 6, 10, 6);
    stabilityColumn->setSpacing(4);
    m_stabilityText = new QLabel(m_stabilityBanner);
    m_stabilityText->setWordWrap(true);
    m_stabilityText->setTextFormat(Qt::RichText);
    m_stabilityText->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Minimum);
    stabilityColumn->addWidget(m_stabilityText);
    auto* stabilityLayout = new QHBoxLayout;
    stabilityLayout->addStretch(1);
    stabilityColumn->addLayout(stabilityLayout);
    m_useSuggestedDt = new QPushButton(m_stabilityBanner);
    m_useSuggestedDt->setObjectName(QStringLiteral("useSuggestedDt"));
    connect(m_useSuggestedDt, &QPushButton::clicked, this, [this] {
        m_controller->setParameter(simcore::Param::Dt, m_suggestedDt);
        m_stabilityBanner->hide();
        status(tr("DT set to %1 s").arg(num(m_suggestedDt)));
    });
    auto* stableImplicit = new QPushButton(tr("Use implicit-euler"), m_stabilityBanner);
    stableImplicit->setToolTip(tr("Linearised backward Euler: stable at any DT (and damps more)"));
    connect(stableImplicit, &QPushButton::clicked, this, [this] {
        m_controller->setIntegrator(QStringLiteral("implicit-euler"));
        m_stabilityBanner->hide();
    });
    auto* dismiss = new QPushButton(tr("Keep DT"), m_stabilityBanner);
    dismiss->setToolTip(tr("Run with this DT anyway (to watch the method fail, for example)"));
    connect(dismiss, &QPushButton::clicked, m_stabilityBanner, &QWidget::hide);
    stabilityLayout->addWidget(m_useSuggestedDt);
    stabilityLayout->addWidget(stableImplicit);
    stabilityLayout->addWidget(dismiss);
    m_stabilityBanner->hide();
    layout->addWidget(m_stabilityBanner);

    m_viewRow = new QHBoxLayout;
    m_viewRow->setSpacing(2);
    layout->addLayout(m_viewRow, 1);
    if (!Viewport::openGLAvailable()) {
        auto* label = new QLabel(tr("The 3D view needs OpenGL 3.3, which this display does not offer.\n"
                                    "Plots, parameters and exports still work."),
                                 central);
        label->setAlignment(Qt::AlignCenter);
        m_noGl = label;
        m_viewRow->addWidget(label);
    } else {
        rebuildViewports(1);
    }
    setCentralWidget(central);
}

void MainWindow::rebuildViewports(int count) {
    if (m_noGl) return;
    if (int(m_viewports.size()) == count) return;
    Camera camera = m_viewports.empty() ? Camera{} : m_viewports.front()->camera();
    const FramePtr frame = m_viewports.empty() ? FramePtr{} : m_viewports.front()->frame();
    for (Viewport* v : m_viewports) delete v;
    m_viewports.clear();
    for (int i = 0; i < count; ++i) {
        auto* v = new Viewport(centralWidget() ? centralWidget() : this);
        v->setObjectName(QStringLiteral("viewport%1").arg(i));
        v->setLane(i);
        v->setOptions(m_options);
        if (frame) v->showFrame(frame);
        v->setCamera(camera);
        m_viewRow->addWidget(v, 1);
        connect(v, &Viewport::grabRequested, m_controller, &SimulationController::grabAlongRay);
        connect(v, &Viewport::anchorMoved, m_controller, &SimulationController::moveAnchor);
        connect(v, &Viewport::releaseRequested, m_controller, &SimulationController::release);
        connect(v, &Viewport::selectRequested, m_controller, &SimulationController::selectAlongRay);
        connect(v, &Viewport::particleSelected, m_controller, &SimulationController::selectParticle);
        v->setHighContrast(m_highContrast->isChecked());
        connect(v, &Viewport::contextRequested, this, [this](const QPoint& at, int particle) {
            QMenu* menu = viewContextMenu(particle);
            menu->setAttribute(Qt::WA_DeleteOnClose);
            menu->popup(at);
        });
        connect(m_controller, &SimulationController::grabbed, v, &Viewport::onGrabbed);
        m_viewports.push_back(v);
    }
    // Three views need room: the docks beside the plots may have to share the plots' place
    // (now for the minimum width; once laid out, for the views' share).
    if (count > 1) {
        keepMinimumWidth();
        QTimer::singleShot(0, this, &MainWindow::keepMinimumWidth);
    }
    // One camera for all: orbiting one view orbits the others.
    for (Viewport* v : m_viewports)
        connect(v, &Viewport::cameraChanged, this, [this, v](const Camera& c) {
            for (Viewport* other : m_viewports)
                if (other != v) other->setCamera(c);
        });
}

void MainWindow::createDocks() {
    m_sceneDock = new SceneDock(this);
    m_parameterDock = new ParameterDock(this);
    m_runDock = new RunDock(this);
    m_plotDock = new PlotDock(this);
    addDockWidget(Qt::LeftDockWidgetArea, m_runDock);
    addDockWidget(Qt::LeftDockWidgetArea, m_sceneDock);
    addDockWidget(Qt::LeftDockWidgetArea, m_parameterDock);
    tabifyDockWidget(m_sceneDock, m_parameterDock);
    addDockWidget(Qt::RightDockWidgetArea, m_plotDock);
    // Energy at a glance: the bars beside the plots, the P–V diagram under the bars; closed
    // until asked for (View menu, --docks), so the default window stays as it was.
    m_energyBarsDock = new EnergyBarsDock(this);
    m_pvDock = new PvDock(this);
    addDockWidget(Qt::RightDockWidgetArea, m_energyBarsDock);
    splitDockWidget(m_plotDock, m_energyBarsDock, Qt::Horizontal);
    splitDockWidget(m_energyBarsDock, m_pvDock, Qt::Vertical);
    m_energyBarsDock->hide();
    m_pvDock->hide();
    // The stability map shares the P–V diagram's place (tabbed when both are open); closed
    // until asked for, and idle while closed.
    m_stabilityMapDock = new StabilityMapDock(this);
    tabifyDockWidget(m_pvDock, m_stabilityMapDock);
    m_stabilityMapDock->hide();
    // Scenes of several bodies: their readout, list and curves; opened when a world starts.
    m_bodiesDock = new BodiesDock(this);
    addDockWidget(Qt::RightDockWidgetArea, m_bodiesDock);
    tabifyDockWidget(m_plotDock, m_bodiesDock);
    m_bodiesDock->hide();
    connect(m_bodiesDock, &BodiesDock::worldRequested, this, [this](const simcore::WorldSpec& spec) {
        startWorld(spec, m_controller->integrators().value(0, QStringLiteral("rk4")));
    });
    connect(m_bodiesDock, &BodiesDock::message, this, &MainWindow::status);
    // The lesson in use, under the Run dock, a tab beside Scene and Parameters (raised when a
    // lesson opens it: its table needs the height; Parameters is one click away for a step that
    // types a value): closed until a lesson (or View) opens it.
    m_lessonDock = new LessonDock(this);
    tabifyDockWidget(m_parameterDock, m_lessonDock);
    m_lessonDock->hide();
    // What the teacher picks off the body (right-click in the view), under the plots.
    m_measureDock = new MeasurePlotDock(this);
    addDockWidget(Qt::RightDockWidgetArea, m_measureDock);
    splitDockWidget(m_plotDock, m_measureDock, Qt::Vertical);
    m_measureDock->hide();
    for (QDockWidget* d : {static_cast<QDockWidget*>(m_sceneDock), static_cast<QDockWidget*>(m_parameterDock),
                           static_cast<QDockWidget*>(m_runDock), static_cast<QDockWidget*>(m_plotDock),
                           static_cast<QDockWidget*>(m_energyBarsDock), static_cast<QDockWidget*>(m_pvDock),
                           static_cast<QDockWidget*>(m_stabilityMapDock), static_cast<QDockWidget*>(m_lessonDock),
                           static_cast<QDockWidget*>(m_measureDock), static_cast<QDockWidget*>(m_bodiesDock)})
        m_viewMenu->addAction(d->toggleViewAction());
    resizeDocks({m_runDock, m_plotDock}, {290, 420}, Qt::Horizontal);
}

// The widest minimum the window may have: a 1280 x 800 projector shows all of it.
constexpr int kMaxMinimumWidth = 1280;

void MainWindow::keepMinimumWidth() {
    // A projector's 1280 px: while the docks beside each other (three views, the Run dock, the
    // plots and the bars) would hold the window wider, the docks beside the plots become tabs
    // of the Plots dock, one at a time.
    // Also while the views, laid out, have less than 30 % of the window: a view is what the
    // class looks at.
    auto crowded = [this] {
        if (minimumSizeHint().width() > kMaxMinimumWidth) return true;
        return isVisible() && centralWidget() && centralWidget()->width() > 0 && centralWidget()->width() < 0.3 * width();
    };
    for (QDockWidget* d : {static_cast<QDockWidget*>(m_stabilityMapDock), static_cast<QDockWidget*>(m_pvDock),
                           static_cast<QDockWidget*>(m_energyBarsDock)}) {
        if (!crowded()) break;
        if (d->isHidden() || d->isFloating() || tabifiedDockWidgets(m_plotDock).contains(d)) continue;
        tabifyDockWidget(m_plotDock, d);
        d->raise();
        // The tabs take the plots' width, not the width the docks had side by side.
        resizeDocks({m_plotDock}, {std::max(320, width() / 4)}, Qt::Horizontal);
    }
    // A window already grown past the screen comes back within it.
    if (const QScreen* s = screen(); s && !isMaximized() && !isFullScreen() && !s->availableGeometry().contains(geometry()))
        setGeometry(fitWithin(geometry(), s->availableGeometry()));
}

QStringList MainWindow::dockNames() {
    return {QStringLiteral("energy-bars"), QStringLiteral("pv"), QStringLiteral("stability-map"), QStringLiteral("timeline"),
            QStringLiteral("lesson"), QStringLiteral("bodies")};
}

QDockWidget* MainWindow::dock(const QString& name) const {
    return name == QLatin1String("energy-bars")     ? static_cast<QDockWidget*>(m_energyBarsDock)
           : name == QLatin1String("pv")            ? static_cast<QDockWidget*>(m_pvDock)
           : name == QLatin1String("stability-map") ? static_cast<QDockWidget*>(m_stabilityMapDock)
           : name == QLatin1String("timeline")      ? static_cast<QDockWidget*>(m_timelineDock)
           : name == QLatin1String("lesson")        ? static_cast<QDockWidget*>(m_lessonDock)
           : name == QLatin1String("bodies")        ? static_cast<QDockWidget*>(m_bodiesDock)
                                                    : nullptr;
}

bool MainWindow::openDock(const QString& name) {
    if (name == QLatin1String("timeline") || name == QLatin1String("lesson")) {  // no share of the right column
        QDockWidget* own = dock(name);
        own->show();
        own->raise();
        return true;
    }
    QDockWidget* dock = this->dock(name);
    if (!dock) return false;
    dock->show();
    dock->raise();
    keepMinimumWidth();  // before the window grows for it
    // The right column: plots, then bars and P–V sharing what is left beside the view.
    // Sized once the window has laid the dock out (on the next event-loop pass).
    QTimer::singleShot(0, this, [this, dock] {
        // A projector's 1280 px: when the docks beside each other would need more than that
        // (three views, the Run dock, the plots and the bars), the new dock shares the plots'
        // place as a tab instead of widening the window.
        keepMinimumWidth();
        if (tabifiedDockWidgets(m_plotDock).contains(dock)) {
            dock->raise();
            return;
        }
        resizeDocks({m_plotDock, dock}, {380, 350}, Qt::Horizontal);
        if (!m_energyBarsDock->isHidden() && !m_pvDock->isHidden())
            resizeDocks({m_energyBarsDock, m_pvDock}, {360, 500}, Qt::Vertical);
        if (!m_energyBarsDock->isHidden() && !m_stabilityMapDock->isHidden())
            resizeDocks({m_energyBarsDock, m_stabilityMapDock}, {300, 560}, Qt::Vertical);
        QTimer::singleShot(0, this, &MainWindow::keepMinimumWidth);  // laid out: the views' share
    });
    return true;
}

void MainWindow::connectController() {
    SimulationController* c = m_controller;
    connect(c, &SimulationController::frameArrived, this, &MainWindow::onFrame);
    connect(c, &SimulationController::sceneChanged, this,
            [this](const std::shared_ptr<const SceneData>& scene) { m_plotDock->setScene(scene->kind, scene->isWorld()); });
    connect(c, &SimulationController::sceneChanged, this, [this](const std::shared_ptr<const SceneData>& scene) {
        m_energyBarsDock->setScene(*scene);
        m_pvDock->setScene(scene->kind);
    });
    connect(c, &SimulationController::historyReset, m_plotDock, &PlotDock::clear);
    connect(m_plotDock, &PlotDock::bandsShownChanged, c, &SimulationController::setErrorBandsWanted);
    connect(c, &SimulationController::historyReset, m_pvDock, &PvDock::clear);
    connect(c, &SimulationController::rowsAppended, this, [this](int first, int count) {
        m_plotDock->appendRows(m_controller->history(), first, count);
        m_pvDock->appendRows(m_controller->history(), first, count);
        m_lessonDock->appendRows(m_controller->history(), first, count);
    });
    connect(c, &SimulationController::viewRowsAppended, this, [this](int view, int first, int count) {
        m_plotDock->appendViewRows(view, m_controller->viewHistory()[std::size_t(view - 1)], first, count);
    });
    connect(c, &SimulationController::historyReset, m_lessonDock, &LessonDock::clearRun);
    connect(c, &SimulationController::historyReset, m_measureDock, &MeasurePlotDock::clearData);
    connect(m_lessonDock, &LessonDock::runUntilRequested, c, &SimulationController::runUntil);
    connect(c, &SimulationController::parameterRejected, this,
            [this](const QString&, const QString& message) { status(message); });
    connect(c, &SimulationController::sceneRejected, this, [this](const QString& message) {
        if (m_pending) {
            const QString path = m_pending->path;
            m_pending.reset();
            warn(tr("Open scene"), tr("Could not open %1: %2").arg(path, message));
            return;
        }
        status(tr("Cannot build that body: %1").arg(message));
    });
    connect(c, &SimulationController::sceneChanged, this, &MainWindow::adoptOpenedFile);
    connect(c, &SimulationController::sceneChanged, this,
            [this](const std::shared_ptr<const SceneData>& scene) {
                showStabilityAdvice(*scene);
                m_sceneDock->showBodyValues(scene->bodyValues);
            });

    connect(m_parameterDock, &ParameterDock::parameterEdited, c,
            qOverload<simcore::Param, double>(&SimulationController::setParameter));
    connect(m_parameterDock, &ParameterDock::bodyChosen, c, &SimulationController::setWorldBody);
    connect(m_parameterDock, &ParameterDock::parameterRejected, this,
            [this](const QString&, const QString& message) { status(message); });
    connect(m_sceneDock, &SceneDock::rebuildRequested, this, &MainWindow::rebuildFromSceneDock);
    connect(m_sceneDock, &SceneDock::shapeRejected, this, [this](const QString&, const QString& m) { status(m); });

    connect(m_runDock, &RunDock::integratorChosen, c, &SimulationController::setIntegrator);
    connect(m_runDock, &RunDock::dtEdited, this, [c](double dt) { c->setParameter(simcore::Param::Dt, dt); });
    connect(m_runDock, &RunDock::runRequested, c, &SimulationController::run);
    connect(m_runDock, &RunDock::pauseRequested, c, &SimulationController::pause);
    connect(m_runDock, &RunDock::stepRequested, c, &SimulationController::step);
    connect(m_runDock, &RunDock::resetRequested, c, &SimulationController::reset);
    connect(m_runDock, &RunDock::speedChosen, c, &SimulationController::setSpeed);
    connect(m_runDock, &RunDock::stepDoublingToggled, c, &SimulationController::setStepDoubling);
    connect(m_runDock, &RunDock::tolerancesEdited, c, &SimulationController::setTolerances);
    connect(m_runDock, &RunDock::message, this, &MainWindow::status);
}

QRect MainWindow::fitWithin(const QRect& wanted, const QRect& available) {
    const QSize size = wanted.size().boundedTo(available.size());
    const int x = std::clamp(wanted.x(), available.left(), available.left() + available.width() - size.width());
    const int y = std::clamp(wanted.y(), available.top(), available.top() + available.height() - size.height());
    return {QPoint(x, y), size};
}

void MainWindow::readSettings() {
    // 1500 x 900 where the screen has room, centred; never larger than the screen's available
    // area (a 1280 x 800 projector gets a window of its size, not one cut off at the edges).
    const QScreen* screen = this->screen() ? this->screen() : QGuiApplication::primaryScreen();
    const QRect available = screen ? screen->availableGeometry() : QRect(0, 0, 1500, 900);
    QRect wanted(QPoint(0, 0), QSize(1500, 900));
    wanted.moveCenter(available.center());
    setGeometry(fitWithin(wanted, available));
    if (!m_useSettings) return;
    QSettings settings;
    if (settings.contains(QStringLiteral("geometry"))) {
        restoreGeometry(settings.value("geometry").toByteArray());
        // Saved on another (larger) screen: brought back within the one the window is on now.
        const QScreen* now = QGuiApplication::screenAt(geometry().center());
        if (!now) now = screen;
        if (now && !isMaximized() && !isFullScreen()) setGeometry(fitWithin(geometry(), now->availableGeometry()));
    }
    restoreState(settings.value(QStringLiteral("windowState")).toByteArray());
    // High contrast stays chosen from one start to the next.
    if (settings.value(QStringLiteral("highContrast"), false).toBool()) m_highContrastWanted = true;
    const double scale = settings.value(QStringLiteral("uiScale"), 1.0).toDouble();
    if (scale > 1.0) setUiScale(scale);
}

void MainWindow::createLanguageMenu() {
    // View > Language: the choice is kept in the settings and applies at the next start (every
    // dock, plot and dialog is built in its language; the running experiment is not torn down
    // for it). The menu says so, in the language chosen as well as in this one.
    QMenu* menu = m_viewMenu->addMenu(tr("&Language"));
    menu->setObjectName(QStringLiteral("languageMenu"));
    auto* group = new QActionGroup(menu);
    const QString saved = m_useSettings ? QSettings().value(QStringLiteral("language")).toString() : QString();
    auto add = [&](const QString& code, const QString& text) {
        QAction* a = menu->addAction(text);
        a->setObjectName(QStringLiteral("language-") + code);
        a->setCheckable(true);
        a->setData(code);
        a->setChecked(code == (saved.isEmpty() ? QStringLiteral("system") : saved));
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, code] { chooseLanguage(code); });
    };
    add(QStringLiteral("system"), tr("System language"));
    menu->addSeparator();
    for (const Language& l : languages()) add(l.code, l.nativeName);
    menu->addSeparator();
    QAction* note = menu->addAction(tr("Applies at the next start (now: %1)")
                                        .arg(QLocale(currentLanguage()).nativeLanguageName()));
    note->setEnabled(false);
}

void MainWindow::chooseLanguage(const QString& code) {
    if (m_useSettings) QSettings().setValue(QStringLiteral("language"), code);
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
    status(tr("Language: %1 at the next start").arg(QLocale(target).nativeLanguageName()));
    auto* box = new QMessageBox(QMessageBox::Information, tr("Language"), text, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setObjectName(QStringLiteral("languageNote"));
    box->open();
}

void MainWindow::writeSettings() {
    if (!m_useSettings) return;
    QSettings settings;
    settings.setValue(QStringLiteral("geometry"), saveGeometry());
    settings.setValue(QStringLiteral("windowState"), saveState());
    settings.setValue(QStringLiteral("highContrast"), m_highContrast->isChecked());
    settings.setValue(QStringLiteral("uiScale"), uiScale());
}

void MainWindow::createClassControls() {
    // Large Run/Pause, Step, Back and Reset across the top, shown in presentation mode: the
    // buttons a teacher presses in front of the class, readable and easy to hit.
    m_classControls = new QToolBar(tr("Class controls"), this);
    m_classControls->setObjectName(QStringLiteral("classControls"));
    m_classControls->setToolButtonStyle(Qt::ToolButtonTextOnly);
    m_classControls->setMovable(false);
    for (QAction* a : {m_runPause, m_step, m_stepBack, m_reset}) m_classControls->addAction(a);
    addToolBar(Qt::TopToolBarArea, m_classControls);
    m_classControls->hide();
    m_classControls->toggleViewAction()->setVisible(false);  // it follows presentation mode
}

void MainWindow::setUiScale(double scale) {
    elui::setUiScale(scale);
    const double now = uiScale();
    const bool presenting = now > 1.0;
    m_presentation->setChecked(presenting);
    // The class controls half as large again as the rest, bold.
    QFont big = baseUiFont();
    big.setPointSizeF(big.pointSizeF() * now * 1.5);
    big.setBold(true);
    m_classControls->setFont(big);
    m_classControls->setVisible(presenting);
    status(presenting ? tr("Presentation mode: text %1x (Ctrl+= larger, Ctrl+- smaller, F5 off)").arg(now)
                      : tr("Normal text size"));
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeSave()) {
        event->ignore();
        return;
    }
    writeSettings();
    event->accept();
}

bool MainWindow::maybeSave() {
    // The title's modified mark is the measure: the parameters or the integrator differ from
    // what the current file holds (running alone does not count).
    if (m_currentFile.isEmpty() || !isWindowModified()) return true;
    QMessageBox box(QMessageBox::Warning, tr("Unsaved changes"),
                    tr("The parameters or the integrator of %1 have changed since it was saved.")
                        .arg(QFileInfo(m_currentFile).fileName()),
                    QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setInformativeText(tr("Save stores the changes and the current state in the file."));
    box.setDefaultButton(QMessageBox::Save);
    box.setObjectName(QStringLiteral("unsavedChangesBox"));
    switch (box.exec()) {
        case QMessageBox::Save: return saveSceneFile(m_currentFile).isEmpty();
        case QMessageBox::Discard: return true;
        default: return false;
    }
}

void MainWindow::setViewOptions(const ViewOptions& options) {
    const bool forcesChanged = options.forces != m_options.forces;
    m_options = options;
    for (Viewport* v : m_viewports) v->setOptions(options);
    if (forcesChanged) m_controller->setForcesWanted(options.forces);
}

void MainWindow::startScene(const simcore::ParameterSet& params, const QStringList& integrators) {
    m_controller->setScene(params, integrators.isEmpty() ? QStringList{QStringLiteral("rk4")} : integrators);
}

void MainWindow::startWorld(const simcore::WorldSpec& spec, const QString& integrator) {
    m_controller->setWorld(spec, integrator);
}

bool MainWindow::refuseForWorld(const QString& what) {
    if (!m_controller->isWorld()) return false;
    warn(what, tr("%1 are for scenes of one body. For a scene of several bodies, elastic-lab-cli run gives its CSV "
                  "(per-body columns, momentum, min_gap), and the Bodies dock its curves.").arg(what));
    return true;
}

void MainWindow::showWorldMode(bool world) {
    if (world == m_worldShown) return;
    m_worldShown = world;
    // What a world has not yet: side by side, the stability map (said in it).
    m_sideBySide->setEnabled(!world);
    m_stabilityMapDock->setWorldNotice(world);
    if (world) {
        m_bodiesDock->show();
        m_bodiesDock->raise();
    }
}

void MainWindow::applyPreset(const Preset& preset) {
    // A preset is a new experiment: it is not the scene file's, so Save asks for a name.
    setCurrentFile({}, simcore::ParameterSet{}, {});
    if (const auto world = preset.world()) {
        startWorld(*world, preset.integrators.value(0, QStringLiteral("rk4")));
    } else {
        m_controller->setStartKick(preset.kickInner, preset.kickOuter);
        startScene(preset.parameters(), preset.integrators);
    }
    status(preset.title + QStringLiteral(": ") + preset.description + tr(" Press Run (Space)."));
}

void MainWindow::applyLesson(const Lesson& lesson) {
    applyPreset(lesson.preset);
    for (const QString& dock : lesson.docks) openDock(dock);
    m_lessonDock->setLesson(findLesson(lesson.id));
    openDock(QStringLiteral("lesson"));
    status(tr("%1: set up. Lessons > Lesson texts says what to change and what to look at. Press Run (Space).")
               .arg(lesson.title));
}

void MainWindow::plotQuantity(const Tracked& quantity) {
    m_measureDock->add(quantity);
    m_measureDock->show();
    m_measureDock->raise();
    status(tr("Plotting the %1 against time (the Measured dock).").arg(quantity.name()));
}

QMenu* MainWindow::viewContextMenu(int particle) {
    auto* menu = new QMenu(this);
    menu->setObjectName(QStringLiteral("viewContextMenu"));
    using K = Tracked::Kind;
    auto plot = [this, menu](const QString& text, K kind, int index = -1, int layer = 0) {
        Tracked t;
        t.kind = kind;
        t.particle = index;
        t.layer = layer;
        menu->addAction(text, this, [this, t] { plotQuantity(t); });
    };
    const FramePtr frame = m_controller->latest();
    const bool layered = frame && !frame->lanes.empty() && frame->lanes.front().body.layered;
    if (particle >= 0) {
        menu->addSection(tr("Particle %1").arg(particle));
        plot(tr("Plot its height"), K::ParticleHeight, particle);
        plot(tr("Plot its speed"), K::ParticleSpeed, particle);
        const auto& layers = frame ? frame->scene->topology.layer : std::vector<simcore::Layer>{};
        if (layered && particle < int(layers.size())) {
            const int layer = layers[std::size_t(particle)] == simcore::Layer::Inner ? 0 : 1;
            plot(layer == 0 ? tr("Plot the inner layer's centre height") : tr("Plot the outer layer's centre height"),
                 K::LayerHeight, -1, layer);
        }
    }
    menu->addSection(tr("Body"));
    plot(tr("Plot the centre-of-mass height"), K::CentreHeight);
    plot(tr("Plot the centre-of-mass speed"), K::CentreSpeed);
    if (layered) plot(tr("Plot the layers' separation"), K::LayerSeparation);
    menu->addSeparator();
    for (QAction* a : m_displayToggles)
        if (a->objectName() == QLatin1String("toggle_Velocity vectors") ||
            a->objectName() == QLatin1String("toggle_Force vectors") ||
            a->objectName() == QLatin1String("toggle_Ruler (drag to measure)"))
            menu->addAction(a);
    return menu;
}

LessonsDialog* MainWindow::showLessons() {
    if (!m_lessonsDialog) {
        m_lessonsDialog = new LessonsDialog(this);
        connect(m_lessonsDialog, &LessonsDialog::setUpRequested, this, [this](const QString& id) {
            if (const Lesson* lesson = findLesson(id)) applyLesson(*lesson);
        });
    }
    m_lessonsDialog->show();
    m_lessonsDialog->raise();
    return m_lessonsDialog;
}

void MainWindow::rebuildFromSceneDock(const simcore::ParameterSet& shape) {
    // Keep the values set so far that the chosen scene also has; the shape comes from the dock.
    simcore::ParameterSet params = shape;
    for (const auto& [id, value] : m_controller->parameters().explicitValues())
        if (!simcore::paramSpec(id).isShape() && params.has(id) && !params.isExplicit(id)) params.set(id, value);
    if (shape.kind() != m_controller->sceneKind()) m_controller->setStartKick(0.0, 0.0);
    m_controller->setScene(params);
}

void MainWindow::onFrame(const FramePtr& frame) {
    if (!frame || frame->lanes.empty()) return;
    rebuildViewports(int(frame->lanes.size()));
    const bool multi = frame->lanes.size() > 1;
    for (Viewport* v : m_viewports) {
        const LaneFrame& lane = frame->lanes[std::size_t(std::min<int>(v->lane(), int(frame->lanes.size()) - 1))];
        v->setTitle(multi ? QStringLiteral("%1, DT %2 s").arg(lane.integrator).arg(num(frame->parameters.get(simcore::Param::Dt)))
                          : QString());
        v->showFrame(frame);
    }
    m_runDock->showFrame(frame);
    if (!m_lessonDock->isHidden()) m_lessonDock->showFrame(frame);
    m_measureDock->showFrame(frame);
    m_plotDock->setLive(frame->running);
    m_plotDock->setViews(*frame);
    m_plotDock->followReference(*frame);
    m_energyBarsDock->showFrame(*frame);
    const bool world = frame->world != nullptr;
    showWorldMode(world);
    m_bodiesDock->showFrame(*frame);
    std::vector<simcore::SceneKind> kinds;
    if (world)
        for (const simcore::WorldBodySpec& b : frame->worldSpec->bodies) kinds.push_back(b.params.kind());
    m_parameterDock->showBodies(kinds, frame->worldBody);
    QStringList integrators;
    for (const LaneFrame& lane : frame->lanes) integrators << lane.integrator;
    m_stabilityMapDock->setState(frame->parameters, integrators);
    if (!m_paramsShown || !(m_shownParams == frame->parameters)) {
        m_shownParams = frame->parameters;
        m_paramsShown = true;
        m_parameterDock->showParameters(frame->parameters);
        m_sceneDock->showParameters(frame->parameters);
        m_pvDock->setParameters(frame->parameters);
    }
    updateTitle(*frame);
    m_runPause->setText(frame->running ? tr("&Pause") : tr("&Run"));
    m_banner->showFrame(*frame);
}

void MainWindow::setHighContrast(bool on) {
    if (m_highContrast->isChecked() != on) m_highContrast->setChecked(on);  // toggled() calls back
    static const QPalette normal = QApplication::palette();
    QApplication::setPalette(on ? highContrastPalette() : normal);
    // The Fusion style draws frames and check boxes in shades of the window colour, which on black
    // vanish: white frames, and a yellow check, say where the controls are.
    qApp->setStyleSheet(on ? QStringLiteral("QPushButton, QComboBox, QLineEdit { border: 1px solid white; padding: 2px 6px; }"
                                            "QPushButton:focus, QComboBox:focus, QLineEdit:focus { border: 2px solid yellow; }"
                                            "QCheckBox::indicator { width: 13px; height: 13px; border: 2px solid white; }"
                                            "QCheckBox::indicator:checked { background: yellow; }")
                           : QString());
    // The banners' own colours: light tints in the normal theme; black with a coloured border
    // in high contrast (their white text stays readable).
    m_banner->setStyleSheet(on ? QStringLiteral("#failureBanner { background: black; border: 3px solid #ff5050; }")
                               : QStringLiteral("#failureBanner { background: #fbe3e1; border-bottom: 2px solid #c0392b; }"));
    m_stabilityBanner->setStyleSheet(
        on ? QStringLiteral("#stabilityBanner { background: black; border: 3px solid yellow; }")
           : QStringLiteral("#stabilityBanner { background: #fdf0d5; border-bottom: 2px solid #d68910; }"));
    for (Viewport* v : m_viewports) v->setHighContrast(on);
}

bool MainWindow::highContrast() const { return m_highContrast->isChecked(); }

QString MainWindow::failureText() const { return m_banner->text(); }

QString MainWindow::stabilityText() const {
    return m_stabilityBanner->isHidden() ? QString() : m_stabilityText->text();
}

void MainWindow::showStabilityAdvice(const SceneData& scene) {
    m_suggestedDt = scene.suggestedDt;
    if (scene.suggestedDt <= 0.0) {
        m_stabilityBanner->hide();
        return;
    }
    // Said before the run goes on (the worker has paused it): a finer mesh has faster modes,
    // so an explicit method needs a smaller DT (docs/numerics.md, "Resolution").
    m_stabilityText->setText(tr("<b>This body is likely unstable at the current DT.</b> %1. The run is paused.")
                                 .arg(scene.stabilityWarning.toHtmlEscaped()));
    m_useSuggestedDt->setText(tr("Use DT = %1 s").arg(num(scene.suggestedDt)));
    m_stabilityBanner->show();
}

void MainWindow::status(const QString& text) { statusBar()->showMessage(text, 12000); }

void MainWindow::warn(const QString& title, const QString& text) {
    auto* box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
    status(text);
}

namespace {
// Equal values for every key of the scene (explicit or default alike).
bool sameValues(const simcore::ParameterSet& a, const simcore::ParameterSet& b) {
    if (a.kind() != b.kind()) return false;
    for (const simcore::ParamSpec* spec : simcore::parametersFor(a.kind()))
        if (a.get(spec->id) != b.get(spec->id)) return false;
    return true;
}
// Larger than any scene file this program writes (a level-4 sphere with its state: ~0.3 MB).
constexpr qint64 kMaxSceneFileBytes = 64 << 20;
}  // namespace

void MainWindow::setCurrentFile(const QString& path, const simcore::ParameterSet& saved, const QString& integrator) {
    m_currentFile = path;
    m_savedParams = saved;
    m_savedIntegrator = integrator;
    if (m_controller->latest()) updateTitle(*m_controller->latest());
}

void MainWindow::updateTitle(const Frame& frame) {
    // Modified = the parameters or lane 0's integrator differ from what the file holds. Running
    // alone does not count: the state changes all the time, and Save always stores it.
    const QString scene = frame.scene && frame.scene->isWorld() ? frame.scene->worldName
                                                                : toQString(simcore::sceneInfo(frame.parameters.kind()).name);
    bool modified = false;
    QString title;
    if (m_currentFile.isEmpty()) {
        title = tr("Elastic Lab — %1").arg(scene);
    } else {
        title = tr("%1[*] — Elastic Lab (%2)").arg(QFileInfo(m_currentFile).fileName(), scene);
        modified = !sameValues(frame.parameters, m_savedParams) || frame.lanes.front().integrator != m_savedIntegrator;
    }
    if (title != windowTitle()) setWindowTitle(title);
    setWindowModified(modified);
}

void MainWindow::fillRecentMenu() {
    m_recentMenu->clear();
    const QStringList paths = m_recent.paths();
    for (int i = 0; i < paths.size(); ++i) {
        const QFileInfo info(paths[i]);
        QAction* a = m_recentMenu->addAction(QStringLiteral("&%1 %2").arg(i + 1).arg(info.fileName()));
        a->setToolTip(paths[i]);
        a->setData(paths[i]);
        const QString path = paths[i];
        connect(a, &QAction::triggered, this, [this, path] {
            if (maybeSave()) openRecent(path);
        });
    }
    if (paths.isEmpty()) m_recentMenu->addAction(tr("(none)"))->setEnabled(false);
    m_recentMenu->addSeparator();
    QAction* clear = m_recentMenu->addAction(tr("&Clear"), this, [this] {
        m_recent.clear();
        fillRecentMenu();
    });
    clear->setEnabled(!paths.isEmpty());
}

void MainWindow::openSceneDialog() {
    if (!maybeSave()) return;
    const QString dir = m_currentFile.isEmpty() ? QString() : QFileInfo(m_currentFile).absolutePath();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open scene"), dir, tr("Elastic Lab scenes (*.json);;All files (*)"));
    if (!path.isEmpty()) openSceneFile(path);
}

QString MainWindow::openSceneFile(const QString& path) {
    // Read here (no simulation is touched), validated by simcore's reader: the running scene
    // changes only when the whole file is good.
    QFile file(path);
    QString error;
    if (!QFileInfo(path).isFile())
        error = QFileInfo::exists(path) ? tr("Could not open %1: not a regular file").arg(path)
                                        : tr("Could not open %1: no such file").arg(path);
    else if (file.size() > kMaxSceneFileBytes)
        error = tr("Could not open %1: %2 bytes is too large for a scene file").arg(path).arg(file.size());
    else if (!file.open(QIODevice::ReadOnly))
        error = tr("Could not open %1: %2").arg(path, file.errorString());
    simlab::SceneFileResult read;
    if (error.isEmpty()) {
        read = simlab::parseSceneFile(file.readAll().toStdString());
        if (!read.file) error = tr("%1 is not a scene this program can open:\n%2").arg(path, QString::fromStdString(read.error));
    }
    if (!error.isEmpty()) {
        warn(tr("Open scene"), error);
        return error;
    }
    openScene(*read.file, {}, path);
    return {};
}

void MainWindow::openScene(const simlab::SceneFile& file, const QStringList& integrators, const QString& path,
                           const simlab::SceneFile* onDisk) {
    const simlab::SceneFile& saved = onDisk ? *onDisk : file;
    m_pending = PendingOpen{path, saved.params, QString::fromStdString(saved.integrator), file.state.has_value(),
                            file.state ? file.state->time : 0.0};
    m_controller->openScene(file, integrators);
}

void MainWindow::adoptOpenedFile() {
    // The scene of a pending open runs now: it becomes the window's file.
    if (!m_pending) return;
    const PendingOpen opened = *m_pending;
    m_pending.reset();
    setCurrentFile(opened.path, opened.params, opened.integrator);
    if (!opened.path.isEmpty()) {
        m_recent.add(opened.path);
        fillRecentMenu();
    }
    status(opened.hasState ? tr("Opened %1: the saved state at t = %2 s, paused. Press Run (Space).")
                                 .arg(opened.path).arg(opened.time)
                           : tr("Opened %1 (no saved state: starts at t = 0). Press Run (Space).").arg(opened.path));
}

QString MainWindow::openRecent(const QString& path) {
    if (!QFileInfo::exists(path)) {
        m_recent.remove(path);
        fillRecentMenu();
        const QString error = tr("%1 no longer exists; it has been removed from the recent files.").arg(path);
        warn(tr("Open recent"), error);
        return error;
    }
    return openSceneFile(path);
}

void MainWindow::saveScene() {
    if (m_currentFile.isEmpty()) saveSceneAs();
    else saveSceneFile(m_currentFile);
}

void MainWindow::saveSceneAs() {
    const QString suggested = m_currentFile.isEmpty()
                                  ? QStringLiteral("%1.json").arg(toQString(simcore::sceneInfo(m_controller->sceneKind()).name))
                                  : m_currentFile;
    QString path = QFileDialog::getSaveFileName(this, tr("Save scene as"), suggested, tr("Elastic Lab scenes (*.json)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
    saveSceneFile(path);
}

QString MainWindow::saveSceneFile(const QString& path) {
    // The state is captured on the worker thread between two steps; the run goes on.
    const SceneCapture capture = m_controller->captureScene();
    QString error = capture.text.empty() ? tr("Could not save %1: no scene is running yet").arg(path)
                                         : writeFile(path, QByteArray::fromStdString(capture.text));
    if (!error.isEmpty()) {
        warn(tr("Save scene"), error);
        return error;
    }
    setCurrentFile(path, capture.parameters, capture.integrator);
    m_recent.add(path);
    fillRecentMenu();
    // Side by side, the file holds the first view only (one integrator, one state).
    if (capture.lanes > 1)
        status(tr("Saved the first view (%1) at t = %2 s to %3; %4 not in the file.")
                   .arg(capture.integrator)
                   .arg(capture.time)
                   .arg(path, capture.lanes == 2 ? tr("the second view is") : tr("the other views are")));
    else
        status(tr("Saved %1 at t = %2 s (%3).").arg(path).arg(capture.time).arg(capture.integrator));
    return {};
}

void MainWindow::exportCsv() {
    if (m_controller->isWorld()) {  // a world's own columns, as the CLI's (world_export.h)
        const WorldExportResult result = exportWorldCsv(this, *m_controller);
        if (!result.error.isEmpty()) warn(tr("Export data"), result.error);
        else if (!result.done.isEmpty()) status(result.done);
        return;
    }
    // Three spellings of the same table; the one this locale's spreadsheet opens by a
    // double-click is offered first (the semicolon dialect where the decimal separator is a comma).
    const QString plain = tr("CSV, comma and decimal point (*.csv)");
    const QString semicolon = tr("CSV for spreadsheets, semicolon and decimal comma (*.csv)");
    const QString workbook = tr("Excel workbook with charts (*.xlsx)");
    QString selected = defaultCsvDialect(locale()) == simlab::CsvDialect::ExcelSemicolon ? semicolon : plain;
    QString path = QFileDialog::getSaveFileName(this, tr("Export data"), QStringLiteral("elastic-lab.csv"),
                                                QStringList{plain, semicolon, workbook}.join(QStringLiteral(";;")),
                                                &selected);
    if (path.isEmpty()) return;
    const bool xlsx = selected == workbook || path.endsWith(QLatin1String(".xlsx"), Qt::CaseInsensitive);
    if (xlsx && !path.endsWith(QLatin1String(".xlsx"), Qt::CaseInsensitive)) {
        if (path.endsWith(QLatin1String(".csv"), Qt::CaseInsensitive)) path.chop(4);
        path += QLatin1String(".xlsx");
    }
    const QString error = xlsx ? writeXlsx(path, m_controller->sceneKind(), m_controller->history())
                               : writeCsv(path, m_controller->sceneKind(), m_controller->history(),
                                          selected == semicolon ? simlab::CsvDialect::ExcelSemicolon
                                                                : simlab::CsvDialect::Plain);
    if (!error.isEmpty()) warn(tr("Export data"), error);
    else status(tr("Wrote %1 rows to %2").arg(m_controller->history().size()).arg(path));
}

void MainWindow::exportPlots() {
    QString filter;
    const QString path = QFileDialog::getSaveFileName(this, tr("Export plots"), QStringLiteral("elastic-lab-plots.png"),
                                                      tr("PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)"),
                                                      &filter);
    if (path.isEmpty()) return;
    const QString error = writePlots(path, m_plotDock->plots(), m_plotDock->specs());
    if (!error.isEmpty()) warn(tr("Export plots"), error);
    else status(tr("Wrote %1").arg(path));
}

void MainWindow::saveViewportScreenshot() {
    if (m_viewports.empty()) return;
    const QString path = QFileDialog::getSaveFileName(this, tr("Save viewport screenshot"),
                                                      QStringLiteral("elastic-lab-view.png"), tr("PNG image (*.png)"));
    if (path.isEmpty()) return;
    QImage image;
    // grab() keeps the text and legend drawn over the GL image.
    if (m_viewports.size() == 1) image = m_viewports.front()->grab().toImage();
    else image = centralWidget()->grab().toImage();
    const QString error = writeImage(path, image);
    if (!error.isEmpty()) warn(tr("Save screenshot"), error);
    else status(tr("Wrote %1").arg(path));
}

void MainWindow::showHelp() {
    auto* help = new HelpDialog(this);
    help->setAttribute(Qt::WA_DeleteOnClose);
    help->show();
}

void MainWindow::chooseSideBySide() {
    CompareDialog dialog(CompareDialog::proposal(m_controller->integrators()),
                         m_controller->parameters().get(simcore::Param::Dt), this);
    if (dialog.exec() != QDialog::Accepted) return;
    startScene(m_controller->parameters(), dialog.integrators());
}

void MainWindow::singleView() {
    startScene(m_controller->parameters(), {m_controller->integrators().value(0, QStringLiteral("rk4"))});
}

void MainWindow::createTimeline() {
    // Under the view (the bottom area, between the side columns); closed until asked for (View
    // menu, --docks timeline) or until a timeline key is pressed.
    m_timelineDock = new TimelineDock(this);
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    addDockWidget(Qt::BottomDockWidgetArea, m_timelineDock);
    m_timelineDock->hide();
    m_viewMenu->addAction(m_timelineDock->toggleViewAction());

    SimulationController* c = m_controller;
    auto travel = [this](const QString& text, const QKeySequence& key, auto command) {
        auto* a = new QAction(text, this);
        a->setShortcut(key);
        connect(a, &QAction::triggered, this, [this, command] {
            m_timelineDock->show();
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

    connect(m_timelineDock, &TimelineDock::scrubRequested, c, &SimulationController::scrubTo);
    connect(m_timelineDock, &TimelineDock::stepBackRequested, c, [c] { c->scrubBy(-1); });
    connect(m_timelineDock, &TimelineDock::startRequested, c, &SimulationController::scrubToStart);
    connect(m_timelineDock, &TimelineDock::endRequested, c, &SimulationController::scrubToEnd);
    connect(m_timelineDock, &TimelineDock::clearAbandonedRequested, c, &SimulationController::clearAbandoned);
    connect(c, &SimulationController::frameArrived, this, [this](const FramePtr& frame) {
        m_timelineDock->showFrame(frame);
        // The plots' cursor at the moment shown, while travelling back.
        if (frame && !frame->lanes.empty())
            m_plotDock->setCursor(frame->lanes.front().diagnostics.time, !frame->running && frame->timeline.scrubbed());
    });
    connect(c, &SimulationController::historyBranched, this, [this] {
        m_plotDock->setHistory(m_controller->history());
        for (std::size_t v = 0; v < m_controller->viewHistory().size(); ++v) {
            const auto& rows = m_controller->viewHistory()[v];
            m_plotDock->appendViewRows(int(v + 1), rows, 0, int(rows.size()));
        }
        m_pvDock->clear();
        m_pvDock->appendRows(m_controller->history(), 0, int(m_controller->history().size()));
    });
    connect(c, &SimulationController::abandonedChanged, this, [this] {
        m_plotDock->setAbandoned(m_controller->abandoned());
        m_timelineDock->setAbandoned(!m_controller->abandoned().empty());
    });
}

}  // namespace elui
