// A load with no path, and a joint held by friction alone (SPEC §1.3; issue 35 items 1 and 4): the
// double lap of cases/friction_double_lap, its inner strip held by friction alone (f = 0.5) between
// two outer strips pressed onto it with 80 MPa over the 10 mm overlap (800 N/mm each), pulled by a
// force on its left end. Checked before the solve, in both modes: the pull against f × the normal
// force of the joint held stuck; a friction 0 or a law without shear leaves the pull no path at all.
// Expected values by hand: the inner strip's equilibrium (the shear its bondlines carry is its pull),
// the normal force at most the 1600 N/mm pressed on both outer strips.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "cases/scene/scene_file_scenes.h"
#include "tests/scene_folder.h"
#include "tests/text_file.h"

using namespace thinlayer;

namespace {

const std::string cases_dir = std::string(THINLAYER_CASES_DIR) + "/friction_double_lap/";

// The shipped scene in a folder of the test's, with each (from, to) replaced in its JSON.
std::string scene_with(const SceneFolder& f, const std::vector<std::pair<std::string, std::string>>& edits) {
  f.write("friction_double_lap.geo", read_text_file(cases_dir + "friction_double_lap.geo"));
  std::string json = read_text_file(cases_dir + "friction_double_lap.json");
  for (const auto& [from, to] : edits) {
    EXPECT_NE(json.find(from), std::string::npos) << from;
    for (std::size_t at; (at = json.find(from)) != std::string::npos;) json.replace(at, from.size(), to);
  }
  return f.write("scene.json", json);
}

std::string pull(double force) { return "\"force\": [" + full_digits(-force) + ", 0]"; }

}  // namespace

// 1000 N/mm against a capacity of 0.5 × (at most 1600): refused before the solve, in both modes.
TEST(LoadPath, FrictionOverloadIsNamedWithBothNumbersInBothModes) {
  SceneFolder f;
  SceneFileBulk bulk(read_scene_spec(scene_with(f, {{"\"force\": [-500, 0]", pull(1000)}})));
  for (const std::string mode : {"limit", "layer"}) {
    const LoadPath path = scene_load_path(bulk, mode, 0.0);
    EXPECT_TRUE(path.no_path.empty()) << path.no_path;
    ASSERT_TRUE(path.capacity_estimated) << path.capacity_note;
    ASSERT_EQ(path.friction.size(), 1u) << mode;
    const FrictionHold& h = path.friction.front();
    EXPECT_EQ(h.bodies, "'inner'");
    EXPECT_NEAR(h.load, 1000.0, 1e-6);            // the inner strip's equilibrium: its bondlines shear its pull
    EXPECT_GT(h.normal, 0.0);
    EXPECT_LE(h.normal, 1600.0 * (1 + 1e-9));     // no more than the pressure puts on both outer strips
    EXPECT_NEAR(h.capacity, 0.5 * h.normal, 1e-9 * h.normal);
    EXPECT_TRUE(h.exceeded());
    ASSERT_EQ(path.exceeded(), &h);
    const std::string line = friction_line(h, "N");
    std::printf("%s mode: %s\n", mode.c_str(), line.c_str());
    EXPECT_NE(line.find("'inner'"), std::string::npos);
    EXPECT_NE(line.find("1000 N/mm"), std::string::npos);
    EXPECT_NE(line.find("exceeds"), std::string::npos);
  }
}

// The estimate is not optimistic: a pull of 98 % of the estimated capacity is held by the solve,
// which converges with the clamp carrying the whole pull.
TEST(LoadPath, APullWithinTheEstimatedCapacityIsHeld) {
  SceneFolder f;
  SceneFileBulk probe(read_scene_spec(scene_with(f, {})));
  const LoadPath estimate = scene_load_path(probe, "limit", 0.0);
  ASSERT_EQ(estimate.friction.size(), 1u);
  EXPECT_FALSE(estimate.friction.front().exceeded());
  const double F = 0.98 * estimate.friction.front().capacity;
  SceneFolder g;
  SceneFileBulk bulk(read_scene_spec(scene_with(g, {{"\"force\": [-500, 0]", pull(F)}})));
  ASSERT_EQ(scene_load_path(bulk, "limit", 0.0).exceeded(), nullptr);
  const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  EXPECT_NEAR(s.record.reactions.at("clamp").x(), F, 1e-8 * F);
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
  EXPECT_TRUE(ok.friction.empty());
}

// The command line: exit 1 and one line naming the body and both numbers, before any solve (the
// solver, given the same scene, ran for 4 s in limit mode and 145 s in layer mode before ending
// "singular system"); friction 0: exit 2 (bad input), one line.
TEST(LoadPath, CommandLineSaysItInOneLine) {
  SceneFolder f;
  const std::string scene = scene_with(f, {{"\"force\": [-500, 0]", pull(1000)}});
  for (const std::string mode : {"limit", "layer"}) {
    const std::string err = (f.path / "err.txt").string();
    const int raw = std::system((std::string(THINLAYER_CLI) + " solve --scene " + scene + " --mode " + mode +
                                 " --out " + (f.path / "r.h5").string() + " >/dev/null 2>" + err).c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    EXPECT_EQ(WEXITSTATUS(raw), 1) << mode;
    const std::string text = read_text_file(err);
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
    EXPECT_NE(text.find("body 'inner' is held by friction alone: its load along the bondlines, 1000 N/mm, exceeds"),
              std::string::npos) << text;
    EXPECT_FALSE(std::filesystem::exists(f.path / "r.h5"));  // nothing solved, nothing written
  }
  SceneFolder g;
  const std::string frictionless = scene_with(g, {{"\"friction\": 0.5", "\"friction\": 0"}});
  const std::string err = (g.path / "err.txt").string();
  const int raw = std::system((std::string(THINLAYER_CLI) + " solve --scene " + frictionless + " >/dev/null 2>" + err).c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 2);
  const std::string text = read_text_file(err);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1) << text;
  EXPECT_NE(text.find("has no path to a support"), std::string::npos) << text;
}
