// SparseCholesky (CHOLMOD), against computations that do not use the code under test: dense Eigen
// factorisations (the condensation built on it: test_condensed_per_body.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/linalg/sparse_cholesky.h"

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

double relative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

// B A⁻¹ Bᵀ by a dense Cholesky factorisation of A.
Eigen::MatrixXd dense_congruence(const Eigen::SparseMatrix<double>& A, const Eigen::SparseMatrix<double>& B) {
  const Eigen::MatrixXd Bd(B);
  return Bd * Eigen::MatrixXd(A).llt().solve(Bd.transpose());
}

// `rows` rows, each with `per_row` random entries on the unknowns `touched` (of n): as the jump
// rows of B, a few entries each, on the interface DOFs only.
Eigen::SparseMatrix<double> random_rows(int rows, int n, const std::vector<int>& touched, int per_row, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<size_t> pick(0, touched.size() - 1);
  std::uniform_real_distribution<double> value(-1, 1);
  std::vector<Eigen::Triplet<double>> t;
  for (int r = 0; r < rows; ++r)
    for (int e = 0; e < per_row; ++e) t.emplace_back(r, touched[pick(rng)], value(rng));
  Eigen::SparseMatrix<double> B(rows, n);
  B.setFromTriplets(t.begin(), t.end());
  return B;
}

void expect_inverse_congruence_matches_dense_solves(const Eigen::SparseMatrix<double>& A,
                                                    const Eigen::SparseMatrix<double>& B) {
  const SparseCholesky cholesky(A);
  const Eigen::MatrixXd W = cholesky.inverse_congruence(B);
  ASSERT_EQ(W.rows(), B.rows());
  ASSERT_EQ(W.cols(), B.rows());
  EXPECT_LT(relative(W, dense_congruence(A, B)), 1e-13);
  EXPECT_EQ((W - W.transpose()).norm(), 0.0);
}

TEST(SparseCholesky, InverseCongruenceMatchesDenseSolves) {
  const Eigen::SparseMatrix<double> A = grid_laplacian(12, 1.0);  // 144 unknowns
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const std::vector<int> touched = random_subset(static_cast<int>(A.rows()), 20, seed);
    expect_inverse_congruence_matches_dense_solves(A, random_rows(15, static_cast<int>(A.rows()), touched, 3, seed));
  }
}

TEST(SparseCholesky, InverseCongruenceOfTwoUncoupledBodies) {
  // Rows joining unknowns of both components, as the jumps between two bodies: each body is a
  // tree of the elimination forest, condensed on its own.
  const Eigen::SparseMatrix<double> A = two_blocks(grid_laplacian(9, 0.5));
  expect_inverse_congruence_matches_dense_solves(
      A, random_rows(12, static_cast<int>(A.rows()), random_subset(static_cast<int>(A.rows()), 30, 7), 4, 7));
}

TEST(SparseCholesky, InverseCongruenceOnAnEdgeOfTheGrid) {
  // The interface of a body is one edge of it, as on the bar: nearly singular A (shift 1e-3),
  // and long separators whose supernodes share their interface unknowns.
  const int k = 15;
  std::vector<int> edge;
  for (int x = k - 1; x >= 0; --x) edge.push_back(x);
  const Eigen::SparseMatrix<double> A = grid_laplacian(k, 1e-3);
  expect_inverse_congruence_matches_dense_solves(A, random_rows(2 * k, k * k, edge, 2, 11));
}

TEST(SparseCholesky, InverseCongruenceByTheIdentityIsTheInverse) {
  // Every unknown touched, every supernode on Γ's paths.
  const Eigen::SparseMatrix<double> A = grid_laplacian(7, 0.3);
  Eigen::SparseMatrix<double> I(A.rows(), A.cols());
  I.setIdentity();
  const Eigen::MatrixXd inverse = SparseCholesky(A).inverse_congruence(I);
  EXPECT_LT(relative(inverse, Eigen::MatrixXd(A).inverse()), 1e-13);
}

TEST(SparseCholesky, InverseCongruenceOfADiagonalMatrix) {
  // Each unknown a tree of its own: n roots.
  Eigen::SparseMatrix<double> A(6, 6);
  for (int i = 0; i < 6; ++i) A.insert(i, i) = 1.0 + i;
  expect_inverse_congruence_matches_dense_solves(A, random_rows(4, 6, {0, 2, 3, 5}, 2, 5));
}

TEST(SparseCholesky, InverseCongruenceOfAnUntouchingBIsZeroAndAMisfitIsRefused) {
  const Eigen::SparseMatrix<double> A = grid_laplacian(4, 1.0);
  const Eigen::MatrixXd W = SparseCholesky(A).inverse_congruence(Eigen::SparseMatrix<double>(3, 16));
  EXPECT_EQ(W.rows(), 3);
  EXPECT_EQ(W.norm(), 0.0);
  EXPECT_THROW(SparseCholesky(A).inverse_congruence(Eigen::SparseMatrix<double>(3, 15)), std::invalid_argument);
}

TEST(SparseCholesky, SingularMatrixThrowsTheSingularSystemMessage) {
  Eigen::SparseMatrix<double> A(3, 3);  // an unknown with no stiffness at all
  A.insert(0, 0) = 2.0;
  A.insert(1, 1) = 0.0;
  A.insert(2, 2) = 3.0;
  try {
    SparseCholesky{A};
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("singular system:", 0), 0u) << e.what();
  }
}

TEST(SparseCholesky, RcondOfADiagonalMatrixIsItsSmallestOverLargestEntry) {
  const Eigen::VectorXd d = (Eigen::VectorXd(5) << 4.0, 1e-3, 250.0, 7.0, 0.5).finished();
  Eigen::SparseMatrix<double> A(5, 5);
  for (int i = 0; i < 5; ++i) A.insert(i, i) = d[i];
  EXPECT_NEAR(SparseCholesky(A).rcond(), 1e-3 / 250.0, 1e-15 * (1e-3 / 250.0));
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

}  // namespace
}  // namespace thinlayer
