// The tools of `study convergence --refine`: the rule that says which Cauchy differences count and
// whether a rate is established under refinement (studies/tools/refined_rate.h), the scene store
// (studies/tools/scene_store.h) and the worker under a wall-time cap (studies/parallel/capped_child.h).
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "core/io/output_target.h"
#include "studies/parallel/capped_child.h"
#include "studies/tools/cauchy_rate.h"
#include "studies/tools/refined_rate.h"
#include "studies/tools/scene_store.h"

namespace thinlayer {
namespace {

constexpr double nan_ = std::numeric_limits<double>::quiet_NaN();

// d_k = C ε_k^p (1 − ρ^p) on the S2 rate grid 1e-4 … 1e-8 (ratio 10^-1/2): every local slope is p.
RefinedRateInput exact(double p) {
  RefinedRateInput in;
  in.eps = geometric_eps_grid(8, 16, 2);
  const double rho = in.eps[1] / in.eps[0];
  in.answered.assign(in.eps.size(), true);
  for (std::size_t k = 0; k + 1 < in.eps.size(); ++k) {
    in.difference.push_back(0.3 * std::pow(in.eps[k], p) * (1 - std::pow(rho, p)));
    in.spread.push_back(1e-15);
    in.status_changes.push_back(0);
  }
  return in;
}

TEST(RefinedRate, ExactPowerLawReadWhereTheGridEnds) {
  const RefinedRate r = refined_rate(exact(0.5));
  ASSERT_TRUE(r.fit);
  EXPECT_NEAR(r.fit->p, 0.5, 1e-3);
  EXPECT_EQ(r.run_first, 0);
  EXPECT_EQ(r.run_last, 7);
  EXPECT_TRUE(r.run_reaches_end);
  ASSERT_EQ(r.local_slopes.size(), 7u);
  for (double s : r.local_slopes) EXPECT_NEAR(s, 0.5, 1e-6);
  EXPECT_TRUE(r.settled);
  EXPECT_EQ(r.counted(), 8);
}

TEST(RefinedRate, SceneWithoutAnAnswerRemovesBothItsDifferences) {
  RefinedRateInput in = exact(1.0);
  in.answered[7] = false;  // ε = 3.16e-8
  const RefinedRate r = refined_rate(in);
  EXPECT_EQ(r.left_out[6], "a scene without an answer");
  EXPECT_EQ(r.left_out[7], "a scene without an answer");
  EXPECT_EQ(r.run_first, 0);
  EXPECT_EQ(r.run_last, 5);  // the thinnest run of at least 3 ends at 1e-7
  EXPECT_FALSE(r.run_reaches_end);
  EXPECT_DOUBLE_EQ(r.run_end_eps, in.eps[6]);
  ASSERT_TRUE(r.fit);
  EXPECT_NEAR(r.fit->p, 1.0, 1e-3);
}

TEST(RefinedRate, SelectionSpreadExcludesDifferencesWithinTenTimesIt) {
  RefinedRateInput in = exact(0.5);
  in.spread[6] = in.difference[6] / 5;  // the difference is 5 times the spread: out
  in.spread[7] = in.difference[7] / 20;  // 20 times: counts
  in.spread[2] = nan_;                   // not measured: out
  const RefinedRate r = refined_rate(in);
  EXPECT_EQ(r.left_out[6], "within 10x the selections' spread");
  EXPECT_EQ(r.left_out[7], "");
  EXPECT_EQ(r.left_out[2], "selection spread not measured");
  EXPECT_EQ(r.run_first, 3);  // 3, 4, 5: the thinnest run of three
  EXPECT_EQ(r.run_last, 5);
  EXPECT_EQ(r.counted(), 6);
}

TEST(RefinedRate, StatusChangeStopsTheTailAbove) {
  RefinedRateInput in = exact(0.5);
  in.status_changes[4] = 1;
  const RefinedRate r = refined_rate(in);
  for (int k = 0; k <= 4; ++k) EXPECT_EQ(r.left_out[k], "above a status change") << k;
  EXPECT_EQ(r.run_first, 5);
  EXPECT_EQ(r.run_last, 7);
}

TEST(RefinedRate, TooFewDifferencesGiveNoRate) {
  RefinedRateInput in = exact(0.5);
  in.answered[2] = in.answered[5] = false;  // runs of 1, 1 and 2 differences
  const RefinedRate r = refined_rate(in);
  EXPECT_FALSE(r.fit);
  EXPECT_EQ(r.run_last, -1);
  EXPECT_EQ(r.counted(), 4);
}

TEST(RefinedVerdict, EstablishedOnlyAtEveryMeshWithSettledSlopes) {
  const RefinedRate good = refined_rate(exact(0.5)), off = refined_rate(exact(0.65));
  EXPECT_TRUE(refined_verdict({{"h", true, good}, {"h/2", true, good}, {"h/4", true, good}}, 0.5).established);
  const RefinedVerdict missing = refined_verdict({{"h", true, good}, {"h/2", true, good}, {"h/4", false, {}}}, 0.5);
  EXPECT_FALSE(missing.established);
  EXPECT_EQ(missing.cause, "h/4 not run");
  EXPECT_EQ(missing.line(), "h 0.50 (0.50 0.50), h/2 0.50 (0.50 0.50), h/4 not run: not established: h/4 not run");
  const RefinedVerdict far = refined_verdict({{"h", true, good}, {"h/2", true, off}, {"h/4", true, good}}, 0.5);
  EXPECT_FALSE(far.established);
  EXPECT_EQ(far.cause, "h/2 0.65 outside 0.5 ± 0.1");
  // Local slopes that have not settled: the last difference ρ^0.2 smaller, so the last slope 0.70
  // after 0.50 (and the fit through the last three 0.60).
  RefinedRateInput drifting = exact(0.5);
  drifting.difference[7] *= std::pow(drifting.eps[7] / drifting.eps[6], 0.2);
  const RefinedVerdict unsettled =
      refined_verdict({{"h", true, good}, {"h/2", true, good}, {"h/4", true, refined_rate(drifting)}}, 0.5);
  EXPECT_FALSE(unsettled.established);
  EXPECT_EQ(unsettled.cause, "h/4 0.60 outside 0.5 ± 0.1; h/4 local slopes not settled (0.50, 0.70)");
}

class SceneStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder = std::filesystem::temp_directory_path() / ("thinlayer-store-" + std::to_string(::getpid()));
    std::filesystem::remove_all(folder);
  }
  void TearDown() override { std::filesystem::remove_all(folder); }
  std::filesystem::path folder;
};

TEST_F(SceneStoreTest, RoundTripDamagedAndForeign) {
  const SceneStore store(folder.string());
  EXPECT_FALSE(store.read("a"));
  const StoredScene s{"dovetail|mode=layer", "fast r1", "answered", "", "converged", 12.5, 11.0, std::string("\0\1\2bytes", 8)};
  store.write("a", s);
  const std::optional<StoredScene> back = store.read("a");
  ASSERT_TRUE(back);
  EXPECT_EQ(back->definition, s.definition);
  EXPECT_EQ(back->solver, s.solver);
  EXPECT_EQ(back->ending, s.ending);
  EXPECT_EQ(back->stop, s.stop);
  EXPECT_EQ(back->seconds, s.seconds);
  EXPECT_EQ(back->cpu_seconds, s.cpu_seconds);
  EXPECT_EQ(back->scene, s.scene);
  // Altered: its checksum fails, it is "damaged" (solved again), not foreign.
  { std::ofstream(store.path_of("a"), std::ios::app) << "x"; }
  std::string damaged;
  EXPECT_FALSE(store.read("a", &damaged));
  EXPECT_NE(damaged.find("checksum"), std::string::npos);
  // A file thinlayer did not write there: refused, never replaced.
  { std::ofstream(store.path_of("b")) << "my notes\n"; }
  EXPECT_THROW(store.read("b"), ForeignStoreFile);
  EXPECT_THROW(store.path_of("../b"), std::invalid_argument);
}

TEST(CappedRun, AnswerCapCrashAndThrow) {
  // The worker protocol through thinlayer's own hidden command: an input it cannot read makes the
  // work throw, and the message comes back.
  const CappedRun threw = run_capped({THINLAYER_CLI, "--refinement-scene-worker"}, "garbage", 60);
  EXPECT_EQ(threw.ending, CappedRun::Ending::Threw);
  EXPECT_NE(threw.message.find("bytes"), std::string::npos) << threw.message;
  const auto start = std::chrono::steady_clock::now();
  const CappedRun capped = run_capped({"/bin/sleep", "30"}, "", 0.5);
  EXPECT_EQ(capped.ending, CappedRun::Ending::Capped);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10);
  const CappedRun crashed = run_capped({"/bin/false"}, "", 10);
  EXPECT_EQ(crashed.ending, CappedRun::Ending::Crashed);
  EXPECT_NE(crashed.message.find("exit status 1"), std::string::npos) << crashed.message;
  const CappedRun killed = run_capped({"/bin/sh", "-c", "kill -TERM $$"}, "", 10);
  EXPECT_EQ(killed.ending, CappedRun::Ending::Interrupted);
}

}  // namespace
}  // namespace thinlayer
