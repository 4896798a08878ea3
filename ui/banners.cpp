#include "ui/banners.h"

#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "ui/failure_banner.h"
#include "ui/failure_text.h"
#include "ui/language.h"
#include "ui/simulation_controller.h"

namespace elui {

Banners::Banners(QWidget* parent, QVBoxLayout* column, SimulationController* controller,
                 std::function<void(const QString&)> status) {
    SimulationController* c = controller;
    m_failure = new FailureBanner(parent);
    QObject::connect(m_failure, &FailureBanner::setDtAndReset, c, [c](double dt) {
        c->setParameter(simcore::Param::Dt, dt);
        c->reset();
    });
    QObject::connect(m_failure, &FailureBanner::useImplicitAndReset, c, [c] {
        c->setIntegrator(QStringLiteral("implicit-euler"));
        c->reset();
    });
    QObject::connect(m_failure, &FailureBanner::resetRequested, c, &SimulationController::reset);
    column->addWidget(m_failure);

    m_stability = new QFrame(parent);
    m_stability->setObjectName(QStringLiteral("stabilityBanner"));
    m_stability->setStyleSheet(
        QStringLiteral("#stabilityBanner { background: #fdf0d5; border-bottom: 2px solid #d68910; }"));
    // The text in lines across the view, the buttons in a row under it (FailureBanner's layout).
    auto* stabilityColumn = new QVBoxLayout(m_stability);
    stabilityColumn->setContentsMargins(10, 6, 10, 6);
    stabilityColumn->setSpacing(4);
    m_stabilityText = new QLabel(m_stability);
    m_stabilityText->setWordWrap(true);
    m_stabilityText->setTextFormat(Qt::RichText);
    m_stabilityText->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Minimum);
    stabilityColumn->addWidget(m_stabilityText);
    auto* stabilityLayout = new QHBoxLayout;
    stabilityLayout->addStretch(1);
    stabilityColumn->addLayout(stabilityLayout);
    m_useSuggestedDt = new QPushButton(m_stability);
    m_useSuggestedDt->setObjectName(QStringLiteral("useSuggestedDt"));
    QObject::connect(m_useSuggestedDt, &QPushButton::clicked, c, [this, c, status] {
        c->setParameter(simcore::Param::Dt, m_suggestedDt);
        m_stability->hide();
        status(tr("DT set to %1 s").arg(num(m_suggestedDt)));
    });
    auto* stableImplicit = new QPushButton(tr("Use implicit-euler"), m_stability);
    stableImplicit->setToolTip(tr("Linearised backward Euler: stable at any DT (and damps more)"));
    QObject::connect(stableImplicit, &QPushButton::clicked, c, [this, c] {
        c->setIntegrator(QStringLiteral("implicit-euler"));
        m_stability->hide();
    });
    auto* dismiss = new QPushButton(tr("Keep DT"), m_stability);
    dismiss->setToolTip(tr("Run with this DT anyway (to watch the method fail, for example)"));
    QObject::connect(dismiss, &QPushButton::clicked, m_stability, &QWidget::hide);
    stabilityLayout->addWidget(m_useSuggestedDt);
    stabilityLayout->addWidget(stableImplicit);
    stabilityLayout->addWidget(dismiss);
    m_stability->hide();
    column->addWidget(m_stability);
}

void Banners::showFrame(const Frame& frame) { m_failure->showFrame(frame); }

void Banners::showStabilityAdvice(const SceneData& scene) {
    m_suggestedDt = scene.suggestedDt();
    if (m_suggestedDt <= 0.0) {
        m_stability->hide();
        return;
    }
    // Said before the run goes on (the worker has paused it): a finer mesh has faster modes,
    // so an explicit method needs a smaller DT (docs/numerics.md, "Resolution").
    m_stabilityText->setText(tr("<b>This body is likely unstable at the current DT.</b> %1. The run is paused.")
                                 .arg(adviceSentence(*scene.stabilityAdvice).toHtmlEscaped()));
    m_useSuggestedDt->setText(tr("Use DT = %1 s").arg(num(m_suggestedDt)));
    m_stability->show();
}

QString Banners::stabilityText() const { return m_stability->isHidden() ? QString() : m_stabilityText->text(); }

void Banners::setHighContrast(bool on) {
    m_failure->setStyleSheet(on ? QStringLiteral("#failureBanner { background: black; border: 3px solid #ff5050; }")
                                : QStringLiteral("#failureBanner { background: #fbe3e1; border-bottom: 2px solid #c0392b; }"));
    m_stability->setStyleSheet(
        on ? QStringLiteral("#stabilityBanner { background: black; border: 3px solid yellow; }")
           : QStringLiteral("#stabilityBanner { background: #fdf0d5; border-bottom: 2px solid #d68910; }"));
}

}  // namespace elui
