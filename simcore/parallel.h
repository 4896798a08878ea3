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
#include <cstddef>
#include <mutex>
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

class ThreadPool {
public:
    explicit ThreadPool(int threads);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    int threads() const { return static_cast<int>(m_workers.size()) + 1; }
    void run(int count, TaskRef task);

private:
    void workerLoop();
    void drain();

    std::vector<std::thread> m_workers;
    std::mutex m_mutex;                  // only for sleeping and waking workers
    std::condition_variable m_wake;
    const TaskRef* m_task = nullptr;  // published by m_generation
    int m_count = 0;
    std::atomic<int> m_next{0};
    std::atomic<unsigned long> m_generation{0};
    std::atomic<int> m_finishedWorkers{0};
    std::atomic<bool> m_stop{false};
};

// The number of hardware threads, at least 1.
int hardwareThreads();

}  // namespace simcore
