// The verdict on what breaks joints (issue 35, item 2; SPEC §3 S3): the validity study of a scene
// file judges the limit law per quantity — the reactions, the adherents' displacements, and the peak
// peel and peak shear at a stated distance d from each bondline end — one verdict per quantity and
// τ; the corner itself is singular in the layer model: its value grows under mesh refinement while
// the value at d converges. Expected values by hand (interpolation, the reactions' norm) or by the
// physics (a singular corner grows, a regular point converges).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "studies/drivers/scene_file_study.h"
#include "studies/tools/bondline_fields.h"
#include "studies/tools/scene_distance.h"

using namespace thinlayer;

namespace {

const std::string double_lap = std::string(THINLAYER_CASES_DIR) + "/double_lap/double_lap.json";

}  // namespace

// d from each end, linear between nodes, the worse face; the corners are the end nodes.
TEST(SceneVerdict, EndStressesInterpolateAtTheStatedDistanceOnTheWorseFace) {
  BondlineField f;
  f.s = {0, 1, 2, 3, 4};
  f.sigma_N = {10, 4, 1, 2, 8};        // plus face
  f.sigma_N_minus = {12, 3, 1, 2, 6};  // minus face: worse at s = 0, better at s = 4
  f.sigma_T = {-9, -5, -1, 3, 7};
  f.sigma_T_minus = {-8, -6, -1, 3, 6};
  const EndStresses e = end_stresses(f, 0.5);
  // s = 0.5: plus 7, minus 7.5; s = 3.5: plus 5, minus 4 → peel 7.5.
  EXPECT_DOUBLE_EQ(e.peel, 7.5);
  // |σ_T| at 0.5: plus 7, minus 7; at 3.5: plus 5, minus 4.5 → 7.
  EXPECT_DOUBLE_EQ(e.shear, 7.0);
  EXPECT_DOUBLE_EQ(e.peel_end, 12.0);
  EXPECT_DOUBLE_EQ(e.shear_end, 9.0);
}

// The double lap (0.2 mm epoxy, bonded): one verdict per quantity and τ; the distances per sample
// are those of the records (each reaction component on its own size, the peaks on max|σ|, by hand); under refinement at the glue's
// own thickness the layer's corner grows while the peaks at d converge.
TEST(SceneVerdict, DoubleLapIsJudgedPerQuantityAndItsCornerGrowsUnderRefinement) {
  SceneStudyOptions options;
  options.validity = true;
  options.verbose = false;
  options.bisection_steps = 1;
  SceneSpec spec = read_scene_spec(double_lap);
  spec.eps = {1.0, 0.2, 0.04};
  SceneFileBulk study_bulk(spec);
  const SceneStudyResult r = run_scene_study(study_bulk, options, nullptr);
  EXPECT_DOUBLE_EQ(r.peak_distance, 0.5);  // max(t = 0.2 mm, 2 × h = 2 × 0.25 mm)
  std::set<std::pair<std::string, double>> rows;
  for (const SceneValidityRow& v : r.validity) rows.insert({v.quantity, v.tau});
  for (const std::string& q : verdict_quantities())
    for (double tau : options.taus) EXPECT_TRUE(rows.count({q, tau})) << q << " " << tau;
  EXPECT_EQ(r.validity.size(), verdict_quantities().size() * options.taus.size());

  // The sample at the glue's own 0.2 mm against its records, by hand. The double lap is held by
  // displacements (clamp and grip): no reaction is fixed by statics, each component is judged on its
  // own size (floored at a thousandth of the largest), the worst reported; the peaks at d on the
  // quantity's scale on the bondlines, the limit's max|sigma_N| and max|sigma_T| (never pointwise).
  const SceneFileScene layer = solve_scene_file_layer(study_bulk, 0.2, SolverKind::Fast, SolverOptions{});
  const SceneFileScene limit = solve_scene_file_limit(study_bulk, SolverKind::Fast, SolverOptions{}, 0.2);
  double largest = 0, worst = 0;
  for (const auto& [name, R] : limit.record.reactions) largest = std::max(largest, R.cwiseAbs().maxCoeff());
  for (const auto& [name, R] : limit.record.reactions)
    for (int c = 0; c < 2; ++c)
      worst = std::max(worst, std::abs(layer.record.reactions.at(name)[c] - R[c]) / std::max(std::abs(R[c]), 1e-3 * largest));
  for (const ReactionComponent& c : reaction_components(study_bulk.model())) EXPECT_FALSE(c.determinate) << c.group;
  const SceneSample* at_02 = nullptr;
  for (const SceneSample& s : r.samples)
    if (std::abs(s.eps - 0.2) < 1e-12) at_02 = &s;
  ASSERT_NE(at_02, nullptr);
  EXPECT_NEAR(at_02->verdict.at("reactions"), worst, 1e-9 * worst);
  EXPECT_DOUBLE_EQ(at_02->verdict.at("u"), at_02->e.at("u"));
  double peel_scale = 0, shear_scale = 0;
  for (const BondlineField& f : bondline_fields(study_bulk, limit.record))
    for (std::size_t k = 0; k < f.s.size(); ++k) {
      peel_scale = std::max(peel_scale, std::abs(f.sigma_N[k]));
      shear_scale = std::max(shear_scale, std::abs(f.sigma_T[k]));
    }
  const EndStresses a = peaks_at_distance(study_bulk, layer.record, 0.5), b = peaks_at_distance(study_bulk, limit.record, 0.5);
  EXPECT_NEAR(at_02->verdict.at("peel_at_d"), std::abs(a.peel - b.peel) / peel_scale, 1e-12);
  EXPECT_NEAR(at_02->verdict.at("shear_at_d"), std::abs(a.shear - b.shear) / shear_scale, 1e-12);

  // Under refinement (h = 0.25, 0.125, 0.0625 at 0.2 mm): the layer's corner shear grows at each
  // halving, its shear at d moves by less than 1 % between the last two; the law's corner converges.
  ASSERT_EQ(r.floor.size(), 3u);
  for (std::size_t k = 1; k < r.floor.size(); ++k) {
    EXPECT_GT(r.floor[k].layer_ends.shear_end, 1.1 * r.floor[k - 1].layer_ends.shear_end) << "level " << k;
    EXPECT_GT(r.floor[k].layer_ends.peel_end, 1.1 * r.floor[k - 1].layer_ends.peel_end) << "level " << k;
  }
  const SceneFloorRow &fine = r.floor[2], &mid = r.floor[1];
  EXPECT_LT(std::abs(fine.layer_ends.shear - mid.layer_ends.shear), 0.01 * fine.layer_ends.shear);
  EXPECT_LT(std::abs(fine.layer_ends.peel - mid.layer_ends.peel), 0.01 * fine.layer_ends.peel);
  EXPECT_LT(std::abs(fine.limit_ends.shear_end - mid.limit_ends.shear_end), 0.01 * fine.limit_ends.shear_end);
  std::printf("layer corner shear %.4g -> %.4g -> %.4g MPa, at d %.4g -> %.4g -> %.4g; law at d %.4g\n",
              r.floor[0].layer_ends.shear_end, mid.layer_ends.shear_end, fine.layer_ends.shear_end,
              r.floor[0].layer_ends.shear, mid.layer_ends.shear, fine.layer_ends.shear, fine.limit_ends.shear);
}

// "Stays within τ up to ε" means at every sampled thickness from the thinnest up: a quantity beyond
// τ at the thinnest sample is within at none, whatever it does above.
TEST(SceneVerdict, WithinMeansAtEveryThinnerSample) {
  SceneSpec spec = read_scene_spec(double_lap);
  spec.eps = {0.2, 0.02, 0.002};
  SceneFileBulk bulk(spec);
  SceneStudyOptions options;
  options.validity = true;
  options.verbose = false;
  options.bisection_steps = 0;
  options.floor_levels = 0;
  const SceneStudyResult r = run_scene_study(bulk, options, nullptr);
  for (const SceneValidityRow& v : r.validity) {
    std::vector<std::pair<double, double>> by_eps;
    for (const SceneSample& s : r.samples) by_eps.push_back({s.eps, s.verdict.at(v.quantity)});
    std::sort(by_eps.begin(), by_eps.end());
    if (by_eps.front().second > v.tau) {
      EXPECT_EQ(v.status, "below_range") << v.quantity << " " << v.tau;
    } else {
      for (const auto& [eps, e] : by_eps) {
        if (eps <= v.eps_max) {
          EXPECT_LE(e, v.tau) << v.quantity << " " << v.tau << " at " << eps;
        }
      }
    }
  }
}
