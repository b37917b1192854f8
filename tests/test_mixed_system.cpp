// The whole contact problem as one sparse system for given statuses (core/solvers/mixed_system.h)
// and the sparse LU under it (core/linalg/sparse_lu.h): the fast solver's last word (issue 25).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/SparseCore>

#include "cases/bar/bar.h"
#include "core/linalg/sparse_lu.h"
#include "core/solvers/condensed_interface.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/mixed_system.h"

namespace thinlayer {
namespace {

// A well-conditioned sparse matrix M (diagonally dominant), then A = D_r M D_c with row and column
// scales spread over 1e-12 … 1e12: its condition number is ~1e24, but only through the scales.
Eigen::SparseMatrix<double> badly_scaled(int n, unsigned seed, Eigen::VectorXd& Dr, Eigen::VectorXd& Dc,
                                         double diagonal_shift = 0) {
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> u(-1, 1), e(-12, 12);
  std::vector<Eigen::Triplet<double>> t;
  Dr.resize(n);
  Dc.resize(n);
  for (int i = 0; i < n; ++i) {
    Dr[i] = std::pow(10.0, e(engine));
    Dc[i] = std::pow(10.0, e(engine));
  }
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 8.0 + diagonal_shift);
    for (int k : {1, 7, 31})
      if (i + k < n) {
        t.emplace_back(i, i + k, u(engine));
        t.emplace_back(i + k, i, u(engine));
      }
  }
  Eigen::SparseMatrix<double> M(n, n);
  M.setFromTriplets(t.begin(), t.end());
  return Eigen::SparseMatrix<double>(Dr.asDiagonal() * M * Dc.asDiagonal());
}

// Every component of x, however small its scale, to a few ulps of the unscaled problem: a plain
// LU with partial pivoting loses the small components of a column-scaled solution.
TEST(SparseLU, SolvesABadlyScaledSystemComponentByComponent) {
  const int n = 300;
  Eigen::VectorXd Dr, Dc;
  const Eigen::SparseMatrix<double> A = badly_scaled(n, 7, Dr, Dc);
  std::mt19937_64 engine(11);
  std::uniform_real_distribution<double> u(1, 2);
  Eigen::VectorXd y(n);  // the unscaled solution, O(1) in every component
  for (int i = 0; i < n; ++i) y[i] = u(engine);
  const Eigen::VectorXd x_true = Dc.cwiseInverse().cwiseProduct(y);
  const Eigen::VectorXd b = A * x_true;
  SparseLU lu;
  ASSERT_TRUE(lu.factor(A));
  const Eigen::VectorXd x = lu.solve(b);
  const double worst = ((x - x_true).cwiseQuotient(x_true)).cwiseAbs().maxCoeff();
  EXPECT_LT(worst, 1e-12);
}

TEST(SparseLU, RefactorsNewValuesOnTheSamePattern) {
  const int n = 200;
  Eigen::VectorXd Dr, Dc;
  SparseLU lu;
  for (double shift : {0.0, 5.0, -3.0}) {
    const Eigen::SparseMatrix<double> A = badly_scaled(n, 3, Dr, Dc, shift);  // same pattern, new values
    const Eigen::VectorXd x_true = Dc.cwiseInverse();
    ASSERT_TRUE(lu.factor(A));
    const Eigen::VectorXd x = lu.solve(A * x_true);
    EXPECT_LT(((x - x_true).cwiseQuotient(x_true)).cwiseAbs().maxCoeff(), 1e-12) << "shift " << shift;
  }
}

TEST(SparseLU, SaysSingular) {
  Eigen::SparseMatrix<double> A(3, 3);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 1}, {0, 1, 2}, {1, 0, 2}, {1, 1, 4}, {2, 2, 1}};  // rank 2
  A.setFromTriplets(t.begin(), t.end());
  SparseLU lu;
  EXPECT_FALSE(lu.factor(A));
}

bar::MeshOptions bar_mesh(double load_scale = 1) { return {.nx = 16, .ny = 16, .load_scale = load_scale}; }

// Two paths to one answer: Table 3's row 4 (λ̄ = 4.5e8, μ̄ = 0.054 daN/mm³) sticks on all of AD in
// limit mode, and the mixed system with every node Stick must give the condensed fast solver's
// answer — and an answer of the problem (its own residual at round-off), which it would not be
// if any node did not stick.
TEST(MixedSystem, AgreesWithTheCondensedSolveOfTheSameStatuses) {
  const Model model = bar::make_model(bar_mesh());
  const LinearSystem system(model);
  const ContactProblem problem(system, {bar::make_interface(model, InterfaceLaw::make(4.5e8, 0.054, 1.0))});
  const SolveReport fast = solve_fast(problem);
  ASSERT_TRUE(fast.converged) << fast.message;
  MixedSystem mixed(problem);
  const MixedSystem::Answer a = mixed.solve(std::vector<Active>(problem.num_nodes(), Active::Stick));
  ASSERT_FALSE(a.singular);
  EXPECT_LT(contact_residual(problem, a.u, a.r, a.band_z).value(), 1e-13);
  EXPECT_LT((a.u - fast.u).norm(), 1e-10 * fast.u.norm());
  EXPECT_LT((a.r - fast.r).norm(), 1e-10 * fast.r.norm());

  // The same system with every node open is the bar resting on nothing along AD: no longer an
  // answer (the loads press it onto the foundation), though still solvable (the bar is pinned).
  const MixedSystem::Answer open = mixed.solve(std::vector<Active>(problem.num_nodes(), Active::Gap));
  ASSERT_FALSE(open.singular);
  EXPECT_GT(contact_residual(problem, open.u, open.r, open.band_z).value(), 1e-3);
}

// A floating layer whose every contact is open is held by nothing: the factorisation says so
// rather than returning a number.
TEST(MixedSystem, AFloatingLayerHeldByNothingIsSingular) {
  bar::LayerOptions layer;
  layer.eps = 1e-3;
  layer.lambda_eps = layer.eps * 450;
  layer.mu_eps = layer.eps * 540;
  const Model model = bar::make_layer_model(bar_mesh(), layer);
  const LinearSystem system(model);
  const ContactProblem problem(system, bar::make_layer_interfaces(model));
  MixedSystem mixed(problem);
  const MixedSystem::Answer a = mixed.solve(std::vector<Active>(problem.num_nodes(), Active::Gap));
  EXPECT_TRUE(a.singular) << "rcond " << a.rcond << ", max u " << a.u.cwiseAbs().maxCoeff();
}

}  // namespace
}  // namespace thinlayer
