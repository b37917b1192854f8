// Bonded faces and the glue (SPEC §1.6, §1.3, §5): the bilateral law's natural map and statuses,
// the limit law of each combination of faces, and an engineer's glue (E, ν ↔ Lamé; its own finite
// law at its thickness, and what the §3.3 classification would choose instead). Every expected value is computed by hand here.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/interface/glue.h"
#include "core/solvers/contact_problem.h"

using namespace thinlayer;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

TEST(BilateralLaw, NaturalMapVanishesForEitherSignOfTheForce) {
  const InterfaceLaw law = InterfaceLaw::make_bilateral(450, 540);
  const Eigen::Vector2d kappa(1e4, 2e4), zero = Eigen::Vector2d::Zero();
  // d = 0: satisfied, in tension (r_N > 0) as in compression.
  EXPECT_EQ(natural_map(law, Eigen::Vector2d(3.0, -2.0), zero, kappa), zero);
  EXPECT_EQ(natural_map(law, Eigen::Vector2d(-3.0, 2.0), zero, kappa), zero);
  // d ≠ 0: the force κ d per row, whatever r (no stop, no skidding block).
  const Eigen::Vector2d d(1e-5, -2e-5);
  const Eigen::Vector2d R = natural_map(law, Eigen::Vector2d(5.0, 0.0), d, kappa);
  EXPECT_DOUBLE_EQ(R[0], 1e4 * 1e-5);
  EXPECT_DOUBLE_EQ(R[1], 2e4 * -2e-5);
  // The same state under the unilateral law with the same stiffnesses: a tension violates it.
  const InterfaceLaw contact = InterfaceLaw::make(450, 540, 0.5);
  EXPECT_GT(natural_map(contact, Eigen::Vector2d(3.0, 0.0), zero, kappa).norm(), 0);
}

TEST(BilateralLaw, ZeroComponentCarriesNoStressInfiniteOneAllowsNoJump) {
  const Eigen::Vector2d kappa(1e4, 1e4);
  // K_T = μ̄ = 0: the tangential row must carry no force.
  const InterfaceLaw c = InterfaceLaw::make_bilateral(450, 0);
  EXPECT_DOUBLE_EQ(natural_map(c, Eigen::Vector2d(0.0, 2.0), Eigen::Vector2d::Zero(), kappa)[1], 2.0);
  // K = ∞ (a tie): local_stress refuses (set-valued), and the law's compliance is exactly 0.
  const InterfaceLaw tie = InterfaceLaw::tie();
  EXPECT_TRUE(tie.bilateral);
  EXPECT_EQ(tie.compliance_N(), 0.0);
  EXPECT_EQ(tie.compliance_T(), 0.0);
  EXPECT_EQ(tie.table1_case(), 'i');
  EXPECT_THROW(local_stress(tie, 1e-3, 0), std::invalid_argument);
}

TEST(BilateralLaw, LocalStressIsTheSpringForEitherSign) {
  const InterfaceLaw law = InterfaceLaw::make_bilateral(450, 540);  // K_N = 1530, K_T = 540
  const LocalStress opening = local_stress(law, -1e-3, 2e-3);
  EXPECT_DOUBLE_EQ(opening.sigma_N, 1530 * 1e-3);  // tension, carried
  EXPECT_DOUBLE_EQ(opening.sigma_T, -540 * 2e-3);
  const LocalStress contact = local_stress(InterfaceLaw::make(450, 540, 0.5), -1e-3, 2e-3);
  EXPECT_EQ(contact.sigma_N, 0.0);  // the unilateral law opens
  EXPECT_EQ(contact.sigma_T, 0.0);
}

TEST(BilateralLaw, StatusesStickWhenLoadedGapWhenNot) {
  const std::vector<InterfaceLaw> laws(4, InterfaceLaw::make_bilateral(450, 540));
  Eigen::VectorXd sigma_N(4), sigma_T(4);
  sigma_N << 2.0, -1.0, 0.0, 0.0;  // tension, compression, pure shear, nothing
  sigma_T << 0.0, 5.0, 3.0, 1e-12;
  const auto s = classify_statuses(laws, sigma_N, sigma_T, 1e-6);
  EXPECT_EQ(s[0], NodeStatus::Stick);  // a tension is not a gap
  EXPECT_EQ(s[1], NodeStatus::Stick);  // |σ_T| > f|σ_N| is no slide for a bonded node
  EXPECT_EQ(s[2], NodeStatus::Stick);  // shear alone is a load (the scale includes |σ_T|)
  EXPECT_EQ(s[3], NodeStatus::Gap);    // 1e-12 of the largest stress: carries nothing
}

TEST(LayerFaces, LimitLawOfEachCombination) {
  const LayerFaces both{FaceHold::Bonded, FaceHold::Bonded}, one{FaceHold::Bonded, FaceHold::Contact},
      other{FaceHold::Contact, FaceHold::Bonded}, none{};
  EXPECT_TRUE(layer_limit_law(450, 540, both, 0.5).bilateral);
  EXPECT_EQ(layer_limit_law(450, 540, both, 0.5).friction, 0.0);
  for (const LayerFaces& f : {one, other, none}) {  // the contact on one face or two: Table 1's law
    const InterfaceLaw law = layer_limit_law(450, 540, f, 0.5);
    EXPECT_FALSE(law.bilateral);
    EXPECT_EQ(law.friction, 0.5);
    EXPECT_EQ(law.table1_case(), 'd');
  }
  EXPECT_TRUE(face_law(FaceHold::Bonded, 0.5).bilateral);
  EXPECT_TRUE(std::isinf(face_law(FaceHold::Bonded, 0.5).K_N()));
  EXPECT_FALSE(face_law(FaceHold::Contact, 0.5).bilateral);
  EXPECT_TRUE(std::isinf(face_law(FaceHold::Contact, 0.5).K_T()));
}

// E, ν ↔ Lamé by the 3D relations, checked both ways: epoxy E = 3000 MPa, ν = 0.35 gives
// λ = 3000·0.35/(1.35·0.3) = 2592.592… and μ = 3000/2.7 = 1111.111…; back, E = μ(3λ + 2μ)/(λ + μ)
// and ν = λ/(2(λ + μ)).
TEST(Glue, YoungAndPoissonToLameAndBack) {
  const LameModuli m = lame_from_young(3000, 0.35);
  EXPECT_NEAR(m.lambda, 3000 * 0.35 / (1.35 * 0.3), 1e-9);
  EXPECT_NEAR(m.mu, 3000 / 2.7, 1e-9);
  EXPECT_NEAR(m.mu * (3 * m.lambda + 2 * m.mu) / (m.lambda + m.mu), 3000, 1e-9);
  EXPECT_NEAR(m.lambda / (2 * (m.lambda + m.mu)), 0.35, 1e-14);
  EXPECT_THROW(lame_from_young(3000, 0.5), std::invalid_argument);
  EXPECT_THROW(lame_from_young(-1, 0.3), std::invalid_argument);
}

// An engineer's glue keeps its moduli at every thickness; its limit law is its own finite springs
// at that thickness, λ̄ = λ_g/t, μ̄ = μ_g/t (SPEC §1.3), never a 0 or ∞ cut-off. The paper's 3 % /
// 30x rule is what classified_law() says it would choose: λ_g/t, μ_g/t against λ_m/L, μ_m/L.
TEST(Glue, EngineersGlueKeepsItsFiniteLawAtEveryThickness) {
  const Glue g = Glue::engineer(3000, 0.35, 0.2);
  const LameModuli m = lame_from_young(3000, 0.35);
  EXPECT_EQ(g.at(0.2).lambda, m.lambda);
  EXPECT_EQ(g.at(0.002).mu, m.mu);  // the same glue thinner, not a softer one
  const AdherentData aluminium{51083.0, 26316.0, 1.5};  // λ_m/L = 34055, μ_m/L = 17544 MPa/mm
  const LayerFaces bonded{FaceHold::Bonded, FaceHold::Bonded};
  for (double t : {0.2, 0.002, 200.0}) {
    const InterfaceLaw law = g.limit_law(t, aluminium, bonded, 0.0);
    EXPECT_TRUE(law.bilateral);
    EXPECT_NEAR(law.lambda_bar, m.lambda / t, 1e-12 * m.lambda / t) << "t " << t;
    EXPECT_NEAR(law.mu_bar, m.mu / t, 1e-12 * m.mu / t) << "t " << t;
    EXPECT_NEAR(law.K_N(), (m.lambda + 2 * m.mu) / t, 1e-12 * m.lambda / t);
    EXPECT_EQ(law.table1_case(), 'd') << "t " << t;
  }
  // t = 0.2: λ_g/t = 12963 (0.38 of the reference), μ_g/t = 5556 (0.32): the rule keeps both.
  const InterfaceLaw rule_02 = g.classified_law(0.2, aluminium, bonded, 0.0);
  EXPECT_NEAR(rule_02.lambda_bar, m.lambda / 0.2, 1e-9);
  EXPECT_NEAR(rule_02.mu_bar, m.mu / 0.2, 1e-9);
  // t = 0.002: λ_g/t = 1.30e6, 38 times the reference; μ_g/t = 5.56e5, 31.7 times: the rule says ∞.
  const InterfaceLaw rule_0002 = g.classified_law(0.002, aluminium, bonded, 0.0);
  EXPECT_TRUE(std::isinf(rule_0002.lambda_bar));
  EXPECT_TRUE(std::isinf(rule_0002.mu_bar));
  // t = 200 mm: μ_g/t = 5.56, 3.2e-4 of the reference: the rule says 0.
  EXPECT_EQ(g.classified_law(200, aluminium, bonded, 0.0).mu_bar, 0.0);
  // The paper's family: classified_law is its Table 1 law.
  const Glue paper = Glue::scaled(1, 1.5, 4500, 5400);
  EXPECT_EQ(paper.classified_law(1e-3, aluminium, LayerFaces{}, 0.5).table1_case(), 'c');
  EXPECT_EQ(paper.limit_law(1e-3, aluminium, LayerFaces{}, 0.5).table1_case(), 'c');
}

// The paper's family: λ_ε = ε^γ λ_g, μ_ε = ε^δ μ_g; the limit law Table 1's whatever ε.
TEST(Glue, ScaledFamilyAndItsTableOneLimit) {
  const Glue g = Glue::scaled(1, 0.5, 4500, 5400);
  EXPECT_NEAR(g.at(1e-4).lambda, 1e-4 * 4500, 1e-15);
  EXPECT_NEAR(g.at(1e-4).mu, 1e-2 * 5400, 1e-12);
  const InterfaceLaw law = g.limit_law(1e-4, AdherentData{4500, 5400, 1}, LayerFaces{}, 0.5);
  EXPECT_EQ(law.lambda_bar, 4500);
  EXPECT_TRUE(std::isinf(law.mu_bar));  // δ < 1
  EXPECT_EQ(law.table1_case(), 'h');
  EXPECT_EQ(Glue::scaled(0.5, 1, 0, 5400).limit_law(1, AdherentData{}, LayerFaces{}, 0.5).lambda_bar, 0.0);  // λ_g = 0
  EXPECT_THROW(Glue::scaled(1, 2, 1, 1), std::invalid_argument);
}
