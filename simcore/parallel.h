#pragma once
// A small pool of threads that lives as long as its owner (a simulation): no thread is
// created per step. run(count, task) calls task(0..count-1) spread over the threads and
// returns when all are done; the calling thread takes part. Workers spin briefly between runs
// (a step makes several in a row) and sleep when the simulation pauses.
//
// Work goes to whichever thread is free: a task is claimed with one compare-and-swap on a
// ticket that holds the run's number and the next task's index, so a worker that has not been
// scheduled yet (a busy machine: compilers, a browser, another simulation beside it) claims
// nothing, the caller does its tasks, and the run ends when every task is done, not when every
// worker has turned up. A worker preempted in the middle of its task holds a run up; when that
// keeps happening (a machine busier than its CPUs) the caller runs alone for a while and then
// tries again. Two threads on a busy machine therefore cost about what one does.
//
// Determinism is the caller's job and is easy: split work into a fixed number of tasks that
// does not depend on the thread count, and combine their results in task order.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
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
    // Claims and runs tasks of run `run` until none is left (or another run has begun);
    // returns how many it ran.
    int claimTasks(std::uint32_t run);

    std::vector<std::thread> m_workers;
    std::mutex m_mutex;                           // only for sleeping and waking workers
    std::condition_variable m_wake;
    std::atomic<const TaskRef*> m_task{nullptr};  // the current run's task and count,
    std::atomic<int> m_count{0};                  //   published by m_ticket
    std::atomic<std::uint64_t> m_ticket{0};       // run number << 32 | next task index
    std::atomic<int> m_done{0};                   // tasks of the current run finished
    std::atomic<std::uint32_t> m_posted{0};       // the newest run (wakes the workers)
    std::uint32_t m_runs = 0;                     // runs started (the caller's own count)
    int m_lateRuns = 0;                           // recent runs held up by a worker (net)
    int m_soloRuns = 0;                           // runs the caller still does alone
    std::atomic<bool> m_stop{false};
};

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
