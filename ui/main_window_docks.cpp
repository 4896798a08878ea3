#include "ui/dock_set.h"

#include <algorithm>

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QScreen>
#include <QTimer>

#include "ui/bodies_dock.h"
#include "ui/energy_bars_dock.h"
#include "ui/lesson_dock.h"
#include "ui/main_window.h"
#include "ui/measure_plot_dock.h"
#include "ui/parameter_dock.h"
#include "ui/plot_dock.h"
#include "ui/pv_dock.h"
#include "ui/run_dock.h"
#include "ui/scene_dock.h"
#include "ui/simulation_controller.h"
#include "ui/stability_map_dock.h"
#include "ui/timeline_dock.h"

namespace elui {

DockSet::DockSet(QMainWindow* window, QMenu* viewMenu) : m_window(window) {
    QMainWindow* w = window;
    m_scene = new SceneDock(w);
    m_parameters = new ParameterDock(w);
    m_run = new RunDock(w);
    m_plots = new PlotDock(w);
    w->addDockWidget(Qt::LeftDockWidgetArea, m_run);
    w->addDockWidget(Qt::LeftDockWidgetArea, m_scene);
    w->addDockWidget(Qt::LeftDockWidgetArea, m_parameters);
    w->tabifyDockWidget(m_scene, m_parameters);
    w->addDockWidget(Qt::RightDockWidgetArea, m_plots);
    // Energy at a glance: the bars beside the plots, the P–V diagram under the bars; closed
    // until asked for (View menu, --docks), so the default window stays as it was.
    m_energyBars = new EnergyBarsDock(w);
    m_pv = new PvDock(w);
    w->addDockWidget(Qt::RightDockWidgetArea, m_energyBars);
    w->splitDockWidget(m_plots, m_energyBars, Qt::Horizontal);
    w->splitDockWidget(m_energyBars, m_pv, Qt::Vertical);
    m_energyBars->hide();
    m_pv->hide();
    // The stability map shares the P–V diagram's place (tabbed when both are open); closed
    // until asked for, and idle while closed.
    m_stabilityMap = new StabilityMapDock(w);
    w->tabifyDockWidget(m_pv, m_stabilityMap);
    m_stabilityMap->hide();
    // The lesson in use, under the Run dock, a tab beside Scene and Parameters (raised when a
    // lesson opens it: its table needs the height; Parameters is one click away for a step that
    // types a value): closed until a lesson (or View) opens it.
    m_lesson = new LessonDock(w);
    w->tabifyDockWidget(m_parameters, m_lesson);
    m_lesson->hide();
    // What the teacher picks off the body (right-click in the view), under the plots.
    m_measured = new MeasurePlotDock(w);
    w->addDockWidget(Qt::RightDockWidgetArea, m_measured);
    w->splitDockWidget(m_plots, m_measured, Qt::Vertical);
    m_measured->hide();
    // Scenes of several bodies: their readout, list and curves; opened when a world starts.
    m_bodies = new BodiesDock(w);
    w->addDockWidget(Qt::RightDockWidgetArea, m_bodies);
    w->tabifyDockWidget(m_plots, m_bodies);
    m_bodies->hide();
    for (QDockWidget* d : {static_cast<QDockWidget*>(m_scene), static_cast<QDockWidget*>(m_parameters),
                           static_cast<QDockWidget*>(m_run), static_cast<QDockWidget*>(m_plots),
                           static_cast<QDockWidget*>(m_energyBars), static_cast<QDockWidget*>(m_pv),
                           static_cast<QDockWidget*>(m_stabilityMap), static_cast<QDockWidget*>(m_lesson),
                           static_cast<QDockWidget*>(m_measured), static_cast<QDockWidget*>(m_bodies)})
    {
        viewMenu->addAction(d->toggleViewAction());
        // Chosen in the View menu, a dock comes to the front, also where it is a tab.
        QObject::connect(d->toggleViewAction(), &QAction::triggered, d, [d](bool on) {
            if (on) d->raise();
        });
    }
    w->resizeDocks({m_run, m_plots}, {290, 420}, Qt::Horizontal);
}

void DockSet::createTimeline(QMenu* viewMenu) {
    // Under the view (the bottom area, between the side columns); closed until asked for (View
    // menu, --docks timeline) or until a timeline key is pressed.
    m_timeline = new TimelineDock(m_window);
    m_window->setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    m_window->setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    m_window->addDockWidget(Qt::BottomDockWidgetArea, m_timeline);
    m_timeline->hide();
    viewMenu->addAction(m_timeline->toggleViewAction());
}

void DockSet::connectController(SimulationController* c) {
    QObject* w = m_window;
    QObject::connect(c, &SimulationController::sceneChanged, w,
                     [this](const std::shared_ptr<const SceneData>& scene) { m_plots->setScene(scene->kind, scene->isWorld()); });
    QObject::connect(c, &SimulationController::sceneChanged, w, [this](const std::shared_ptr<const SceneData>& scene) {
        m_energyBars->setScene(*scene);
        m_pv->setScene(scene->kind);
    });
    QObject::connect(c, &SimulationController::historyReset, m_plots, &PlotDock::clear);
    QObject::connect(m_plots, &PlotDock::bandsShownChanged, c, &SimulationController::setErrorBandsWanted);
    QObject::connect(c, &SimulationController::historyReset, m_pv, &PvDock::clear);
    QObject::connect(c, &SimulationController::rowsAppended, w, [this, c](int first, int count) {
        m_plots->appendRows(c->history(), first, count);
        m_pv->appendRows(c->history(), first, count);
        m_lesson->appendRows(c->history(), first, count);
    });
    QObject::connect(c, &SimulationController::viewRowsAppended, w, [this, c](int view, int first, int count) {
        m_plots->appendViewRows(view, c->viewHistory()[std::size_t(view - 1)], first, count);
    });
    QObject::connect(c, &SimulationController::historyReset, m_lesson, &LessonDock::clearRun);
    QObject::connect(c, &SimulationController::historyReset, m_measured, &MeasurePlotDock::clearData);
    QObject::connect(m_lesson, &LessonDock::runUntilRequested, c, &SimulationController::runUntil);

    QObject::connect(m_parameters, &ParameterDock::parameterEdited, c,
                     qOverload<simcore::Param, double>(&SimulationController::setParameter));
    QObject::connect(m_parameters, &ParameterDock::bodyChosen, c, &SimulationController::setWorldBody);

    QObject::connect(m_run, &RunDock::integratorChosen, c, &SimulationController::setIntegrator);
    QObject::connect(m_run, &RunDock::dtEdited, c, [c](double dt) { c->setParameter(simcore::Param::Dt, dt); });
    QObject::connect(m_run, &RunDock::runRequested, c, &SimulationController::run);
    QObject::connect(m_run, &RunDock::pauseRequested, c, &SimulationController::pause);
    QObject::connect(m_run, &RunDock::stepRequested, c, &SimulationController::step);
    QObject::connect(m_run, &RunDock::resetRequested, c, &SimulationController::reset);
    QObject::connect(m_run, &RunDock::speedChosen, c, &SimulationController::setSpeed);
    QObject::connect(m_run, &RunDock::stepDoublingToggled, c, &SimulationController::setStepDoubling);
    QObject::connect(m_run, &RunDock::floatPrecisionChosen, c, &SimulationController::setFloatPrecision);
    QObject::connect(m_run, &RunDock::tolerancesEdited, c, &SimulationController::setTolerances);
}

void DockSet::connectTimeline(SimulationController* c) {
    QObject* w = m_window;
    QObject::connect(m_timeline, &TimelineDock::scrubRequested, c, &SimulationController::scrubTo);
    QObject::connect(m_timeline, &TimelineDock::stepBackRequested, c, [c] { c->scrubBy(-1); });
    QObject::connect(m_timeline, &TimelineDock::startRequested, c, &SimulationController::scrubToStart);
    QObject::connect(m_timeline, &TimelineDock::endRequested, c, &SimulationController::scrubToEnd);
    QObject::connect(m_timeline, &TimelineDock::clearAbandonedRequested, c, &SimulationController::clearAbandoned);
    QObject::connect(c, &SimulationController::frameArrived, w, [this](const FramePtr& frame) {
        m_timeline->showFrame(frame);
        // The plots' cursor at the moment shown, while travelling back.
        if (frame && !frame->lanes.empty())
            m_plots->setCursor(frame->lanes.front().diagnostics.time, !frame->running && frame->timeline.scrubbed());
    });
    QObject::connect(c, &SimulationController::historyBranched, w, [this, c] {
        m_plots->setHistory(c->history());
        for (std::size_t v = 0; v < c->viewHistory().size(); ++v) {
            const auto& rows = c->viewHistory()[v];
            m_plots->appendViewRows(int(v + 1), rows, 0, int(rows.size()));
        }
        m_pv->clear();
        m_pv->appendRows(c->history(), 0, int(c->history().size()));
    });
    QObject::connect(c, &SimulationController::abandonedChanged, w, [this, c] {
        m_plots->setAbandoned(c->abandoned());
        m_timeline->setAbandoned(!c->abandoned().empty());
    });
}

// The widest minimum the window may have: a 1280 x 800 projector shows all of it.
constexpr int kMaxMinimumWidth = 1280;

void DockSet::keepMinimumWidth() {
    QMainWindow* w = m_window;
    // A projector's 1280 px: while the docks beside each other (three views, the Run dock, the
    // plots and the bars) would hold the window wider, the docks beside the plots become tabs
    // of the Plots dock, one at a time.
    // Also while the views, laid out, have less than 30 % of the window: a view is what the
    // class looks at.
    auto crowded = [w] {
        if (w->minimumSizeHint().width() > kMaxMinimumWidth) return true;
        return w->isVisible() && w->centralWidget() && w->centralWidget()->width() > 0 &&
               w->centralWidget()->width() < 0.3 * w->width();
    };
    for (QDockWidget* d : {static_cast<QDockWidget*>(m_stabilityMap), static_cast<QDockWidget*>(m_pv),
                           static_cast<QDockWidget*>(m_energyBars)}) {
        if (!crowded()) break;
        if (d->isHidden() || d->isFloating() || w->tabifiedDockWidgets(m_plots).contains(d)) continue;
        w->tabifyDockWidget(m_plots, d);
        d->raise();
        // The tabs take the plots' width, not the width the docks had side by side.
        w->resizeDocks({m_plots}, {std::max(320, w->width() / 4)}, Qt::Horizontal);
    }
    // A window already grown past the screen comes back within it.
    if (const QScreen* s = w->screen();
        s && !w->isMaximized() && !w->isFullScreen() && !s->availableGeometry().contains(w->geometry()))
        w->setGeometry(MainWindow::fitWithin(w->geometry(), s->availableGeometry()));
}

QStringList DockSet::names() {
    return {QStringLiteral("energy-bars"), QStringLiteral("pv"), QStringLiteral("stability-map"), QStringLiteral("timeline"),
            QStringLiteral("lesson"), QStringLiteral("bodies")};
}

QDockWidget* DockSet::dock(const QString& name) const {
    return name == QLatin1String("energy-bars")     ? static_cast<QDockWidget*>(m_energyBars)
           : name == QLatin1String("pv")            ? static_cast<QDockWidget*>(m_pv)
           : name == QLatin1String("stability-map") ? static_cast<QDockWidget*>(m_stabilityMap)
           : name == QLatin1String("timeline")      ? static_cast<QDockWidget*>(m_timeline)
           : name == QLatin1String("lesson")        ? static_cast<QDockWidget*>(m_lesson)
           : name == QLatin1String("bodies")        ? static_cast<QDockWidget*>(m_bodies)
                                                    : nullptr;
}

bool DockSet::open(const QString& name) {
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
    QTimer::singleShot(0, m_window, [this, dock] {
        // A projector's 1280 px: when the docks beside each other would need more than that
        // (three views, the Run dock, the plots and the bars), the new dock shares the plots'
        // place as a tab instead of widening the window.
        keepMinimumWidth();
        if (m_window->tabifiedDockWidgets(m_plots).contains(dock)) {
            dock->raise();
            return;
        }
        m_window->resizeDocks({m_plots, dock}, {380, 350}, Qt::Horizontal);
        if (!m_energyBars->isHidden() && !m_pv->isHidden())
            m_window->resizeDocks({m_energyBars, m_pv}, {360, 500}, Qt::Vertical);
        if (!m_energyBars->isHidden() && !m_stabilityMap->isHidden())
            m_window->resizeDocks({m_energyBars, m_stabilityMap}, {300, 560}, Qt::Vertical);
        QTimer::singleShot(0, m_window, [this] { keepMinimumWidth(); });  // laid out: the views' share
    });
    return true;
}

}  // namespace elui
