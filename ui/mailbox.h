#pragma once
// Mailbox: hands work from one thread to the thread of a receiving QObject.
//
//   sender thread                                  receiver's thread
//   ─────────────                                  ─────────────────
//   post(message) ─▶ [ std::mutex | queue ] ─▶ deliver(): take and run them, oldest first
//        └─ first message since the last          ▲
//           delivery: write(eventfd, 1) ──────────┘  a QSocketNotifier on the receiver's
//                                                    thread sees the eventfd readable
//
// Why not queued signals with arguments: Qt copies such arguments on the sending thread and
// destroys them on the receiving one, synchronised by Qt's own futex-based mutexes. Debian's Qt
// is not built with ThreadSanitizer, so TSan cannot see that hand-over and reports every one
// of them. Here each message is built by our code, queued and taken under a std::mutex (which
// TSan sees).
//
// Why not a queued (argument-less) call for the wake-up either: Qt appends every event posted
// to a thread to that thread's post-event list, a QList that the receiving thread also appends
// to and compacts, under a QMutex inside QtCore. When the list grows, Qt moves it with memmove,
// which TSan intercepts even inside an uninstrumented library, while the QMutex it cannot see:
// it reported the worker's memmove of the GUI thread's list against the GUI thread's own
// (CI, test_gui_files; docs/reliability.md, "The post-event list"). The eventfd wake-up shares
// no memory between the threads (the sender writes a counter in the kernel, the receiver's
// event loop polls it), so nothing of Qt's crosses the threads at all.
//
// Messages run in the order they were posted, one delivery at a time on the receiver's thread.
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>

#include <QObject>

class QSocketNotifier;

namespace elui {

// A one-shot gate: one thread waits until another opens it. A std::mutex and
// std::condition_variable, so ThreadSanitizer sees that everything done before open()
// happens before wait() returns.
class Latch {
public:
    void open();
    void wait();

private:
    std::mutex m_mutex;
    std::condition_variable m_opened;
    bool m_open = false;
};

class Mailbox : public QObject {
    Q_OBJECT
public:
    using Message = std::function<void()>;

    // Messages run on the receiver's thread: the mailbox is the receiver's child, so it lives
    // (and moves) with it and is deleted with it.
    // The wake-up's notifier is the mailbox's child: it moves with it (a move before the
    // receiver's thread starts, as SimulationController does, is the one Qt supports).
    explicit Mailbox(QObject* receiver);
    ~Mailbox() override;

    // Any thread: message runs on the receiver's thread after every message posted before it.
    void post(Message message);
    // Any thread: posts message and waits until it has run (so has everything posted before).
    // On the receiver's own thread it delivers the queue and runs message directly, since
    // waiting there would wait forever.
    void call(Message message);

    // Messages posted and not yet taken for delivery (0 after a call() returns, unless another
    // thread posted meanwhile).
    std::size_t pending() const;

private:
    // Receiver's thread: runs the queued messages one by one, oldest first (a nested event
    // loop inside a message delivers the next ones, still in order, tested). After the last message
    // it no longer touches the mailbox, so a call() may end the receiver's use of it.
    void deliver();
    // Receiver's thread, when the eventfd is readable: resets it, then delivers.
    void wake();
    // Makes the eventfd readable (any thread).
    void wakeUp();

    int m_wakeFd = -1;           // eventfd: written by post(), read by wake()
    QSocketNotifier* m_notifier = nullptr;
    mutable std::mutex m_mutex;  // guards the two fields below
    std::deque<Message> m_queue;
    bool m_wakePending = false;  // a wake-up is written and has not yet emptied the queue
};

}  // namespace elui
