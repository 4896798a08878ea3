#pragma once
// MeasurePlotDock ("Measured"): what the teacher picked off the body (right-click in the view:
// a particle's height or speed, a layer centre's height, the centre of mass's height or speed,
// the layers' separation) against simulated time, one curve per quantity and view (side by
// side: the view's integrator in the legend, a dash per view). Lengths on the left axis [m],
// speeds on the right [m/s]. Sampled from every frame the window shows; a reset or a rebuild
// clears the curves, time travel back cuts them at the moment shown.

#include <vector>

#include <QDockWidget>

#include "ui/frame.h"
#include "ui/tracked.h"

class QCustomPlot;
class QCPGraph;
class QLabel;
class QTimer;

namespace elui {

class MeasurePlotDock : public QDockWidget {
    Q_OBJECT
public:
    explicit MeasurePlotDock(QWidget* parent = nullptr);

    // Adds a quantity (again: nothing); its curves start with the next frame.
    void add(const Tracked& quantity);
    const std::vector<Tracked>& quantities() const { return m_quantities; }
    // The legend names of the curves, in order; a curve's point count and last value.
    QStringList curveNames() const;
    int pointCount(int curve) const;
    double lastValue(int curve) const;
    QCustomPlot* plot() const { return m_plot; }

public slots:
    void showFrame(const elui::FramePtr& frame);
    void clearData();  // a reset or a rebuild: the curves start again
    void removeAll();

private:
    struct Curve {
        int quantity = 0;
        int lane = 0;
        QCPGraph* graph = nullptr;
    };
    void rebuildCurves(const Frame& frame);

    QCustomPlot* m_plot = nullptr;
    QLabel* m_hint = nullptr;
    QTimer* m_replot = nullptr;
    std::vector<Tracked> m_quantities;
    std::vector<Curve> m_curves;
    int m_lanes = 0;
    QStringList m_laneNames;
    double m_lastTime = -1.0;
    bool m_dirty = false;
};

}  // namespace elui
