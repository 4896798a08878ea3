// Cancel is safe everywhere a long computation can be cancelled (issue 31): a study (its
// reference included: cancelling it there read the last sample of an empty list, SIGSEGV), a
// refinement study, a stability scan, a long-time energy run and a sweep point, each cancelled
// at many instants, as the GUI's Cancel and Python's Ctrl+C do. Run under ASan+UBSan by the
// sanitizer suite (every test runs there; these take about a second each in Release).
//
// Two kinds of instant. Deterministic: the cancel flag is set inside the k-th progress call
// (k = 0: before the start), for every k the computation makes, and what comes back is
// compared with an uncancelled run: every row kept is equal to that run's row (a cancelled
// point is marked so), nothing is half-measured, and the run after the cancel gives the
// uncancelled result again (nothing shared was left behind).
// The instants spread geometrically from 0 to ~0.2 s after the start; where each lands depends
// on the machine, and every outcome is checked: a cancelled result holds only complete rows or
// rows marked cancelled, an uncancelled one is complete. No assertion depends on the clock.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include <QtTest>

#include "simlab/conservation.h"
#include "simlab/refinement.h"
#include "simlab/request.h"
#include "simlab/stability.h"
#include "simlab/study.h"
#include "simlab/sweep.h"

namespace {

// Runs work(&cancel) while another thread sets cancel after `delay`.
template <class Work>
auto cancelledAfter(std::chrono::microseconds delay, Work&& work) {
    std::atomic<bool> cancel{false};
    std::thread canceller([&] {
        std::this_thread::sleep_for(delay);
        cancel = true;
    });
    auto result = work(&cancel);
    canceller.join();
    return result;
}

std::chrono::microseconds instant(int k) { return std::chrono::microseconds(static_cast<long>(20.0 * std::pow(1.6, k))) * (k > 0); }

constexpr int kInstants = 22;  // 0, 32 us, ... ~0.2 s

// Runs run(progress, cancel) once with the flag set inside the k-th progress call (k = 0: set
// before the call), for k = 0, 1, 2, ... until the flag is never set (k beyond the last call);
// check(result, k, flagSet) judges each (a flag set in the last call, after the work, cancels
// nothing). Returns how many calls an uncancelled run makes.
template <class Result, class Run, class Check>
int cancelAtEveryProgressCall(Run&& run, Check&& check) {
    for (int k = 0;; ++k) {
        std::atomic<bool> cancel{k == 0};
        int calls = 0;
        auto onProgress = [&] {
            if (++calls == k) cancel = true;
        };
        const Result r = run(onProgress, &cancel);
        check(r, k, cancel.load());
        if (!cancel) return calls;
        if (k > 1000) return -1;  // never ends: the check below fails
    }
}

// Three integrators (one adaptive) at two steps on the ring: six points and an rk4 reference.
simlab::StudySpec ringStudy(double duration) {
    simlab::StudySpec spec;
    spec.params = simcore::ParameterSet(simcore::SceneKind::Ring2d);
    spec.integrators = {"euler", "rk4", "rk45"};
    spec.dts = {0.002, 0.001};
    spec.tolerances = {1e-4, 1e-6};
    spec.duration = duration;
    spec.samples = 10;
    return spec;
}

// The ring at three resolutions and a temporal curve of two runs.
simlab::RefinementSpec ringRefinement(double duration) {
    simlab::RefinementSpec spec;
    spec.params = simcore::ParameterSet(simcore::SceneKind::Ring2d);
    spec.key = "particles";
    spec.values = {12, 24, 48};
    spec.duration = duration;
    spec.interval = 0.01;
    spec.temporalRuns = 2;
    return spec;
}

bool sameStudyRow(const simlab::StudyRow& a, const simlab::StudyRow& b) {
    return a.item.integrator == b.item.integrator && a.item.dt == b.item.dt && a.item.tolerance == b.item.tolerance &&
           a.steps == b.steps && a.forceEvaluations == b.forceEvaluations && a.errorFinal == b.errorFinal &&
           a.errorMax == b.errorMax && a.errorRms == b.errorRms && a.errorEnergy == b.errorEnergy && a.ok == b.ok &&
           a.failure == b.failure;
}

bool sameRefinementRow(const simlab::RefinementRow& a, const simlab::RefinementRow& b) {
    return a.value == b.value && a.particles == b.particles && a.dt == b.dt && a.steps == b.steps &&
           a.errorVolume == b.errorVolume && a.errorCom == b.errorCom && a.ok == b.ok && a.reference == b.reference;
}

bool sameStabilityRow(const simlab::StabilityRow& a, const simlab::StabilityRow& b) {
    return a.integrator == b.integrator && a.stable == b.stable && a.unstable == b.unstable &&
           a.reasonAbove == b.reasonAbove && a.runs == b.runs;
}

}  // namespace

class TestCancel : public QObject {
    Q_OBJECT

private slots:
    void studyCancelledAnywhere() {
        const simlab::StudySpec spec = ringStudy(0.2);
        int cancelledInReference = 0;
        for (int k = 0; k < kInstants; ++k) {
            const simlab::StudyResult r =
                cancelledAfter(instant(k), [&](const std::atomic<bool>* c) { return simlab::runStudy(spec, {}, c); });
            if (r.reference.cancelled) {
                ++cancelledInReference;
                QVERIFY(r.cancelled);
                QVERIFY(r.rows.empty());
                QVERIFY(r.reference.positions.empty());
                continue;
            }
            QCOMPARE(r.reference.positions.size(), r.reference.times.size());
            for (const simlab::StudyRow& row : r.rows)
                QVERIFY2(row.ok || row.failure == "cancelled", row.failure.c_str());
            if (!r.cancelled) QCOMPARE(r.rows.size(), std::size_t{6});
        }
        // The first instant (0: cancelled before the reference's first step) always lands in it.
        QVERIFY(cancelledInReference >= 1);
        // A row asked for with a cancelled reference is a cancelled row, never a read of nothing.
        simlab::StudyReference none;
        none.cancelled = true;
        none.times = {0.1, 0.2};
        const simlab::StudyRow row = simlab::runStudyItem(spec, {"rk4", "double", 0.001, -1.0}, none);
        QVERIFY(!row.ok);
        QCOMPARE(row.failure, std::string("cancelled"));
    }

    void refinementCancelledAnywhere() {
        const simlab::RefinementSpec spec = ringRefinement(0.1);
        for (int k = 0; k < kInstants; ++k) {
            const simlab::RefinementResult r =
                cancelledAfter(instant(k), [&](const std::atomic<bool>* c) { return simlab::runRefinement(spec, {}, c); });
            if (!r.cancelled) QCOMPARE(r.rows.size(), std::size_t{3});
            for (const simlab::RefinementRow& row : r.rows) QVERIFY(row.particles > 0);
        }
    }

    void stabilityScanCancelledAnywhere() {
        simlab::StabilitySpec spec;
        spec.params = simcore::ParameterSet(simcore::SceneKind::Ring2d);
        spec.integrators = {"euler", "rk4"};
        spec.duration = 0.5;
        const simlab::LinearModes modes = simlab::linearModes(spec.params);
        for (int k = 0; k < kInstants; ++k) {
            const auto rows = cancelledAfter(
                instant(k), [&](const std::atomic<bool>* c) { return simlab::runStability(spec, modes, {}, c); });
            QVERIFY(rows.size() <= spec.integrators.size());
            for (const simlab::StabilityRow& row : rows) QVERIFY(row.stable >= 0.0 && !std::isnan(row.unstable));
        }
    }

    void studyCancelledAtEveryProgressCall() {
        const simlab::StudySpec spec = ringStudy(0.1);
        const simlab::StudyResult full = simlab::runStudy(spec);
        QVERIFY(!full.cancelled);
        QCOMPARE(full.rows.size(), std::size_t{6});
        auto run = [&](auto& onProgress, const std::atomic<bool>* c) {
            return simlab::runStudy(spec, [&](const simlab::StudyProgress&) { onProgress(); }, c);
        };
        bool cancelledRows = false;
        const int calls = cancelAtEveryProgressCall<simlab::StudyResult>(run, [&](const simlab::StudyResult& r, int k, bool cancelled) {
            QVERIFY(!r.cancelled || cancelled);  // the flag set in the last call comes too late: not cancelled
            if (r.reference.cancelled) QVERIFY(r.rows.empty() && r.reference.positions.empty());
            QVERIFY(r.rows.size() <= full.rows.size());
            for (std::size_t i = 0; i < r.rows.size(); ++i) {
                if (r.rows[i].failure == "cancelled") {
                    cancelledRows = true;
                    QVERIFY(!r.rows[i].ok);
                    QVERIFY2(i + 1 == r.rows.size(), "a cancelled point is the last one");
                } else {
                    QVERIFY2(sameStudyRow(r.rows[i], full.rows[i]), qPrintable(QString("k = %1, row %2").arg(k).arg(i)));
                }
            }
            if (!r.cancelled) QCOMPARE(r.rows.size(), full.rows.size());
        });
        QCOMPARE(calls, 8);  // the reference, six points, the end
        QVERIFY(cancelledRows);  // a point started with the flag already set came back marked
    }

    void refinementCancelledAtEveryProgressCall() {
        const simlab::RefinementSpec spec = ringRefinement(0.05);
        const simlab::RefinementResult full = simlab::runRefinement(spec);
        QVERIFY(!full.cancelled);
        auto run = [&](auto& onProgress, const std::atomic<bool>* c) {
            return simlab::runRefinement(spec, [&](const simlab::StudyProgress&) { onProgress(); }, c);
        };
        const int calls = cancelAtEveryProgressCall<simlab::RefinementResult>(run, [&](const simlab::RefinementResult& r, int k, bool cancelled) {
            QVERIFY(!r.cancelled || cancelled);
            QVERIFY(r.rows.size() <= full.rows.size());
            // Rows are whole levels, each equal to the uncancelled run's level of that size.
            for (const simlab::RefinementRow& row : r.rows) {
                const auto same = std::find_if(full.rows.begin(), full.rows.end(),
                                               [&](const simlab::RefinementRow& f) { return f.value == row.value; });
                QVERIFY2(same != full.rows.end() && sameRefinementRow(row, *same), qPrintable(QString("k = %1").arg(k)));
            }
            if (!r.cancelled) {
                QCOMPARE(r.rows.size(), full.rows.size());
                QCOMPARE(r.temporal.size(), full.temporal.size());
                QCOMPARE(r.timeErrorVolume, full.timeErrorVolume);
            }
        });
        QCOMPARE(calls, 6);  // the reference, two levels, two temporal runs, the end
    }

    void stabilityScanCancelledAtEveryProgressCall() {
        simlab::StabilitySpec spec;
        spec.params = simcore::ParameterSet(simcore::SceneKind::Ring2d);
        spec.integrators = {"euler", "midpoint", "rk4"};
        spec.duration = 0.3;
        const simlab::LinearModes modes = simlab::linearModes(spec.params);
        const auto full = simlab::runStability(spec, modes);
        QCOMPARE(full.size(), std::size_t{3});
        auto run = [&](auto& onProgress, const std::atomic<bool>* c) {
            return simlab::runStability(spec, modes, [&](const simlab::StabilityProgress&) { onProgress(); }, c);
        };
        const int calls = cancelAtEveryProgressCall<std::vector<simlab::StabilityRow>>(
            run, [&](const std::vector<simlab::StabilityRow>& rows, int k, bool cancelled) {
                // Cancelled in the progress call before integrator k: exactly the k - 1 before it,
                // each with the uncancelled run's limits (a scan cut short is never reported).
                QCOMPARE(rows.size(), cancelled ? std::size_t(std::max(0, k - 1)) : full.size());
                for (std::size_t i = 0; i < rows.size(); ++i)
                    QVERIFY2(sameStabilityRow(rows[i], full[i]), qPrintable(QString("k = %1, row %2").arg(k).arg(i)));
            });
        QCOMPARE(calls, 4);
    }

    void conservationCancelledAtEveryProgressCall() {
        simlab::ConservationSpec spec;
        spec.integrators = {"verlet", "rk4"};
        spec.periods = 200;
        spec.dt = 0.01;
        spec.samples = 40;
        const simlab::ConservationResult full = simlab::runConservation(spec);
        QVERIFY(!full.cancelled);
        QCOMPARE(full.rows.size(), std::size_t{2});
        auto run = [&](auto& onProgress, const std::atomic<bool>* c) {
            return simlab::runConservation(spec, [&](int, int, const std::string&) { onProgress(); }, c);
        };
        const int calls = cancelAtEveryProgressCall<simlab::ConservationResult>(
            run, [&](const simlab::ConservationResult& r, int k, bool cancelled) {
                QVERIFY(!r.cancelled || cancelled);
                QCOMPARE(r.rows.size(), r.cancelled ? std::size_t(std::max(0, k - 1)) : full.rows.size());
                for (std::size_t i = 0; i < r.rows.size(); ++i) {
                    QCOMPARE(r.rows[i].integrator, full.rows[i].integrator);
                    QCOMPARE(r.rows[i].steps, full.rows[i].steps);
                    QCOMPARE(r.rows[i].finalError, full.rows[i].finalError);
                    QCOMPARE(r.rows[i].curve, full.rows[i].curve);
                }
            });
        QCOMPARE(calls, 3);
    }

    // A sweep point has no progress calls: cancelled from another thread at many instants. A
    // cancelled point says so; an uncancelled one is the same row as a fresh run's.
    void sweepPointCancelledAnywhere() {
        simlab::SweepSpec spec;
        spec.sceneName = "ring2d";
        spec.params = simcore::ParameterSet(simcore::SceneKind::Ring2d);
        spec.keys = {"ks"};
        spec.axes = {{400, 800}};
        spec.duration = 0.5;
        simlab::checkSweep(spec);
        const simlab::SweepRow full = simlab::runSweepPoint(spec, 1);
        QCOMPARE(full.status, std::string("ok"));
        const auto metric = [&](const std::string& name) {
            return std::find(spec.metrics.begin(), spec.metrics.end(), name) - spec.metrics.begin();
        };
        const auto steps = metric("steps"), wall = metric("wall_seconds");
        QVERIFY(steps < long(spec.metrics.size()) && wall < long(spec.metrics.size()));
        std::atomic<bool> before{true};  // cancelled before its first step: nothing stepped
        const simlab::SweepRow none = simlab::runSweepPoint(spec, 1, &before);
        QCOMPARE(none.reason, std::string("cancelled"));
        QCOMPARE(none.metrics[steps], 0.0);
        for (int k = 0; k < kInstants; ++k) {
            const simlab::SweepRow row =
                cancelledAfter(instant(k), [&](const std::atomic<bool>* c) { return simlab::runSweepPoint(spec, 1, c); });
            QCOMPARE(row.index, 1L);
            QCOMPARE(row.values, full.values);
            QCOMPARE(row.metrics.size(), full.metrics.size());
            if (row.reason == "cancelled") {
                QCOMPARE(row.status, std::string("failed"));
                QVERIFY(row.metrics[steps] < full.metrics[steps]);
                continue;
            }
            QCOMPARE(row.status, full.status);
            for (std::size_t m = 0; m < row.metrics.size(); ++m)
                if (long(m) != wall)
                    QVERIFY2(row.metrics[m] == full.metrics[m] || (std::isnan(row.metrics[m]) && std::isnan(full.metrics[m])),
                             spec.metrics[m].c_str());
        }
        // ... and the next run after all those cancels is the uncancelled row again.
        QCOMPARE(simlab::runSweepPoint(spec, 1).metrics[steps], full.metrics[steps]);
    }
};

QTEST_GUILESS_MAIN(TestCancel)
#include "test_cancel.moc"
