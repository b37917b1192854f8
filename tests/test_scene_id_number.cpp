// Scene ids name each thickness by text that reads back as the same double: two thicknesses one
// rounding apart are two scenes with two ids (they were one id, and writing both failed with
// "attribute already exists"), and the ones six digits hold keep the text ids always had.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/io/scene_id_number.h"

namespace thinlayer {
namespace {

TEST(SceneIdNumber, ValuesSixDigitsHoldKeepTheirOldText) {
  EXPECT_EQ(scene_id_number(0.01), "0.01");
  EXPECT_EQ(scene_id_number(5e-3), "0.005");
  EXPECT_EQ(scene_id_number(1e-4), "0.0001");
  EXPECT_EQ(scene_id_number(1e-6), "1e-06");
  EXPECT_EQ(scene_id_number(3.16228e-06), "3.16228e-06");
}

TEST(SceneIdNumber, ThicknessesOneRoundingApartGetTwoIdsThatReadBack) {
  const double a = std::pow(10.0, -5.5), b = 1e-5 * std::pow(10.0, -0.5);
  ASSERT_NE(a, b);  // the floor study's and the rate grid's 10^-5.5, computed two ways
  EXPECT_NE(scene_id_number(a), scene_id_number(b));
  EXPECT_EQ(std::stod(scene_id_number(a)), a);
  EXPECT_EQ(std::stod(scene_id_number(b)), b);
}

}  // namespace
}  // namespace thinlayer
