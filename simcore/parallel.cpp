#include "simcore/parallel.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include <climits>

#if defined(__linux__)
#include <fcntl.h>
#include <linux/futex.h>
#include <pthread.h>
#include <sched.h>
#include <time.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define SIMCORE_CPU_RELAX() _mm_pause()
#else
#define SIMCORE_CPU_RELAX() std::this_thread::yield()
#endif

namespace simcore {

namespace {
// A worker spins this many times for the next run before it sleeps (about 1 ms: a pause is
// ~50 ns here): a step dispatches about 17 runs, and waking a sleeping thread costs tens of us.
// At 2,000 spins (~100 us) the worker fell asleep during the caller's serial stretches at L6
// and each wake-up showed in the profile (scheduler functions ~4 %); 20,000 gave 270 -> 285
// steps/s there. Between bursts (the GUI's frames) it burns at most ~1 ms of a core.
constexpr int kSpinsBeforeSleep = 20000;
// The fewest spins of a worker that keeps finding no work (see workerLoop).
constexpr int kMinSpins = 64;
// The caller spins this long for a worker's last task before it sleeps on the futex: on a
// quiet machine balanced chunks end within tens of microseconds of each other; a worker that
// takes longer has most likely been preempted for a time slice (milliseconds), and the
// sleeping caller's CPU goes to whoever can use it (the worker itself, moved there). Halved
// after each run the caller slept through (a busy machine), doubled after each it did not.
constexpr double kCallerSpinMax = 200e-6, kCallerSpinMin = 20e-6;
// The fallback: over a window of runs (at least kWindowRuns and kWindowSeconds of them), the
// caller's own work and its waits for the workers after it are summed. Two threads take
// own + wait per run, the caller alone about 2 x own (balanced chunks): when the waits exceed
// the work, the caller runs alone for a while (kSoloFirst, doubled while the trials that
// follow keep failing, up to kSoloLongest), then tries the workers again for one window.
constexpr int kWindowRuns = 32;
constexpr double kWindowSeconds = 0.02;
constexpr double kSoloFirst = 0.05, kSoloLongest = 0.8;

// A CPU is contended when a thread of the pool was kept off it: over a check interval
// (kBusyCheck, at least; each thread checks itself, see keptOffCpu) it ran for less than three
// quarters of the time it did not sleep, and at least 0.2 ms less. Then, for kBusyFor, waits spin only briefly
// (kBusySpins pauses for a worker, kCallerSpinMin for the caller) and sleep: on a contended
// machine the process's threads share one scheduler group's fair share, and a thread spinning
// for its partner takes that time from the partner (or from the caller's serial stretches).
// Not every preemption: this virtual machine preempts a running thread once or twice every
// 2 ms when nothing else runs (a kernel thread, most likely; not traced), and
// when one involuntary context switch marked the pool busy (stops 36-38), it was busy about
// half the time on a quiet machine; the worker, spinning only kBusySpins pauses, slept through
// the caller's serial stretches between runs (half of them 5-20 us) and woke late: two threads
// ran the L6 sphere at 490-530 steps/s where 520-550 were there (stop 39).
constexpr auto kBusyCheck = std::chrono::milliseconds(2);
constexpr auto kBusyFor = std::chrono::milliseconds(50);
// When the caller's time between two runs is longer than kBetweenRuns (its serial stretches are
// 5-20 us at L6), it was outside the pool: a GUI frame's pause, a file written between steps.
// Its check then starts a new interval at the run (OffCpuProbe::restart). A check interval
// longer than 20 ms is not judged at all (OffCpuProbe's default).
constexpr auto kBetweenRuns = std::chrono::microseconds(500);
constexpr int kBusySpins = 256;
// A run's ticket: run number << 32 | front << 16 | back, the tasks not yet claimed being
// [front, back). The caller claims from the front, the workers from the back: with two threads
// and four chunks the caller runs 0 and 1 and the worker 3 and 2 run after run, so each keeps
// its own particles in its own cache, and only when one is late does the other take the chunk
// next to its own. (Claimed in one order, 0 1 2 3, a thread took whichever chunk came next, and
// the chunks' data moved between the CPUs' caches when either was late.)
constexpr std::uint64_t kTicketFront = std::uint64_t{1} << 16;
constexpr std::uint64_t kTicketMaxTasks = 0xffff;

using Clock = std::chrono::steady_clock;
double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

std::atomic<ThreadPool::TestHook> g_testHook{nullptr};
std::atomic<const ThreadPool::CpuHooks*> g_cpuHooks{nullptr};

int poolCurrentCpu() {
    const ThreadPool::CpuHooks* hooks = g_cpuHooks.load(std::memory_order_acquire);
    return hooks ? hooks->current() : currentCpu();
}
int poolMoveOffCpu(int cpu) {
    const ThreadPool::CpuHooks* hooks = g_cpuHooks.load(std::memory_order_acquire);
    return hooks ? hooks->moveOff(cpu) : moveOffCpu(cpu);
}
int poolMoveOntoCpu(int cpu) {
    const ThreadPool::CpuHooks* hooks = g_cpuHooks.load(std::memory_order_acquire);
    return hooks ? hooks->moveOnto(cpu) : moveOntoCpu(cpu);
}
double poolThreadCpuSeconds() {
    const ThreadPool::CpuHooks* hooks = g_cpuHooks.load(std::memory_order_acquire);
    return hooks ? hooks->threadCpu() : threadCpuSeconds();
}
int poolRunnableThreads() {
    const ThreadPool::CpuHooks* hooks = g_cpuHooks.load(std::memory_order_acquire);
    return hooks ? hooks->runnable() : runnableThreads();
}
// The CPUs the calling thread may use (its affinity mask; the hardware count where the system
// cannot tell).
int allowedCpus() {
#if defined(__linux__)
    cpu_set_t mask;
    CPU_ZERO(&mask);
    if (sched_getaffinity(0, sizeof mask, &mask) == 0) return std::max(1, CPU_COUNT(&mask));
#endif
    return hardwareThreads();
}
// How long a worker's judgement of the other CPUs' load holds (reading it costs a few
// microseconds; the worker may find itself on the caller's CPU at every run while it stays).
// On another CPU than the caller's (the usual place on a quiet machine) it judges only while it
// was kept off its own CPU lately (never on a quiet machine), at most every kJoinJudgementFor;
// it joins the caller at most every kJoinEvery (a join the kernel's balancer undoes is not
// tried again at every run).
constexpr auto kLoadJudgementFor = std::chrono::milliseconds(2);
constexpr auto kJoinJudgementFor = std::chrono::milliseconds(10);
constexpr auto kJoinEvery = std::chrono::milliseconds(50);
// A join the worker finds undone within kJoinHeld doubles the wait before the next, up to
// kJoinEvery << kJoinBackoffMost (3.2 s); one that held sets it back to kJoinEvery.
constexpr auto kJoinHeld = std::chrono::milliseconds(200);
constexpr int kJoinBackoffMost = 6;
// A join also needs the worker off its CPU for kJoinOffShare of the time it wanted to run over
// a span of kJoinSpan (stop 43): beside programs of the same weight a split thread is off about
// half the time; beside programs at a lower weight (other sessions, the lab's shell at a higher
// priority) about a tenth, in slices that still fail one 2 ms check, and there the pair joined
// onto one CPU gained nothing over one thread (1.01-1.06x, rounds lost).
constexpr auto kJoinSpan = std::chrono::milliseconds(20);
constexpr double kJoinOffShare = 0.3;

// Sleep while `word` holds `expected` (returns at once when it does not, and may return
// spuriously: callers check their condition again); wake every sleeper on `word`.
void futexWait(std::atomic<std::uint32_t>& word, std::uint32_t expected) {
#if defined(__linux__)
    static_assert(sizeof(std::atomic<std::uint32_t>) == sizeof(std::uint32_t));
    syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word), FUTEX_WAIT_PRIVATE, expected, nullptr, nullptr, 0);
#else
    word.wait(expected, std::memory_order_acquire);
#endif
}
void futexWakeAll(std::atomic<std::uint32_t>& word) {
#if defined(__linux__)
    syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word), FUTEX_WAKE_PRIVATE, INT_MAX, nullptr, nullptr, 0);
#else
    word.notify_all();
#endif
}

void runTask(const TaskRef& task, int index, bool worker) {
    if (const ThreadPool::TestHook hook = g_testHook.load(std::memory_order_acquire)) hook(index, worker);
    task(index);
}
}  // namespace

bool keptOffCpu(double wall, double cpu, double away) {
    const double wanted = wall - away, off = wanted - cpu;
    return wanted > 0.0 && cpu >= 0.0 && off > 0.25 * wanted && off > 2e-4;
}

bool OffCpuProbe::check(double wall, double cpu) {
    const bool judged = m_cpuAt >= 0.0 && cpu >= 0.0 && wall - m_wallAt <= m_longest;
    const bool off = judged && keptOffCpu(wall - m_wallAt, cpu - m_cpuAt, m_away);
    restart(wall, cpu);
    return off;
}

void OffCpuProbe::restart(double wall, double cpu) {
    m_wallAt = wall;
    m_cpuAt = cpu;
    m_away = 0.0;
}

ShareJudge::Verdict ShareJudge::together(double now, double wall, double cpu) {
    const double aloneShare = m_aloneShare;
    m_aloneShare = -1.0;
    if (!(wall > 0.0) || cpu < 0.0) return Verdict::Together;
    const double share = cpu / wall;
    if (aloneShare >= 0.0) {  // the window after a stretch alone
        if (aloneShare > kMargin * share) {
            m_backoff = kBackoffFirst;  // alone won: a trial after it loses starts the waits short
            return Verdict::Alone;
        }
        m_trialAfter = now + m_backoff;  // alone lost: the next trial later
        m_backoff = std::min(2.0 * m_backoff, kBackoffLongest);
        return Verdict::Together;
    }
    // Under one CPU together (at least a CPU: alone cannot win), in two windows in a row: beside
    // two busy programs the pair's share hovers about one CPU, and one window in forty there
    // fell under (stop 43). A window at a CPU or more does not shorten the wait before the next
    // trial (trials that lose would come every 0.2 s there), nor does a trial that cannot be
    // judged (the caller preempted or away for a while during it).
    m_lowWindows = share < kMayWin ? m_lowWindows + 1 : 0;
    if (m_lowWindows < 2 || now < m_trialAfter) return Verdict::Together;
    m_lowWindows = 0;
    m_trialAfter = now + m_backoff;
    return Verdict::Try;
}

void ShareJudge::alone(double wall, double cpu) { m_aloneShare = wall > 0.0 && cpu >= 0.0 ? cpu / wall : -1.0; }

int currentCpu() {
#if defined(__linux__)
    return sched_getcpu();
#else
    return -1;
#endif
}

namespace {
// Moves the calling thread within its affinity mask: `pick` narrows a copy of the mask (false:
// no move), the thread runs under the narrowed mask for a moment (the kernel migrates it before
// the call returns), then gets its whole mask back. Returns the CPU it is on then, or -1.
template <class Narrow>
int moveWithinMask(int cpu, Narrow pick) {
#if defined(__linux__)
    cpu_set_t mask;
    CPU_ZERO(&mask);
    if (cpu < 0 || cpu >= CPU_SETSIZE || sched_getaffinity(0, sizeof mask, &mask) != 0 || !CPU_ISSET(cpu, &mask))
        return -1;
    cpu_set_t narrowed = mask;
    if (!pick(narrowed) || sched_setaffinity(0, sizeof narrowed, &narrowed) != 0) return -1;
    const int now = sched_getcpu();
    sched_setaffinity(0, sizeof mask, &mask);
    return now;
#else
    (void)cpu;
    (void)pick;
    return -1;
#endif
}
}  // namespace

int moveOffCpu(int cpu) {
#if defined(__linux__)
    return moveWithinMask(cpu, [cpu](cpu_set_t& set) {  // the others: `cpu` is then forbidden
        if (CPU_COUNT(&set) < 2) return false;
        CPU_CLR(cpu, &set);
        return true;
    });
#else
    (void)cpu;
    return -1;
#endif
}

int moveOntoCpu(int cpu) {
#if defined(__linux__)
    return moveWithinMask(cpu, [cpu](cpu_set_t& set) {  // `cpu` alone
        CPU_ZERO(&set);
        CPU_SET(cpu, &set);
        return true;
    });
#else
    (void)cpu;
    return -1;
#endif
}

int runnableThreads() {
#if defined(__linux__)
    // "0.52 0.58 0.59 3/210 4567": the fourth field is runnable / all scheduling entities.
    const int fd = ::open("/proc/loadavg", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return -1;
    char text[128];
    const ssize_t n = ::read(fd, text, sizeof text - 1);
    ::close(fd);
    if (n <= 0) return -1;
    text[n] = '\0';
    const char* field = text;
    for (int i = 0; i < 3; ++i) {
        field = std::strchr(field, ' ');
        if (!field) return -1;
        ++field;
    }
    int runnable = -1;
    const auto [end, ec] = std::from_chars(field, text + n, runnable);
    return ec == std::errc() && *end == '/' ? runnable : -1;
#else
    return -1;
#endif
}

bool moveIsWorthIt(int runnable, int cpus) { return cpus >= 2 && (runnable < 0 || runnable - 2 < cpus); }
bool joinIsWorthIt(int runnable, int cpus) { return cpus >= 2 && runnable >= 0 && runnable - 2 >= cpus; }

double threadCpuSeconds() {
#if defined(__linux__)
    timespec t{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t) == 0) return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
#endif
    return -1.0;
}

SchedStat threadSchedStat() {
#if defined(__linux__)
    const int fd = ::open("/proc/thread-self/schedstat", O_RDONLY | O_CLOEXEC);
    if (fd < 0) return {};
    char text[96];
    const ssize_t n = ::read(fd, text, sizeof text - 1);
    ::close(fd);
    if (n <= 0) return {};
    text[n] = '\0';
    std::uint64_t ran = 0, waited = 0;
    const char* end = text + n;
    const auto first = std::from_chars(text, end, ran);
    if (first.ec != std::errc() || first.ptr == end || *first.ptr != ' ') return {};
    if (std::from_chars(first.ptr + 1, end, waited).ec != std::errc()) return {};
    return {1e-9 * static_cast<double>(ran), 1e-9 * static_cast<double>(waited)};
#else
    return {};
#endif
}

int hardwareThreads() {
    const unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : static_cast<int>(n);
}

int quotaThreads(std::string_view cpuMax) {
    // "<quota> <period>" in microseconds, or "max <period>" for no quota.
    const std::size_t space = cpuMax.find(' ');
    if (space == std::string_view::npos) return 0;
    auto number = [](std::string_view text, double& out) {
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, out);
        return ec == std::errc() && ptr == end;
    };
    double quota = 0.0, period = 0.0;
    if (!number(cpuMax.substr(0, space), quota) || !number(cpuMax.substr(space + 1), period)) return 0;
    if (!(quota > 0.0) || !(period > 0.0)) return 0;
    return std::max(1, static_cast<int>(std::ceil(quota / period - 1e-9)));
}

namespace {

std::string readSmallFile(const std::string& path) {
    std::ifstream in(path);
    std::string text;
    std::getline(in, text, '\0');
    return text;
}

// The threads the cgroup's CPU quota allows (0: none): cgroup v2 from the process's cgroup up
// to the root (the smallest quota on the way holds), else cgroup v1's cpu controller.
int cgroupThreads() {
    std::istringstream lines(readSmallFile("/proc/self/cgroup"));
    int threads = 0;
    auto take = [&threads](int n) {
        if (n > 0 && (threads == 0 || n < threads)) threads = n;
    };
    for (std::string line; std::getline(lines, line);) {
        const std::size_t first = line.find(':'), second = line.find(':', first + 1);
        if (first == std::string::npos || second == std::string::npos) continue;
        const std::string controllers = line.substr(first + 1, second - first - 1);
        std::string path = line.substr(second + 1);
        if (controllers.empty()) {  // cgroup v2
            for (;;) {
                take(quotaThreads(readSmallFile("/sys/fs/cgroup" + path + "/cpu.max")));
                if (path.empty() || path == "/") break;
                path = path.substr(0, path.rfind('/'));
            }
        } else if (controllers.find("cpu") != std::string::npos) {  // cgroup v1
            const std::string dir = "/sys/fs/cgroup/" + controllers + path;
            const std::string quota = readSmallFile(dir + "/cpu.cfs_quota_us");
            const std::string period = readSmallFile(dir + "/cpu.cfs_period_us");
            if (!quota.empty() && !period.empty()) take(quotaThreads(quota + " " + period));
        }
    }
    return threads;
}

}  // namespace

int availableThreads() {
#if defined(__linux__)
    const int n = allowedCpus();
    const int quota = cgroupThreads();
    return quota > 0 ? std::min(n, quota) : n;
#else
    return hardwareThreads();
#endif
}

ThreadPool::ThreadPool(int threads)
    : m_workerCount(std::max(0, threads - 1)),
      m_ownerStatAt(threadSchedStat()),
      m_owner(std::this_thread::get_id()),
      m_madeAt(Clock::now()) {
    for (int i = 1; i < threads; ++i) m_workers.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
    // A new "run" number with m_stop set: spinning workers see it, sleeping ones are woken.
    m_stop.store(true, std::memory_order_seq_cst);
    m_posted.fetch_add(1, std::memory_order_seq_cst);
    futexWakeAll(m_posted);
    for (std::thread& t : m_workers) t.join();
    // ELASTIC_LAB_POOL_STATS=1: what the waits did, on stderr (scripts/threads-beside-stress.sh).
    if (const char* stats = std::getenv("ELASTIC_LAB_POOL_STATS"); stats && *stats == '1' && !m_workers.empty())
        printStats();
}

void ThreadPool::printStats() const {
    const Counters c = counters();
    // The threads' scheduler statistics over the pool's life: the caller's only when the thread
    // that made the pool destroys it (it is then, in every use here, the one that ran it).
    const double lived = seconds(Clock::now() - m_madeAt);
    const SchedStat owner = std::this_thread::get_id() == m_owner ? threadSchedStat() : SchedStat{};
    const bool known = owner.waited >= 0.0 && m_ownerStatAt.waited >= 0.0;
    const double callerRan = known ? owner.ran - m_ownerStatAt.ran : -1e-3;
    const double callerWaited = known ? owner.waited - m_ownerStatAt.waited : -1e-3;
    std::fprintf(stderr,
                 "pool: %llu runs, %llu alone in %llu periods, caller slept %llu, worker slept %llu, worker tasks %llu, "
                 "kept off a CPU %llu, worker tasks on the caller's CPU %llu, moved off it %llu, stayed %llu, "
                 "joined it %llu, tried alone by the CPU share %llu, alone won %llu, over %.0f ms the caller ran %.0f ms "
                 "and waited for a CPU %.0f ms, the workers ran %.0f ms and waited %.0f ms (the caller's -1 where unknown)\n",
                 static_cast<unsigned long long>(c.runs), static_cast<unsigned long long>(c.soloRuns),
                 static_cast<unsigned long long>(c.soloPeriods), static_cast<unsigned long long>(c.callerSleeps),
                 static_cast<unsigned long long>(c.workerSleeps), static_cast<unsigned long long>(c.workerTasks),
                 static_cast<unsigned long long>(c.busyMarks), static_cast<unsigned long long>(c.sharedCpuTasks),
                 static_cast<unsigned long long>(c.moves), static_cast<unsigned long long>(c.stays),
                 static_cast<unsigned long long>(c.joins), static_cast<unsigned long long>(c.shareTrials),
                 static_cast<unsigned long long>(c.shareWins), 1e3 * lived, 1e3 * callerRan, 1e3 * callerWaited,
                 1e-6 * static_cast<double>(m_workersRanNs.load(std::memory_order_relaxed)),
                 1e-6 * static_cast<double>(m_workersWaitedNs.load(std::memory_order_relaxed)));
}

void ThreadPool::setTestHook(TestHook hook) { g_testHook.store(hook, std::memory_order_release); }
void ThreadPool::setCpuHooks(const CpuHooks* hooks) { g_cpuHooks.store(hooks, std::memory_order_release); }

ThreadPool::Counters ThreadPool::counters() const {
    Counters c;
    c.runs = m_statRuns.load(std::memory_order_relaxed);
    c.soloRuns = m_statSolo.load(std::memory_order_relaxed);
    c.callerSleeps = m_statCallerSleeps.load(std::memory_order_relaxed);
    c.workerSleeps = m_statWorkerSleeps.load(std::memory_order_relaxed);
    c.workerTasks = m_statWorkerTasks.load(std::memory_order_relaxed);
    c.soloPeriods = m_statSoloPeriods.load(std::memory_order_relaxed);
    c.busyMarks = m_statBusyMarks.load(std::memory_order_relaxed);
    c.callerBusyMarks = m_statCallerBusyMarks.load(std::memory_order_relaxed);
    c.sharedCpuTasks = m_statSharedCpuTasks.load(std::memory_order_relaxed);
    c.moves = m_statMoves.load(std::memory_order_relaxed);
    c.stays = m_statStays.load(std::memory_order_relaxed);
    c.joins = m_statJoins.load(std::memory_order_relaxed);
    c.shareTrials = m_statShareTrials.load(std::memory_order_relaxed);
    c.shareWins = m_statShareWins.load(std::memory_order_relaxed);
    return c;
}

double ThreadPool::poolCpuSeconds() {
    const double caller = poolThreadCpuSeconds();
    if (caller < 0.0) return -1.0;
    if (const CpuHooks* hooks = g_cpuHooks.load(std::memory_order_acquire); hooks && hooks->workersCpu) {
        const double workers = hooks->workersCpu(*this);
        return workers < 0.0 ? -1.0 : caller + workers;
    }
    double workers = 0.0;
#if defined(__linux__)
    for (std::thread& worker : m_workers) {
        clockid_t clock{};
        timespec t{};
        if (pthread_getcpuclockid(worker.native_handle(), &clock) != 0 || clock_gettime(clock, &t) != 0) return -1.0;
        workers += static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
    }
    return caller + workers;
#else
    return -1.0;
#endif
}

bool ThreadPool::contended(ContentionProbe& probe) {
    const Clock::time_point now = Clock::now();
    const std::int64_t ticks = now.time_since_epoch().count();
    if (now >= probe.nextCheck) {
        probe.nextCheck = now + kBusyCheck;
        if (probe.offCpu.check(seconds(now.time_since_epoch()), poolThreadCpuSeconds())) {
            probe.keptOffAt = now;
            m_busyUntil.store(ticks + std::chrono::duration_cast<Clock::duration>(kBusyFor).count(),
                              std::memory_order_relaxed);
            m_statBusyMarks.fetch_add(1, std::memory_order_relaxed);
            if (&probe == &m_callerProbe) m_statCallerBusyMarks.fetch_add(1, std::memory_order_relaxed);
        }
    }
    return ticks < m_busyUntil.load(std::memory_order_relaxed);
}

int ThreadPool::claimTasks(std::uint32_t run, bool worker) {
    int claimed = 0;
    std::uint64_t ticket = m_ticket.load(std::memory_order_acquire);
    for (;;) {
        if (static_cast<std::uint32_t>(ticket >> 32) != run) return claimed;  // a later run has begun
        // The caller takes tasks from the front, the workers from the back (see kTicketFront).
        const auto front = static_cast<int>((ticket >> 16) & 0xffffu), back = static_cast<int>(ticket & 0xffffu);
        if (front >= back) return claimed;
        const int index = worker ? back - 1 : front;
        // A count read after a later run was posted only makes the claim below fail.
        const int count = m_count.load(std::memory_order_acquire);
        if (!m_ticket.compare_exchange_weak(ticket, worker ? ticket - 1 : ticket + kTicketFront, std::memory_order_acq_rel,
                                            std::memory_order_acquire))
            continue;
        // Task `index` of this run is ours: the caller waits for it, so the run (and its task)
        // lives until we report it done.
        runTask(*m_task.load(std::memory_order_acquire), index, worker);
        // The last task done wakes the caller if it sleeps. Sequentially consistent with the
        // caller's "asleep" flag and its reading of m_done: either it sees this count, or this
        // thread sees its flag (no lost wake-up).
        const std::uint32_t done = m_done.fetch_add(1, std::memory_order_seq_cst) + 1;
        if (worker && done == static_cast<std::uint32_t>(count) && m_callerAsleep.load(std::memory_order_seq_cst) != 0)
            futexWakeAll(m_done);
        ++claimed;
        ticket = m_ticket.load(std::memory_order_acquire);
    }
}

int ThreadPool::placeWorker(WorkerPlacement& at, const ContentionProbe& probe) {
    const Clock::time_point keptOffAt = probe.keptOffAt;
    // On the caller's CPU the two would only take turns (see parallel.h): move first,
    // unless the other CPUs are as busy (moveIsWorthIt, judged at most every
    // kLoadJudgementFor). On another CPU while they are as busy, join the caller's: the two
    // then take turns on a CPU the kernel's balancer soon leaves to them, where split each
    // would share a CPU with another program and wait for the other at every run. Only a
    // pool of two (more threads on one CPU would give up more CPUs than they gain), only when
    // this worker was found kept off its CPU lately, and less often each time the kernel undoes
    // the join at once (see parallel.h).
    int cpu = poolCurrentCpu();
    const int callerCpu = m_callerCpu.load(std::memory_order_relaxed);
    const auto judgeLoad = [&](Clock::time_point now, Clock::duration hold) {
        if (now < at.judgedUntil) return;
        const int runnable = poolRunnableThreads(), cpus = allowedCpus();
        at.moveWorthIt = moveIsWorthIt(runnable, cpus);
        // The count is the kernel's at one instant (a kernel thread woken for a moment
        // counts): a join needs two judgements in a row.
        at.joinStreak = joinIsWorthIt(runnable, cpus) ? at.joinStreak + 1 : 0;
        at.judgedUntil = now + hold;
    };
    if (cpu >= 0 && cpu == callerCpu) {
        at.together = true;
        judgeLoad(Clock::now(), kLoadJudgementFor);
        if (!at.moveWorthIt) {
            m_statStays.fetch_add(1, std::memory_order_relaxed);
        } else if (const int moved = poolMoveOffCpu(cpu); moved >= 0) {
            m_statMoves.fetch_add(1, std::memory_order_relaxed);
            cpu = moved;
        }
    } else if (cpu >= 0 && callerCpu >= 0 && m_workerCount == 1) {
        const Clock::time_point now = Clock::now();
        if (at.together) {  // split since the last run: a join undone soon after is backed off
            at.together = false;
            if (at.joinedAt != Clock::time_point{})
                at.joinBackoff = now - at.joinedAt < kJoinHeld ? std::min(at.joinBackoff + 1, kJoinBackoffMost) : 0;
            at.joinedAt = Clock::time_point{};
        }
        const bool keptOff = keptOffAt != Clock::time_point{} && now - keptOffAt < kBusyFor;
        if (!keptOff) {  // no judgement of the load either: nothing is read on a quiet machine
            at.joinStreak = 0;
            at.spanCpuAt = -1.0;
            return cpu;
        }
        // The share of the last span off the CPU (a span begins at the first run kept off).
        if (at.spanCpuAt < 0.0 || now - at.spanAt >= kJoinSpan) {
            const double cpuNow = poolThreadCpuSeconds();
            if (at.spanCpuAt >= 0.0 && cpuNow >= 0.0) {
                const double wanted = seconds(now - at.spanAt) - (probe.asleep - at.spanAwayAt);
                at.offShare = wanted > 0.0 ? std::max(0.0, wanted - (cpuNow - at.spanCpuAt)) / wanted : 0.0;
            } else {
                at.offShare = 0.0;
            }
            at.spanAt = now;
            at.spanCpuAt = cpuNow;
            at.spanAwayAt = probe.asleep;
        }
        if (at.offShare < kJoinOffShare) return cpu;
        judgeLoad(now, kJoinJudgementFor);
        if (at.joinStreak >= 2 && now >= at.joinAfter) {
            at.joinAfter = now + kJoinEvery * (1 << at.joinBackoff);
            if (const int joined = poolMoveOntoCpu(callerCpu); joined >= 0) {
                m_statJoins.fetch_add(1, std::memory_order_relaxed);
                cpu = joined;
                at.together = true;
                at.joinedAt = now;
            }
        }
    }
    return cpu;
}

void ThreadPool::workerLoop() {
    std::uint32_t seen = 0;
    // How long to spin for the next run: the full time while this worker finds work, a few
    // spins once it keeps arriving after the caller has done everything (a busy machine, where
    // spinning only takes time from the caller, which shares the CPU with it).
    int spinLimit = kSpinsBeforeSleep;
    ContentionProbe probe;
    WorkerPlacement placement;
    for (;;) {
        int spins = 0;
        const int limit = contended(probe) ? std::min(spinLimit, kBusySpins) : spinLimit;
        std::uint32_t posted = 0;
        while ((posted = m_posted.load(std::memory_order_acquire)) == seen) {
            if (++spins < limit) {
                SIMCORE_CPU_RELAX();
                continue;
            }
            // Announce the sleep, then check again (both sequentially consistent, as the
            // caller's post and its reading of m_sleepers): either the new run is seen here,
            // or the caller sees a sleeper and wakes it. The futex sleeps only while m_posted
            // still holds `seen`.
            m_sleepers.fetch_add(1, std::memory_order_seq_cst);
            if (m_posted.load(std::memory_order_seq_cst) == seen) {
                m_statWorkerSleeps.fetch_add(1, std::memory_order_relaxed);
                const Clock::time_point asleep = Clock::now();
                futexWait(m_posted, seen);
                const double slept = seconds(Clock::now() - asleep);
                probe.offCpu.away(slept);
                probe.asleep += slept;
            }
            m_sleepers.fetch_sub(1, std::memory_order_seq_cst);
        }
        if (m_stop.load(std::memory_order_acquire)) {
            if (const SchedStat stat = threadSchedStat(); stat.waited >= 0.0) {
                m_workersRanNs.fetch_add(static_cast<std::int64_t>(1e9 * stat.ran), std::memory_order_relaxed);
                m_workersWaitedNs.fetch_add(static_cast<std::int64_t>(1e9 * stat.waited), std::memory_order_relaxed);
            }
            return;
        }
        seen = posted;
        const int cpu = placeWorker(placement, probe);
        const int ran = claimTasks(seen, true);
        if (ran > 0) {
            m_statWorkerTasks.fetch_add(static_cast<std::uint64_t>(ran), std::memory_order_relaxed);
            if (cpu >= 0 && cpu == m_callerCpu.load(std::memory_order_relaxed))
                m_statSharedCpuTasks.fetch_add(static_cast<std::uint64_t>(ran), std::memory_order_relaxed);
        }
        spinLimit = ran > 0 ? std::min(2 * spinLimit, kSpinsBeforeSleep) : std::max(spinLimit / 4, kMinSpins);
    }
}

bool ThreadPool::waitForTasks(int count) {
    const auto all = static_cast<std::uint32_t>(count);
    bool slept = false;
    const Clock::time_point start = Clock::now();
    for (int spins = 1;; ++spins) {
        const std::uint32_t done = m_done.load(std::memory_order_acquire);
        if (done >= all) break;
        if ((spins & 31) != 0 || seconds(Clock::now() - start) < m_callerSpin) {
            SIMCORE_CPU_RELAX();
            continue;
        }
        // Announce the sleep, then read m_done again (see claimTasks): the worker that finishes
        // the last task either is seen here or sees the flag and wakes us.
        m_callerAsleep.store(1, std::memory_order_seq_cst);
        if (m_done.load(std::memory_order_seq_cst) == done) {
            m_statCallerSleeps.fetch_add(1, std::memory_order_relaxed);
            const Clock::time_point asleep = Clock::now();
            futexWait(m_done, done);
            m_callerProbe.offCpu.away(seconds(Clock::now() - asleep));
            slept = true;
        }
        m_callerAsleep.store(0, std::memory_order_seq_cst);
    }
    m_callerSpin = slept ? std::max(m_callerSpin / 2, kCallerSpinMin) : std::min(m_callerSpin * 2, kCallerSpinMax);
    return slept;
}

void ThreadPool::judgeRun(double ownSeconds, double waitSeconds) {
    m_ownSeconds += ownSeconds;
    m_waitSeconds += waitSeconds;
    if (++m_windowRuns < kWindowRuns || m_ownSeconds + m_waitSeconds < kWindowSeconds) return;
    // One window judged: the workers cost more than they bring when the caller waited for them
    // longer than it worked, or when the pool's threads together got a smaller share of a CPU
    // than the caller alone gets (ShareJudge). Which thread runs a task never changes a result,
    // so these clocks decide speed only.
    const Clock::time_point now = Clock::now();
    ShareJudge::Verdict share = ShareJudge::Verdict::Together;
    if (m_windowClock.valid) {
        const double cpu = poolCpuSeconds();
        share = m_share.together(seconds(now.time_since_epoch()), seconds(now - m_windowClock.wallAt),
                                 cpu < 0.0 ? -1.0 : cpu - m_windowClock.cpuAt);
    } else {
        m_share.dropAlone();
    }
    m_windowClock.valid = false;
    if ((m_waitSeconds > m_ownSeconds || share != ShareJudge::Verdict::Together) && m_aloneAllowed) {
        m_soloLength = m_soloLength == 0 ? kSoloFirst : std::min(2 * m_soloLength, kSoloLongest);
        m_soloUntil = now + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(m_soloLength));
        const double cpu = poolThreadCpuSeconds();
        m_soloClock = {now, cpu, cpu >= 0.0};
        m_statSoloPeriods.fetch_add(1, std::memory_order_relaxed);
        if (share == ShareJudge::Verdict::Try) m_statShareTrials.fetch_add(1, std::memory_order_relaxed);
        if (share == ShareJudge::Verdict::Alone) m_statShareWins.fetch_add(1, std::memory_order_relaxed);
    } else {
        m_soloLength = 0;  // two threads pay: the next solo period (if any) starts short
    }
    m_ownSeconds = m_waitSeconds = 0.0;
    m_windowRuns = 0;
}

void ThreadPool::run(int count, TaskRef task) {
    if (count <= 0) return;
    if (static_cast<std::uint64_t>(count) > kTicketMaxTasks) {
        // More tasks than a ticket counts: in runs of at most kTicketMaxTasks, in order.
        for (int first = 0; first < count; first += static_cast<int>(kTicketMaxTasks)) {
            const int n = std::min(count - first, static_cast<int>(kTicketMaxTasks));
            auto part = [&](int i) { task(first + i); };
            run(n, part);
        }
        return;
    }
    if (m_workers.empty() || count == 1) {
        for (int i = 0; i < count; ++i) runTask(task, i, false);
        return;
    }
    m_statRuns.fetch_add(1, std::memory_order_relaxed);
    const Clock::time_point entered = Clock::now();
    if (entered - m_lastRunEnd > kBetweenRuns) {
        m_callerProbe.offCpu.restart(seconds(entered.time_since_epoch()), poolThreadCpuSeconds());
        m_callerProbe.nextCheck = entered + kBusyCheck;
        m_windowClock.valid = m_soloClock.valid = false;  // the caller was outside the pool: no share to judge
    }
    if (contended(m_callerProbe)) m_callerSpin = kCallerSpinMin;
    if (m_soloLength > 0 && m_windowRuns == 0) {
        // Running alone (the fallback) until m_soloUntil; then one window with the workers.
        if (entered < m_soloUntil) {
            m_statSolo.fetch_add(1, std::memory_order_relaxed);
            for (int i = 0; i < count; ++i) runTask(task, i, false);
            m_lastRunEnd = Clock::now();
            return;
        }
        // The stretch alone is over: the caller's share over it, for the window's judgement.
        const double cpu = poolThreadCpuSeconds();
        if (m_soloClock.valid && cpu >= 0.0) m_share.alone(seconds(entered - m_soloClock.wallAt), cpu - m_soloClock.cpuAt);
        else m_share.dropAlone();
        m_soloClock.valid = false;
    }
    if (m_windowRuns == 0) {
        const double cpu = poolCpuSeconds();
        m_windowClock = {entered, cpu, cpu >= 0.0};
    }
    const std::uint32_t run = ++m_runs;
    // Close the ticket first: a worker still holding the last run's ticket (it read it before
    // this run began) must not claim an index of this run against this run's count. Its
    // compare-and-swap fails once the ticket has moved, and a worker that sees the new count
    // (released below) also sees the closed ticket.
    m_ticket.store((static_cast<std::uint64_t>(run) << 32) | (kTicketMaxTasks * kTicketFront), std::memory_order_release);
    m_task.store(&task, std::memory_order_release);
    m_count.store(count, std::memory_order_release);
    m_callerCpu.store(poolCurrentCpu(), std::memory_order_relaxed);  // released with the ticket below
    m_done.store(0, std::memory_order_release);
    // Open it: the task, its count and the cleared counter are visible to whoever claims.
    m_ticket.store((static_cast<std::uint64_t>(run) << 32) | static_cast<std::uint64_t>(count), std::memory_order_release);
    // Post it, then wake sleeping workers (sequentially consistent with a worker's "asleep"
    // count and its reading of m_posted: see workerLoop).
    m_posted.store(run, std::memory_order_seq_cst);
    if (m_sleepers.load(std::memory_order_seq_cst) != 0) futexWakeAll(m_posted);
    const Clock::time_point start = Clock::now();
    claimTasks(run, false);
    const Clock::time_point own = Clock::now();
    waitForTasks(count);
    m_lastRunEnd = Clock::now();
    judgeRun(seconds(own - start), seconds(m_lastRunEnd - own));
}

}  // namespace simcore
