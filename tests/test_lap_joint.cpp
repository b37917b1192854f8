// The shipped single-lap shear joint (cases/lap_joint), both modes, read like a user's scene:
// each mode converges to the SPEC residual, the reactions balance the press on the overlap,
// the bondline slips at the overlap's ends first (shear lag), and at ε = 1e-3 mm the layer
// model's adherents are within the paper's validity tolerance of the limit law.
#include <gtest/gtest.h>

#include <string>

#include "cases/scene/scene_file_scenes.h"
#include "studies/tools/scene_distance.h"

using namespace thinlayer;

namespace {

const std::string lap_joint = std::string(THINLAYER_CASES_DIR) + "/lap_joint/lap_joint.json";
constexpr double press_force = 5.0 * 12.5;  // daN/mm: 5 daN/mm² on the 12.5 mm overlap, downwards

void expect_reactions_balance_the_press(const SceneRecord& r) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const auto& [name, R] : r.reactions) sum += R;
  EXPECT_NEAR(sum.x(), 0.0, 1e-8 * press_force);
  EXPECT_NEAR(sum.y(), press_force, 1e-8 * press_force);
}

}  // namespace

TEST(LapJoint, LimitModeConvergesAndSlipsAtTheOverlapEndsFirst) {
  SceneFileBulk bulk(read_scene_spec(lap_joint));
  const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  EXPECT_LE(s.report.residual.value(), 1e-10);
  expect_reactions_balance_the_press(s.record);
  // Shear lag: the shear peaks at both ends of the overlap, so a partly slipping bondline
  // slides at its ends and sticks in the middle, never the other way round.
  const std::vector<int>& status = s.record.interfaces.at(0).status;  // along the bondline
  ASSERT_GT(s.limit.slide, 0);
  ASSERT_GT(s.limit.stick, 0);
  EXPECT_EQ(s.limit.gap, 0);  // pressed all along
  size_t first_stick = 0, last_stick = status.size() - 1;
  while (status[first_stick] != 2) ++first_stick;
  while (status[last_stick] != 2) --last_stick;
  for (size_t k = first_stick; k <= last_stick; ++k) EXPECT_EQ(status[k], 2) << "node " << k << " inside the stick zone";
  EXPECT_GT(first_stick, 0u);
  EXPECT_LT(last_stick, status.size() - 1);
}

TEST(LapJoint, LayerModeConvergesAndIsWithinOnePercentAtTheThousandthOfAMillimetre) {
  SceneFileBulk bulk(read_scene_spec(lap_joint));
  const SceneFileScene limit = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  const SceneFileScene layer = solve_scene_file_layer(bulk, 1e-3, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(layer.report.converged) << layer.report.message;
  EXPECT_LE(layer.report.residual.value(), 1e-10);
  expect_reactions_balance_the_press(layer.record);
  EXPECT_EQ(layer.record.interfaces.size(), 2u);  // S+ and S-
  // The paper (§3.2): the limit law is valid up to ε = 1e-3 mm; SPEC §3 S3's tolerance τ = 1 %.
  EXPECT_LT(scene_distance(bulk, layer.record, limit.record).at("u"), 0.01);
}
