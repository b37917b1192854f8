// S2's controls (studies/drivers/quadrature_control.h, selection_control.h) on a coarse dovetail:
// what they solve, what they store, and that the selection check can fail.
#include <gtest/gtest.h>

#include <cmath>

#include "studies/drivers/convergence_study.h"
#include "studies/drivers/quadrature_control.h"
#include "studies/drivers/selection_control.h"

namespace thinlayer {
namespace {

DovetailLimitBulk& coarse_bulk() {
  static DovetailLimitBulk bulk(dovetail::MeshOptions{0.05, 0.2, 2});
  return bulk;
}

TEST(SelectionControl, TheTwoSelectionsAgreeAndTheCheckSaysSo) {
  DovetailSceneCache cache(coarse_bulk(), 2, false, "test");
  SelectionControlOptions options;
  options.cases = std::string(1, 'f');  // (GCC 12 warns, wrongly, on assigning the literal)
  options.pairs = {{1e-2, 5e-3}};
  options.tolerance = 1e-8;
  std::vector<Check> checks;
  const std::vector<SelectionRow> rows = run_selection_control(options, cache, nullptr, checks);
  ASSERT_EQ(rows.size(), 1u);  // no selective row without case (e)
  EXPECT_TRUE(rows[0].converged);
  EXPECT_NE(rows[0].minus_id, rows[0].plus_id);
  EXPECT_NE(rows[0].plus_id.find("-plus"), std::string::npos) << rows[0].plus_id;
  ASSERT_EQ(rows[0].spread.size(), options.quantities.size());
  for (size_t i = 0; i < rows[0].spread.size(); ++i) {
    EXPECT_LE(rows[0].spread[i], 1e-8) << options.quantities[i];
    EXPECT_GT(rows[0].cauchy[i], 1e3 * rows[0].spread[i]) << options.quantities[i];
  }
  ASSERT_EQ(checks.size(), 1u);
  EXPECT_EQ(checks[0].id, "convergence.f.selections_agree");
  EXPECT_TRUE(checks[0].pass) << checks[0].got;
  // Asking the selections for the impossible fails the check: it can fail. (Both selections now
  // end on the same statuses, whose answer is solved exactly without the spring: their spread is
  // exactly 0 here, so an agreement of 0 is met.)
  options.agreement = -1;
  std::vector<Check> strict;
  run_selection_control(options, cache, nullptr, strict);
  EXPECT_FALSE(strict.at(0).pass);
}

TEST(QuadratureControl, SolvesCaseESelectiveBesideTheRule) {
  DovetailSceneCache cache(coarse_bulk(), 2, false, "test");
  QuadratureControlOptions options;
  options.eps = {1e-2, 1e-3, 1e-4};
  options.tolerance = 1e-8;
  const QuadratureControl c = run_quadrature_control(options, cache, nullptr);
  ASSERT_EQ(c.eps.size(), 3u);
  ASSERT_EQ(c.reach.size(), 3u);
  ASSERT_EQ(c.selective.d_sigma_N_away.size(), 2u);
  ASSERT_EQ(c.rule.zigzag_rms.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_NE(c.selective.ids[k], c.rule.ids[k]);
    EXPECT_NE(c.selective.ids[k].find("-selective"), std::string::npos);
    EXPECT_TRUE(std::isfinite(c.selective.zigzag_rms[k]) && std::isfinite(c.rule.zigzag_rms[k]));
  }
  EXPECT_EQ(cache.solves(), 6);  // three thicknesses, two quadratures
}

}  // namespace
}  // namespace thinlayer
