#pragma once
// The matrix of linearised backward Euler as an operator for Eigen's conjugate gradient.
//
//   A u = S (M - h D - h^2 K) S u + (I - S) u
//
// S masks the free coordinates (mass > 0 and no prescribed velocity), so A is symmetric and
// the identity on fixed particles, absent axes and wall contacts (Baraff & Witkin's filter). K and D are never assembled: OdeSystem::forceJacobianProduct
// applies them spring by spring, and for each gas layer as a rank-one term plus the sparse
// pressure term (simcore/jacobians.h). This follows Eigen's "matrix-free solvers" recipe: an
// EigenBase type whose product with a dense vector is specialised below.

#include <cmath>

#include <Eigen/Core>
#include <Eigen/IterativeLinearSolvers>

#include "simcore/integrators.h"

namespace simcore {
class ImplicitOperator;
}

namespace Eigen::internal {
template <>
struct traits<simcore::ImplicitOperator> : public Eigen::internal::traits<Eigen::SparseMatrix<double>> {};
}  // namespace Eigen::internal

namespace simcore {

class ImplicitOperator : public Eigen::EigenBase<ImplicitOperator> {
public:
    using Scalar = double;
    using RealScalar = double;
    using StorageIndex = int;
    enum { ColsAtCompileTime = Eigen::Dynamic, MaxColsAtCompileTime = Eigen::Dynamic, IsRowMajor = false };

    Eigen::Index rows() const { return m_n; }
    Eigen::Index cols() const { return m_n; }

    template <typename Rhs>
    Eigen::Product<ImplicitOperator, Rhs, Eigen::AliasFreeProduct> operator*(const Eigen::MatrixBase<Rhs>& x) const {
        return Eigen::Product<ImplicitOperator, Rhs, Eigen::AliasFreeProduct>(*this, x.derived());
    }

    void resize(Eigen::Index n) {
        m_n = n;
        m_u.setZero(n);
        m_ku.setZero(n);
        m_du.setZero(n);
        m_out.setZero(n);
        m_zero.setZero(n);
        m_kdiag.setZero(n);
        m_ddiag.setZero(n);
        m_diagonal.setZero(n);
        m_free.setZero(n);
    }
    // Binds the system (already linearised) and the step h; computes the diagonal.
    void set(OdeSystem& system, double h) {
        m_system = &system;
        m_h = h;
        system.forceJacobianDiagonal(m_kdiag, m_ddiag);
        constrain(nullptr);
    }
    // Coordinates where `prescribed` is finite leave the free set (nullptr: none).
    void constrain(const Eigen::VectorXd* prescribed) {
        const Eigen::VectorXd& mass = m_system->coordinateMass();
        for (Eigen::Index i = 0; i < m_n; ++i) {
            const bool free = mass[i] > 0.0 && !(prescribed && std::isfinite((*prescribed)[i]));
            m_free[i] = free ? 1.0 : 0.0;
            m_diagonal[i] = free ? mass[i] - m_h * m_ddiag[i] - m_h * m_h * m_kdiag[i] : 1.0;
        }
    }
    bool isFree(Eigen::Index i) const { return m_free[i] != 0.0; }
    // (M - h D - h^2 K) z for z supported on constrained coordinates: what a prescribed
    // velocity change does to the free rows (moved to the right-hand side).
    const Eigen::VectorXd& coupling(const Eigen::VectorXd& z) const {
        m_system->forceJacobianProduct(z, m_zero, m_ku);
        m_system->forceJacobianProduct(m_zero, z, m_du);
        const Eigen::VectorXd& mass = m_system->coordinateMass();
        for (Eigen::Index i = 0; i < m_n; ++i) m_out[i] = mass[i] * z[i] - m_h * m_du[i] - m_h * m_h * m_ku[i];
        return m_out;
    }
    const Eigen::VectorXd& diagonal() const { return m_diagonal; }

    // A u, in scratch owned by the operator (the solver holds it by const reference).
    template <typename Vec>
    const Eigen::VectorXd& product(const Vec& u) const {
        Eigen::VectorXd& out = m_out;
        const Eigen::VectorXd& mass = m_system->coordinateMass();
        for (Eigen::Index i = 0; i < m_n; ++i) m_u[i] = m_free[i] * u[i];
        // (K u) and (D u) in one pass each: K dx with dv = 0, then D dv with dx = 0.
        m_system->forceJacobianProduct(m_u, m_zero, m_ku);
        m_system->forceJacobianProduct(m_zero, m_u, m_du);
        for (Eigen::Index i = 0; i < m_n; ++i)
            out[i] = m_free[i] != 0.0 ? mass[i] * m_u[i] - m_h * m_du[i] - m_h * m_h * m_ku[i] : u[i];
        return out;
    }

private:
    Eigen::Index m_n = 0;
    OdeSystem* m_system = nullptr;
    double m_h = 0.0;
    mutable Eigen::VectorXd m_u, m_ku, m_du, m_out;
    Eigen::VectorXd m_zero, m_kdiag, m_ddiag, m_diagonal, m_free;
};

// Jacobi preconditioner reading ImplicitOperator::diagonal() (Eigen's DiagonalPreconditioner
// needs coefficient access, which a matrix-free operator does not have).
class JacobiPreconditioner {
public:
    JacobiPreconditioner() = default;
    template <typename MatType>
    explicit JacobiPreconditioner(const MatType& mat) {
        compute(mat);
    }
    Eigen::Index rows() const { return m_inverse.size(); }
    Eigen::Index cols() const { return m_inverse.size(); }
    template <typename MatType>
    JacobiPreconditioner& analyzePattern(const MatType&) {
        return *this;
    }
    template <typename MatType>
    JacobiPreconditioner& factorize(const MatType& mat) {
        m_inverse = mat.diagonal();
        for (Eigen::Index i = 0; i < m_inverse.size(); ++i)
            m_inverse[i] = m_inverse[i] > 0.0 ? 1.0 / m_inverse[i] : 1.0;
        return *this;
    }
    template <typename MatType>
    JacobiPreconditioner& compute(const MatType& mat) {
        return factorize(mat);
    }
    template <typename Rhs>
    auto solve(const Eigen::MatrixBase<Rhs>& b) const {
        return (m_inverse.array() * b.derived().array()).matrix();
    }
    Eigen::ComputationInfo info() const { return Eigen::Success; }

private:
    Eigen::VectorXd m_inverse;
};

}  // namespace simcore

namespace Eigen::internal {
template <typename Rhs>
struct generic_product_impl<simcore::ImplicitOperator, Rhs, SparseShape, DenseShape, GemvProduct>
    : generic_product_impl_base<simcore::ImplicitOperator, Rhs,
                                generic_product_impl<simcore::ImplicitOperator, Rhs>> {
    using Scalar = typename Product<simcore::ImplicitOperator, Rhs>::Scalar;
    template <typename Dest>
    static void scaleAndAddTo(Dest& dst, const simcore::ImplicitOperator& lhs, const Rhs& rhs,
                              const Scalar& alpha) {
        dst.noalias() += alpha * lhs.product(rhs);
    }
};
}  // namespace Eigen::internal
