// The condensation body by body (issue 13): the supported bodies factored as a linear solve
// factors them, each a tree of the factor's elimination forest, W = Σ_b B_b (K_b⁻¹)_ΓΓ B_bᵀ
// from the block of K⁻¹ on Γ (SparseCholesky::inverse_congruence), checked against references
// that use neither: dense Eigen factorisations of the whole K, Eigen's own sparse Cholesky, and
// a solve of the dovetail's settled statuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include "cases/bar/bar.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "core/linalg/connected_components.h"
#include "core/solvers/condensed_interface.h"
#include "core/solvers/fast_solver.h"

namespace thinlayer {
namespace {

template <class A, class B>
double relative(const A& a, const B& reference) {
  return (a - reference).norm() / reference.norm();
}

// The condensation against references computed without it: W and g₀ to 1e-12, W exactly
// symmetric, its reciprocal condition estimate in (0, 1].
void expect_condensation(const CondensedInterface& condensed, const Eigen::MatrixXd& W_reference,
                         const Eigen::VectorXd& g0_reference) {
  EXPECT_LT(relative(condensed.W(), W_reference), 1e-12);
  EXPECT_EQ((condensed.W() - condensed.W().transpose()).norm(), 0.0);
  EXPECT_LT(relative(condensed.g0(), g0_reference), 1e-12);
  EXPECT_GT(condensed.rcond(), 0.0);
  EXPECT_LE(condensed.rcond(), 1.0);
}

// A path graph i — i + stride on `count` unknowns starting at `first`, in an n × n matrix.
void add_path(std::vector<Eigen::Triplet<double>>& t, int first, int stride, int count) {
  for (int k = 0; k < count; ++k) {
    const int i = first + k * stride;
    t.emplace_back(i, i, 2.0);
    if (k + 1 < count) t.emplace_back(i, i + stride, -1.0), t.emplace_back(i + stride, i, -1.0);
  }
}

TEST(ConnectedComponents, InterleavedPartsNumberedByTheirSmallestUnknown) {
  // Unknowns 1, 3, 5, 7 form one part, 0, 2, 4, 6 another, 8 is alone (its diagonal only).
  std::vector<Eigen::Triplet<double>> t;
  add_path(t, 1, 2, 4);
  add_path(t, 0, 2, 4);
  t.emplace_back(8, 8, 1.0);
  Eigen::SparseMatrix<double> A(9, 9);
  A.setFromTriplets(t.begin(), t.end());
  EXPECT_EQ(connected_components(A), (std::vector<int>{0, 1, 0, 1, 0, 1, 0, 1, 2}));
  // The lower triangle alone (as CHOLMOD reads a symmetric matrix) joins the same unknowns.
  const Eigen::SparseMatrix<double> lower = A.triangularView<Eigen::Lower>();
  EXPECT_EQ(connected_components(lower), connected_components(A));
  EXPECT_THROW(connected_components(Eigen::SparseMatrix<double>(2, 3)), std::invalid_argument);
}

DovetailLimitBulk& coarse_bulk() {
  // Two bodies (base, tenon), small enough for dense factorisations of the whole K.
  static DovetailLimitBulk bulk(dovetail::MeshOptions{0.1, 0.4, 2});
  return bulk;
}

TEST(CondensedInterface, TheDovetailsTwoBodiesAreFoundFromTheStiffness) {
  const LinearSystem& system = coarse_bulk().system();
  const std::vector<int> part = connected_components(system.K());
  // The base is body 0 and comes first in the free numbering: parts and bodies coincide.
  for (int i = 0; i < system.num_free(); ++i) ASSERT_EQ(part[i], system.body_of(i)) << "free DOF " << i;
  EXPECT_EQ(*std::max_element(part.begin(), part.end()), 1);
}

// W = B K⁻¹ Bᵀ, g₀ = B K⁻¹ F + g_D and the bulk displacement, all from a dense LLT of the whole
// K (both bodies at once, Eigen's own factorisation), against the per-body condensation.
TEST(CondensedInterface, PerBodyCondensationMatchesADenseFactorOfTheWholeStiffness) {
  DovetailLimitBulk& bulk = coarse_bulk();
  const LinearSystem& system = bulk.system();
  ASSERT_LT(system.num_free(), 3000);  // dense stays cheap
  const ContactProblem problem(system, {dovetail::make_limit_interface(bulk.model(), dovetail::limit_law({1, 1}))});
  const Eigen::LLT<Eigen::MatrixXd> dense(Eigen::MatrixXd(system.K()));
  ASSERT_EQ(dense.info(), Eigen::Success);
  const Eigen::MatrixXd B = Eigen::MatrixXd(problem.B());
  const Eigen::MatrixXd W_reference = B * dense.solve(B.transpose());
  const Eigen::VectorXd g0_reference = B * dense.solve(system.F()) + problem.jump_offset();

  const CondensedInterface condensed(problem);
  expect_condensation(condensed, W_reference, g0_reference);

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const Eigen::VectorXd r = Eigen::VectorXd::NullaryExpr(B.rows(), [&] { return uniform(rng); });
  const Eigen::VectorXd u_reference = dense.solve(system.F() + B.transpose() * r);
  EXPECT_LT(relative(condensed.displacement(problem, r, Eigen::VectorXd()), u_reference), 1e-12);
}

// The jump rows each settled status imposes on r (paper §4; contact_problem.h), given d = g₀ +
// (W + C) r: gap r = 0; stick d = 0; slide d_N = 0 and r_T = f |r_N| in the direction of r_T.
struct StatusSystem {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
};

StatusSystem status_system(const ContactProblem& problem, const Eigen::MatrixXd& W, const Eigen::VectorXd& g0,
                           const Eigen::VectorXd& r) {
  const int rows = static_cast<int>(r.size());
  Eigen::MatrixXd WC = W;
  WC.diagonal() += problem.compliance();
  StatusSystem s{Eigen::MatrixXd::Zero(rows, rows), Eigen::VectorXd::Zero(rows)};
  const double r_N_max = r(Eigen::seq(0, rows - 1, 2)).cwiseAbs().maxCoeff();
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const int N = 2 * k, T = N + 1;
    const double f = problem.law(k).friction;
    if (std::abs(r[N]) <= 1e-12 * r_N_max) {  // gap
      s.A(N, N) = s.A(T, T) = 1;
      continue;
    }
    s.A.row(N) = WC.row(N);  // d_N = 0
    s.b[N] = -g0[N];
    if (std::abs(r[T]) >= (1 - 1e-9) * f * std::abs(r[N])) {  // slide: r_T + sign(r_T) f r_N = 0
      s.A(T, T) = 1;
      s.A(T, N) = (r[T] > 0 ? 1 : -1) * f;
    } else {  // stick: d_T = 0
      s.A.row(T) = WC.row(T);
      s.b[T] = -g0[T];
    }
  }
  return s;
}

// The dovetail, case d, limit mode on the study's mesh: the fast solver's answer against an
// independent solve of the statuses it settled on (Eigen's sparse Cholesky of the whole K,
// 2m solves for W, a dense LU of the status rows). Main's answer before the per-body
// condensation agreed with this reference to the same 1e-12.
TEST(CondensedInterface, DovetailLimitAnswerIsTheSolveOfItsSettledStatuses) {
  DovetailLimitBulk bulk;  // h = 0.025 along S
  const LinearSystem& system = bulk.system();
  const ContactProblem problem(system, {dovetail::make_limit_interface(bulk.model(),
                                                                       dovetail::limit_law(dovetail::exponents_of('d')))});
  const SolveReport report = solve_fast(problem, CondensedInterface(problem));
  ASSERT_TRUE(report.converged) << report.message;

  const Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> K(system.K());
  ASSERT_EQ(K.info(), Eigen::Success);
  const Eigen::MatrixXd Bt = Eigen::MatrixXd(problem.B().transpose());
  const Eigen::MatrixXd W = problem.B() * K.solve(Bt);
  const Eigen::VectorXd g0 = problem.B() * K.solve(system.F()) + problem.jump_offset();
  const StatusSystem s = status_system(problem, W, g0, report.r);
  const Eigen::VectorXd r = s.A.partialPivLu().solve(s.b);
  const Eigen::VectorXd u = K.solve(Eigen::VectorXd(system.F() + problem.B().transpose() * r));
  EXPECT_LT(relative(report.r, r), 1e-12);
  EXPECT_LT(relative(report.u, u), 1e-12);
}

// The bar (limit mode, 32 contact nodes): W and g₀ from the block of K⁻¹ on Γ against
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

  expect_condensation(CondensedInterface(problem), W_reference, g0_reference);
}

}  // namespace
}  // namespace thinlayer
