// The zigzag measures of S2's quadrature control (studies/tools/zigzag.h): the alternating part of
// a chain's values, the decay length of a zigzag, and the right flank's nodes of the dovetail.
#include <gtest/gtest.h>

#include <cmath>

#include "cases/dovetail/dovetail_scenes.h"
#include "studies/drivers/convergence_study.h"
#include "studies/tools/zigzag.h"

namespace thinlayer {
namespace {

TEST(Zigzag, TheAlternatingPartIgnoresStraightLinesAndKeepsTheZigzag) {
  std::vector<double> v;
  for (int i = 0; i < 8; ++i) v.push_back(3.0 - 0.2 * i + 0.5 * (i % 2 ? -1 : 1));
  const std::vector<double> z = alternating_part(v);
  ASSERT_EQ(z.size(), 6u);
  for (size_t i = 0; i < z.size(); ++i) EXPECT_NEAR(std::abs(z[i]), 0.5, 1e-12) << i;
  EXPECT_NEAR(rms(z), 0.5, 1e-12);
  EXPECT_EQ(rms({}), 0.0);
}

TEST(Zigzag, TheReachIsTheDecayLengthAfterThePeak) {
  for (double length : {0.7, 2.0, 6.0}) {
    std::vector<double> z = {0.01, 0.2};  // rising to the peak at index 2
    for (int i = 0; i < 12; ++i) z.push_back((i % 2 ? -1 : 1) * std::exp(-i / length));
    const auto reach = zigzag_reach(z);
    ASSERT_TRUE(reach) << length;
    EXPECT_NEAR(*reach, length, 1e-9 * length);
  }
  EXPECT_FALSE(zigzag_reach({1.0, 0.5}));               // too few nodes after the peak
  EXPECT_FALSE(zigzag_reach({0.1, 1.0, 1.0, 1.0, 1.0}));  // no decay
}

TEST(Zigzag, TheRightFlankRunsFromTheBottomCornerUp) {
  DovetailLimitBulk bulk(dovetail::MeshOptions{0.05, 0.2, 2});
  const DovetailNodes nodes = dovetail_nodes(bulk);
  const std::vector<int> flank = right_flank_nodes(nodes);
  ASSERT_GE(flank.size(), 8u);
  double previous_y = -0.5;
  for (int k : flank) {
    const Eigen::Vector2d x = nodes.base_x.row(nodes.S[k].minus_node).transpose();
    EXPECT_GT(x.y(), previous_y) << k;  // strictly upwards, strictly inside
    EXPECT_LT(x.y(), 0.0) << k;
    EXPECT_NEAR(x.x(), 0.6 - 0.4 * (x.y() + 0.5), 1e-9) << k;  // on the line (0.6, −0.5) – (0.4, 0)
    previous_y = x.y();
  }
  const std::vector<int> away = right_flank_nodes(nodes, 0.1);
  EXPECT_LT(away.size(), flank.size());
  for (int k : away) EXPECT_GT(distance_to_slot_corner(nodes.base_x.row(nodes.S[k].minus_node).transpose()), 0.1);
}

}  // namespace
}  // namespace thinlayer
