// Threads follow the CPUs the process may use (affinity mask, cgroup CPU quota), and the pool
// hands work to whichever thread is free (simcore/parallel.h).
#include <pthread.h>
#include <sched.h>

#include <QtTest>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <thread>
#include <vector>

#include "simcore/float_path.h"
#include "simcore/parallel.h"
#include "simcore/simulation.h"

using namespace simcore;

namespace {
// The test hooks' state (ThreadPool::setTestHook takes a plain function).
std::atomic<ThreadPool*> g_pool{nullptr};
std::atomic<int> g_workerIn{0};
std::atomic<int> g_workerTasks{0};
std::atomic<int> g_stallEvery{0};
// Whether this thread is one of a pool's workers (the pool's threads set it through the hook).
thread_local bool g_inWorker = false;
void markWorker(int, bool worker) { g_inWorker = worker; }

// A worker stalled in the middle of a run, as a preempted one is: every g_stallEvery-th task a
// worker takes sleeps 300 us before it runs (longer than most tasks here), so the caller finishes
// its own tasks first, waits, sleeps, and the fallback may send it on alone.
void stallSomeWorkerTasks(int, bool worker) {
    if (!worker) return;
    const int k = g_workerTasks.fetch_add(1, std::memory_order_relaxed);
    const int every = g_stallEvery.load(std::memory_order_relaxed);
    if (every > 0 && k % every == 0) std::this_thread::sleep_for(std::chrono::microseconds(300));
}

// Caller and worker in one run of two tasks, the worker's task held until the caller sleeps:
// the caller's task 0 waits for the worker to take task 1; the worker's task waits until the
// caller announces its sleep (all its tasks done), then lingers so that it really sleeps.
void holdWorkerUntilCallerSleeps(int task, bool worker) {
    if (!worker) {
        if (task == 0)
            while (g_workerIn.load(std::memory_order_acquire) == 0) std::this_thread::yield();
        return;
    }
    g_workerIn.store(1, std::memory_order_release);
    while (!g_pool.load(std::memory_order_acquire)->callerSleeping()) std::this_thread::yield();
    std::this_thread::sleep_for(std::chrono::microseconds(200));
    g_workerTasks.fetch_add(1, std::memory_order_relaxed);
}

// The caller's task 0 waits until a worker has taken a task (so a sleeping worker must wake).
void callerWaitsForWorker(int task, bool worker) {
    if (worker) {
        g_workerIn.store(1, std::memory_order_release);
        g_workerTasks.fetch_add(1, std::memory_order_relaxed);
    } else if (task == 0) {
        while (g_workerIn.load(std::memory_order_acquire) == 0) std::this_thread::yield();
    }
}

// What the pool's threads take for their CPU (ThreadPool::setCpuHooks): the caller one CPU, the
// workers either the same or another; moving off a CPU and onto the caller's counted, and
// granted or refused.
std::atomic<std::thread::id> g_callerId{};
std::atomic<bool> g_workersOnCallersCpu{true}, g_moveGranted{true};
std::atomic<int> g_moveCalls{0}, g_joinCalls{0};
std::atomic<int> g_runnable{2};  // the caller and the worker: the other CPU idle
int fakeCurrentCpu() {
    if (std::this_thread::get_id() == g_callerId.load()) return 5;
    return g_workersOnCallersCpu.load() ? 5 : 6;
}
int fakeMoveOffCpu(int cpu) {
    g_moveCalls.fetch_add(1);
    return g_moveGranted.load() && cpu == 5 ? 7 : -1;
}
int fakeMoveOntoCpu(int cpu) {
    g_joinCalls.fetch_add(1);
    return g_moveGranted.load() && cpu == 5 ? 5 : -1;
}
// With g_flicker, every other reading says the other CPUs are idle (a kernel thread's moment).
std::atomic<bool> g_flicker{false};
std::atomic<int> g_runnableReads{0};
int fakeRunnable() { return g_flicker.load() && g_runnableReads.fetch_add(1) % 2 == 1 ? 2 : g_runnable.load(); }
// The workers' CPU clock: frozen while g_keptOff (a thread kept off its CPU all the time it is
// awake), else running with the wall clock (never kept off); the caller's is its own.
// With g_lightlyKeptOff, kept off 0.75 ms of every 5 ms (15 %: a program at a lower weight takes
// its shortest slices): one 2 ms check in three finds it kept off, a 20 ms span does not.
std::atomic<bool> g_keptOff{false}, g_lightlyKeptOff{false};
double fakeThreadCpu() {
    if (std::this_thread::get_id() == g_callerId.load()) return threadCpuSeconds();
    if (g_keptOff.load()) return 1.0;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    if (!g_lightlyKeptOff.load()) return wall;
    const double period = 0.005, off = 0.00075;
    const double periods = std::floor(wall / period);
    return periods * (period - off) + std::max(0.0, wall - periods * period - off);
}
constexpr ThreadPool::CpuHooks kFakeCpus{fakeCurrentCpu, fakeMoveOffCpu, fakeMoveOntoCpu, fakeRunnable, fakeThreadCpu,
                                         nullptr};
// CPU clocks for the share judge (ShareJudge): each thread of the pool gets g_shareTogether of a
// CPU while the pool runs together, the caller g_shareAlone while it runs alone (a host that
// runs two virtual CPUs on about one core); a reading's interval counts as alone when the pool
// ran a run alone in it. The workers' own clocks (their kept-off checks) follow the wall clock.
std::atomic<const ThreadPool*> g_sharePool{nullptr};
std::atomic<double> g_shareTogether{0.35}, g_shareAlone{0.9};
struct FakeShareClock {
    double wallAt = -1.0, cpu = 0.0;
    std::uint64_t soloAt = 0;
    double read(double togetherRate, double aloneRate) {
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
        const std::uint64_t solo = g_sharePool.load()->counters().soloRuns;
        if (wallAt >= 0.0) cpu += (wall - wallAt) * (solo != soloAt ? aloneRate : togetherRate);
        wallAt = wall;
        soloAt = solo;
        return cpu;
    }
};
FakeShareClock g_callerShareClock, g_workersShareClock;  // read by the caller only
double shareThreadCpu() {
    if (std::this_thread::get_id() != g_callerId.load())
        return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    return g_callerShareClock.read(g_shareTogether.load(), g_shareAlone.load());
}
double shareWorkersCpu(const ThreadPool&) { return g_workersShareClock.read(g_shareTogether.load(), 0.0); }
constexpr ThreadPool::CpuHooks kShareCpus{fakeCurrentCpu, fakeMoveOffCpu, fakeMoveOntoCpu, fakeRunnable, shareThreadCpu,
                                          shareWorkersCpu};
// One run of eight tasks of 20 us each (spinning: the threads stay awake).
void spinRun(ThreadPool& pool) {
    pool.run(8, [](int) {
        const auto end = std::chrono::steady_clock::now() + std::chrono::microseconds(20);
        while (std::chrono::steady_clock::now() < end) {}
    });
}
struct CpuHooksGuard {
    CpuHooksGuard() { ThreadPool::setCpuHooks(&kFakeCpus); }
    ~CpuHooksGuard() { ThreadPool::setCpuHooks(nullptr); }
};

struct HookGuard {
    explicit HookGuard(ThreadPool::TestHook hook) { ThreadPool::setTestHook(hook); }
    ~HookGuard() { ThreadPool::setTestHook(nullptr); }
};

ParameterSet level4Sphere() {
    ParameterSet p(SceneKind::Sphere3d);
    p.set(Param::Subdivisions, 4);
    p.set(Param::Gravity, 0.0);
    p.set(Param::Perturb, 0.02);
    p.set(Param::Scaling, 1.0);  // the thesis's per-particle body, as bench runs it
    return p;
}
}  // namespace

class TestThreads : public QObject {
    Q_OBJECT
private slots:
    void quotaIsReadFromCpuMax() {
        QCOMPARE(quotaThreads("max 100000"), 0);
        QCOMPARE(quotaThreads("max 100000\n"), 0);
        QCOMPARE(quotaThreads("100000 100000"), 1);
        QCOMPARE(quotaThreads("150000 100000\n"), 2);
        QCOMPARE(quotaThreads("50000 100000"), 1);
        QCOMPARE(quotaThreads("400000 100000"), 4);
        QCOMPARE(quotaThreads(""), 0);
        QCOMPARE(quotaThreads("garbage"), 0);
        QCOMPARE(quotaThreads("-1 100000"), 0);  // cgroup v1's "no quota"
        QCOMPARE(quotaThreads("100000 0"), 0);
    }

    void defaultThreadsAreTheCpusWeMayUse() {
        cpu_set_t set;
        CPU_ZERO(&set);
        QCOMPARE(sched_getaffinity(0, sizeof set, &set), 0);
        const int mask = CPU_COUNT(&set);
        QVERIFY(availableThreads() >= 1);
        QVERIFY(availableThreads() <= mask);
        // CTest runs this test a second time under `taskset -c 0` with this variable set.
        if (const QByteArray expected = qgetenv("ELASTIC_LAB_EXPECT_CPUS"); !expected.isEmpty()) {
            QCOMPARE(mask, expected.toInt());
            QCOMPARE(availableThreads(), expected.toInt());
        }
        // A body split in chunks (a level-4 sphere) uses as many threads as it may, up to its
        // chunks.
        ParameterSet sphere(SceneKind::Sphere3d);
        QVERIFY(!sphere.set(Param::Subdivisions, 4));
        Simulation sim(sphere, "rk4");
        QCOMPARE(sim.threads(), std::min(availableThreads(), sim.forces().chunks()));
        QCOMPARE(sim.forces().chunks(), 2);
    }

    void everyTaskRunsOnceWhoeverTakesIt() {
        // Many short runs of varying size: each task exactly once per run, whatever thread
        // (the caller or a worker that turns up late) claims it. Under `taskset -c 0` the
        // worker shares the caller's CPU, so it is often not there when a run begins.
        ThreadPool pool(2);
        QCOMPARE(pool.threads(), 2);
        std::vector<std::atomic<int>> hits(64);
        for (int run = 0; run < 20000; ++run) {
            const int count = 1 + run % 64;
            for (int i = 0; i < count; ++i) hits[static_cast<std::size_t>(i)].store(0, std::memory_order_relaxed);
            pool.run(count, [&](int i) { hits[static_cast<std::size_t>(i)].fetch_add(1, std::memory_order_relaxed); });
            for (int i = 0; i < count; ++i)
                if (hits[static_cast<std::size_t>(i)].load(std::memory_order_relaxed) != 1)
                    QFAIL(qPrintable(QStringLiteral("run %1: task %2 ran %3 times").arg(run).arg(i).arg(hits[static_cast<std::size_t>(i)].load())));
        }
    }

    // The caller claims tasks from the front and the worker from the back: in every run the
    // caller's tasks are 0..k-1 and the worker's k..n-1, so each thread meets the same chunks
    // run after run (its cache keeps their data). Tasks of 20 us, eight per run, so that both
    // take part; a run of more tasks than a ticket counts (65,535) runs each once too.
    void callerTakesTheFrontWorkerTheBack() {
        ThreadPool pool(2);
        pool.setRunAloneAllowed(false);
        HookGuard hook(markWorker);
        constexpr int kTasks = 8;
        std::array<std::atomic<int>, kTasks> byWorker{};
        int workerRuns = 0;
        for (int run = 0; run < 2000; ++run) {
            for (auto& w : byWorker) w.store(-1, std::memory_order_relaxed);
            pool.run(kTasks, [&](int i) {
                const auto end = std::chrono::steady_clock::now() + std::chrono::microseconds(20);
                while (std::chrono::steady_clock::now() < end) {}
                byWorker[static_cast<std::size_t>(i)].store(g_inWorker ? 1 : 0, std::memory_order_relaxed);
            });
            // 0 0 ... 0 1 1 ... 1: never a worker's task before a caller's.
            bool worker = false;
            for (int i = 0; i < kTasks; ++i) {
                const int w = byWorker[static_cast<std::size_t>(i)].load(std::memory_order_relaxed);
                QVERIFY(w >= 0);
                if (w == 0 && worker) QFAIL(qPrintable(QStringLiteral("run %1: the caller ran task %2 after the worker's").arg(run).arg(i)));
                worker = worker || w == 1;
            }
            workerRuns += worker ? 1 : 0;
        }
        if (availableThreads() >= 2) QVERIFY2(workerRuns > 0, "the worker took no task");
        std::vector<std::atomic<std::uint8_t>> hits(70000);
        pool.run(70000, [&](int i) { hits[static_cast<std::size_t>(i)].fetch_add(1, std::memory_order_relaxed); });
        for (std::size_t i = 0; i < hits.size(); ++i) QCOMPARE(int(hits[i].load()), 1);
    }

    // A worker that finds itself on the caller's CPU moves off it before it claims, unless the
    // other CPUs are as busy (as many other runnable threads as CPUs); one on another CPU stays;
    // a refused move leaves it where it is. Tasks begun on the caller's CPU count as shared.
    void workerOnTheCallersCpuMovesOff_data() {
        QTest::addColumn<bool>("together");
        QTest::addColumn<bool>("granted");
        QTest::addColumn<int>("others");  // runnable besides the caller and the worker: none, fewer than the CPUs, as many
        QTest::addColumn<int>("threads");
        QTest::addColumn<bool>("flicker");  // every other count of runnable threads says idle
        QTest::addColumn<int>("keptOff");  // the worker kept off its CPU while awake: 0 never, 1 always, 2 15 %
        QTest::newRow("on the caller's CPU, the other idle") << true << true << 0 << 2 << false << 0;
        QTest::newRow("on the caller's CPU, one program beside") << true << true << 1 << 2 << false << 0;
        QTest::newRow("on the caller's CPU, the others as busy") << true << true << 2 << 2 << false << 0;
        QTest::newRow("on another CPU") << false << true << 1 << 2 << false << 0;
        QTest::newRow("on another CPU, the others as busy") << false << true << 2 << 2 << false << 1;
        QTest::newRow("on another CPU, the others as busy, the join refused") << false << false << 2 << 2 << false << 1;
        QTest::newRow("on another CPU, the others as busy, three threads") << false << true << 2 << 3 << false << 1;
        QTest::newRow("on another CPU, the others as busy at every other count") << false << true << 2 << 2 << true << 1;
        QTest::newRow("on another CPU, the others as busy, not kept off its CPU") << false << true << 2 << 2 << false << 0;
        QTest::newRow("on another CPU, the others as busy, kept off 15 % of the time") << false << true << 2 << 2 << false << 2;
        QTest::newRow("the move refused") << true << false << 0 << 2 << false << 0;
    }
    void workerOnTheCallersCpuMovesOff() {
        QFETCH(bool, together);
        QFETCH(bool, granted);
        QFETCH(int, others);
        QFETCH(int, threads);
        QFETCH(bool, flicker);
        QFETCH(int, keptOff);
        g_flicker.store(flicker);
        g_keptOff.store(keptOff == 1);
        g_lightlyKeptOff.store(keptOff == 2);
        g_runnableReads.store(0);
        g_callerId.store(std::this_thread::get_id());
        g_workersOnCallersCpu.store(together);
        g_moveGranted.store(granted);
        g_moveCalls.store(0);
        g_joinCalls.store(0);
        cpu_set_t mask;
        CPU_ZERO(&mask);
        QCOMPARE(sched_getaffinity(0, sizeof mask, &mask), 0);
        // The fake count follows the CPUs allowed (two here; one under `taskset -c 0`): none, one
        // fewer than the CPUs, or as many besides the caller and the worker.
        const int cpus = CPU_COUNT(&mask);
        g_runnable.store(2 + (others == 0 ? 0 : others == 1 ? cpus - 1 : cpus));
        ThreadPool::Counters c;
        const auto start = std::chrono::steady_clock::now();
        {
            CpuHooksGuard fakeCpus;
            ThreadPool pool(threads);
            pool.setRunAloneAllowed(false);
            for (int run = 0; run < 500; ++run) spinRun(pool);  // at least 40 ms: a join waits for two judgements 10 ms apart
            c = pool.counters();
        }  // the workers have stopped: their counts are final
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        QVERIFY2(c.workerTasks > 0, "the workers took no task");
        const bool asBusy = others >= 2 && cpus >= 2;
        const bool stays = others >= 2 || cpus < 2;  // (one CPU: moveIsWorthIt says no move)
        if (together && !stays) {
            QVERIFY(g_moveCalls.load() > 0);
            QCOMPARE(c.moves, granted ? std::uint64_t(g_moveCalls.load()) : std::uint64_t{0});
            QCOMPARE(c.sharedCpuTasks, granted ? std::uint64_t{0} : c.workerTasks);
            QCOMPARE(c.stays, std::uint64_t{0});
        } else {
            QCOMPARE(g_moveCalls.load(), 0);
            QCOMPARE(c.moves, std::uint64_t{0});
            if (together) QCOMPARE(c.sharedCpuTasks, c.workerTasks);
            QVERIFY(together ? c.stays > 0 : c.stays == 0);
        }
        // A worker of a pool of two on another CPU joins the caller's while the others are as
        // busy (two judgements in a row, 10 ms apart) and it is kept off its own CPU (for 30 %
        // of a 20 ms span: 15 % is a lower-weight program's), at most every 50 ms; never otherwise.
        g_flicker.store(false);
        g_keptOff.store(false);
        g_lightlyKeptOff.store(false);
        if (!together && asBusy && threads == 2 && !flicker && keptOff == 1) {
            QVERIFY(g_joinCalls.load() >= 1);
            QVERIFY2(g_joinCalls.load() <= 1 + static_cast<int>(elapsed / 0.05),
                     qPrintable(QStringLiteral("%1 joins in %2 s").arg(g_joinCalls.load()).arg(elapsed)));
            QCOMPARE(c.joins, granted ? std::uint64_t(g_joinCalls.load()) : std::uint64_t{0});
            if (!granted) QCOMPARE(c.sharedCpuTasks, std::uint64_t{0});
        } else {
            QCOMPARE(g_joinCalls.load(), 0);
            QCOMPARE(c.joins, std::uint64_t{0});
            if (!together) QCOMPARE(c.sharedCpuTasks, std::uint64_t{0});
        }
    }

    // A join the kernel undoes at once (here: the worker still finds itself on its own CPU at
    // the next run) is tried again after twice the wait each time (50 ms, then 100, 200, ...),
    // not every 50 ms: n joins take at least 100 ms * (2^(n-1) - 1).
    void joinUndoneAtOnceBacksOff() {
        g_callerId.store(std::this_thread::get_id());
        g_workersOnCallersCpu.store(false);
        g_moveGranted.store(true);
        g_keptOff.store(true);
        g_joinCalls.store(0);
        cpu_set_t mask;
        CPU_ZERO(&mask);
        QCOMPARE(sched_getaffinity(0, sizeof mask, &mask), 0);
        if (CPU_COUNT(&mask) < 2) QSKIP("one CPU allowed: nothing to join");
        g_runnable.store(2 + CPU_COUNT(&mask));  // the others as busy
        const auto start = std::chrono::steady_clock::now();
        double elapsed = 0.0;
        {
            CpuHooksGuard fakeCpus;
            ThreadPool pool(2);
            pool.setRunAloneAllowed(false);
            while (elapsed < 0.5) {
                spinRun(pool);
                elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            }
        }
        elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        g_keptOff.store(false);
        const int joins = g_joinCalls.load();
        QVERIFY(joins >= 2);
        QVERIFY2(joins <= 2 + static_cast<int>(std::log2(1.0 + elapsed / 0.1)),
                 qPrintable(QStringLiteral("%1 joins in %2 s").arg(joins).arg(elapsed)));
    }

    // The share judge alone, fed shares (CPU seconds per wall second): under kMayWin of one CPU
    // together, two windows in a row, it tries alone; alone goes on while its share beats
    // together's by kMargin; a trial lost waits kBackoffFirst, then twice as long each time, up
    // to kBackoffLongest, until alone wins again (a window at a CPU or more does not shorten it).
    void shareJudgeTriesAloneUnderOneCpu() {
        using V = ShareJudge::Verdict;
        ShareJudge judge;
        const auto low = [&](double now) { return judge.together(now, 0.02, 0.012); };  // 0.6 of a CPU
        QCOMPARE(judge.together(0.0, 0.02, 0.036), V::Together);  // 1.8 CPUs: quiet
        QCOMPARE(judge.together(0.0, 0.02, 0.020), V::Together);  // one CPU: alone cannot win
        QCOMPARE(judge.together(0.0, 0.02, -1.0), V::Together);   // unknown
        QCOMPARE(judge.together(0.0, 0.0, 0.01), V::Together);
        QCOMPARE(low(0.0), V::Together);                           // one window under a CPU
        QCOMPARE(judge.together(0.0, 0.02, 0.020), V::Together);  // then one at a CPU
        QCOMPARE(low(0.0), V::Together);
        QCOMPARE(low(0.0), V::Try);                                // two in a row; no trial before 0.2
        judge.alone(0.05, 0.045);                                  // alone: 0.9
        QCOMPARE(low(0.1), V::Alone);                              // 0.9 > 1.1 x 0.6
        QCOMPARE(judge.backoff(), ShareJudge::kBackoffFirst);
        judge.alone(0.1, 0.07);                                    // alone: 0.7, not 1.1 x 0.65
        QCOMPARE(judge.together(0.2, 0.02, 0.013), V::Together);  // lost: no trial before 0.2 + 0.2
        QCOMPARE(judge.backoff(), 2 * ShareJudge::kBackoffFirst);  // and the wait after the next doubled
        QCOMPARE(low(0.3), V::Together);
        QCOMPARE(low(0.39), V::Together);
        QCOMPARE(low(0.41), V::Try);                               // none before 0.41 + 0.4
        judge.alone(0.05, 0.02);                                   // alone worse
        QCOMPARE(low(0.5), V::Together);                           // none before 0.5 + 0.4
        QCOMPARE(low(0.6), V::Together);
        QCOMPARE(low(0.89), V::Together);
        QCOMPARE(low(0.91), V::Try);                               // none before 0.91 + 0.8
        judge.alone(0.05, 0.045);
        judge.dropAlone();                                         // the caller left the pool
        QCOMPARE(low(1.0), V::Together);                           // a trial not judged waits too
        QCOMPARE(low(1.1), V::Together);
        QCOMPARE(low(1.72), V::Try);
        double now = 2.0;
        for (int i = 0; i < 12; ++i) {  // trials lost in a row
            const double wait = judge.backoff();
            judge.alone(0.05, 0.01);
            QCOMPARE(low(now), V::Together);
            QCOMPARE(low(now + 0.5 * wait), V::Together);
            QCOMPARE(low(now + 0.99 * wait), V::Together);
            now += wait + 0.01;
            QCOMPARE(low(now), V::Try);
        }
        QCOMPARE(judge.backoff(), ShareJudge::kBackoffLongest);
        QCOMPARE(judge.together(now, 0.02, 0.03), V::Together);  // 1.5 CPUs
        QCOMPARE(judge.backoff(), ShareJudge::kBackoffLongest);   // still the longest wait
        judge.alone(0.05, 0.045);
        QCOMPARE(low(now + 0.1), V::Alone);
        QCOMPARE(judge.backoff(), ShareJudge::kBackoffFirst);     // alone won: short again
    }

    // The pool with the share judge, on fake CPU clocks: the host gives the pair 2 x 0.35 of a CPU
    // and the caller alone 0.9 (it goes alone, and stays: alone wins again and again); alone only
    // 0.5 (it tries, loses, and tries less often); a quiet machine (never tries).
    void poolGoesAloneWhenTogetherGetsLessCpu_data() {
        QTest::addColumn<double>("together");
        QTest::addColumn<double>("alone");
        QTest::newRow("alone gets more") << 0.35 << 0.9;
        QTest::newRow("alone gets less") << 0.35 << 0.5;
        QTest::newRow("quiet") << 0.9 << 1.0;
    }
    void poolGoesAloneWhenTogetherGetsLessCpu() {
        QFETCH(double, together);
        QFETCH(double, alone);
        g_callerId.store(std::this_thread::get_id());
        g_workersOnCallersCpu.store(false);  // split: no move; not kept off: no join
        g_shareTogether.store(together);
        g_shareAlone.store(alone);
        g_callerShareClock = g_workersShareClock = FakeShareClock{};
        const bool wins = alone > ShareJudge::kMargin * 2 * together;
        ThreadPool::Counters c;
        const auto start = std::chrono::steady_clock::now();
        double elapsed = 0.0;
        {
            ThreadPool::setCpuHooks(&kShareCpus);
            ThreadPool pool(2);
            g_sharePool.store(&pool);
            // Until alone has won three times (or, else, 0.6 s).
            while (elapsed < (wins ? 20.0 : 0.6) && (!wins || pool.counters().shareWins < 3)) {
                spinRun(pool);
                elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            }
            c = pool.counters();
        }
        ThreadPool::setCpuHooks(nullptr);
        g_sharePool.store(nullptr);
        const QString what = QStringLiteral("%1 s: %2 runs, %3 alone in %4 stretches, %5 trials, %6 won")
                                 .arg(elapsed).arg(c.runs).arg(c.soloRuns).arg(c.soloPeriods).arg(c.shareTrials).arg(c.shareWins);
        qInfo("%s", qPrintable(what));
        if (together * 2 >= ShareJudge::kMayWin) {
            QVERIFY2(c.shareTrials == 0 && c.shareWins == 0, qPrintable(what));
        } else if (wins) {
            // Three wins, whatever began the first stretch alone: a trial, or on a loaded
            // machine (a sanitizer's build beside other work) the fallback of the waits, after
            // whose stretch the judge compares the shares as after a trial (CI at stop 44:
            // 0 trials, 3 won).
            QVERIFY2(c.shareWins >= 3, qPrintable(what));
            QVERIFY2(c.shareTrials <= 2, qPrintable(what));  // alone kept winning: no new trial needed
        } else {
            // It went alone for a while (a trial, or the waits' fallback as above) and alone
            // never won.
            QVERIFY2((c.shareTrials >= 1 || c.soloPeriods >= 1) && c.shareWins == 0, qPrintable(what));
            // Trials lost back off: at most one at once, then after 0.2, 0.4, 0.8 s ...
            QVERIFY2(c.shareTrials <= 1 + static_cast<unsigned>(std::log2(1.0 + elapsed / ShareJudge::kBackoffFirst)),
                     qPrintable(what));
        }
    }

    // The rule behind it: with n CPUs, a worker sharing the caller's CPU gains by moving while
    // fewer than n other threads are runnable (some CPU is less busy than theirs); an unknown
    // count moves. The kernel's count includes the thread that reads it.
    void moveIsWorthItWhileAnotherCpuIsLessBusy() {
        QVERIFY(moveIsWorthIt(2, 2));   // the other CPU idle
        QVERIFY(moveIsWorthIt(3, 2));   // one program beside: half of its CPU beats turns on ours
        QVERIFY(!moveIsWorthIt(4, 2));  // two beside: the pair keeps a whole CPU
        QVERIFY(!moveIsWorthIt(9, 2));
        QVERIFY(moveIsWorthIt(5, 4));
        QVERIFY(!moveIsWorthIt(6, 4));
        QVERIFY(!moveIsWorthIt(2, 1));  // one CPU: nowhere to go
        QVERIFY(moveIsWorthIt(-1, 2));
        // Joining is the mirror, where the count is known and there is a CPU to give up.
        for (int cpus = 1; cpus <= 4; ++cpus)
            for (int runnable = 1; runnable <= 9; ++runnable)
                QCOMPARE(joinIsWorthIt(runnable, cpus), cpus >= 2 && !moveIsWorthIt(runnable, cpus));
        QVERIFY(joinIsWorthIt(4, 2));
        QVERIFY(!joinIsWorthIt(3, 2));
        QVERIFY(!joinIsWorthIt(-1, 2));
        QVERIFY(!joinIsWorthIt(5, 1));
        QVERIFY(runnableThreads() >= 1);  // at least this thread
    }

    // moveOffCpu and moveOntoCpu really move the thread (the kernel migrates it before the
    // narrowed mask takes effect) and give its mask back whole; with one CPU allowed they do
    // nothing.
    void moveOffCpuMovesAndKeepsTheMask() {
        cpu_set_t before;
        CPU_ZERO(&before);
        QCOMPARE(sched_getaffinity(0, sizeof before, &before), 0);
        QCOMPARE(moveOffCpu(-1), -1);
        if (CPU_COUNT(&before) < 2) QSKIP("one CPU allowed: nowhere to move");
        for (int i = 0; i < 20; ++i) {
            const int cpu = currentCpu();
            QVERIFY(cpu >= 0);
            const int moved = moveOffCpu(cpu);
            QVERIFY2(moved >= 0 && moved != cpu, qPrintable(QStringLiteral("from %1 to %2").arg(cpu).arg(moved)));
            QVERIFY(CPU_ISSET(moved, &before));
            cpu_set_t after;
            CPU_ZERO(&after);
            QCOMPARE(sched_getaffinity(0, sizeof after, &after), 0);
            QVERIFY(CPU_EQUAL(&before, &after));
        }
        // And onto a chosen CPU (a worker joining the caller's): there, the mask given back.
        QCOMPARE(moveOntoCpu(-1), -1);
        for (int i = 0; i < 20; ++i) {
            const int cpu = currentCpu();
            int target = -1;
            for (int k = 0; k < CPU_SETSIZE && target < 0; ++k)
                if (k != cpu && CPU_ISSET(k, &before)) target = k;
            QVERIFY(target >= 0);
            QCOMPARE(moveOntoCpu(target), target);
            cpu_set_t after;
            CPU_ZERO(&after);
            QCOMPARE(sched_getaffinity(0, sizeof after, &after), 0);
            QVERIFY(CPU_EQUAL(&before, &after));
        }
        // Pinned to one CPU (as under `taskset -c 0`): no move, the mask untouched.
        cpu_set_t one;
        CPU_ZERO(&one);
        const int here = currentCpu();
        CPU_SET(here, &one);
        QCOMPARE(sched_setaffinity(0, sizeof one, &one), 0);
        const int moved = moveOffCpu(here);
        int elsewhere = -1;  // a CPU outside the one-CPU mask: no join there either
        for (int k = 0; k < CPU_SETSIZE && elsewhere < 0; ++k)
            if (k != here && CPU_ISSET(k, &before)) elsewhere = k;
        const int joined = moveOntoCpu(elsewhere);
        cpu_set_t after;
        CPU_ZERO(&after);
        sched_getaffinity(0, sizeof after, &after);
        sched_setaffinity(0, sizeof before, &before);
        QCOMPARE(moved, -1);
        QCOMPARE(joined, -1);
        QVERIFY(CPU_EQUAL(&one, &after));
    }

    // A thread kept off its CPU for more than a quarter of the time it wanted to run marks the
    // pool contended; a preemption of a few microseconds and the thread's own sleeps do not.
    void keptOffCpuJudgesTheShareOffTheCpu() {
        QVERIFY(!keptOffCpu(2e-3, 1.98e-3, 0.0));    // a kernel thread's 20 us
        QVERIFY(!keptOffCpu(2e-3, 1.6e-3, 0.0));     // a fifth of the time
        QVERIFY(keptOffCpu(2e-3, 1.0e-3, 0.0));      // half of it: another program's time slice
        QVERIFY(!keptOffCpu(2e-3, 0.5e-3, 1.4e-3));  // slept 1.4 ms, ran 0.5 of the 0.6 it wanted
        QVERIFY(keptOffCpu(2e-3, 0.2e-3, 1.5e-3));   // wanted 0.5 ms, ran 0.2
        QVERIFY(!keptOffCpu(2e-3, 0.0, 2e-3));       // slept throughout
        QVERIFY(!keptOffCpu(2e-3, -1.0, 0.0));       // no thread CPU clock: never contended
        QVERIFY(!keptOffCpu(2e-3, 0.06e-3, 1.9e-3)); // 40 us off of 100: a kernel thread, not a program
        // A thread's check of itself over its intervals (seconds): the first check only starts
        // one; time away (asleep, or outside the pool) is not time kept off; an interval longer
        // than 20 ms is not judged.
        OffCpuProbe probe;
        QVERIFY(!probe.check(1.000, 5.0));
        QVERIFY(!probe.check(1.002, 5.00198));   // ran 1.98 of 2 ms
        QVERIFY(probe.check(1.004, 5.00298));    // ran 1 of 2 ms
        probe.away(0.0015);
        QVERIFY(!probe.check(1.006, 5.00343));   // away 1.5 ms, ran 0.45 of the 0.5 it wanted
        probe.away(0.0015);
        QVERIFY(probe.check(1.008, 5.00363));    // away 1.5 ms, ran 0.2 of 0.5
        QVERIFY(!probe.check(1.008 + 0.024, 5.00463));  // 24 ms: not judged
        QVERIFY(probe.check(1.034, 5.00473));    // the next interval is: ran 0.1 of 2 ms
        QVERIFY(!probe.check(1.036, -1.0));      // no CPU clock
        // Back from outside the pool: the interval starts there (without the restart there is
        // none to judge: the last check had no CPU clock, and it was 964 ms ago).
        probe.restart(2.000, 6.0);
        QVERIFY(probe.check(2.002, 6.0005));     // ran 0.5 of 2 ms
        // The clock it reads is this thread's: it moves while the thread works, not while it sleeps.
        const double before = threadCpuSeconds();
        QVERIFY(before >= 0.0);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        QVERIFY(threadCpuSeconds() - before < 0.02);
    }
    // threadSchedStat reads the kernel's account of the calling thread: two threads that spin
    // 60 ms of wall time each on one CPU take turns, so each ran for less than its wall time and
    // waited for the CPU; a sleeping thread neither runs nor waits; the time run is the CPU clock.
    void schedStatCountsTheWaitForACpu() {
        if (threadSchedStat().waited < 0.0) QSKIP("no /proc/thread-self/schedstat here");
        cpu_set_t mask;
        CPU_ZERO(&mask);
        QCOMPARE(sched_getaffinity(0, sizeof mask, &mask), 0);
        int first = 0;
        while (!CPU_ISSET(first, &mask)) ++first;
        std::array<SchedStat, 2> spent{};
        auto spin = [&](int k) {
            cpu_set_t one;
            CPU_ZERO(&one);
            CPU_SET(first, &one);
            pthread_setaffinity_np(pthread_self(), sizeof one, &one);
            const SchedStat before = threadSchedStat();
            const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(60);
            while (std::chrono::steady_clock::now() < end) {}
            const SchedStat after = threadSchedStat();
            spent[static_cast<std::size_t>(k)] = {after.ran - before.ran, after.waited - before.waited};
        };
        std::thread a(spin, 0), b(spin, 1);
        a.join();
        b.join();
        if (spent[0].ran == 0.0 && spent[1].ran == 0.0) QSKIP("the kernel keeps no scheduler statistics (0 0 0)");
        for (const SchedStat& s : spent) {
            QVERIFY2(s.ran > 0.0 && s.waited > 0.0, qPrintable(QStringLiteral("ran %1 s, waited %2 s").arg(s.ran).arg(s.waited)));
        }
        QVERIFY(spent[0].waited + spent[1].waited > 0.01);  // about 60 ms between them
        const SchedStat before = threadSchedStat();
        std::this_thread::sleep_for(std::chrono::milliseconds(30));
        const SchedStat after = threadSchedStat();
        QVERIFY(after.ran - before.ran < 0.01 && after.waited - before.waited < 0.01);
        // The time it ran is the thread's CPU clock: 100 ms of CPU spun, 100 ms ran (the kernel
        // brings a running thread's count up to date at its timer ticks: 10 ms either way at most).
        const SchedStat start = threadSchedStat();
        const double cpuStart = threadCpuSeconds();
        while (threadCpuSeconds() - cpuStart < 0.1) {}
        const double ran = threadSchedStat().ran - start.ran;
        QVERIFY2(ran > 0.09 && ran < 0.11, qPrintable(QStringLiteral("ran %1 s").arg(ran)));
    }


    // A caller that shares its CPU with a busy thread (another program's, as a teacher's laptop
    // has) finds itself kept off the CPU, and the pool turns to its short spins; every task still
    // runs once. Both are pinned to the CPU the test runs on (the pool, made first, keeps its
    // worker free); a caller that never notices fails after 20,000 runs of 50 us (about a second
    // of its work, where the first check comes after 2 ms).
    void callerBesideABusyThreadIsKeptOff() {
        ThreadPool pool(2);
        pool.setRunAloneAllowed(false);
        cpu_set_t saved, one;
        QCOMPARE(pthread_getaffinity_np(pthread_self(), sizeof saved, &saved), 0);
        CPU_ZERO(&one);
        CPU_SET(sched_getcpu(), &one);
        QCOMPARE(pthread_setaffinity_np(pthread_self(), sizeof one, &one), 0);
        std::atomic<bool> stop{false};
        std::thread hog([&] {
            pthread_setaffinity_np(pthread_self(), sizeof one, &one);
            while (!stop.load(std::memory_order_relaxed)) {}
        });
        std::vector<std::atomic<int>> hits(2);
        int runs = 0;
        for (; runs < 20000 && pool.counters().callerBusyMarks == 0; ++runs) {
            pool.run(2, [&](int i) {
                const auto end = std::chrono::steady_clock::now() + std::chrono::microseconds(50);
                while (std::chrono::steady_clock::now() < end) {}
                hits[static_cast<std::size_t>(i)].fetch_add(1, std::memory_order_relaxed);
            });
        }
        stop.store(true, std::memory_order_relaxed);
        hog.join();
        pthread_setaffinity_np(pthread_self(), sizeof saved, &saved);
        QVERIFY2(pool.counters().callerBusyMarks > 0, qPrintable(QStringLiteral("not marked busy in %1 runs").arg(runs)));
        QCOMPARE(hits[0].load(), runs);
        QCOMPARE(hits[1].load(), runs);
    }

    // A caller that sleeps between runs (a GUI frame's pause) was outside the pool, not kept off
    // its CPU: each run after a pause starts a new interval, never judged with the pause in it
    // (judged with it, every check after a 3 ms pause marks the pool busy: 39 of 40 runs).
    void callerPausingBetweenRunsIsNotKeptOff() {
        ThreadPool pool(2);
        std::atomic<int> ran{0};
        for (int run = 0; run < 40; ++run) {
            std::this_thread::sleep_for(std::chrono::milliseconds(3));
            pool.run(2, [&](int) { ran.fetch_add(1, std::memory_order_relaxed); });
        }
        QCOMPARE(ran.load(), 80);
        QCOMPARE(pool.counters().callerBusyMarks, std::uint64_t{0});
    }

    // The caller sleeps (futex) when a worker's task keeps it waiting, and the worker that
    // finishes the last task wakes it. A lost wake-up hangs here (CTest's time limit catches
    // it); each round the caller is held until it has announced its sleep.
    void sleepingCallerIsWoken() {
        ThreadPool pool(2);
        pool.setRunAloneAllowed(false);  // the caller must wait for the worker every round
        g_pool.store(&pool, std::memory_order_release);
        HookGuard hook(holdWorkerUntilCallerSleeps);
        g_workerTasks.store(0);
        std::atomic<int> ran{0};
        for (int round = 0; round < 50; ++round) {
            g_workerIn.store(0, std::memory_order_release);
            pool.run(2, [&](int) { ran.fetch_add(1, std::memory_order_relaxed); });
            QCOMPARE(ran.load(), 2 * (round + 1));
            QVERIFY(!pool.callerSleeping());
        }
        QCOMPARE(g_workerTasks.load(), 50);   // each round the worker ran one task
        QVERIFY(pool.counters().callerSleeps > 0);
        g_pool.store(nullptr);
    }

    // A worker whose spin ran out sleeps on a futex; the next run wakes it (a lost wake-up
    // hangs: the caller's task 0 waits for the worker to take a task).
    void sleepingWorkerIsWoken() {
        ThreadPool pool(2);
        pool.setRunAloneAllowed(false);
        HookGuard hook(callerWaitsForWorker);
        g_workerTasks.store(0);
        for (int round = 0; round < 20; ++round) {
            while (pool.sleepingWorkers() == 0) std::this_thread::yield();  // the worker sleeps (or is about to)
            g_workerIn.store(0, std::memory_order_release);
            std::atomic<int> ran{0};
            pool.run(2, [&](int) { ran.fetch_add(1, std::memory_order_relaxed); });
            QCOMPARE(ran.load(), 2);
        }
        QVERIFY(g_workerTasks.load() >= 20);  // each round the worker woke and ran a task (or both)
        QVERIFY(pool.counters().workerSleeps >= 20);
    }

    // Tasks run exactly once each while the worker is stalled now and then in the middle of a
    // run (the caller waits, sleeps, and may go on alone for a while).
    void everyTaskRunsOnceWithAStalledWorker() {
        ThreadPool pool(2);
        HookGuard hook(stallSomeWorkerTasks);
        g_workerTasks.store(0);
        g_stallEvery.store(7);
        std::vector<std::atomic<int>> hits(16);
        for (int run = 0; run < 1500; ++run) {
            const int count = 2 + run % 15;
            for (int i = 0; i < count; ++i) hits[static_cast<std::size_t>(i)].store(0, std::memory_order_relaxed);
            pool.run(count, [&](int i) { hits[static_cast<std::size_t>(i)].fetch_add(1, std::memory_order_relaxed); });
            for (int i = 0; i < count; ++i)
                if (hits[static_cast<std::size_t>(i)].load(std::memory_order_relaxed) != 1)
                    QFAIL(qPrintable(QStringLiteral("run %1: task %2 ran %3 times").arg(run).arg(i).arg(hits[static_cast<std::size_t>(i)].load())));
        }
        g_stallEvery.store(0);
        const ThreadPool::Counters c = pool.counters();
        QCOMPARE(c.runs, std::uint64_t{1500});
        QVERIFY(c.soloRuns <= c.runs);
    }

    // A step's pool runs with two threads (each a join where the caller may wait): RK4 with the
    // kept end-of-step forces makes 8 per step: the first stage's (its held-back unpadding, the
    // stage sums and the save), two for each of the other three stages, and the measurement's
    // (the forces' chunks and the scan). One more is a save or a scan on its own again.
    void rk4StepMakesEightPoolRuns() {
        Simulation sim(level4Sphere(), "rk4");
        sim.setThreads(2);
        QCOMPARE(sim.threads(), 2);
        QVERIFY(sim.step());  // the first step has no kept forces yet
        const ThreadPool* pool = sim.forces().pool();
        QVERIFY(pool != nullptr);
        const std::uint64_t before = pool->counters().runs;
        for (int i = 0; i < 10; ++i) QVERIFY(sim.step());
        QCOMPARE(pool->counters().runs - before, std::uint64_t{80});
    }

    // Which thread runs a chunk, a stalled worker and the caller's runs alone never change a
    // result: the double and the float path step a sphere with one thread and with two (the
    // worker stalled every fifth task it takes) to the same bits.
    // Level 4 runs two chunks, level 6 four, which either thread takes while it is free (a
    // stalled worker leaves the caller the rest).
    void stalledWorkerKeepsTheBits_data() {
        QTest::addColumn<int>("level");
        QTest::addColumn<int>("chunks");
        QTest::newRow("level 4") << 4 << 2;
        QTest::newRow("level 6") << 6 << 4;
    }
    void stalledWorkerKeepsTheBits() {
        QFETCH(int, level);
        QFETCH(int, chunks);
        ParameterSet p = level4Sphere();
        QVERIFY(!p.set(Param::Subdivisions, level));
        Simulation one(p, "rk4");
        one.setThreads(1);
        Simulation two(p, "rk4");
        two.setThreads(2);
        QCOMPARE(two.threads(), 2);
        QCOMPARE(two.forces().chunks(), chunks);
        FloatSimulation floatOne(one);
        floatOne.setThreads(1);
        FloatSimulation floatTwo(two);
        floatTwo.setThreads(2);
        QCOMPARE(floatTwo.threads(), 2);
        // Two threads step at least 40 times and on until the worker has taken a chunk (on a
        // busy machine a worker may not be scheduled at all for a few milliseconds); one
        // thread then steps as many times.
        int doubleSteps = 0, floatSteps = 0;
        {
            HookGuard hook(stallSomeWorkerTasks);
            g_workerTasks.store(0);
            g_stallEvery.store(5);
            constexpr int kMostSteps = 100000;
            while (doubleSteps < 40 || (g_workerTasks.load() == 0 && doubleSteps < kMostSteps)) {
                QVERIFY(two.step());
                ++doubleSteps;
            }
            const int doubleWorkerTasks = g_workerTasks.load();
            while (floatSteps < 40 || (g_workerTasks.load() == doubleWorkerTasks && floatSteps < kMostSteps)) {
                QVERIFY(floatTwo.step());
                ++floatSteps;
            }
            g_stallEvery.store(0);
            QVERIFY2(doubleWorkerTasks > 0, "the worker took no chunk of the double path");
            QVERIFY2(g_workerTasks.load() > doubleWorkerTasks, "the worker took no chunk of the float path");
        }
        for (int i = 0; i < doubleSteps; ++i) QVERIFY(one.step());
        for (int i = 0; i < floatSteps; ++i) QVERIFY(floatOne.step());
        const Eigen::VectorXd& a = one.state();
        const Eigen::VectorXd& b = two.state();
        QCOMPARE(a.size(), b.size());
        QVERIFY(std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0);
        QCOMPARE(floatTwo.stateHash(), floatOne.stateHash());
    }
};

QTEST_GUILESS_MAIN(TestThreads)
#include "test_threads.moc"
