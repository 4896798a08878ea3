// Threads follow the CPUs the process may use (affinity mask, cgroup CPU quota), and the pool
// hands work to whichever thread is free (simcore/parallel.h).
#include <sched.h>

#include <QtTest>
#include <atomic>
#include <vector>

#include "simcore/parallel.h"
#include "simcore/simulation.h"

using namespace simcore;

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
        QCOMPARE(sim.threads(), std::min(availableThreads(), ForceModel::kChunks));
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
};

QTEST_GUILESS_MAIN(TestThreads)
#include "test_threads.moc"
