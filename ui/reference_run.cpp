#include "ui/reference_run.h"

#include <algorithm>

#include "ui/mailbox.h"

namespace elui {

ReferenceRun::ReferenceRun(QObject* parent) : QObject(parent), m_mailbox(new Mailbox(this)) {}

ReferenceRun::~ReferenceRun() {
    blockSignals(true);  // the receivers may be half destroyed already (a dock's children)
    stop();
}

void ReferenceRun::stop() {
    if (m_shared) {
        {
            std::lock_guard<std::mutex> lock(m_shared->mutex);
            m_shared->cancel = true;
        }
        m_shared->wake.notify_all();
    }
    if (m_thread.joinable()) m_thread.join();
    m_shared.reset();
    m_start.reset();
    ++m_serial;  // rows of the old start still in the mailbox are dropped
    m_target = 0.0;
    const bool had = !m_samples.empty() || m_failure;
    m_samples.clear();
    m_failure.reset();
    if (had) emit restarted();
}

void ReferenceRun::follow(const std::shared_ptr<const simcore::SimulationSnapshot>& start, double until) {
    if (!start) {
        stop();
        return;
    }
    if (start != m_start) {
        stop();
        m_start = start;
        m_shared = std::make_shared<Shared>();
        emit restarted();
        m_thread = std::thread(&ReferenceRun::work, this, *start, m_shared, m_serial);
    }
    if (until <= m_target) return;
    m_target = until;
    {
        std::lock_guard<std::mutex> lock(m_shared->mutex);
        m_shared->target = until;
    }
    m_shared->wake.notify_all();
}

void ReferenceRun::work(simcore::SimulationSnapshot start, std::shared_ptr<Shared> shared, quint64 serial) {
    simcore::Simulation sim(start.params, start.integrator);
    sim.restore(start);
    sim.setIntegrator("rk45");
    simcore::IntegratorOptions options = sim.integratorOptions();
    options.atol = options.rtol = kTolerance;
    options.fixedStep = false;
    options.stepDoubling = false;
    options.maxStep = 0.0;
    sim.setIntegratorOptions(options);

    const double t0 = sim.time();
    long gridIndex = 1;  // the next row on the grid is at t0 + gridIndex * kSampleInterval
    std::vector<simcore::Diagnostics> batch{sim.diagnostics()};
    auto flush = [&] {
        if (batch.empty()) return;
        m_mailbox->post([this, serial, rows = std::move(batch)] {
            if (serial != m_serial) return;
            const int first = int(m_samples.size());
            m_samples.insert(m_samples.end(), rows.begin(), rows.end());
            emit samplesAppended(first, int(rows.size()));
        });
        batch.clear();
    };
    auto cancelled = [&] {
        std::lock_guard<std::mutex> lock(shared->mutex);
        return shared->cancel;
    };
    flush();
    for (;;) {
        double target;
        {
            std::unique_lock<std::mutex> lock(shared->mutex);
            shared->wake.wait(lock, [&] { return shared->cancel || shared->target > sim.time(); });
            if (shared->cancel) return;
            target = shared->target;
        }
        while (sim.time() < target) {
            const double grid = t0 + double(gridIndex) * kSampleInterval;
            const double next = std::min(target, grid);
            if (!sim.advanceTo(next)) {
                flush();
                m_mailbox->post([this, serial, failure = *sim.failure()] {
                    if (serial != m_serial) return;
                    m_failure = failure;
                    emit failed();
                });
                return;
            }
            batch.push_back(sim.diagnostics());
            while (t0 + double(gridIndex) * kSampleInterval <= sim.time()) ++gridIndex;
            if (batch.size() >= 64) {
                flush();
                if (cancelled()) return;
            }
        }
        flush();
    }
}

}  // namespace elui
