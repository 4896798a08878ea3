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

#include <vector>

#include <QDockWidget>

#include "ui/plot_series.h"

class QCustomPlot;
class QCPGraph;
class QLabel;
class QComboBox;
class QCheckBox;
class QTimer;
class QVBoxLayout;

namespace elui {

// The legend in rows of at most five under the axes (the plot's last layout row), not over
// the newest data; its font a little smaller than `base`. For the docks' QCustomPlots.
void legendUnderAxes(QCustomPlot* plot, const QFont& base);

class PlotDock : public QDockWidget {
    Q_OBJECT
public:
    explicit PlotDock(QWidget* parent = nullptr);

    void setScene(simcore::SceneKind kind);
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
    // A series' plotted value at time t: the last point at or before t (NaN: none).
    double valueAt(const QString& plotId, int series, double t) const;
    int abandonedPointCount(const QString& plotId, int series) const;
signals:
    // "Show error band" switched: the worker fills the rows' bands only while it is on.
    void bandsShownChanged(bool on);

public slots:
    void clear();  // the series (the abandoned future stays until setAbandoned)
    void appendRows(const std::vector<simcore::Diagnostics>& history, int first, int count);
    // Redraws the series from the whole history (after a branch cut it).
    void setHistory(const std::vector<simcore::Diagnostics>& history);
    void setAbandoned(const std::vector<simcore::Diagnostics>& rows);
    void setCursor(double time, bool visible);
    void replotNow();

private:
    void scheduleReplot();
    void updateCursor();
    int plotIndex(const QString& plotId) const;
    void updateBandNote();
    // The two graphs (value + e, value - e, filled between) of a series with a band.
    struct Band {
        int series = -1;
        QCPGraph* upper = nullptr;
        QCPGraph* lower = nullptr;
    };
    const Band* band(const QString& plotId, int series) const;

    simcore::SceneKind m_kind = simcore::SceneKind::Ring2d;
    std::vector<PlotSpec> m_specs;
    std::vector<QCustomPlot*> m_plots;
    QVBoxLayout* m_plotLayout = nullptr;
    QComboBox* m_windowCombo = nullptr;
    QCheckBox* m_autoscale = nullptr;
    QCheckBox* m_showBands = nullptr;
    QLabel* m_bandNote = nullptr;   // says why no band is drawn
    std::vector<std::vector<Band>> m_bands;  // per plot
    bool m_lastRowHasBand = false;
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
