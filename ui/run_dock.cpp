#include "ui/run_dock.h"

#include <cmath>

#include <QElapsedTimer>

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "ui/parameter_dock.h"

namespace elui {

RunDock::RunDock(QWidget* parent) : QDockWidget(tr("Run"), parent) {
    setObjectName(QStringLiteral("RunDock"));
    auto* host = new QWidget(this);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(4, 4, 4, 4);
    auto* form = new QFormLayout;
    m_integrator = new QComboBox(host);
    m_integrator->setObjectName(QStringLiteral("integratorCombo"));
    for (const simcore::IntegratorInfo& info : simcore::integratorTable()) {
        m_integrator->addItem(toQString(info.name));
        m_integrator->setItemData(m_integrator->count() - 1,
                                  QStringLiteral("order %1: %2").arg(info.order).arg(toQString(info.description)),
                                  Qt::ToolTipRole);
    }
    m_integrator->setPlaceholderText(tr("side by side (see each view)"));
    form->addRow(tr("Integrator"), m_integrator);
    m_dt = new QLineEdit(host);
    m_dt->setObjectName(QStringLiteral("dtEdit"));
    const simcore::ParamSpec* dtSpec = &simcore::paramSpec(simcore::Param::Dt);
    m_dt->setToolTip(toQString(dtSpec->meaning) + QStringLiteral("; allowed ") +
                     QString::fromStdString(dtSpec->rangeText()) + QStringLiteral(" s"));
    form->addRow(tr("DT [s]"), m_dt);
    m_speed = new QComboBox(host);
    m_speed->setObjectName(QStringLiteral("speedCombo"));
    for (Speed s : {Speed::RealTime, Speed::Quarter, Speed::Tenth, Speed::AsFastAsPossible})
        m_speed->addItem(speedName(s), int(s));
    m_speed->setToolTip(tr("How fast simulated time runs against the wall clock"));
    form->addRow(tr("Speed"), m_speed);
    layout->addLayout(form);

    auto* buttons = new QHBoxLayout;
    m_run = new QPushButton(tr("Run"), host);
    m_run->setObjectName(QStringLiteral("runButton"));
    m_step = new QPushButton(tr("Step"), host);
    m_reset = new QPushButton(tr("Reset"), host);
    buttons->addWidget(m_run);
    buttons->addWidget(m_step);
    buttons->addWidget(m_reset);
    layout->addLayout(buttons);
    m_doubling = new QCheckBox(tr("Estimate error (step doubling)"), host);
    m_doubling->setObjectName(QStringLiteral("stepDoubling"));
    m_doubling->setToolTip(tr("Fixed-step integrators: estimate the local error by taking each step also as "
                              "two half steps. Costs about twice the work. rk45 always reports its own estimate."));
    layout->addWidget(m_doubling);
    m_readout = new QLabel(host);
    m_readout->setObjectName(QStringLiteral("readout"));
    m_readout->setTextFormat(Qt::RichText);
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont mono = m_readout->font();
    mono.setFamily(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::Monospace);
    m_readout->setFont(mono);
    layout->addWidget(m_readout);
    layout->addStretch(1);
    setWidget(host);

    connect(m_integrator, &QComboBox::currentTextChanged, this, [this](const QString& name) {
        if (!m_updating) emit integratorChosen(name);
    });
    connect(m_dt, &QLineEdit::editingFinished, this, [this] {
        double v = 0.0;
        const QString error = ParameterForm::validate(simcore::paramSpec(simcore::Param::Dt), m_dt->text(), &v);
        if (!error.isEmpty()) {
            m_dt->setStyleSheet(QStringLiteral("background: #ffd6d6"));
            emit message(error);
            return;
        }
        m_dt->setStyleSheet(QString());
        if (v != m_shownDt) emit dtEdited(v);
    });
    connect(m_run, &QPushButton::clicked, this, [this] {
        if (m_running) emit pauseRequested();
        else emit runRequested();
    });
    connect(m_step, &QPushButton::clicked, this, &RunDock::stepRequested);
    connect(m_reset, &QPushButton::clicked, this, &RunDock::resetRequested);
    connect(m_speed, &QComboBox::currentIndexChanged, this,
            [this] { emit speedChosen(Speed(m_speed->currentData().toInt())); });
    connect(m_doubling, &QCheckBox::toggled, this, &RunDock::stepDoublingToggled);
}

void RunDock::showFrame(const FramePtr& frame) {
    if (!frame || frame->lanes.empty()) return;
    m_updating = true;
    m_running = frame->running;
    m_run->setText(m_running ? tr("Pause") : tr("Run"));
    const LaneFrame& lane = frame->lanes.front();
    const bool single = frame->lanes.size() == 1;
    // Side by side each view names its own integrator: the combo is not one lane's, so it shows
    // none (its placeholder says why) rather than a stale name.
    m_integrator->setEnabled(single);
    if (single) {
        if (m_integrator->currentText() != lane.integrator) m_integrator->setCurrentText(lane.integrator);
    } else if (m_integrator->currentIndex() != -1) {
        m_integrator->setCurrentIndex(-1);
    }
    const double dt = frame->parameters.get(simcore::Param::Dt);
    if (dt != m_shownDt && !m_dt->hasFocus()) {
        m_dt->setText(QString::number(dt, 'g', 10));
        m_shownDt = dt;
    }
    const int speedIndex = m_speed->findData(int(frame->speed));
    if (speedIndex != m_speed->currentIndex()) m_speed->setCurrentIndex(speedIndex);
    m_updating = false;

    // While running, the numbers change every frame: five updates a second are readable and
    // leave the GUI thread free; a paused or stepped frame always shows at once.
    if (frame->running && m_lastReadout.isValid() && m_lastReadout.elapsed() < 200) return;
    m_lastReadout.start();
    const simcore::Diagnostics& d = lane.diagnostics;
    auto row = [](const QString& name, const QString& value) {
        return QStringLiteral("<tr><td>%1&nbsp;</td><td align=right>%2</td></tr>").arg(name, value);
    };
    QString html = QStringLiteral("<table cellspacing=0>");
    html += row(tr("simulated time"), QStringLiteral("%1 s").arg(d.time, 0, 'f', 3));
    html += row(tr("wall time"), QStringLiteral("%1 s").arg(frame->wallSeconds, 0, 'f', 2));
    html += row(tr("steps"), QString::number(d.step));
    html += row(tr("steps/s"), frame->running ? QString::number(std::lround(frame->stepsPerSecond)) : tr("paused"));
    html += row(tr("step taken"), QStringLiteral("%1 s").arg(d.dt, 0, 'g', 3));
    html += row(tr("error estimate"),
                d.errorEstimate >= 0 ? QStringLiteral("%1 m").arg(d.errorEstimate, 0, 'e', 2) : tr("off"));
    html += row(tr("contact energy"), QStringLiteral("%1 J").arg(d.contact, 0, 'g', 4));
    html += row(tr("removed by contact"),
                QStringLiteral("%1 J").arg(d.removedContact + d.removedCollisions, 0, 'g', 4));
    html += row(tr("energy drift"), QStringLiteral("%1 J").arg(d.energyDrift(), 0, 'e', 2));
    if (d.hasSolverCounters) {  // CVODE's own counters (issue 13)
        const simcore::SolverCounters& c = d.solver;
        html += row(tr("force evaluations"), QString::number(d.forceEvaluations));
        html += row(tr("CVODE steps / RHS"), QStringLiteral("%1 / %2").arg(c.steps).arg(c.rhsEvaluations));
        html += row(tr("Jv products / linear it."), QStringLiteral("%1 / %2").arg(c.jacobianProducts).arg(c.linearIterations));
        html += row(tr("error-test / conv. failures"),
                    QStringLiteral("%1 / %2").arg(c.errorTestFailures).arg(c.convergenceFailures));
        html += row(tr("order, re-initialisations"), QStringLiteral("%1, %2").arg(c.order).arg(c.reinitialisations));
    }
    for (std::size_t i = 1; i < frame->lanes.size(); ++i)
        html += row(tr("%1 vs %2").arg(frame->lanes[i].integrator, lane.integrator),
                    frame->lanes[i].failure ? tr("blew up")
                                            : QStringLiteral("%1 m").arg(frame->lanes[i].divergence, 0, 'e', 2));
    html += QStringLiteral("</table>");
    if (frame->fallingBehind)
        html += tr("<p style='color:#b35900'>Cannot keep up with real time: showing as fast as it runs.</p>");
    if (m_readout->text() != html) m_readout->setText(html);
}

}  // namespace elui
