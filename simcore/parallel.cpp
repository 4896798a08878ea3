#include "simcore/parallel.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#if defined(__linux__)
#include <sched.h>
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
// A run is late when its caller waited this long for a worker after the others were done (a
// preempted worker: balanced chunks end within microseconds of each other); after this many
// late runs (net of on-time ones) the caller runs the next kSoloRuns runs alone. Which thread
// runs a task never changes a result, so this clock decides speed only.
constexpr auto kLateWait = std::chrono::microseconds(300);
constexpr int kLateRunsBeforeSolo = 8;
constexpr int kSoloRuns = 2000;
}  // namespace

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
    int n = hardwareThreads();
#if defined(__linux__)
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) n = std::max(1, CPU_COUNT(&set));
    if (const int quota = cgroupThreads(); quota > 0) n = std::min(n, quota);
#endif
    return n;
}

ThreadPool::ThreadPool(int threads) {
    for (int i = 1; i < threads; ++i) m_workers.emplace_back([this] { workerLoop(); });
}

ThreadPool::~ThreadPool() {
    {
        std::lock_guard lock(m_mutex);
        m_stop.store(true, std::memory_order_release);
    }
    m_wake.notify_all();
    for (std::thread& t : m_workers) t.join();
}

int ThreadPool::claimTasks(std::uint32_t run) {
    int claimed = 0;
    std::uint64_t ticket = m_ticket.load(std::memory_order_acquire);
    for (;;) {
        if (static_cast<std::uint32_t>(ticket >> 32) != run) return claimed;  // a later run has begun
        const auto index = static_cast<int>(ticket & 0xffffffffu);
        // A count read after a later run was posted only makes the claim below fail.
        if (index >= m_count.load(std::memory_order_acquire)) return claimed;
        if (!m_ticket.compare_exchange_weak(ticket, ticket + 1, std::memory_order_acq_rel,
                                            std::memory_order_acquire))
            continue;
        // Task `index` of this run is ours: the caller waits for it, so the run (and its task)
        // lives until we report it done.
        (*m_task.load(std::memory_order_acquire))(index);
        m_done.fetch_add(1, std::memory_order_acq_rel);
        ++claimed;
        ticket = m_ticket.load(std::memory_order_acquire);
    }
}

void ThreadPool::workerLoop() {
    std::uint32_t seen = 0;
    // How long to spin for the next run: the full time while this worker finds work, a few
    // spins once it keeps arriving after the caller has done everything (a busy machine, where
    // spinning only takes time from the caller, which shares the CPU with it).
    int spinLimit = kSpinsBeforeSleep;
    for (;;) {
        int spins = 0;
        while (m_posted.load(std::memory_order_acquire) == seen && !m_stop.load(std::memory_order_acquire)) {
            if (++spins < spinLimit) {
                SIMCORE_CPU_RELAX();
                continue;
            }
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [&] {
                return m_posted.load(std::memory_order_acquire) != seen || m_stop.load(std::memory_order_acquire);
            });
        }
        if (m_stop.load(std::memory_order_acquire)) return;
        seen = m_posted.load(std::memory_order_acquire);
        spinLimit = claimTasks(seen) > 0 ? std::min(2 * spinLimit, kSpinsBeforeSleep)
                                         : std::max(spinLimit / 4, kMinSpins);
    }
}

void ThreadPool::run(int count, TaskRef task) {
    if (count <= 0) return;
    if (m_workers.empty() || count == 1 || m_soloRuns > 0) {
        if (m_soloRuns > 0) --m_soloRuns;
        for (int i = 0; i < count; ++i) task(i);
        return;
    }
    const std::uint32_t run = ++m_runs;
    // Close the ticket first: a worker still holding the last run's ticket (it read it before
    // this run began) must not claim an index of this run against this run's count. Its
    // compare-and-swap fails once the ticket has moved, and a worker that sees the new count
    // (released below) also sees the closed ticket.
    m_ticket.store((static_cast<std::uint64_t>(run) << 32) | 0xffffffffu, std::memory_order_release);
    m_task.store(&task, std::memory_order_release);
    m_count.store(count, std::memory_order_release);
    m_done.store(0, std::memory_order_release);
    // Open it: the task, its count and the cleared counter are visible to whoever claims.
    m_ticket.store(static_cast<std::uint64_t>(run) << 32, std::memory_order_release);
    {
        // Under the mutex, so a worker about to sleep cannot miss the new run.
        std::lock_guard lock(m_mutex);
        m_posted.store(run, std::memory_order_release);
    }
    m_wake.notify_all();
    claimTasks(run);
    // Every task has been claimed; wait for the ones a worker is still running. Spin a little,
    // then yield: on a quiet machine yielding returns at once, on a busy one it lets the
    // worker (or whoever holds the CPU it waits for) finish sooner.
    int spins = 0;
    std::chrono::steady_clock::time_point yieldingSince;
    bool late = false;
    while (m_done.load(std::memory_order_acquire) < count) {
        if (++spins < kMinSpins * 4) {
            SIMCORE_CPU_RELAX();
            continue;
        }
        if (spins == kMinSpins * 4) yieldingSince = std::chrono::steady_clock::now();
        std::this_thread::yield();
        if (!late && (spins & 15) == 0) late = std::chrono::steady_clock::now() - yieldingSince > kLateWait;
    }
    // A worker that keeps holding up the runs (preempted in the middle of its task: a machine
    // busier than its CPUs) costs more than it brings: the caller then runs alone for a while
    // and tries again. Which thread runs a task never changes a result.
    m_lateRuns = late ? m_lateRuns + 1 : std::max(0, m_lateRuns - 1);
    if (m_lateRuns >= kLateRunsBeforeSolo) {
        m_lateRuns = 0;
        m_soloRuns = kSoloRuns;
    }
}

}  // namespace simcore
