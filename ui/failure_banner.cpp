#include "ui/failure_banner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "ui/accessibility.h"
#include "ui/failure_text.h"
#include "ui/language.h"
#include "ui/mailbox.h"

namespace elui {

FailureBanner::FailureBanner(QWidget* parent) : QFrame(parent) {
    setObjectName(QStringLiteral("failureBanner"));
    setStyleSheet(QStringLiteral("#failureBanner { background: #fbe3e1; border-bottom: 2px solid #c0392b; }"));
    // An alert to screen readers: announced when it appears and when the check's answer replaces
    // its text, read as its plain text (present()).
    markAsAlert(this);
    m_fromCheck = new Mailbox(this);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(10, 6, 10, 6);
    layout->setSpacing(4);
    m_text = new QLabel(this);
    m_text->setObjectName(QStringLiteral("failureText"));
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::RichText);
    // Lines across the whole view: the text never asks for width (it takes what the view has).
    m_text->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Minimum);
    layout->addWidget(m_text);
    auto* buttons = new QHBoxLayout;
    buttons->addStretch(1);
    m_smaller = new QPushButton(this);
    m_smaller->setObjectName(QStringLiteral("failureSmallerDt"));
    m_smaller->setToolTip(tr("Start again from the beginning with the step that ran through the failed stretch"));
    connect(m_smaller, &QPushButton::clicked, this, [this] {
        if (m_check && m_check->workingDt > 0.0) emit setDtAndReset(m_check->workingDt);
    });
    m_implicit = new QPushButton(tr("Use implicit-euler and reset"), this);
    m_implicit->setObjectName(QStringLiteral("failureImplicit"));
    m_implicit->setToolTip(tr("Start again with the implicit Euler integrator, which is stable at any time step"));
    connect(m_implicit, &QPushButton::clicked, this, &FailureBanner::useImplicitAndReset);
    m_reset = new QPushButton(tr("Reset"), this);
    m_reset->setObjectName(QStringLiteral("failureReset"));
    m_reset->setToolTip(tr("Start again from the beginning with the same settings"));
    connect(m_reset, &QPushButton::clicked, this, &FailureBanner::resetRequested);
    buttons->addWidget(m_smaller);
    buttons->addWidget(m_implicit);
    buttons->addWidget(m_reset);
    layout->addLayout(buttons);
    hide();
}

FailureBanner::~FailureBanner() { stopCheck(); }

void FailureBanner::stopCheck() {
    if (m_cancel) m_cancel->store(true);
    if (m_thread.joinable()) m_thread.join();
    m_cancel.reset();
    m_checking = false;
}

QString FailureBanner::text() const { return isHidden() ? QString() : m_text->text(); }

void FailureBanner::showFrame(const Frame& frame) {
    const LaneFrame& lane = frame.lanes.front();
    const bool failed = frame.lanes.size() == 1 && lane.failure.has_value();
    if (!failed) {
        if (m_shown) {
            stopCheck();
            ++m_checkSerial;  // a result still in the mailbox is for a failure no longer shown
            m_check.reset();
            m_shown = false;
            m_failureStep = -1;
            hide();
        }
        return;
    }
    if (m_shown && lane.failure->step == m_failureStep) return;
    stopCheck();
    ++m_checkSerial;
    m_shown = true;
    m_failure = *lane.failure;
    m_failureStep = m_failure.step;
    m_integrator = lane.integrator;
    m_dt = frame.parameters.get(simcore::Param::Dt);
    m_check.reset();
    if (lane.stretchStart) startCheck(*lane.stretchStart, m_failure);
    present();
    show();
    announceAlert(this);
}

void FailureBanner::startCheck(const simcore::SimulationSnapshot& start, const simcore::Failure& failure) {
    m_checking = true;
    m_cancel = std::make_shared<std::atomic<bool>>(false);
    const quint64 serial = m_checkSerial;
    m_thread = std::thread([this, start, failure, serial, cancel = m_cancel] {
        simlab::FailureCheck check = simlab::checkFailure(start, failure, cancel.get());
        if (cancel->load()) return;
        m_fromCheck->post([this, check = std::move(check), serial] {
            if (serial != m_checkSerial) return;
            m_checking = false;
            m_check = check;
            present();
            announceAlert(this);  // the answer replaces "checking…": read it out
        });
    });
}

// The check's verdict in words: simlab's text in English; in another language the same sentences
// with the same numbers (the failure's reason and the linearised verdict too: failure_text.h).
QString FailureBanner::checkText(const simlab::FailureCheck& c) {
    if (currentLanguage() == QLatin1String("en")) return QString::fromStdString(simlab::failureCheckText(c));
    if (c.physical && c.rerunFailure)
        return tr("The body itself collapses — no step size will save it: run again from t = %1 s at a step of %2 s "
                  "(%3), it fails at t = %4 s as well (%5). Change the body instead: lighter masses or less gravity, "
                  "stiffer springs (ks, and the radial ones), more gas pressure, or more damping.")
            .arg(num(c.from, 'f', 3), num(c.rerunDt, 'g', 3), QString::fromStdString(c.integrator),
                 num(c.rerunFailure->time, 'f', 3), failureReason(c.rerunFailure->reason));
    return tr("The step was too large: run again from t = %1 s at a step of %2 s, the same stretch runs through "
              "t = %3 s. The linearised body agrees: %4.")
        .arg(num(c.from, 'f', 3), num(c.rerunDt, 'g', 3), num(c.until, 'f', 3),
             verdictSentence(c.verdict));
}

void FailureBanner::present() {
    QString head = tr("<b>The simulation blew up</b> at t = %1 s (step %2): %3. The run is paused and shows the "
                      "last good state.")
                       .arg(num(m_failure.time, 'f', 3))
                       .arg(m_failure.step)
                       .arg(failureReason(m_failure.reason).toHtmlEscaped());
    QString body;
    const bool physical = m_check && m_check->checked && m_check->physical;
    const bool numerical = m_check && m_check->checked && !m_check->physical;
    if (m_checking)
        body = tr("Checking whether a smaller step survives the same stretch (a re-run at a quarter of DT, in the "
                  "background)…");
    else if (m_check && m_check->checked)
        body = checkText(*m_check).toHtmlEscaped();
    else
        body = tr("Try a smaller DT, a more stable integrator (rk4, or implicit-euler), softer springs or less "
                  "pressure, then Reset.");
    if (physical) body = QStringLiteral("<b>%1</b>").arg(body);
    m_text->setText(head + QStringLiteral("<br>") + body);
    setAccessibleName(plainText(m_text->text()));
    // Only remedies that work: the step that ran through; no DT button for the body's own failure.
    m_smaller->setVisible(numerical && m_check->workingDt > 0.0);
    if (numerical) m_smaller->setText(tr("Use DT = %1 s and reset").arg(num(m_check->workingDt)));
    const bool unchecked = !m_checking && !(m_check && m_check->checked);
    m_implicit->setVisible((numerical || unchecked) && m_integrator != QStringLiteral("implicit-euler"));
}

}  // namespace elui
