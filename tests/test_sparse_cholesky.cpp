// SparseCholesky (CHOLMOD) and the condensation built on it, against computations that do not
// use the code under test: dense Eigen factorisations, and Eigen's own sparse Cholesky.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include "cases/bar/bar.h"
#include "core/linalg/sparse_cholesky.h"
#include "core/solvers/condensed_interface.h"
#include "core/solvers/contact_problem.h"

namespace thinlayer {
namespace {

// The 5-point Laplacian of a k × k grid plus `shift` times the identity: SPD for shift > 0.
Eigen::SparseMatrix<double> grid_laplacian(int k, double shift) {
  std::vector<Eigen::Triplet<double>> t;
  auto id = [k](int x, int y) { return x + k * y; };
  for (int y = 0; y < k; ++y)
    for (int x = 0; x < k; ++x) {
      t.emplace_back(id(x, y), id(x, y), 4.0 + shift);
      if (x + 1 < k) t.emplace_back(id(x, y), id(x + 1, y), -1.0), t.emplace_back(id(x + 1, y), id(x, y), -1.0);
      if (y + 1 < k) t.emplace_back(id(x, y), id(x, y + 1), -1.0), t.emplace_back(id(x, y + 1), id(x, y), -1.0);
    }
  Eigen::SparseMatrix<double> A(k * k, k * k);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

// Two copies of A, uncoupled: a matrix whose graph has two components (two bodies).
Eigen::SparseMatrix<double> two_blocks(const Eigen::SparseMatrix<double>& A) {
  std::vector<Eigen::Triplet<double>> t;
  for (int block = 0; block < 2; ++block)
    for (int c = 0; c < A.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
        t.emplace_back(it.row() + block * A.rows(), it.col() + block * A.cols(), it.value());
  Eigen::SparseMatrix<double> D(2 * A.rows(), 2 * A.cols());
  D.setFromTriplets(t.begin(), t.end());
  return D;
}

std::vector<int> random_subset(int n, int count, unsigned seed) {
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  std::mt19937 rng(seed);
  std::shuffle(all.begin(), all.end(), rng);
  return {all.begin(), all.begin() + count};  // in random order, not sorted
}

// S = A_ΓΓ - A_ΓI A_II⁻¹ A_IΓ, densely, rows and columns in the order of `last`.
Eigen::MatrixXd dense_schur_complement(const Eigen::MatrixXd& A, const std::vector<int>& last) {
  std::vector<bool> is_last(A.rows(), false);
  for (int i : last) is_last[i] = true;
  std::vector<int> rest;
  for (int i = 0; i < A.rows(); ++i)
    if (!is_last[i]) rest.push_back(i);
  const Eigen::MatrixXd A_GG = A(last, last), A_GI = A(last, rest), A_II = A(rest, rest);
  return A_GG - A_GI * A_II.llt().solve(A_GI.transpose());
}

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

void expect_trailing_factor_is_the_schur_complements(const Eigen::SparseMatrix<double>& A,
                                                    const std::vector<int>& last) {
  const SparseCholesky cholesky(A, last);
  const Eigen::MatrixXd L = cholesky.trailing_factor();
  const Eigen::MatrixXd S = dense_schur_complement(Eigen::MatrixXd(A), last);
  ASSERT_EQ(L.rows(), static_cast<Eigen::Index>(last.size()));
  ASSERT_EQ(L.cols(), static_cast<Eigen::Index>(last.size()));
  EXPECT_EQ(Eigen::MatrixXd(L.triangularView<Eigen::StrictlyUpper>()).norm(), 0.0) << "not lower triangular";
  EXPECT_LT(relative(L * L.transpose(), S), 1e-13);
  // The Cholesky factor with a positive diagonal is unique: it is S's own.
  EXPECT_LT(relative(L, Eigen::MatrixXd(S.llt().matrixL())), 1e-12);
  // Solves are unaffected by the ordering.
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0);
  EXPECT_LT(relative(cholesky.solve(b), Eigen::MatrixXd(A).llt().solve(b)), 1e-13);
}

TEST(SparseCholesky, TrailingFactorIsTheSchurComplementsCholeskyFactor) {
  const Eigen::SparseMatrix<double> A = grid_laplacian(12, 1.0);  // 144 unknowns
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_trailing_factor_is_the_schur_complements(A, random_subset(static_cast<int>(A.rows()), 20, seed));
  }
}

TEST(SparseCholesky, TrailingFactorOfTwoUncoupledBodies) {
  // Γ spread over both components: the factor's postordering would group each component's
  // columns together, which must not move Γ away from the end.
  const Eigen::SparseMatrix<double> A = two_blocks(grid_laplacian(9, 0.5));
  expect_trailing_factor_is_the_schur_complements(A, random_subset(static_cast<int>(A.rows()), 30, 7));
}

TEST(SparseCholesky, TrailingFactorOfAnEdgeOfTheGrid) {
  // The interface of a body is one edge of it, as on the bar.
  const int k = 15;
  std::vector<int> edge;
  for (int x = k - 1; x >= 0; --x) edge.push_back(x);
  expect_trailing_factor_is_the_schur_complements(grid_laplacian(k, 1e-3), edge);
}

TEST(SparseCholesky, NoTrailingFactorWithoutUnknownsOrderedLast) {
  EXPECT_EQ(SparseCholesky(grid_laplacian(4, 1.0)).trailing_factor().size(), 0);
}

TEST(SparseCholesky, RejectsRepeatedOrOutOfRangeIndicesOrderedLast) {
  const Eigen::SparseMatrix<double> A = grid_laplacian(4, 1.0);
  EXPECT_THROW(SparseCholesky(A, {3, 5, 3}), std::invalid_argument);
  EXPECT_THROW(SparseCholesky(A, {16}), std::invalid_argument);
}

TEST(SparseCholesky, SingularMatrixThrowsTheSingularSystemMessage) {
  Eigen::SparseMatrix<double> A(3, 3);  // an unknown with no stiffness at all
  A.insert(0, 0) = 2.0;
  A.insert(1, 1) = 0.0;
  A.insert(2, 2) = 3.0;
  for (const bool with_last : {false, true}) {
    SCOPED_TRACE(with_last ? "with unknowns ordered last" : "default ordering");
    try {
      if (with_last) SparseCholesky(A, {0, 2});
      else SparseCholesky{A};
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()).rfind("singular system:", 0), 0u) << e.what();
    }
  }
}

TEST(SparseCholesky, RcondOfADiagonalMatrixIsItsSmallestOverLargestEntry) {
  const Eigen::VectorXd d = (Eigen::VectorXd(5) << 4.0, 1e-3, 250.0, 7.0, 0.5).finished();
  Eigen::SparseMatrix<double> A(5, 5);
  for (int i = 0; i < 5; ++i) A.insert(i, i) = d[i];
  EXPECT_NEAR(SparseCholesky(A).rcond(), 1e-3 / 250.0, 1e-15 * (1e-3 / 250.0));
  EXPECT_NEAR(SparseCholesky(A, {2, 1}).rcond(), 1e-3 / 250.0, 1e-15 * (1e-3 / 250.0));
}

TEST(SparseCholesky, RcondNeverUnderestimatesTheTrueReciprocalCondition) {
  // The pivots of a Cholesky factorisation lie in [λ_min, λ_max], so the estimate is optimistic.
  const Eigen::SparseMatrix<double> A = grid_laplacian(10, 1e-4);
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(A)).eigenvalues();
  const double true_rcond = lambda.minCoeff() / lambda.maxCoeff();
  const double estimate = SparseCholesky(A).rcond();
  EXPECT_GE(estimate, true_rcond);
  EXPECT_LE(estimate, 1.0);
}

// The bar (limit mode, 32 contact nodes): W and g₀ from the Schur complement's factor against
// W = B K⁻¹ Bᵀ and g₀ = B K⁻¹ F + g_D with 2m dense solves by Eigen's own sparse Cholesky.
TEST(CondensedInterface, DelassusOperatorOfTheBarMatchesTwoMDenseSolves) {
  const Model model = bar::make_model({32, 32, ElementType::Q1, TriangleDiagonal::Right, PlaneHypothesis::Strain});
  const LinearSystem system(model);
  const ContactProblem problem(system, {bar::make_interface(model, InterfaceLaw::make(450, 540, 1.0))});
  ASSERT_EQ(problem.num_nodes(), 32);  // the contact nodes along AD
  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> reference(system.K());
  ASSERT_EQ(reference.info(), Eigen::Success);
  const Eigen::MatrixXd Bt = Eigen::MatrixXd(problem.B().transpose());
  const Eigen::MatrixXd W_reference = problem.B() * reference.solve(Bt);
  const Eigen::VectorXd g0_reference = problem.B() * reference.solve(system.F()) + problem.jump_offset();

  const CondensedInterface condensed(problem);
  EXPECT_LT(relative(condensed.W(), W_reference), 1e-12);
  EXPECT_EQ((condensed.W() - condensed.W().transpose()).norm(), 0.0);
  EXPECT_LT(relative(condensed.g0(), g0_reference), 1e-12);
  EXPECT_GT(condensed.rcond(), 0.0);
  EXPECT_LE(condensed.rcond(), 1.0);
}

}  // namespace
}  // namespace thinlayer
