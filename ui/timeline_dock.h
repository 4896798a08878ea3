#pragma once
// TimelineDock: time travel under the view. A slider over the run's recorded moments, buttons
// for the start, one step back and the newest moment (Home, Shift+S, End), what is kept, and
// Clear for the abandoned future a branch leaves in the plots.
//
// Dragging the slider asks the worker for a moment (SimulationController::scrubTo, which pauses);
// the frame that comes back moves the view, the readout and the plots' cursor together. Any
// change made there (integrator, DT, a parameter, the mouse) and Run or Step branch the run
// from that instant.

#include <QDockWidget>

#include "ui/frame.h"

class QLabel;
class QPushButton;
class QSlider;

namespace elui {

class TimelineDock : public QDockWidget {
    Q_OBJECT
public:
    explicit TimelineDock(QWidget* parent = nullptr);
    QSlider* slider() const { return m_slider; }
    QLabel* info() const { return m_info; }
    QPushButton* clearButton() const { return m_clear; }

public slots:
    void showFrame(const elui::FramePtr& frame);
    void setAbandoned(bool present);

signals:
    void scrubRequested(long moment);
    void stepBackRequested();
    void startRequested();
    void endRequested();
    void clearAbandonedRequested();

private:
    QSlider* m_slider = nullptr;
    QPushButton* m_start = nullptr;
    QPushButton* m_back = nullptr;
    QPushButton* m_end = nullptr;
    QPushButton* m_clear = nullptr;
    QLabel* m_info = nullptr;
    QLabel* m_where = nullptr;
    bool m_updating = false;
};

// "12.3 MiB" and the like.
QString byteText(std::size_t bytes);

}  // namespace elui
