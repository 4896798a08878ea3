// Cancel is safe everywhere a long computation can be cancelled (issue 31): a study (its
// reference included: cancelling it there read the last sample of an empty list, SIGSEGV), a
// refinement study and a stability scan, each cancelled at many instants from another thread,
// as the GUI's Cancel and Python's Ctrl+C do. Run under ASan+UBSan by the sanitizer suite.
//
// The instants spread geometrically from 0 to ~0.2 s after the start; where each lands depends
// on the machine, and every outcome is checked: a cancelled result holds only complete rows or
// rows marked cancelled, an uncancelled one is complete. No assertion depends on the clock.
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include <QtTest>

#include "simlab/refinement.h"
#include "simlab/stability.h"
#include "simlab/study.h"

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

}  // namespace

class TestCancel : public QObject {
    Q_OBJECT

private slots:
    void studyCancelledAnywhere() {
        simlab::StudySpec spec;
        spec.params = simcore::ParameterSet(simcore::SceneKind::Ring2d);
        spec.integrators = {"euler", "rk4", "rk45"};
        spec.dts = {0.002, 0.001};
        spec.tolerances = {1e-4, 1e-6};
        spec.duration = 0.2;
        spec.samples = 10;
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
        simlab::RefinementSpec spec;
        spec.params = simcore::ParameterSet(simcore::SceneKind::Ring2d);
        spec.key = "particles";
        spec.values = {12, 24, 48};
        spec.duration = 0.1;
        spec.interval = 0.01;
        spec.temporalRuns = 2;
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
};

QTEST_GUILESS_MAIN(TestCancel)
#include "test_cancel.moc"
