#include "core/solvers/condensed_interface.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

#include "core/linalg/cholesky_inverse.h"
#include "core/linalg/connected_components.h"

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

// Rows and columns `idx` (ascending) of a sparse matrix: the principal block of one body.
// Column by column in order, its entries already sorted, so no triplets and no sort: it is on
// the path of every limit-mode solve: the dovetail's two bodies at h = 0.0125 in 0.9 ms, where
// block() (every column, triplets, a sort) took 3.8 ms, a tenth of a linear solve.
Eigen::SparseMatrix<double> principal_block(const Eigen::SparseMatrix<double>& A, const std::vector<int>& idx) {
  std::vector<int> position(A.rows(), -1);
  for (size_t k = 0; k < idx.size(); ++k) position[idx[k]] = static_cast<int>(k);
  const auto m = static_cast<Eigen::Index>(idx.size());
  Eigen::SparseMatrix<double> out(m, m);
  out.reserve(A.nonZeros());
  for (Eigen::Index j = 0; j < m; ++j) {
    out.startVec(j);
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, idx[j]); it; ++it)
      if (position[it.row()] >= 0) out.insertBack(position[it.row()], j) = it.value();
  }
  out.finalize();
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

// The supported free DOFs, one list (ascending) per connected body of K's graph. A body must
// be wholly supported or wholly floating: the two are condensed differently.
std::vector<std::vector<int>> supported_bodies(const LinearSystem& system) {
  const std::vector<int> part = connected_components(system.K());
  std::vector<int> body_of_part(part.empty() ? 0 : *std::max_element(part.begin(), part.end()) + 1, -1);
  std::vector<bool> part_floats(body_of_part.size(), false);
  for (int i = 0; i < system.num_free(); ++i)
    if (system.floating(i)) part_floats[part[i]] = true;
  std::vector<std::vector<int>> bodies;
  for (int i = 0; i < system.num_free(); ++i) {
    if (system.floating(i)) continue;
    if (part_floats[part[i]])
      throw std::logic_error("condensation: a floating body shares stiffness with a supported one");
    int& body = body_of_part[part[i]];
    if (body < 0) {
      body = static_cast<int>(bodies.size());
      bodies.emplace_back();
    }
    bodies[body].push_back(i);
  }
  return bodies;
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
    if (!system.floating(i)) continue;
    if (on_interface[i]) floating_face_.push_back(i);
    else floating_interior_.push_back(i);
  }

  const int rows = static_cast<int>(B.rows());
  W_ = Eigen::MatrixXd::Zero(rows, rows);
  g0_ = problem.jump_offset();
  for (std::vector<int>& dofs : supported_bodies(system)) condense_body(problem, std::move(dofs), on_interface);
  W_ = 0.5 * (W_ + W_.transpose()).eval();  // symmetric up to round-off; make it exact

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

void CondensedInterface::condense_body(const ContactProblem& problem, std::vector<int> dofs,
                                       const std::vector<bool>& on_interface) {
  const LinearSystem& system = problem.system();
  const Eigen::SparseMatrix<double>& B = problem.B();
  const int rows = static_cast<int>(B.rows());
  std::vector<int> gamma, gamma_dofs;  // Γ_b as positions in dofs, and as free DOFs
  for (size_t a = 0; a < dofs.size(); ++a)
    if (on_interface[dofs[a]]) {
      gamma.push_back(static_cast<int>(a));
      gamma_dofs.push_back(dofs[a]);
    }
  Eigen::SparseMatrix<double> K_b;
  const bool whole = static_cast<int>(dofs.size()) == system.num_free();  // K_b = K: no copy
  if (!whole) K_b = principal_block(system.K(), dofs);
  const Eigen::SparseMatrix<double>& K_body = whole ? system.K() : K_b;
  SupportedBody body{std::move(dofs), nullptr};
  body.factor = gamma.empty() ? std::make_shared<SparseCholesky>(K_body)
                              : std::make_shared<SparseCholesky>(K_body, gamma);
  if (!gamma.empty()) {
    // B touches only Γ_b of this body: W_b = B_Γ S_b⁻¹ B_Γᵀ, S_b⁻¹ from the trailing factor
    // L_ΓΓ (L_ΓΓ L_ΓΓᵀ = S_b). B_Γ is sparse (a few entries per jump row), so both products
    // cost |Γ_b| per entry of B_Γ, against (2/3)|Γ_b|³ for the inverse.
    const Eigen::SparseMatrix<double> B_G = block(B, all_indices(rows), gamma_dofs);
    const Eigen::MatrixXd B_S = B_G * cholesky_inverse(body.factor->trailing_factor());  // B_Γ S_b⁻¹
    W_ += B_G * B_S.transpose();  // S_b⁻¹ is symmetric: (B_Γ S_b⁻¹)ᵀ = S_b⁻¹ B_Γᵀ
  }
  const Eigen::SparseMatrix<double> B_b = block(B, all_indices(rows), body.dofs);
  g0_ += B_b * body.factor->solve(Eigen::VectorXd(take(system.F(), body.dofs)));
  supported_.push_back(std::move(body));
}

double CondensedInterface::rcond() const {
  double r = 1;
  for (const SupportedBody& body : supported_) r = std::min(r, body.factor->rcond());
  if (factor_interior_) r = std::min(r, factor_interior_->rcond());
  return r;
}

Eigen::VectorXd CondensedInterface::displacement(const ContactProblem& problem, const Eigen::VectorXd& r,
                                                 const Eigen::VectorXd& w) const {
  const LinearSystem& system = problem.system();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(system.num_free());
  const Eigen::VectorXd force = system.F() + problem.B().transpose() * r;
  for (const SupportedBody& body : supported_) {
    const Eigen::VectorXd u_b = body.factor->solve(Eigen::VectorXd(take(force, body.dofs)));
    for (size_t i = 0; i < body.dofs.size(); ++i) u[body.dofs[i]] = u_b[i];
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
