#pragma once
// A small pool of threads that lives as long as its owner (a simulation): no thread is
// created per step. run(count, task) calls task(0..count-1) spread over the threads and
// returns when all are done; the calling thread takes part.
//
// Work goes to whichever thread is free: a task is claimed with one compare-and-swap on a
// ticket that holds the run's number and the tasks not yet claimed (the caller takes them from
// the front, the workers from the back, so each thread meets the same tasks run after run and
// keeps their data in its cache), so a worker that has not been
// scheduled yet (a busy machine: compilers, a browser, another simulation beside it) claims
// nothing, the caller does its tasks, and the run ends when every task is done, not when every
// worker has turned up.
//
// Waits degrade gracefully. A worker spins for the next run (about 1 ms while it keeps finding
// work, a few microseconds once it keeps arriving late), then sleeps on a futex; the caller
// spins, then yields, then sleeps on a futex until the last task is done. Neither holds a CPU
// for long that another thread (its partner, preempted, or another process) could use.
// A worker that finds itself on the CPU the caller posted the run from moves to another CPU
// before it claims (moveOffCpu). On a busy machine the kernel wakes a sleeping worker on its
// waker's CPU when the other CPU is taken by another program; there caller and worker only
// take turns on one CPU while the other program has the second to itself, and two threads lost
// to one (stop 41: 50-80 % of the worker's tasks ran on the caller's CPU beside `stress-ng --cpu
// 1`). Moved, the worker shares the other program's CPU instead. It stays when the other CPUs
// are at least as busy as this one (as many runnable threads besides the caller and itself as
// CPUs: moveIsWorthIt): there the two taking turns on one CPU get a whole CPU, and split, each
// would get a share of a busier one (beside `stress-ng --cpu 2` two threads fell from 1.4-1.6x
// one thread to 1.1x when the worker always moved). The mirror: a worker of a pool of two that
// finds itself on another CPU while the others are as busy joins the caller's CPU (moveOntoCpu;
// two readings of the count in a row, at most every 50 ms): split, each thread shares a CPU with
// another program and the pair waits for whichever was preempted at every run. Only while the
// worker is kept off its own CPU, for 30 % of a 20 ms span (stop 43): runnable threads of other
// programs in another scheduling group (another session, a lower priority) may take little of
// it (about a tenth, in slices that fail a single 2 ms check; joined there, two threads ran at
// 0.97x one beside three compilers, and at 1.36x with the span). And a join the
// kernel undoes at once (its balancer separating the pair: the count said busy, the weights
// said otherwise) is tried again only after twice as long, up to seconds: beside three
// compilers in other sessions, the lab's shell at higher priority, two threads fell from 1.29x
// one thread to 1.01x when the worker joined by the count alone, 40-100 times a run.
// When a run's caller keeps waiting for a preempted worker longer than it works itself (a
// machine busier than its CPUs: two fixed chunks cannot be shared once begun), one thread
// would be faster: the caller runs alone for a while, then tries two threads again, and
// backs off while the trials keep failing. It also runs alone while the pool's threads together
// get less CPU time than the caller alone does (ShareJudge: a virtual machine whose host runs its
// two CPUs on about one core). Two threads on a busy machine therefore cost about what one does,
// and on a quiet one keep their ~1.9x.
//
// Determinism is the caller's job and is easy: split work into a fixed number of tasks that
// does not depend on the thread count, and combine their results in task order. Which thread
// ran a task, and whether the caller ran alone, never changes a result.

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <thread>
#include <type_traits>
#include <vector>

namespace simcore {

// A non-owning reference to a callable: unlike std::function it never allocates, so
// dispatching work inside a step allocates nothing.
template <class Signature>
class FunctionRef;
template <class... Args>
class FunctionRef<void(Args...)> {
public:
    // The callable must outlive the call it is passed to (a temporary lambda in the call's own
    // full expression does).
    template <class F>
        requires(!std::is_same_v<std::remove_cvref_t<F>, FunctionRef>)
    FunctionRef(F&& f)  // NOLINT: implicit on purpose, like std::function_ref
        : m_object(const_cast<void*>(static_cast<const void*>(&f))),
          m_call([](void* object, Args... args) { (*static_cast<std::remove_reference_t<F>*>(object))(args...); }) {}
    void operator()(Args... args) const { m_call(m_object, args...); }

private:
    void* m_object;
    void (*m_call)(void*, Args...);
};

// A task of a run: called with its index.
using TaskRef = FunctionRef<void(int)>;
// Element-wise work on a range (begin, length) of a vector.
using RangeWork = FunctionRef<void(std::ptrdiff_t, std::ptrdiff_t)>;

// Whether a thread was kept off its CPU over an interval of `wall` seconds in which it ran `cpu`
// seconds and slept on purpose for `away`: runnable but not running (another thread had its CPU)
// for more than a quarter of the time it wanted to run, and for more than 0.2 ms. A kernel
// thread's or a timer's preemption of tens of microseconds is not that, even in a short
// interval; a time slice given to another program (a millisecond or more) is. The time a woken
// thread waits for a CPU counts as asleep: the pool cannot tell it apart without the kernel's
// scheduler statistics. (Stop 39 read them as zeros; at stop 42 /proc/thread-self/schedstat's
// second field, the time spent runnable waiting for a CPU, counted on this machine's kernel
// 6.18: 367 ms of 1 s for a spinning thread beside `stress-ng --cpu 2`. Read for
// ELASTIC_LAB_POOL_STATS since stop 43 (threadSchedStat), not for the pool's decisions.)
bool keptOffCpu(double wall, double cpu, double away);
// The calling thread's CPU time in seconds (-1 where the system cannot tell).
double threadCpuSeconds();
// The kernel's scheduler statistics of the calling thread (/proc/thread-self/schedstat): the
// time it ran and the time it was runnable but waited for a CPU (another thread had it), in
// seconds; both -1 where the system cannot tell. A virtual machine's steal is in neither: over
// an interval, wall - ran - waited is the time the thread slept or its CPU was taken by the host.
struct SchedStat {
    double ran = -1.0, waited = -1.0;
};
SchedStat threadSchedStat();

// One thread's check of itself, fed the clocks (seconds) at each check and told when the thread
// sleeps: an interval longer than `longest` is not judged and only starts the next one.
class OffCpuProbe {
public:
    explicit OffCpuProbe(double longest = 0.02) : m_longest(longest) {}
    // The check at wall time `wall` with the thread's CPU time `cpu`: whether the interval since
    // the last check shows the thread kept off its CPU (keptOffCpu); then a new interval begins.
    bool check(double wall, double cpu);
    // A new interval from here, the last one dropped unjudged (the caller comes back from
    // outside the pool, where it may have slept or worked on other things: neither its wall
    // time nor its CPU time there says anything).
    void restart(double wall, double cpu);
    void away(double seconds) { m_away += seconds; }

private:
    double m_longest;
    double m_wallAt = 0.0, m_cpuAt = -1.0;  // at the last check (-1: none yet)
    double m_away = 0.0;                    // since then
};

// Whether the caller alone would be faster than the pool's threads together, judged by the CPU
// time they get (stop 43). On a virtual machine whose host runs the two virtual CPUs on about one
// core (the host's other guests busy: the steal time in /proc/stat), two threads lost to one by
// 15-40 % with nothing else running in the guest: each thread was kept off its CPU half the time,
// at a different moment from the other, and the pair waited for whichever was away at every run.
// The waits then are no longer than the work (the fallback's own test), but the pair together
// got 0.6 CPU-seconds per second where one thread alone got 0.9. One thread can use at most one
// CPU: while the pool's threads together get less than kMayWin of one CPU (their CPU time over a
// window's wall time, waits and serial stretches included; two windows in a row), the caller tries a stretch alone and
// measures its own share; alone stays while its share beats together's by kMargin, and each
// stretch alone is followed by one window together that judges again. A trial that loses backs
// off: the next comes only after twice as long (kBackoffFirst up to kBackoffLongest), until alone
// wins again (beside two busy programs the pair's share hovers about one CPU; trials there lose). On a quiet machine the pair gets 1.8-1.9 CPUs, beside one
// or two busy programs 1.0-1.4: no trial, and nothing is read but two clocks per window.
// Fed seconds on any one clock; `now` only orders the trials.
class ShareJudge {
public:
    static constexpr double kMayWin = 0.95, kMargin = 1.1;
    static constexpr double kBackoffFirst = 0.2, kBackoffLongest = 6.4;
    enum class Verdict {
        Together,  // stay together
        Try,       // together got less than kMayWin of a CPU: try a stretch alone
        Alone,     // alone got the larger share over the last stretch: go on alone
    };
    // A window together ended at `now`: the pool's threads got `cpu` seconds of CPU in `wall`
    // (cpu < 0: unknown, together).
    Verdict together(double now, double wall, double cpu);
    // A stretch alone ended: the caller got `cpu` seconds of CPU in `wall`.
    void alone(double wall, double cpu);
    // Forgets a stretch alone that cannot be judged (the caller left the pool during it).
    void dropAlone() { m_aloneShare = -1.0; }
    double backoff() const { return m_backoff; }

private:
    double m_aloneShare = -1.0;  // the caller's share over the last stretch alone (-1: none to judge)
    double m_trialAfter = 0.0;   // no trial before this time
    int m_lowWindows = 0;        // windows in a row together under kMayWin
    double m_backoff = kBackoffFirst;
};

class ThreadPool {
public:
    explicit ThreadPool(int threads);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int threads() const { return static_cast<int>(m_workers.size()) + 1; }
    void run(int count, TaskRef task);

    // What the pool's waits did since it was made (diagnostics and tests; relaxed counts, exact
    // once the pool is idle).
    struct Counters {
        std::uint64_t runs = 0;           // runs of more than one task
        std::uint64_t soloRuns = 0;       // of which the caller ran alone (the busy-machine fallback)
        std::uint64_t callerSleeps = 0;   // the caller slept waiting for a worker's task
        std::uint64_t workerSleeps = 0;   // a worker slept waiting for the next run
        std::uint64_t workerTasks = 0;    // tasks run by workers
        std::uint64_t soloPeriods = 0;    // times the caller chose to run alone
        std::uint64_t busyMarks = 0;      // times a thread found itself kept off its CPU
        std::uint64_t callerBusyMarks = 0; // of which the caller
        std::uint64_t sharedCpuTasks = 0;  // worker tasks begun on the CPU the caller posted the run from
        std::uint64_t moves = 0;           // times a worker moved off the caller's CPU
        std::uint64_t stays = 0;           // times it stayed there, the other CPUs as busy (moveIsWorthIt)
        std::uint64_t joins = 0;           // times a worker on another CPU joined the caller's, the others as busy
        std::uint64_t shareTrials = 0;     // times the caller tried alone, the pool together getting under one CPU (ShareJudge)
        std::uint64_t shareWins = 0;       // times alone then got the larger share and went on alone
    };
    Counters counters() const;
    // Workers asleep right now (waiting on the futex for the next run).
    int sleepingWorkers() const { return static_cast<int>(m_sleepers.load(std::memory_order_acquire)); }
    // Whether the caller is asleep right now, waiting for a worker's task.
    bool callerSleeping() const { return m_callerAsleep.load(std::memory_order_acquire) != 0; }

    // Whether the caller may run alone for a while when the workers cost more than they bring
    // (the default; tests that need every run shared turn it off).
    void setRunAloneAllowed(bool allowed) { m_aloneAllowed = allowed; }

    // Tests only: called before every task of every pool, with the task's index and whether a
    // worker (not the caller) runs it; a test stalls a thread there in the middle of a run.
    // Set it while no pool is running; nullptr (the default) removes it.
    using TestHook = void (*)(int task, bool worker);
    static void setTestHook(TestHook hook);
    // Tests only: what the pool's threads take for their CPU and how they move off one
    // (currentCpu and moveOffCpu below by default). Set while no pool runs; nullptr: the real ones.
    struct CpuHooks {
        int (*current)();
        int (*moveOff)(int cpu);
        int (*moveOnto)(int cpu);
        int (*runnable)();
        double (*threadCpu)();  // the calling thread's CPU time (threadCpuSeconds)
        double (*workersCpu)(const ThreadPool& pool);  // the pool's workers' CPU time together, read by the caller
    };
    static void setCpuHooks(const CpuHooks* hooks);

private:
    void workerLoop();
    // ELASTIC_LAB_POOL_STATS=1: the counters and the threads' scheduler statistics, on stderr.
    void printStats() const;
    // A worker's place at the start of a run (see above): off the caller's CPU, or onto it, by
    // the load it judged last and (to join) when it was last found kept off its own CPU. Returns
    // the CPU it is on (-1: unknown).
    struct WorkerPlacement {
        bool moveWorthIt = true;  // by the last judgement of the load
        int joinStreak = 0;       // judgements in a row that said join (two: join)
        int joinBackoff = 0;      // joins undone at once in a row: the wait before the next doubles
        bool together = false;    // on the caller's CPU at the last run
        std::chrono::steady_clock::time_point judgedUntil{}, joinAfter{};
        std::chrono::steady_clock::time_point joinedAt{};  // the last join, until the worker finds it undone
        // The worker's time off its CPU over spans of kJoinSpan (wall, CPU and sleep at the span's
        // start) and the share off in the last span: a join needs kJoinOffShare of it.
        std::chrono::steady_clock::time_point spanAt{};
        double spanCpuAt = -1.0, spanAwayAt = 0.0, offShare = 0.0;
    };
    // Claims and runs tasks of run `run` until none is left (or another run has begun);
    // returns how many it ran.
    int claimTasks(std::uint32_t run, bool worker);
    // The caller's wait for the tasks a worker still runs; returns true when it had to sleep.
    bool waitForTasks(int count);
    // Whether the machine is contended (see parallel.cpp): each thread checks itself now and
    // then (OffCpuProbe); a thread kept off its CPU marks the pool busy for a while.
    struct ContentionProbe {
        std::chrono::steady_clock::time_point nextCheck{};
        OffCpuProbe offCpu;
        std::chrono::steady_clock::time_point keptOffAt{};  // the last check that found this thread kept off its CPU
        double asleep = 0.0;  // seconds slept on purpose since the thread began (the worker's)
    };
    int placeWorker(WorkerPlacement& at, const ContentionProbe& probe);
    bool contended(ContentionProbe& probe);
    // The fallback's decision after each run that used the workers.
    void judgeRun(double ownSeconds, double waitSeconds);
    // The CPU time of the pool's threads, the caller's and the workers' (the caller reads it).
    double poolCpuSeconds();
    // The share judge's clocks (ShareJudge; the caller's own state): a window together and a
    // stretch alone start with the wall time and CPU time read then; `valid` false when the
    // caller left the pool since (a gap between runs longer than kBetweenRuns).
    struct ShareClock {
        std::chrono::steady_clock::time_point wallAt{};
        double cpuAt = 0.0;
        bool valid = false;
    };

    int m_workerCount;  // set before the workers start (they read it; m_workers grows meanwhile)
    std::vector<std::thread> m_workers;
    std::atomic<const TaskRef*> m_task{nullptr};  // the current run's task and count,
    std::atomic<int> m_count{0};                  //   published by m_ticket
    std::atomic<std::uint64_t> m_ticket{0};       // run number << 32 | front << 16 | back (parallel.cpp)
    std::atomic<std::uint32_t> m_done{0};         // tasks of the current run finished (a futex)
    std::atomic<std::uint32_t> m_posted{0};       // the newest run (a futex the workers sleep on)
    std::atomic<std::uint32_t> m_sleepers{0};     // workers asleep or about to sleep on m_posted
    std::atomic<std::uint32_t> m_callerAsleep{0}; // the caller asleep or about to sleep on m_done
    std::atomic<bool> m_stop{false};
    std::uint32_t m_runs = 0;                     // runs started (the caller's own count)
    // The fallback (the caller's own state): time the caller worked and waited over the
    // current window of runs, the solo period's length and end.
    double m_ownSeconds = 0.0, m_waitSeconds = 0.0;
    int m_windowRuns = 0;
    double m_soloLength = 0.0;  // seconds; 0: not running alone
    bool m_aloneAllowed = true;
    std::chrono::steady_clock::time_point m_soloUntil;
    double m_callerSpin = 200e-6;  // seconds the caller spins before it sleeps (adaptive)
    ContentionProbe m_callerProbe;
    ShareJudge m_share;
    ShareClock m_windowClock, m_soloClock;
    // ELASTIC_LAB_POOL_STATS: the owner's scheduler statistics when the pool was made (the
    // caller's, when the same thread runs the pool and destroys it) and the workers' at their
    // end (nanoseconds, summed), for the time the threads waited for a CPU.
    SchedStat m_ownerStatAt;
    std::thread::id m_owner;
    std::chrono::steady_clock::time_point m_madeAt;
    std::atomic<std::int64_t> m_workersRanNs{0}, m_workersWaitedNs{0};
    std::chrono::steady_clock::time_point m_lastRunEnd{};  // when the caller's last run ended
    std::atomic<std::int64_t> m_busyUntil{0};  // steady_clock ticks: contended until then
    std::atomic<int> m_callerCpu{-1};          // the CPU the caller posted the current run from (-1: unknown)
    // Counters (relaxed, read by counters()). The caller alone writes the runs, solo, caller
    // sleep and caller busy counts; every pool thread adds to the others (atomic adds).
    std::atomic<std::uint64_t> m_statRuns{0}, m_statSolo{0}, m_statCallerSleeps{0}, m_statWorkerSleeps{0},
        m_statWorkerTasks{0}, m_statSoloPeriods{0}, m_statBusyMarks{0}, m_statCallerBusyMarks{0},
        m_statSharedCpuTasks{0}, m_statMoves{0}, m_statStays{0}, m_statJoins{0}, m_statShareTrials{0},
        m_statShareWins{0};
};

// The CPU the calling thread runs on now (-1 where the system cannot tell).
int currentCpu();
// Moves the calling thread off CPU `cpu` to another CPU it may use: its affinity mask is narrowed
// to the others for a moment, which migrates it before the call returns, then given back whole
// (the scheduler leaves it where it now is until it has a reason to move it). Returns the CPU
// it moved to, or -1 when it did not move (one CPU allowed, `cpu` not among them, the system
// refused).
int moveOffCpu(int cpu);

// Moves the calling thread onto CPU `cpu` (its mask narrowed to that CPU for a moment, then given
// back whole). Returns the CPU it is on, or -1 when it did not move (`cpu` not allowed, the
// system refused).
int moveOntoCpu(int cpu);

// The threads runnable on the whole system now, the caller's included (the kernel's count in
// /proc/loadavg); -1 where the system cannot tell.
int runnableThreads();
// Whether a worker on the caller's CPU gains by moving off it, with `runnable` threads runnable
// (itself and the caller included; -1: unknown) and `cpus` CPUs allowed: when the others number
// fewer than the CPUs, some other CPU is less busy than the one the two share.
bool moveIsWorthIt(int runnable, int cpus);
// Whether a worker on another CPU than the caller's (a pool of two) gains by joining it: when the
// others number at least the CPUs (known, and at least two CPUs), a pair on one CPU gets that
// CPU, where split each shares a CPU with another program.
bool joinIsWorthIt(int runnable, int cpus);

// The number of hardware threads, at least 1.
int hardwareThreads();

// The CPUs this process may use, at least 1: the affinity mask (taskset, a Slurm job's CPU
// binding, a container's cpuset) and the cgroup's CPU quota (cpu.max in cgroup v2,
// cpu.cfs_quota_us / cpu.cfs_period_us in v1), rounded up. The default thread count.
int availableThreads();
// The threads a cgroup CPU quota allows: ceil(quota / period) from cgroup v2's cpu.max text
// ("150000 100000" -> 2); 0 when there is no quota ("max 100000") or the text is not one.
int quotaThreads(std::string_view cpuMax);

}  // namespace simcore
