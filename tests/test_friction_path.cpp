// Continuation in the Coulomb coefficient (core/solvers/friction_path.h): the stages change
// how the answer is found, never which problem it answers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "cases/bar/bar.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/friction_path.h"

namespace thinlayer {
namespace {

// The bar's layer mode on a small mesh (Table 3 row 3: λ̄ = 450, μ̄ = 540 daN/mm³, f = 1 on
// both faces), whose answer has gaps, slides and sticks.
struct SmallBarLayer {
  Model model;
  LinearSystem system;
  ContactProblem problem;
  explicit SmallBarLayer(const bar::LayerOptions& layer)
      : model(bar::make_layer_model(mesh(), layer)), system(model), problem(system, bar::make_layer_interfaces(model)) {}
  static bar::MeshOptions mesh() {
    bar::MeshOptions m;
    m.nx = m.ny = 8;
    return m;
  }
};

bar::LayerOptions row3_layer() {
  bar::LayerOptions layer;
  layer.eps = 1e-3;
  layer.lambda_eps = layer.eps * 450;
  layer.mu_eps = layer.eps * 540;
  return layer;
}

TEST(FrictionPath, ScalesEveryCoulombCoefficientAndNothingElse) {
  const SmallBarLayer bar(row3_layer());
  const ContactProblem half = with_friction_scaled(bar.problem, 0.5);
  ASSERT_EQ(half.interfaces().size(), bar.problem.interfaces().size());
  for (size_t i = 0; i < half.interfaces().size(); ++i) {
    const InterfaceLaw &law = half.interfaces()[i].law, &original = bar.problem.interfaces()[i].law;
    EXPECT_DOUBLE_EQ(law.friction, 0.5 * original.friction);
    EXPECT_EQ(law.lambda_bar, original.lambda_bar);
    EXPECT_EQ(law.mu_bar, original.mu_bar);
  }
  EXPECT_EQ(half.B().nonZeros(), bar.problem.B().nonZeros());
  EXPECT_EQ(half.kappa(), bar.problem.kappa());
  EXPECT_FALSE(with_friction_scaled(bar.problem, 0).law(0).tangential_active());  // frictionless
  for (double bad : {-0.5, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(with_friction_scaled(bar.problem, bad), std::invalid_argument) << bad;
}

TEST(FrictionPath, TheAnswerIsTheScenesOwnNotTheLastStages) {
  const SmallBarLayer bar(row3_layer());
  const CondensedInterface condensed(bar.problem);
  SolverOptions options;
  options.friction_path = {0.0, 0.5};
  const SolveReport along = solve_fast(bar.problem, condensed, options);
  ASSERT_TRUE(along.converged) << along.message;
  EXPECT_NE(along.message.find("[friction path: f x 0 converged, f x 0.5 converged, then f x 1]"), std::string::npos)
      << along.message;
  // Judged on the scene itself (f = 1) ...
  EXPECT_LE(contact_residual(bar.problem, along.u, along.r).value(), options.tolerance);
  // ... which the last stage's answer (f = 0.5) does not solve: the check can tell them apart.
  const ContactProblem half = with_friction_scaled(bar.problem, 0.5);
  const SolveReport stage = solve_fast(half, condensed);
  ASSERT_TRUE(stage.converged) << stage.message;
  EXPECT_GT(contact_residual(bar.problem, stage.u, stage.r).value(), 1e3 * options.tolerance);
  // The stages' work is counted: the first stage is the frictionless solve from rest, and each
  // later solve takes at least one step.
  const SolveReport frictionless = solve_fast(with_friction_scaled(bar.problem, 0), condensed);
  EXPECT_GE(along.iterations, frictionless.iterations + 2);
  // And it is the direct solve's answer.
  const SolveReport direct = solve_fast(bar.problem, condensed);
  ASSERT_TRUE(direct.converged) << direct.message;
  EXPECT_LE((along.r - direct.r).norm(), 1e-6 * direct.r.norm());
}

TEST(FrictionPath, ABadMultiplierIsRejected) {
  const SmallBarLayer bar(row3_layer());
  SolverOptions options;
  options.friction_path = {0.0, -1.0};
  EXPECT_THROW(solve_fast(bar.problem, options), std::invalid_argument);
}

}  // namespace
}  // namespace thinlayer
