#pragma once
// The yardstick of issue 13's timing target: one linear solve of the same three-body mesh with
// the layer bonded to both adherents. Every interface node pair is tied (its two DOFs merged
// into one unknown), the merged stiffness factored with CHOLMOD and solved once.
#include <algorithm>
#include <chrono>
#include <numeric>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/linalg/sparse_cholesky.h"
#include "core/solvers/contact_problem.h"

namespace thinlayer {

// Seconds for the merge, the factorisation and the solve (wall clock, one run).
inline double bonded_solve_seconds(const ContactProblem& problem) {
  const auto start = std::chrono::steady_clock::now();
  const LinearSystem& system = problem.system();
  const int n = system.num_free();
  // Union of the free DOFs across every interface node pair (x with x, y with y).
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceNode& node = problem.node(k);
    if (node.on_foundation()) continue;
    for (int c = 0; c < 2; ++c) {
      const int a = system.free_index(node.plus_dof_x + c), b = system.free_index(node.minus_dof_x + c);
      if (a >= 0 && b >= 0) parent[root(a)] = root(b);
    }
  }
  std::vector<int> merged(n, -1);
  int m = 0;
  for (int i = 0; i < n; ++i)
    if (root(i) == i) merged[i] = m++;
  std::vector<Eigen::Triplet<double>> t;
  const Eigen::SparseMatrix<double>& K = system.K();
  for (int c = 0; c < K.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it)
      t.emplace_back(merged[root(static_cast<int>(it.row()))], merged[root(static_cast<int>(it.col()))], it.value());
  Eigen::SparseMatrix<double> K_bonded(m, m);
  K_bonded.setFromTriplets(t.begin(), t.end());
  Eigen::VectorXd F = Eigen::VectorXd::Zero(m);
  for (int i = 0; i < n; ++i) F[merged[root(i)]] += system.F()[i];
  const SparseCholesky factor(K_bonded);
  const Eigen::VectorXd u = factor.solve(F);
  volatile double sink = u.sum();  // keep the solve
  (void)sink;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace thinlayer
