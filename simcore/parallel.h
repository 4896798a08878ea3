#pragma once
// A small pool of threads that lives as long as its owner (a simulation): no thread is
// created per step. run(count, task) calls task(0..count-1) spread over the threads and
// returns when all are done; the calling thread takes part.
//
// Determinism is the caller's job and is easy: split work into a fixed number of tasks that
// does not depend on the thread count, and combine their results in task order.

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace simcore {

class ThreadPool {
public:
    explicit ThreadPool(int threads);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int threads() const { return static_cast<int>(m_workers.size()) + 1; }
    void run(int count, const std::function<void(int)>& task);

private:
    void workerLoop();
    void drain();

    std::vector<std::thread> m_workers;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::condition_variable m_done;
    const std::function<void(int)>* m_task = nullptr;  // guarded by m_mutex for publication
    int m_count = 0;
    std::atomic<int> m_next{0};
    unsigned long m_generation = 0;
    int m_busyWorkers = 0;  // workers inside drain()
    int m_joined = 0;       // workers that picked up the current generation
    bool m_stop = false;
};

// The number of hardware threads, at least 1.
int hardwareThreads();

}  // namespace simcore
