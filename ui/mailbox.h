#pragma once
// Mailbox: hands work from one thread to the thread of a receiving QObject.
//
//   sender thread                                  receiver's thread
//   ─────────────                                  ─────────────────
//   post(message) ─▶ [ std::mutex | queue ] ─▶ deliver(): take and run them, oldest first
//        └─ first message since the last          ▲
//           delivery: one argument-less  ─────────┘  (the deliver() slot, queued)
//           queued wake-up, posted under the lock
//
// Why not queued signals with arguments: Qt copies such arguments on the sending thread and
// destroys them on the receiving one, synchronised by Qt's own futex-based mutexes. Debian's Qt
// is not built with ThreadSanitizer, so TSan cannot see that hand-over and reports every one
// of them. Here each message is built by our code, queued and taken under a std::mutex (which
// TSan sees), and Qt only carries a wake-up that holds nothing. Because the wake-up is posted
// while the lock is held, even Qt's event object (allocated on the sender, freed on the
// receiver after deliver() has taken the lock) is ordered for TSan.
//
// Messages run in the order they were posted, one delivery at a time on the receiver's thread.

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>

#include <QObject>

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
    explicit Mailbox(QObject* receiver) : QObject(receiver) {}

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
    // loop inside a message delivers the next ones, still in order). After the last message
    // it no longer touches the mailbox, so a call() may end the receiver's use of it.
    // The wake-up is this slot invoked by index, so the queued event holds nothing our code
    // reads before deliver() has taken the lock.
    Q_INVOKABLE void deliver();

    mutable std::mutex m_mutex;  // guards the two fields below
    std::deque<Message> m_queue;
    bool m_wakePending = false;  // a wake-up is queued and has not yet emptied the queue
};

}  // namespace elui
