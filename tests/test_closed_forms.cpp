// The classical closed forms drawn beside a joint's computed curves (issue 35, item 5;
// studies/tools/closed_forms.h, studies/drivers/joint_closed_forms.h): Volkersen's shear lag and
// Goland–Reissner's lap with bending. Checked by what must hold whatever the formulas' constants:
// each shear integrates to the force P through the overlap (by hand: ∫ cosh = sinh / ω, ...); a
// balanced joint's shear is symmetric; at a vanishing load Goland–Reissner's bending factor k is 1
// and its shear is Volkersen's for adherents whose surface strain is four times the mean (membrane
// plus the bending of the eccentric shear, the 1 + 3k); and the joints they are drawn for are
// recognised from the scene — the shipped single and double laps, not the scarf.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/drivers/joint_closed_forms.h"
#include "studies/tools/closed_forms.h"
#include "tests/scene_folder.h"
#include "tests/text_file.h"

using namespace thinlayer;

namespace {

// ∫ f over [a, b], Simpson's rule on n (even) intervals.
template <typename F>
double integral(F f, double a, double b, int n = 2000) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(a + i * h);
  return sum * h / 3;
}

}  // namespace

TEST(ClosedForms, VolkersenCarriesTheForceAndIsSymmetricWhenBalanced) {
  const Volkersen balanced{25.0, 500.0, 2 * 78554.0, 2 * 78554.0, 1111.1, 0.2};
  EXPECT_NEAR(integral([&](double x) { return balanced.shear(x); }, 0, 25), 500.0, 1e-8 * 500);
  for (double x : {0.0, 3.0, 10.0}) EXPECT_NEAR(balanced.shear(x), balanced.shear(25 - x), 1e-9 * balanced.shear(0));
  EXPECT_GT(balanced.shear(0), 500.0 / 25);  // peaks at the ends, above the mean
  const Volkersen unbalanced{10.0, 80.0, 1e5, 3e5, 1111.1, 0.2};
  EXPECT_NEAR(integral([&](double x) { return unbalanced.shear(x); }, 0, 10), 80.0, 1e-8 * 80);
  EXPECT_GT(unbalanced.shear(0), unbalanced.shear(10));  // the softer adherent's loaded end carries more
}

TEST(ClosedForms, GolandReissnerCarriesTheForceAndReducesToVolkersenWithoutBending) {
  const GolandReissner lap{12.5, 500.0, 78554.0, 2.0, 1111.1, 3000.0, 0.2};
  EXPECT_NEAR(integral([&](double x) { return lap.shear(x); }, -12.5, 12.5), 500.0, 1e-8 * 500);
  EXPECT_GT(lap.k(), 0.0);
  EXPECT_LT(lap.k(), 1.0);
  EXPECT_GT(lap.peel(12.5), 0.0);  // tension at the overlap's ends
  const GolandReissner light{12.5, 1e-9, 78554.0, 2.0, 1111.1, 3000.0, 0.2};
  EXPECT_NEAR(light.k(), 1.0, 1e-5);
  const Volkersen quarter{25.0, 1e-9, 78554.0 * 2 / 4, 78554.0 * 2 / 4, 1111.1, 0.2};
  for (double x : {-12.5, -5.0, 0.0, 7.0})
    EXPECT_NEAR(light.shear(x), quarter.shear(x + 12.5), 1e-4 * light.shear(12.5)) << "x " << x;
}

TEST(ClosedForms, TheLapsAreRecognisedAndTheScarfIsNot) {
  const std::string cases(THINLAYER_CASES_DIR);
  SceneFileBulk single(read_scene_spec(cases + "/single_lap/single_lap.json"));
  const SceneFileScene s = solve_scene_file_limit(single, SolverKind::Fast, SolverOptions{});
  const JointClosedForms a = joint_closed_forms(single, s.record);
  EXPECT_EQ(a.joint, "single lap") << a.why_not;
  ASSERT_EQ(a.bondlines.size(), 1u);
  EXPECT_NEAR(a.bondlines[0].t_1, 1.0, 1e-9);  // the sheets' thickness across the bondline
  EXPECT_NEAR(a.bondlines[0].P, std::abs(s.record.reactions.at("grip").x()), 1e-6 * a.bondlines[0].P);
  EXPECT_EQ(a.bondlines[0].gr_peel.size(), a.bondlines[0].s.size());

  SceneFileBulk twice(read_scene_spec(cases + "/double_lap/double_lap.json"));
  const SceneFileScene d = solve_scene_file_limit(twice, SolverKind::Fast, SolverOptions{});
  const JointClosedForms b = joint_closed_forms(twice, d.record);
  EXPECT_EQ(b.joint, "double lap") << b.why_not;
  ASSERT_EQ(b.bondlines.size(), 2u);
  // Each bondline carries half the pull (the joint is symmetric), and Volkersen's on it is the inner
  // strip's half (1.5 mm) against an outer strip (1.5 mm).
  const double pull = std::abs(d.record.reactions.at("grip").x());
  for (const ClosedFormCurves& c : b.bondlines) {
    EXPECT_NEAR(c.P, pull / 2, 1e-3 * pull);
    EXPECT_NEAR(c.t_1, 1.5, 1e-9);
    EXPECT_NEAR(c.t_2, 1.5, 1e-9);
    EXPECT_TRUE(c.gr_shear.empty());
  }

  SceneFileBulk scarf(read_scene_spec(cases + "/scarf/scarf.json"));
  const SceneFileScene sc = solve_scene_file_limit(scarf, SolverKind::Fast, SolverOptions{});
  const JointClosedForms c = joint_closed_forms(scarf, sc.record);
  EXPECT_EQ(c.joint, "");
  EXPECT_NE(c.why_not.find("no strip along the bondlines"), std::string::npos) << c.why_not;
}

// Goland–Reissner's bending factor beside a linear model is the linear statics' of the joint's own
// supports (SPEC 3 S2 item 4; studies/tools/lap_beam.h). On the single lap pinned at both adherents'
// mid-planes (no rotation held) the joint is a two-force member: the load runs along the line between
// the pins, whose offset from the lower adherent's mid-plane at the overlap's end is (t/2) L/(L + c)
// — by hand k = L/(L + c) = 17.5/23.75 with arms L = 17.5 mm and half overlap c = 6.25 mm, at any
// load. The model's own moment there, from its pin's reaction by statics, is the same; GR's
// geometrically nonlinear k falls with the load (not the model's: shown second).
TEST(ClosedForms, TheLinearBendingFactorOfAPinnedLapIsItsStaticsAtAnyLoad) {
  const std::string cases(THINLAYER_CASES_DIR);
  SceneFolder f;
  std::string geo = read_text_file(cases + "/single_lap/single_lap.geo");
  auto replace = [&](const std::string& from, const std::string& to) {
    ASSERT_NE(geo.find(from), std::string::npos) << from;
    geo.replace(geo.find(from), from.size(), to);
  };
  // The pins: the middles of the lower sheet's left end and the upper sheet's right end.
  replace("Line(5) = {5, 1};    // lower left end: the clamp", "Point(9) = {0, t / 2, 0, h};\nLine(5) = {5, 9};\nLine(10) = {9, 1};");
  replace("Line(7) = {6, 7};    // upper right end: the grip", "Point(10) = {a + L, 1.5 * t, 0, h};\nLine(7) = {6, 10};\nLine(11) = {10, 7};");
  replace("Curve Loop(1) = {1, 2, -3, 4, 5};", "Curve Loop(1) = {1, 2, -3, 4, 5, 10};");
  replace("Curve Loop(2) = {3, 6, 7, 8, 9};", "Curve Loop(2) = {3, 6, 7, 11, 8, 9};");
  replace("Physical Curve(\"clamp\") = {5};", "Physical Point(\"pin_left\") = {9};");
  replace("Physical Curve(\"grip\") = {7};", "Physical Point(\"pin_right\") = {10};");
  f.write("single_lap.geo", geo);
  std::string json = read_text_file(cases + "/single_lap/single_lap.json");
  const std::string supports = "\"supports\": [{\"group\": \"clamp\", \"u\": [0, 0]}, {\"group\": \"grip\", \"u\": [0.01, 0]}]";
  ASSERT_NE(json.find(supports), std::string::npos);
  const double k_hand = 17.5 / 23.75;
  double gr_nonlinear[2] = {0, 0};
  for (const double P : {20.0, 2000.0}) {
    std::string j = json;
    j.replace(j.find(supports), supports.size(),
              "\"supports\": [{\"group\": \"pin_left\", \"u\": [0, 0]}, {\"group\": \"pin_right\", \"u\": [null, 0]}],\n"
              "  \"loads\": [{\"group\": \"pin_right\", \"force\": [" + full_digits(P) + ", 0]}]");
    SceneFileBulk bulk(read_scene_spec(f.write("scene.json", j)));
    const SceneFileScene s = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
    ASSERT_TRUE(s.report.converged) << s.report.message;
    const JointClosedForms forms = joint_closed_forms(bulk, s.record);
    ASSERT_EQ(forms.joint, "single lap") << forms.why_not;
    const ClosedFormCurves& c = forms.bondlines.at(0);
    ASSERT_FALSE(c.gr_shear.empty()) << c.gr_why_not;
    EXPECT_NEAR(c.k_ends[0], k_hand, 1e-9) << P;
    EXPECT_NEAR(c.k_ends[1], k_hand, 1e-9) << P;
    EXPECT_NEAR(c.k, k_hand, 1e-9) << P;
    // The model: the lower arm's moment at the overlap's start (x = 17.5, on its mid-plane y = 0.5)
    // from the pin's reaction at (0, 0.5): M = -17.5 R_y; its tension N = -R_x.
    const Eigen::Vector2d R = s.record.reactions.at("pin_left");
    EXPECT_NEAR(std::abs(-17.5 * R.y()) / (std::abs(R.x()) * 0.5), k_hand, 1e-6) << P;
    gr_nonlinear[P > 100] = c.k_nonlinear;
    // The axis names its ends, whichever way the bondline runs: the end at the overlap's start
    // (x = 17.5) is where the lower sheet runs on to pin_left, the one at x = 30 the upper to pin_right.
    const bool left_first = c.start.find("(17.5") == 0;
    const std::string& at_left = left_first ? c.start : c.end;
    const std::string& at_right = left_first ? c.end : c.start;
    EXPECT_EQ(at_left.find("(17.5, 1)"), 0u) << at_left;
    EXPECT_NE(at_left.find("'lower' runs on to pin_left"), std::string::npos) << at_left;
    EXPECT_EQ(at_right.find("(30, 1)"), 0u) << at_right;
    EXPECT_NE(at_right.find("'upper' runs on to pin_right"), std::string::npos) << at_right;
  }
  EXPECT_GT(gr_nonlinear[0] - gr_nonlinear[1], 0.1);  // GR's own k changes with the load typed
}
