#pragma once
// SUNDIALS CVODE behind the integrator interface (issue 13): cvode-bdf and cvode-adams.
// Only the factory is public; SUNDIALS headers stay inside cvode_integrators.cpp.

#include <memory>

#include "simcore/integrators.h"

namespace simcore {

// bdf = true: variable-order BDF (1-5), Newton with matrix-free GMRES on the analytic
// Jacobian-vector product, preconditioned by implicit-euler's solve. false: variable-order
// Adams-Moulton (1-12) with fixed-point (functional) iteration.
std::unique_ptr<Integrator> makeCvodeIntegrator(bool bdf);

}  // namespace simcore
