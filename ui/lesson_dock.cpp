#include "ui/lesson_dock.h"

#include <cmath>
#include <limits>

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QRegularExpression>
#include <QScrollArea>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include "ui/language.h"
#include "ui/lesson_measures.h"

namespace elui {

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

// How a lesson's answer is read off the window's run; None: it is not (a stability scan or a
// weightless impact gives it: "Measure").
enum class Reading { None, AtTime, Failure, LeastArea, LeastAreaPressure, LeastAreaTime, LiftOff };

struct RunReading {
    Reading kind = Reading::None;
    QString integrator;   // AtTime: the view of this integrator (empty: the first view)
    std::function<double(const LaneFrame&)> value = {};  // AtTime
    double restitution = -1.0;  // LiftOff: only with this restitution
};

RunReading makeReading(Reading kind, const QString& integrator = {}, std::function<double(const LaneFrame&)> value = {},
                       double restitution = -1.0) {
    RunReading r;
    r.kind = kind;
    r.integrator = integrator;
    r.value = std::move(value);
    r.restitution = restitution;
    return r;
}

RunReading runReading(const QString& lesson, const QString& key) {
    auto drift = [](const LaneFrame& l) { return l.diagnostics.energyDrift(); };
    if (lesson == QLatin1String("euler-limit") && key == QLatin1String("blowup-time")) return makeReading(Reading::Failure);
    if (lesson == QLatin1String("energy-drift") && key.startsWith(QLatin1String("drift-")))
        return makeReading(Reading::AtTime, key.mid(6), drift);
    if (lesson == QLatin1String("heavy-inner")) {
        if (key == QLatin1String("sag")) return makeReading(Reading::AtTime, {}, [](const LaneFrame& l) { return l.body.sag(); });
        if (key == QLatin1String("collapse-time")) return makeReading(Reading::Failure);
    }
    if (lesson == QLatin1String("pv-isotherm")) {
        if (key == QLatin1String("min-area")) return makeReading(Reading::LeastArea);
        if (key == QLatin1String("max-pressure")) return makeReading(Reading::LeastAreaPressure);
        if (key == QLatin1String("squash-time")) return makeReading(Reading::LeastAreaTime);
    }
    if (lesson == QLatin1String("restitution") && key.startsWith(QLatin1String("liftoff-e")))
        return makeReading(Reading::LiftOff, {}, {}, key.mid(9).toDouble());
    if (lesson == QLatin1String("stiff-springs") && key == QLatin1String("implicit-drift"))
        return makeReading(Reading::AtTime, QStringLiteral("implicit-euler"), drift);
    return {};
}

QString number(double v) { return std::isfinite(v) ? num(v, 'g', 4) : QStringLiteral("—"); }

}  // namespace

LessonDock::LessonDock(QWidget* parent) : QDockWidget(tr("Lesson"), parent) {
    setObjectName(QStringLiteral("LessonDock"));
    auto* scroll = new QScrollArea(this);
    scroll->setAccessibleName(tr("Lesson"));
    scroll->setAccessibleDescription(tr("Run until a time, a stopwatch, and each answer of the lesson beside what your run gives"));
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // rows wrap to the dock's width
    auto* host = new QWidget(scroll);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(6, 6, 6, 6);

    m_title = new QLabel(host);
    m_title->setObjectName(QStringLiteral("lessonTitle"));
    m_title->setWordWrap(true);
    layout->addWidget(m_title);

    createRunUntilRow(host, layout);
    createStopwatchRow(host, layout);
    m_readout = new QLabel(host);
    m_readout->setObjectName(QStringLiteral("lessonReadout"));
    m_readout->setTextFormat(Qt::RichText);
    m_readout->setWordWrap(true);
    layout->addWidget(m_readout);

    createAnswers(host, layout);

    scroll->setWidget(host);
    setWidget(scroll);
    setLesson(nullptr);
    updateStopwatch();
}

// "Run until t = [3.000 s]": runs as fast as possible and pauses at that simulated time.
void LessonDock::createRunUntilRow(QWidget* host, QVBoxLayout* layout) {
    auto* untilRow = new QHBoxLayout;
    m_until = new QDoubleSpinBox(host);
    m_until->setObjectName(QStringLiteral("runUntilTime"));
    m_until->setRange(0.001, 9999.0);
    m_until->setDecimals(3);
    m_until->setValue(3.0);
    m_until->setSuffix(QStringLiteral(" s"));
    m_until->setAccessibleName(tr("Run until this simulated time"));
    m_until->setToolTip(tr("The simulated time [s] at which Run until pauses"));
    m_runUntil = new QPushButton(tr("Run until t ="), host);
    m_runUntil->setObjectName(QStringLiteral("runUntil"));
    m_runUntil->setToolTip(tr("Run as fast as possible and pause at this simulated time."));
    connect(m_runUntil, &QPushButton::clicked, this, [this] { emit runUntilRequested(m_until->value()); });
    untilRow->addWidget(m_runUntil);
    untilRow->addWidget(m_until, 1);
    layout->addLayout(untilRow);
}

// The stopwatch: simulated time between Start and Stop, Zero to start over.
void LessonDock::createStopwatchRow(QWidget* host, QVBoxLayout* layout) {
    auto* watchRow = new QHBoxLayout;
    m_watch = new QLabel(host);
    m_watch->setObjectName(QStringLiteral("stopwatch"));
    m_watch->setToolTip(tr("Simulated time between Start and Stop (the first view's clock)."));
    m_watchButton = new QToolButton(host);
    m_watchButton->setText(tr("Start"));
    m_watchButton->setObjectName(QStringLiteral("stopwatchStartStop"));
    m_watchButton->setToolTip(tr("Start or stop the stopwatch on the simulated clock"));
    m_watchReset = new QToolButton(host);
    m_watchReset->setText(tr("Zero"));
    m_watchReset->setToolTip(tr("Set the stopwatch back to zero"));
    connect(m_watchButton, &QToolButton::clicked, this, [this] {
        const double now = m_last && !m_last->lanes.empty() ? m_last->lanes.front().diagnostics.time : 0.0;
        if (m_watchRunning) m_watchHeld += now - m_watchStart;
        else m_watchStart = now;
        m_watchRunning = !m_watchRunning;
        updateStopwatch();
    });
    connect(m_watchReset, &QToolButton::clicked, this, [this] {
        m_watchHeld = 0.0;
        m_watchStart = m_last && !m_last->lanes.empty() ? m_last->lanes.front().diagnostics.time : 0.0;
        updateStopwatch();
    });
    m_watch->setMinimumWidth(0);
    watchRow->addWidget(m_watch, 1);
    watchRow->addWidget(m_watchButton);
    watchRow->addWidget(m_watchReset);
    layout->addLayout(watchRow);
}

// The answers' table (answer, expected, you got), its legend and Measure.
void LessonDock::createAnswers(QWidget* host, QVBoxLayout* layout) {
    m_table = new QTableWidget(0, 3, host);
    m_table->setObjectName(QStringLiteral("lessonAnswers"));
    m_table->setHorizontalHeaderLabels({tr("answer"), tr("expected"), tr("you got")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_table->horizontalHeader()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setSectionResizeMode(2, QHeaderView::ResizeToContents);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setWordWrap(true);
    layout->addWidget(m_table, 1);

    auto* measureRow = new QHBoxLayout;
    m_measure = new QPushButton(tr("Measure"), host);
    m_measure->setObjectName(QStringLiteral("lessonMeasure"));
    m_measure->setToolTip(tr("Measure every answer on the parameters in use, as the lesson's elastic-lab-cli "
                             "commands do (stability scans, weightless impacts, runs)."));
    connect(m_measure, &QPushButton::clicked, this, &LessonDock::measure);
    m_measureNote = new QLabel(host);
    auto* legend = new QLabel(tr("<small>you got: from your run, or <i>measured</i> (Measure); green within the "
                                 "text's tolerance, amber off it</small>"),
                              host);
    legend->setWordWrap(true);
    layout->addWidget(legend);
    m_legend = legend;
    m_measureNote->setWordWrap(true);
    measureRow->addWidget(m_measure);
    measureRow->addWidget(m_measureNote, 1);
    layout->addLayout(measureRow);
}

LessonDock::~LessonDock() {
    if (m_worker.joinable()) m_worker.join();
}

void LessonDock::setLesson(const Lesson* lesson) {
    m_lesson = lesson;
    m_keys.clear();
    m_expected.clear();
    m_got.clear();
    if (lesson) {
        const QString html = lesson->html();
        const auto answers = lessonAnswers(html);
        // The table follows the text's order.
        static const QRegularExpression key(QStringLiteral("class=\"answer\" data-key=\"([^\"]+)\""));
        for (auto it = key.globalMatch(html); it.hasNext();) m_keys << it.next().captured(1);
        for (const QString& k : m_keys) m_expected[k] = answers.value(k);
        const QList<double> until = lessonUntil(html);
        if (!until.isEmpty()) m_until->setValue(until.front());
        m_title->setText(QStringLiteral("<b>%1</b>").arg(lesson->title.toHtmlEscaped()));
    } else {
        m_title->setText(tr("No lesson: choose one in the Lessons menu. Run until and the stopwatch work "
                            "for any scene."));
    }
    m_table->setVisible(lesson != nullptr);
    m_legend->setVisible(lesson != nullptr);
    m_measure->setVisible(lesson != nullptr);
    m_measureNote->setVisible(lesson != nullptr);
    m_measureNote->clear();
    clearRun();
}

double LessonDock::untilTime() const { return m_until->value(); }

double LessonDock::stopwatch() const {
    const double now = m_last && !m_last->lanes.empty() ? m_last->lanes.front().diagnostics.time : 0.0;
    return m_watchHeld + (m_watchRunning ? now - m_watchStart : 0.0);
}

void LessonDock::updateStopwatch() {
    m_watch->setText(tr("Stopwatch: <b>%1 s</b>").arg(num(stopwatch(), 'f', 3)));
    m_watchButton->setText(m_watchRunning ? tr("Stop") : tr("Start"));
}

double LessonDock::got(const QString& key) const {
    auto it = m_got.find(key);
    return it == m_got.end() ? kNone : it->second.first;
}

bool LessonDock::gotFromRun(const QString& key) const {
    auto it = m_got.find(key);
    return it != m_got.end() && it->second.second;
}

bool LessonDock::readFromRun(const QString& key) const {
    return m_lesson && runReading(m_lesson->id, key).kind != Reading::None;
}

void LessonDock::setGot(const QString& key, double value, bool fromRun) {
    auto it = m_got.find(key);
    if (it != m_got.end() && it->second.second && !fromRun) return;  // the run's own reading wins
    if (it != m_got.end() && it->second.first == value && it->second.second == fromRun) return;
    m_got[key] = {value, fromRun};
    fillTable();
}

void LessonDock::clearRun() {
    // A running stopwatch keeps what it has gathered and goes on from the new start (t = 0).
    if (m_watchRunning && m_last && !m_last->lanes.empty()) {
        m_watchHeld += m_last->lanes.front().diagnostics.time - m_watchStart;
        m_watchStart = 0.0;
    }
    // The figures read so far stay (a lesson's next step, e.g. e = 0.2 or mass_inner = 10 after
    // a reset, stands beside the first); this run reads them again from its own start.
    m_readThisRun.clear();
    m_landed = false;
    m_liftOff = m_lastLiftOff = -1.0;
    m_leastInner.reset();
    m_lastFrame.reset();
    m_lastTouching = false;
    m_impact = m_rebound = -1.0;
    fillTable();
}

void LessonDock::fillTable() {
    m_table->setRowCount(int(m_keys.size()));
    for (int r = 0; r < m_keys.size(); ++r) {
        const QString& key = m_keys[r];
        const double expected = m_expected[key].value;
        const double value = got(key);
        // From the run: upright; from Measure: italic; none yet: a dash, the tooltip says how.
        const QString how = readFromRun(key) ? tr("read off your run") : tr("press Measure");
        const QString gotText = number(value);
        auto set = [&](int column, const QString& text) {
            auto* item = m_table->item(r, column);
            if (!item) m_table->setItem(r, column, item = new QTableWidgetItem);
            item->setText(text);
        };
        set(0, key);
        set(1, number(expected));
        set(2, gotText);
        QTableWidgetItem* gotItem = m_table->item(r, 2);
        QFont font = m_table->font();
        // (Upright where the italic face cannot show the number: Arabic-Indic digits.)
        if (std::isfinite(value) && !gotFromRun(key)) setItalicIfLegible(font, gotText);
        gotItem->setFont(font);
        gotItem->setToolTip(std::isfinite(value) ? (gotFromRun(key) ? tr("read off your run")
                                                                     : tr("measured on the parameters in use"))
                                                 : how);
        // Within the text's tolerance: green; off: amber.
        if (auto* item = m_table->item(r, 2); std::isfinite(value)) {
            const double off = std::abs(value - expected) / std::abs(expected);
            item->setBackground(off <= m_expected[key].relativeTolerance ? QColor(0xd8, 0xf0, 0xd8) : QColor(0xff, 0xe8, 0xc0));
        } else {
            item->setBackground(QBrush());
        }
    }
    m_table->resizeRowsToContents();
}

// The one body's readouts: its centre against the floor, the touch-down and take-off speeds
// (from the frames), the lowest point and the inner gas.
QStringList LessonDock::bodyLines(const Frame& frame) {
    QStringList lines;
    const LaneFrame& first = frame.lanes.front();
    const BodyMeasures& b = first.body;
    lines << tr("centre of mass: %1 m above the floor, vertical speed %2 m/s")
                 .arg(num(b.centreOfMass.y() - b.floor, 'f', 3))
                 .arg(num(b.centreVelocity.y(), 'f', 3));
    if (b.layered)
        lines << tr("layer centres above the floor: inner %1 m, outer %2 m; the inner one sits <b>%3 m</b> %4")
                     .arg(num(b.layerCentre[0].y() - b.floor, 'f', 3))
                     .arg(num(b.layerCentre[1].y() - b.floor, 'f', 3))
                     .arg(num(std::abs(b.sag()), 'f', 4))
                     .arg(b.sag() >= 0.0 ? tr("below") : tr("above"));
    // The centre's speed where the body last touched down and last took off (frames).
    const bool touching = first.diagnostics.contact > 0.0;
    if (m_lastFrame && touching && !m_lastTouching) m_impact = -m_lastFrame->lanes.front().body.centreVelocity.y();
    if (m_lastFrame && !touching && m_lastTouching) m_rebound = b.centreVelocity.y();
    m_lastTouching = touching;
    m_lastFrame = m_last;
    if (m_impact > 0.0)
        lines << tr("centre of mass hit the floor at %1 m/s%2")
                     .arg(num(m_impact, 'f', 3))
                     .arg(m_rebound > 0.0 ? tr(", left it at %1 m/s (ratio %2)")
                                                .arg(num(m_rebound, 'f', 3))
                                                .arg(num(m_rebound / m_impact, 'f', 3))
                                          : QString());
    // Resting on the floor, the smooth contact lets the lowest particles sink a little.
    lines << (b.lowest >= 0.0 ? tr("lowest point %1 m above the floor%2") : tr("lowest point %1 m into the floor (contact)%2"))
                 .arg(num(std::abs(b.lowest), 'f', 3))
                 .arg(m_lastLiftOff >= 0 ? tr("; last left the floor at t = %1 s").arg(num(m_lastLiftOff, 'f', 3))
                                         : QString());
    if (first.diagnostics.hasGas)
        lines << tr("inner layer: %1 %2, pressure %3 %4")
                     .arg(num(first.diagnostics.volume[0], 'g', 4))
                     .arg(frame.scene && frame.scene->kind == simcore::SceneKind::Ring2d ? QStringLiteral("m²")
                                                                                           : QStringLiteral("m³"))
                     .arg(num(first.diagnostics.pressure[0], 'g', 4))
                     .arg(frame.scene && frame.scene->kind == simcore::SceneKind::Ring2d ? QStringLiteral("N/m")
                                                                                           : QStringLiteral("N/m²"));
    return lines;
}

// A world's readouts: the total momentum and the smallest gap, then each body's centre velocity
// and outer volume (the figures lessons 9 and 10 ask for).
QStringList LessonDock::worldLines(const simcore::WorldDiagnostics& d, bool flat) {
    const auto vector = [flat](const Eigen::Vector3d& v) {
        return flat ? QStringLiteral("(%1, %2)").arg(num(v.x(), 'g', 4), num(v.y(), 'g', 4))
                    : QStringLiteral("(%1, %2, %3)").arg(num(v.x(), 'g', 4), num(v.y(), 'g', 4), num(v.z(), 'g', 4));
    };
    QStringList lines;
    lines << (d.minGapBodies[0] >= 0 ? tr("total momentum <b>%1 kg m/s</b>; smallest gap %2 m")
                                     : tr("total momentum <b>%1 kg m/s</b>; no gap below %2 m"))
                 .arg(vector(d.momentum), number(d.minGap));
    for (std::size_t k = 0; k < d.bodies.size(); ++k) {
        const simcore::BodyDiagnostics& b = d.bodies[k];
        lines << tr("body%1: centre velocity %2 m/s, outer %3 %4 of %5 at rest")
                     .arg(k + 1)
                     .arg(vector(b.velocity))
                     .arg(flat ? tr("area") : tr("volume"))
                     .arg(number(b.volume[1]))
                     .arg(number(b.restVolume[1]));
    }
    return lines;
}

void LessonDock::showFrame(const FramePtr& frame) {
    if (!frame || frame->lanes.empty()) return;
    m_last = frame;
    m_params = frame->parameters;
    const LaneFrame& first = frame->lanes.front();
    const double t = first.diagnostics.time;

    // Readouts.
    QStringList lines;
    lines << tr("t = <b>%1 s</b>").arg(num(t, 'f', 3));
    for (const LaneFrame& lane : frame->lanes)
        lines << tr("%1: energy drift <b>%2 J</b>%3")
                     .arg(lane.integrator)
                     .arg(num(lane.diagnostics.energyDrift(), 'g', 4))
                     .arg(lane.failure ? tr(", blew up at t = %1 s").arg(num(lane.failure->time, 'f', 3)) : QString());
    if (frame->world)
        lines << worldLines(*frame->world, frame->scene && frame->scene->kind == simcore::SceneKind::Ring2d);
    else
        lines << bodyLines(*frame);
    m_readout->setText(lines.join(QStringLiteral("<br>")));
    updateStopwatch();

    if (!m_lesson) return;
    const double until = m_until->value();
    for (const QString& key : m_keys) {
        const RunReading reading = runReading(m_lesson->id, key);
        if (reading.kind == Reading::Failure) {
            for (const LaneFrame& lane : frame->lanes)
                if (lane.failure) setGot(key, lane.failure->time, true);
        } else if (reading.kind == Reading::AtTime && !m_readThisRun.count(key)) {
            // The first frame at or past the lesson's time (Run until stops exactly there).
            for (const LaneFrame& lane : frame->lanes)
                if ((reading.integrator.isEmpty() ? &lane == &first : lane.integrator == reading.integrator) &&
                    lane.diagnostics.time >= until - 1e-9 && lane.diagnostics.time < until + 0.05) {
                    setGot(key, reading.value(lane), true);
                    m_readThisRun.insert(key);
                }
        }
    }
    readRows();
}

void LessonDock::appendRows(const std::vector<simcore::Diagnostics>& history, int first, int count) {
    for (int i = first; i < first + count && i < int(history.size()); ++i) {
        const simcore::Diagnostics& d = history[std::size_t(i)];
        if (d.contact > 0.0) {
            m_landed = true;
        } else if (m_landed) {
            if (m_liftOff < 0.0) m_liftOff = d.time;
            m_lastLiftOff = d.time;
            m_landed = false;
        }
        if (d.hasGas && (!m_leastInner || d.volume[0] < m_leastInner->volume[0])) m_leastInner = d;
    }
    readRows();
}

void LessonDock::readRows() {
    if (!m_lesson) return;
    for (const QString& key : m_keys) {
        const RunReading reading = runReading(m_lesson->id, key);
        switch (reading.kind) {
            case Reading::LiftOff:
                if (m_liftOff >= 0.0 && m_params.get(simcore::Param::Restitution) == reading.restitution)
                    setGot(key, m_liftOff, true);
                break;
            case Reading::LeastArea:
                if (m_leastInner) setGot(key, m_leastInner->volume[0], true);
                break;
            case Reading::LeastAreaPressure:
                if (m_leastInner) setGot(key, m_leastInner->pressure[0], true);
                break;
            case Reading::LeastAreaTime:
                if (m_leastInner) setGot(key, m_leastInner->time, true);
                break;
            default: break;
        }
    }
}

void LessonDock::measure() {
    if (!m_lesson || measuring()) return;
    if (m_worker.joinable()) m_worker.join();
    m_done = false;
    m_measure->setEnabled(false);
    m_measureNote->setText(tr("measuring on the parameters in use…"));
    const auto table = lessonMeasures(m_lesson->id);
    const simcore::ParameterSet params = m_params;
    QStringList keys;
    for (const QString& k : m_keys)
        if (!readFromRun(k)) keys << k;
    m_worker = std::thread([this, table, params, keys] {
        std::map<QString, double> values;
        for (const QString& k : keys)
            if (table.contains(k)) values[k] = table.value(k)(params);
        QMetaObject::invokeMethod(this, [this, values] { finishMeasure(values); }, Qt::QueuedConnection);
        m_done = true;
    });
}

void LessonDock::finishMeasure(const std::map<QString, double>& values) {
    for (const auto& [key, value] : values) setGot(key, value, false);
    m_measure->setEnabled(true);
    m_measureNote->setText(tr("measured on the parameters in use"));
}

}  // namespace elui
