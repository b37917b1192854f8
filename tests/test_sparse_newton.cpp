// A body held by contact and friction alone, in limit mode (core/solvers/sparse_newton.h):
// semismooth Newton on the whole sparse system from the bonded solve. Checked on the shipped
// friction-held double lap (cases/friction_lap) at a coarse mesh: against the statics of the joint
// (the clamp carries the pull), against the other path to the same discrete answer (the condensed
// active set), and on which scenes the path is taken.
#include <gtest/gtest.h>

#include "cases/dovetail/dovetail_scenes.h"
#include "cases/scene/scene_file_scenes.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/sparse_newton.h"

using namespace thinlayer;

namespace {

const std::string cases_dir = THINLAYER_CASES_DIR;

// The friction-held double lap at 1 mm along its bondlines (26 nodes on each): small enough for
// the condensed path's many damped steps.
SceneSpec coarse_friction_lap(double pull = 500) {
  SceneSpec spec = read_scene_spec(cases_dir + "/friction_lap/friction_lap.json");
  spec.h_interface = 1.0;
  spec.h_far = 2.0;
  for (SceneLoadSpec& load : spec.loads)
    if (load.group == "grip") load.vector = {-pull, 0.0};
  return spec;
}

double relative(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST(SparseNewton, HoldsTheFrictionLapsInnerStripInAFewSteps) {
  SceneFileBulk bulk(coarse_friction_lap());
  const ContactProblem problem(bulk.system(), bulk.limit_interfaces(0));
  ASSERT_TRUE(takes_sparse_newton(problem));
  const SolveReport report = solve_fast(problem);
  EXPECT_TRUE(report.converged) << report.message;
  EXPECT_EQ(report.method, "sparse Newton");
  EXPECT_LE(report.iterations, 8);
  // Statics: nothing holds the inner strip but its bondlines, so the outer strips' clamp carries
  // the whole pull of 500 N/mm (the clamping pressures cancel each other).
  const SceneFileScene scene = solve_scene_file_limit(bulk, SolverKind::Fast, {});
  const Eigen::Vector2d clamp = scene.record.reactions.at("clamp");
  EXPECT_NEAR(clamp.x(), 500.0, 1e-7);
  EXPECT_NEAR(clamp.y(), 0.0, 1e-7);
  EXPECT_EQ(scene.record.numbers.at("setup_time_s"), 0.0);  // nothing condensed
}

TEST(SparseNewton, AgreesWithTheCondensedPath) {
  SceneFileBulk bulk(coarse_friction_lap());
  const ContactProblem problem(bulk.system(), bulk.limit_interfaces(0));
  const SolveReport newton = solve_fast(problem);
  SolverOptions condensed_path;
  condensed_path.sparse_newton = false;
  const SolveReport condensed = solve_fast(problem, condensed_path);
  ASSERT_TRUE(newton.converged) << newton.message;
  ASSERT_TRUE(condensed.converged) << condensed.message;
  EXPECT_EQ(condensed.method, "floating-layer ladder");  // the nodal floating body's condensed path
  EXPECT_LT(relative(newton.u, condensed.u), 1e-8);
  EXPECT_LT(relative(newton.r, condensed.r), 1e-8);
}

TEST(SparseNewton, KeepsAHoldWhereUnequalPressuresBendTheJoint) {
  // Clamping pressures of 85.7 and 43.9 MPa on the two outer strips (the generator's seed 2,
  // scripts/random_friction_joints.py, f = 0.131, a pull of 84 N/mm): the stack bends, one face slides
  // whole and the inner strip is held by a part of the other. Plain Newton on the statuses let every
  // node slide from its third step on (the strip free along its faces: a singular step) and cycled;
  // the hold and the backtracking (sparse_newton.cpp) bring it to the answer the condensed path finds.
  SceneSpec spec = coarse_friction_lap(84.32);
  for (SceneInterfaceSpec& i : spec.interfaces) i.friction = 0.131;
  for (SceneLoadSpec& load : spec.loads)
    if (load.group == "press_top") load.pressure = 85.72;
    else if (load.group == "press_bottom") load.pressure = 43.86;
  SceneFileBulk bulk(spec);
  const ContactProblem problem(bulk.system(), bulk.limit_interfaces(0));
  const SparseNewtonRun newton = solve_sparse_newton(problem, {});
  EXPECT_TRUE(newton.report.converged) << newton.report.message;
  EXPECT_FALSE(newton.cycled);
  SolverOptions condensed_path;
  condensed_path.sparse_newton = false;
  const SolveReport condensed = solve_fast(problem, condensed_path);
  ASSERT_TRUE(condensed.converged) << condensed.message;
  EXPECT_LT(relative(newton.report.u, condensed.u), 1e-8);
  EXPECT_LT(relative(newton.report.r, condensed.r), 1e-8);
  // Some node of the inner strip sticks: below friction's capacity the strip keeps a hold.
  int stuck = 0;
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const double r_N = newton.report.r[2 * k], r_T = newton.report.r[2 * k + 1];
    stuck += r_N < 0 && std::abs(r_T) < 0.999 * problem.law(k).friction * std::abs(r_N);
  }
  EXPECT_GT(stuck, 0);
}

TEST(SparseNewton, TakenOnlyWhereABodyIsHeldByContactAndNoLayerBand) {
  // Supported bodies (the dovetail's limit mode): the condensed active set, fast there.
  DovetailLimitBulk dovetail;
  const ContactProblem supported(dovetail.system(), {dovetail::make_limit_interface(dovetail.model(),
                                                                                    dovetail::limit_law({}))});
  EXPECT_FALSE(takes_sparse_newton(supported));
  // The friction lap's layer mode: its layer bands need the floating-layer solver.
  SceneFileBulk bulk(coarse_friction_lap());
  const SceneLayerModel layer = make_scene_layer_model(bulk.spec(), bulk.meshes(), bulk.interface_nodes(), 0.0);
  const LinearSystem system(layer.model);
  const ContactProblem layered(system, layer.interfaces);
  EXPECT_FALSE(takes_sparse_newton(layered));
}
