#include "core/solvers/layer_smoother.h"

#include <algorithm>

#include "core/linalg/sparse_block.h"

namespace thinlayer {

LayerSmoother::LayerSmoother(const MixedSystem& mixed, const ContactProblem& problem, const DescentBlocks& blocks)
    : blocks_(blocks), K_(mixed.K_y()), F_(mixed.F_y()) {
  const auto& B = mixed.B_y();
  const Eigen::SparseMatrix<double> B_col = B;  // column access for the dense blocks
  for (const DescentBlock& b : blocks.blocks) {
    BlockData data;
    const int n = static_cast<int>(b.y.size()), rows = static_cast<int>(b.rows.size());
    data.A = Eigen::MatrixXd::Zero(n, n);
    data.G = Eigen::MatrixXd::Zero(rows, n);
    data.g.resize(rows);
    std::vector<int> local(mixed.num_unknowns(), -1);
    for (int a = 0; a < n; ++a) local[b.y[a]] = a;
    for (int a = 0; a < n; ++a)
      for (Eigen::SparseMatrix<double>::InnerIterator it(K_, b.y[a]); it; ++it)
        if (local[it.row()] >= 0) data.A(local[it.row()], a) = it.value();
    for (int q = 0; q < rows; ++q) {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B, b.rows[q]); it; ++it)
        data.G(q, local[it.col()]) = it.value();
      data.g[q] = problem.jump_offset()[b.rows[q]];
    }
    data_.push_back(std::move(data));
  }
  if (!blocks.interior.empty()) {
    std::vector<int> boundary;
    for (const DescentBlock& b : blocks.blocks) boundary.insert(boundary.end(), b.y.begin(), b.y.end());
    K_II_ = sparse_block(K_, blocks.interior, blocks.interior);
    K_IB_ = sparse_block(K_, blocks.interior, boundary);
    boundary_ = boundary;
    interior_factor_ = std::make_unique<SparseCholesky>(K_II_);
  }
  state_.assign(B.rows(), RowState::Kink);
  fresh_.assign(blocks.blocks.size(), true);
}

void LayerSmoother::sweep(const std::vector<RowKind>& kind, const Eigen::VectorXd& row_threshold, Eigen::VectorXd& y) {
  solve_interior(y);
  for (size_t b = 0; b < data_.size(); ++b) solve_block(b, kind, row_threshold, y);
  solve_interior(y);
  for (size_t b = data_.size(); b-- > 0;) solve_block(b, kind, row_threshold, y);
}

Eigen::VectorXd LayerSmoother::project(const std::vector<RowKind>& kind, Eigen::VectorXd y) const {
  for (size_t b = 0; b < data_.size(); ++b) {
    const DescentBlock& block = blocks_.blocks[b];
    Eigen::VectorXd x(block.y.size());
    for (size_t a = 0; a < block.y.size(); ++a) x[a] = y[block.y[a]];
    std::vector<RowKind> k(block.rows.size());
    for (size_t q = 0; q < block.rows.size(); ++q) k[q] = kind[block.rows[q]];
    const Eigen::VectorXd p = project_to_domain(data_[b].A, data_[b].G, data_[b].g, k, x);
    for (size_t a = 0; a < block.y.size(); ++a) y[block.y[a]] = p[a];
  }
  return y;
}

void LayerSmoother::solve_interior(Eigen::VectorXd& y) {
  if (!interior_factor_) return;
  Eigen::VectorXd y_B(boundary_.size());
  for (size_t a = 0; a < boundary_.size(); ++a) y_B[a] = y[boundary_[a]];
  Eigen::VectorXd rhs(blocks_.interior.size());
  for (size_t a = 0; a < blocks_.interior.size(); ++a) rhs[a] = F_[blocks_.interior[a]];
  rhs -= K_IB_ * y_B;
  const Eigen::VectorXd y_I = interior_factor_->solve(rhs);
  for (size_t a = 0; a < blocks_.interior.size(); ++a) y[blocks_.interior[a]] = y_I[a];
}


void LayerSmoother::solve_block(size_t b, const std::vector<RowKind>& kind, const Eigen::VectorXd& row_threshold, Eigen::VectorXd& y) {
  const DescentBlock& block = blocks_.blocks[b];
  const BlockData& data = data_[b];
  const int n = static_cast<int>(block.y.size()), rows = static_cast<int>(block.rows.size());
  BlockProblem p;
  p.A = data.A;
  p.G = data.G;
  p.g = data.g;
  Eigen::VectorXd x(n);
  for (int a = 0; a < n; ++a) x[a] = y[block.y[a]];
  // c = F_J − K_{J,rest} y_rest = F_J − (K y)_J + A x (K symmetric: its column j is its row j).
  p.c.resize(n);
  for (int a = 0; a < n; ++a) {
    double Ky = 0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(K_, block.y[a]); it; ++it) Ky += it.value() * y[it.row()];
    p.c[a] = F_[block.y[a]] - Ky;
  }
  p.c += data.A * x;
  p.kind.resize(rows);
  p.s.resize(rows);
  std::vector<RowState> guess(rows);
  for (int q = 0; q < rows; ++q) {
    p.kind[q] = kind[block.rows[q]];
    p.s[q] = row_threshold[block.rows[q]];
    guess[q] = state_[block.rows[q]];
  }
  const BlockMinimum m = minimise_block(p, fresh_[b] ? std::vector<RowState>{} : guess);
  fresh_[b] = false;
  branches_solved_ += m.branches_solved;
  worst_inconsistency_ = std::max(worst_inconsistency_, m.inconsistency);
  for (int a = 0; a < n; ++a) y[block.y[a]] = m.x[a];
  if (lambda_.size() != static_cast<Eigen::Index>(state_.size())) lambda_ = Eigen::VectorXd::Zero(state_.size());
  for (int q = 0; q < rows; ++q) {
    state_[block.rows[q]] = m.state[q];
    lambda_[block.rows[q]] = m.lambda[q];
  }
}


}  // namespace thinlayer
