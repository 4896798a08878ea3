#include "ui/plot_dock.h"

#include <algorithm>
#include <cmath>

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QScrollArea>
#include <QTimer>
#include <QVBoxLayout>

#include "qcustomplot.h"
#include "ui/language.h"
#include "ui/plot_ticks.h"

namespace elui {

namespace {

// A view's line style: 1 solid, 2 dashed, 3 dotted.
Qt::PenStyle viewStyle(int view) {
    static const Qt::PenStyle styles[] = {Qt::SolidLine, Qt::DashLine, Qt::DotLine};
    return styles[view % 3];
}
// A view's colour in the drift plot (one curve per view).
QColor viewColor(int view) {
    static const QColor colors[] = {QColor(30, 30, 30), QColor(30, 90, 200), QColor(200, 60, 30)};
    return colors[view % 3];
}

}  // namespace

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
    // At most five entries a row, fewer when the plot is narrow: the energy legend's eight in
    // one row would hold the Plots dock at ~650 px, five at ~480 px, and leave the view no room
    // on a 1280 px projector. The plot's own minimum width is set, so the legend's wish does
    // not widen the dock; before each replot the wrap is the most entries that fit.
    plot->legend->setWrap(5);
    plot->setMinimumWidth(220);
    QObject::connect(plot, &QCustomPlot::beforeReplot, plot->legend, [plot] {
        QCPLegend* legend = plot->legend;
        const int room = plot->width() - 8;
        const int current = legend->wrap();
        int wrap = 5;
        for (; wrap > 2; --wrap) {  // at least two a row: eight entries in four rows
            legend->setWrap(wrap);
            legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
            if (legend->minimumOuterSizeHint().width() <= room) break;
        }
        if (wrap != current) {
            legend->setWrap(wrap);
            legend->setFillOrder(QCPLayoutGrid::foColumnsFirst, true);
        }
    });
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
    m_showBands = new QCheckBox(tr("Show per-step error band"), host);
    m_showBands->setObjectName(QStringLiteral("showErrorBand"));
    m_showBands->setToolTip(tr("A band around volume, pressure and total energy: the integrator's local error estimate "
                               "of each step carried to them (|O(y + e) - O(y)|): the error one step adds, not the "
                               "error of the run so far, which can be far larger. rk45, CVODE and step doubling "
                               "have an estimate; other methods show no band."));
    // What the band is, or why none is seen: its own line, wrapped (a narrow dock stays narrow).
    m_bandNote = new QLabel(host);
    m_bandNote->setObjectName(QStringLiteral("errorBandNote"));
    m_bandNote->setStyleSheet(QStringLiteral("QLabel { color: #806000; }"));
    m_windowCombo->setAccessibleName(tr("Time window of the plots"));
    m_windowCombo->setToolTip(tr("How much of the run the plots show: the last seconds, or all of it"));
    m_bandNote->setWordWrap(true);
    m_bandNote->hide();
    bar->addWidget(new QLabel(tr("Show"), host));
    bar->addWidget(m_windowCombo);
    bar->addWidget(m_autoscale);
    bar->addStretch(1);
    layout->addLayout(bar);
    // The band's switch on a line of its own: one long row would hold the dock (and with it
    // the window) wider than a projector's 1280 px once the energy docks open beside it.
    layout->addWidget(m_showBands);
    layout->addWidget(m_bandNote);
    createReferenceControls(host, layout);
    // The plots scroll when the screen is too short for them (a projector in presentation
    // mode): each keeps the height its axes and legend need instead of being squashed.
    auto* scroll = new QScrollArea(host);
    scroll->setObjectName(QStringLiteral("plotsScroll"));
    scroll->setAccessibleName(tr("Plots"));
    scroll->setAccessibleDescription(tr("Volume, pressure and energy against simulated time, one plot under the other"));
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto* plotHost = new QWidget(scroll);
    m_plotLayout = new QVBoxLayout(plotHost);
    m_plotLayout->setContentsMargins(0, 0, 0, 0);
    scroll->setWidget(plotHost);
    layout->addWidget(scroll, 1);
    createDriftPlot(host);
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

// Side by side: every view's energy drift on a log axis, under the plots (hidden with one view).
void PlotDock::createDriftPlot(QWidget* host) {
    m_driftPlot = new QCustomPlot(host);
    m_driftPlot->setObjectName(QStringLiteral("plot_drift"));
    m_driftPlot->setMinimumHeight(plotMinimumHeight());
    m_driftPlot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    m_driftPlot->setPlottingHints(QCP::phFastPolylines | QCP::phCacheLabels);
    m_driftPlot->plotLayout()->insertRow(0);
    m_driftPlot->plotLayout()->addElement(
        0, 0, new QCPTextElement(m_driftPlot, tr("Energy drift per view"), QFont(font().family(), font().pointSize(), QFont::Bold)));
    m_driftPlot->xAxis->setLabel(tr("t [s]"));
    m_driftPlot->yAxis->setLabel(tr("|drift| [J]"));
    m_driftPlot->yAxis->setScaleType(QCPAxis::stLogarithmic);
    m_driftPlot->yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    m_driftPlot->yAxis->setNumberFormat(QStringLiteral("eb"));
    m_driftPlot->yAxis->setNumberPrecision(0);
    keepTickLabelsApart(m_driftPlot->xAxis);
    keepTickLabelsApart(m_driftPlot->yAxis);
    legendUnderAxes(m_driftPlot, font());
    m_driftMarks = m_driftPlot->addGraph();
    m_driftMarks->setLineStyle(QCPGraph::lsNone);
    m_driftMarks->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCross, QPen(QColor(210, 30, 30), 2.2), Qt::NoBrush, 11));
    m_driftMarks->setName(tr("✕ a view failed"));
    m_driftMarks->removeFromLegend();
    m_viewOf.insert(m_driftMarks, -1);
    connect(m_driftPlot, &QCustomPlot::mouseWheel, this, [this] { m_autoscale->setChecked(false); });
    connect(m_driftPlot, &QCustomPlot::mousePress, this, [this] { m_autoscale->setChecked(false); });
    m_driftPlot->hide();
    m_plotLayout->addWidget(m_driftPlot, 1);
    m_views.push_back({});
    m_driftGraphs.push_back(m_driftPlot->addGraph());
    m_driftGraphs[0]->setPen(QPen(viewColor(0), 1.6, viewStyle(0)));
}

void PlotDock::setScene(simcore::SceneKind kind, bool world) {
    if (m_created && kind == m_kind && world == m_world) {
        clear();
        return;
    }
    m_created = true;
    m_kind = kind;
    m_world = world;
    for (QCustomPlot* p : m_plots) delete p;
    m_plots.clear();
    m_bands.clear();
    m_viewGraphs.clear();
    m_viewLegend.clear();
    m_failMarks.clear();
    // The plots' graphs went with them; the drift plot's stay.
    m_viewOf.clear();
    m_viewOf.insert(m_driftMarks, -1);
    for (std::size_t v = 0; v < m_driftGraphs.size(); ++v) m_viewOf.insert(m_driftGraphs[v], int(v));
    m_specs = plotSpecs(kind, world);
    for (const PlotSpec& spec : m_specs) {
        QCustomPlot* plot = createPlot(spec);
        addBandsAndMarks(plot, spec);
    }
    // The drift plot stays last, with the same share of the height as each plot.
    m_plotLayout->removeWidget(m_driftPlot);
    m_plotLayout->addWidget(m_driftPlot, 1);
    // The views' graphs again for the new plots (the views stay until a frame says otherwise).
    for (int v = 1; v < int(m_views.size()); ++v) addViewGraphs(v);
    updateViewLegend();
    rebuildReferenceGraphs();
    clear();
    updateCursor();
}

// One plot of the scene: title, axes, the series, the abandoned future's faint copies (graph
// i is series i, then the abandoned ones) and the cursor's line and label.
QCustomPlot* PlotDock::createPlot(const PlotSpec& spec) {
    auto* plot = new QCustomPlot(m_plotLayout->parentWidget());
    plot->setObjectName(QStringLiteral("plot_") + spec.id);
    plot->setAccessibleName(spec.title);
    plot->setAccessibleDescription(tr("%1 against simulated time; the numbers are in the Run dock's readout and in "
                                      "File > Export Data").arg(spec.title));
    plot->setMinimumHeight(plotMinimumHeight());
    plot->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    // Live traces: fast polylines and cached labels keep a replot cheap on a busy machine.
    plot->setPlottingHints(QCP::phFastPolylines | QCP::phCacheLabels);
    plot->plotLayout()->insertRow(0);
    auto* title = new QCPTextElement(plot, spec.title, QFont(font().family(), font().pointSize(), QFont::Bold));
    plot->plotLayout()->addElement(0, 0, title);
    plot->xAxis->setLabel(tr("t [s]"));
    plot->yAxis->setLabel(spec.yLabel);
    // A narrow dock or presentation mode: only as many numbers as fit apart (plot_ticks.h).
    keepTickLabelsApart(plot->xAxis);
    keepTickLabelsApart(plot->yAxis);
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
    return plot;
}

// The error bands (two graphs each, behind the curves, out of the legend), the zoom that stops
// autoscaling, and the red crosses where a view failed; the plot joins the dock.
void PlotDock::addBandsAndMarks(QCustomPlot* plot, const PlotSpec& spec) {
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
    // Where a view failed: a red cross at the end of its curves.
    QCPGraph* marks = plot->addGraph();
    marks->setLineStyle(QCPGraph::lsNone);
    marks->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCross, QPen(QColor(210, 30, 30), 2.2), Qt::NoBrush, 11));
    marks->setName(tr("✕ a view failed"));
    marks->removeFromLegend();
    m_viewOf.insert(marks, -1);
    m_failMarks.push_back(marks);
    m_viewGraphs.emplace_back();
    m_viewLegend.emplace_back();
}

int PlotDock::plotMinimumHeight() const {
    // Twelve lines of text: a title, tick labels, an axis label, up to four legend rows and
    // room for the curves; grows with the font (presentation mode), the plots then scroll.
    return std::max(140, 12 * QFontMetrics(font()).height());
}

void PlotDock::changeEvent(QEvent* event) {
    QDockWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange) {
        for (QCustomPlot* plot : m_plots) plot->setMinimumHeight(plotMinimumHeight());
        m_driftPlot->setMinimumHeight(plotMinimumHeight());
    }
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

QString PlotDock::bandNote() const { return m_bandNote->text(); }
bool PlotDock::bandsShown() const { return m_showBands->isChecked(); }
void PlotDock::setBandsShown(bool on) { m_showBands->setChecked(on); }

void PlotDock::updateBandNote() {
    QString note;
    if (m_showBands->isChecked()) {
        if (!m_lastRowHasBand)
            note = tr("No band: this integrator gives no error estimate. Use rk45, CVODE, or tick \"Estimate error "
                      "(step doubling)\" in the Run dock.");
        else if (m_bandsThin)
            note = tr("The band is there but thinner than a line: each step's error estimate is below half a pixel "
                      "at this zoom (an adaptive method keeps it under its tolerance). Loosen rtol/atol in the Run "
                      "dock, or use a fixed-step method at a larger DT with step doubling, to see it.");
        else
            note = tr("Band: the error each step adds (a per-step estimate), not the error of the run so far.");
    }
    if (note != m_bandNote->text()) m_bandNote->setText(note);
    m_bandNote->setVisible(!note.isEmpty());
}

bool PlotDock::bandsThinnerThanALine() const {
    // The widest band point in view, in pixels of its plot's value axis.
    double widest = 0.0;
    bool any = false;
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        const QCustomPlot* plot = m_plots[i];
        if (plot->axisRect()->height() < 10) return false;  // not laid out yet: unknown
        const double unitsPerPixel = plot->yAxis->range().size() / plot->axisRect()->height();
        const QCPRange x = plot->xAxis->range();
        for (const Band& b : m_bands[i]) {
            auto up = b.upper->data()->findBegin(x.lower), lo = b.lower->data()->findBegin(x.lower);
            for (; up != b.upper->data()->constEnd() && lo != b.lower->data()->constEnd() && up->key <= x.upper; ++up, ++lo) {
                if (std::isnan(up->value) || std::isnan(lo->value)) continue;
                any = true;
                widest = std::max(widest, 0.5 * (up->value - lo->value) / unitsPerPixel);
            }
        }
    }
    return any && widest < 0.5;
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
        for (const ViewGraph& g : m_viewGraphs[i]) g.graph->data()->clear();
        m_failMarks[i]->data()->clear();
    }
    for (QCPGraph* g : m_driftGraphs) g->data()->clear();
    m_driftMarks->data()->clear();
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
    QString text = tr("t = %1 s").arg(num(m_cursorTime, 'f', 4));
    const auto& series = m_specs[std::size_t(i)].series;
    for (std::size_t s = 0; s < series.size(); ++s)
        text += (s % 3 == 0 ? QStringLiteral("\n") : QStringLiteral("   ")) +
                QStringLiteral("%1 %2").arg(series[s].name).arg(num(valueAt(plotId, int(s), m_cursorTime), 'g', 6));
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
    {
        QVector<QCPGraphData> drift;
        drift.reserve(count);
        for (int r = first; r < first + count; ++r) {
            const simcore::Diagnostics& d = history[std::size_t(r)];
            const double value = std::abs(d.energyDrift());
            if (value > 0.0 && std::isfinite(value)) drift.append(QCPGraphData(d.time, value));
        }
        m_driftGraphs[0]->data()->add(drift, true);
    }
    if (count > 0) {
        m_lastTime = std::max(m_lastTime, history[std::size_t(first + count - 1)].time);
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
    updateFailureMarks();
    // Robust autoscale side by side: while any view runs, the failed ones are left out of the
    // value range (their blow-up would flatten the others).
    bool anyLive = false;
    for (const ViewInfo& v : m_views) anyLive = anyLive || !v.failedAt;
    auto counted = [&](const QCPGraph* g) {
        const int view = m_viewOf.value(g, 0);
        if (view < 0) return false;  // the failure marks sit on the curves' ends
        return !(m_views.size() > 1 && anyLive && view < int(m_views.size()) && m_views[std::size_t(view)].failedAt);
    };
    std::vector<QCustomPlot*> plots = m_plots;
    if (m_driftPlot->isVisible()) plots.push_back(m_driftPlot);
    for (QCustomPlot* plot : plots) {
        const bool log = plot == m_driftPlot;
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
                if (!log && !counted(plot->graph(g))) continue;
                if (log && m_viewOf.value(plot->graph(g), 0) < 0) continue;
                bool ok = false;
                const QCPRange r = plot->graph(g)->getValueRange(ok, log ? QCP::sdPositive : QCP::sdBoth, QCPRange(lo, hi));
                if (!ok) continue;
                y = found ? QCPRange(std::min(y.lower, r.lower), std::max(y.upper, r.upper)) : r;
                found = true;
            }
            if (found && log) {
                plot->yAxis->setRange(y.lower / 2.0, y.upper * 2.0);
            } else if (found) {
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
    if (m_showBands->isChecked() && m_lastRowHasBand) {
        const bool thin = bandsThinnerThanALine();
        if (thin != m_bandsThin) {
            m_bandsThin = thin;
            updateBandNote();
        }
    }
}

// --- side by side ---

bool PlotDock::compared(std::size_t plot, std::size_t series) const {
    // The energy plot compares its total only (eight terms three times over would hide each other).
    return m_specs[plot].id != QStringLiteral("energy") || m_specs[plot].series[series].name == tr("total");
}

QCPGraph* PlotDock::viewGraph(int plot, int view, int series) const {
    if (plot < 0 || plot >= int(m_plots.size())) return nullptr;
    if (view == 0) return series < int(m_specs[std::size_t(plot)].series.size()) ? m_plots[std::size_t(plot)]->graph(series) : nullptr;
    for (const ViewGraph& g : m_viewGraphs[std::size_t(plot)])
        if (g.view == view && g.series == series) return g.graph;
    return nullptr;
}

void PlotDock::addViewGraphs(int view) {
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        const auto& series = m_specs[i].series;
        for (std::size_t s = 0; s < series.size(); ++s) {
            if (!compared(i, s)) continue;
            QCPGraph* g = m_plots[i]->addGraph();
            g->setPen(QPen(series[s].color, series[s].name == tr("total") ? 2.0 : 1.4, viewStyle(view)));
            g->setName(QStringLiteral("%1, view %2").arg(series[s].name).arg(view + 1));
            g->removeFromLegend();
            m_viewOf.insert(g, view);
            m_viewGraphs[i].push_back({view, int(s), g});
        }
    }
    while (int(m_driftGraphs.size()) <= view) {
        QCPGraph* g = m_driftPlot->addGraph();
        const int v = int(m_driftGraphs.size());
        g->setPen(QPen(viewColor(v), 1.6, viewStyle(v)));
        m_viewOf.insert(g, v);
        m_driftGraphs.push_back(g);
    }
}

void PlotDock::ensureViews(int count) {
    while (int(m_views.size()) < count) {
        m_views.push_back({});
        addViewGraphs(int(m_views.size()) - 1);
    }
    m_driftPlot->setVisible(m_views.size() > 1);
}

void PlotDock::dropViews(int count) {
    count = std::max(count, 1);
    if (int(m_views.size()) <= count) return;
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        auto& graphs = m_viewGraphs[i];
        for (auto it = graphs.begin(); it != graphs.end();) {
            if (it->view < count) {
                ++it;
                continue;
            }
            m_viewOf.remove(it->graph);
            m_plots[i]->removeGraph(it->graph);
            it = graphs.erase(it);
        }
    }
    while (int(m_driftGraphs.size()) > count) {
        m_viewOf.remove(m_driftGraphs.back());
        m_driftPlot->removeGraph(m_driftGraphs.back());
        m_driftGraphs.pop_back();
    }
    m_views.resize(std::size_t(count));
    m_driftPlot->setVisible(m_views.size() > 1);
}

void PlotDock::updateViewLegend() {
    // One line per view in each plot's legend: its line style and integrator (and when it failed).
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        for (QCPGraph* g : m_viewLegend[i]) m_plots[i]->removeGraph(g);
        m_viewLegend[i].clear();
    }
    const bool multi = m_views.size() > 1;
    // Side by side the energy plot is each view's total: view 1's other terms step aside (the
    // energy bars compare every term, view by view).
    for (std::size_t i = 0; i < m_plots.size(); ++i)
        for (std::size_t s = 0; s < m_specs[i].series.size(); ++s) {
            if (compared(i, s)) continue;
            QCPGraph* g = m_plots[i]->graph(int(s));
            g->setVisible(!multi);
            if (multi) g->removeFromLegend();
            else g->addToLegend();
        }
    auto name = [&](int v) {
        const ViewInfo& info = m_views[std::size_t(v)];
        // Short: five entries share a legend row. The cross and time say where it failed.
        QString text = QStringLiteral("%1 %2").arg(v + 1).arg(info.integrator);
        if (info.failedAt) text += tr(" ✕ %1 s").arg(num(*info.failedAt, 'f', 2));
        return text;
    };
    if (multi)
        for (std::size_t i = 0; i < m_plots.size(); ++i)
            for (int v = 0; v < int(m_views.size()); ++v) {
                QCPGraph* g = m_plots[i]->addGraph();
                g->setPen(QPen(QColor(60, 60, 60), 1.6, viewStyle(v)));
                g->setName(name(v));
                m_viewOf.insert(g, -1);
                m_viewLegend[i].push_back(g);
            }
    for (int v = 0; v < int(m_driftGraphs.size()); ++v)
        if (v < int(m_views.size())) m_driftGraphs[std::size_t(v)]->setName(name(v));
}

void PlotDock::setViews(const Frame& frame) {
    const int count = int(frame.lanes.size());
    bool changed = count != int(m_views.size());
    if (count < int(m_views.size())) dropViews(count);
    ensureViews(count);
    for (int v = 0; v < count; ++v) {
        const LaneFrame& lane = frame.lanes[std::size_t(v)];
        const std::optional<double> failedAt =
            lane.failure ? std::optional<double>(lane.failure->time) : std::nullopt;
        ViewInfo& info = m_views[std::size_t(v)];
        if (info.integrator != lane.integrator || info.failedAt != failedAt) {
            info.integrator = lane.integrator;
            info.failedAt = failedAt;
            changed = true;
        }
    }
    if (!changed) return;
    updateViewLegend();
    scheduleReplot();
}

void PlotDock::appendViewRows(int view, const std::vector<simcore::Diagnostics>& rows, int first, int count) {
    if (view < 1 || count <= 0) return;
    ensureViews(view + 1);
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        for (const ViewGraph& g : m_viewGraphs[i]) {
            if (g.view != view) continue;
            const SeriesSpec& spec = m_specs[i].series[std::size_t(g.series)];
            QVector<QCPGraphData> points;
            points.reserve(count);
            for (int r = first; r < first + count; ++r) {
                const simcore::Diagnostics& d = rows[std::size_t(r)];
                points.append(QCPGraphData(d.time, spec.value(d)));
            }
            g.graph->data()->add(points, true);
        }
    }
    QVector<QCPGraphData> drift;
    for (int r = first; r < first + count; ++r) {
        const simcore::Diagnostics& d = rows[std::size_t(r)];
        const double value = std::abs(d.energyDrift());
        if (value > 0.0 && std::isfinite(value)) drift.append(QCPGraphData(d.time, value));
    }
    m_driftGraphs[std::size_t(view)]->data()->add(drift, true);
    m_lastTime = std::max(m_lastTime, rows[std::size_t(first + count - 1)].time);
    scheduleReplot();
}

void PlotDock::updateFailureMarks() {
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        QVector<QCPGraphData> marks;
        for (int v = 0; v < int(m_views.size()); ++v) {
            if (!m_views[std::size_t(v)].failedAt) continue;
            for (std::size_t s = 0; s < m_specs[i].series.size(); ++s) {
                const QCPGraph* g = viewGraph(int(i), v, int(s));
                if (g && !g->data()->isEmpty()) {
                    const auto last = g->data()->constEnd() - 1;
                    marks.append(QCPGraphData(last->key, last->value));
                }
            }
        }
        std::sort(marks.begin(), marks.end(), [](const QCPGraphData& a, const QCPGraphData& b) { return a.key < b.key; });
        m_failMarks[i]->data()->set(marks, true);
    }
    QVector<QCPGraphData> marks;
    for (int v = 0; v < int(m_views.size()) && v < int(m_driftGraphs.size()); ++v) {
        const QCPGraph* g = m_driftGraphs[std::size_t(v)];
        if (m_views[std::size_t(v)].failedAt && !g->data()->isEmpty()) {
            const auto last = g->data()->constEnd() - 1;
            marks.append(QCPGraphData(last->key, last->value));
        }
    }
    std::sort(marks.begin(), marks.end(), [](const QCPGraphData& a, const QCPGraphData& b) { return a.key < b.key; });
    m_driftMarks->data()->set(marks, true);
}

int PlotDock::viewPointCount(const QString& plotId, int view, int series) const {
    const QCPGraph* g = viewGraph(plotIndex(plotId), view, series);
    return g ? g->data()->size() : -1;
}

double PlotDock::viewLastValue(const QString& plotId, int view, int series) const {
    const QCPGraph* g = viewGraph(plotIndex(plotId), view, series);
    return g && !g->data()->isEmpty() ? (g->data()->constEnd() - 1)->value : qQNaN();
}

double PlotDock::viewLastTime(const QString& plotId, int view, int series) const {
    const QCPGraph* g = viewGraph(plotIndex(plotId), view, series);
    return g && !g->data()->isEmpty() ? (g->data()->constEnd() - 1)->key : qQNaN();
}

int PlotDock::driftPointCount(int view) const {
    return view >= 0 && view < int(m_driftGraphs.size()) ? m_driftGraphs[std::size_t(view)]->data()->size() : -1;
}

double PlotDock::lastDrift(int view) const {
    if (view < 0 || view >= int(m_driftGraphs.size()) || m_driftGraphs[std::size_t(view)]->data()->isEmpty()) return qQNaN();
    return (m_driftGraphs[std::size_t(view)]->data()->constEnd() - 1)->value;
}

int PlotDock::failureMarkCount(const QString& plotId) const {
    if (plotId == QStringLiteral("drift")) return m_driftMarks->data()->size();
    const int i = plotIndex(plotId);
    return i < 0 ? -1 : m_failMarks[std::size_t(i)]->data()->size();
}

QStringList PlotDock::legendNames(const QString& plotId) const {
    const QCustomPlot* plot = plotId == QStringLiteral("drift") ? m_driftPlot
                              : plotIndex(plotId) >= 0          ? m_plots[std::size_t(plotIndex(plotId))]
                                                                : nullptr;
    QStringList names;
    if (!plot) return names;
    for (int k = 0; k < plot->legend->itemCount(); ++k)
        if (auto* item = qobject_cast<QCPPlottableLegendItem*>(plot->legend->item(k))) names << item->plottable()->name();
    return names;
}

}  // namespace elui
