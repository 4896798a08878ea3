#pragma once
// Waiting in tests: on a condition, never on the wall clock.
//
// A test never decides pass or fail by how long something took. It waits until a condition
// holds, and the only limit is a guard against a hang: far beyond any honest run, scaled by
// what the build costs (ThreadSanitizer runs the suite 5-15x slower, ASan 2-4x), so a busy or
// slow machine makes a test slower, never red. docs/reliability.md ("Waiting in tests").
#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QThread>

namespace testsupport {

// How many times slower than Release this build may run, at worst.
#if defined(__SANITIZE_THREAD__)
inline constexpr int kBuildSlowdown = 10;
#elif defined(__SANITIZE_ADDRESS__)
inline constexpr int kBuildSlowdown = 4;
#else
inline constexpr int kBuildSlowdown = 1;
#endif

// The hang guard: a wait this long means the code hung (a lost wake-up, a dead lock, a run
// that never ends). Every wait in the suite is well under a second in Release on an idle machine.
inline constexpr int kHangGuardMs = 60'000 * kBuildSlowdown;

// Processes this thread's events until pred() holds; false only when the hang guard is reached.
template <class Pred>
bool waitUntil(Pred pred) {
    QElapsedTimer guard;
    guard.start();
    while (!pred()) {
        if (guard.elapsed() > kHangGuardMs) return pred();
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
        if (!pred()) QThread::msleep(1);
    }
    return true;
}

// Waits for a child process to end; false only when the hang guard is reached.
inline bool waitForExit(QProcess& p) { return p.waitForFinished(kHangGuardMs); }

}  // namespace testsupport
