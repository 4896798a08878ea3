#include "ui/run_dock.h"

#include <cmath>
#include <functional>
#include <map>

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
#include "simlab/request.h"
#include "ui/accessibility.h"
#include "ui/field_keys.h"
#include "ui/language.h"
#include "ui/parameter_dock.h"

namespace elui {

namespace {
// Whether the named integrator chooses its own steps (rk45, cvode-*): asked once per name.
bool isAdaptive(const QString& name) {
    static const std::map<QString, bool> table = [] {
        std::map<QString, bool> t;
        for (const simcore::IntegratorInfo& info : simcore::integratorTable())
            if (auto integrator = simcore::makeIntegrator(info.name)) t[toQString(info.name)] = integrator->adaptive();
        return t;
    }();
    const auto it = table.find(name);
    return it != table.end() && it->second;
}
}  // namespace

RunDock::RunDock(QWidget* parent) : QDockWidget(tr("Run"), parent) {
    setObjectName(QStringLiteral("RunDock"));
    auto* host = new QWidget(this);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(createForm(host));
    createButtons(host, layout);
    createReadout(host, layout);
    layout->addStretch(1);
    setWidget(host);
    connectFields();
    connectButtons();
}

// Integrator, DT, the adaptive methods' tolerances and the speed, one row each.
QFormLayout* RunDock::createForm(QWidget* host) {
    auto* form = new QFormLayout;
    m_integrator = new QComboBox(host);
    m_integrator->setObjectName(QStringLiteral("integratorCombo"));
    for (const simcore::IntegratorInfo& info : simcore::integratorTable()) {
        m_integrator->addItem(toQString(info.name));
        m_integrator->setItemData(m_integrator->count() - 1,
                                  tr("order %1: %2").arg(info.order).arg(simcoreText(info.description)),
                                  Qt::ToolTipRole);
    }
    m_integrator->setPlaceholderText(tr("side by side (see each view)"));
    form->addRow(tr("Integrator"), m_integrator);
    m_integrator->setToolTip(tr("The method that advances the body in time; each one's order and idea are in its "
                                "item's tooltip and in Help"));
    m_integrator->setAccessibleName(tr("Integrator"));
    m_dt = new QLineEdit(host);
    m_dt->setObjectName(QStringLiteral("dtEdit"));
    const simcore::ParamSpec* dtSpec = &simcore::paramSpec(simcore::Param::Dt);
    m_dtTip = tr("%1; allowed %2 s").arg(simcoreText(dtSpec->meaning), QString::fromStdString(dtSpec->rangeText()));
    m_dt->setToolTip(m_dtTip);
    form->addRow(tr("DT [s]"), m_dt);
    // The float32 path (issue 27): the front door decides which integrators may take it.
    m_precision = new QComboBox(host);
    m_precision->setObjectName(QStringLiteral("precisionCombo"));
    m_precision->addItem(tr("double"), QStringLiteral("double"));
    m_precision->addItem(tr("float"), QStringLiteral("float"));
    m_precision->setToolTip(tr("double: state and forces in 64-bit numbers. float: in 32-bit numbers, as fast "
                               "engines and games compute (euler, midpoint, rk4, symplectic-euler, verlet; one "
                               "view; no walls or mouse: the run stops at a wall, a held particle steps in double). "
                               "The readout shows how far the float run is from double."));
    m_precision->setAccessibleName(tr("Precision"));
    form->addRow(tr("Precision"), m_precision);
    // The adaptive methods' tolerances (rk45, cvode-bdf, cvode-adams): the CLI's --rtol and
    // --atol, with their ranges. Greyed out while no view uses an adaptive method.
    auto* tolerances = new QWidget(host);
    auto* tolRow = new QHBoxLayout(tolerances);
    tolRow->setContentsMargins(0, 0, 0, 0);
    m_rtol = new QLineEdit(tolerances);
    m_rtol->setObjectName(QStringLiteral("rtolEdit"));
    m_atol = new QLineEdit(tolerances);
    m_atol->setObjectName(QStringLiteral("atolEdit"));
    m_tolTip = tr("rk45, cvode-bdf and cvode-adams choose their steps so that each step's error estimate stays "
                  "below atol + rtol |y| (as elastic-lab-cli --atol, --rtol). rtol in (0, 1], atol in [0, 1] "
                  "(m and m/s). Smaller: smaller steps, more force evaluations, a thinner error band.");
    tolRow->addWidget(new QLabel(tr("rtol"), tolerances));
    tolRow->addWidget(m_rtol, 1);
    tolRow->addWidget(new QLabel(tr("atol"), tolerances));
    tolRow->addWidget(m_atol, 1);
    tolerances->setToolTip(m_tolTip);
    m_rtol->setToolTip(m_tolTip);
    m_atol->setToolTip(m_tolTip);
    m_rtol->setAccessibleName(tr("Relative tolerance rtol"));
    m_atol->setAccessibleName(tr("Absolute tolerance atol"));
    form->addRow(tr("Tolerance"), tolerances);
    m_speed = new QComboBox(host);
    m_speed->setObjectName(QStringLiteral("speedCombo"));
    for (Speed s : {Speed::RealTime, Speed::Quarter, Speed::Tenth, Speed::AsFastAsPossible})
        m_speed->addItem(speedName(s), int(s));
    m_speed->setToolTip(tr("How fast simulated time runs against the wall clock"));
    form->addRow(tr("Speed"), m_speed);
    m_speed->setAccessibleName(tr("Speed"));
    return form;
}

// Run / Pause, Step, Reset in a row, and the step-doubling switch under them.
void RunDock::createButtons(QWidget* host, QVBoxLayout* layout) {
    auto* buttons = new QHBoxLayout;
    m_run = new QPushButton(tr("Run", "button: start the simulation"), host);
    m_run->setObjectName(QStringLiteral("runButton"));
    m_run->setToolTip(tr("Run or pause the simulation (Space)"));
    m_step = new QPushButton(tr("Step"), host);
    m_step->setToolTip(tr("One step DT forward (S)"));
    m_reset = new QPushButton(tr("Reset"), host);
    m_reset->setToolTip(tr("Back to the start state with the same parameters (Ctrl+R)"));
    buttons->addWidget(m_run);
    buttons->addWidget(m_step);
    buttons->addWidget(m_reset);
    layout->addLayout(buttons);
    m_doubling = new QCheckBox(tr("Estimate error (step doubling)"), host);
    m_doubling->setObjectName(QStringLiteral("stepDoubling"));
    m_doubling->setToolTip(tr("Fixed-step integrators: estimate the local error by taking each step also as "
                              "two half steps. Costs about twice the work. rk45 always reports its own estimate."));
    layout->addWidget(m_doubling);
}

// The readout: the run's numbers in a monospace table, read out by screen readers.
void RunDock::createReadout(QWidget* host, QVBoxLayout* layout) {
    m_readout = new QLabel(host);
    m_readout->setObjectName(QStringLiteral("readout"));
    m_readout->setTextFormat(Qt::RichText);
    m_readout->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QFont mono = m_readout->font();
    mono.setFamily(QStringLiteral("monospace"));
    mono.setStyleHint(QFont::Monospace);
    m_readout->setFont(mono);
    layout->addWidget(m_readout);
    // Tab reaches it; a screen reader reads its text, and again when it changes (at most once a
    // second: it changes every frame).
    makeLive(m_readout, tr("Readout"));
    m_readout->setAccessibleDescription(tr("Time, steps, energies and the energy balance of the run"));
}

// The typed fields: checked, committed on Enter or leaving, put back on Escape.
void RunDock::connectFields() {
    connect(m_integrator, &QComboBox::currentTextChanged, this, [this](const QString& name) {
        if (m_updating) return;
        emit integratorChosen(name);
        // A method without a float build ends a float run: the run goes on in double.
        if (m_precision->currentData().toString() == QLatin1String("float") &&
            !precisionAllowed(QStringLiteral("float"), name))
            emit floatPrecisionChosen(false);
    });
    connect(m_precision, &QComboBox::currentIndexChanged, this, [this] {
        if (!m_updating) choosePrecision();
    });
    auto commitDt = [this] {
        double v = 0.0;
        const QString error = ParameterForm::validate(simcore::paramSpec(simcore::Param::Dt), m_dt->text(), &v);
        markField(m_dt, error, m_dtTip);
        if (!error.isEmpty()) {
            emit message(error);
            return false;
        }
        if (v != m_shownDt) emit dtEdited(v);
        return true;
    };
    connect(m_dt, &QLineEdit::editingFinished, this, commitDt);
    // Enter commits and leaves the field, Escape puts back the DT in use (field_keys.h).
    installFieldKeys(m_dt, commitDt, [this] {
        m_dt->setText(num(m_shownDt, 'g', 10));
        markField(m_dt, {}, m_dtTip);
    });
    auto commitTolerances = [this] {
        bool okR = false, okA = false;
        const double rtol = toCNumber(m_rtol->text()).trimmed().toDouble(&okR);
        const double atol = toCNumber(m_atol->text()).trimmed().toDouble(&okA);
        const bool goodR = okR && rtol > 0.0 && rtol <= 1.0, goodA = okA && atol >= 0.0 && atol <= 1.0;
        markField(m_rtol, goodR ? QString() : tr("rtol: '%1' is not a number in (0, 1]").arg(m_rtol->text()), m_tolTip);
        markField(m_atol, goodA ? QString() : tr("atol: '%1' is not a number in [0, 1]").arg(m_atol->text()), m_tolTip);
        if (!goodR || !goodA) {
            emit message(!goodR ? m_rtol->toolTip() : m_atol->toolTip());
            return false;
        }
        if (atol != m_shownAtol || rtol != m_shownRtol) emit tolerancesEdited(atol, rtol);
        return true;
    };
    for (QLineEdit* edit : {m_rtol, m_atol}) {
        connect(edit, &QLineEdit::editingFinished, this, commitTolerances);
        installFieldKeys(edit, commitTolerances, [this] {
            m_rtol->setText(num(m_shownRtol, 'g', 6));
            m_atol->setText(num(m_shownAtol, 'g', 6));
            markField(m_rtol, {}, m_tolTip);
            markField(m_atol, {}, m_tolTip);
        });
    }
}

bool RunDock::precisionAllowed(const QString& precision, const QString& integrator) {
    const auto problem = simlab::precisionProblem(precision.toStdString(), integrator.toStdString());
    if (!problem) return true;
    emit message(QString::fromStdString(*problem));  // the front door's words, as its other refusals
    m_updating = true;
    m_precision->setCurrentIndex(0);
    m_updating = false;
    return false;
}

void RunDock::choosePrecision() {
    const QString precision = m_precision->currentData().toString();
    if (!precisionAllowed(precision, m_integrator->currentText())) return;
    emit floatPrecisionChosen(precision == QLatin1String("float"));
}

void RunDock::connectButtons() {
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

QString RunDock::viewTable(const Frame& frame) {
    // Side by side: each view's own numbers, one column per view (the table above is view 1's).
    const auto& lanes = frame.lanes;
    auto cells = [&](const QString& name, const std::function<QString(const LaneFrame&, std::size_t)>& value) {
        QString tr_ = QStringLiteral("<tr><td>%1&nbsp;</td>").arg(name);
        for (std::size_t v = 0; v < lanes.size(); ++v)
            tr_ += QStringLiteral("<td align=right>&nbsp;%1</td>").arg(value(lanes[v], v));
        return tr_ + QStringLiteral("</tr>");
    };
    QString html = QStringLiteral("<p style='margin-top:6px'><b>%1</b></p><table cellspacing=0>").arg(tr("Each view"));
    html += cells(tr("view"), [](const LaneFrame& l, std::size_t v) {
        return QStringLiteral("<b>%1 %2</b>").arg(v + 1).arg(l.integrator.toHtmlEscaped());
    });
    html += cells(tr("time"), [](const LaneFrame& l, std::size_t) {
        return l.failure ? QStringLiteral("<span style='color:#c0392b'>✕ %1 s</span>").arg(num(l.failure->time, 'f', 3))
                         : QStringLiteral("%1 s").arg(num(l.diagnostics.time, 'f', 3));
    });
    html += cells(tr("steps"), [](const LaneFrame& l, std::size_t) { return num(static_cast<long long>(l.diagnostics.step)); });
    html += cells(tr("energy drift"), [](const LaneFrame& l, std::size_t) {
        return QStringLiteral("%1 J").arg(num(l.diagnostics.energyDrift(), 'g', 3));
    });
    const int reference = lanes.size() > 1 ? lanes[1].divergenceReference : 0;
    // On two lines: the longest label would otherwise set the dock's width.
    html += cells(tr("distance<br>to view %1").arg(reference + 1), [&](const LaneFrame& l, std::size_t v) {
        if (int(v) == reference) return QStringLiteral("—");
        if (l.failure) return tr("failed");
        return QStringLiteral("%1 m").arg(num(l.divergence, 'g', 3));
    });
    return html + QStringLiteral("</table>");
}

QString RunDock::floatRows(const Frame& frame) {
    auto row = [](const QString& name, const QString& value) {
        return QStringLiteral("<tr><td>%1&nbsp;</td><td align=right>%2</td></tr>").arg(name, value);
    };
    const LaneFrame& lane = frame.lanes.front();
    if (!frame.floatActive)
        return row(tr("precision"), lane.pointer.active ? tr("double while held") : tr("double"));
    QString html = row(tr("precision"), tr("float"));
    // The distance to the shadow double run (small bodies), else the predicted round-off.
    if (frame.floatDistance >= 0.0)
        html += row(tr("float − double"), QStringLiteral("%1 m").arg(num(frame.floatDistance, 'e', 2)));
    else
        html += row(tr("round-off (est.)"), QStringLiteral("%1 m").arg(num(frame.floatRoundoff, 'e', 2)));
    return html;
}

// The controls as the frame has them (integrator, precision, DT, tolerances, speed), without
// their signals (m_updating) and without overwriting a field being edited.
void RunDock::showControls(const Frame& frame) {
    m_updating = true;
    m_running = frame.running;
    m_run->setText(m_running ? tr("Pause") : tr("Run", "button: start the simulation"));
    const LaneFrame& lane = frame.lanes.front();
    const bool single = frame.lanes.size() == 1;
    // Side by side each view names its own integrator: the combo is not one lane's, so it shows
    // none (its placeholder says why) rather than a stale name.
    m_integrator->setEnabled(single);
    if (single) {
        if (m_integrator->currentText() != lane.integrator) m_integrator->setCurrentText(lane.integrator);
    } else if (m_integrator->currentIndex() != -1) {
        m_integrator->setCurrentIndex(-1);
    }
    // Float runs one view of one body: side by side, and a world's bodies, step in double.
    m_precision->setEnabled(single && !frame.world);
    if (const int index = frame.floatWanted ? 1 : 0; m_precision->currentIndex() != index)
        m_precision->setCurrentIndex(index);
    const double dt = frame.parameters.get(simcore::Param::Dt);
    if (dt != m_shownDt && !m_dt->hasFocus()) {
        m_dt->setText(num(dt, 'g', 10));
        markField(m_dt, {}, m_dtTip);  // the DT in use: nothing refused
    }
    m_shownDt = dt;
    bool adaptive = false;
    for (const LaneFrame& l : frame.lanes) adaptive = adaptive || isAdaptive(l.integrator);
    m_rtol->parentWidget()->setEnabled(adaptive);
    if ((frame.atol != m_shownAtol || frame.rtol != m_shownRtol) && !m_rtol->hasFocus() && !m_atol->hasFocus()) {
        m_rtol->setText(num(frame.rtol, 'g', 6));
        m_atol->setText(num(frame.atol, 'g', 6));
        markField(m_rtol, {}, m_tolTip);
        markField(m_atol, {}, m_tolTip);
    }
    m_shownAtol = frame.atol;
    m_shownRtol = frame.rtol;
    const int speedIndex = m_speed->findData(int(frame.speed));
    if (speedIndex != m_speed->currentIndex()) m_speed->setCurrentIndex(speedIndex);
    m_updating = false;
}

void RunDock::showFrame(const FramePtr& frame) {
    if (!frame || frame->lanes.empty()) return;
    showControls(*frame);
    const LaneFrame& lane = frame->lanes.front();
    const bool single = frame->lanes.size() == 1;

    // While running, the numbers change every frame: five updates a second are readable and
    // leave the GUI thread free; a paused or stepped frame always shows at once.
    if (frame->running && m_lastReadout.isValid() && m_lastReadout.elapsed() < 200) return;
    m_lastReadout.start();
    const simcore::Diagnostics& d = lane.diagnostics;
    auto row = [](const QString& name, const QString& value) {
        return QStringLiteral("<tr><td>%1&nbsp;</td><td align=right>%2</td></tr>").arg(name, value);
    };
    QString html = QStringLiteral("<table cellspacing=0>");
    // Side by side the first table holds what the views share (the clock, the common step);
    // each view's own numbers are in the Each view table under it, not view 1's twice over
    // (which also kept the dock within a 1280 px projector at presentation size).
    if (single) html += row(tr("simulated time"), QStringLiteral("%1 s").arg(num(d.time, 'f', 3)));
    html += row(tr("wall time"), QStringLiteral("%1 s").arg(num(frame->wallSeconds, 'f', 2)));
    if (single) html += row(tr("steps"), num(static_cast<long long>(d.step)));
    html += row(tr("steps/s"), frame->running ? num(static_cast<long long>(std::lround(frame->stepsPerSecond))) : tr("paused"));
    html += row(tr("step taken"), QStringLiteral("%1 s").arg(num(d.dt, 'g', 3)));
    if (single) {
        html += row(tr("error estimate"),
                    d.errorEstimate >= 0 ? QStringLiteral("%1 m").arg(num(d.errorEstimate, 'e', 2)) : tr("off"));
        html += row(tr("contact energy"), QStringLiteral("%1 J").arg(num(d.contact, 'g', 4)));
        html += row(tr("removed by contact"),
                    QStringLiteral("%1 J").arg(num(d.removedContact + d.removedCollisions, 'g', 4)));
        html += row(tr("energy drift"), QStringLiteral("%1 J").arg(num(d.energyDrift(), 'e', 2)));
        if (frame->floatWanted) html += floatRows(*frame);
    }
    if (d.hasSolverCounters) {  // CVODE's own counters (issue 13)
        const simcore::SolverCounters& c = d.solver;
        html += row(tr("force evaluations"), num(static_cast<long long>(d.forceEvaluations)));
        html += row(tr("CVODE steps / RHS"), QStringLiteral("%1 / %2").arg(c.steps).arg(c.rhsEvaluations));
        html += row(tr("Jv products / linear it."), QStringLiteral("%1 / %2").arg(c.jacobianProducts).arg(c.linearIterations));
        html += row(tr("error-test / conv. failures"),
                    QStringLiteral("%1 / %2").arg(c.errorTestFailures).arg(c.convergenceFailures));
        html += row(tr("order, re-initialisations"), QStringLiteral("%1, %2").arg(c.order).arg(c.reinitialisations));
    }
    html += QStringLiteral("</table>");
    if (!single) html += viewTable(*frame);
    if (frame->fallingBehind)
        html += tr("<p style='color:#b35900'>Cannot keep up with real time: showing as fast as it runs.</p>");
    if (m_readout->text() != html) m_readout->setText(html);
}

}  // namespace elui
