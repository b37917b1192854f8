#pragma once
// The smoother of the layer's descent (core/solvers/tnnmg.h): on the Tresca energy J_s of
// core/solvers/descent_blocks.h, the adherents off S solved exactly (one Cholesky factor, kept), then
// each block — a film column and the adherent nodes facing it — minimised exactly with the rest held
// (core/solvers/block_minimiser.h), forward then backward. Each row ends on one branch: open, at its
// kink (d = 0), or sliding one way; those branches are what a truncated correction holds.
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/linalg/sparse_cholesky.h"
#include "core/solvers/block_minimiser.h"
#include "core/solvers/descent_blocks.h"
#include "core/solvers/mixed_system.h"

namespace thinlayer {

class LayerSmoother {
 public:
  LayerSmoother(const MixedSystem& mixed, const ContactProblem& problem, const DescentBlocks& blocks);

  // One sweep forward and one backward, on J_s with these rows and row thresholds (force unit; the
  // tangential row of node k at 2k + 1), from y (updated in place).
  void sweep(const std::vector<RowKind>& kind, const Eigen::VectorXd& row_threshold, Eigen::VectorXd& y);
  // The projection of y onto dom φ, block by block, in each block's energy norm (block_minimiser.h).
  Eigen::VectorXd project(const std::vector<RowKind>& kind, Eigen::VectorXd y) const;

  // Each row's branch and multiplier λ (r = −λ), as the last solve of its block left them.
  const std::vector<RowState>& state() const { return state_; }
  const Eigen::VectorXd& lambda() const { return lambda_; }
  int branches_solved() const { return branches_solved_; }
  double worst_inconsistency() const { return worst_inconsistency_; }
  void reset_counters() {
    branches_solved_ = 0;
    worst_inconsistency_ = 0;
  }

 private:
  // Each block's constant parts, dense: its stiffness, jump rows and offsets.
  struct BlockData {
    Eigen::MatrixXd A, G;
    Eigen::VectorXd g;
  };
  void solve_interior(Eigen::VectorXd& y);
  void solve_block(size_t b, const std::vector<RowKind>& kind, const Eigen::VectorXd& row_threshold, Eigen::VectorXd& y);

  const DescentBlocks& blocks_;
  const Eigen::SparseMatrix<double>& K_;
  const Eigen::VectorXd& F_;
  std::vector<BlockData> data_;
  Eigen::SparseMatrix<double> K_II_, K_IB_;
  std::vector<int> boundary_;
  std::unique_ptr<SparseCholesky> interior_factor_;
  std::vector<RowState> state_;
  std::vector<bool> fresh_;
  Eigen::VectorXd lambda_;
  int branches_solved_ = 0;
  double worst_inconsistency_ = 0;
};

}  // namespace thinlayer
