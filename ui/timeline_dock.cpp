#include "ui/timeline_dock.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>

namespace elui {

QString byteText(std::size_t bytes) {
    const double b = double(bytes);
    if (b >= 1024.0 * 1024.0 * 1024.0)
        return QStringLiteral("%1 GiB").arg(b / (1024.0 * 1024.0 * 1024.0), 0, 'f', 2);
    if (b >= 1024.0 * 1024.0) return QStringLiteral("%1 MiB").arg(b / (1024.0 * 1024.0), 0, 'f', 1);
    if (b >= 1024.0) return QStringLiteral("%1 KiB").arg(b / 1024.0, 0, 'f', 0);
    return QStringLiteral("%1 B").arg(bytes);
}

TimelineDock::TimelineDock(QWidget* parent) : QDockWidget(tr("Timeline"), parent) {
    setObjectName(QStringLiteral("TimelineDock"));
    auto* host = new QWidget(this);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(6, 4, 6, 4);
    auto* row = new QHBoxLayout;
    m_start = new QPushButton(tr("|◀ Start"), host);
    m_start->setToolTip(tr("The start of the recorded run (Home)"));
    m_back = new QPushButton(tr("◀ Step back"), host);
    m_back->setToolTip(tr("One step back (Shift+S); S steps forward"));
    m_slider = new QSlider(Qt::Horizontal, host);
    m_slider->setObjectName(QStringLiteral("timelineSlider"));
    m_slider->setToolTip(
        tr("Every moment of the run: drag to travel back in time (the run pauses)"));
    m_slider->setRange(0, 0);
    m_slider->setFocusPolicy(Qt::ClickFocus);  // Home / End belong to the window's actions
    m_end = new QPushButton(tr("Newest ▶|"), host);
    m_end->setToolTip(tr("The newest recorded moment (End)"));
    m_clear = new QPushButton(tr("Clear abandoned"), host);
    m_clear->setToolTip(tr("Remove the faint lines of the abandoned future from the plots"));
    m_clear->setEnabled(false);
    row->addWidget(m_start);
    row->addWidget(m_back);
    row->addWidget(m_slider, 1);
    row->addWidget(m_end);
    row->addWidget(m_clear);
    layout->addLayout(row);
    // Where the view is, then what is kept: a line each, never widening the window.
    m_where = new QLabel(host);
    m_where->setObjectName(QStringLiteral("timelineWhere"));
    m_where->setTextFormat(Qt::RichText);
    m_info = new QLabel(host);
    m_info->setObjectName(QStringLiteral("timelineInfo"));
    for (QLabel* l : {m_where, m_info}) {
        l->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
        layout->addWidget(l);
    }
    setWidget(host);

    connect(m_slider, &QSlider::valueChanged, this, [this](int value) {
        if (!m_updating) emit scrubRequested(long(value));
    });
    connect(m_start, &QPushButton::clicked, this, &TimelineDock::startRequested);
    connect(m_back, &QPushButton::clicked, this, &TimelineDock::stepBackRequested);
    connect(m_end, &QPushButton::clicked, this, &TimelineDock::endRequested);
    connect(m_clear, &QPushButton::clicked, this, &TimelineDock::clearAbandonedRequested);
}

void TimelineDock::showFrame(const FramePtr& frame) {
    if (!frame || frame->lanes.empty()) return;
    const TimelineInfo& t = frame->timeline;
    m_updating = true;
    m_slider->setRange(int(t.first), int(t.last));
    // While the user drags, the slider is where the hand is; the frame follows it.
    if (!m_slider->isSliderDown()) m_slider->setValue(int(t.moment));
    m_updating = false;
    const double time = frame->lanes.front().diagnostics.time;
    if (t.scrubbed())
        m_where->setText(
            tr("<b>Back in time</b>: t = %1 s, step %2 of %3 · a change, Run or Step branches here")
                .arg(time, 0, 'f', 4)
                .arg(t.moment)
                .arg(t.last));
    else
        m_where->setText(tr("t = %1 s, step %2 (newest) · recorded from t = %3 s")
                             .arg(time, 0, 'f', 4)
                             .arg(t.moment)
                             .arg(t.firstTime, 0, 'f', 3));
    m_info->setText(tr("%1 checkpoints / %2 steps · %3 of %4")
                        .arg(t.checkpoints)
                        .arg(t.interval)
                        .arg(byteText(t.bytes), byteText(t.budget)));
    m_back->setEnabled(t.moment > t.first);
    m_start->setEnabled(t.moment > t.first);
    m_end->setEnabled(t.scrubbed());
}

void TimelineDock::setAbandoned(bool present) { m_clear->setEnabled(present); }

}  // namespace elui
