// The mailbox between the GUI and the simulation thread (ui/mailbox.h): order, blocking calls,
// no lost wake-up, nested delivery, and a mailbox moved to its thread before that thread starts
// (as the controller's inbox is). Run under ThreadSanitizer too: every hand-over must be one it
// sees (a std::mutex and an eventfd; nothing through Qt's event queue).
#include <QEventLoop>
#include <QTest>
#include <QThread>
#include <QTimer>

#include <thread>
#include <vector>

#include "test_support.h"
#include "ui/mailbox.h"

using elui::Latch;
using elui::Mailbox;

namespace {

// A receiver on a thread of its own, started after its mailbox moved there with it.
struct ThreadedReceiver {
    QThread thread;
    QObject* receiver = new QObject;
    Mailbox* box = new Mailbox(receiver);
    ThreadedReceiver() {
        receiver->moveToThread(&thread);
        thread.start();
    }
    ~ThreadedReceiver() {
        box->call([this] {
            delete receiver;  // the mailbox with it; call() touches nothing of it afterwards
            QThread::currentThread()->quit();
        });
        thread.wait();
    }
};

}  // namespace

class TestMailbox : public QObject {
    Q_OBJECT
private slots:
    void messagesRunInOrderOnTheReceiversThread() {
        ThreadedReceiver r;
        std::vector<int> seen[2];  // touched on the receiver's thread only
        bool wrongThread = false;
        QThread* const target = &r.thread;
        constexpr int kEach = 5000;
        std::vector<std::thread> senders;
        for (int s = 0; s < 2; ++s)
            senders.emplace_back([&, s] {
                for (int i = 0; i < kEach; ++i)
                    r.box->post([&, s, i] {
                        if (QThread::currentThread() != target) wrongThread = true;
                        seen[s].push_back(i);
                    });
            });
        for (auto& t : senders) t.join();
        // Behind every message posted before it: afterwards all of them have run.
        std::size_t counted[2] = {};
        r.box->call([&] { counted[0] = seen[0].size(), counted[1] = seen[1].size(); });
        QCOMPARE(r.box->pending(), std::size_t(0));
        QVERIFY(!wrongThread);
        for (int s = 0; s < 2; ++s) {
            QCOMPARE(counted[s], std::size_t(kEach));
            for (int i = 0; i < kEach; ++i) QCOMPARE(seen[s][std::size_t(i)], i);  // each sender's order kept
        }
    }

    void noWakeUpIsLost() {
        // Ping-pong: every message arrives at an empty queue whose last wake-up was consumed,
        // the case in which a lost wake-up would hang.
        ThreadedReceiver r;
        Mailbox here(this);
        int pongs = 0;
        constexpr int kRounds = 2000;
        std::function<void()> ping;
        ping = [&] {
            r.box->post([&] {
                here.post([&] {
                    if (++pongs < kRounds) ping();
                });
            });
        };
        ping();
        QVERIFY(testsupport::waitUntil([&] { return pongs == kRounds; }));
    }

    void nestedEventLoopsDeliverInOrder() {
        // A message that opens a nested event loop (as a modal dialog does): the messages behind
        // it run inside that loop, in order, and none of them twice.
        Mailbox box(this);
        std::vector<int> order;
        box.post([&] {
            order.push_back(1);
            QEventLoop loop;
            box.post([&] { order.push_back(3); });
            box.post([&] { loop.quit(); });
            loop.exec();
            order.push_back(4);
        });
        box.post([&] { order.push_back(2); });
        QVERIFY(testsupport::waitUntil([&] { return order.size() == 4; }));
        QCoreApplication::processEvents();
        QCOMPARE(order, (std::vector<int>{1, 2, 3, 4}));
    }

    void callOnTheReceiversOwnThreadRunsAtOnce() {
        Mailbox box(this);
        std::vector<int> order;
        box.post([&] { order.push_back(1); });
        box.call([&] { order.push_back(2); });  // delivers what is queued, then runs
        QCOMPARE(order, (std::vector<int>{1, 2}));
        QCOMPARE(box.pending(), std::size_t(0));
    }

    void latchOrdersWork() {
        Latch latch;
        int value = 0;  // written before open(), read after wait(): TSan must see the order
        std::thread t([&] {
            value = 42;
            latch.open();
        });
        latch.wait();
        QCOMPARE(value, 42);
        t.join();
    }
};

QTEST_GUILESS_MAIN(TestMailbox)
#include "test_mailbox.moc"
