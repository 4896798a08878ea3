#include "parallel.h"

namespace simcore {

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
        m_stop = true;
    }
    m_wake.notify_all();
    for (std::thread& t : m_workers) t.join();
}

void ThreadPool::drain() {
    for (int i = m_next.fetch_add(1); i < m_count; i = m_next.fetch_add(1)) {
        (*m_task)(i);
    }
}

void ThreadPool::workerLoop() {
    unsigned long seen = 0;
    for (;;) {
        {
            std::unique_lock lock(m_mutex);
            m_wake.wait(lock, [&] { return m_stop || m_generation != seen; });
            if (m_stop) return;
            seen = m_generation;
            ++m_busyWorkers;
            ++m_joined;
        }
        drain();
        {
            std::lock_guard lock(m_mutex);
            --m_busyWorkers;
        }
        m_done.notify_all();
    }
}

void ThreadPool::run(int count, const std::function<void(int)>& task) {
    if (count <= 0) return;
    if (m_workers.empty() || count == 1) {
        for (int i = 0; i < count; ++i) task(i);
        return;
    }
    {
        std::lock_guard lock(m_mutex);
        m_task = &task;
        m_count = count;
        m_next.store(0);
        m_joined = 0;
        ++m_generation;
    }
    m_wake.notify_all();
    drain();
    // Wait until every worker has joined this generation and left drain(): no late worker can
    // then read m_task or m_next of the next run.
    std::unique_lock lock(m_mutex);
    const int workers = static_cast<int>(m_workers.size());
    m_done.wait(lock, [&] { return m_joined == workers && m_busyWorkers == 0; });
    m_task = nullptr;
}

}  // namespace simcore
