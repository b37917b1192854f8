// An engineer's glue carries the joint in limit mode (SPEC §1.3, issue 35 item 1): a glue given by
// E, ν and a thickness t gets its own finite springs K_N = (λ_g+2μ_g)/t, K_T = μ_g/t at t, never a
// 0 or ∞ cut-off. The shipped steel single lap (cases/single_lap: 1 mm steel sheets, 0.5 mm epoxy
// E 3000 MPa, ν 0.35) is the joint the paper's 3 % / 30x rule broke: μ_g/t = 2222 MPa/mm is 2.75 %
// of the steel's μ_m/L = 80769 MPa/mm, so the rule chose class (c), μ̄ = 0, and the limit mode
// carried 3.8e-22 N/mm where the meshed layer carries ~245 N/mm. The same with 2 mm aluminium
// sheets and a 3 mm line (μ_g/t = 2.8 % of μ_m/L). Expected values are computed by hand here.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cases/scene/scene_file_scenes.h"
#include "studies/drivers/scene_solve_output.h"
#include "core/interface/glue.h"
#include "tests/scene_folder.h"
#include "tests/text_file.h"

using namespace thinlayer;

namespace {

const std::string cases_dir = std::string(THINLAYER_CASES_DIR) + "/single_lap/";

// The grip's reaction along the pull (N/mm).
double grip_force(const SceneFileScene& s) { return s.record.reactions.at("grip").x(); }

// Both modes of a single-lap scene: the grip force (N/mm) of each, at thickness eps.
std::pair<double, double> grip_forces(SceneFileBulk& bulk, double eps) {
  const SceneFileScene limit = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{}, eps);
  const SceneFileScene layer = solve_scene_file_layer(bulk, eps, SolverKind::Fast, SolverOptions{});
  EXPECT_TRUE(limit.report.converged) << limit.report.message;
  EXPECT_TRUE(layer.report.converged) << layer.report.message;
  EXPECT_TRUE(limit.carries_load);
  return {grip_force(limit), grip_force(layer)};
}

// The limit law carries the load the layer carries: at the glue's own thickness t the same force to
// first order, and, as the same glue thins, the two converge at the rate the asymptotics predict
// for a finite law, p = 1 (case (d), docs/joints.md "Bonded faces"): the relative difference at t/10 is
// below a fifth of the one at t (p > 0.7) and below 3 %. With the rule's μ̄ = 0 the limit mode
// carried nothing (1e-22 N/mm) at every thickness.
void expect_limit_carries_what_the_layer_carries(SceneFileBulk& bulk) {
  const double t = bulk.spec().interfaces.at(0).glue->thickness;
  const auto [F_limit, F_layer] = grip_forces(bulk, t);
  const auto [F_limit_10, F_layer_10] = grip_forces(bulk, t / 10);
  const double d = std::abs(F_limit - F_layer) / F_layer, d_10 = std::abs(F_limit_10 - F_layer_10) / F_layer_10;
  std::printf("%s: grip force at t = %g mm: limit %.6g, layer %.6g N/mm (%.3g %% apart); at t/10: %.6g, %.6g (%.3g %%)\n",
              bulk.spec().name.c_str(), t, F_limit, F_layer, 100 * d, F_limit_10, F_layer_10, 100 * d_10);
  EXPECT_GT(F_layer, 0);
  EXPECT_GT(F_limit, 0.5 * F_layer);  // the same order: the law carries the joint
  EXPECT_LT(F_limit, 2.0 * F_layer);
  EXPECT_LT(d_10, d / 5);
  EXPECT_LT(d_10, 0.03);
  const SceneFileScene limit = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  // The law solved is the line's own, case (d), and the rule's choice is kept beside it.
  const SceneBondline& b = limit.bondlines.at(0);
  const SceneInterfaceSpec& spec = bulk.spec().interfaces.at(0);
  const LameModuli g = lame_from_young(spec.glue->E, spec.glue->nu);
  EXPECT_EQ(b.law.table1_case(), 'd');
  EXPECT_NEAR(b.law.K_N(), (g.lambda + 2 * g.mu) / t, 1e-12 * g.lambda / t);
  EXPECT_NEAR(b.law.K_T(), g.mu / t, 1e-12 * g.mu / t);
  EXPECT_EQ(b.classified.table1_case(), 'c');  // what the rule would have chosen: μ̄ = 0
  EXPECT_EQ(b.classified.mu_bar, 0.0);
}

}  // namespace

// 1 mm steel (E 210000, ν 0.3: μ_m = 80769 MPa; L = 0.968 mm, 2 area/perimeter of a 30 x 1 sheet)
// bonded by 0.5 mm of epoxy: μ_g/t = 1111.1/0.5 = 2222 MPa/mm, 2.7 % of μ_m/L.
TEST(EngineerGlueLaw, SteelSingleLapCarriesTheLoadInLimitMode) {
  SceneFileBulk bulk(read_scene_spec(cases_dir + "single_lap.json"));
  const AdherentData ref = bulk.reference(0);
  const LameModuli g = lame_from_young(3000, 0.35);
  ASSERT_LT(g.mu / 0.5, 0.03 * ref.mu_m / ref.L) << "the scene no longer exercises the rule's cut-off";
  expect_limit_carries_what_the_layer_carries(bulk);
}

// 2 mm aluminium sheets (E 70000, ν 0.33) and a 3 mm line of the same epoxy, on a 32.5 mm overlap
// (a 3 mm layer needs a bondline of at least 30 mm): μ_g/t = 370 MPa/mm against μ_m/L ≈ 13158.
TEST(EngineerGlueLaw, ThreeMillimetreLineBetweenAluminiumSheetsCarriesTheLoad) {
  SceneFolder f;
  std::string geo = read_text_file(cases_dir + "single_lap.geo");
  ASSERT_NE(geo.find("L = 30;"), std::string::npos);
  ASSERT_NE(geo.find("t = 1;"), std::string::npos);
  geo.replace(geo.find("L = 30;"), 7, "L = 50;");
  geo.replace(geo.find("t = 1;"), 6, "t = 2;");
  f.write("single_lap.geo", geo);
  std::string json = read_text_file(cases_dir + "single_lap.json");
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"\"E\": 210000, \"nu\": 0.3}", "\"E\": 70000, \"nu\": 0.33}"},
                                 {"\"thickness\": 0.5", "\"thickness\": 3"},
                                 {"\"interface\": 0.25", "\"interface\": 0.5"}})
    for (std::size_t at; (at = json.find(from)) != std::string::npos;) json.replace(at, from.size(), to);
  SceneFileBulk bulk(read_scene_spec(f.write("al.json", json)));
  const AdherentData ref = bulk.reference(0);
  ASSERT_LT(lame_from_young(3000, 0.35).mu / 3, 0.03 * ref.mu_m / ref.L) << "the scene no longer exercises the cut-off";
  expect_limit_carries_what_the_layer_carries(bulk);
}

// The rule's law itself, solved (what `solve --mode limit` does beside the glue's own to say what the
// rule would cost): μ̄ = 0 carries next to nothing, every node "stick" — and the scene says so.
TEST(EngineerGlueLaw, TheRulesLawCarriesNothingAndSaysSo) {
  SceneFileBulk bulk(read_scene_spec(cases_dir + "single_lap.json"));
  const SceneFileScene rule = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{}, 0, default_status_tolerance,
                                                     /*classified=*/true);
  ASSERT_TRUE(rule.report.converged) << rule.report.message;
  EXPECT_EQ(rule.bondlines.at(0).law.mu_bar, 0.0);
  EXPECT_LT(std::abs(grip_force(rule)), 1e-6 * 210000 * 0.01);  // nothing against E |u| of the grip
  EXPECT_FALSE(rule.carries_load);
  EXPECT_NE(no_load_warning(rule).find("carries next to nothing"), std::string::npos) << no_load_warning(rule);
}
