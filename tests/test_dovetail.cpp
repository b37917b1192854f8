// The dovetail assembly (SPEC §2.2) in both modes, and a floating layer with nothing to hold it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/mesh/layer_band.h"
#include "core/mesh/structured_rectangle.h"
#include "core/solvers/fast_solver.h"
#include "cases/dovetail/dovetail_scenes.h"

namespace thinlayer {
namespace {

const double inf = std::numeric_limits<double>::infinity();

DovetailLimitBulk& coarse_bulk() {
  // A coarser mesh than the default keeps the tests quick; the physics is the same.
  static DovetailLimitBulk bulk(dovetail::MeshOptions{0.05, 0.2, 2});
  return bulk;
}

Eigen::Vector2d total_reaction(const SceneRecord& r) {
  return r.reactions.at("tenon_top") + r.reactions.at("base_bottom");
}

TEST(DovetailLimit, EveryCaseConvergesAndBalances) {
  for (char c = 'a'; c <= 'i'; ++c) {
    SCOPED_TRACE(std::string("case ") + c);
    const DovetailScene s = solve_dovetail_limit(coarse_bulk(), dovetail::exponents_of(c), std::string(1, c),
                                                 SolverKind::Fast, SolverOptions{});
    ASSERT_TRUE(s.report.converged) << s.report.message;
    EXPECT_EQ(s.record.text.at("table1_case"), std::string(1, c));  // Table 2 → Table 1 letter
    // No load but the supports: the two reactions balance.
    const double scale = s.record.reactions.at("tenon_top").norm();
    EXPECT_LT(total_reaction(s.record).norm(), 1e-8 * std::max(scale, 1.0));
  }
}

TEST(DovetailLimit, CaseAIsTwoBodiesThatDoNotInteract) {
  // σ = 0 on S: the tenon, held only at its top, translates rigidly by the imposed (1e-3, 1e-3)
  // and the clamped base does not move.
  const DovetailScene s = solve_dovetail_limit(coarse_bulk(), dovetail::exponents_of('a'), "a", SolverKind::Fast,
                                               SolverOptions{});
  ASSERT_TRUE(s.report.converged);
  EXPECT_EQ(s.report.r.norm(), 0.0);
  const Model& model = coarse_bulk().model();
  const int base_nodes = model.bodies[0].mesh.num_nodes();
  for (int n = 0; n < s.record.u.rows(); ++n) {
    const Eigen::Vector2d expected = n < base_nodes ? Eigen::Vector2d(0, 0) : Eigen::Vector2d(1e-3, 1e-3);
    EXPECT_NEAR((s.record.u.row(n).transpose() - expected).norm(), 0.0, 1e-15) << "node " << n;
  }
  EXPECT_NEAR(s.record.reactions.at("tenon_top").norm(), 0.0, 1e-9);
}

TEST(DovetailLimit, SolversAgree) {
  for (char c : {'d', 'i', 'e'}) {
    SCOPED_TRACE(std::string("case ") + c);
    const auto e = dovetail::exponents_of(c);
    const DovetailScene fast = solve_dovetail_limit(coarse_bulk(), e, std::string(1, c), SolverKind::Fast, SolverOptions{});
    SolverOptions relaxation_options;
    relaxation_options.tolerance = 1e-11;
    const DovetailScene relaxation =
        solve_dovetail_limit(coarse_bulk(), e, std::string(1, c), SolverKind::Relaxation, relaxation_options);
    ASSERT_TRUE(relaxation.report.converged) << relaxation.report.message;
    const auto& a = fast.record.interfaces.at(0);
    const auto& b = relaxation.record.interfaces.at(0);
    const double norm = std::hypot(a.jump_N.norm(), a.jump_T.norm());
    EXPECT_LT(std::hypot((a.jump_N - b.jump_N).norm(), (a.jump_T - b.jump_T).norm()), 1e-8 * norm);
  }
}

TEST(DovetailLayer, LayerModelApproachesTheLimitAsEpsShrinks) {
  // Case (d): the tenon's reaction in layer mode tends to the limit mode's as ε → 0.
  const auto e = dovetail::exponents_of('d');
  const DovetailScene limit = solve_dovetail_limit(coarse_bulk(), e, "d", SolverKind::Fast, SolverOptions{});
  const Eigen::Vector2d R0 = limit.record.reactions.at("tenon_top");
  double previous = inf;
  for (double eps : {1e-2, 1e-3, 1e-4}) {
    SCOPED_TRACE("eps " + std::to_string(eps));
    const DovetailScene s = solve_dovetail_layer(coarse_bulk(), e, eps, "d", SolverKind::Fast, SolverOptions{});
    ASSERT_TRUE(s.report.converged) << s.report.message;
    const double distance = (s.record.reactions.at("tenon_top") - R0).norm() / R0.norm();
    EXPECT_LT(distance, previous);
    previous = distance;
    // The bulk residual is ≤ 1e-10 of ‖F‖, which carries the lifting of the imposed
    // displacement (about 100 |R0| here); summed over ~5000 DOFs that allows ~1e-7 |R0|.
    EXPECT_LT(total_reaction(s.record).norm(), 1e-6 * R0.norm());
    // Both faces are recorded, and the combined status has one entry per node of S.
    ASSERT_EQ(s.record.interfaces.size(), 2u);
    EXPECT_EQ(s.record.combined_status.size(), s.record.interfaces[0].status.size());
  }
  EXPECT_LT(previous, 0.05);
}

TEST(DovetailLayer, FacesMatchNodeForNode) {
  const DovetailScene s = solve_dovetail_layer(coarse_bulk(), dovetail::exponents_of('d'), 1e-3, "d", SolverKind::Fast,
                                               SolverOptions{});
  const auto& plus = s.record.interfaces.at(0);   // S+: tenon / layer
  const auto& minus = s.record.interfaces.at(1);  // S-: layer / base
  ASSERT_EQ(plus.x.rows(), minus.x.rows());
  const auto& base_S = coarse_bulk().meshes().base.node_set("S");
  ASSERT_EQ(static_cast<int>(base_S.size()), minus.x.rows());
  for (int k = 0; k < minus.x.rows(); ++k) {
    EXPECT_EQ(minus.x.row(k), coarse_bulk().meshes().base.nodes.row(base_S[k])) << k;
    // The faces are ε apart along the normal; the across-segments of the band are longer where
    // they tilt: ε√1.16 at the mouth, ε / sin(θ/2) ≈ 1.79 ε at the slot's bottom corners
    // (interior angle θ = 90° - atan(0.4) ≈ 68.2°).
    const double gap = (plus.x.row(k) - minus.x.row(k)).norm();
    EXPECT_GE(gap, 1e-3 * (1 - 1e-9)) << k;
    EXPECT_LE(gap, 1e-3 / std::sin(0.5 * (M_PI / 2 - std::atan(0.4))) * (1 + 1e-9)) << k;
  }
}

TEST(FloatingLayer, AllContactsOpenGivesZeroForcesAndSaysSo) {
  // A block pulled away from a layer that rests on a clamped block: the layer has nothing to
  // hold it. The forces are zero, the layer's position is not determined, and the solver
  // says so: the residual is met, but the answer is not unique, so the solve is reported as
  // singular, not converged (issue 5).
  const double eps = 1e-3;
  Model model;
  model.bodies.reserve(3);  // the references below must survive the push_backs
  RectangleMeshSpec lower{0, -1, 1, 1, 4, 4};
  RectangleMeshSpec upper{0, eps, 1, 1, 4, 4};
  model.bodies.push_back({"lower", structured_rectangle(lower), Material{4500, 5400, PlaneHypothesis::Strain}});
  model.bodies.push_back({"upper", structured_rectangle(upper), Material{4500, 5400, PlaneHypothesis::Strain}});
  const Mesh& lo = model.bodies[0].mesh;
  const Mesh& up = model.bodies[1].mesh;
  FacePolyline bottom_face(5, 2), top_face(5, 2);
  for (int i = 0; i < 5; ++i) {
    bottom_face.row(i) = lo.nodes.row(lo.node_set("top")[i]);
    top_face.row(i) = up.nodes.row(up.node_set("bottom")[i]);
  }
  model.bodies.push_back({"layer", layer_band(bottom_face, top_face, 2), Material{4.5, 5.4, PlaneHypothesis::Strain}, true});
  for (int c : {0, 1}) {
    model.dirichlet.push_back({"lower_bottom", 0, lo.node_set("bottom"), c, 0.0});
    model.dirichlet.push_back({"upper_top", 1, up.node_set("top"), c, c == 1 ? 1e-3 : 0.0});
  }
  const InterfaceLaw law = InterfaceLaw::make(inf, inf, 0.5);
  const Mesh& layer = model.bodies[2].mesh;
  const LinearSystem system(model);
  const ContactProblem problem(
      system, {paired_interface("S+", law, model, 1, up.node_set("bottom"), up.edge_set("bottom"), 2, layer.node_set("S+"), 1e-12),
               paired_interface("S-", law, model, 2, layer.node_set("S-"), layer.edge_set("S-"), 0, lo.node_set("top"), 1e-12)});
  const SolveReport s = solve_fast(problem);
  EXPECT_FALSE(s.converged) << s.message;
  EXPECT_EQ(s.stop_cause, StopCause::Singular);
  EXPECT_LE(s.residual.value(), 1e-10);
  EXPECT_EQ(s.r.norm(), 0.0);
  EXPECT_NE(s.message.find("held by none of its contacts"), std::string::npos) << s.message;
}

}  // namespace
}  // namespace thinlayer
