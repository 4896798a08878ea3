// What the worker hands to the GUI (ui/frame_publisher.h): rows at most one per kRowInterval,
// the newest frame winning in the slot while the rows add up, one announcement per take,
// history resets dropping the rows not yet taken, and branch marks counted in the rows taken.
#include <QTest>

#include <memory>

#include "simcore/simulation.h"
#include "ui/frame_publisher.h"

using namespace elui;

namespace {

// A ring stepping at half the row interval: every other step is due a row.
struct Ring {
    simcore::Simulation sim{[] {
        simcore::ParameterSet p(simcore::SceneKind::Ring2d);
        p.set(simcore::Param::Dt, FramePublisher::kRowInterval / 2);
        return p;
    }(),
                            "rk4"};
    void steps(int n) {
        for (int i = 0; i < n; ++i) sim.step();
    }
};

std::shared_ptr<Frame> frame() { return std::make_shared<Frame>(); }

}  // namespace

class TestFramePublisher : public QObject {
    Q_OBJECT
private slots:
    void rowsAtMostOnePerInterval() {
        Ring ring;
        FramePublisher publisher([] {});
        publisher.recordRow(ring.sim, false);  // t = 0
        publisher.recordRow(ring.sim, false);  // the same moment again: not due
        for (int i = 0; i < 8; ++i) {
            ring.steps(1);
            publisher.recordRow(ring.sim, false);
        }
        publisher.publish(frame());
        const FrameBatch batch = publisher.takeBatch();
        // t = 0, 1, 2, 3, 4 ms out of nine moments half a millisecond apart.
        QCOMPARE(batch.rows.size(), std::size_t(5));
        for (std::size_t i = 1; i < batch.rows.size(); ++i)
            QVERIFY(batch.rows[i].time - batch.rows[i - 1].time >= FramePublisher::kRowInterval * (1 - 1e-9));
        QCOMPARE(batch.rows.back().step, 8L);
    }

    void newestFrameWinsAndRowsAddUp() {
        Ring ring;
        int announced = 0;
        FramePublisher publisher([&announced] { ++announced; });
        QCOMPARE(publisher.publishedSerial(), quint64(0));
        publisher.recordRow(ring.sim, false);
        publisher.publish(frame());
        ring.steps(2);
        publisher.recordRow(ring.sim, false);
        publisher.publish(frame());
        // Two frames, one announcement: the slot was full for the second.
        QCOMPARE(announced, 1);
        QCOMPARE(publisher.publishedSerial(), quint64(2));
        FrameBatch batch = publisher.takeBatch();
        QVERIFY(batch.frame);
        QCOMPARE(batch.frame->serial, quint64(2));
        QCOMPARE(batch.rows.size(), std::size_t(2));
        QVERIFY(batch.historyReset);  // the first history begins with the first batch
        // Taken: empty until the next publish, which is announced again.
        batch = publisher.takeBatch();
        QVERIFY(!batch.frame);
        QVERIFY(batch.rows.empty());
        publisher.publish(frame());
        QCOMPARE(announced, 2);
        batch = publisher.takeBatch();
        QCOMPARE(batch.frame->serial, quint64(3));
        QVERIFY(!batch.historyReset);
        QVERIFY(batch.rows.empty());
    }

    void aNewHistoryDropsTheRowsNotTaken() {
        Ring ring;
        FramePublisher publisher([] {});
        publisher.recordRow(ring.sim, false);
        publisher.publish(frame());
        (void)publisher.takeBatch();
        ring.steps(2);
        publisher.recordRow(ring.sim, false);
        publisher.publish(frame());           // in the slot, not taken
        ring.steps(2);
        publisher.recordRow(ring.sim, false);  // recorded, not published
        publisher.startHistory();
        ring.sim.reset();
        publisher.recordRow(ring.sim, false);  // the new history's first row, at once
        publisher.publish(frame());
        const FrameBatch batch = publisher.takeBatch();
        QVERIFY(batch.historyReset);
        QCOMPARE(batch.rows.size(), std::size_t(1));
        QCOMPARE(batch.rows.front().step, 0L);
    }

    void branchesCountTheRowsBeforeThem() {
        Ring ring;
        FramePublisher publisher([] {});
        publisher.recordRow(ring.sim, false);
        publisher.publish(frame());
        (void)publisher.takeBatch();
        for (int i = 0; i < 3; ++i) {
            ring.steps(2);
            publisher.recordRow(ring.sim, false);
        }
        publisher.publish(frame());            // three rows wait in the slot
        ring.steps(2);
        publisher.recordRow(ring.sim, false);  // a fourth since
        const double at = ring.sim.time();
        publisher.branch(at);
        publisher.recordRow(ring.sim, false);  // the branch's first row: at once, same time
        publisher.publish(frame());
        const FrameBatch batch = publisher.takeBatch();
        QCOMPARE(batch.rows.size(), std::size_t(5));
        QCOMPARE(batch.branches.size(), std::size_t(1));
        QCOMPARE(batch.branches.front().rowsBefore, std::size_t(4));
        QCOMPARE(batch.branches.front().time, at);
        QCOMPARE(batch.rows[4].time, at);
    }

    void clearedItHoldsNothing() {
        Ring ring;
        FramePublisher publisher([] {});
        publisher.recordRow(ring.sim, false);
        publisher.publish(frame());
        publisher.clear();
        const FrameBatch batch = publisher.takeBatch();
        QVERIFY(!batch.frame);
        QVERIFY(batch.rows.empty());
    }
};

QTEST_APPLESS_MAIN(TestFramePublisher)
#include "test_frame_publisher.moc"
