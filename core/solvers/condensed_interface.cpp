#include "core/solvers/condensed_interface.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <utility>

#include <Eigen/Dense>

#include "core/linalg/connected_components.h"
#include "core/linalg/sparse_block.h"

namespace thinlayer {

namespace {

// Rows and columns `idx` (ascending) of a sparse matrix: the principal block of one body.
// Column by column in order, its entries already sorted, so no triplets and no sort: it is on
// the path of every limit-mode solve: the dovetail's two bodies at h = 0.0125 in 0.9 ms, where
// sparse_block() (every column, triplets, a sort) took 3.8 ms, a tenth of a linear solve.
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

// The supported free DOFs (ascending). A body must be wholly supported or wholly floating: the
// two are condensed differently, so a connected part of K holding both is refused.
std::vector<int> supported_dofs(const LinearSystem& system) {
  std::vector<int> dofs;
  for (int i = 0; i < system.num_free(); ++i)
    if (!system.floating(i)) dofs.push_back(i);
  if (static_cast<int>(dofs.size()) == system.num_free()) return dofs;  // nothing floats
  const std::vector<int> part = connected_components(system.K());
  std::vector<bool> part_floats(system.num_free(), false);
  for (int i = 0; i < system.num_free(); ++i)
    if (system.floating(i)) part_floats[part[i]] = true;
  for (int i : dofs)
    if (part_floats[part[i]]) throw std::logic_error("condensation: a floating body shares stiffness with a supported one");
  return dofs;
}

}  // namespace

CondensedInterface::CondensedInterface(const ContactProblem& problem) {
  const auto start = std::chrono::steady_clock::now();
  const LinearSystem& system = problem.system();
  const Eigen::SparseMatrix<double>& B = problem.B();
  const int n = system.num_free();

  std::vector<bool> on_interface(n, false);
  for (int c = 0; c < B.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(B, c); it; ++it) on_interface[it.col()] = true;

  condense_supported(problem, supported_dofs(system));
  condense_floating(problem, on_interface);
  setup_time_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void CondensedInterface::condense_supported(const ContactProblem& problem, std::vector<int> dofs) {
  const LinearSystem& system = problem.system();
  const Eigen::SparseMatrix<double>& B = problem.B();
  const int rows = static_cast<int>(B.rows());
  g0_ = problem.jump_offset();
  supported_ = std::move(dofs);
  if (supported_.empty()) {
    W_ = Eigen::MatrixXd::Zero(rows, rows);
    return;
  }
  // All supported (limit mode): K and B as they are, no copies.
  const bool whole = static_cast<int>(supported_.size()) == system.num_free();
  Eigen::SparseMatrix<double> K_s, B_s;
  if (!whole) K_s = principal_block(system.K(), supported_), B_s = sparse_block(B, all_indices(rows), supported_);
  factor_ = std::make_shared<SparseCholesky>(whole ? system.K() : K_s);
  const Eigen::SparseMatrix<double>& B_supported = whole ? B : B_s;
  W_ = factor_->inverse_congruence(B_supported);
  g0_ += B_supported * factor_->solve(Eigen::VectorXd(take(system.F(), supported_)));
}

void CondensedInterface::condense_floating(const ContactProblem& problem, const std::vector<bool>& on_interface) {
  const LinearSystem& system = problem.system();
  std::vector<bool> is_band(system.num_bodies(), false);
  for (const FloatingBand& band : system.floating_bands()) {
    is_band[band.body] = true;
    floating_.push_back(FloatingCondensation::band(band, on_interface));
  }
  std::vector<std::vector<int>> nodal(system.num_bodies());  // the other floating bodies' free DOFs
  for (int i = 0; i < system.num_free(); ++i)
    if (system.floating(i) && !is_band[system.body_of(i)]) nodal[system.body_of(i)].push_back(i);
  for (const std::vector<int>& dofs : nodal) {
    if (dofs.empty()) continue;
    if (std::none_of(dofs.begin(), dofs.end(), [&](int i) { return static_cast<bool>(on_interface[i]); }))
      throw std::runtime_error("singular system: a floating body touches no interface");
    floating_.push_back(FloatingCondensation::nodal(system, dofs, on_interface));
  }
  int size = 0;
  for (const FloatingCondensation& f : floating_) size += f.size();
  if (!size) return;
  const Eigen::SparseMatrix<double>& B = problem.B();
  B_L_ = Eigen::MatrixXd::Zero(B.rows(), size);
  S_ = Eigen::MatrixXd::Zero(size, size);
  f_L_ = Eigen::VectorXd::Zero(size);
  int offset = 0;
  for (const FloatingCondensation& f : floating_) {
    B_L_.middleCols(offset, f.size()) = Eigen::MatrixXd(sparse_block(B, all_indices(static_cast<int>(B.rows())), f.face_dofs())) * f.T();
    S_.block(offset, offset, f.size(), f.size()) = f.S();
    f_L_.segment(offset, f.size()) = f.f();
    offset += f.size();
  }
}

std::vector<Eigen::VectorXd> CondensedInterface::band_coordinates(const Eigen::VectorXd& x) const {
  std::vector<Eigen::VectorXd> z;
  int offset = 0;
  for (const FloatingCondensation& f : floating_) {
    if (f.is_band()) z.push_back(x.segment(offset, f.size()));
    offset += f.size();
  }
  return z;
}

Eigen::VectorXd CondensedInterface::floating_unknowns(const Eigen::VectorXd& u,
                                                      const std::vector<Eigen::VectorXd>& band_z) const {
  Eigen::VectorXd x(S_.rows());
  int offset = 0;
  size_t band = 0;
  for (const FloatingCondensation& f : floating_) {
    if (f.is_band()) {
      x.segment(offset, f.size()) = band_z.at(band++);
    } else {  // a nodal body's x is its face DOFs
      for (int k = 0; k < f.size(); ++k) x[offset + k] = u[f.face_dofs()[k]];
    }
    offset += f.size();
  }
  return x;
}

Eigen::MatrixXd CondensedInterface::floating_selection(LayerSelection face) const {
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(S_.rows(), S_.cols());
  int offset = 0;
  for (const FloatingCondensation& f : floating_) {
    P.block(offset, offset, f.size(), f.size()) = f.selection(face);
    offset += f.size();
  }
  return P;
}

double CondensedInterface::rcond() const {
  double r = factor_ ? factor_->rcond() : 1.0;
  for (const FloatingCondensation& f : floating_) r = std::min(r, f.rcond());
  return r;
}

Eigen::VectorXd CondensedInterface::displacement(const ContactProblem& problem, const Eigen::VectorXd& r,
                                                 const Eigen::VectorXd& x) const {
  const LinearSystem& system = problem.system();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(system.num_free());
  const Eigen::VectorXd force = system.F() + problem.B().transpose() * r;
  if (factor_) {
    const Eigen::VectorXd u_s = factor_->solve(Eigen::VectorXd(take(force, supported_)));
    for (size_t i = 0; i < supported_.size(); ++i) u[supported_[i]] = u_s[i];
  }
  int offset = 0;
  for (const FloatingCondensation& f : floating_) {
    f.displacement(x.segment(offset, f.size()), u);
    offset += f.size();
  }
  return u;
}

}  // namespace thinlayer
