#pragma once
// FramePublisher: what the worker hands to the GUI thread (see frame.h and sim_worker.h).
//
// It keeps lane 0's time-series rows recorded since the last publish (at most one per
// kRowInterval of simulated time), the branch marks and the history-reset flag made since
// then, and the one-batch slot the GUI takes from: publish() moves a frame and those rows into
// the slot (the newest frame replaces one not yet taken, the rows add up), takeBatch() empties
// it. The slot is guarded by a mutex; everything else is the worker thread's. SimWorker
// records and publishes; SimulationController takes, from the GUI thread.

#include <atomic>
#include <functional>
#include <mutex>
#include <vector>

#include "ui/frame.h"

namespace elui {

class FramePublisher {
public:
    // Smallest simulated interval between two recorded time-series rows [s].
    static constexpr double kRowInterval = 1e-3;

    // `announce` is called (on the worker thread, under the slot's lock) when a frame lands in
    // an empty slot: once per take.
    explicit FramePublisher(std::function<void()> announce) : m_announce(std::move(announce)) {}

    // --- worker thread ---
    // Records lane 0's row now, unless it failed or the last row is less than kRowInterval
    // ago; with its error bands (two measurements) when `errorBands`.
    void recordRow(simcore::Simulation& lane0, bool errorBands);
    // A world's row (its totals as a Diagnostics), as recordRow.
    void recordRow(const simcore::Diagnostics& row);
    // Side by side: every other live lane's row at the common time `time` (at most one per
    // kRowInterval of it), for the plots' other views.
    void recordLaneRows(const std::vector<const simcore::Simulation*>& lanes, double time);
    // The same from each lane's row (lane 0's first; nullptr for a failed lane): a world's totals.
    void recordLaneRows(const std::vector<const simcore::Diagnostics*>& rows, double time);
    // A new history begins: the rows not yet published are dropped, and the next batch tells
    // the GUI to clear (dropping the rows not yet taken too).
    void startHistory();
    // The run branches off at lane 0's simulated time `time`: the rows recorded since are
    // the branch's, and its first row is recorded at once.
    void branch(double time);
    void clearBranches() { m_branches.clear(); }
    // Numbers the frame and moves it, with the rows and marks since the last publish, into
    // the slot.
    void publish(std::shared_ptr<Frame> frame);
    // Drops everything (the worker's shutdown).
    void clear();

    // --- any thread ---
    // The newest frame and the rows recorded since the last take.
    FrameBatch takeBatch();
    // The serial number of the newest frame published (0: none yet).
    quint64 publishedSerial() const { return m_published.load(); }

private:
    std::function<void()> m_announce;
    std::vector<simcore::Diagnostics> m_rows;  // recorded since the last publish
    std::vector<std::vector<simcore::Diagnostics>> m_laneRows;  // lanes 1.. since the last publish
    double m_lastLaneRowTime = -1.0;      // the common time at the last lane rows, < 0: none [s]
    double m_lastRowTime = -1.0;          // lane 0's time at the last row, < 0: none yet [s]
    bool m_historyReset = true;           // a new history began since the last publish
    std::vector<FrameBatch::Branch> m_branches;  // since the last publish
    quint64 m_serial = 0;                 // the last frame's number
    std::atomic<quint64> m_published{0};

    std::mutex m_slotMutex;               // guards the two fields below
    FrameBatch m_slot;
    bool m_slotPending = false;           // announced and not yet taken
};

}  // namespace elui
