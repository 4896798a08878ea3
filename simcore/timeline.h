#pragma once
// TimelineRecorder: a run's recorded moments within a memory budget (the GUI's time travel).
//
// A moment is the state after `index` steps of the run (index 0: its start). The recorder
// keeps a checkpoint (SimulationSnapshot of every lane) every `interval` moments; any moment
// between two checkpoints is re-simulated from the one before it, which gives the original
// state bit for bit because the engine is deterministic and the snapshot holds everything a
// step reads. The caller replays what it did between steps (edits, the pointer) itself.
//
// Budget: when the checkpoints hold more bytes than the budget, every other one is dropped
// (the interval doubles), never the run's first: the whole run stays reachable, re-simulated
// from further back. A world of several bodies is recorded the same way (a WorldSnapshot per lane
// in place of the lanes' SimulationSnapshots). A lane whose integrator cannot be restored exactly (CVODE) is recorded at
// every moment instead (no re-simulation); thinned, only the moments kept remain exact.

#include <cstddef>
#include <vector>

#include "simcore/simulation.h"
#include "simcore/world.h"

namespace simcore {

struct TimelineCheckpoint {
    long index = 0;                         // the moment: steps since the timeline began
    std::vector<SimulationSnapshot> lanes;  // every lane's state at that moment
    std::vector<WorldSnapshot> worlds;      // or every world's (a scene of several bodies, one per lane)
    std::vector<double> extra;              // the caller's own state at that moment
    bool exact = true;                      // every lane can be re-simulated from here
    std::size_t bytes = 0;
};

class TimelineRecorder {
public:
    static constexpr std::size_t kDefaultBudget = std::size_t(256) << 20;  // 256 MiB
    static constexpr long kDefaultInterval = 16;

    explicit TimelineRecorder(std::size_t budgetBytes = kDefaultBudget,
                              long interval = kDefaultInterval);

    // Forgets every moment; the next record() begins the timeline.
    void clear();
    // A new budget; the checkpoints are thinned to it at once.
    void setBudget(std::size_t bytes);
    // The moment `index` has been reached (after its step; 0 at the start). Keeps a checkpoint
    // when index is a multiple of the interval, when it is the first moment, or when a lane
    // cannot be re-simulated exactly. Then thins to the budget. Returns whether it kept one.
    bool record(long index, const std::vector<const Simulation*>& lanes,
                std::vector<double> extra = {});
    // The same for a scene of several bodies (one World per lane instead of the Simulations).
    bool record(long index, const std::vector<const World*>& worlds, std::vector<double> extra = {});
    // A branch at `index`: forgets every moment after it.
    void truncateAfter(long index);
    // The checkpoint to start from for moment `index`: the latest at or before it (nullptr
    // when there is none, i.e. before the first moment).
    const TimelineCheckpoint* checkpointFor(long index) const;

    bool empty() const { return m_checkpoints.empty(); }
    long first() const { return m_checkpoints.empty() ? 0 : m_checkpoints.front().index; }
    long last() const { return m_last; }  // the newest moment reached
    std::size_t bytes() const { return m_bytes; }
    std::size_t budget() const { return m_budget; }
    long interval() const { return m_interval; }
    std::size_t checkpointCount() const { return m_checkpoints.size(); }
    int thinnings() const { return m_thinnings; }  // times every other checkpoint was dropped
    const std::vector<TimelineCheckpoint>& checkpoints() const { return m_checkpoints; }

private:
    // Starts recording moment `index`; whether a checkpoint of it is kept.
    bool keeps(long index, bool exact);
    void add(TimelineCheckpoint c);
    void thin();

    std::size_t m_budget;
    long m_baseInterval;
    long m_interval;
    std::vector<TimelineCheckpoint> m_checkpoints;  // by index, ascending
    std::size_t m_bytes = 0;
    long m_last = -1;
    int m_thinnings = 0;
};

}  // namespace simcore
