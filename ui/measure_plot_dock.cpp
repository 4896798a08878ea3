#include "ui/measure_plot_dock.h"

#include <cmath>
#include <limits>

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTimer>
#include <QVBoxLayout>

#include "qcustomplot.h"
#include "ui/plot_dock.h"

namespace elui {

namespace {
// One colour per quantity, one dash per view.
QColor curveColor(int quantity) {
    static const QColor colours[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
                                     QColor(0x94, 0x67, 0xbd), QColor(0xff, 0x7f, 0x0e), QColor(0x8c, 0x56, 0x4b)};
    return colours[quantity % 6];
}
const Qt::PenStyle kLaneDash[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine};
}  // namespace

MeasurePlotDock::MeasurePlotDock(QWidget* parent) : QDockWidget(tr("Measured"), parent) {
    setObjectName(QStringLiteral("MeasuredDock"));
    auto* host = new QWidget(this);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* bar = new QHBoxLayout;
    m_hint = new QLabel(tr("Right-click a particle or the body in the view to plot it here."), host);
    m_hint->setWordWrap(true);
    auto* remove = new QPushButton(tr("Remove all"), host);
    remove->setObjectName(QStringLiteral("measuredRemoveAll"));
    connect(remove, &QPushButton::clicked, this, &MeasurePlotDock::removeAll);
    bar->addWidget(m_hint, 1);
    bar->addWidget(remove);
    layout->addLayout(bar);
    m_plot = new QCustomPlot(host);
    m_plot->setObjectName(QStringLiteral("measuredPlot"));
    m_plot->setMinimumHeight(160);
    m_plot->xAxis->setLabel(tr("t [s]"));
    m_plot->yAxis->setLabel(tr("length [m]"));
    m_plot->yAxis2->setLabel(tr("speed [m/s]"));
    m_plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    legendUnderAxes(m_plot, font());
    layout->addWidget(m_plot, 1);
    setWidget(host);
    // Replotted at most ten times a second, whatever the frame rate.
    m_replot = new QTimer(this);
    m_replot->setInterval(100);
    connect(m_replot, &QTimer::timeout, this, [this] {
        if (!m_dirty) return;
        m_dirty = false;
        m_plot->xAxis->rescale();
        for (QCPAxis* axis : {m_plot->yAxis, m_plot->yAxis2}) {
            QCPRange range;
            bool any = false;
            for (const Curve& c : m_curves)
                if (c.graph->valueAxis() == axis) {
                    bool ok = false;
                    const QCPRange r = c.graph->getValueRange(ok);
                    if (!ok) continue;
                    range = any ? QCPRange(std::min(range.lower, r.lower), std::max(range.upper, r.upper)) : r;
                    any = true;
                }
            if (any) {
                const double pad = std::max(0.05 * range.size(), 1e-3);
                axis->setRange(range.lower - pad, range.upper + pad);
            }
        }
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    });
    m_replot->start();
}

void MeasurePlotDock::add(const Tracked& quantity) {
    for (const Tracked& q : m_quantities)
        if (q == quantity) return;
    m_quantities.push_back(quantity);
    m_lanes = 0;  // rebuilt with the next frame
}

void MeasurePlotDock::rebuildCurves(const Frame& frame) {
    m_plot->clearGraphs();
    m_curves.clear();
    m_lanes = int(frame.lanes.size());
    m_laneNames.clear();
    for (const LaneFrame& l : frame.lanes) m_laneNames << l.integrator;
    bool speeds = false;
    for (int q = 0; q < int(m_quantities.size()); ++q)
        for (int lane = 0; lane < m_lanes; ++lane) {
            const Tracked& t = m_quantities[std::size_t(q)];
            QCPGraph* g = m_plot->addGraph(m_plot->xAxis, t.isSpeed() ? m_plot->yAxis2 : m_plot->yAxis);
            speeds = speeds || t.isSpeed();
            QPen pen(curveColor(q), 2.0);
            pen.setStyle(kLaneDash[lane % 3]);
            g->setPen(pen);
            g->setName(m_lanes > 1 ? QStringLiteral("%1 (%2)").arg(t.name(), m_laneNames[lane]) : t.name());
            m_curves.push_back({q, lane, g});
        }
    m_plot->yAxis2->setVisible(speeds);
    m_hint->setVisible(m_quantities.empty());
    m_lastTime = -1.0;
    m_dirty = true;
}

void MeasurePlotDock::showFrame(const FramePtr& frame) {
    if (!frame || frame->lanes.empty() || m_quantities.empty()) return;
    QStringList names;
    for (const LaneFrame& l : frame->lanes) names << l.integrator;
    if (m_lanes != int(frame->lanes.size()) || names != m_laneNames) rebuildCurves(*frame);
    const double t = frame->lanes.front().diagnostics.time;
    if (t == m_lastTime) return;
    for (Curve& c : m_curves) {
        // Back in time (a scrub, a branch): the curve ends at the moment shown.
        if (t < m_lastTime) c.graph->data()->removeAfter(t);
        const LaneFrame& lane = frame->lanes[std::size_t(c.lane)];
        const double v = m_quantities[std::size_t(c.quantity)].value(lane);
        if (std::isfinite(v)) c.graph->addData(lane.diagnostics.time, v);
    }
    m_lastTime = t;
    m_dirty = true;
}

void MeasurePlotDock::clearData() {
    for (Curve& c : m_curves) c.graph->data()->clear();
    m_lastTime = -1.0;
    m_dirty = true;
}

void MeasurePlotDock::removeAll() {
    m_quantities.clear();
    m_plot->clearGraphs();
    m_curves.clear();
    m_lanes = 0;
    m_hint->setVisible(true);
    m_plot->yAxis2->setVisible(false);
    m_plot->replot();
}

QStringList MeasurePlotDock::curveNames() const {
    QStringList out;
    for (const Curve& c : m_curves) out << c.graph->name();
    return out;
}

int MeasurePlotDock::pointCount(int curve) const {
    return curve >= 0 && curve < int(m_curves.size()) ? m_curves[std::size_t(curve)].graph->dataCount() : -1;
}

double MeasurePlotDock::lastValue(int curve) const {
    if (curve < 0 || curve >= int(m_curves.size())) return std::numeric_limits<double>::quiet_NaN();
    const auto points = m_curves[std::size_t(curve)].graph->data();
    return points->isEmpty() ? std::numeric_limits<double>::quiet_NaN() : (points->constEnd() - 1)->value;
}

}  // namespace elui
