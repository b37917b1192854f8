// A scene bonded on every face is linear (core/solvers/bonded_solve.h): one sparse solve of the
// whole mixed system. Checked against a second path to the same answer — the bulk condensed onto
// the interface (dense Delassus operator, CHOLMOD factors) and the same statuses solved there —
// and on which scenes the path is taken. Closed forms of the bonded law through this path:
// tests/test_scene_joint.cpp (SceneJoint.*) and tests/test_scene_file.cpp.
#include <gtest/gtest.h>

#include <stdexcept>

#include "cases/scene/scene_file_scenes.h"
#include "core/solvers/active_set.h"
#include "core/solvers/bonded_solve.h"
#include "core/solvers/fast_solver.h"

using namespace thinlayer;

namespace {

const std::string cases_dir = THINLAYER_CASES_DIR;

// The shipped double lap's layer mode at its glue's own thickness (0.2 mm), both faces bonded.
struct DoubleLapLayer {
  SceneFileBulk bulk{read_scene_spec(cases_dir + "/double_lap/double_lap.json")};
  SceneLayerModel layer = make_scene_layer_model(bulk.spec(), bulk.meshes(), bulk.interface_nodes(), 0.0);
  LinearSystem system{layer.model};
  ContactProblem problem{system, layer.interfaces};
};

double relative(const Eigen::VectorXd& a, const Eigen::VectorXd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST(BondedSolve, TheSparseSolveAgreesWithTheCondensedOne) {
  DoubleLapLayer s;
  ASSERT_TRUE(every_interface_bonded(s.problem));
  const SolveReport sparse = solve_bonded(s.problem);
  EXPECT_TRUE(sparse.converged) << sparse.message;
  EXPECT_EQ(sparse.iterations, 1);
  EXPECT_LT(sparse.residual.value(), 1e-12);
  // The other path: the bulk condensed onto the interface, the layer onto its faces, the same
  // statuses solved on the dense condensed system (the limit-mode machinery's one Newton step).
  const CondensedInterface condensed(s.problem);
  const Condensed c = condense(s.problem, condensed, 0.01, false);
  const Step step = solve_statuses(c, bonded_statuses(s.problem));
  ASSERT_FALSE(step.singular);
  const Eigen::VectorXd u = condensed.displacement(s.problem, step.r, step.w);
  EXPECT_LT(relative(sparse.u, u), 1e-9);
  EXPECT_LT(relative(sparse.r, step.r), 1e-9);
  // Each node of both faces of both bondlines carries a force: nothing left open.
  for (Active a : bonded_statuses(s.problem)) EXPECT_EQ(a, Active::Bonded);
}

TEST(BondedSolve, SolveFastTakesItForABondedSceneInBothModes) {
  DoubleLapLayer s;
  const SolveReport layer = solve_fast(s.problem);
  EXPECT_TRUE(layer.converged) << layer.message;
  EXPECT_EQ(layer.iterations, 1);
  EXPECT_NE(layer.message.find("every face bonded"), std::string::npos) << layer.message;
  const SceneFileScene limit = solve_scene_file_limit(s.bulk, SolverKind::Fast, {});
  EXPECT_TRUE(limit.report.converged) << limit.report.message;
  EXPECT_EQ(limit.report.iterations, 1);
  EXPECT_EQ(limit.record.numbers.at("setup_time_s"), 0.0);  // nothing condensed
}

TEST(BondedSolve, NotTakenWhereAFaceIsInContact) {
  // The shipped lap joint: Signorini-Coulomb on both faces of its layer.
  SceneFileBulk bulk(read_scene_spec(cases_dir + "/lap_joint/lap_joint.json"));
  const SceneLayerModel layer = make_scene_layer_model(bulk.spec(), bulk.meshes(), bulk.interface_nodes(), 0.01);
  const LinearSystem system(layer.model);
  const ContactProblem problem(system, layer.interfaces);
  EXPECT_FALSE(every_interface_bonded(problem));
  EXPECT_THROW(solve_bonded(problem), std::invalid_argument);
  const SolveReport report = solve_fast(problem);
  EXPECT_EQ(report.message.find("every face bonded"), std::string::npos) << report.message;
  // No interface at all is not "bonded everywhere".
  EXPECT_FALSE(every_interface_bonded(ContactProblem(system, {})));
}
