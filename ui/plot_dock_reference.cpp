// PlotDock's reference curve (plot_dock.h): a converged solution beside the run, and the
// run's distance to it, the error of the run so far, said beside the band's per-step error.
#include <cmath>

#include <QCheckBox>
#include <QLabel>
#include <QVBoxLayout>

#include "qcustomplot.h"
#include "ui/failure_text.h"
#include "ui/plot_dock.h"
#include "ui/reference_run.h"

namespace elui {

namespace {

// The plotted point of a graph at time t exactly (a row of the run), or none.
std::optional<double> pointAt(const QCPGraph* graph, double t) {
    const auto points = graph->data();
    auto it = points->findBegin(t, false);
    if (it == points->constEnd() || std::abs(it->key - t) > 1e-9 * std::max(1.0, std::abs(t))) return std::nullopt;
    return it->value;
}

}  // namespace

void PlotDock::createReferenceControls(QWidget* host, QVBoxLayout* layout) {
    m_reference = new ReferenceRun(this);
    m_showReference = new QCheckBox(tr("Reference curve (rk45)"), host);
    m_showReference->setObjectName(QStringLiteral("showReference"));
    m_showReference->setToolTip(
        tr("A converged solution (rk45 at tolerance 1e-10) from the run's start, computed beside the run on a thread of its own and drawn "
           "dashed: the distance between a curve and it is the error of the run so far (the global error), "
           "where the band is the error one step adds. It follows the run up to the first change of the "
           "physics (a parameter edit other than DT, or a drag)."));
    m_referenceNote = new QLabel(host);
    m_referenceNote->setObjectName(QStringLiteral("referenceNote"));
    m_referenceNote->setWordWrap(true);
    m_referenceNote->hide();
    layout->addWidget(m_showReference);
    layout->addWidget(m_referenceNote);
    connect(m_showReference, &QCheckBox::toggled, this, [this](bool on) {
        if (!on) m_reference->stop();
        for (const auto& graphs : m_referenceGraphs)
            for (const ReferenceGraph& r : graphs) r.graph->setVisible(on);
        // One legend line per plot, only while the curve is drawn.
        for (const auto& graphs : m_referenceGraphs)
            if (!graphs.empty()) {
                if (on) graphs.front().graph->addToLegend();
                else graphs.front().graph->removeFromLegend();
            }
        updateReferenceNote();
        scheduleReplot();
    });
    connect(m_reference, &ReferenceRun::restarted, this, [this] {
        for (const auto& graphs : m_referenceGraphs)
            for (const ReferenceGraph& r : graphs) r.graph->data()->clear();
        updateReferenceNote();
        scheduleReplot();
    });
    connect(m_reference, &ReferenceRun::samplesAppended, this, &PlotDock::appendReference);
    connect(m_reference, &ReferenceRun::failed, this, &PlotDock::updateReferenceNote);
}

void PlotDock::rebuildReferenceGraphs() {
    m_referenceGraphs.clear();
    for (std::size_t i = 0; i < m_plots.size(); ++i) {
        std::vector<ReferenceGraph> graphs;
        for (std::size_t s = 0; s < m_specs[i].series.size(); ++s) {
            if (!m_specs[i].series[s].error) continue;  // the series with a band
            QCPGraph* g = m_plots[i]->addGraph();
            g->setPen(QPen(QColor(20, 20, 20), 1.2, Qt::DashLine));
            g->setName(tr("reference (rk45, 1e-10)"));
            // One legend line per plot, while the curve is drawn.
            if (!graphs.empty() || !m_showReference->isChecked()) g->removeFromLegend();
            g->setVisible(m_showReference->isChecked());
            graphs.push_back({int(s), g});
        }
        m_referenceGraphs.push_back(std::move(graphs));
    }
    appendReference(0, int(m_reference->samples().size()));
}

void PlotDock::appendReference(int first, int count) {
    const auto& rows = m_reference->samples();
    for (std::size_t i = 0; i < m_referenceGraphs.size(); ++i)
        for (const ReferenceGraph& r : m_referenceGraphs[i]) {
            const auto& value = m_specs[i].series[std::size_t(r.series)].value;
            for (int k = first; k < first + count; ++k) r.graph->addData(rows[std::size_t(k)].time, value(rows[std::size_t(k)]));
        }
    updateReferenceNote();
    scheduleReplot();
}

void PlotDock::followReference(const Frame& frame) {
    if (!m_showReference->isChecked() || frame.lanes.empty()) return;
    m_runTime = frame.lanes.front().diagnostics.time;
    m_physicsChangedAt = frame.physicsChangedAt;
    m_reference->follow(frame.runStart, std::min(m_runTime, m_physicsChangedAt));
    updateReferenceNote();
}

bool PlotDock::referenceShown() const { return m_showReference->isChecked(); }
void PlotDock::setReferenceShown(bool on) { m_showReference->setChecked(on); }
QString PlotDock::referenceNote() const { return m_showReference->isChecked() ? m_referenceNote->text() : QString(); }

int PlotDock::referencePointCount(const QString& plotId, int series) const {
    const int i = plotIndex(plotId);
    if (i < 0) return -1;
    for (const ReferenceGraph& r : m_referenceGraphs[std::size_t(i)])
        if (r.series == series) return r.graph->data()->size();
    return -1;
}

double PlotDock::referenceValueAt(const QString& plotId, int series, double t) const {
    const int i = plotIndex(plotId);
    if (i < 0) return qQNaN();
    for (const ReferenceGraph& r : m_referenceGraphs[std::size_t(i)])
        if (r.series == series) return pointAt(r.graph, t).value_or(qQNaN());
    return qQNaN();
}

void PlotDock::updateReferenceNote() {
    m_referenceTime = m_referenceEnergyError = qQNaN();
    if (!m_showReference->isChecked()) {
        m_referenceNote->hide();
        return;
    }
    const auto& rows = m_reference->samples();
    QStringList lines;
    // The total energy's distance at the latest reference row that is also a row of the run.
    const int energy = plotIndex(QStringLiteral("energy"));
    const ReferenceGraph* total = nullptr;
    if (energy >= 0)
        for (const ReferenceGraph& r : m_referenceGraphs[std::size_t(energy)]) total = &r;
    if (total && !rows.empty()) {
        const QCPGraph* run = m_plots[std::size_t(energy)]->graph(total->series);
        const auto& value = m_specs[std::size_t(energy)].series[std::size_t(total->series)].value;
        for (auto it = rows.rbegin(); it != rows.rend() && it - rows.rbegin() < 8; ++it) {
            const auto ran = pointAt(run, it->time);
            if (!ran) continue;
            m_referenceTime = it->time;
            m_referenceEnergyError = *ran - value(*it);
            break;
        }
    }
    if (std::isnan(m_referenceTime)) {
        lines << tr("Reference: computing from the run's start…");
    } else {
        QString line = tr("At t = %1 s the run's total energy is %2 J from the reference: the error of the run so far.")
                           .arg(m_referenceTime, 0, 'f', 3)
                           .arg(m_referenceEnergyError, 0, 'g', 3);
        for (const Band& b : m_bands[std::size_t(energy)])
            if (b.series == total->series) {
                const auto upper = pointAt(b.upper, m_referenceTime);
                const auto ran = pointAt(m_plots[std::size_t(energy)]->graph(total->series), m_referenceTime);
                if (upper && ran && m_showBands->isChecked())
                    line += QLatin1Char(' ') + tr("The band there, one step's error: ±%1 J.").arg(*upper - *ran, 0, 'g', 3);
            }
        lines << line;
    }
    if (const auto& failure = m_reference->failure())
        lines << tr("The reference itself failed at t = %1 s (%2): the body fails at every step size.")
                     .arg(failure->time, 0, 'f', 3)
                     .arg(failureReason(failure->reason));
    else if (m_physicsChangedAt < m_runTime)
        lines << tr("The run was changed at t = %1 s (a parameter edit or a drag): the reference stops there.")
                     .arg(m_physicsChangedAt, 0, 'f', 3);
    else if (!rows.empty() && rows.back().time < m_runTime - 1e-9)
        lines << tr("The reference has reached t = %1 s (computing).").arg(rows.back().time, 0, 'f', 3);
    m_referenceNote->setText(lines.join(QLatin1Char(' ')));
    m_referenceNote->show();
}

}  // namespace elui
