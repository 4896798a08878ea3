#pragma once
// RunDock: integrator, DT, precision, run/pause, single step, reset, speed, and the readout
// (simulated time, wall time, steps per second, error estimate, divergence side by side, how
// far a float run is from double).

#include <QDockWidget>
#include <QElapsedTimer>

#include "ui/frame.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QVBoxLayout;
class QFormLayout;
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
    QComboBox* precisionCombo() const { return m_precision; }

public slots:
    void showFrame(const elui::FramePtr& frame);

public:
    // Side by side: every view's time (✕ and when, for a failed one), steps, energy drift and
    // distance to the reference view (view 1, or the first live one once view 1 failed).
    static QString viewTable(const Frame& frame);
    // Precision float: the readout's rows (the precision in use, and how far the float run is
    // from double: the RMS distance to its shadow double run, or above Lanes::kShadowParticles
    // the predicted round-off eps X sqrt(n)).
    static QString floatRows(const Frame& frame);

signals:
    void integratorChosen(const QString& name);
    void dtEdited(double dt);
    void runRequested();
    void pauseRequested();
    void stepRequested();
    void resetRequested();
    void speedChosen(elui::Speed speed);
    void stepDoublingToggled(bool on);
    // Precision float chosen (true) or double; refused by the front door (simlab::precisionProblem)
    // for an integrator without a float build, with its message.
    void floatPrecisionChosen(bool on);
    void tolerancesEdited(double atol, double rtol);
    void message(const QString& text);

private:
    void showControls(const Frame& frame);
    QFormLayout* createForm(QWidget* host);
    void createButtons(QWidget* host, QVBoxLayout* layout);
    void createReadout(QWidget* host, QVBoxLayout* layout);
    void connectFields();
    void connectButtons();
    QComboBox* m_integrator = nullptr;
    QLineEdit* m_dt = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_step = nullptr;
    QPushButton* m_reset = nullptr;
    QComboBox* m_speed = nullptr;
    QComboBox* m_precision = nullptr;
    // Asks the front door whether `precision` may run with `integrator`; a refusal puts the
    // combo back to double with the message.
    bool precisionAllowed(const QString& precision, const QString& integrator);
    void choosePrecision();
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
