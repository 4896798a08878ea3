#include "ui/energy_bars_dock.h"

#include <algorithm>
#include <cmath>

#include <QTimer>

#include "qcustomplot.h"
#include "ui/plot_ticks.h"

namespace elui {

namespace {
// The lanes side by side: lane 0 solid, then hatched, then dotted (the same colour).
Qt::BrushStyle laneBrush(int lane) {
    switch (lane) {
        case 0: return Qt::SolidPattern;
        case 1: return Qt::BDiagPattern;
        default: return Qt::Dense5Pattern;
    }
}
QString laneBrushName(int lane) {
    switch (lane) {
        case 0: return QObject::tr("solid");
        case 1: return QObject::tr("hatched");
        default: return QObject::tr("dotted");
    }
}
QString joules(double v) {
    // Read out in class: "1108 J", "72.2 J", "0.153 J", never "1.11e+03 J".
    const double a = std::abs(v);
    if (a == 0.0) return QStringLiteral("0 J");
    const int decimals = a >= 100.0 ? 0 : a >= 10.0 ? 1 : a >= 1.0 ? 2 : -1;
    return (decimals >= 0 ? QString::number(v, 'f', decimals) : QString::number(v, 'g', 3)) + QStringLiteral(" J");
}
}  // namespace

EnergyBarsDock::EnergyBarsDock(QWidget* parent) : QDockWidget(tr("Energy bars"), parent) {
    setObjectName(QStringLiteral("EnergyBarsDock"));
    m_plot = new QCustomPlot(this);
    m_plot->setObjectName(QStringLiteral("energyBars"));
    m_plot->setMinimumSize(220, 200);
    m_plot->setPlottingHints(QCP::phCacheLabels);
    m_plot->plotLayout()->insertRow(0);
    m_title = new QCPTextElement(m_plot, tr("Energy book"), QFont(font().family(), font().pointSize(), QFont::Bold));
    m_plot->plotLayout()->addElement(0, 0, m_title);
    // Categories down the left (readable without rotation), joules along the bottom.
    m_plot->yAxis->setRangeReversed(true);
    m_plot->yAxis->grid()->setVisible(false);
    m_plot->yAxis->setTickLength(0, 0);
    m_plot->yAxis->setSubTicks(false);
    m_plot->xAxis->setLabel(tr("energy [J]"));
    m_plot->xAxis->ticker()->setTickCount(4);
    keepTickLabelsApart(m_plot->xAxis);  // a narrow dock: as many numbers as fit apart
    // A row of text per bar (its name must not touch the next one), the two-line title and the
    // energy axis below: the plot's minimum height, in the font of the moment.
    connect(m_plot, &QCustomPlot::beforeReplot, this, [this] {
        const QFontMetrics fm(m_plot->yAxis->tickLabelFont());
        const double rows = m_keys.empty() ? 8.0 : m_keys.back() + 1.2;
        const int needed = std::max(200, int(rows * (fm.height() + 2)) + 5 * fm.height() + 30);
        if (m_plot->minimumHeight() != needed) m_plot->setMinimumHeight(needed);
    });
    // Every number beside its bar inside the plot, measured on the laid-out axis.
    connect(m_plot, &QCustomPlot::afterLayout, this, &EnergyBarsDock::makeRoomForNumbers);
    // The zero line every bar starts from, negative to the left.
    m_plot->xAxis->grid()->setZeroLinePen(QPen(QColor(60, 60, 60), 1.2));
    setWidget(m_plot);

    m_textTimer = new QTimer(this);
    m_textTimer->setSingleShot(true);
    m_textTimer->setInterval(100);  // numbers that change 60 times a second cannot be read
    connect(m_textTimer, &QTimer::timeout, this, &EnergyBarsDock::refreshText);
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) refreshText();
    });
    setScene(simcore::SceneKind::Ring2d, {true, true, true});
}

void EnergyBarsDock::setScene(const SceneData& scene) {
    std::array<bool, 3> families{};
    for (int f = 0; f < 3; ++f) families[std::size_t(f)] = scene.topology.springs[std::size_t(f)].size() > 0;
    setScene(scene.kind, families);
}

void EnergyBarsDock::setScene(simcore::SceneKind kind, const std::array<bool, 3>& families) {
    m_kind = kind;
    m_families = families;
    m_hasFrame = false;
    rebuild();
}

void EnergyBarsDock::rebuild() {
    m_plot->clearPlottables();
    m_plot->clearItems();
    m_items.clear();
    m_labels.clear();
    m_bars = energyBars(m_kind, m_families, m_projection);
    // Positions: the parts of the total, a gap, then removed and drift.
    m_keys.clear();
    double key = 0.0;
    bool parts = true;
    auto ticker = QSharedPointer<QCPAxisTickerText>::create();
    for (const EnergyBar& bar : m_bars) {
        if (parts && !bar.part) key += 0.5;
        parts = bar.part;
        m_keys.push_back(key);
        ticker->addTick(key, bar.name);
        key += 1.0;
    }
    m_plot->yAxis->setTicker(ticker);
    m_plot->yAxis->setRange(-0.6, key - 0.4);

    const double width = 0.8 / m_lanes;
    for (std::size_t b = 0; b < m_bars.size(); ++b) {
        const QColor c = energyColor(m_bars[b].term);
        for (int lane = 0; lane < m_lanes; ++lane) {
            auto* bars = new QCPBars(m_plot->yAxis, m_plot->xAxis);
            bars->setWidth(width);
            bars->setPen(QPen(c.darker(130), 1.0));
            bars->setBrush(QBrush(c, laneBrush(lane)));
            bars->setAntialiased(false);
            // One data point, written in place by every frame.
            bars->data()->add(QCPBarsData(m_keys[b] + (lane - 0.5 * (m_lanes - 1)) * width, 0.0));
            m_items.push_back(bars);
        }
        auto* label = new QCPItemText(m_plot);
        label->position->setType(QCPItemPosition::ptPlotCoords);
        label->position->setCoords(0.0, m_keys[b]);
        label->setPadding(QMargins(4, 0, 4, 0));
        label->setClipToAxisRect(false);
        label->setVisible(false);
        m_labels.push_back(label);
    }
    refreshText();
}

void EnergyBarsDock::showFrame(const Frame& frame) {
    if (frame.lanes.empty()) return;
    const int lanes = std::max<int>(1, int(frame.lanes.size()));
    const bool projection = frame.parameters.get(simcore::Param::Contact) == 1.0;
    if (lanes != m_lanes || projection != m_projection) {
        m_lanes = lanes;
        m_projection = projection;
        rebuild();
    }
    // The lanes' integrators, for the title (QString assignment shares, it does not copy).
    if (m_laneNames.size() != qsizetype(frame.lanes.size())) m_laneNames.resize(qsizetype(frame.lanes.size()));
    for (std::size_t lane = 0; lane < frame.lanes.size(); ++lane)
        if (m_laneNames[qsizetype(lane)] != frame.lanes[lane].integrator) m_laneNames[qsizetype(lane)] = frame.lanes[lane].integrator;
    // Values in place: no allocation on this path.
    double lo = 0.0, hi = 0.0;
    for (int lane = 0; lane < m_lanes && lane < int(frame.lanes.size()); ++lane) {
        const simcore::Diagnostics& d = frame.lanes[std::size_t(lane)].diagnostics;
        for (std::size_t b = 0; b < m_bars.size(); ++b) {
            const double v = m_bars[b].value(d);
            barAt(int(b), lane)->data()->begin()->value = v;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    }
    const simcore::Diagnostics& d0 = frame.lanes.front().diagnostics;
    m_time = d0.time;
    m_total = d0.total();
    m_start = d0.initialEnergy;
    m_hasFrame = true;
    // The axis grows at once when a bar would leave it, and shrinks only when the bars use
    // less than a third of it (no jitter while the body swings). Room on both sides for the
    // numbers.
    const double span = std::max(hi - lo, 1e-9);
    const double needLo = lo < 0.0 ? lo - 0.35 * span : -0.05 * span;
    const double needHi = hi > 0.0 ? hi + 0.35 * span : 0.05 * span;
    const QCPRange now = m_plot->xAxis->range();
    if (now.lower > needLo || now.upper < needHi || now.size() > 3.0 * (needHi - needLo))
        m_plot->xAxis->setRange(needLo, needHi);
    if (!m_textTimer->isActive()) m_textTimer->start();
    if (isVisible()) m_plot->replot(QCustomPlot::rpQueuedReplot);
}

void EnergyBarsDock::makeRoomForNumbers() {
    // A number starts at x (its bar's end, or the zero line) and is w pixels wide; with the axis
    // [L, U] over W pixels it ends inside when (x - L) / (U - L) * W + w <= W, that is
    // U >= L + (x - L) * W / (W - w). The upper end grows to the largest such U (never shrinks
    // here: showFrame's rule shrinks it when the bars need far less).
    const QCPRange range = m_plot->xAxis->range();
    const double width = m_plot->axisRect()->width();
    if (width < 40 || m_lanes != 1) return;
    double upper = range.upper;
    for (const QCPItemText* label : m_labels) {
        if (!label->visible()) continue;
        const QFontMetricsF fm(label->font());
        const double w = fm.horizontalAdvance(label->text()) + label->padding().left() + label->padding().right() + 2.0;
        if (w >= 0.8 * width) continue;  // cannot fit whatever the range: leave it
        const double x = label->position->coords().x();
        upper = std::max(upper, range.lower + (x - range.lower) * width / (width - w));
    }
    if (upper > range.upper) m_plot->xAxis->setRange(range.lower, upper);
}

bool EnergyBarsDock::numbersInside() const {
    const QRect rect = m_plot->axisRect()->rect();
    for (const QCPItemText* label : m_labels) {
        if (!label->visible()) continue;
        const QFontMetricsF fm(label->font());
        const double left = m_plot->xAxis->coordToPixel(label->position->coords().x());
        const double right = left + fm.horizontalAdvance(label->text()) + label->padding().left() + label->padding().right();
        if (left < rect.left() - 1 || right > rect.right() + 1) return false;
    }
    return true;
}

void EnergyBarsDock::refreshText() {
    const bool numbers = m_lanes == 1 && m_hasFrame;
    for (std::size_t b = 0; b < m_labels.size(); ++b) {
        QCPItemText* label = m_labels[b];
        label->setVisible(numbers);
        if (!numbers) continue;
        // At the end of a bar to the right; right of the zero line for a bar to the left (there
        // the number would run into the names).
        const double v = barAt(int(b), 0)->data()->constBegin()->value;
        label->position->setCoords(std::max(v, 0.0), m_keys[b]);
        label->setPositionAlignment(Qt::AlignLeft | Qt::AlignVCenter);
        label->setText(joules(v));
    }
    QString title = tr("Energy book");
    if (m_hasFrame) {
        title = tr("Energy at t = %1 s\ntotal %2, at the start %3")
                    .arg(m_time, 0, 'f', 2)
                    .arg(joules(m_total), joules(m_start));
        if (m_lanes > 1) {
            QStringList lanes;
            for (int lane = 0; lane < m_lanes && lane < m_laneNames.size(); ++lane)
                lanes << QStringLiteral("%1: %2").arg(laneBrushName(lane), m_laneNames[lane]);
            // One view a line: a narrow dock would clip them side by side.
            title = tr("Energy at t = %1 s\n%2").arg(m_time, 0, 'f', 2).arg(lanes.join(QLatin1Char('\n')));
        }
    }
    m_title->setText(title);
    if (isVisible()) m_plot->replot(QCustomPlot::rpQueuedReplot);
}

QStringList EnergyBarsDock::barIds() const {
    QStringList ids;
    for (const EnergyBar& b : m_bars) ids << b.id;
    return ids;
}

QStringList EnergyBarsDock::barNames() const {
    QStringList names;
    for (const EnergyBar& b : m_bars) names << b.name;
    return names;
}

double EnergyBarsDock::value(int bar, int lane) const {
    if (bar < 0 || bar >= int(m_bars.size()) || lane < 0 || lane >= m_lanes) return std::nan("");
    return barAt(bar, lane)->data()->constBegin()->value;
}

QColor EnergyBarsDock::color(int bar, int lane) const {
    if (bar < 0 || bar >= int(m_bars.size()) || lane < 0 || lane >= m_lanes) return {};
    return barAt(bar, lane)->brush().color();
}

QString EnergyBarsDock::title() const { return m_title->text(); }

}  // namespace elui
