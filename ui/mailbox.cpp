#include "ui/mailbox.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include <sys/eventfd.h>
#include <unistd.h>

#include <QSocketNotifier>
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

Mailbox::Mailbox(QObject* receiver) : QObject(receiver), m_wakeFd(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {
    if (m_wakeFd < 0) throw std::runtime_error(std::string("mailbox: eventfd: ") + std::strerror(errno));
    m_notifier = new QSocketNotifier(m_wakeFd, QSocketNotifier::Read, this);
    connect(m_notifier, &QSocketNotifier::activated, this, &Mailbox::wake);
}

Mailbox::~Mailbox() {
    delete m_notifier;  // before its descriptor is closed
    ::close(m_wakeFd);
}

void Mailbox::post(Message message) {
    std::lock_guard lock(m_mutex);
    m_queue.push_back(std::move(message));
    if (m_wakePending) return;  // the wake-up already written will find this message too
    m_wakePending = true;
    wakeUp();
}

void Mailbox::wake() {
    // Reset the counter first: a message posted from here on writes a new wake-up.
    std::uint64_t count = 0;
    [[maybe_unused]] const ssize_t read = ::read(m_wakeFd, &count, sizeof count);
    deliver();
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
            if (!more) m_wakePending = false;  // from here a new post writes a new wake-up
            // Messages wait behind this one: keep the eventfd readable while it runs, so that an
            // event loop it opens (a modal dialog) delivers them, in order, instead of stalling.
            else wakeUp();
        }
        message();
    }
}

void Mailbox::wakeUp() {
    const std::uint64_t one = 1;
    // Cannot fail short of a counter at 2^64 - 2 or a closed descriptor (the mailbox outlives
    // every sender by design).
    [[maybe_unused]] const ssize_t written = ::write(m_wakeFd, &one, sizeof one);
}

}  // namespace elui
