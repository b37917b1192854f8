// The layer mode's interior-point method (core/solvers/layer_interior_point.h) and its fall-back.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "cases/bar/bar.h"
#include "cases/dovetail/dovetail.h"
#include "core/io/reference_tables.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/layer_interior_point.h"

namespace thinlayer {
namespace {

// The dovetail's case (d) at ε = 1e-3 on the coarse mesh (h = 0.05 along S): a layer whose film is
// open over most of the slot (its position there decided by its membrane) and slides on the right
// flank.
struct CoarseDovetailLayer {
  Model model;
  std::unique_ptr<LinearSystem> system;
  std::unique_ptr<ContactProblem> problem;
  explicit CoarseDovetailLayer(char law_case = 'd', double eps = 1e-3) {
    dovetail::MeshOptions mesh;
    mesh.h_interface = 0.05;
    mesh.h_far = 0.2;
    const dovetail::LimitMeshes limit = dovetail::make_limit_meshes(mesh);
    model = dovetail::make_layer_model(dovetail::make_layer_meshes(limit, eps, 2), dovetail::exponents_of(law_case));
    system = std::make_unique<LinearSystem>(model);
    problem = std::make_unique<ContactProblem>(*system, dovetail::make_layer_interfaces(model));
  }
};

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).norm() / std::max(a.norm(), 1e-300);
}

// Where the film is free the two methods select different answers (the interior point method the
// analytic centre of the optimal face, the ladder what its selection spring leaves): both meet the
// tolerance on the true problem and agree on what it determines (SPEC §1.5) — the adherents'
// displacements, the forces on S and the reactions — to 1e-8.
TEST(LayerInteriorPoint, AgreesWithTheLadderOnWhatTheProblemDetermines) {
  const CoarseDovetailLayer scene;
  SolverOptions ipm_options, ladder_options;
  ladder_options.layer_method = LayerMethod::Ladder;
  const SolveReport ipm = solve_fast(*scene.problem, ipm_options);
  const SolveReport ladder = solve_fast(*scene.problem, ladder_options);
  ASSERT_TRUE(ipm.converged) << ipm.message;
  ASSERT_TRUE(ladder.converged) << ladder.message;
  EXPECT_EQ(ipm.method, "layer interior point");
  EXPECT_EQ(ladder.method, "floating-layer ladder");
  EXPECT_LE(ipm.residual.value(), 1e-10);
  const LinearSystem& system = *scene.system;
  std::vector<int> adherent;
  for (int i = 0; i < system.num_free(); ++i)
    if (!system.floating(i)) adherent.push_back(i);
  Eigen::VectorXd a(adherent.size()), b(adherent.size());
  for (size_t k = 0; k < adherent.size(); ++k) a[k] = ipm.u[adherent[k]], b[k] = ladder.u[adherent[k]];
  EXPECT_LT(relative_difference(a, b), 1e-8);
  EXPECT_LT(relative_difference(ipm.r, ladder.r), 1e-8);
  const auto reactions = [&](const SolveReport& r) {
    return system.reactions(system.expand(r.u), system.scatter(scene.problem->B().transpose() * r.r));
  };
  const auto ra = reactions(ipm), rb = reactions(ladder);
  for (const auto& [name, R] : ra) EXPECT_LT((R - rb.at(name)).norm() / R.norm(), 1e-8) << name;
}

// A layer on a rigid foundation (the bar's row 3 at ε = 1e-4: one face against a prescribed plane,
// no adherent node on that side) converges to the tolerance on the method alone.
TEST(LayerInteriorPoint, ConvergesOnALayerAgainstARigidFoundation) {
  const Table3Row row = load_table3_paper().at(2);
  bar::MeshOptions mesh;
  mesh.nx = mesh.ny = 16;
  bar::LayerOptions layer;
  layer.eps = 1e-4;
  layer.lambda_eps = layer.eps * row.lambda_bar;
  layer.mu_eps = layer.eps * row.mu_bar;
  const Model model = bar::make_layer_model(mesh, layer);
  const LinearSystem system(model);
  const ContactProblem problem(system, bar::make_layer_interfaces(model));
  ASSERT_TRUE(layer_interior_point_applies(problem));
  const InteriorPointRun run = solve_layer_interior_point(problem, SolverOptions{});
  EXPECT_TRUE(run.report.converged) << run.report.message;
  EXPECT_LE(run.report.residual.value(), 1e-10);
  EXPECT_EQ(run.report.iterations, run.factorisations);
  EXPECT_LE(run.factorisations, 40);
}

// A method that stops short says so, and the ladder takes over from rest: the answer names both
// methods and counts both's steps. Capped at 3 factorisations, the interior-point method cannot
// reach the tolerance here (a path from the glued joint needs a dozen).
TEST(LayerInteriorPoint, AStallIsReportedAndTheLadderTakesOver) {
  const CoarseDovetailLayer scene;
  SolverOptions capped;
  capped.max_iterations = 3;
  const InteriorPointRun run = solve_layer_interior_point(*scene.problem, capped, [] {
    InteriorPointOptions o;
    o.max_factorisations = 3;
    return o;
  }());
  EXPECT_FALSE(run.report.converged);
  EXPECT_EQ(run.report.stop_cause, StopCause::IterationCap);
  EXPECT_NE(run.report.message.find("NOT converged"), std::string::npos) << run.report.message;
  const SolveReport report = solve_fast(*scene.problem, capped);
  EXPECT_NE(report.method.find("after layer interior point"), std::string::npos) << report.method;
  EXPECT_NE(report.message.find("taken over from the layer interior point"), std::string::npos) << report.message;
  EXPECT_GE(report.iterations, run.factorisations);
}

// A problem the method is not for is declined, not attempted: a limit-mode problem (finite springs,
// no layer band).
TEST(LayerInteriorPoint, DeclinesAProblemWithoutALayer) {
  dovetail::MeshOptions mesh;
  mesh.h_interface = 0.1;
  mesh.h_far = 0.3;
  const dovetail::LimitMeshes limit = dovetail::make_limit_meshes(mesh);
  const Model model = dovetail::make_limit_model(limit);
  const LinearSystem system(model);
  const ContactProblem problem(system, {dovetail::make_limit_interface(model, dovetail::limit_law(dovetail::exponents_of('d')))});
  EXPECT_FALSE(layer_interior_point_applies(problem));
  const InteriorPointRun run = solve_layer_interior_point(problem, SolverOptions{});
  EXPECT_FALSE(run.applies);
  EXPECT_EQ(run.factorisations, 0);
}

}  // namespace
}  // namespace thinlayer
