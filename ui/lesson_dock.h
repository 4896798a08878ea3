#pragma once
// LessonDock: the lesson in use beside the run (the Lessons menu opens it), and the tools a
// class measures with, lesson or not.
//
//   Run until t = [T] s     runs as fast as possible and pauses at T (the lesson's own T first)
//   Stopwatch               simulated time between Start and Stop (lane 0's clock)
//   Readouts                time; each view's energy drift; the centre of mass (height, vertical
//                           speed); the layers' centres and how far the inner one sits below;
//                           the lowest point above the floor and when the body last left it;
//                           the centre's speed where it last touched down and took off (frames);
//                           the inner layer's area and pressure
//   Expected / you got      one row per answer of the lesson's text: the figure it states, and
//                           the same figure read off this run (values at the lesson's time, a
//                           failure's time, the smallest area, the lift-off) or, for figures a
//                           scan or a weightless impact gives, measured on the parameters in use
//                           by "Measure" (ui/lesson_measures.h, on a worker thread).

#include <atomic>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <thread>
#include <vector>

#include <QDockWidget>

#include "ui/frame.h"
#include "ui/lessons.h"

class QDoubleSpinBox;
class QLabel;
class QVBoxLayout;
class QPushButton;
class QTableWidget;
class QToolButton;

namespace elui {

class LessonDock : public QDockWidget {
    Q_OBJECT
public:
    explicit LessonDock(QWidget* parent = nullptr);
    ~LessonDock() override;

    // The lesson shown (nullptr: none; the tools stay).
    void setLesson(const Lesson* lesson);
    QString lessonId() const { return m_lesson ? m_lesson->id : QString(); }
    double untilTime() const;
    QDoubleSpinBox* untilBox() const { return m_until; }
    QPushButton* runUntilButton() const { return m_runUntil; }
    QToolButton* stopwatchButton() const { return m_watchButton; }
    QPushButton* measureButton() const { return m_measure; }
    QTableWidget* answerTable() const { return m_table; }
    QLabel* readout() const { return m_readout; }
    // The stopwatch's reading [s of simulated time]; running or stopped.
    double stopwatch() const;
    bool stopwatchRunning() const { return m_watchRunning; }
    // "You got" of an answer key: the value read off the run or measured (NaN: none yet), and
    // whether it came from the run (else from Measure).
    double got(const QString& key) const;
    bool gotFromRun(const QString& key) const;
    // Whether a key is read off the window's run.
    bool readFromRun(const QString& key) const;
    bool measuring() const { return m_worker.joinable() && !m_done; }

public slots:
    void showFrame(const elui::FramePtr& frame);
    void appendRows(const std::vector<simcore::Diagnostics>& history, int first, int count);
    void clearRun();  // a reset, a rebuild: a new run (the figures read so far stay until it replaces them)
    void measure();   // the lesson's figures on the parameters in use, in the background

signals:
    void runUntilRequested(double simulatedTime);

private:
    void createRunUntilRow(QWidget* host, QVBoxLayout* layout);
    void createStopwatchRow(QWidget* host, QVBoxLayout* layout);
    void createAnswers(QWidget* host, QVBoxLayout* layout);
    void fillTable();
    void readRows();  // the answers read off the rows so far
    void setGot(const QString& key, double value, bool fromRun);
    void finishMeasure(const std::map<QString, double>& values);
    void updateStopwatch();
    QStringList bodyLines(const Frame& frame);
    static QStringList worldLines(const simcore::WorldDiagnostics& d, bool flat);

    const Lesson* m_lesson = nullptr;
    QLabel* m_title = nullptr;
    QDoubleSpinBox* m_until = nullptr;
    QPushButton* m_runUntil = nullptr;
    QLabel* m_watch = nullptr;
    QToolButton* m_watchButton = nullptr;
    QToolButton* m_watchReset = nullptr;
    QLabel* m_readout = nullptr;
    QTableWidget* m_table = nullptr;
    QPushButton* m_measure = nullptr;
    QLabel* m_measureNote = nullptr;
    QLabel* m_legend = nullptr;

    QStringList m_keys;                       // the answers, in the table's order
    std::map<QString, LessonAnswer> m_expected;
    std::map<QString, std::pair<double, bool>> m_got;  // value, from the run

    // The run as read so far.
    FramePtr m_last;
    simcore::ParameterSet m_params;
    bool m_landed = false;                    // a row had wall contact
    double m_liftOff = -1.0;                  // first row in the air after a landing [s]
    double m_lastLiftOff = -1.0;              // the latest such row [s]
    std::optional<simcore::Diagnostics> m_leastInner;  // the row with the smallest inner area
    std::set<QString> m_readThisRun;          // AtTime answers read since the last reset
    FramePtr m_lastFrame;                     // the frame before (the centre's speed at a touch-down)
    bool m_lastTouching = false;
    double m_impact = -1.0, m_rebound = -1.0; // the centre's speed at the last touch-down, take-off [m/s]

    // Stopwatch on lane 0's clock.
    bool m_watchRunning = false;
    double m_watchStart = 0.0;
    double m_watchHeld = 0.0;                 // time gathered before the last start [s]

    std::thread m_worker;
    std::atomic<bool> m_done{true};
};

}  // namespace elui
