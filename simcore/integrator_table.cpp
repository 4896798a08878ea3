#include "simcore/integrator_table.h"

#include <array>
#include <cmath>

#include "simcore/internal/cvode_integrators.h"
#include "simcore/internal/integrator_makers.h"
#include "simcore/params.h"

namespace simcore {

namespace {
// clang-format off
constexpr std::array kIntegrators = {
    IntegratorInfo{"euler", 1, "explicit Euler: x and v both from the old state (thesis eq. 22)", "explicit-rk"},
    IntegratorInfo{"midpoint", 2, "the thesis's midpoint (eq. 31-33), i.e. Heun's RK2: two force evaluations", "explicit-rk"},
    IntegratorInfo{"rk4", 4, "classical Runge-Kutta 4 (eq. 35-40): four force evaluations", "explicit-rk"},
    IntegratorInfo{"symplectic-euler", 1, "semi-implicit Euler: v from the old forces, then x from the new v", "symplectic"},
    IntegratorInfo{"verlet", 2, "velocity Verlet (order 1 when damping is on: damping is taken at the half-step velocity)", "symplectic"},
    IntegratorInfo{"yoshida4", 4, "Yoshida's 4th-order composition of velocity Verlet: 3 substeps (one backwards), 4 force evaluations (order 1 with damping)", "symplectic"},
    IntegratorInfo{"yoshida8", 8, "Yoshida's 8th-order composition of velocity Verlet (solution D): 15 substeps, 16 force evaluations (order 1 with damping)", "symplectic"},
    IntegratorInfo{"rk45", 5, "Dormand-Prince 5(4): adaptive step from atol/rtol, embedded error estimate every step", "adaptive"},
    IntegratorInfo{"implicit-euler", 1, "linearised backward Euler (Baraff-Witkin 1998): spring and gas Jacobians, matrix-free CG", "implicit"},
    IntegratorInfo{"cvode-bdf", 5, "SUNDIALS CVODE, variable-order BDF 1-5: Newton, matrix-free GMRES on the analytic Jacobian, implicit-euler's solve as preconditioner; adaptive from atol/rtol", "production"},
    IntegratorInfo{"xpbd", 1, "extended position-based dynamics (Macklin et al. 2016, small steps 2019): springs as compliant distance constraints, `substeps` substeps of one iteration per step", "constraint"},
    IntegratorInfo{"cvode-adams", 12, "SUNDIALS CVODE, variable-order Adams-Moulton 1-12 with fixed-point iteration (non-stiff); adaptive from atol/rtol", "production"},
};
// clang-format on
}  // namespace

std::span<const IntegratorInfo> integratorTable() { return kIntegrators; }

std::unique_ptr<Integrator> makeIntegrator(std::string_view name) {
    if (auto explicitMethod = makeExplicitIntegrator(name)) return explicitMethod;
    if (name == "implicit-euler") return makeImplicitEuler();
    if (name == "cvode-bdf") return makeCvodeIntegrator(true);
    if (name == "cvode-adams") return makeCvodeIntegrator(false);
    if (name == "xpbd") return makeXpbd();
    return nullptr;
}

bool hasStabilityFunction(std::string_view name) {
    return name == "euler" || name == "midpoint" || name == "rk4" || name == "rk45" ||
           name == "implicit-euler";
}

std::complex<double> stabilityFunction(std::string_view name, std::complex<double> z) {
    // Truncated exponential series for the explicit Runge-Kutta methods; Dormand-Prince's
    // 5th-order solution adds z^6/600 (its 6 stages cannot match e^z to 6th order).
    const std::complex<double> one(1.0, 0.0);
    if (name == "euler") return one + z;
    if (name == "midpoint") return one + z + z * z / 2.0;
    if (name == "rk4") return one + z * (one + z / 2.0 * (one + z / 3.0 * (one + z / 4.0)));
    if (name == "rk45")
        return one + z * (one + z / 2.0 * (one + z / 3.0 * (one + z / 4.0 * (one + z / 5.0)))) +
               std::pow(z, 6) / 600.0;
    if (name == "implicit-euler") return one / (one - z);
    return {std::nan(""), 0.0};
}

std::string_view integratorFamily(std::string_view name) {
    for (const auto& info : integratorTable())
        if (info.name == name) return info.family;
    return {};
}

std::span<const std::string_view> integratorFamilies() {
    static constexpr std::array<std::string_view, 6> families = {"explicit-rk", "symplectic", "implicit",
                                                                 "adaptive",    "production", "constraint"};
    return families;
}

std::optional<std::string> unknownIntegrator(std::string_view name) {
    for (const auto& info : integratorTable())
        if (info.name == name) return std::nullopt;
    return "unknown integrator " + quoteShort(name) + "; allowed: " + integratorNames();
}

std::string integratorNames() {
    std::string names;
    for (const auto& info : integratorTable()) {
        if (!names.empty()) names += ", ";
        names += info.name;
    }
    return names;
}

}  // namespace simcore
