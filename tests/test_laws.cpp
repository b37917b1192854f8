// The limit interface laws (core/interface/law.h) and the choice of a law from physical data
// (core/interface/classifier.h), against SPEC §1.2–§1.3, §2.2 and the reference tables
// reference/table1.csv and reference/table2.csv (read through core/io/reference_tables.h,
// the independent source of Tables 1 and 2).
//
// Every expected stress below is worked out by hand in a comment from the law of SPEC §1.2:
//   σ_N = −K_N [u]_N⁺,  K_N = λ̄ + 2μ̄;   trial σ_T = −K_T [u]_T, K_T = μ̄;
//   |trial| ≤ f|σ_N| → σ_T = trial (stick), else σ_T = −f|σ_N| sign([u]_T) (slide).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/interface/classifier.h"
#include "core/interface/law.h"
#include "core/io/csv_table.h"
#include "core/io/reference_tables.h"

namespace thinlayer {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A finite (d) law of the bar's size: λ̄ = 450, μ̄ = 540 daN/mm³, so K_N = 450 + 2·540 = 1530
// and K_T = 540; friction f = 0.5.
InterfaceLaw law_d() { return InterfaceLaw::make(450, 540, 0.5); }

// ---------------------------------------------------------------------------------------------
// local_stress: the finite laws.

TEST(LocalStress, OpeningGivesZeroStress) {
  // [u]_N < 0: a gap; no normal force, hence a zero friction threshold and σ_T = 0 even for a
  // tangential jump.
  const LocalStress s = local_stress(law_d(), -1e-3, 2e-3);
  EXPECT_EQ(s.sigma_N, 0.0);
  EXPECT_EQ(s.sigma_T, 0.0);
}

TEST(LocalStress, ZeroNormalJumpIsGap) {
  // [u]_N = 0 is still a gap ([u]_N ≤ 0, SPEC §1.2): σ_N = 0 and σ_T = 0.
  const LocalStress s = local_stress(law_d(), 0.0, 2e-3);
  EXPECT_EQ(s.sigma_N, 0.0);
  EXPECT_EQ(s.sigma_T, 0.0);
}

TEST(LocalStress, ContactNormalStressIsMinusKNTimesPenetration) {
  // [u]_N = 2e-3 mm: σ_N = −1530 · 2e-3 = −3.06 daN/mm².
  const LocalStress s = local_stress(law_d(), 2e-3, 0.0);
  EXPECT_DOUBLE_EQ(s.sigma_N, -3.06);
  EXPECT_EQ(s.sigma_T, 0.0);
}

TEST(LocalStress, StickBelowThresholdIsTheTangentialSpring) {
  // [u]_N = 2e-3: σ_N = −3.06, threshold f|σ_N| = 1.53. [u]_T = ±1e-3: trial = ∓540e-3 = ∓0.54,
  // below the threshold: σ_T = ∓0.54.
  const LocalStress plus = local_stress(law_d(), 2e-3, 1e-3);
  EXPECT_DOUBLE_EQ(plus.sigma_N, -3.06);
  EXPECT_DOUBLE_EQ(plus.sigma_T, -0.54);
  const LocalStress minus = local_stress(law_d(), 2e-3, -1e-3);
  EXPECT_DOUBLE_EQ(minus.sigma_T, 0.54);
}

TEST(LocalStress, SlideAboveThresholdIsCoulomb) {
  // [u]_N = 2e-3: threshold 1.53. [u]_T = ±1e-2: trial = ∓5.4, above it:
  // σ_T = −f|σ_N| sign([u]_T) = ∓1.53.
  const LocalStress plus = local_stress(law_d(), 2e-3, 1e-2);
  EXPECT_DOUBLE_EQ(plus.sigma_N, -3.06);
  EXPECT_DOUBLE_EQ(plus.sigma_T, -1.53);
  const LocalStress minus = local_stress(law_d(), 2e-3, -1e-2);
  EXPECT_DOUBLE_EQ(minus.sigma_T, 1.53);
}

TEST(LocalStress, FrictionBoundHoldsOverASweepOfJumps) {
  // |σ_T| ≤ f|σ_N| and σ_N ≤ 0 for every jump; σ_T opposes [u]_T.
  const InterfaceLaw law = law_d();
  for (double jn = -2e-3; jn <= 4e-3; jn += 2.5e-4)
    for (double jt = -2e-2; jt <= 2e-2; jt += 1.3e-3) {
      const LocalStress s = local_stress(law, jn, jt);
      EXPECT_LE(s.sigma_N, 0.0);
      EXPECT_LE(std::abs(s.sigma_T), law.friction * std::abs(s.sigma_N) * (1 + 1e-15)) << jn << " " << jt;
      EXPECT_LE(s.sigma_T * jt, 0.0);
    }
}

TEST(LocalStress, CaseBNormalStiffnessIsTwoMu) {
  // (b): λ̄ = 0, μ̄ = 540: K_N = 2μ̄ = 1080 (eq. 43), so [u]_N = 1e-3 gives σ_N = −1.08.
  const InterfaceLaw law = InterfaceLaw::make(0, 540, 0.5);
  ASSERT_EQ(law.table1_case(), 'b');
  EXPECT_DOUBLE_EQ(law.K_N(), 1080.0);
  EXPECT_DOUBLE_EQ(local_stress(law, 1e-3, 0).sigma_N, -1.08);
  // and the tangential spring is μ̄: [u]_T = 1e-3 → trial −0.54, |−0.54| = 0.54 = f|σ_N| is at
  // the threshold, where stick and slide give the same σ_T = −0.54.
  EXPECT_DOUBLE_EQ(local_stress(law, 1e-3, 1e-3).sigma_T, -0.54);
}

TEST(LocalStress, CaseCHasNoTangentialStress) {
  // (c): μ̄ = 0: σ_N = −λ̄ [u]_N⁺ = −450 · 2e-3 = −0.9, σ_T = 0 whatever [u]_T.
  const InterfaceLaw law = InterfaceLaw::make(450, 0, 0.5);
  ASSERT_EQ(law.table1_case(), 'c');
  const LocalStress s = local_stress(law, 2e-3, 1e-2);
  EXPECT_DOUBLE_EQ(s.sigma_N, -0.9);
  EXPECT_EQ(s.sigma_T, 0.0);
}

TEST(LocalStress, CaseAIsStressFree) {
  // (a): λ̄ = μ̄ = 0: σ = 0 whatever the jump, interpenetration included.
  const InterfaceLaw law = InterfaceLaw::make(0, 0, 0.5);
  ASSERT_EQ(law.table1_case(), 'a');
  for (auto [jn, jt] : std::vector<std::pair<double, double>>{{1.0, 1.0}, {-1.0, 0.3}, {5e-3, -2.0}}) {
    const LocalStress s = local_stress(law, jn, jt);
    EXPECT_EQ(s.sigma_N, 0.0);
    EXPECT_EQ(s.sigma_T, 0.0);
  }
}

TEST(LocalStress, ZeroFrictionGivesNoTangentialStress) {
  const InterfaceLaw law = InterfaceLaw::make(450, 540, 0.0);
  const LocalStress s = local_stress(law, 2e-3, 1e-3);
  EXPECT_DOUBLE_EQ(s.sigma_N, -3.06);
  EXPECT_EQ(s.sigma_T, 0.0);
}

TEST(LocalStress, ThrowsForRigidLaws) {
  // K_N = ∞ (λ̄ = ∞ or μ̄ = ∞) or K_T = ∞ (μ̄ = ∞): the stress is set-valued.
  for (auto [l, m] : std::vector<std::pair<double, double>>{
           {kInf, 0}, {kInf, 540}, {kInf, kInf}, {450, kInf}, {0, kInf}}) {
    const InterfaceLaw law = InterfaceLaw::make(l, m, 0.5);
    EXPECT_THROW(local_stress(law, 1e-3, 1e-3), std::invalid_argument)
        << "case " << law.table1_case();
  }
}

// (d) → Signorini–Coulomb as λ̄, μ̄ → ∞ (scaled together by s). For a fixed stress state,
// σ_N = −p (p = 10) and |σ_T| = τ = 2 < f p = 5 (stick), the jump that carries it is
// [u]_N = p/K_N and [u]_T = −σ_T/K_T, both → 0 like 1/s: in the limit, contact without
// penetration and stick without slip.
TEST(LocalStress, CaseDJumpForGivenStressVanishesLikeOneOverStiffness) {
  const double p = 10, tau = 2;
  double previous_jn = kInf;
  for (double s : {1.0, 1e2, 1e4, 1e6, 1e8}) {
    const InterfaceLaw law = InterfaceLaw::make(450 * s, 540 * s, 0.5);
    ASSERT_EQ(law.table1_case(), 'd');
    const double jn = p / law.K_N(), jt = -tau / law.K_T();
    const LocalStress st = local_stress(law, jn, jt);
    EXPECT_NEAR(st.sigma_N, -p, 1e-13 * p) << "s = " << s;
    EXPECT_NEAR(st.sigma_T, tau, 1e-13 * p) << "s = " << s;
    // 1/K_N = 1/(1530 s): the penetration is 10/(1530 s) ≤ 6.6e-3/s.
    EXPECT_LE(jn, 6.6e-3 / s);
    if (std::isfinite(previous_jn)) {
      EXPECT_NEAR(previous_jn / jn, 100.0, 1e-9);
    }
    previous_jn = jn;
  }
}

// ... and for a fixed small slip [u]_T = 1e-6 mm under the same σ_N = −p = −10 (f p = 5), the
// tangential stress is the spring's −540 s · 1e-6 while that is below 5 (s < 5/5.4e-4 ≈ 9259),
// then the Coulomb value −f|σ_N| = −5: any slip, however small, mobilises full friction in
// the limit.
TEST(LocalStress, CaseDSmallSlipMobilisesFullFrictionInTheLimit) {
  const double p = 10, slip = 1e-6;
  for (double s : {1.0, 1e2, 1e3}) {
    const InterfaceLaw law = InterfaceLaw::make(450 * s, 540 * s, 0.5);
    EXPECT_NEAR(local_stress(law, p / law.K_N(), slip).sigma_T, -540 * s * slip, 1e-12) << "s = " << s;
  }
  for (double s : {1e4, 1e6, 1e8}) {
    const InterfaceLaw law = InterfaceLaw::make(450 * s, 540 * s, 0.5);
    EXPECT_NEAR(local_stress(law, p / law.K_N(), slip).sigma_T, -5.0, 1e-12) << "s = " << s;
  }
}

// ---------------------------------------------------------------------------------------------
// Compliances and activity flags.

TEST(InterfaceLaw, CompliancesOfZeroAndRigidLaws) {
  const InterfaceLaw free_law = InterfaceLaw::make(0, 0, 0.5);
  EXPECT_EQ(free_law.compliance_N(), kInf);
  EXPECT_EQ(free_law.compliance_T(), kInf);
  const InterfaceLaw rigid = InterfaceLaw::make(kInf, kInf, 0.5);
  EXPECT_EQ(rigid.compliance_N(), 0.0);
  EXPECT_EQ(rigid.compliance_T(), 0.0);
  // (d): 1/1530 and 1/540.
  EXPECT_DOUBLE_EQ(law_d().compliance_N(), 1.0 / 1530);
  EXPECT_DOUBLE_EQ(law_d().compliance_T(), 1.0 / 540);
}

TEST(InterfaceLaw, ActivityFlags) {
  EXPECT_FALSE(InterfaceLaw::make(0, 0, 0.5).normal_active());        // (a)
  EXPECT_FALSE(InterfaceLaw::make(0, 0, 0.5).tangential_active());
  EXPECT_TRUE(InterfaceLaw::make(450, 0, 0.5).normal_active());       // (c)
  EXPECT_FALSE(InterfaceLaw::make(450, 0, 0.5).tangential_active());
  EXPECT_TRUE(InterfaceLaw::make(0, 540, 0.5).normal_active());       // (b): K_N = 2μ̄ > 0
  EXPECT_TRUE(InterfaceLaw::make(0, 540, 0.5).tangential_active());
  EXPECT_FALSE(InterfaceLaw::make(450, 540, 0.0).tangential_active()); // frictionless
  EXPECT_TRUE(InterfaceLaw::make(kInf, kInf, 1.0).tangential_active()); // (i)
}

// ---------------------------------------------------------------------------------------------
// InterfaceLaw::make validation.

TEST(InterfaceLawMake, RejectsNaN) {
  EXPECT_THROW(InterfaceLaw::make(kNaN, 1, 0.5), std::invalid_argument);
  EXPECT_THROW(InterfaceLaw::make(1, kNaN, 0.5), std::invalid_argument);
  EXPECT_THROW(InterfaceLaw::make(1, 1, kNaN), std::invalid_argument);
}

TEST(InterfaceLawMake, RejectsNegativeValues) {
  EXPECT_THROW(InterfaceLaw::make(-1, 1, 0.5), std::invalid_argument);
  EXPECT_THROW(InterfaceLaw::make(1, -1e-300, 0.5), std::invalid_argument);
  EXPECT_THROW(InterfaceLaw::make(1, 1, -0.1), std::invalid_argument);
  EXPECT_THROW(InterfaceLaw::make(-kInf, 1, 0.5), std::invalid_argument);
  EXPECT_THROW(InterfaceLaw::make(1, -kInf, 0.5), std::invalid_argument);
}

TEST(InterfaceLawMake, RejectsInfiniteFriction) {
  EXPECT_THROW(InterfaceLaw::make(1, 1, kInf), std::invalid_argument);
}

TEST(InterfaceLawMake, AcceptsInfiniteStiffnessAndZeroes) {
  const InterfaceLaw law = InterfaceLaw::make(kInf, kInf, 0.0);
  EXPECT_EQ(law.lambda_bar, kInf);
  EXPECT_EQ(law.mu_bar, kInf);
  EXPECT_EQ(law.friction, 0.0);
  const InterfaceLaw zero = InterfaceLaw::make(0, 0, 1.0);
  EXPECT_EQ(zero.lambda_bar, 0.0);
  EXPECT_EQ(zero.mu_bar, 0.0);
  const InterfaceLaw d = InterfaceLaw::make(4.5e2, 5.4e2, 1.0);
  EXPECT_EQ(d.lambda_bar, 4.5e2);
  EXPECT_EQ(d.mu_bar, 5.4e2);
  EXPECT_EQ(d.friction, 1.0);
}

TEST(LimitOf, ZeroFiniteInfinite) {
  EXPECT_EQ(limit_of(0.0), Limit::Zero);
  EXPECT_EQ(limit_of(-0.0), Limit::Zero);
  EXPECT_EQ(limit_of(1e-300), Limit::Finite);  // small is not zero: exact 0 only
  EXPECT_EQ(limit_of(1e300), Limit::Finite);   // large is not infinite: IEEE inf only
  EXPECT_EQ(limit_of(kInf), Limit::Infinite);
  EXPECT_STREQ(to_string(Limit::Zero), "0");
  EXPECT_STREQ(to_string(Limit::Finite), "finite");
  EXPECT_STREQ(to_string(Limit::Infinite), "inf");
}

// ---------------------------------------------------------------------------------------------
// Table 1.

// A representative value of each limit.
double value_of(const std::string& limit) {
  if (limit == "0") return 0.0;
  if (limit == "finite") return 3.7;
  if (limit == "inf") return kInf;
  throw std::runtime_error("unknown limit '" + limit + "'");
}

// The nine cells of SPEC §1.2's table, typed from it: rows μ̄ = 0, finite, ∞; columns
// λ̄ = ∞, finite, 0.
TEST(Table1, CaseLettersOfAllNineCombinations) {
  struct Cell { const char* lambda; const char* mu; char expected; };
  const std::vector<Cell> cells = {
      {"inf", "0", 'e'},      {"finite", "0", 'c'},      {"0", "0", 'a'},
      {"inf", "finite", 'f'}, {"finite", "finite", 'd'}, {"0", "finite", 'b'},
      {"inf", "inf", 'i'},    {"finite", "inf", 'h'},    {"0", "inf", 'g'}};
  for (const Cell& c : cells) {
    const InterfaceLaw law = InterfaceLaw::make(value_of(c.lambda), value_of(c.mu), 0.5);
    EXPECT_EQ(law.table1_case(), c.expected) << "lambda " << c.lambda << ", mu " << c.mu;
  }
}

TEST(Table1, ReferenceFileHasNineDistinctCasesAndCombinations) {
  const auto rows = load_table1();
  ASSERT_EQ(rows.size(), 9u);
  std::set<char> letters;
  std::set<std::pair<std::string, std::string>> combinations;
  for (const auto& r : rows) {
    letters.insert(r.law_case);
    combinations.insert({r.lambda_limit, r.mu_limit});
    for (const std::string& l : {r.lambda_limit, r.mu_limit})
      EXPECT_TRUE(l == "0" || l == "finite" || l == "inf") << "case " << r.law_case << ": '" << l << "'";
  }
  EXPECT_EQ(letters, (std::set<char>{'a', 'b', 'c', 'd', 'e', 'f', 'g', 'h', 'i'}));
  EXPECT_EQ(combinations.size(), 9u);
}

TEST(Table1, TableOneCaseAgreesWithReferenceFile) {
  for (const auto& r : load_table1()) {
    const InterfaceLaw law = InterfaceLaw::make(value_of(r.lambda_limit), value_of(r.mu_limit), 0.5);
    EXPECT_EQ(law.table1_case(), r.law_case) << "lambda " << r.lambda_limit << ", mu " << r.mu_limit;
  }
}

// The descriptive columns of table1.csv agree with K_N = λ̄ + 2μ̄, K_T = μ̄: "Signorini" exactly
// when K_N = ∞, "sigma_N = 0" exactly when K_N = 0, "Coulomb" exactly when K_T = ∞,
// "sigma_T = 0" exactly when K_T = 0; and the case (b) row names 2 mu_bar as its stiffness.
TEST(Table1, DescriptiveColumnsAgreeWithTheStiffnesses) {
  const CsvTable t = CsvTable::read(reference_dir() + "/table1.csv");
  ASSERT_EQ(t.rows(), 9);
  for (int i = 0; i < t.rows(); ++i) {
    const InterfaceLaw law =
        InterfaceLaw::make(value_of(t.text(i, "lambda_limit")), value_of(t.text(i, "mu_limit")), 0.5);
    const std::string normal = t.text(i, "normal_law"), tangential = t.text(i, "tangential_law");
    SCOPED_TRACE("case " + t.text(i, "case"));
    EXPECT_EQ(normal == "Signorini", std::isinf(law.K_N()));
    EXPECT_EQ(normal == "sigma_N = 0", law.K_N() == 0);
    EXPECT_EQ(tangential == "Coulomb", std::isinf(law.K_T()));
    EXPECT_EQ(tangential == "sigma_T = 0", law.K_T() == 0);
    if (t.text(i, "case") == "b") {
      EXPECT_NE(normal.find("2 mu_bar"), std::string::npos) << normal;
      EXPECT_EQ(normal.find("lambda"), std::string::npos) << normal;
      EXPECT_EQ(law.K_N(), 2 * law.mu_bar);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Table 2.

// lim_{ε→0} ε^e · c (c > 0): 0 if e > 0, c if e = 0, ∞ if e < 0.
double limit_of_power(double exponent, double c) {
  if (exponent > 0) return 0.0;
  if (exponent == 0) return c;
  return kInf;
}

TEST(Table2, ReferenceFileMatchesSpecCaseList) {
  // SPEC §2.2: (e) γ=.5 δ=1.5, (c) γ=1 δ=1.5, (a) γ=1.5 δ=1.5, (f) γ=.5 δ=1, (d) γ=1 δ=1,
  // (b) γ=1.5 δ=1, (i) γ=.5 δ=.5, (h) γ=1 δ=.5, (g) γ=1.5 δ=.5.
  const std::map<char, std::pair<double, double>> spec = {
      {'e', {0.5, 1.5}}, {'c', {1, 1.5}}, {'a', {1.5, 1.5}}, {'f', {0.5, 1}}, {'d', {1, 1}},
      {'b', {1.5, 1}},   {'i', {0.5, 0.5}}, {'h', {1, 0.5}}, {'g', {1.5, 0.5}}};
  const auto rows = load_table2();
  ASSERT_EQ(rows.size(), 9u);
  std::set<char> seen;
  for (const auto& r : rows) {
    ASSERT_TRUE(spec.count(r.law_case)) << r.law_case;
    EXPECT_TRUE(seen.insert(r.law_case).second) << "duplicate case " << r.law_case;
    EXPECT_EQ(r.gamma, spec.at(r.law_case).first) << "case " << r.law_case;
    EXPECT_EQ(r.delta, spec.at(r.law_case).second) << "case " << r.law_case;
  }
}

// λ_ε/ε = ε^(γ−1) λ_g and μ_ε/ε = ε^(δ−1) μ_g; their limits, through table1_case(), give
// the table's letter: Tables 1 and 2 are consistent.
TEST(Table2, LimitsOfTheScalingsGiveTheTableOneLetter) {
  const double lambda_g = 4500, mu_g = 5400;
  for (const auto& r : load_table2()) {
    const InterfaceLaw law = InterfaceLaw::make(limit_of_power(r.gamma - 1, lambda_g),
                                                limit_of_power(r.delta - 1, mu_g), 0.5);
    EXPECT_EQ(law.table1_case(), r.law_case) << "gamma " << r.gamma << ", delta " << r.delta;
  }
}

// Also through Table 1 as data: the limits of Table 2's scalings are the (lambda_limit,
// mu_limit) pair that table1.csv lists for the same letter.
TEST(Table2, LimitsMatchTableOneFileRowOfTheSameLetter) {
  auto name = [](double exponent) { return exponent > 0 ? "0" : exponent == 0 ? "finite" : "inf"; };
  std::map<char, Table1Row> table1;
  for (const auto& r : load_table1()) table1[r.law_case] = r;
  for (const auto& r : load_table2()) {
    ASSERT_TRUE(table1.count(r.law_case));
    EXPECT_EQ(table1[r.law_case].lambda_limit, name(r.gamma - 1)) << "case " << r.law_case;
    EXPECT_EQ(table1[r.law_case].mu_limit, name(r.delta - 1)) << "case " << r.law_case;
  }
}

// The §3.3 classifier at a small thickness recovers the same letters. With L = 1, λ_g = λ_m,
// μ_g = μ_m, the ratio to the reference is ε^(γ−1): at ε = 1e-8 that is 1e4 (> 30: ∞), 1 (finite)
// or 1e-4 (< 0.03: 0) for γ = 0.5, 1, 1.5 (likewise for δ).
TEST(Table2, ClassifierAtSmallThicknessGivesTheTableLetter) {
  const AdherentData adherent{4500, 5400, 1.0};
  const double eps = 1e-8;
  for (const auto& r : load_table2()) {
    const LayerData layer{eps, std::pow(eps, r.gamma) * adherent.lambda_m, std::pow(eps, r.delta) * adherent.mu_m};
    EXPECT_EQ(classify_layer(layer, adherent, 0.5).table1_case(), r.law_case)
        << "gamma " << r.gamma << ", delta " << r.delta;
  }
}

// ... but not at the thickest ε of the study: at ε = 1e-2 the ratios are 10, 1 and 0.1, all
// inside [0.03, 30], so every one of the nine cases is classified (d).
TEST(Table2, ClassifierAtThickestLayerSeesEveryCaseAsD) {
  const AdherentData adherent{4500, 5400, 1.0};
  const double eps = 1e-2;
  for (const auto& r : load_table2()) {
    const LayerData layer{eps, std::pow(eps, r.gamma) * adherent.lambda_m, std::pow(eps, r.delta) * adherent.mu_m};
    EXPECT_EQ(classify_layer(layer, adherent, 0.5).table1_case(), 'd')
        << "gamma " << r.gamma << ", delta " << r.delta;
  }
}

// ---------------------------------------------------------------------------------------------
// The classifier (SPEC §1.3, paper §3.3).

TEST(Classifier, BelowThreePercentIsZero) {
  EXPECT_EQ(classify_coefficient(2.0, 100.0), 0.0);      // 2 % of the reference
  EXPECT_EQ(classify_coefficient(0.0, 100.0), 0.0);
  EXPECT_EQ(classify_coefficient(1e-300, 100.0), 0.0);
}

TEST(Classifier, AboveThirtyTimesIsInfinite) {
  EXPECT_EQ(classify_coefficient(3100.0, 100.0), kInf);  // 31 × the reference
  EXPECT_EQ(classify_coefficient(1e300, 100.0), kInf);
}

TEST(Classifier, InBetweenIsTheRatioItself) {
  for (double ratio : {3.5, 50.0, 100.0, 2999.0}) EXPECT_EQ(classify_coefficient(ratio, 100.0), ratio);
}

// The implementation compares with strict inequalities (ratio < 0.03·ref → 0,
// ratio > 30·ref → ∞), so both thresholds themselves belong to the finite range. The
// thresholds are computed with the same products, 0.03·ref and 30·ref, so they are exact.
TEST(Classifier, ThresholdValuesThemselvesAreFinite) {
  const ClassifierThresholds t;
  for (double ref : {1.0, 112.5, 135.0, 4500.0}) {
    const double low = t.zero_below * ref, high = t.infinite_above * ref;
    EXPECT_EQ(classify_coefficient(low, ref), low) << "ref " << ref;
    EXPECT_EQ(classify_coefficient(high, ref), high) << "ref " << ref;
    EXPECT_EQ(classify_coefficient(std::nextafter(low, 0.0), ref), 0.0) << "ref " << ref;
    EXPECT_EQ(classify_coefficient(std::nextafter(high, kInf), ref), kInf) << "ref " << ref;
  }
}

TEST(Classifier, CustomThresholdsAreHonoured) {
  const ClassifierThresholds t{0.1, 10.0};
  EXPECT_EQ(classify_coefficient(5.0, 100.0, t), 0.0);     // 5 % < 10 %
  EXPECT_EQ(classify_coefficient(20.0, 100.0, t), 20.0);
  EXPECT_EQ(classify_coefficient(1100.0, 100.0, t), kInf); // 11× > 10×
}

TEST(Classifier, InvalidCoefficientInputsThrow) {
  EXPECT_THROW(classify_coefficient(kNaN, 100.0), std::invalid_argument);
  EXPECT_THROW(classify_coefficient(-1.0, 100.0), std::invalid_argument);
  EXPECT_THROW(classify_coefficient(kInf, 100.0), std::invalid_argument);
  EXPECT_THROW(classify_coefficient(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(classify_coefficient(1.0, -100.0), std::invalid_argument);
  EXPECT_THROW(classify_coefficient(1.0, kInf), std::invalid_argument);
  EXPECT_THROW(classify_coefficient(1.0, kNaN), std::invalid_argument);
}

TEST(Classifier, InvalidLayerInputsThrow) {
  const AdherentData bar{4500, 5400, 40.0};
  EXPECT_THROW(classify_layer({0.0, 1, 1}, bar, 1.0), std::invalid_argument);
  EXPECT_THROW(classify_layer({-1e-3, 1, 1}, bar, 1.0), std::invalid_argument);
  EXPECT_THROW(classify_layer({kNaN, 1, 1}, bar, 1.0), std::invalid_argument);
  EXPECT_THROW(classify_layer({kInf, 1, 1}, bar, 1.0), std::invalid_argument);
  EXPECT_THROW(classify_layer({1e-3, -1, 1}, bar, 1.0), std::invalid_argument);  // λ_ε < 0
  EXPECT_THROW(classify_layer({1e-3, 1, 1}, AdherentData{4500, 5400, 0.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(classify_layer({1e-3, 1, 1}, bar, -1.0), std::invalid_argument);   // f < 0
}

// The bar (SPEC §2.1): λ_m/L = 4500/40 = 112.5, μ_m/L = 5400/40 = 135 daN/mm³. A layer
// ε = 1e-3 mm with λ_ε = 0.45 (λ_ε/ε = 450 = 4 × 112.5: finite) and μ_ε = 5.4e-5
// (μ_ε/ε = 0.054 = 4e-4 × 135 < 3 %: zero) is law (c) with λ̄ = 450, μ̄ = 0.
TEST(Classifier, BarLayerExample) {
  const InterfaceLaw law = classify_layer({1e-3, 0.45, 5.4e-5}, {4500, 5400, 40.0}, 1.0);
  EXPECT_DOUBLE_EQ(law.lambda_bar, 450.0);
  EXPECT_EQ(law.mu_bar, 0.0);
  EXPECT_EQ(law.friction, 1.0);
  EXPECT_EQ(law.table1_case(), 'c');
}

}  // namespace
}  // namespace thinlayer
