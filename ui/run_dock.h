#pragma once
// RunDock: integrator, DT, run/pause, single step, reset, speed, and the readout
// (simulated time, wall time, steps per second, error estimate, divergence side by side).

#include <QDockWidget>
#include <QElapsedTimer>

#include "ui/frame.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace elui {

class RunDock : public QDockWidget {
    Q_OBJECT
public:
    explicit RunDock(QWidget* parent = nullptr);
    QPushButton* runButton() const { return m_run; }
    QComboBox* integratorCombo() const { return m_integrator; }
    QLabel* readout() const { return m_readout; }
    QLineEdit* dtEdit() const { return m_dt; }

public slots:
    void showFrame(const elui::FramePtr& frame);

public:
    // Side by side: every view's time (✕ and when, for a failed one), steps, energy drift and
    // distance to the reference view (view 1, or the first live one once view 1 failed).
    static QString viewTable(const Frame& frame);

signals:
    void integratorChosen(const QString& name);
    void dtEdited(double dt);
    void runRequested();
    void pauseRequested();
    void stepRequested();
    void resetRequested();
    void speedChosen(elui::Speed speed);
    void stepDoublingToggled(bool on);
    void tolerancesEdited(double atol, double rtol);
    void message(const QString& text);

private:
    QComboBox* m_integrator = nullptr;
    QLineEdit* m_dt = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_step = nullptr;
    QPushButton* m_reset = nullptr;
    QComboBox* m_speed = nullptr;
    QCheckBox* m_doubling = nullptr;
    QLabel* m_readout = nullptr;
    bool m_running = false;
    bool m_updating = false;
    double m_shownDt = -1.0;  // the DT in use (the last frame's)
    QString m_dtTip;
    QLineEdit* m_rtol = nullptr;
    QLineEdit* m_atol = nullptr;
    double m_shownAtol = -1.0, m_shownRtol = -1.0;  // the tolerances in use
    QString m_tolTip;
    QElapsedTimer m_lastReadout;
};

}  // namespace elui
