// Verdicts on what can differ (SPEC 3 S2 item 4; studies/tools/scene_distance.h), on the shipped
// steel single lap (cases/single_lap: 12.5 mm overlap, clamp at x = 0, grip at x = 47.5):
//  - pulled by a force along x at the grip (held in y there): the joint's x-reaction is the pull
//    itself, by statics, whatever the glue — only the clamp holds x (not judged); the y-reactions
//    of clamp and grip share the bending, which statics does not split (judged). By hand: the rows
//    are force x, force y and the moment; the clamp's x reactions sit at heights 0..1 mm, so a
//    combination of the rows giving 1 on each of them has no moment part and no y part: it is the
//    force-x row, which sums the clamp's x alone (fixed); a sum of the clamp's y alone would need
//    the y row without the grip's y, i.e. a moment part, which the clamp's x rows forbid (free);
//  - held by displacements (as shipped): every reaction can differ (none fixed);
//  - a peel curve crossing zero: the peak at d there is judged on the limit's max|sigma_N| on the
//    bondline (finite and small), where main's pointwise ratio exploded (4950 % at d = 1 mm);
//  - --peak-distance beyond half the bondline (30 mm on 12.5) is bad input: one line, exit 2.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <map>
#include <string>

#include "cases/scene/scene_file_scenes.h"
#include "studies/tools/bondline_fields.h"
#include "studies/tools/scene_distance.h"
#include "tests/edited_case.h"
#include "tests/text_file.h"

using namespace thinlayer;

namespace {

const std::string lap = std::string(THINLAYER_CASES_DIR) + "/single_lap/single_lap.json";

std::string force_loaded(const SceneFolder& f) {
  return edited_case(f, "single_lap",
                     {{"\"supports\": [{\"group\": \"clamp\", \"u\": [0, 0]}, {\"group\": \"grip\", \"u\": [0.01, 0]}]",
                       "\"supports\": [{\"group\": \"clamp\", \"u\": [0, 0]}, {\"group\": \"grip\", \"u\": [null, 0]}],\n"
                       "  \"loads\": [{\"group\": \"grip\", \"force\": [100, 0]}]"}});
}

std::map<std::string, bool> determinate(const Model& model) {
  std::map<std::string, bool> out;
  for (const ReactionComponent& c : reaction_components(model)) out[c.group + (c.component == 0 ? " x" : " y")] = c.determinate;
  return out;
}

}  // namespace

TEST(WhatCanDiffer, AForceLoadedLapsPullIsFixedByStaticsItsBendingIsNot) {
  SceneFolder f;
  SceneFileBulk bulk(read_scene_spec(force_loaded(f)));
  const std::map<std::string, bool> d = determinate(bulk.model());
  ASSERT_EQ(d.size(), 3u);  // clamp x, clamp y, grip y (the grip's x is loaded, not held)
  EXPECT_TRUE(d.at("clamp x"));
  EXPECT_FALSE(d.at("clamp y"));
  EXPECT_FALSE(d.at("grip y"));
  EXPECT_EQ(determinate_reactions(reaction_components(bulk.model())), "clamp x");
  // The statics itself: the clamp's x-reaction is -100 N/mm in the limit solve and in the layer's.
  const SceneFileScene limit = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{});
  EXPECT_NEAR(limit.record.reactions.at("clamp").x(), -100.0, 1e-8);
}

TEST(WhatCanDiffer, ADisplacementLoadedLapsReactionsAreAllJudged) {
  SceneFileBulk bulk(read_scene_spec(lap));
  const std::map<std::string, bool> d = determinate(bulk.model());
  ASSERT_EQ(d.size(), 4u);
  for (const auto& [which, fixed] : d) EXPECT_FALSE(fixed) << which;
  EXPECT_EQ(determinate_reactions(reaction_components(bulk.model())), "");
}

TEST(WhatCanDiffer, APeakWherePeelCrossesZeroIsJudgedOnItsScale) {
  SceneFileBulk bulk(read_scene_spec(lap));
  const double eps = 0.05;
  const SceneFileScene limit = solve_scene_file_limit(bulk, SolverKind::Fast, SolverOptions{}, eps);
  const SceneFileScene layer = solve_scene_file_layer(bulk, eps, SolverKind::Fast, SolverOptions{});
  ASSERT_TRUE(limit.report.converged && layer.report.converged);
  // Where the law's peel first crosses zero from the end s = 0 (linear between nodes), and its scale.
  const BondlineField f = bondline_fields(bulk, limit.record).at(0);
  double d = -1, scale = 0;
  for (std::size_t k = 0; k < f.s.size(); ++k) scale = std::max(scale, std::abs(f.sigma_N[k]));
  for (std::size_t k = 1; k < f.s.size() && d < 0; ++k)
    if ((f.sigma_N[k - 1] > 0) != (f.sigma_N[k] > 0))
      d = f.s[k - 1] + (f.s[k] - f.s[k - 1]) * f.sigma_N[k - 1] / (f.sigma_N[k - 1] - f.sigma_N[k]);
  ASSERT_GT(d, 0);
  ASSERT_LT(d, 0.5 * f.s.back());
  const EndStresses a = peaks_at_distance(bulk, layer.record, d), b = peaks_at_distance(bulk, limit.record, d);
  const double pointwise = std::abs(a.peel - b.peel) / std::abs(b.peel);
  const double on_scale = std::abs(a.peel - b.peel) / scale;
  const double verdict = verdict_distance(bulk, layer.record, limit.record, d).at("peel_at_d");
  std::printf("peel crosses zero at d = %.4g mm: pointwise %.3g, on max|sigma_N| = %.4g MPa: %.3g\n", d, pointwise, scale,
              on_scale);
  EXPECT_NEAR(verdict, on_scale, 1e-12 * on_scale);
  EXPECT_TRUE(std::isfinite(verdict));
  EXPECT_LT(verdict, 0.1);              // a layer 50 um thick against its law: within a tenth of the peel's scale
  EXPECT_GT(pointwise, 10 * verdict);   // what main reported there: a ratio of near-zeros
}

TEST(WhatCanDiffer, APeakDistanceBeyondHalfTheBondlineIsRefused) {
  SceneFolder f;
  const std::string err = (f.path / "err.txt").string(), out = (f.path / "out.txt").string();
  const int raw = std::system((std::string(THINLAYER_CLI) + " study validity --scene " + lap + " --peak-distance 30 >" +
                               out + " 2>" + err).c_str());
  ASSERT_TRUE(WIFEXITED(raw));
  EXPECT_EQ(WEXITSTATUS(raw), 2);
  const std::string message = read_text_file(err);
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 1) << message;
  EXPECT_NE(message.find("beyond half the shortest bondline (12.5 mm long)"), std::string::npos) << message;
  // 6 mm, within half of 12.5, is not refused by that rule (the study runs on: not run here).
}
