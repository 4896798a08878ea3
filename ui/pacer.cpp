#include "ui/pacer.h"

#include <chrono>

namespace elui {

double speedFactor(Speed speed) {
    switch (speed) {
        case Speed::RealTime: return 1.0;
        case Speed::Quarter: return 0.25;
        case Speed::Tenth: return 0.1;
        case Speed::AsFastAsPossible: return 0.0;
    }
    return 1.0;
}

QString speedName(Speed speed) {
    switch (speed) {
        case Speed::RealTime: return QStringLiteral("Real time");
        case Speed::Quarter: return QStringLiteral("1/4 speed");
        case Speed::Tenth: return QStringLiteral("1/10 speed");
        case Speed::AsFastAsPossible: return QStringLiteral("As fast as possible");
    }
    return {};
}

WallClock steadyWallClock() {
    return [] { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); };
}

Pacer::Pacer(WallClock clock) : m_now(std::move(clock)) { m_publishStart = m_rateStart = m_now(); }

void Pacer::start(double simTime) {
    if (!m_running) restart(simTime);
    m_running = true;
}

void Pacer::stop() {
    if (m_running) m_wallBeforeStart += since(m_clockStart);
    m_running = false;
}

void Pacer::restart(double simTime) {
    // The wall time run so far is kept; the clock then counts from here.
    if (m_running && m_clockStart >= 0.0) m_wallBeforeStart += since(m_clockStart);
    m_clockStart = m_now();
    m_clockSimStart = simTime;
    m_fallingBehind = false;
}

void Pacer::startOver(double simTime) {
    restart(simTime);
    m_wallBeforeStart = 0.0;
}

void Pacer::setSpeed(Speed speed, double simTime) {
    m_speed = speed;
    restart(simTime);
}

double Pacer::beginTick(bool toTarget) {
    m_tickStart = m_now();
    m_tickPaced = !(m_speed == Speed::AsFastAsPossible || toTarget);
    // Where the honest clock says simulated time should be now.
    m_tickTarget = m_tickPaced ? m_clockSimStart + since(m_clockStart) * speedFactor(m_speed)
                               : std::numeric_limits<double>::infinity();
    return m_tickTarget;
}

void Pacer::endTick(double simTime, bool outOfBudget) {
    if (m_tickPaced) {
        // Could not keep up: say so and restart the clock here instead of piling up debt.
        m_fallingBehind = outOfBudget && simTime < m_tickTarget;
        if (m_fallingBehind) {
            const double now = m_now();
            m_wallBeforeStart += now - m_clockStart;
            m_clockStart = now;
            m_clockSimStart = simTime;
        }
    }
    const double now = m_now(), rateWindow = now - m_rateStart;
    if (rateWindow >= kRateWindow) {
        m_stepsPerSecond = double(m_rateSteps) / rateWindow;
        m_rateSteps = 0;
        m_rateStart = now;
    }
}

bool Pacer::frameDue(bool force) {
    const double now = m_now();
    if (!force && now - m_publishStart < kPublishInterval) return false;
    m_publishStart = now;
    return true;
}

}  // namespace elui
