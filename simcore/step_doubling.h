#pragma once
// StepDoubling: Richardson's local error estimate for a fixed-step method, as a wrapper
// around its step.
//
//   y_h      one step of h from y0          (what the run keeps)
//   y_h/2    two steps of h/2 from y0
//   e        (y_h/2 - y_h) / (1 - 2^-p)     the local error of y_h, p the method's order
//
// (y_h/2's own error is 2^-p of it.) The run keeps y_h, so switching the estimate on changes
// nothing but the cost: about twice the evaluations, all counted. The report's
// errorEstimate is the root mean square of e's positions per particle, < 0 when the half
// steps failed or the estimate is not finite.

#include <Eigen/Core>

#include "simcore/integrators.h"

namespace simcore {

class StepDoubling {
public:
    // Sizes the buffers for states of `size` (held only while the estimate is on: the memory
    // bound counts what a run holds); release() gives them back.
    void prepare(Eigen::Index size);
    void release();
    bool ready(Eigen::Index size) const { return m_error.size() == size; }
    // One step of h of `method` on y (y0 in, y_h out) with the estimate in the report.
    StepReport step(Integrator& method, OdeSystem& system, double t, double h, Eigen::VectorXd& y);
    // e over the whole state from the last step, nullptr when it had none.
    const double* localError() const { return m_hasError ? m_error.data() : nullptr; }

private:
    Eigen::VectorXd m_start;      // y0
    Eigen::VectorXd m_full;       // y_h
    Eigen::VectorXd m_error;      // e
    bool m_hasError = false;
};

}  // namespace simcore
