// The two contact solvers against each other and against the laws they solve, on the bar.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cases/bar/bar.h"
#include "core/solvers/contact_problem.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/relaxation_solver.h"

namespace thinlayer {
namespace {

const double inf = std::numeric_limits<double>::infinity();

struct SmallBar : ::testing::Test {
  Model model = bar::make_model({8, 8, ElementType::Q1, TriangleDiagonal::Right, PlaneHypothesis::Strain});
  LinearSystem system{model};
  ContactProblem problem(const InterfaceLaw& law) { return ContactProblem(system, {bar::make_interface(model, law)}); }
};

double relative_distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

// One law per behaviour the solvers must handle: compliant (d), rigid in both directions (i),
// frictionless Signorini (e), compliant normal without tangential interaction (c), and a
// frictional law with f = 0.
const InterfaceLaw laws[] = {
    InterfaceLaw::make(450, 540, 1.0),  InterfaceLaw::make(inf, inf, 1.0), InterfaceLaw::make(inf, 0, 1.0),
    InterfaceLaw::make(450, 0, 1.0),    InterfaceLaw::make(450, 540, 0.0), InterfaceLaw::make(4.5e8, 5.4e8, 1.0),
};

TEST_F(SmallBar, FastAndRelaxationAgreeOnEveryKindOfLaw) {
  for (const InterfaceLaw& law : laws) {
    SCOPED_TRACE(std::string("law case ") + law.table1_case() + ", f = " + std::to_string(law.friction));
    const ContactProblem p = problem(law);
    const SolveReport fast = solve_fast(p);
    SolverOptions relaxation_options;
    relaxation_options.tolerance = 1e-11;
    const SolveReport relaxation = solve_relaxation(p, relaxation_options);
    ASSERT_TRUE(fast.converged) << fast.message;
    ASSERT_TRUE(relaxation.converged) << relaxation.message;
    EXPECT_LT(fast.residual.value(), 1e-10);
    EXPECT_LT(relative_distance(p.jumps(relaxation.u), p.jumps(fast.u)), 1e-8);
    EXPECT_LT(relative_distance(relaxation.r, fast.r), 1e-6);
  }
}

TEST_F(SmallBar, SolutionSatisfiesTheLawNodeByNode) {
  const InterfaceLaw law = InterfaceLaw::make(450, 540, 1.0);
  const ContactProblem p = problem(law);
  const SolveReport s = solve_fast(p);
  const Eigen::VectorXd g = p.jumps(s.u);
  int contact = 0, slide = 0;
  for (int k = 0; k < p.num_nodes(); ++k) {
    const double l = p.node(k).length;
    const double sigma_N = s.r[2 * k] / l, sigma_T = s.r[2 * k + 1] / l;
    // Normal: σ_N = -K_N [u]_N⁺ holds for the compliant law at every node.
    EXPECT_NEAR(sigma_N, -law.K_N() * std::max(g[2 * k], 0.0), 1e-9 * law.K_N() * g.cwiseAbs().maxCoeff());
    // Tangential: |σ_T| ≤ f|σ_N|, and σ_T = -K_T [u]_T strictly inside the cone.
    EXPECT_LE(std::abs(sigma_T), law.friction * std::abs(sigma_N) * (1 + 1e-9) + 1e-12);
    if (sigma_N < 0) ++contact;
    if (std::abs(sigma_T) < law.friction * std::abs(sigma_N) * (1 - 1e-6)) {
      EXPECT_NEAR(sigma_T, -law.K_T() * g[2 * k + 1], 1e-8 * std::abs(sigma_N));
    } else if (sigma_N < 0) {
      ++slide;
      // Sliding: the slip d_T = [u]_T - (spring part) opposes σ_T.
      const double slip = g[2 * k + 1] + sigma_T / law.K_T();
      EXPECT_LE(slip * sigma_T, 1e-12);
    }
  }
  EXPECT_GT(contact, 0);
  EXPECT_GT(slide, 0);  // the test exercises the slide branch
}

TEST_F(SmallBar, ForcesBalance) {
  // Applied tractions + interface forces + support reactions = 0 (per unit thickness).
  const ContactProblem p = problem(InterfaceLaw::make(inf, inf, 1.0));
  const SolveReport s = solve_fast(p);
  const Eigen::VectorXd u_full = system.expand(s.u);
  const Eigen::VectorXd interface_force = system.scatter(p.B().transpose() * s.r);
  Eigen::Vector2d total = Eigen::Vector2d::Zero();
  for (const auto& [name, R] : system.reactions(u_full, interface_force)) total += R;
  for (int dof = 0; dof < system.num_dofs(); ++dof) total[dof % 2] += system.external_force()[dof] + interface_force[dof];
  // Applied: F1·L along +x on AG and F2·L along y on GE.
  EXPECT_NEAR(bar::F1 * bar::side, 400.0, 1e-12);
  EXPECT_NEAR(total.norm(), 0.0, 1e-9 * 400.0);
}

TEST_F(SmallBar, FreeLawLeavesTheBarUnsupportedVertically) {
  // Case (a): no interaction at all; with only D holding u₂ the bar still has a solution
  // (the pin carries everything) and the interface forces vanish exactly.
  const ContactProblem p = problem(InterfaceLaw::make(0, 0, 1.0));
  const SolveReport s = solve_fast(p);
  ASSERT_TRUE(s.converged) << s.message;
  EXPECT_EQ(s.r.norm(), 0.0);
}

TEST_F(SmallBar, RelaxationSaysSoWhenItHitsTheIterationCap) {
  SolverOptions options;
  options.max_iterations = 5;
  const SolveReport s = solve_relaxation(problem(InterfaceLaw::make(450, 540, 1.0)), options);
  EXPECT_FALSE(s.converged);
  EXPECT_EQ(s.iterations, 5);
  EXPECT_NE(s.message.find("NOT converged"), std::string::npos);
  EXPECT_GT(s.residual.value(), options.tolerance);
}

TEST_F(SmallBar, FastSolverSaysSoWhenItHitsTheIterationCap) {
  SolverOptions options;
  options.max_iterations = 1;
  const SolveReport s = solve_fast(problem(InterfaceLaw::make(4.5e8, 5.4e8, 1.0)), options);
  EXPECT_FALSE(s.converged);
  EXPECT_NE(s.message.find("NOT converged"), std::string::npos);
}

TEST_F(SmallBar, ResidualDetectsAViolatedLaw) {
  // The exact solution perturbed at one node must show in the natural-map residual.
  const ContactProblem p = problem(InterfaceLaw::make(450, 540, 1.0));
  SolveReport s = solve_fast(p);
  Eigen::VectorXd r = s.r;
  r[2 * 3 + 1] += 0.1 * std::abs(r[2 * 3]);
  EXPECT_LT(contact_residual(p, s.u, s.r).value(), 1e-10);
  EXPECT_GT(contact_residual(p, s.u, r).interface, 1e-4);
  EXPECT_GT(contact_residual(p, s.u, r).bulk, 1e-4);
}

}  // namespace
}  // namespace thinlayer

namespace thinlayer {
namespace {

// Skip what a scene doesn't need (issue 5): each shortcut changes the cost, never the answer.
TEST_F(SmallBar, AWarmStartFromTheAnswerIsOneLinearSolve) {
  for (const InterfaceLaw& law : laws) {
    SCOPED_TRACE(std::string("law case ") + law.table1_case());
    const ContactProblem p = problem(law);
    const SolveReport cold = solve_fast(p);
    ASSERT_TRUE(cold.converged) << cold.message;
    SolverOptions warm;
    warm.initial_r = cold.r;
    const SolveReport again = solve_fast(p, warm);
    ASSERT_TRUE(again.converged) << again.message;
    EXPECT_EQ(again.iterations, 1);
    EXPECT_LE(relative_distance(again.u, cold.u), 1e-12);
  }
  SolverOptions wrong;
  wrong.initial_r = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(solve_fast(problem(laws[0]), wrong), std::invalid_argument);
}

TEST_F(SmallBar, FrictionlessRowsLeftOutOrKeptGiveTheSameAnswer) {
  for (const InterfaceLaw& law : {InterfaceLaw::make(inf, 0, 1.0), InterfaceLaw::make(450, 0, 1.0),
                                  InterfaceLaw::make(450, 540, 0.0)}) {
    SCOPED_TRACE(std::string("law case ") + law.table1_case() + ", f = " + std::to_string(law.friction));
    const ContactProblem p = problem(law);
    const SolveReport skipped = solve_fast(p);
    SolverOptions kept;
    kept.skip_frictionless_rows = false;
    const SolveReport full = solve_fast(p, kept);
    ASSERT_TRUE(skipped.converged) << skipped.message;
    ASSERT_TRUE(full.converged) << full.message;
    EXPECT_LE(relative_distance(full.u, skipped.u), 1e-10);
    EXPECT_EQ(full.r(Eigen::seq(1, Eigen::last, 2)).norm(), 0.0);  // no tangential force either way
  }
}

}  // namespace
}  // namespace thinlayer
