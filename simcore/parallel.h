#pragma once
// A small pool of threads that lives as long as its owner (a simulation): no thread is
// created per step. run(count, task) calls task(0..count-1) spread over the threads and
// returns when all are done; the calling thread takes part. Workers spin briefly between runs
// (a step makes several in a row) and sleep when the simulation pauses.
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
    std::mutex m_mutex;                  // only for sleeping and waking workers
    std::condition_variable m_wake;
    const std::function<void(int)>* m_task = nullptr;  // published by m_generation
    int m_count = 0;
    std::atomic<int> m_next{0};
    std::atomic<unsigned long> m_generation{0};
    std::atomic<int> m_finishedWorkers{0};
    std::atomic<bool> m_stop{false};
};

// The number of hardware threads, at least 1.
int hardwareThreads();

}  // namespace simcore
