#include "ui/plot_dock.h"

#include <algorithm>
#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QTimer>
#include <QVBoxLayout>

#include "qcustomplot.h"

namespace elui {

void legendUnderAxes(QCustomPlot* plot, const QFont& base) {
    plot->legend->setVisible(true);
    plot->legend->setBrush(QColor(255, 255, 255, 190));
    QFont legendFont = base;
    legendFont.setPointSizeF(legendFont.pointSizeF() * 0.85);
    plot->legend->setFont(legendFont);
    plot->axisRect()->insetLayout()->take(plot->legend);
    plot->plotLayout()->addElement(plot->plotLayout()->rowCount(), 0, plot->legend);
    plot->plotLayout()->setRowStretchFactor(plot->plotLayout()->rowCount() - 1, 0.001);
    plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);
    // At most five entries a row: the energy legend's eight in one row would hold the Plots
    // dock at ~650 px and leave the view no room when the energy docks open beside it.
    plot->legend->setWrap(5);
    plot->legend->setBorderPen(Qt::NoPen);
    plot->legend->setMargins(QMargins(4, 0, 4, 0));
}

PlotDock::PlotDock(QWidget* parent) : QDockWidget(tr("Plots"), parent) {
    setObjectName(QStringLiteral("PlotsDock"));
    auto* host = new QWidget(this);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* bar = new QHBoxLayout;
    m_windowCombo = new QComboBox(host);
    m_windowCombo->setObjectName(QStringLiteral("plotWindow"));
    m_windowCombo->addItem(tr("Last 5 s"), 5.0);
    m_windowCombo->addItem(tr("Last 10 s"), 10.0);
    m_windowCombo->addItem(tr("Last 30 s"), 30.0);
    m_windowCombo->addItem(tr("Full history"), 0.0);
    m_windowCombo->setCurrentIndex(1);
    m_autoscale = new QCheckBox(tr("Autoscale"), host);
    m_autoscale->setChecked(true);
    m_autoscale->setToolTip(tr("Fit the axes to the data; off while you zoom (wheel) and pan (drag)"));
    m_showBands = new QCheckBox(tr("Show error band"), host);
    m_showBands->setObjectName(QStringLiteral("showErrorBand"));
    m_showBands->setToolTip(tr("A band around volume, pressure and total energy: the integrator's local error estimate "
                               "of each step carried to them (|O(y + e) - O(y)|). rk45, CVODE and step doubling "
                               "have an estimate; other methods show no band."));
    m_bandNote = new QLabel(host);
    m_bandNote->setObjectName(QStringLiteral("errorBandNote"));
    m_bandNote->setStyleSheet(QStringLiteral("QLabel { color: #806000; }"));
    bar->addWidget(new QLabel(tr("Show"), host));
    bar->addWidget(m_windowCombo);
    bar->addWidget(m_autoscale);
    bar->addWidget(m_showBands);
    bar->addWidget(m_bandNote);
    bar->addStretch(1);
    layout->addLayout(bar);
    m_plotLayout = new QVBoxLayout;
    layout->addLayout(m_plotLayout, 1);
    setWidget(host);

    m_replotTimer = new QTimer(this);
    m_replotTimer->setSingleShot(true);
    m_replotTimer->setInterval(100);  // 10 replots a second are plenty for a trace
    connect(m_replotTimer, &QTimer::timeout, this, &PlotDock::replotNow);
    connect(m_windowCombo, &QComboBox::currentIndexChanged, this,
            [this] { setWindow(m_windowCombo->currentData().toDouble()); });
    connect(m_autoscale, &QCheckBox::toggled, this, [this](bool on) {
        if (on) scheduleReplot();
    });
    connect(m_showBands, &QCheckBox::toggled, this, [this](bool on) {
        for (const auto& bands : m_bands)
            for (const Band& b : bands) {
                b.upper->setVisible(on);
                b.lower->setVisible(on);
            }
        updateBandNote();
        scheduleReplot();
        emit bandsShownChanged(on);
    });
    setScene(simcore::SceneKind::Ring2d);
}

void PlotDock::setScene(simcore::SceneKind kind) {
    if (m_created && kind == m_kind) {
        clear();
        return;
    }
    m_created = true;
    m_kind = kind;
    for (QCustomPlot* p : m_plots) delete p;
    m_plots.clear();
    m_bands.clear();
    m_specs = plotSpecs(kind);
    for (const PlotSpec& spec : m_specs) {
        auto* plot = new QCustomPlot(widget());
        plot->setObjectName(QStringLiteral("plot_") + spec.id);
        plot->setMinimumHeight(140);
        plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
        // Live traces: fast polylines and cached labels keep a replot cheap on a busy machine.
        plot->setPlottingHints(QCP::phFastPolylines | QCP::phCacheLabels);
        plot->plotLayout()->insertRow(0);
        auto* title = new QCPTextElement(plot, spec.title, QFont(font().family(), font().pointSize(), QFont::Bold));
        plot->plotLayout()->addElement(0, 0, title);
        plot->xAxis->setLabel(tr("t [s]"));
        plot->yAxis->setLabel(spec.yLabel);
        legendUnderAxes(plot, font());
        for (const SeriesSpec& s : spec.series) {
            QCPGraph* g = plot->addGraph();
            g->setName(s.name);
            g->setPen(QPen(s.color, s.name == tr("total") ? 2.0 : 1.4));
        }
        // The abandoned future: the same colours, faint and dashed, behind the series.
        for (const SeriesSpec& s : spec.series) {
            QCPGraph* g = plot->addGraph();
            g->setName(s.name + tr(" (abandoned)"));
            QColor faint = s.color;
            faint.setAlpha(90);
            g->setPen(QPen(faint, 1.2, Qt::DashLine));
            g->removeFromLegend();
            g->setLayer(QStringLiteral("background"));
        }
        // The cursor line and its values.
        auto* line = new QCPItemStraightLine(plot);
        line->setObjectName(QStringLiteral("cursorLine"));
        line->setPen(QPen(QColor(40, 40, 40, 200), 1.0));
        line->setVisible(false);
        auto* label = new QCPItemText(plot);
        label->setObjectName(QStringLiteral("cursorText"));
        // Beside the line at the top: x in time, y a fraction of the axis rect.
        label->setPositionAlignment(Qt::AlignLeft | Qt::AlignTop);
        label->position->setTypeX(QCPItemPosition::ptPlotCoords);
        label->position->setTypeY(QCPItemPosition::ptAxisRectRatio);
        label->position->setCoords(0.0, 0.02);
        label->setTextAlignment(Qt::AlignLeft);
        label->setBrush(QColor(255, 255, 255, 200));
        label->setPen(QPen(QColor(40, 40, 40, 120)));
        label->setPadding(QMargins(3, 1, 3, 1));
        QFont small = font();
        small.setPointSizeF(small.pointSizeF() * 0.85);
        label->setFont(small);
        label->setVisible(false);
        // The bands after every series (graph i stays series i), behind them, out of the legend.
        std::vector<Band> bands;
        for (std::size_t s = 0; s < spec.series.size(); ++s) {
            if (!spec.series[s].error) continue;
            QColor edge = spec.series[s].color, fill = edge;
            edge.setAlpha(90);
            fill.setAlpha(60);
            Band b{int(s), plot->addGraph(), plot->addGraph()};
            for (QCPGraph* g : {b.upper, b.lower}) {
                g->setName(spec.series[s].name + tr(" error band"));
                g->setPen(QPen(edge, 0.8));
                g->removeFromLegend();
                g->setLayer(QStringLiteral("grid"));  // drawn under the curves
                g->setVisible(m_showBands->isChecked());
            }
            b.lower->setBrush(fill);
            b.lower->setChannelFillGraph(b.upper);
            bands.push_back(b);
        }
        m_bands.push_back(std::move(bands));
        // Zooming or dragging by hand means the user wants to look: stop autoscaling.
        connect(plot, &QCustomPlot::mouseWheel, this, [this] { m_autoscale->setChecked(false); });
        connect(plot, &QCustomPlot::mousePress, this, [this] { m_autoscale->setChecked(false); });
        plot->setNotAntialiasedElements(m_live ? QCP::aePlottables : QCP::aeNone);
        m_plotLayout->addWidget(plot, 1);
        m_plots.push_back(plot);
    }
    clear();
    updateCursor();
}

QStringList PlotDock::plotIds() const {
    QStringList ids;
    for (const PlotSpec& s : m_specs) ids << s.id;
    return ids;
}

QStringList PlotDock::seriesNames(const QString& plotId) const {
    QStringList names;
    for (const PlotSpec& p : m_specs)
        if (p.id == plotId)
            for (const SeriesSpec& s : p.series) names << s.name;
    return names;
}

int PlotDock::pointCount(const QString& plotId, int series) const {
    for (std::size_t i = 0; i < m_specs.size(); ++i)
        if (m_specs[i].id == plotId && series < m_plots[i]->graphCount())
            return m_plots[i]->graph(series)->data()->size();
    return -1;
}

double PlotDock::lastValue(const QString& plotId, int series) const {
    for (std::size_t i = 0; i < m_specs.size(); ++i)
        if (m_specs[i].id == plotId && series < m_plots[i]->graphCount()) {
            auto graphData = m_plots[i]->graph(series)->data();
            return graphData->isEmpty() ? qQNaN() : (graphData->constEnd() - 1)->value;
        }
    return qQNaN();
}

const PlotDock::Band* PlotDock::band(const QString& plotId, int series) const {
    for (std::size_t i = 0; i < m_specs.size(); ++i)
        if (m_specs[i].id == plotId)
            for (const Band& b : m_bands[i])
                if (b.series == series) return &b;
    return nullptr;
}

int PlotDock::bandPointCount(const QString& plotId, int series) const {
    const Band* b = band(plotId, series);
    if (!b) return -1;
    int count = 0;
    for (auto it = b->upper->data()->constBegin(); it != b->upper->data()->constEnd(); ++it)
        if (!std::isnan(it->value)) ++count;
    return count;
}

double PlotDock::lastBandHalfWidth(const QString& plotId, int series) const {
    const Band* b = band(plotId, series);
    if (!b || b->upper->data()->isEmpty()) return qQNaN();
    return 0.5 * ((b->upper->data()->constEnd() - 1)->value - (b->lower->data()->constEnd() - 1)->value);
}

bool PlotDock::bandsShown() const { return m_showBands->isChecked(); }
void PlotDock::setBandsShown(bool on) { m_showBands->setChecked(on); }

void PlotDock::updateBandNote() {
    const bool missing = m_showBands->isChecked() && !m_lastRowHasBand;
    m_bandNote->setText(missing ? tr("(no error estimate: use rk45, CVODE or step doubling)") : QString());
}

void PlotDock::setWindow(double seconds) {
    m_window = seconds;
    const int index = m_windowCombo->findData(seconds);
    if (index >= 0 && index != m_windowCombo->currentIndex()) m_windowCombo->setCurrentIndex(index);
    scheduleReplot();
}

void PlotDock::setLive(bool live) {
    if (live == m_live) return;
    m_live = live;
    for (QCustomPlot* p : m_plots) p->setNotAntialiasedElements(live ? QCP::aePlottables : QCP::aeNone);
    scheduleReplot();
}

void PlotDock::clear() {
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        for (std::size_t g = 0; g < m_specs[i].series.size(); ++g) m_plots[i]->graph(int(g))->data()->clear();
        for (const Band& b : m_bands[i]) {
            b.upper->data()->clear();
            b.lower->data()->clear();
        }
    }
    m_lastTime = 0.0;
    m_lastRowHasBand = false;
    updateBandNote();
    scheduleReplot();
}

void PlotDock::setHistory(const std::vector<simcore::Diagnostics>& history) {
    clear();
    appendRows(history, 0, int(history.size()));
}

void PlotDock::setAbandoned(const std::vector<simcore::Diagnostics>& rows) {
    for (std::size_t i = 0; i < m_specs.size(); ++i) {
        const auto& series = m_specs[i].series;
        for (std::size_t s = 0; s < series.size(); ++s) {
            QVector<QCPGraphData> points;
            points.reserve(qsizetype(rows.size()));
            for (const simcore::Diagnostics& d : rows) points.append(QCPGraphData(d.time, series[s].value(d)));
            m_plots[i]->graph(int(series.size() + s))->data()->set(points, true);
        }
    }
    m_abandonedEnd = rows.empty() ? 0.0 : rows.back().time;
    scheduleReplot();
}

int PlotDock::abandonedPointCount(const QString& plotId, int series) const {
    const int i = plotIndex(plotId);
    if (i < 0 || series < 0 || series >= int(m_specs[std::size_t(i)].series.size())) return -1;
    return m_plots[std::size_t(i)]->graph(int(m_specs[std::size_t(i)].series.size()) + series)->data()->size();
}

int PlotDock::plotIndex(const QString& plotId) const {
    for (std::size_t i = 0; i < m_specs.size(); ++i)
        if (m_specs[i].id == plotId) return int(i);
    return -1;
}

double PlotDock::valueAt(const QString& plotId, int series, double t) const {
    const int i = plotIndex(plotId);
    if (i < 0 || series < 0 || series >= int(m_specs[std::size_t(i)].series.size())) return qQNaN();
    const auto points = m_plots[std::size_t(i)]->graph(series)->data();
    // The last point at or before t (a tiny tolerance for the time's printing round trip).
    auto it = points->findEnd(t + 1e-12 * std::max(1.0, std::abs(t)), false);
    if (it == points->constBegin()) return qQNaN();
    return (it - 1)->value;
}

QString PlotDock::cursorText(const QString& plotId) const {
    const int i = plotIndex(plotId);
    if (i < 0) return {};
    // Compact: three values a line under the time, so the label hides little of the curves.
    QString text = tr("t = %1 s").arg(m_cursorTime, 0, 'f', 4);
    const auto& series = m_specs[std::size_t(i)].series;
    for (std::size_t s = 0; s < series.size(); ++s)
        text += (s % 3 == 0 ? QStringLiteral("\n") : QStringLiteral("   ")) +
                QStringLiteral("%1 %2").arg(series[s].name).arg(valueAt(plotId, int(s), m_cursorTime), 0, 'g', 6);
    return text;
}

void PlotDock::setCursor(double time, bool visible) {
    if (time == m_cursorTime && visible == m_cursorVisible) return;
    m_cursorTime = time;
    m_cursorVisible = visible;
    updateCursor();
    scheduleReplot();
}

void PlotDock::updateCursor() {
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        QCustomPlot* plot = m_plots[i];
        for (int k = 0; k < plot->itemCount(); ++k) {
            QCPAbstractItem* item = plot->item(k);
            if (auto* line = qobject_cast<QCPItemStraightLine*>(item)) {
                line->point1->setCoords(m_cursorTime, 0.0);
                line->point2->setCoords(m_cursorTime, 1.0);
                line->setVisible(m_cursorVisible);
            } else if (auto* label = qobject_cast<QCPItemText*>(item)) {
                label->setText(cursorText(m_specs[i].id));
                label->position->setCoords(m_cursorTime, 0.02);
                label->setVisible(m_cursorVisible);
            }
        }
    }
}

void PlotDock::appendRows(const std::vector<simcore::Diagnostics>& history, int first, int count) {
    for (std::size_t i = 0; i < m_specs.size(); ++i) {
        QCustomPlot* plot = m_plots[i];
        const auto& series = m_specs[i].series;
        for (std::size_t s = 0; s < series.size(); ++s) {
            QVector<QCPGraphData> points;
            points.reserve(count);
            for (int r = first; r < first + count; ++r) {
                const simcore::Diagnostics& d = history[std::size_t(r)];
                points.append(QCPGraphData(d.time, series[s].value(d)));
            }
            plot->graph(int(s))->data()->add(points, true);
        }
        for (const Band& b : m_bands[i]) {
            // value +- e; NaN (a gap) where the row has no estimate.
            const SeriesSpec& spec = series[std::size_t(b.series)];
            QVector<QCPGraphData> upper, lower;
            upper.reserve(count);
            lower.reserve(count);
            for (int r = first; r < first + count; ++r) {
                const simcore::Diagnostics& d = history[std::size_t(r)];
                const double value = spec.value(d), e = spec.error(d);
                upper.append(QCPGraphData(d.time, value + e));
                lower.append(QCPGraphData(d.time, value - e));
            }
            b.upper->data()->add(upper, true);
            b.lower->data()->add(lower, true);
        }
    }
    if (count > 0) {
        m_lastTime = history[std::size_t(first + count - 1)].time;
        m_lastRowHasBand = history[std::size_t(first + count - 1)].errors.valid;
        updateBandNote();
    }
    if (m_cursorVisible) updateCursor();
    scheduleReplot();
}

void PlotDock::scheduleReplot() {
    m_dirty = true;
    if (!m_replotTimer->isActive()) m_replotTimer->start();
}

void PlotDock::replotNow() {
    if (!m_dirty) return;
    m_dirty = false;
    const bool autoscale = m_autoscale->isChecked();
    for (QCustomPlot* plot : m_plots) {
        if (autoscale) {
            // The newest data, the abandoned future's end, and the cursor stay in view.
            const double end = std::max(m_lastTime, m_abandonedEnd);
            double lo = m_window > 0 ? std::max(0.0, end - m_window) : 0.0;
            if (m_cursorVisible && m_window > 0 && m_cursorTime < lo) lo = std::max(0.0, m_cursorTime - 0.5 * m_window);
            const double hi = std::max(end, lo + (m_window > 0 ? m_window : 1.0));
            plot->xAxis->setRange(lo, m_window > 0 ? lo + m_window : hi);
            bool found = false;
            QCPRange y;
            for (int g = 0; g < plot->graphCount(); ++g) {
                if (!plot->graph(g)->visible()) continue;  // a hidden error band
                bool ok = false;
                const QCPRange r = plot->graph(g)->getValueRange(ok, QCP::sdBoth, QCPRange(lo, hi));
                if (!ok) continue;
                y = found ? QCPRange(std::min(y.lower, r.lower), std::max(y.upper, r.upper)) : r;
                found = true;
            }
            if (found) {
                const double pad = std::max(1e-9, 0.06 * (y.upper - y.lower));
                plot->yAxis->setRange(y.lower - pad, y.upper + pad);
            }
        }
        // The cursor's label on the side of the line with more room.
        const QCPRange x = plot->xAxis->range();
        const bool right = m_cursorTime > x.lower + 0.55 * (x.upper - x.lower);
        for (int k = 0; k < plot->itemCount(); ++k)
            if (auto* label = qobject_cast<QCPItemText*>(plot->item(k)))
                label->setPositionAlignment((right ? Qt::AlignRight : Qt::AlignLeft) | Qt::AlignTop);
        plot->replot(QCustomPlot::rpQueuedReplot);
    }
}

}  // namespace elui
