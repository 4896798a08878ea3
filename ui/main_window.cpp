#include "ui/main_window.h"

#include "ui/banners.h"
#include "ui/main_menus.h"

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
#include "simlab/request.h"
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
    m_menus = std::make_unique<MainMenus>(this);
    createCentral();
    m_docks = std::make_unique<DockSet>(this, m_menus->viewMenu());
    connect(bodiesDock(), &BodiesDock::worldRequested, this, [this](const simcore::WorldSpec& spec) {
        startWorld(spec, m_controller->integrators());  // every view side by side
    });
    connect(bodiesDock(), &BodiesDock::message, this, &MainWindow::status);
    connectController();
    // Time travel: the timeline dock under the view, its keys in the Simulation menu, its wiring.
    m_docks->createTimeline(m_menus->viewMenu());
    m_menus->addTimelineActions(timelineDock());
    m_docks->connectTimeline(m_controller);
    m_menus->addClassControls();
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

void MainWindow::createCentral() {
    auto* central = new QWidget(this);
    auto* layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);

    m_banners = std::make_unique<Banners>(central, layout, m_controller, [this](const QString& text) { status(text); });

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
        v->setHighContrast(highContrast());
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
        m_docks->keepMinimumWidth();
        QTimer::singleShot(0, this, [this] { m_docks->keepMinimumWidth(); });
    }
    // One camera for all: orbiting one view orbits the others.
    for (Viewport* v : m_viewports)
        connect(v, &Viewport::cameraChanged, this, [this, v](const Camera& c) {
            for (Viewport* other : m_viewports)
                if (other != v) other->setCamera(c);
        });
}

QStringList MainWindow::dockNames() { return DockSet::names(); }

QDockWidget* MainWindow::dock(const QString& name) const { return m_docks->dock(name); }

bool MainWindow::openDock(const QString& name) { return m_docks->open(name); }

void MainWindow::connectController() {
    SimulationController* c = m_controller;
    connect(c, &SimulationController::frameArrived, this, &MainWindow::onFrame);
    m_docks->connectController(c);
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
                m_banners->showStabilityAdvice(*scene);
                sceneDock()->showBodyValues(scene->bodyValues);
            });
    connect(parameterDock(), &ParameterDock::parameterRejected, this,
            [this](const QString&, const QString& message) { status(message); });
    connect(sceneDock(), &SceneDock::rebuildRequested, this, &MainWindow::rebuildFromSceneDock);
    connect(sceneDock(), &SceneDock::shapeRejected, this, [this](const QString&, const QString& m) { status(m); });
    connect(runDock(), &RunDock::message, this, &MainWindow::status);
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

void MainWindow::writeSettings() {
    if (!m_useSettings) return;
    QSettings settings;
    settings.setValue(QStringLiteral("geometry"), saveGeometry());
    settings.setValue(QStringLiteral("windowState"), saveState());
    settings.setValue(QStringLiteral("highContrast"), highContrast());
    settings.setValue(QStringLiteral("uiScale"), uiScale());
}

void MainWindow::setUiScale(double scale) {
    elui::setUiScale(scale);
    const double now = uiScale();
    const bool presenting = now > 1.0;
    m_menus->presentation()->setChecked(presenting);
    // The class controls half as large again as the rest, bold.
    QFont big = baseUiFont();
    big.setPointSizeF(big.pointSizeF() * now * 1.5);
    big.setBold(true);
    classControls()->setFont(big);
    classControls()->setVisible(presenting);
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

void MainWindow::startWorld(const simcore::WorldSpec& spec, const QStringList& integrators) {
    m_controller->setWorld(spec, integrators);
}

std::optional<simcore::WorldSpec> MainWindow::runningWorld() const {
    const FramePtr& frame = m_controller->latest();
    if (!m_controller->isWorld() || !frame || !frame->worldSpec) return std::nullopt;
    return *frame->worldSpec;
}

void MainWindow::showWorldMode(bool world) {
    if (world == m_worldShown) return;
    m_worldShown = world;
    if (world) {
        bodiesDock()->show();
        bodiesDock()->raise();
    }
}

void MainWindow::applyPreset(const Preset& preset) {
    // A preset is a new experiment: it is not the scene file's, so Save asks for a name.
    setCurrentFile({}, simcore::ParameterSet{}, {});
    if (const auto world = preset.world()) {
        startWorld(*world, preset.integrators);
    } else {
        m_controller->setStartKick(preset.kickInner, preset.kickOuter);
        startScene(preset.parameters(), preset.integrators);
    }
    status(preset.title + QStringLiteral(": ") + preset.description + tr(" Press Run (Space)."));
}

void MainWindow::applyLesson(const Lesson& lesson) {
    applyPreset(lesson.preset);
    for (const QString& dock : lesson.docks) openDock(dock);
    lessonDock()->setLesson(findLesson(lesson.id));
    openDock(QStringLiteral("lesson"));
    status(tr("%1: set up. Lessons > Lesson texts says what to change and what to look at. Press Run (Space).")
               .arg(lesson.title));
}

void MainWindow::plotQuantity(const Tracked& quantity) {
    measureDock()->add(quantity);
    measureDock()->show();
    measureDock()->raise();
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
    for (QAction* a : m_menus->displayToggles())
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
    runDock()->showFrame(frame);
    if (!lessonDock()->isHidden()) lessonDock()->showFrame(frame);
    measureDock()->showFrame(frame);
    plotDock()->setLive(frame->running);
    plotDock()->setViews(*frame);
    plotDock()->followReference(*frame);
    energyBarsDock()->showFrame(*frame);
    const bool world = frame->world != nullptr;
    showWorldMode(world);
    bodiesDock()->showFrame(*frame);
    std::vector<simcore::SceneKind> kinds;
    if (world)
        for (const simcore::WorldBodySpec& b : frame->worldSpec->bodies) kinds.push_back(b.params.kind());
    parameterDock()->showBodies(kinds, frame->worldBody);
    QStringList integrators;
    for (const LaneFrame& lane : frame->lanes) integrators << lane.integrator;
    if (world && frame->worldSpec) stabilityMapDock()->setWorld(*frame->worldSpec, integrators);  // the whole world's map
    else stabilityMapDock()->setState(frame->parameters, integrators);
    if (!m_paramsShown || !(m_shownParams == frame->parameters)) {
        m_shownParams = frame->parameters;
        m_paramsShown = true;
        parameterDock()->showParameters(frame->parameters);
        sceneDock()->showParameters(frame->parameters);
        pvDock()->setParameters(frame->parameters);
    }
    updateTitle(*frame);
    m_menus->setRunning(frame->running);
    m_banners->showFrame(*frame);
}

void MainWindow::setHighContrast(bool on) {
    if (m_menus->highContrast()->isChecked() != on) m_menus->highContrast()->setChecked(on);  // toggled() calls back
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
    m_banners->setHighContrast(on);
    for (Viewport* v : m_viewports) v->setHighContrast(on);
}

bool MainWindow::highContrast() const { return m_menus->highContrast()->isChecked(); }

QString MainWindow::failureText() const { return failureBanner()->text(); }

QString MainWindow::stabilityText() const { return m_banners->stabilityText(); }

FailureBanner* MainWindow::failureBanner() const { return m_banners->failure(); }

QPushButton* MainWindow::useSuggestedDtButton() const { return m_banners->useSuggestedDt(); }

QMenu* MainWindow::lessonsMenu() const { return m_menus->lessonsMenu(); }

QMenu* MainWindow::recentMenu() const { return m_menus->recentMenu(); }

QToolBar* MainWindow::classControls() const { return m_menus->classControls(); }

QAction* MainWindow::presentationAction() const { return m_menus->presentation(); }

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
        m_menus->fillRecentMenu();
    }
    status(opened.hasState ? tr("Opened %1: the saved state at t = %2 s, paused. Press Run (Space).")
                                 .arg(opened.path).arg(opened.time)
                           : tr("Opened %1 (no saved state: starts at t = 0). Press Run (Space).").arg(opened.path));
}

QString MainWindow::openRecent(const QString& path) {
    if (!QFileInfo::exists(path)) {
        m_recent.remove(path);
        m_menus->fillRecentMenu();
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
    m_menus->fillRecentMenu();
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
    const QString error = writePlots(path, plotDock()->plots(), plotDock()->specs());
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
    sideBySide(dialog.integrators());
}

QString MainWindow::sideBySide(const QStringList& integrators) {
    std::vector<std::string> lanes;
    for (const QString& name : integrators) lanes.push_back(name.toStdString());
    // A world: the spec running now (with its edits), every view from its start.
    const FramePtr& frame = m_controller->latest();
    const std::shared_ptr<const simcore::WorldSpec> world =
        m_controller->isWorld() && frame ? frame->worldSpec : std::shared_ptr<const simcore::WorldSpec>();
    try {  // the front door's checks, as for elastic-lab --compare
        if (world) simlab::checkLanes(*world, lanes);
        else simlab::checkLanes(m_controller->parameters(), lanes);
    } catch (const simlab::RequestError& e) {
        const QString refusal = QString::fromStdString(e.what());
        warn(tr("Side by side"), refusal);
        return refusal;
    }
    if (world) startWorld(*world, integrators);
    else startScene(m_controller->parameters(), integrators);
    return {};
}

void MainWindow::singleView() {
    const QStringList one{m_controller->integrators().value(0, QStringLiteral("rk4"))};
    const FramePtr& frame = m_controller->latest();
    if (m_controller->isWorld() && frame && frame->worldSpec) startWorld(*frame->worldSpec, one);
    else startScene(m_controller->parameters(), one);
}

}  // namespace elui
