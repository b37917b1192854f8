// The Cauchy-difference rate (SPEC §3 S2, item 1): the floor cancels, the tail rule picks what
// it says, and too short a tail is "not measurable".
#include <gtest/gtest.h>

#include <cmath>

#include "studies/tools/cauchy_rate.h"

namespace thinlayer {
namespace {

// q(ε) = floor + C ε^p + D ε^(p+1): a quantity with a mesh floor and the O(ε) relative remainder.
std::vector<double> differences_of(const std::vector<double>& eps, double p, double floor) {
  auto q = [&](double e) { return floor + 0.7 * std::pow(e, p) + 5.0 * std::pow(e, p + 1); };
  std::vector<double> d;
  for (size_t k = 0; k + 1 < eps.size(); ++k) d.push_back(std::abs(q(eps[k]) - q(eps[k + 1])));
  return d;
}

TEST(CauchyRate, TheFloorCancelsAndTheTailGivesTheRate) {
  const std::vector<double> eps = geometric_eps_grid(4, 16, 2);  // 1e-2 … 1e-8
  ASSERT_EQ(eps.size(), 13u);
  EXPECT_DOUBLE_EQ(eps.front(), 1e-2);
  EXPECT_NEAR(eps.back(), 1e-8, 1e-22);
  for (double p : {0.5, 1.0}) {
    // A floor 1000 times the ε-term at the smallest ε: the modes' distance would read ~0 there.
    const CauchyRate r = cauchy_rate(eps, differences_of(eps, p, 3.0), std::vector<bool>(eps.size(), true));
    ASSERT_TRUE(r.fit);
    EXPECT_NEAR(r.fit->p, p, 2e-3 * p) << "p = " << p;  // the remainder: 7e-4 of the leading term at 1e-4
    EXPECT_EQ(r.fit->points, 8);                          // differences from ε_k = 1e-4 … 10^-7.5
    for (size_t k = 0; k < r.eps.size(); ++k) EXPECT_EQ(r.in_tail[k], r.eps[k] <= 1e-4 * (1 + 1e-9)) << k;
  }
}

TEST(CauchyRate, AnUnconvergedSceneDropsBothOfItsDifferences) {
  const std::vector<double> eps = geometric_eps_grid(8, 16, 2);  // 1e-4 … 1e-8: 8 differences
  std::vector<bool> converged(eps.size(), true);
  converged[4] = false;  // ε = 1e-6
  const CauchyRate r = cauchy_rate(eps, differences_of(eps, 0.5, 0.0), converged);
  ASSERT_TRUE(r.fit);
  EXPECT_EQ(r.fit->points, 6);
  EXPECT_FALSE(r.in_tail[3]);
  EXPECT_FALSE(r.in_tail[4]);
  EXPECT_TRUE(r.in_tail[2]);
  EXPECT_TRUE(r.in_tail[5]);
}

TEST(CauchyRate, FewerThanThreeTailDifferencesIsNotMeasurable) {
  const std::vector<double> eps = geometric_eps_grid(4, 10, 2);  // 1e-2 … 1e-5: tail 1e-4, 10^-4.5
  const CauchyRate r = cauchy_rate(eps, differences_of(eps, 0.5, 0.0), std::vector<bool>(eps.size(), true));
  EXPECT_FALSE(r.fit);
  TailRule wider;
  wider.eps_max = 1e-3;
  EXPECT_TRUE(cauchy_rate(eps, differences_of(eps, 0.5, 0.0), std::vector<bool>(eps.size(), true), wider).fit);
}

// A node that changes status between two thicknesses changes the expansion's coefficient there:
// the differences at and above that pair are not the asymptotic tail. Synthetic: a jump added to
// the difference across the change spoils the slope of the whole grid, not of the tail below it.
TEST(CauchyRate, TheTailStartsBelowTheLastStatusChange) {
  const std::vector<double> eps = geometric_eps_grid(8, 16, 2);  // 1e-4 … 1e-8: 8 differences
  std::vector<double> d = differences_of(eps, 0.5, 0.0);
  d[2] *= 8;                                        // the pair (1e-5, 10^-5.5): a node changes status
  std::vector<int> changes(d.size(), 0);
  changes[2] = 1;
  const std::vector<bool> converged(eps.size(), true);
  const CauchyRate r = cauchy_rate(eps, d, converged, TailRule{}, changes);
  ASSERT_TRUE(r.fit);
  EXPECT_EQ(r.fit->points, 5);  // the differences from 10^-5.5 down
  for (size_t k = 0; k < d.size(); ++k) EXPECT_EQ(r.in_tail[k], k > 2) << k;
  EXPECT_NEAR(r.fit->p, 0.5, 2e-3);
  ASSERT_TRUE(r.fit_any_status);  // the old rule, kept beside: all 8, slope spoilt by the jump
  EXPECT_EQ(r.fit_any_status->points, 8);
  EXPECT_GT(std::abs(r.fit_any_status->p - 0.5), 0.05);
  // A change next to an unconverged scene is not an answer's change: it does not cut the tail.
  std::vector<bool> one_unconverged = converged;
  one_unconverged[3] = false;
  const CauchyRate u = cauchy_rate(eps, d, one_unconverged, TailRule{}, {0, 0, 0, 1, 0, 0, 0, 0});
  EXPECT_TRUE(u.in_tail[0] && u.in_tail[1]);
  // The rule can be switched off, and a change at the thinnest pair leaves too short a tail.
  TailRule off;
  off.after_status_changes = false;
  EXPECT_EQ(cauchy_rate(eps, d, converged, off, changes).fit->points, 8);
  EXPECT_FALSE(cauchy_rate(eps, d, converged, TailRule{}, {0, 0, 0, 0, 0, 0, 0, 1}).fit);
  EXPECT_THROW(cauchy_rate(eps, d, converged, TailRule{}, {1, 0}), std::invalid_argument);
}

TEST(CauchyRate, RejectsAGridThatDoesNotDecrease) {
  EXPECT_THROW(cauchy_rate({1e-4, 1e-3}, {1.0}, {true, true}), std::invalid_argument);
  EXPECT_THROW(cauchy_rate({1e-3, 1e-4}, {1.0, 2.0}, {true, true}), std::invalid_argument);
  EXPECT_THROW(geometric_eps_grid(5, 4, 2), std::invalid_argument);
}

}  // namespace
}  // namespace thinlayer
