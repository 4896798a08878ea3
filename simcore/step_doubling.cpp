#include "simcore/step_doubling.h"

#include <algorithm>
#include <cmath>

namespace simcore {

void StepDoubling::prepare(Eigen::Index size) {
    m_start.setZero(size);
    m_full.setZero(size);
    m_error.setZero(size);
    m_hasError = false;
}

void StepDoubling::release() {
    m_start.resize(0);
    m_full.resize(0);
    m_error.resize(0);
    m_hasError = false;
}

StepReport StepDoubling::step(Integrator& method, OdeSystem& system, double t, double h, Eigen::VectorXd& y) {
    m_hasError = false;
    m_start = y;
    StepReport report = method.step(system, t, h, y);
    // A failed or non-finite step has nothing to estimate (the caller fails it).
    if (report.failure || !y.allFinite()) return report;
    m_full = y;
    y = m_start;
    const double half = 0.5 * report.h;
    const StepReport first = method.step(system, t, half, y);
    const StepReport second = first.failure ? first : method.step(system, t + half, half, y);
    const double p = method.order();
    const Eigen::Index n = system.layout().positions;
    const double particles = static_cast<double>(n / 3);
    const double rms = std::sqrt((y.head(n) - m_full.head(n)).squaredNorm() / std::max(1.0, particles));
    report.errorEstimate = second.failure || !std::isfinite(rms) ? -1.0 : rms / (1.0 - std::pow(2.0, -p));
    if (report.errorEstimate >= 0.0) {
        m_error = (y - m_full) / (1.0 - std::pow(2.0, -p));
        m_hasError = true;
    }
    y = m_full;
    return report;
}

}  // namespace simcore
