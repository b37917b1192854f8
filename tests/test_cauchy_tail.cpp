// The rate read where the grid ends (studies/tools/cauchy_fit.h, issue 36): the Cauchy differences of
// q(ε) = q₀ + A ε^p + B ε^s are generated here by hand, so the asymptotic rate is known.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "studies/tools/cauchy_fit.h"

namespace thinlayer {
namespace {

// |q(ε_k) − q(ε_k+1)| of q(ε) = A ε^p + B ε^s on a grid.
std::vector<double> differences(const std::vector<double>& eps, double A, double p, double B, double s) {
  std::vector<double> d;
  auto q = [&](double e) { return A * std::pow(e, p) + B * std::pow(e, s); };
  for (std::size_t k = 0; k + 1 < eps.size(); ++k) d.push_back(std::abs(q(eps[k]) - q(eps[k + 1])));
  return d;
}

std::vector<double> half_decades(int from, int to) {  // 10^(-k/2), k = from ... to
  std::vector<double> eps;
  for (int k = from; k <= to; ++k) eps.push_back(std::pow(10.0, -k / 2.0));
  return eps;
}

TEST(CauchyTail, ReadsTheAsymptoticRateWhereAnOrderOneRemainderBiasesTheWholeGrid) {
  // The bonded laws' (b) contact/bonded: the ε^0.5 misfit and the O(ε) remainder crossing near 1e-4,
  // on S2's grid 1e-3 ... 1e-8, where the remainder has fallen to 1 % of the misfit at the grid's end
  // (100 ε / ε^0.5). On 1e-3 ... 1e-6 (10 % there) the last three differences still read 0.67: the
  // tail is the asymptotic rate only as far as the grid goes past the crossing.
  const std::vector<double> eps = half_decades(6, 16);  // 1e-3 ... 1e-8
  const std::vector<double> d = differences(eps, 1.0, 0.5, 100.0, 1.0);
  const auto whole = fit_cauchy_differences(eps, d);
  const CauchyTail tail = fit_cauchy_tail(eps, d);
  ASSERT_TRUE(whole && tail.fit);
  EXPECT_GT(whole->p, 0.6);              // biased by the remainder's range
  EXPECT_NEAR(tail.fit->p, 0.5, 0.05);   // its end: the slope as ε → 0
  EXPECT_TRUE(tail.settled);
  EXPECT_EQ(tail.local_slopes.size(), d.size() - 1);
  EXPECT_GT(tail.local_slopes.front(), tail.local_slopes.back());  // falling towards 0.5
}

TEST(CauchyTail, NotSettledWhileASlowerTermStillFades) {
  // A term decaying like ε^0.2 that stops at 1e-6 (as the dovetail's corner in (c) with one face
  // bonded), sampled where it still weighs: the last local slopes move by more than 0.1.
  const std::vector<double> eps = half_decades(8, 13);
  std::vector<double> d = differences(eps, 1.0, 0.5, 0.0, 1.0);
  for (std::size_t k = 0; k < d.size(); ++k) d[k] += 3e-3 * std::pow(eps[k], 0.2) * (k < 3 ? 1.0 : 0.05);
  const CauchyTail tail = fit_cauchy_tail(eps, d);
  EXPECT_FALSE(tail.settled);
}

TEST(CauchyTail, LocalSlopeIsExactOnAnyGrid) {
  // The lap joint's grid alternates ratios 2 and 2.5: the plain log ratio of neighbouring differences
  // would miss p by ± 0.26; the local slope with both (1 − ρ^p) factors recovers it.
  const std::vector<double> eps = {0.1, 0.05, 0.02, 0.01, 0.005, 0.002, 0.001};
  for (double p : {0.5, 1.0, 1.7}) {
    const std::vector<double> d = differences(eps, 3.0, p, 0.0, 1.0);
    for (std::size_t k = 0; k + 2 < eps.size(); ++k)
      EXPECT_NEAR(cauchy_local_slope(eps[k], eps[k + 1], eps[k + 2], d[k], d[k + 1]), p, 1e-9) << p << " " << k;
    const CauchyTail tail = fit_cauchy_tail(eps, d);
    ASSERT_TRUE(tail.fit);
    EXPECT_NEAR(tail.fit->p, p, 1e-3);
    EXPECT_TRUE(tail.settled);
  }
  EXPECT_TRUE(std::isnan(cauchy_local_slope(1e-3, 1e-4, 1e-5, 0.0, 1e-6)));  // a zero difference has no slope
}

TEST(CauchyTail, NeedsThreeDifferences) {
  const std::vector<double> eps = {1e-2, 1e-3, 1e-4};
  EXPECT_FALSE(fit_cauchy_tail(eps, differences(eps, 1, 0.5, 0, 1)).fit);
  EXPECT_THROW(fit_cauchy_tail(eps, differences(eps, 1, 0.5, 0, 1), 2), std::invalid_argument);
}

}  // namespace
}  // namespace thinlayer
