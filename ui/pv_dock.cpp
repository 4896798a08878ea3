#include "ui/pv_dock.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QTimer>
#include <QVBoxLayout>

#include "qcustomplot.h"
#include "simcore/scenes.h"
#include "ui/parameter_dock.h"
#include "ui/plot_dock.h"
#include "ui/plot_series.h"
#include "ui/plot_ticks.h"

namespace elui {

namespace {
constexpr int kIsothermSamples = 96;
}

PvDock::PvDock(QWidget* parent) : QDockWidget(tr("P–V diagram"), parent) {
    setObjectName(QStringLiteral("PvDock"));
    auto* host = new QWidget(this);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(4, 4, 4, 4);
    m_wide = new QCheckBox(tr("Whole curve (0.5 to 1.5 × rest volume)"), host);
    m_wide->setObjectName(QStringLiteral("pvWide"));
    m_wide->setToolTip(tr("Off: the axes fit the trail, to see it move. On: a wide stretch of the isotherm, to see "
                          "where on it the layer sits."));
    layout->addWidget(m_wide);
    m_note = new QLabel(host);
    m_note->setWordWrap(true);
    m_note->setAlignment(Qt::AlignCenter);
    layout->addWidget(m_note, 1);
    m_plotHost = new QWidget(host);
    auto* plotsLayout = new QVBoxLayout(m_plotHost);
    plotsLayout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_plotHost, 1);
    const QString layerNames[2] = {tr("inner layer"), tr("outer layer")};
    for (int layer = 0; layer < 2; ++layer) {
        auto* plot = new QCustomPlot(m_plotHost);
        plot->setObjectName(layer == 0 ? QStringLiteral("pv_inner") : QStringLiteral("pv_outer"));
        plot->setMinimumSize(240, 170);
        plot->setPlottingHints(QCP::phFastPolylines | QCP::phCacheLabels);
        plot->plotLayout()->insertRow(0);
        plot->plotLayout()->addElement(
            0, 0, new QCPTextElement(plot, tr("P–V, %1").arg(layerNames[layer]), QFont(font().family(), font().pointSize(), QFont::Bold)));
        const QColor colour = layerColor(layer);
        // The trail under the isotherm: the thin dashed curve running along the thick trail
        // is what "lies on the isotherm" looks like.
        m_trails[std::size_t(layer)] = new QCPCurve(plot->xAxis, plot->yAxis);
        m_trails[std::size_t(layer)]->setPen(QPen(colour, 3.0));
        m_trails[std::size_t(layer)]->setName(tr("trail"));
        m_isotherms[std::size_t(layer)] = plot->addGraph();
        m_isotherms[std::size_t(layer)]->setPen(QPen(QColor(40, 40, 40), 1.2, Qt::DashLine));
        m_now[std::size_t(layer)] = plot->addGraph();
        m_now[std::size_t(layer)]->setLineStyle(QCPGraph::lsNone);
        m_now[std::size_t(layer)]->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, colour.darker(140), colour, 8));
        m_now[std::size_t(layer)]->setName(tr("now"));
        m_now[std::size_t(layer)]->data()->add(QCPGraphData(0.0, 0.0));
        m_now[std::size_t(layer)]->setVisible(false);
        m_now[std::size_t(layer)]->removeFromLegend();
        legendUnderAxes(plot, font());
        plot->xAxis->ticker()->setTickCount(4);
        // A narrow dock: as many numbers as fit apart (plot_ticks.h).
        keepTickLabelsApart(plot->xAxis);
        keepTickLabelsApart(plot->yAxis);
        plotsLayout->addWidget(plot, 1);
        m_plots[std::size_t(layer)] = plot;
    }
    setWidget(host);

    m_replotTimer = new QTimer(this);
    m_replotTimer->setSingleShot(true);
    m_replotTimer->setInterval(100);
    connect(m_replotTimer, &QTimer::timeout, this, &PvDock::replotNow);
    connect(m_wide, &QCheckBox::toggled, this, &PvDock::scheduleReplot);
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) scheduleReplot();
    });
    setScene(simcore::SceneKind::Ring2d);
    setParameters(simcore::ParameterSet(simcore::SceneKind::Ring2d));
}

void PvDock::setScene(simcore::SceneKind kind) {
    m_kind = kind;
    m_gas = simcore::hasGas(kind);
    const bool flat = kind == simcore::SceneKind::Ring2d;
    for (QCustomPlot* plot : m_plots) {
        plot->xAxis->setLabel(flat ? tr("area V [m²]") : tr("volume V [m³]"));
        plot->yAxis->setLabel(flat ? tr("pressure P [N/m]") : tr("pressure P [Pa]"));
    }
    m_note->setText(tr("%1 has no gas: no P–V diagram.").arg(toQString(simcore::sceneInfo(kind).name)));
    m_note->setVisible(!m_gas);
    m_plotHost->setVisible(m_gas);
    m_wide->setVisible(m_gas);
    m_restVolume = {0.0, 0.0};
    clear();
}

void PvDock::setParameters(const simcore::ParameterSet& params) {
    if (!m_gas || !simcore::hasGas(params.kind())) return;
    // c = nRT of each layer, in joules (the gas terms of the force model use exactly these).
    const std::array<double, 2> c{params.get(simcore::Param::PressureInner), params.get(simcore::Param::PressureOuter)};
    if (c == m_c) return;
    m_c = c;
    for (int layer = 0; layer < 2; ++layer)
        m_isotherms[std::size_t(layer)]->setName(tr("P = nRT/V, nRT = %1 J").arg(c[std::size_t(layer)]));
    scheduleReplot();
}

int PvDock::trailSize(int layer) const { return m_trails[std::size_t(layer)]->data()->size(); }

QPointF PvDock::trailPoint(int layer, int index) const {
    const QCPCurveData& p = *(m_trails[std::size_t(layer)]->data()->constBegin() + index);
    return {p.key, p.value};
}

std::vector<QPointF> PvDock::isothermPoints(int layer) const {
    std::vector<QPointF> points;
    for (auto it = m_isotherms[std::size_t(layer)]->data()->constBegin(); it != m_isotherms[std::size_t(layer)]->data()->constEnd(); ++it)
        points.emplace_back(it->key, it->value);
    return points;
}

void PvDock::clear() {
    for (int layer = 0; layer < 2; ++layer) {
        m_trails[std::size_t(layer)]->data()->clear();
        m_now[std::size_t(layer)]->setVisible(false);
        m_vMin[std::size_t(layer)] = std::numeric_limits<double>::infinity();
        m_vMax[std::size_t(layer)] = -std::numeric_limits<double>::infinity();
    }
    scheduleReplot();
}

void PvDock::appendRows(const std::vector<simcore::Diagnostics>& history, int first, int count) {
    if (!m_gas || count <= 0) return;
    for (int layer = 0; layer < 2; ++layer) {
        const std::size_t l = std::size_t(layer);
        QCPCurve* trail = m_trails[l];
        // The curve's parameter t is the point's index: the trail is drawn in the order recorded.
        double t = trail->data()->size();
        QVector<QCPCurveData> points;
        points.reserve(count);
        for (int r = first; r < first + count; ++r) {
            const simcore::Diagnostics& d = history[std::size_t(r)];
            points.append(QCPCurveData(t++, d.volume[l], d.pressure[l]));
            m_vMin[l] = std::min(m_vMin[l], d.volume[l]);
            m_vMax[l] = std::max(m_vMax[l], d.volume[l]);
        }
        trail->data()->add(points, true);
        const simcore::Diagnostics& last = history[std::size_t(first + count - 1)];
        m_restVolume[l] = last.restVolume[l];
        QCPGraphData& now = *m_now[l]->data()->begin();
        now.key = last.volume[l];
        now.value = last.pressure[l];
        m_now[l]->setVisible(true);
    }
    scheduleReplot();
}

void PvDock::scheduleReplot() {
    m_dirty = true;
    if (!m_replotTimer->isActive()) m_replotTimer->start();
}

void PvDock::fit(int layer) {
    const std::size_t l = std::size_t(layer);
    const double rest = m_restVolume[l];
    const bool hasTrail = m_vMax[l] >= m_vMin[l];
    double lo = 0.0, hi = 0.0;
    if (m_wide->isChecked() && rest > 0.0) {
        lo = 0.5 * rest;
        hi = 1.5 * rest;
        if (hasTrail) {
            lo = std::min(lo, m_vMin[l]);
            hi = std::max(hi, m_vMax[l]);
        }
    } else if (hasTrail) {
        // The trail with a margin; at least ±0.5 % of V, so a body at rest shows a stretch of
        // the isotherm and not a dot.
        const double pad = std::max(0.15 * (m_vMax[l] - m_vMin[l]), 0.005 * std::abs(m_vMax[l]));
        lo = m_vMin[l] - pad;
        hi = m_vMax[l] + pad;
    } else if (rest > 0.0) {
        lo = 0.9 * rest;
        hi = 1.1 * rest;
    } else {
        return;  // nothing recorded yet
    }
    lo = std::max(lo, 1e-9 * std::abs(hi));  // P = c/V needs V > 0
    if (!(hi > lo)) hi = lo * 1.01 + 1e-12;
    QCustomPlot* plot = m_plots[l];
    plot->xAxis->setRange(lo, hi);
    // The isotherm over the shown volumes, sampled evenly.
    const double c = m_c[l];
    QVector<QCPGraphData> curve;
    curve.reserve(kIsothermSamples);
    for (int k = 0; k < kIsothermSamples; ++k) {
        const double v = lo + (hi - lo) * k / (kIsothermSamples - 1);
        curve.append(QCPGraphData(v, c / v));
    }
    m_isotherms[l]->data()->set(curve, true);
    // Pressure range: the isotherm's over these volumes, and the trail's (it lies on the
    // isotherm unless c was edited during the run).
    double pLo = std::min(c / hi, c / lo), pHi = std::max(c / hi, c / lo);
    bool ok = false;
    const QCPRange trailP = m_trails[l]->getValueRange(ok);
    if (ok) {
        pLo = std::min(pLo, trailP.lower);
        pHi = std::max(pHi, trailP.upper);
    }
    const double pad = std::max(0.06 * (pHi - pLo), 1e-9 * std::max(1.0, std::abs(pHi)));
    plot->yAxis->setRange(pLo - pad, pHi + pad);
}

void PvDock::replotNow() {
    if (!m_dirty || !m_gas) return;
    m_dirty = false;
    for (int layer = 0; layer < 2; ++layer) {
        fit(layer);
        if (isVisible()) m_plots[std::size_t(layer)]->replot(QCustomPlot::rpQueuedReplot);
    }
}

}  // namespace elui
