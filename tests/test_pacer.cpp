// The worker's pacing (ui/pacer.h) on a wall clock the test moves by hand: real time and a
// fraction of it, as fast as possible within the tick budget, falling behind and being
// forgiven, the steps-per-second meter, and when a frame is due. Every clock reading is a
// value the test set (dyadic fractions, so the sums are exact); nothing here waits on the wall.
#include <QTest>

#include <cmath>
#include <limits>

#include "ui/pacer.h"

using namespace elui;

namespace {

// The wall as the pacer sees it [s]; the test moves it.
struct HandClock {
    double now = 100.0;
    WallClock reader() {
        return [this] { return now; };
    }
};

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

class TestPacer : public QObject {
    Q_OBJECT
private slots:
    void pausedUntilStarted() {
        HandClock wall;
        Pacer pacer(wall.reader());
        QVERIFY(!pacer.running());
        QCOMPARE(pacer.speed(), Speed::RealTime);
        wall.now += 5.0;
        QVERIFY(pacer.frameDue(false));
        QCOMPARE(pacer.wallSeconds(), 0.0);
        QCOMPARE(pacer.stepsPerSecond(), 0.0);
        QVERIFY(!pacer.fallingBehind());
    }

    void realTimeFollowsTheWall() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.startOver(0.0);
        pacer.start(0.0);
        QCOMPARE(pacer.timerInterval(), 4);
        // No wall time yet: nowhere to go.
        QCOMPARE(pacer.beginTick(false), 0.0);
        pacer.endTick(0.0, false);
        wall.now += 1.25;
        QCOMPARE(pacer.beginTick(false), 1.25);
        pacer.endTick(1.25, false);
        QVERIFY(!pacer.fallingBehind());
        QVERIFY(pacer.frameDue(true));
        QCOMPARE(pacer.wallSeconds(), 1.25);
        // The clock counts from where it started, not from the last tick.
        wall.now += 0.5;
        QCOMPARE(pacer.beginTick(false), 1.75);
        pacer.endTick(1.75, false);
    }

    void startingAgainDoesNotRestart() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.start(0.0);
        wall.now += 1.0;
        pacer.start(123.0);  // already running: the clock keeps its origin
        QCOMPARE(pacer.beginTick(false), 1.0);
    }

    void quarterSpeed() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.start(0.0);
        wall.now += 1.0;
        pacer.endTick(pacer.beginTick(false), false);
        // A new speed counts from here and from where the lanes are.
        pacer.setSpeed(Speed::Quarter, 1.0);
        QCOMPARE(pacer.speed(), Speed::Quarter);
        QCOMPARE(pacer.timerInterval(), 4);
        wall.now += 2.0;
        QCOMPARE(pacer.beginTick(false), 1.5);  // 2 wall seconds are half a simulated one
        pacer.endTick(1.5, false);
        // The wall time run is all of it, across the speed change.
        QVERIFY(pacer.frameDue(true));
        QCOMPARE(pacer.wallSeconds(), 3.0);
    }

    void pausedTheClockStops() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.start(0.0);
        wall.now += 1.5;
        pacer.stop();
        QVERIFY(!pacer.running());
        wall.now += 100.0;
        QVERIFY(pacer.frameDue(true));
        QCOMPARE(pacer.wallSeconds(), 1.5);
        // Running again: the clock counts from the lanes' time, not from before the pause.
        pacer.start(1.5);
        wall.now += 0.25;
        QCOMPARE(pacer.beginTick(false), 1.75);
        pacer.endTick(1.75, false);
        QVERIFY(pacer.frameDue(true));
        QCOMPARE(pacer.wallSeconds(), 1.75);
        // A new history forgets the wall time run.
        pacer.startOver(0.0);
        QVERIFY(pacer.frameDue(true));
        QCOMPARE(pacer.wallSeconds(), 0.0);
    }

    void asFastAsPossibleWithinTheTickBudget() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.setSpeed(Speed::AsFastAsPossible, 0.0);
        QCOMPARE(pacer.timerInterval(), 0);
        pacer.start(0.0);
        QCOMPARE(pacer.beginTick(false), kInf);
        // Steps until the tick's wall budget is spent, and not sooner.
        QVERIFY(!pacer.budgetSpent());
        wall.now += Pacer::kTickBudget / 2;
        QVERIFY(!pacer.budgetSpent());
        wall.now += Pacer::kTickBudget;
        QVERIFY(pacer.budgetSpent());
        pacer.endTick(7.0, true);
        // Not paced: never behind, however little was done.
        QVERIFY(!pacer.fallingBehind());
        // The next tick has a budget of its own.
        QCOMPARE(pacer.beginTick(false), kInf);
        QVERIFY(!pacer.budgetSpent());
    }

    void runningUntilATargetIsNotPaced() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.start(0.0);
        QCOMPARE(pacer.beginTick(true), kInf);
        wall.now += 1.0;
        pacer.endTick(0.5, true);
        QVERIFY(!pacer.fallingBehind());
    }

    void fallingBehindIsSaidAndForgiven() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.start(0.0);
        wall.now += 1.0;
        QCOMPARE(pacer.beginTick(false), 1.0);
        // The budget ran out with the lanes at 0.25 s of the 1 s the clock asked for.
        wall.now += 0.5;
        QVERIFY(pacer.budgetSpent());
        pacer.endTick(0.25, true);
        QVERIFY(pacer.fallingBehind());
        // The clock restarted where the lanes are: no debt to rush through ...
        QCOMPARE(pacer.beginTick(false), 0.25);
        // ... and the wall time run is all of it.
        QVERIFY(pacer.frameDue(true));
        QCOMPARE(pacer.wallSeconds(), 1.5);
        // Keeping up again clears the flag.
        wall.now += 0.125;
        QCOMPARE(pacer.beginTick(false), 0.375);
        pacer.endTick(0.375, false);
        QVERIFY(!pacer.fallingBehind());
    }

    void aSpentBudgetAtTheTargetIsNotBehind() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.start(0.0);
        wall.now += 1.0;
        QCOMPARE(pacer.beginTick(false), 1.0);
        wall.now += 0.5;
        pacer.endTick(1.0, true);  // the last step reached the target as the budget ran out
        QVERIFY(!pacer.fallingBehind());
        QCOMPARE(pacer.beginTick(false), 1.5);  // the clock was not restarted
    }

    void restartForgivesFallingBehind() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.start(0.0);
        wall.now += 1.0;
        pacer.beginTick(false);
        pacer.endTick(0.0, true);
        QVERIFY(pacer.fallingBehind());
        pacer.restart(0.0);
        QVERIFY(!pacer.fallingBehind());
    }

    void rateMeter() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.setSpeed(Speed::AsFastAsPossible, 0.0);
        pacer.start(0.0);
        // 100 steps in a quarter second: the window is still open, nothing measured yet.
        pacer.beginTick(false);
        for (int i = 0; i < 100; ++i) pacer.countStep();
        wall.now += 0.25;
        pacer.endTick(1.0, true);
        QCOMPARE(pacer.stepsPerSecond(), 0.0);
        // 100 more in the next quarter: 200 steps over half a second.
        pacer.beginTick(false);
        for (int i = 0; i < 100; ++i) pacer.countStep();
        wall.now += 0.25;
        pacer.endTick(2.0, true);
        QCOMPARE(pacer.stepsPerSecond(), 400.0);
        // A new window: 50 steps over a whole second.
        pacer.beginTick(false);
        for (int i = 0; i < 50; ++i) pacer.countStep();
        wall.now += 1.0;
        pacer.endTick(3.0, true);
        QCOMPARE(pacer.stepsPerSecond(), 50.0);
        // Paused, nothing runs: the meter shows none.
        pacer.stop();
        QCOMPARE(pacer.stepsPerSecond(), 0.0);
    }

    void framesAtMostAtThePublishInterval() {
        HandClock wall;
        Pacer pacer(wall.reader());
        pacer.start(0.0);
        QVERIFY(pacer.frameDue(true));
        QVERIFY(!pacer.frameDue(false));
        wall.now += Pacer::kPublishInterval / 2;
        QVERIFY(!pacer.frameDue(false));
        QVERIFY(pacer.frameDue(true));  // forced: always, and the interval restarts
        wall.now += Pacer::kPublishInterval * 0.75;
        QVERIFY(!pacer.frameDue(false));
        wall.now += Pacer::kPublishInterval * 0.5;
        QVERIFY(pacer.frameDue(false));
        // The frame is dated when it was due.
        QVERIFY(std::abs(pacer.wallSeconds() - Pacer::kPublishInterval * 1.75) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestPacer)
#include "test_pacer.moc"
