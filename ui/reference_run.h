#pragma once
// ReferenceRun: a converged solution of the run shown, computed beside it on a thread of its
// own, for the Plots dock's reference curve. The error band is the error each step adds; the
// distance between a curve and the reference is the error of the run so far (the global error).
//
//   GUI thread                                   reference thread
//   ──────────                                   ────────────────
//   follow(start, until) ─▶ [ mutex | target ] ─▶ rk45 at tolerance 1e-10 from `start`,
//   (every frame)                                 advanceTo(next sample) ... up to the target
//   samples() ◀── Mailbox ◀── batches of rows ◀── a row every kSampleInterval and at each target
//
// The start is the run's first state (Frame::runStart: lane 0 when the timeline began, after
// the start kick); the target is the run's newest time, capped at the first change of the
// physics (Frame::physicsChangedAt: a parameter edit other than DT, or a drag), after which
// the run and the reference no longer solve the same problem. A new start (a reset, a new
// scene, an opened file) restarts it; the integrator, DT and the tolerances of the run do not
// matter (the exact solution is theirs too). The reference stops at its own failure (a body
// that collapses at every step size) and says so.

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include <QObject>

#include "simcore/simulation.h"

namespace elui {

class Mailbox;

class ReferenceRun : public QObject {
    Q_OBJECT
public:
    static constexpr double kTolerance = 1e-10;       // rk45's atol [m, m/s] and rtol
    static constexpr double kSampleInterval = 0.005;  // a row at least this often [s]

    explicit ReferenceRun(QObject* parent = nullptr);
    ~ReferenceRun() override;  // cancels and joins

    // Follow the run that began at `start` up to simulated time `until` (cheap when neither
    // changed; a new start restarts from it). A null start stops and forgets.
    void follow(const std::shared_ptr<const simcore::SimulationSnapshot>& start, double until);
    void stop();

    bool active() const { return m_start != nullptr; }
    // The rows computed so far (GUI thread), in time order.
    const std::vector<simcore::Diagnostics>& samples() const { return m_samples; }
    // The reference's own failure, if it failed.
    const std::optional<simcore::Failure>& failure() const { return m_failure; }
    double target() const { return m_target; }

signals:
    void restarted();                          // samples() was emptied
    void samplesAppended(int first, int count);
    void failed();

private:
    struct Shared {
        std::mutex mutex;
        std::condition_variable wake;
        double target = 0.0;
        bool cancel = false;
    };
    void work(simcore::SimulationSnapshot start, std::shared_ptr<Shared> shared, quint64 serial);

    Mailbox* m_mailbox = nullptr;
    std::shared_ptr<const simcore::SimulationSnapshot> m_start;
    std::shared_ptr<Shared> m_shared;
    std::thread m_thread;
    quint64 m_serial = 0;  // results of an older start are dropped
    double m_target = 0.0;
    std::vector<simcore::Diagnostics> m_samples;
    std::optional<simcore::Failure> m_failure;
};

}  // namespace elui
