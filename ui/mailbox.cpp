#include "mailbox.h"

#include <memory>

#include <QMetaMethod>
#include <QThread>

namespace elui {

void Latch::open() {
    std::lock_guard lock(m_mutex);
    m_open = true;
    m_opened.notify_all();
}

void Latch::wait() {
    std::unique_lock lock(m_mutex);
    m_opened.wait(lock, [this] { return m_open; });
}

void Mailbox::post(Message message) {
    std::lock_guard lock(m_mutex);
    m_queue.push_back(std::move(message));
    if (m_wakePending) return;  // the queued wake-up will find this message too
    m_wakePending = true;
    // Under the lock: Qt's event for the wake-up is made before the unlock that deliver()'s
    // lock follows, so its destruction on the receiver's thread is ordered after it.
    static const QMetaMethod wakeUp = staticMetaObject.method(staticMetaObject.indexOfMethod("deliver()"));
    wakeUp.invoke(this, Qt::QueuedConnection);
}

void Mailbox::call(Message message) {
    if (QThread::currentThread() == thread()) {
        deliver();
        message();
        return;
    }
    auto done = std::make_shared<Latch>();
    post([&message, done] {
        message();
        done->open();
    });
    done->wait();
}

std::size_t Mailbox::pending() const {
    std::lock_guard lock(m_mutex);
    return m_queue.size();
}

void Mailbox::deliver() {
    for (bool more = true; more;) {
        Message message;
        {
            std::lock_guard lock(m_mutex);
            if (m_queue.empty()) {  // a nested delivery took them
                m_wakePending = false;
                return;
            }
            message = std::move(m_queue.front());
            m_queue.pop_front();
            more = !m_queue.empty();
            if (!more) m_wakePending = false;  // from here a new post sends a new wake-up
        }
        message();
    }
}

}  // namespace elui
