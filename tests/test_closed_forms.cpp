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
