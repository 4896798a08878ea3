#include "simcore/parallel.h"

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
}  // namespace

int hardwareThreads() {
    const unsigned n = std::thread::hardware_concurrency();
    return n == 0 ? 1 : static_cast<int>(n);
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

void ThreadPool::drain() {
    for (int i = m_next.fetch_add(1, std::memory_order_relaxed); i < m_count;
         i = m_next.fetch_add(1, std::memory_order_relaxed))
        (*m_task)(i);
}

void ThreadPool::workerLoop() {
    unsigned long seen = 0;
    for (;;) {
        int spins = 0;
        while (m_generation.load(std::memory_order_acquire) == seen &&
               !m_stop.load(std::memory_order_acquire)) {
            if (++spins < kSpinsBeforeSleep) {
                SIMCORE_CPU_RELAX();
                continue;
            }
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [&] {
                return m_generation.load(std::memory_order_acquire) != seen ||
                       m_stop.load(std::memory_order_acquire);
            });
        }
        if (m_stop.load(std::memory_order_acquire)) return;
        seen = m_generation.load(std::memory_order_acquire);
        drain();
        // Release: this worker's results and its last read of m_task happen before the caller
        // sees the count, so the caller may publish the next run.
        m_finishedWorkers.fetch_add(1, std::memory_order_acq_rel);
    }
}

void ThreadPool::run(int count, TaskRef task) {
    if (count <= 0) return;
    if (m_workers.empty() || count == 1) {
        for (int i = 0; i < count; ++i) task(i);
        return;
    }
    m_task = &task;
    m_count = count;
    m_next.store(0, std::memory_order_relaxed);
    m_finishedWorkers.store(0, std::memory_order_relaxed);
    {
        // Under the mutex, so a worker about to sleep cannot miss the new generation.
        std::lock_guard lock(m_mutex);
        m_generation.fetch_add(1, std::memory_order_acq_rel);
    }
    m_wake.notify_all();
    drain();
    // Every worker joins each run (and leaves drain() at once when no task is left): when all
    // have reported, none can still read m_task or m_next.
    const int workers = static_cast<int>(m_workers.size());
    int spins = 0;
    while (m_finishedWorkers.load(std::memory_order_acquire) < workers) {
        if (++spins < kSpinsBeforeSleep)
            SIMCORE_CPU_RELAX();
        else
            std::this_thread::yield();
    }
    m_task = nullptr;
}

}  // namespace simcore
