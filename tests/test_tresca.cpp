// Coulomb through Tresca's fixed point (core/solvers/tresca.h): the bar's limit problem of
// Table 3's row 1 (f = 1), where the active-set method converges, solved again from rest by the
// fixed point; both must be the same Coulomb solution.
#include <gtest/gtest.h>

#include "cases/bar/bar.h"
#include "core/solvers/active_set.h"
#include "core/solvers/condensed_interface.h"
#include "core/solvers/tresca.h"

namespace thinlayer {
namespace {

TEST(Tresca, ItsFixedPointIsTheCoulombSolution) {
  bar::MeshOptions mesh;
  mesh.nx = mesh.ny = 16;
  const Model model = bar::make_model(mesh);
  const LinearSystem system(model);
  const ContactProblem problem(system, {bar::make_interface(model, InterfaceLaw::make(4.5e8, 5.4e8, 1.0))});
  const CondensedInterface condensed(problem);
  const Condensed c = condense(problem, condensed, 0.01, true);

  Eigen::VectorXd r_active = Eigen::VectorXd::Zero(c.g0.size()), none;
  std::vector<Active> statuses = guess_statuses(c, r_active, jump_part(c, r_active, none));
  ASSERT_TRUE(active_set(c, problem, statuses, r_active, none, 100).settled);
  const Step exact = solve_statuses(c, statuses);

  Eigen::VectorXd r = Eigen::VectorXd::Zero(c.g0.size());
  const TrescaRun run = solve_tresca_fixed_point(c, r);
  ASSERT_TRUE(run.converged) << run.threshold_updates << " threshold updates";
  EXPECT_LT((r - exact.r).norm(), 1e-8 * exact.r.norm());
  EXPECT_LT(condensed_residual(c, problem, r, jump_part(c, r, none)), 1e-8);
  // Some nodes slide and some stick: the thresholds did matter.
  int slide = 0, stick = 0;
  for (Active a : statuses) {
    slide += a == Active::SlidePositive || a == Active::SlideNegative;
    stick += a == Active::Stick;
  }
  EXPECT_GT(slide, 0);
  EXPECT_GT(stick, 0);
}

}  // namespace
}  // namespace thinlayer
