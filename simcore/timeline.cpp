#include "simcore/timeline.h"

#include <algorithm>

namespace simcore {

TimelineRecorder::TimelineRecorder(std::size_t budgetBytes, long interval)
    : m_budget(budgetBytes), m_baseInterval(std::max(1L, interval)), m_interval(m_baseInterval) {}

void TimelineRecorder::clear() {
    m_checkpoints.clear();
    m_bytes = 0;
    m_last = -1;
    m_interval = m_baseInterval;
    m_thinnings = 0;
}

void TimelineRecorder::setBudget(std::size_t bytes) {
    m_budget = bytes;
    if (m_bytes > m_budget) thin();
}

bool TimelineRecorder::keeps(long index, bool exact) {
    if (index <= m_last && !m_checkpoints.empty()) truncateAfter(index - 1);
    m_last = index;
    return m_checkpoints.empty() || index % m_interval == 0 || !exact ||
           !m_checkpoints.back().exact;  // re-simulation starts from an exact state
}

void TimelineRecorder::add(TimelineCheckpoint c) {
    m_bytes += c.bytes;
    m_checkpoints.push_back(std::move(c));
    if (m_bytes > m_budget) thin();
}

bool TimelineRecorder::record(long index, const std::vector<const Simulation*>& lanes,
                              std::vector<double> extra) {
    bool exact = true;
    for (const Simulation* sim : lanes) exact = exact && sim->integrator().restorable();
    if (!keeps(index, exact)) return false;
    TimelineCheckpoint c;
    c.index = index;
    c.exact = exact;
    c.extra = std::move(extra);
    c.lanes.reserve(lanes.size());
    c.bytes = sizeof(TimelineCheckpoint) + sizeof(double) * c.extra.capacity();
    for (const Simulation* sim : lanes) {
        c.lanes.push_back(sim->snapshot());
        c.bytes += c.lanes.back().bytes();
    }
    add(std::move(c));
    return true;
}

bool TimelineRecorder::record(long index, const std::vector<const World*>& worlds, std::vector<double> extra) {
    bool exact = true;
    for (const World* world : worlds) exact = exact && world->integrator().restorable();
    if (!keeps(index, exact)) return false;
    TimelineCheckpoint c;
    c.index = index;
    c.exact = exact;
    c.extra = std::move(extra);
    c.worlds.reserve(worlds.size());
    c.bytes = sizeof(TimelineCheckpoint) + sizeof(double) * c.extra.capacity();
    for (const World* world : worlds) {
        c.worlds.push_back(world->snapshot());
        c.bytes += c.worlds.back().bytes();
    }
    add(std::move(c));
    return true;
}

void TimelineRecorder::thin() {
    // Every other checkpoint goes (the interval doubles), the first always stays; again
    // while still over the budget and there is anything left to drop.
    while (m_bytes > m_budget && m_checkpoints.size() > 1) {
        m_interval *= 2;
        ++m_thinnings;
        std::vector<TimelineCheckpoint> kept;
        kept.reserve(m_checkpoints.size() / 2 + 1);
        m_bytes = 0;
        for (std::size_t i = 0; i < m_checkpoints.size(); ++i) {
            TimelineCheckpoint& c = m_checkpoints[i];
            if (i == 0 || c.index % m_interval == 0) {
                m_bytes += c.bytes;
                kept.push_back(std::move(c));
            }
        }
        m_checkpoints = std::move(kept);
    }
}

void TimelineRecorder::truncateAfter(long index) {
    while (!m_checkpoints.empty() && m_checkpoints.back().index > index) {
        m_bytes -= m_checkpoints.back().bytes;
        m_checkpoints.pop_back();
    }
    m_last = std::min(m_last, index);
}

const TimelineCheckpoint* TimelineRecorder::checkpointFor(long index) const {
    auto it = std::upper_bound(m_checkpoints.begin(), m_checkpoints.end(), index,
                               [](long i, const TimelineCheckpoint& c) { return i < c.index; });
    if (it == m_checkpoints.begin()) return nullptr;
    return &*(it - 1);
}

}  // namespace simcore
