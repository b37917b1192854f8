// A refusal is a proof (SPEC 1.3): before a solve, a scene is refused only where statics proves that
// no forces inside each contact node's admissible set balance every body, force and moment (an LP,
// cases/scene/load_path.h). The scenes:
//  - the double lap of cases/friction_double_lap, its inner strip held by friction alone (f = 0.5)
//    between two outer strips pressed onto it with 80 MPa over the 10 mm overlap (800 N/mm each),
//    pulled by a force on its left end. With both outer strips clamped, statics does not fix the
//    normal force (a clamp can press harder): no pull is refused; a pull the solve cannot hold fails
//    and the stuck-joint estimate explains it. With the upper strip on rollers (u_x held, u_y free)
//    the normal force is fixed by statics, N = 800 N/mm on each face, and friction holds at most
//    0.5 x (800 + 800) = 800 N/mm: 790 solves, 810 and 1000 are refused with the least imbalance
//    10 and 200 N/mm (by hand: pull − capacity).
//  - cases/round_tenon: a round plug wedged in its socket by an undercut, pulled out along its neck
//    (solves in both modes; main refused it as "none of its contacts is pressed"), and the same
//    plug in a shallow socket (no undercut: every force inside the cones pushes it up, refused).
// A friction 0 or a law without shear leaves the pull no path at all (exit 2).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "cases/scene/scene_file_scenes.h"
#include "tests/cli_in_folder.h"
#include "tests/scene_folder.h"
#include "tests/text_file.h"

using namespace thinlayer;

namespace {

const std::string cases_dir = std::string(THINLAYER_CASES_DIR) + "/friction_double_lap/";
const std::string tenon_dir = std::string(THINLAYER_CASES_DIR) + "/round_tenon/";

// The shipped scene in a folder of the test's, with each (from, to) replaced in its JSON (and in its
// geometry: `geo_edits`).
std::string scene_with(const SceneFolder& f, const std::vector<std::pair<std::string, std::string>>& edits,
                       const std::vector<std::pair<std::string, std::string>>& geo_edits = {}) {
  auto edited = [](std::string text, const std::vector<std::pair<std::string, std::string>>& list) {
    for (const auto& [from, to] : list) {
      EXPECT_NE(text.find(from), std::string::npos) << from;
      for (std::size_t at; (at = text.find(from)) != std::string::npos;) text.replace(at, from.size(), to);
    }
    return text;
  };
  f.write("friction_double_lap.geo", edited(read_text_file(cases_dir + "friction_double_lap.geo"), geo_edits));
  return f.write("scene.json", edited(read_text_file(cases_dir + "friction_double_lap.json"), edits));
}

std::string pull(double force) { return "\"force\": [" + full_digits(-force) + ", 0]"; }

// The upper strip on rollers at its right end (u_x held, u_y free), the lower one clamped: the
// normal force on both faces is the 800 N/mm pressed on the upper strip, fixed by statics.
std::string on_rollers(const SceneFolder& f, double force) {
  return scene_with(f, {{"\"force\": [-500, 0]", pull(force)},
                        {"\"supports\": [{\"group\": \"clamp\", \"u\": [0, 0]}]",
                         "\"supports\": [{\"group\": \"clamp\", \"u\": [0, 0]}, {\"group\": \"roll\", \"u\": [0, null]}]"}},
                    {{"Physical Curve(\"clamp\") = {8, 12};", "Physical Curve(\"roll\") = {8};\nPhysical Curve(\"clamp\") = {12};"}});
}

}  // namespace

// Rollers: the capacity is 800 N/mm by statics. 810 and 1000 N/mm are refused in both modes, with
// the least imbalance (pull − 800) the proof stands on; 790 N/mm is not refused and solves.
TEST(LoadPath, AFrictionOverloadFixedByStaticsIsRefusedWithItsImbalance) {
  for (const double force : {810.0, 1000.0}) {
    SceneFolder f;
    SceneFileBulk bulk(read_scene_spec(on_rollers(f, force)));
    for (const std::string mode : {"limit", "layer"}) {
      const LoadPath path = scene_load_path(bulk, mode, 0.0);
      EXPECT_TRUE(path.no_path.empty()) << path.no_path;
      EXPECT_NEAR(path.imbalance_any_shear, 0.0, 1e-9 * force) << mode;
      EXPECT_NEAR(path.imbalance_in_cones, force - 800.0, 1e-6 * force) << mode;
      std::printf("%s mode, %g N/mm: %s\n", mode.c_str(), force, path.friction_overload.c_str());
      EXPECT_NE(path.friction_overload.find("body 'inner' is loaded with (" + std::to_string(int(-force)) + ", 0) N/mm"),
                std::string::npos) << path.friction_overload;
      EXPECT_NE(path.friction_overload.find("friction cannot hold it"), std::string::npos);
    }
  }
  SceneFolder g;
  SceneFileBulk within(read_scene_spec(on_rollers(g, 790.0)));
  const LoadPath path = scene_load_path(within, "limit", 0.0);
  EXPECT_TRUE(path.no_path.empty() && path.friction_overload.empty()) << path.friction_overload;
  const SceneFileScene s = solve_scene_file_limit(within, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  EXPECT_NEAR(s.record.reactions.at("clamp").x() + s.record.reactions.at("roll").x(), 790.0, 1e-8 * 790.0);
}

// Clamped strips: statics leaves the normal force free, so 1000 N/mm is not refused; the solve runs,
// fails (the strips cannot press 1000 N/mm of friction), and the estimate of the joint held stuck
// explains it after the solver's own line: exit 1, nothing refused before.
TEST(LoadPath, AnOverloadStaticsCannotProveIsSolvedAndTheEstimateExplainsTheFailure) {
  SceneFolder f;
  const std::string scene = scene_with(f, {{"\"force\": [-500, 0]", pull(1000)}});
  SceneFileBulk bulk(read_scene_spec(scene));
  for (const std::string mode : {"limit", "layer"}) {
    const LoadPath path = scene_load_path(bulk, mode, 0.0);
    EXPECT_TRUE(path.no_path.empty() && path.friction_overload.empty()) << mode << path.friction_overload;
    EXPECT_LE(path.imbalance_in_cones, 1e-6 * path.loads) << mode;
  }
  const std::vector<FrictionHold> holds = scene_friction_estimate(bulk, "limit", 0.0);
  ASSERT_EQ(holds.size(), 1u);
  EXPECT_EQ(holds.front().bodies, "'inner'");
  EXPECT_NEAR(holds.front().load, 1000.0, 1e-6);          // the inner strip's equilibrium: its bondlines shear its pull
  EXPECT_LE(holds.front().normal, 1600.0 * (1 + 1e-9));   // no more than the pressure puts on both outer strips
  EXPECT_TRUE(holds.front().exceeded());
  std::string err;
  EXPECT_EQ(run_cli("solve --scene " + scene + " --mode limit", f, err), 1);
  EXPECT_NE(err.find("NOT converged"), std::string::npos) << err;
  EXPECT_NE(err.find("exceeds f x its normal force in the joint held stuck"), std::string::npos) << err;
  EXPECT_NE(err.find("an estimate"), std::string::npos) << err;
  EXPECT_LT(err.find("NOT converged"), err.find("an estimate")) << err;  // the estimate follows the failure
}

// The wedged round tenon: every force inside the cones it needs exists (the undercut pushes the head
// down), so nothing is refused, and it solves in both modes with the clamp carrying the pull.
TEST(LoadPath, TheWedgedRoundTenonSolvesInBothModes) {
  SceneFileBulk bulk(read_scene_spec(tenon_dir + "round_tenon.json"));
  for (const std::string mode : {"limit", "layer"}) {
    const LoadPath path = scene_load_path(bulk, mode, 0.0);
    EXPECT_TRUE(path.no_path.empty() && path.friction_overload.empty()) << mode << path.no_path << path.friction_overload;
    const SceneFileScene s = mode == "limit" ? solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{})
                                             : solve_scene_file_layer(bulk, 0.0, SolverKind::Fast, SolverOptions{});
    ASSERT_TRUE(s.report.converged) << mode << ": " << s.report.message;
    EXPECT_NEAR(s.record.reactions.at("clamp").y(), -100.0, 1e-8 * 100) << mode;
  }
}

// The same plug in a shallow socket (no undercut): within f = 0.3 every contact force pushes the
// head up, so the pull of 100 N/mm has at least 100 N/mm of imbalance; refused in both modes, exit 1.
TEST(LoadPath, APlugWithNoUndercutIsRefusedByStatics) {
  const std::string scene = tenon_dir + "shallow_socket.json";
  SceneFileBulk bulk(read_scene_spec(scene));
  for (const std::string mode : {"limit", "layer"}) {
    const LoadPath path = scene_load_path(bulk, mode, 0.0);
    EXPECT_TRUE(path.no_path.empty()) << path.no_path;
    EXPECT_GE(path.imbalance_in_cones, 100.0 * (1 - 1e-9)) << mode;
    EXPECT_NE(path.friction_overload.find("body 'plug' is loaded with (0, 100) N/mm"), std::string::npos)
        << path.friction_overload;
    SceneFolder f;
    std::string err;
    EXPECT_EQ(run_cli("solve --scene " + scene + " --mode " + mode + " --out " + (f.path / "r.h5").string(), f, err), 1);
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find("Statics proves"), std::string::npos) << err;
    EXPECT_NE(err.find("nothing solved"), std::string::npos) << err;
    EXPECT_FALSE(std::filesystem::exists(f.path / "r.h5"));
  }
}

// Friction 0: the bondlines push only; nothing carries the pull along them. A bilateral law
// without shear (mu_bar = 0) likewise. Named before the solve, with the body and its load.
TEST(LoadPath, NoShearOnTheBondlinesLeavesThePullNoPath) {
  SceneFolder f;
  SceneFileBulk frictionless(read_scene_spec(scene_with(f, {{"\"friction\": 0.5", "\"friction\": 0"}})));
  for (const std::string mode : {"limit", "layer"}) {
    const std::string line = scene_load_path(frictionless, mode, 0.0).no_path;
    EXPECT_NE(line.find("body 'inner' is loaded with (-500, 0) N/mm"), std::string::npos) << line;
    EXPECT_NE(line.find("no shear (friction 0)"), std::string::npos) << line;
  }
  SceneFolder g;
  SceneFileBulk shearless(read_scene_spec(scene_with(
      g, {{"\"glue\": {\"E\": 3000, \"nu\": 0.35, \"thickness\": 0.2}",
           "\"faces\": {\"plus\": \"bonded\", \"minus\": \"bonded\"}, \"law\": {\"lambda_bar\": 1000, \"mu_bar\": 0}"}})));
  const std::string line = scene_load_path(shearless, "limit", 0.0).no_path;
  EXPECT_NE(line.find("body 'inner'"), std::string::npos) << line;
  EXPECT_NE(line.find("no shear (mu_bar = 0)"), std::string::npos) << line;
  // The glued double lap (both faces bonded, finite law) has a path and no friction hold.
  SceneFolder h;
  SceneFileBulk glued(read_scene_spec(scene_with(
      h, {{"\"friction\": 0.5,", "\"faces\": {\"plus\": \"bonded\", \"minus\": \"bonded\"},"}})));
  const LoadPath ok = scene_load_path(glued, "limit", 0.0);
  EXPECT_TRUE(ok.no_path.empty()) << ok.no_path;
  EXPECT_TRUE(ok.friction_overload.empty()) << ok.friction_overload;
}

// Friction 0 on the command line: exit 2 (bad input), one line.
TEST(LoadPath, CommandLineSaysANoPathInOneLine) {
  SceneFolder g;
  const std::string frictionless = scene_with(g, {{"\"friction\": 0.5", "\"friction\": 0"}});
  std::string text;
  EXPECT_EQ(run_cli("solve --scene " + frictionless, g, text), 2);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_NE(text.find("has no path to a support"), std::string::npos) << text;
}
