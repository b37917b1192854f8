// The building blocks of the studies S2–S4: the rate fit, the distances between modes (with
// their zero-limit normalisation), the bisection, and the scene cache's identity of scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "studies/tools/bisection.h"
#include "studies/drivers/convergence_study.h"
#include "studies/tools/error_norms.h"
#include "studies/tools/mode_distance.h"
#include "studies/tools/rate_fit.h"
#include "studies/tools/scene_cache.h"

namespace thinlayer {
namespace {

// The thicknesses of the fits' tests, and e = floor + C εᵖ on them (exact: by hand, not by the fit).
const std::vector<double> fit_eps = {1e-2, 5e-3, 1e-3, 5e-4, 1e-4};

std::vector<double> power_law(double floor, double C, double p) {
  std::vector<double> e;
  for (double x : fit_eps) e.push_back(floor + C * std::pow(x, p));
  return e;
}

TEST(RateFit, RecoversAnExactPowerLaw) {
  const auto fit = fit_power_law(fit_eps, power_law(0, 3.0, 0.5));
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->p, 0.5, 1e-12);
  EXPECT_NEAR(fit->C, 3.0, 1e-10);
  EXPECT_NEAR(fit->p_stderr, 0.0, 1e-10);
  EXPECT_EQ(fit->points, 5);
}

TEST(RateFit, StandardErrorMatchesTheScatterOfTheSlope) {
  // Noise of known size on log e: the standard error must estimate the spread of p over
  // many samples (the textbook regression result), neither far smaller nor far larger.
  const std::vector<double>& eps = fit_eps;
  std::mt19937 rng(42);
  std::normal_distribution<double> noise(0.0, 0.1);
  double sum = 0, sum2 = 0, stderr_mean = 0;
  const int samples = 2000;
  for (int s = 0; s < samples; ++s) {
    std::vector<double> e;
    for (double x : eps) e.push_back(std::pow(x, 1.0) * std::exp(noise(rng)));
    const auto fit = fit_power_law(eps, e);
    ASSERT_TRUE(fit);
    sum += fit->p;
    sum2 += fit->p * fit->p;
    stderr_mean += fit->p_stderr / samples;
  }
  const double mean = sum / samples, spread = std::sqrt(sum2 / samples - mean * mean);
  EXPECT_NEAR(mean, 1.0, 0.01);
  EXPECT_NEAR(stderr_mean / spread, 1.0, 0.2);  // E[s] is a little below σ for 3 degrees of freedom
}

TEST(RateFit, SkipsZerosAndNeedsThreePoints) {
  EXPECT_FALSE(fit_power_law({1e-2, 1e-3, 1e-4}, {1e-1, 0.0, 1e-3}));  // two usable points
  const auto fit = fit_power_law({1e-2, 1e-3, 1e-4, 1e-5}, {1e-2, 0.0, 1e-4, 1e-5});
  ASSERT_TRUE(fit);
  EXPECT_EQ(fit->points, 3);
  EXPECT_NEAR(fit->p, 1.0, 1e-12);
  EXPECT_THROW(fit_power_law({1e-2, 1e-3}, {1.0}), std::invalid_argument);
  EXPECT_THROW(fit_power_law({1e-2, -1e-3, 1e-4}, {1, 1, 1}), std::invalid_argument);
}

TEST(ErrorNorms, RelativeToTheReferenceWhereItIsLarge) {
  const Eigen::VectorXd b = Eigen::VectorXd::Constant(4, 2.0), a = Eigen::VectorXd::Constant(4, 2.2);
  const Eigen::VectorXd w = Eigen::VectorXd::Constant(4, 0.5);
  EXPECT_NEAR(relative_distance(a, b, w, 1e-3), 0.1, 1e-14);
}

TEST(ErrorNorms, ZeroLimitFieldIsMeasuredAgainstTheScale) {
  // Case (a): the limit stress is zero; the layer's is small. Relative to zero the distance
  // would be infinite; against the scale it is the layer's stress over the scale.
  const Eigen::VectorXd b = Eigen::VectorXd::Zero(3), a = Eigen::VectorXd::Constant(3, 0.01);
  const Eigen::VectorXd w = Eigen::VectorXd::Ones(3);
  EXPECT_NEAR(relative_distance(a, b, w, 2.0), 0.005, 1e-15);
  EXPECT_EQ(relative_distance(b, b, w, 2.0), 0.0);
}

TEST(ErrorNorms, WeightsAreTributaryLengths) {
  // A node with twice the length counts twice.
  Eigen::VectorXd a(2), b(2), w(2);
  a << 1, 0;
  b << 0, 0;
  w << 2, 1;
  EXPECT_NEAR(weighted_norm(a - b, w), std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(relative_distance(a, b, w, 1.0), std::sqrt(2.0) / std::sqrt(3.0), 1e-15);
}

TEST(ErrorNorms, RejectsBadInput) {
  const Eigen::VectorXd v = Eigen::VectorXd::Ones(3);
  EXPECT_THROW(relative_distance(v, Eigen::VectorXd::Ones(2), v, 1.0), std::invalid_argument);
  EXPECT_THROW(relative_distance(v, v, v, 0.0), std::invalid_argument);
  EXPECT_THROW(relative_distance(v, v, -v, 1.0), std::invalid_argument);
}

TEST(Bisection, FindsTheCrossingOfAPowerLaw) {
  // e(ε) = 10 ε^0.5 crosses τ = 0.1 at ε = 1e-4; 30 halvings of log ε from [1e-5, 1e-2].
  int calls = 0;
  auto e = [&](double eps) {
    ++calls;
    return 10 * std::sqrt(eps);
  };
  const Bracket b = bisect_log(e, {1e-5, e(1e-5), 1e-2, e(1e-2)}, 0.1, 30);
  EXPECT_EQ(calls, 32);
  EXPECT_LE(b.error_within, 0.1);
  EXPECT_GT(b.error_beyond, 0.1);
  EXPECT_NEAR(std::log(b.eps_within / 1e-4), 0.0, 1e-6);
  EXPECT_LT(b.eps_within, b.eps_beyond);
}

TEST(Bisection, EachStepHalvesTheLogBracket) {
  auto e = [](double eps) { return eps; };
  const Bracket b = bisect_log(e, {1e-4, 1e-4, 1e-2, 1e-2}, 5e-3, 2);
  EXPECT_NEAR(std::log10(b.eps_beyond / b.eps_within), 0.5, 1e-12);
}

TEST(Bisection, RejectsABracketThatDoesNotBracket) {
  auto e = [](double eps) { return eps; };
  EXPECT_THROW(bisect_log(e, {1e-4, 1e-4, 1e-2, 1e-2}, 1.0, 3), std::invalid_argument);
  EXPECT_THROW(bisect_log(e, {0.0, 0.0, 1e-2, 1e-2}, 1e-3, 3), std::invalid_argument);
}

TEST(SceneCache, DefinitionsDifferInEveryField) {
  const dovetail::MeshOptions mesh;
  const std::string base = layer_scene('d', 1e-3, 1e-8).definition(mesh);
  EXPECT_NE(base, layer_scene('e', 1e-3, 1e-8).definition(mesh));
  EXPECT_NE(base, layer_scene('d', 5e-4, 1e-8).definition(mesh));
  EXPECT_NE(base, layer_scene('d', 1e-3, 1e-10).definition(mesh));
  EXPECT_NE(base, limit_scene('d', 1e-8).definition(mesh));
  EXPECT_NE(base, layer_scene('d', 1e-3, 1e-8).definition(dovetail::MeshOptions{0.05, 0.1, 2}));
  EXPECT_EQ(base, layer_scene('d', 1e-3, 1e-8).definition(mesh));
  DovetailSceneDef control = layer_scene('d', 1e-3, 1e-8);
  control.quadrature = LayerQuadrature::Full;
  EXPECT_NE(base, control.definition(mesh));
  control = layer_scene('d', 1e-3, 1e-8);
  control.selection = LayerSelection::PlusFace;
  EXPECT_NE(base, control.definition(mesh));
  EXPECT_NE(definition_hash(base), definition_hash(layer_scene('d', 5e-4, 1e-8).definition(mesh)));
  // FNV-1a of the empty string is its offset basis: the hash is the standard one, stable across runs.
  EXPECT_EQ(definition_hash(""), 14695981039346656037ull);
  EXPECT_EQ(definition_hash("a"), 0xaf63dc4c8601ec8cull);
}

DovetailLimitBulk& coarse_bulk() {
  static DovetailLimitBulk bulk(dovetail::MeshOptions{0.05, 0.2, 2});
  return bulk;
}

TEST(SceneCache, SolvesEachSceneOnce) {
  DovetailSceneCache cache(coarse_bulk(), 2, false, "test");
  cache.solve({limit_scene('d', 1e-10), layer_scene('d', 1e-2, 1e-8), layer_scene('b', 1e-2, 1e-8),
               layer_scene('d', 1e-2, 1e-8)});
  EXPECT_EQ(cache.solves(), 3);
  EXPECT_EQ(cache.reuses(), 1);
  const DovetailScene& s = cache.get(layer_scene('d', 1e-2, 1e-8));
  EXPECT_EQ(cache.solves(), 3);
  EXPECT_EQ(cache.reuses(), 2);
  EXPECT_TRUE(s.report.converged);
  EXPECT_NE(s.record.id.find("tol1e-08"), std::string::npos) << s.record.id;
}

TEST(ModeDistance, ASceneIsAtDistanceZeroFromItselfAndItsJumpsAreTheStoredOnes) {
  DovetailSceneCache cache(coarse_bulk(), 1, false, "test");
  const DovetailScene& limit = cache.get(limit_scene('d', 1e-10));
  const DovetailNodes nodes = dovetail_nodes(coarse_bulk());
  const ModeDistance self = mode_distance(limit.record, limit.record, nodes);
  for (const std::string& q : distance_quantities()) EXPECT_EQ(self.e.at(q), 0.0) << q;
  EXPECT_EQ(self.status_diff, 0);
  // The distance recomputes the limit's jumps from the adherents' displacements: against a
  // record whose stored jumps are zeroed, the jump distances are those stored jumps' size.
  SceneRecord zeroed = limit.record;
  zeroed.interfaces[0].jump_N.setZero();
  zeroed.interfaces[0].sigma_N.setZero();
  const ModeDistance d = mode_distance(limit.record, zeroed, nodes);
  EXPECT_EQ(d.e.at("jump_N"), 0.0);  // jumps come from u, identical in both records
  EXPECT_GT(d.e.at("sigma_N"), 0.0);
}

TEST(ModeDistance, TheReactionIsRelativeToTheLargerOfItsSizeAndTheLoadsScale) {
  DovetailSceneCache cache(coarse_bulk(), 1, false, "test");
  const SceneRecord& limit = cache.get(limit_scene('d', 1e-10)).record;
  const DovetailNodes nodes = dovetail_nodes(coarse_bulk());
  const Eigen::Vector2d R = limit.reactions.at("tenon_top");
  // R_ref = σ_ref × the top edge: the stress of an adherent strained by U/L over 0.8 L.
  const double R_ref = dovetail::mu_m * std::hypot(dovetail::pull_x, dovetail::pull_y) * 0.8;
  ASSERT_GT(R.norm(), 0.1);  // case (d) holds the pull, with less than R_ref: the glue is soft
  ASSERT_LT(R.norm(), R_ref);
  SceneRecord moved = limit;
  moved.reactions["tenon_top"] = R + Eigen::Vector2d(0.01, 0);
  EXPECT_NEAR(mode_distance(moved, limit, nodes).e.at("R_top"), 0.01 / R_ref, 1e-14);
  // Against a reference reaction larger than R_ref, relative to that reaction.
  SceneRecord big = limit;
  big.reactions["tenon_top"] = Eigen::Vector2d(0, 100 * R_ref);
  SceneRecord big_moved = big;
  big_moved.reactions["tenon_top"] += Eigen::Vector2d(R_ref, 0);
  EXPECT_NEAR(mode_distance(big_moved, big, nodes).e.at("R_top"), 0.01, 1e-14);
}

TEST(ModeDistance, LayerApproachesLimitAsEpsShrinks) {
  // Case (d) has finite limits: the distance must shrink between ε = 1e-2 and 1e-3.
  DovetailSceneCache cache(coarse_bulk(), 2, false, "test");
  cache.solve({limit_scene('d', 1e-10), layer_scene('d', 1e-2, 1e-8), layer_scene('d', 1e-3, 1e-8)});
  const DovetailNodes nodes = dovetail_nodes(coarse_bulk());
  const SceneRecord& limit = cache.get(limit_scene('d', 1e-10)).record;
  const double e2 = mode_distance(cache.get(layer_scene('d', 1e-2, 1e-8)).record, limit, nodes).e.at("u");
  const double e3 = mode_distance(cache.get(layer_scene('d', 1e-3, 1e-8)).record, limit, nodes).e.at("u");
  EXPECT_LT(e3, e2);
  EXPECT_GT(e2, 0.0);
}

TEST(ModeDistance, CornerDistance) {
  EXPECT_NEAR(distance_to_slot_corner({0.4, 0.0}), 0.0, 1e-15);
  EXPECT_NEAR(distance_to_slot_corner({0.0, -0.5}), 0.6, 1e-15);
}

}  // namespace
}  // namespace thinlayer

namespace thinlayer {
namespace {

TEST(RateFitWithFloor, RecoversRateAndFloor) {
  const std::vector<double> e = power_law(4e-4, 0.15, 1.0);
  const auto fit = fit_power_law_with_floor(fit_eps, e);
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->p, 1.0, 1e-4);
  EXPECT_NEAR(fit->floor, 4e-4, 1e-8);
  EXPECT_NEAR(fit->C, 0.15, 1e-4);
  // The plain power law sees the floor as a slower rate.
  EXPECT_LT(fit_power_law(fit_eps, e)->p, 0.7);
}

TEST(RateFitWithFloor, WithoutAFloorItIsThePowerLaw) {
  const auto fit = fit_power_law_with_floor(fit_eps, power_law(0, 0.3, 0.5));
  ASSERT_TRUE(fit);
  EXPECT_NEAR(fit->p, 0.5, 1e-4);
  EXPECT_NEAR(fit->floor, 0.0, 1e-9);
  EXPECT_FALSE(fit_power_law_with_floor({1e-2, 1e-3, 1e-4}, {1, 2, 3}));  // 3 points, 3 parameters
}

}  // namespace
}  // namespace thinlayer
