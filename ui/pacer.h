#pragma once
// Pacer: how fast the worker's run goes, measured on the wall (see sim_worker.h).
//
// It owns the wall clock and everything read off it: whether the run is going, its speed (real
// time, a fraction of it, or as fast as possible), the clock's origin (the wall time and the
// simulated time of the last (re)start), how far simulated time should have come by the end of
// a tick, the tick's wall budget, the falling-behind flag, the steps-per-second meter and
// whether a frame is due. It never steps anything: SimWorker asks it where simulated time
// should be, steps the lanes there itself and tells it where they got. Pure logic, no Qt
// object and no thread of its own (the worker's thread reads it); a test drives it with a
// clock it moves by hand.
//
//   start/restart ──▶ beginTick ──▶ (the worker steps: countStep, budgetSpent) ──▶ endTick
//                      target         per step                                   behind? rate

#include <functional>
#include <limits>

#include "ui/frame.h"

namespace elui {

// Monotonic wall time in seconds. The worker reads the wall only through this: its pacing
// (real time, a fraction of it), the tick budget, the frame rate and the steps-per-second
// meter. The default is std::chrono::steady_clock; a test passes a clock it moves itself.
using WallClock = std::function<double()>;
WallClock steadyWallClock();

class Pacer {
public:
    // Per tick, stepping stops after this much wall time so commands and frames keep flowing [s].
    static constexpr double kTickBudget = 0.015;
    // Frames are published at most this often while running [s] (the screen cannot show more).
    static constexpr double kPublishInterval = 1.0 / 90.0;
    // The steps-per-second meter averages over at least this much wall time [s].
    static constexpr double kRateWindow = 0.5;

    explicit Pacer(WallClock clock);

    bool running() const { return m_running; }
    Speed speed() const { return m_speed; }
    // The worker's timer interval for this speed [ms]: 0 (as often as possible) when not paced.
    int timerInterval() const { return m_speed == Speed::AsFastAsPossible ? 0 : 4; }

    // Starts counting from simulated time `simTime` (nothing when already running).
    void start(double simTime);
    // Stops counting; the wall time run so far is kept.
    void stop();
    // The clock counts from here and from simulated time `simTime` (the wall time run so far is
    // kept); forgives falling behind.
    void restart(double simTime);
    // Back at the start of a history: restart, and no wall time run yet.
    void startOver(double simTime);
    // A new speed counts from here and from simulated time `simTime`.
    void setSpeed(Speed speed, double simTime);

    // --- one tick (the worker's timer) ---
    // Starts the tick's budget; returns where simulated time should be by its end [s]: where the
    // clock says (its origin plus the wall time since, times the speed factor), or +infinity
    // when not paced (as fast as possible, or running until a target time).
    double beginTick(bool toTarget);
    // Whether this tick has stepped longer than kTickBudget.
    bool budgetSpent() const { return since(m_tickStart) > kTickBudget; }
    // One step taken (the meter's count).
    void countStep() { ++m_rateSteps; }
    // Ends the tick with the lanes at simulated time `simTime`, having stopped early for the
    // budget (outOfBudget) or not. Paced and short of the target after a spent budget means
    // the machine cannot keep up: falling behind, and the clock restarts here instead of
    // piling up a debt it would later rush through. Then the meter's window closes if due.
    void endTick(double simTime, bool outOfBudget);

    bool fallingBehind() const { return m_fallingBehind; }
    // Steps counted per wall second over the last closed window, at least kRateWindow long
    // (0 while paused).
    double stepsPerSecond() const { return m_running ? m_stepsPerSecond : 0.0; }

    // Whether a frame is due now: always when forced, otherwise once kPublishInterval has
    // passed since the last one. A yes restarts the interval and dates wallSeconds().
    bool frameDue(bool force);
    // The wall time run so far, as of the last frame due [s].
    double wallSeconds() const { return m_wallBeforeStart + (m_running ? m_publishStart - m_clockStart : 0.0); }

private:
    double since(double wallStart) const { return m_now() - wallStart; }

    WallClock m_now;
    bool m_running = false;
    Speed m_speed = Speed::RealTime;
    double m_clockStart = -1.0;           // wall time of the last (re)start, < 0: never started [s]
    double m_clockSimStart = 0.0;         // simulated time at the last (re)start [s]
    double m_wallBeforeStart = 0.0;       // wall time run before the last start [s]
    bool m_fallingBehind = false;
    double m_tickStart = 0.0;             // wall time the current tick began [s]
    bool m_tickPaced = false;             // the current tick follows the clock
    double m_tickTarget = 0.0;            // where the current tick should bring simulated time [s]
    double m_rateStart = 0.0;             // wall time the meter's window opened [s]
    long m_rateSteps = 0;                 // steps counted in the open window
    double m_stepsPerSecond = 0.0;        // the last closed window's rate [1/s]
    double m_publishStart = 0.0;          // wall time of the last frame due [s]
};

}  // namespace elui
