// Warnings with one meaning each (issue 35, item 3): the film admissibility of SPEC §1.5 for
// contact faces and films only; a bonded glue's largest strain reported as a load level, never a
// warning; in both modes a body that moves more than 5 % of its size, and in limit mode a bondline
// that slips more than one element along S (the layer mode's rule). The joints are those of docs/solvers.md
// ("Small displacements, both modes"):
// a glued aluminium single lap at 20 MPa of mean shear (2 mm sheets, 25 mm overlap, 0.2 mm epoxy,
// 500 N/mm on the grip), with its grip held sideways or left free; the friction-held double lap;
// the paper's lap joint pulled 1 mm. Expected values by hand in each test.
#include <gtest/gtest.h>

#include <string>

#include "cases/answer_admissibility.h"
#include "cases/film_admissibility.h"
#include "cases/scene/scene_file_scenes.h"
#include "tests/scene_folder.h"
#include "tests/text_file.h"

using namespace thinlayer;

namespace {

const std::string cases_dir = std::string(THINLAYER_CASES_DIR);

std::string replaced(std::string text, const std::vector<std::pair<std::string, std::string>>& edits) {
  for (const auto& [from, to] : edits) {
    EXPECT_NE(text.find(from), std::string::npos) << from;
    for (std::size_t at; (at = text.find(from)) != std::string::npos;) text.replace(at, from.size(), to);
  }
  return text;
}

// The aluminium single lap of docs/solvers.md at 20 MPa: cases/single_lap's drawing with 2 mm sheets,
// 50 mm long, overlapping over 25 mm; 500 N/mm on the grip; the grip held sideways or not.
std::string aluminium_lap(const SceneFolder& f, bool grip_held_sideways) {
  f.write("single_lap.geo", replaced(read_text_file(cases_dir + "/single_lap/single_lap.geo"),
                                     {{"L = 30;", "L = 50;"}, {"t = 1;", "t = 2;"}, {"a = 17.5;", "a = 25;"}}));
  const std::string supports = grip_held_sideways ? R"([{"group": "clamp", "u": [0, 0]}, {"group": "grip", "u": [null, 0]}])"
                                                  : R"([{"group": "clamp", "u": [0, 0]}])";
  return f.write("lap.json", replaced(read_text_file(cases_dir + "/single_lap/single_lap.json"),
                                      {{"\"E\": 210000, \"nu\": 0.3}", "\"E\": 70000, \"nu\": 0.33}"},
                                       {"\"thickness\": 0.5", "\"thickness\": 0.2"},
                                       {R"([{"group": "clamp", "u": [0, 0]}, {"group": "grip", "u": [0.01, 0]}])",
                                        supports + R"(, "loads": [{"group": "grip", "force": [500, 0]}])"}}));
}

}  // namespace

// A bonded glue has no film: no slip, no film strain; its strain is a load level. The mean shear
// stress 500/25 = 20 MPa strains the epoxy (G = 3000/2.7 = 1111 MPa) by γ = 0.018, a principal
// strain of γ/2 = 0.009; its peak at the overlap's ends is higher — and no warning says so.
TEST(AnswerWarnings, ABondedGluesStrainIsALoadLevelNotAWarning) {
  SceneFolder f;
  SceneFileBulk bulk(read_scene_spec(aluminium_lap(f, true)));
  const SceneFileScene s = solve_scene_file_layer(bulk, 0, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  const auto& n = s.record.numbers;
  EXPECT_EQ(n.count("film_slip_over_h"), 0u);  // both faces bonded: no contact face
  EXPECT_EQ(n.count("film_strain_max"), 0u);   // and no film
  ASSERT_EQ(n.count("glue_strain_max"), 1u);
  EXPECT_GT(n.at("glue_strain_max"), 0.009);
  EXPECT_EQ(film_warning(s.record), "");
  const std::string line = film_line(s.record);
  EXPECT_NE(line.find("linear elastic glue assumed; peak strain"), std::string::npos) << line;
  std::printf("aluminium lap at 20 MPa, layer mode: %s\n", line.c_str());
  EXPECT_EQ(displacement_warning_line(s.record), "");  // the grip held sideways: 0.9 mm on a 50 mm sheet
}

// The paper's layer, in contact on both faces (the friction-held double lap at 500 N/mm): a film,
// its slip over h and strain recorded, no glue strain.
TEST(AnswerWarnings, AFilmInContactKeepsItsAdmissibility) {
  SceneFileBulk bulk(read_scene_spec(cases_dir + "/friction_double_lap/friction_double_lap.json"));
  const SceneFileScene s = solve_scene_file_layer(bulk, 0, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(s.report.converged) << s.report.message;
  const auto& n = s.record.numbers;
  EXPECT_EQ(n.count("film_slip_over_h"), 1u);
  EXPECT_EQ(n.count("film_strain_max"), 1u);
  EXPECT_EQ(n.count("glue_strain_max"), 0u);
  // The slip is that of the contact faces: recomputed from the faces alone it is the same.
  EXPECT_DOUBLE_EQ(n.at("film_slip_over_h"), film_admissibility(s.record).slip_over_h);
}

// Its grip left free sideways, the lap bends about its eccentricity: solved linearly it deflects
// far more than 5 % of the 50 mm sheet, in both modes, and says so naming the body.
TEST(AnswerWarnings, ALargeDeflectionIsWarnedInBothModes) {
  SceneFolder f;
  SceneFileBulk bulk(read_scene_spec(aluminium_lap(f, false)));
  for (const bool layer : {false, true}) {
    const SceneFileScene s = layer ? solve_scene_file_layer(bulk, 0, SolverKind::Fast, SolverOptions{})
                                   : solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
    ASSERT_TRUE(s.report.converged) << s.report.message;
    const AnswerAdmissibility a = answer_admissibility(s.record);
    EXPECT_EQ(a.body, "upper");
    EXPECT_NEAR(a.size, 50.0, 1e-9);
    EXPECT_GT(a.displacement_over_size, displacement_warning);
    const std::string w = displacement_warning_line(s.record);
    std::printf("%s mode: %s\n", layer ? "layer" : "limit", w.c_str());
    EXPECT_NE(w.find("body 'upper' moves"), std::string::npos) << w;
  }
}

// Limit mode, the layer mode's rule: the paper's lap joint (0.5 mm elements along S, f = 0.5)
// pulled 1 mm at its grip slides along most of its bondline by more than an element; pulled
// 0.075 mm (as shipped) it does not.
TEST(AnswerWarnings, ALimitModeSlipAboveOneElementIsWarned) {
  SceneFolder f;
  f.write("lap_joint.geo", read_text_file(cases_dir + "/lap_joint/lap_joint.geo"));
  const std::string shipped = read_text_file(cases_dir + "/lap_joint/lap_joint.json");
  SceneFileBulk pulled(read_scene_spec(f.write("far.json", replaced(shipped, {{"\"u\": [0.075, 0]", "\"u\": [1, 0]"}}))));
  const SceneFileScene far = solve_scene_file_limit(pulled, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(far.report.converged) << far.report.message;
  EXPECT_GT(far.record.numbers.at("slip_over_h"), 1.0);
  // The largest slip over h is the largest |[u]_T| over its element, by hand from the fields.
  const InterfaceFields& S = far.record.interfaces.at(0);
  double largest = 0;
  for (Eigen::Index k = 1; k + 1 < S.jump_T.size(); ++k)
    largest = std::max(largest, std::abs(S.jump_T[k]) / (0.5 * ((S.x.row(k + 1) - S.x.row(k)).norm() +
                                                                 (S.x.row(k) - S.x.row(k - 1)).norm())));
  EXPECT_GE(far.record.numbers.at("slip_over_h"), largest * (1 - 1e-12));
  EXPECT_NE(limit_slip_warning_line(far.record).find("the bondline slips"), std::string::npos);
  SceneFileBulk shipped_bulk(read_scene_spec(cases_dir + "/lap_joint/lap_joint.json"));
  const SceneFileScene near = solve_scene_file_limit(shipped_bulk, SolverKind::Fast, SolverOptions{});
  EXPECT_LT(near.record.numbers.at("slip_over_h"), 1.0);
  EXPECT_EQ(limit_slip_warning_line(near.record), "");
}
