#include "core/solvers/condensed_interface.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <Eigen/Dense>

namespace thinlayer {

namespace {

// Rows `rows` and columns `cols` of a sparse matrix.
Eigen::SparseMatrix<double> block(const Eigen::SparseMatrix<double>& A, const std::vector<int>& rows,
                                  const std::vector<int>& cols) {
  std::vector<int> row_of(A.rows(), -1), col_of(A.cols(), -1);
  for (size_t i = 0; i < rows.size(); ++i) row_of[rows[i]] = static_cast<int>(i);
  for (size_t j = 0; j < cols.size(); ++j) col_of[cols[j]] = static_cast<int>(j);
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
      if (row_of[it.row()] >= 0 && col_of[it.col()] >= 0) t.emplace_back(row_of[it.row()], col_of[it.col()], it.value());
  Eigen::SparseMatrix<double> out(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

std::vector<int> all_indices(int n) {
  std::vector<int> all(n);
  for (int i = 0; i < n; ++i) all[i] = i;
  return all;
}

Eigen::VectorXd take(const Eigen::VectorXd& v, const std::vector<int>& idx) {
  Eigen::VectorXd out(idx.size());
  for (size_t i = 0; i < idx.size(); ++i) out[i] = v[idx[i]];
  return out;
}

}  // namespace

CondensedInterface::CondensedInterface(const ContactProblem& problem) {
  const auto start = std::chrono::steady_clock::now();
  const LinearSystem& system = problem.system();
  const Eigen::SparseMatrix<double>& K = system.K();
  const Eigen::SparseMatrix<double>& B = problem.B();
  const int n = system.num_free();

  std::vector<bool> on_interface(n, false);
  for (int c = 0; c < B.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(B, c); it; ++it) on_interface[it.col()] = true;
  for (int i = 0; i < n; ++i) {
    if (!system.floating(i)) supported_.push_back(i);
    else if (on_interface[i]) floating_face_.push_back(i);
    else floating_interior_.push_back(i);
  }
  std::vector<int> floating_all = floating_face_;
  floating_all.insert(floating_all.end(), floating_interior_.begin(), floating_interior_.end());
  if (block(K, supported_, floating_all).nonZeros() != 0)
    throw std::logic_error("condensation: a floating body shares stiffness with a supported one");

  const int rows = static_cast<int>(B.rows());
  W_ = Eigen::MatrixXd::Zero(rows, rows);
  g0_ = problem.jump_offset();
  if (!supported_.empty()) {
    // B touches only the interface DOFs Γ of the supported bodies: factor K_AA with Γ last,
    // whose trailing factor L_ΓΓ is that of the Schur complement S_ΓΓ (sparse_cholesky.h), so
    //   W = B_Γ S_ΓΓ⁻¹ B_Γᵀ = Zᵀ Z,   Z = L_ΓΓ⁻¹ B_Γᵀ   (one small dense triangular solve)
    // instead of 2m sparse solves with K_AA.
    std::vector<int> gamma, gamma_dofs;  // Γ as positions in supported_, and as free DOFs
    for (size_t a = 0; a < supported_.size(); ++a)
      if (on_interface[supported_[a]]) {
        gamma.push_back(static_cast<int>(a));
        gamma_dofs.push_back(supported_[a]);
      }
    if (static_cast<int>(supported_.size()) == n)  // K_AA = K: factor it without a copy
      factor_supported_ = std::make_shared<SparseCholesky>(K, gamma);
    else
      factor_supported_ = std::make_shared<SparseCholesky>(block(K, supported_, supported_), gamma);
    const Eigen::MatrixXd B_G = Eigen::MatrixXd(block(B, all_indices(rows), gamma_dofs));
    const Eigen::MatrixXd Z = factor_supported_->trailing_factor().triangularView<Eigen::Lower>().solve(B_G.transpose());
    W_ = Z.transpose() * Z;
    W_ = 0.5 * (W_ + W_.transpose()).eval();  // symmetric up to round-off; make it exact
    const Eigen::SparseMatrix<double> B_A = block(B, all_indices(rows), supported_);
    const Eigen::VectorXd F_A = take(system.F(), supported_);
    g0_ += B_A * factor_supported_->solve(F_A);
  }
  if (!floating_face_.empty()) {
    B_L_ = Eigen::MatrixXd(block(B, all_indices(rows), floating_face_));
    S_ = Eigen::MatrixXd(block(K, floating_face_, floating_face_));
    f_L_ = take(system.F(), floating_face_);
    if (!floating_interior_.empty()) {
      // The interior with its faces held is an ordinary supported problem: factor it.
      // (Not the trailing-factor route of the supported part, with the faces last and a shift
      // α on them, S = L_ff L_ffᵀ - αI: tried, it moved the bar's layer scene at ε = 1e-4 by
      // 6e-8 relative through the layer's soft modes, and the interior being a few rows of
      // nodes thick, its |f| banded solves cost less than the dense |f| × |f| factor.)
      factor_interior_ = std::make_shared<SparseCholesky>(block(K, floating_interior_, floating_interior_));
      K_if_ = block(K, floating_interior_, floating_face_);
      const Eigen::MatrixXd Y = factor_interior_->solve(Eigen::MatrixXd(K_if_));  // K_ii⁻¹ K_if
      S_ -= K_if_.transpose() * Y;
      S_ = 0.5 * (S_ + S_.transpose()).eval();
      f_L_ -= K_if_.transpose() * factor_interior_->solve(Eigen::VectorXd(take(system.F(), floating_interior_)));
    }
  } else if (!floating_interior_.empty()) {
    throw std::runtime_error("singular system: a floating body touches no interface");
  }
  setup_time_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double CondensedInterface::rcond() const {
  double r = 1;
  for (const auto& factor : {factor_supported_, factor_interior_})
    if (factor) r = std::min(r, factor->rcond());
  return r;
}

Eigen::VectorXd CondensedInterface::displacement(const ContactProblem& problem, const Eigen::VectorXd& r,
                                                 const Eigen::VectorXd& w) const {
  const LinearSystem& system = problem.system();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(system.num_free());
  const Eigen::VectorXd force = system.F() + problem.B().transpose() * r;
  if (factor_supported_) {
    const Eigen::VectorXd u_A = factor_supported_->solve(Eigen::VectorXd(take(force, supported_)));
    for (size_t i = 0; i < supported_.size(); ++i) u[supported_[i]] = u_A[i];
  }
  for (size_t i = 0; i < floating_face_.size(); ++i) u[floating_face_[i]] = w[i];
  if (factor_interior_) {
    // Interior DOFs carry no interface force: K_ii u_i = F_i - K_if w.
    const Eigen::VectorXd rhs = take(system.F(), floating_interior_) - K_if_ * w;
    const Eigen::VectorXd u_i = factor_interior_->solve(rhs);
    for (size_t i = 0; i < floating_interior_.size(); ++i) u[floating_interior_[i]] = u_i[i];
  }
  return u;
}

}  // namespace thinlayer
