#pragma once
// EnergyBarsDock: the energy book as a live bar chart, beside the energy plot.
//
//   kinetic             ██████████
//   spring: structural  ███                      parts of the total: they sum to
//   gravity         ████|                        E = kinetic + springs + gravity + gas
//   gas                 ██████                       + contact + mouse
//   ...                 |
//   removed by damping  ████                     what left the body, and
//   drift               ▏                        E + removed − W_mouse − W_edits − E_0
//
// Horizontal bars from a zero line: a negative value (gravity below y = 0, gas −c ln V with
// V > 1) is a bar to the left. The colours are the energy plot's (plot_series.h, one table).
// Only the terms the scene has (no gas in spring1d; the spring families its topology has).
// Side by side, every lane gets its bar in each group: lane 1 solid, lane 2 hatched, lane 3
// dotted, named in the title. Each painted frame writes the values into the bars in place
// (no allocation) and queues one replot; the numbers beside the bars (one lane only) and the
// axis range are refreshed at most 10 times a second.

#include <array>
#include <vector>

#include <QDockWidget>

#include "ui/frame.h"
#include "ui/plot_series.h"

class QCustomPlot;
class QCPBars;
class QCPItemText;
class QCPTextElement;
class QTimer;

namespace elui {

class EnergyBarsDock : public QDockWidget {
    Q_OBJECT
public:
    explicit EnergyBarsDock(QWidget* parent = nullptr);

    // The bars of this body (its scene kind and spring families).
    void setScene(const SceneData& scene);
    void setScene(simcore::SceneKind kind, const std::array<bool, 3>& families);
    // Every lane's diagnostics of the frame the GUI paints.
    void showFrame(const Frame& frame);

    // What is drawn (tests, docs): the bars' ids and labels in order, lanes, the value and
    // the brush colour of bar i of a lane.
    QStringList barIds() const;
    QStringList barNames() const;
    const std::vector<EnergyBar>& bars() const { return m_bars; }
    int laneCount() const { return m_lanes; }
    double value(int bar, int lane = 0) const;
    QColor color(int bar, int lane = 0) const;
    QString title() const;
    QCustomPlot* plot() const { return m_plot; }
    // Whether every number shown beside a bar lies inside the plot's axis rect (as drawn last).
    bool numbersInside() const;

public slots:
    void refreshText();  // numbers, title and axis range; then a replot

private:
    void rebuild();
    void makeRoomForNumbers();  // after the layout: the axis long enough for every number
    QCPBars* barAt(int bar, int lane) const { return m_items[std::size_t(bar * m_lanes + lane)]; }

    QCustomPlot* m_plot = nullptr;
    QCPTextElement* m_title = nullptr;
    QTimer* m_textTimer = nullptr;
    simcore::SceneKind m_kind = simcore::SceneKind::Ring2d;
    std::array<bool, 3> m_families{true, true, true};
    bool m_projection = false;
    int m_lanes = 1;
    std::vector<EnergyBar> m_bars;
    std::vector<QCPBars*> m_items;        // bar-major: [bar * lanes + lane]
    std::vector<QCPItemText*> m_labels;   // one per bar (the values, single lane only)
    std::vector<double> m_keys;           // the bars' positions on the category axis
    QStringList m_laneNames;
    double m_time = 0.0;
    double m_total = 0.0;
    double m_start = 0.0;
    bool m_hasFrame = false;
};

}  // namespace elui
