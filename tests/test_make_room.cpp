// Making room for the layer in a chosen direction (issue 35, item 6): a bondline's "make_room"
// [dx, dy] moves the plus body along d by ε / (d·n) instead of along the bondline's normal n, so
// that the layer is still ε thick across the bondline. The scarf of cases/scarf (two 3 mm steel
// strips, a 10 mm run at a slope of 3/10, the right strip pulled along the axis): along its normal
// the pulled strip is lifted off the axis by 0.0958 ε/0.1 mm and the validity study measures that
// offset; along the axis it stays in line. Expected values by hand: n = (3, 10)/√109.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cases/scene/scene_file_scenes.h"
#include "studies/tools/scene_distance.h"
#include "tests/scene_folder.h"
#include "tests/text_file.h"

using namespace thinlayer;

namespace {

const std::string scarf_dir = std::string(THINLAYER_CASES_DIR) + "/scarf/";
const double root109 = std::sqrt(109.0);

// The shipped scarf with its "make_room" replaced (or removed: "").
std::string scarf_with(const SceneFolder& f, const std::string& make_room) {
  f.write("scarf.geo", read_text_file(scarf_dir + "scarf.geo"));
  std::string json = read_text_file(scarf_dir + "scarf.json");
  const std::string shipped = ",\n                \"make_room\": [1, 0]";
  const auto at = json.find(shipped);
  EXPECT_NE(at, std::string::npos);
  json.replace(at, shipped.size(), make_room.empty() ? "" : ",\n \"make_room\": " + make_room);
  return f.write("scarf.json", json);
}

// Every node of the right strip moved by the same vector from its limit-mode position (mm).
Eigen::Vector2d translation_of_right_strip(const SceneFileBulk& bulk, const SceneRecord& layer) {
  const int right = bulk.spec().body_index("right");
  int offset = 0;
  for (int b = 0; b < right; ++b) offset += bulk.meshes().bodies[b].num_nodes();
  const Mesh& m = bulk.meshes().bodies[right];
  const Eigen::Vector2d first = (layer.nodes.row(offset) - m.nodes.row(0)).transpose();
  for (int k = 0; k < m.num_nodes(); ++k)
    EXPECT_LT(((layer.nodes.row(offset + k) - m.nodes.row(k)).transpose() - first).norm(), 1e-12) << "node " << k;
  return first;
}

}  // namespace

// Along the axis [1, 0]: the strip translates by ε / (d·n) = ε √109 / 3 along x, the layer is ε
// thick across the scarf; by default it translates by ε n (0.0958 mm up at ε = 0.1).
TEST(MakeRoom, TheScarfsStripMovesAlongTheAxisOrAlongTheNormal) {
  const double eps = 0.1;
  SceneFileBulk along(read_scene_spec(scarf_dir + "scarf.json"));
  const SceneFileScene a = solve_scene_file_layer(along, eps, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(a.report.converged) << a.report.message;
  const Eigen::Vector2d moved = translation_of_right_strip(along, a.record);
  EXPECT_NEAR(moved.x(), eps * root109 / 3, 1e-12);
  EXPECT_NEAR(moved.y(), 0.0, 1e-12);
  EXPECT_NEAR(moved.dot(Eigen::Vector2d(3, 10) / root109), eps, 1e-12);  // ε thick across the bondline
  SceneFolder f;
  SceneFileBulk normal(read_scene_spec(scarf_with(f, "")));
  const SceneFileScene n = solve_scene_file_layer(normal, eps, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(n.report.converged) << n.report.message;
  const Eigen::Vector2d lifted = translation_of_right_strip(normal, n.record);
  EXPECT_NEAR(lifted.x(), eps * 3 / root109, 1e-12);
  EXPECT_NEAR(lifted.y(), eps * 10 / root109, 1e-12);  // 0.0958 mm off the clamped strip's axis
}

// What the validity study measures: along the axis, the modelling error, first order in ε (the
// adherents' distance halves with ε: p = 1 ± 0.15, the rate of a finite law); along the normal, the
// offset's bending — more than half the displacement at 0.1 mm.
TEST(MakeRoom, AlongTheAxisTheDistanceIsTheLawsNotTheOffsets) {
  SceneFileBulk along(read_scene_spec(scarf_dir + "scarf.json"));
  SceneFolder f;
  SceneFileBulk normal(read_scene_spec(scarf_with(f, "")));
  auto distance = [](SceneFileBulk& bulk, double eps) {
    const SceneFileScene layer = solve_scene_file_layer(bulk, eps, SolverKind::Fast, SolverOptions{});
    const SceneFileScene limit = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{}, eps);
    return scene_distance(bulk, layer.record, limit.record).at("u");
  };
  const double a1 = distance(along, 0.1), a2 = distance(along, 0.05), n1 = distance(normal, 0.1);
  std::printf("u distance at 0.1 mm: along the axis %.3g (at 0.05: %.3g), along the normal %.3g\n", a1, a2, n1);
  EXPECT_NEAR(std::log(a1 / a2) / std::log(2.0), 1.0, 0.15);
  EXPECT_LT(a1, 0.02);
  EXPECT_GT(n1, 0.5);
}

// A direction along the bondline, or away from the plus body, is refused before anything is solved,
// naming the key; so is no direction at all.
TEST(MakeRoom, ADirectionThatCannotMakeRoomIsRefused) {
  SceneFolder f;
  try {
    SceneFileBulk bulk(read_scene_spec(scarf_with(f, "[-1, 0]")));
    FAIL() << "a direction into the minus body was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'make_room' [-1, 0] is"), std::string::npos) << e.what();
  }
  SceneFolder g;
  try {
    SceneFileBulk bulk(read_scene_spec(scarf_with(g, "[10, -3]")));  // along the scarf
    FAIL() << "a direction along the bondline was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("90 deg from"), std::string::npos) << e.what();
  }
  SceneFolder h;
  EXPECT_THROW(read_scene_spec(scarf_with(h, "[0, 0]")), InputError);
}
