#pragma once
// FailureBanner: the red banner over the view when the run blew up, and what to do about it.
//
//   ┌───────────────────────────────────────────────────────────────────────────────┐
//   │ The simulation blew up at t = 0.912 s (step 913): the inner layer collapsed …  │
//   │ The body itself collapses — no step size will save it: run again from …        │
//   │                                   [Use DT = 0.0025 s and reset] [Use implicit…] [Reset] │
//   └───────────────────────────────────────────────────────────────────────────────┘
//
// Numerics or physics: when a lane fails, the banner re-runs the failed stretch (from the
// lane's recorded state some time before the failure, LaneFrame::stretchStart) at a quarter
// of the step - no more than 0.9 of the method's verdict limit - on a std::thread
// (simlab::checkFailure), and says which it was. A failure the smaller step survives was the
// step's: the banner offers the step that ran through and implicit Euler. One it does not
// survive is the body's own: "the body itself collapses — no step size will save it", with
// the body's remedies in words and Reset alone (no DT button). Until the check ends it says
// it is checking. The text is laid out in lines across the view, the buttons in a row under
// it (it never widens the window). The result comes back through a Mailbox (mailbox.h).

#include <atomic>
#include <memory>
#include <optional>
#include <thread>

#include <QFrame>

#include "ui/frame.h"
#include "simlab/stability.h"

class QLabel;
class QPushButton;

namespace elui {

class Mailbox;

class FailureBanner : public QFrame {
    Q_OBJECT
public:
    explicit FailureBanner(QWidget* parent = nullptr);
    ~FailureBanner() override;  // cancels and joins the check

    // Shown while the single view's lane has failed (side by side a view fails alone: its
    // title and curves say so); hidden otherwise. Cheap with every frame.
    void showFrame(const Frame& frame);

    QString text() const;                 // the banner's text (rich text), empty when hidden
    bool checking() const { return m_checking; }
    // The check's outcome for the failure shown (none while checking or without a stretch).
    const std::optional<simlab::FailureCheck>& check() const { return m_check; }
    QPushButton* smallerDtButton() const { return m_smaller; }
    QPushButton* implicitButton() const { return m_implicit; }
    QPushButton* resetButton() const { return m_reset; }
    QLabel* label() const { return m_text; }

signals:
    void setDtAndReset(double dt);
    void useImplicitAndReset();
    void resetRequested();

private:
    void startCheck(const simcore::SimulationSnapshot& start, const simcore::Failure& failure);
    void stopCheck();
    void present();

    QLabel* m_text = nullptr;
    QPushButton* m_smaller = nullptr;
    QPushButton* m_implicit = nullptr;
    QPushButton* m_reset = nullptr;
    Mailbox* m_fromCheck = nullptr;

    bool m_shown = false;
    long m_failureStep = -1;
    simcore::Failure m_failure;
    QString m_integrator;
    double m_dt = 0.0;
    std::optional<simlab::FailureCheck> m_check;
    bool m_checking = false;
    std::thread m_thread;
    std::shared_ptr<std::atomic<bool>> m_cancel;
    quint64 m_checkSerial = 0;            // which check a result belongs to
};

}  // namespace elui
