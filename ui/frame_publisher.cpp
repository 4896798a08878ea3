#include "ui/frame_publisher.h"

namespace elui {

void FramePublisher::recordRow(simcore::Simulation& lane0, bool errorBands) {
    if (lane0.failed()) return;
    const double t = lane0.time();
    if (m_lastRowTime >= 0.0 && t - m_lastRowTime < kRowInterval * (1.0 - 1e-9)) return;
    m_lastRowTime = t;
    m_rows.push_back(lane0.diagnostics());
    // The plots' error bands (two measurements per row, only for steps with an estimate and
    // while the plots show them).
    if (errorBands) m_rows.back().errors = lane0.observableErrors();
}

void FramePublisher::recordRow(const simcore::Diagnostics& row) {
    if (m_lastRowTime >= 0.0 && row.time - m_lastRowTime < kRowInterval * (1.0 - 1e-9)) return;
    m_lastRowTime = row.time;
    m_rows.push_back(row);
}

void FramePublisher::recordLaneRows(const std::vector<const simcore::Simulation*>& lanes, double time) {
    std::vector<const simcore::Diagnostics*> rows;
    for (const simcore::Simulation* lane : lanes) rows.push_back(lane->failed() ? nullptr : &lane->diagnostics());
    recordLaneRows(rows, time);
}

void FramePublisher::recordLaneRows(const std::vector<const simcore::Diagnostics*>& rows, double time) {
    if (m_lastLaneRowTime >= 0.0 && time - m_lastLaneRowTime < kRowInterval * (1.0 - 1e-9)) return;
    m_lastLaneRowTime = time;
    if (m_laneRows.size() < rows.size() - 1) m_laneRows.resize(rows.size() - 1);
    for (std::size_t i = 1; i < rows.size(); ++i)
        if (rows[i]) m_laneRows[i - 1].push_back(*rows[i]);
}

void FramePublisher::startHistory() {
    m_lastRowTime = -1.0;
    m_lastLaneRowTime = -1.0;
    m_laneRows.clear();
    m_rows.clear();
    m_historyReset = true;
}

void FramePublisher::branch(double time) {
    m_branches.push_back({m_rows.size(), time});
    m_lastRowTime = -1.0;  // the branch's rows start at once
    m_lastLaneRowTime = -1.0;
}

void FramePublisher::publish(std::shared_ptr<Frame> frame) {
    frame->serial = ++m_serial;
    std::lock_guard lock(m_slotMutex);
    m_slot.frame = std::move(frame);
    if (m_historyReset) {
        // Rows not yet taken from before the reset belong to the old history: drop them.
        m_slot.rows.clear();
        m_slot.laneRows.clear();
        m_slot.historyReset = true;
        m_slot.branches.clear();
        m_historyReset = false;
    }
    for (FrameBatch::Branch b : m_branches) {
        b.rowsBefore += m_slot.rows.size();
        m_slot.branches.push_back(b);
    }
    m_branches.clear();
    m_slot.rows.insert(m_slot.rows.end(), m_rows.begin(), m_rows.end());
    m_rows.clear();
    if (m_slot.laneRows.size() < m_laneRows.size()) m_slot.laneRows.resize(m_laneRows.size());
    for (std::size_t i = 0; i < m_laneRows.size(); ++i) {
        m_slot.laneRows[i].insert(m_slot.laneRows[i].end(), m_laneRows[i].begin(), m_laneRows[i].end());
        m_laneRows[i].clear();
    }
    m_published.store(m_slot.frame->serial);
    if (!m_slotPending) {
        m_slotPending = true;
        m_announce();
    }
}

void FramePublisher::clear() {
    m_rows = {};
    m_laneRows = {};
    m_branches = {};
    std::lock_guard lock(m_slotMutex);
    m_slot = FrameBatch{};
}

FrameBatch FramePublisher::takeBatch() {
    std::lock_guard lock(m_slotMutex);
    FrameBatch out = std::move(m_slot);
    m_slot = FrameBatch{};
    m_slotPending = false;
    return out;
}

}  // namespace elui
