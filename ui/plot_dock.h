#pragma once
// PlotDock: live QCustomPlot graphs of lane 0's time series (volume, pressure, energies).
//
// Rows arrive as they are recorded; the plots are marked dirty and replotted at most 10
// times a second (queued replot), whatever the step rate. Rolling window or full history;
// autoscale, or zoom and pan by mouse (autoscale switches off when the user zooms).
//
// Time travel: a cursor line at the moment shown (when paused) with the plotted values there,
// read from the plot's own data; and the abandoned future of the last branch as faint lines
// (graphs after the series, not in the legend).
//
// Error bands ("Show error band"): around the volumes, the pressures and the total energy,
// value +- the half-width the row's error estimate implies (simcore::ObservableErrors), a
// translucent fill in the series' colour between two graphs kept out of the legend. Rows of
// a step without an estimate (rk4 without step doubling, ...) have no band, and the dock says so.

#include <limits>
#include <vector>

#include <QDockWidget>
#include <QHash>

#include "ui/frame.h"
#include "ui/plot_series.h"

class QCustomPlot;
class QCPGraph;
class QCPAbstractPlottable;
class QLabel;
class QComboBox;
class QCheckBox;
class QTimer;
class QVBoxLayout;

namespace elui {
class ReferenceRun;
}

namespace elui {

// Side by side (views = lanes): every plot shows every view. View 1 draws the series as
// before (solid); views 2 and 3 draw the same series in the same colours, dashed and dotted
// (the energy plot then shows each view's total only: eight terms three times over would hide
// each other; the energy bars compare every term); the
// legend names each view with its line style. A fourth plot, "Energy drift per view", shows
// |E_total + E_removed - E_0| of each view on a log axis (shown side by side only). A view
// that fails stops alone: its curves end with a red cross and the legend says when; the other
// views run on. Autoscale leaves failed views out of the value range while any view is still
// running, so a blown-up view (euler's 9e5 J) does not flatten the others (its curve leaves
// the top of the plot; the log drift plot shows it whole).
//
// The legend in rows of at most five under the axes (the plot's last layout row), not over
// the newest data; its font a little smaller than `base`. For the docks' QCustomPlots.
void legendUnderAxes(QCustomPlot* plot, const QFont& base);

class PlotDock : public QDockWidget {
    Q_OBJECT
public:
    explicit PlotDock(QWidget* parent = nullptr);

    // world: a scene of several bodies (the energy of the whole world; the volume and pressure
    // of each body are in the Bodies dock).
    void setScene(simcore::SceneKind kind, bool world = false);
    simcore::SceneKind kind() const { return m_kind; }
    // Plot ids shown for the current scene, in order ("volume", "pressure", "energy").
    QStringList plotIds() const;
    QStringList seriesNames(const QString& plotId) const;
    int pointCount(const QString& plotId, int series) const;
    double lastValue(const QString& plotId, int series) const;
    // The error band of a series: its points with a band, and the last one's half-width
    // (NaN: none). -1 / NaN for a series without a band.
    int bandPointCount(const QString& plotId, int series) const;
    double lastBandHalfWidth(const QString& plotId, int series) const;
    bool bandsShown() const;
    // What the dock says about the band: what it is, or why none is seen (no estimate, or
    // thinner than a line at this zoom). Empty while the band is off.
    QString bandNote() const;
    // Whether every band point in view is narrower than half a pixel (the band "invisible").
    bool bandsThinnerThanALine() const;
    void setBandsShown(bool on);
    std::vector<QCustomPlot*> plots() const { return m_plots; }
    const std::vector<PlotSpec>& specs() const { return m_specs; }

    // Seconds of history shown; 0 = all of it.
    void setWindow(double seconds);
    // While live, traces are drawn without antialiasing (cheaper); paused, smooth.
    void setLive(bool live);
    double window() const { return m_window; }

    // The cursor: its time, and the text beside it (t and every series' value there).
    bool cursorVisible() const { return m_cursorVisible; }
    double cursorTime() const { return m_cursorTime; }
    QString cursorText(const QString& plotId) const;
    // Side by side: the views (names, failures) from the frame; cheap when nothing changed.
    void setViews(const Frame& frame);
    int viewCount() const { return int(m_views.size()); }
    // A view's curve of series `series` in plot `plotId` (view 0: the series' own graph):
    // its points, and -1 when the view has no such curve.
    int viewPointCount(const QString& plotId, int view, int series) const;
    double viewLastValue(const QString& plotId, int view, int series) const;
    double viewLastTime(const QString& plotId, int view, int series) const;  // [s], NaN: none
    QCustomPlot* driftPlot() const { return m_driftPlot; }
    int driftPointCount(int view) const;
    double lastDrift(int view) const;        // [J], NaN: none
    int failureMarkCount(const QString& plotId) const;  // "drift" for the drift plot
    QStringList legendNames(const QString& plotId) const;
    // A series' plotted value at time t: the last point at or before t (NaN: none).
    double valueAt(const QString& plotId, int series, double t) const;
    int abandonedPointCount(const QString& plotId, int series) const;

    // The reference curve ("Compare with a reference", plot_dock_reference.cpp): a converged
    // rk45 solution from the run's start (reference_run.h) drawn dashed beside the series that
    // have an error band, and the run's distance to it - the error of the run so far - said in
    // words beside the band's. Fed by every frame while it is on.
    void followReference(const Frame& frame);
    bool referenceShown() const;
    void setReferenceShown(bool on);
    QString referenceNote() const;  // empty while off
    int referencePointCount(const QString& plotId, int series) const;  // -1: no such curve
    double referenceValueAt(const QString& plotId, int series, double t) const;  // NaN: none at t
    // The last time the run and the reference are compared at, and the run's total energy
    // minus the reference's there [s], [J] (NaN: not yet).
    double referenceTime() const { return m_referenceTime; }
    double referenceEnergyError() const { return m_referenceEnergyError; }
    ReferenceRun* referenceRun() const { return m_reference; }
signals:
    // "Show error band" switched: the worker fills the rows' bands only while it is on.
    void bandsShownChanged(bool on);

public slots:
    void clear();  // the series (the abandoned future stays until setAbandoned)
    void appendRows(const std::vector<simcore::Diagnostics>& history, int first, int count);
    // View `view` (>= 1) side by side: its rows [first, first + count).
    void appendViewRows(int view, const std::vector<simcore::Diagnostics>& rows, int first, int count);
    // Redraws the series from the whole history (after a branch cut it).
    void setHistory(const std::vector<simcore::Diagnostics>& history);
    void setAbandoned(const std::vector<simcore::Diagnostics>& rows);
    void setCursor(double time, bool visible);
    void replotNow();

protected:
    void changeEvent(QEvent* event) override;

private:
    int plotMinimumHeight() const;
    void scheduleReplot();
    void updateCursor();
    int plotIndex(const QString& plotId) const;
    void updateBandNote();
    void createDriftPlot(QWidget* host);
    QCustomPlot* createPlot(const PlotSpec& spec);
    void addBandsAndMarks(QCustomPlot* plot, const PlotSpec& spec);
    void createReferenceControls(QWidget* host, QVBoxLayout* layout);
    void rebuildReferenceGraphs();        // after setScene: graphs for the new plots, refilled
    void appendReference(int first, int count);
    void updateReferenceNote();
    // The two graphs (value + e, value - e, filled between) of a series with a band.
    struct Band {
        int series = -1;
        QCPGraph* upper = nullptr;
        QCPGraph* lower = nullptr;
    };
    const Band* band(const QString& plotId, int series) const;
    // Side by side.
    struct ViewInfo {
        QString integrator;
        std::optional<double> failedAt;   // [s]
    };
    struct ViewGraph {
        int view = 0;
        int series = 0;
        QCPGraph* graph = nullptr;
    };
    void ensureViews(int count);          // graphs for views [size, count)
    void dropViews(int count);            // views >= count go
    void addViewGraphs(int view);
    void updateViewLegend();
    void updateFailureMarks();
    bool compared(std::size_t plot, std::size_t series) const;
    QCPGraph* viewGraph(int plot, int view, int series) const;
    std::vector<ViewInfo> m_views;
    std::vector<std::vector<ViewGraph>> m_viewGraphs;   // per plot: views >= 1
    std::vector<std::vector<QCPGraph*>> m_viewLegend;   // per plot: a legend line per view
    std::vector<QCPGraph*> m_failMarks;                 // per plot
    QHash<const QCPAbstractPlottable*, int> m_viewOf;   // graph -> view (-1: marks)
    QCustomPlot* m_driftPlot = nullptr;
    std::vector<QCPGraph*> m_driftGraphs;               // per view
    QCPGraph* m_driftMarks = nullptr;

    simcore::SceneKind m_kind = simcore::SceneKind::Ring2d;
    bool m_world = false;
    std::vector<PlotSpec> m_specs;
    std::vector<QCustomPlot*> m_plots;
    QVBoxLayout* m_plotLayout = nullptr;
    QComboBox* m_windowCombo = nullptr;
    QCheckBox* m_autoscale = nullptr;
    QCheckBox* m_showBands = nullptr;
    QLabel* m_bandNote = nullptr;   // says why no band is drawn
    std::vector<std::vector<Band>> m_bands;  // per plot
    bool m_lastRowHasBand = false;
    QCheckBox* m_showReference = nullptr;
    QLabel* m_referenceNote = nullptr;
    ReferenceRun* m_reference = nullptr;
    struct ReferenceGraph {
        int series = -1;
        QCPGraph* graph = nullptr;
    };
    std::vector<std::vector<ReferenceGraph>> m_referenceGraphs;  // per plot
    double m_runTime = 0.0;                // lane 0's time in the last frame followed [s]
    double m_physicsChangedAt = 0.0;       // Frame::physicsChangedAt of that frame [s]
    double m_referenceTime = std::numeric_limits<double>::quiet_NaN();
    double m_referenceEnergyError = std::numeric_limits<double>::quiet_NaN();
    bool m_bandsThin = false;  // as of the last replot (bandsThinnerThanALine)
    QTimer* m_replotTimer = nullptr;
    double m_window = 10.0;
    double m_lastTime = 0.0;
    double m_abandonedEnd = 0.0;          // time of the abandoned future's last row
    double m_cursorTime = 0.0;
    bool m_cursorVisible = false;
    bool m_dirty = false;
    bool m_live = false;
    bool m_created = false;
};

}  // namespace elui
