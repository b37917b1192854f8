// S5's seeded scene generator (SPEC §3 S5, studies/tools/scene_generator.h): one seed is one scene,
// always the same, and the draws stay inside the ranges the SPEC names.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "cases/bar/bar.h"
#include "studies/tools/scene_generator.h"

namespace thinlayer {
namespace {

TEST(SceneGenerator, OneSeedIsOneSceneAlways) {
  for (int seed : {1, 2, 77, 200}) {
    const GeneratedScene a = generate_scene(seed), b = generate_scene(seed);
    EXPECT_EQ(a.describe(), b.describe());
    EXPECT_EQ(a.eps, b.eps);  // bit for bit, not only to the description's digits
  }
  std::set<std::string> seen;
  for (int seed = 1; seed <= 200; ++seed) seen.insert(generate_scene(seed).describe());
  EXPECT_EQ(seen.size(), 200u);  // the seed is in the description: 200 different lines
}

TEST(SceneGenerator, DrawsStayInTheirRangesAndCoverEveryKind) {
  const GeneratorRanges ranges;
  int dovetail = 0, bar = 0, scene_file = 0, drawn_exponents = 0;
  for (int seed = 1; seed <= 2000; ++seed) {
    const GeneratedScene s = generate_scene(seed, ranges);
    SCOPED_TRACE(s.describe());
    switch (s.kind) {
      case GeneratedScene::Kind::Dovetail:
        ++dovetail;
        if (!s.law_case) ++drawn_exponents;
        EXPECT_GE(s.eps, 1e-8);
        EXPECT_LE(s.eps, 0.1);
        EXPECT_GE(s.friction, 0.0);
        EXPECT_LE(s.friction, 1.0);
        EXPECT_GE(s.h_interface, ranges.h_min);
        EXPECT_LE(s.h_interface, ranges.h_max);
        EXPECT_GE(s.exponents.gamma, 0.0);
        EXPECT_LT(s.exponents.delta, 2.0);  // as the CLI allows (0 <= δ < 2)
        EXPECT_GE(s.layer_elements, 2);
        EXPECT_LE(s.layer_elements, 4);
        break;
      case GeneratedScene::Kind::Bar:
        ++bar;
        EXPECT_GE(s.bar_row, 1);
        EXPECT_LE(s.bar_row, 6);
        EXPECT_GE(s.eps, 1e-8);
        EXPECT_LE(s.eps, bar::thickest_layer);
        EXPECT_GE(s.bar_nx, 16);
        EXPECT_LE(s.bar_nx, ranges.bar_nx_max);
        EXPECT_GE(s.load_scale, 0.1);
        EXPECT_LE(s.load_scale, 10.0);
        break;
      case GeneratedScene::Kind::SceneFile:
        ++scene_file;
        EXPECT_FALSE(s.scene_file.empty());
        EXPECT_GT(s.eps_fraction, 0.0);
        EXPECT_LE(s.eps_fraction, 1.0);
        break;
    }
  }
  // 60 / 20 / 20 % (binomial spread at n = 2000: ±1 % is about one standard deviation, so ±5 %
  // fails only on a biased draw).
  EXPECT_NEAR(dovetail / 2000.0, 0.6, 0.05);
  EXPECT_NEAR(bar / 2000.0, 0.2, 0.05);
  EXPECT_NEAR(scene_file / 2000.0, 0.2, 0.05);
  EXPECT_NEAR(drawn_exponents / static_cast<double>(dovetail), 0.5, 0.05);
}

TEST(SceneGenerator, ANarrowerMeshRangeIsHonoured) {
  GeneratorRanges coarse;
  coarse.h_min = 0.0125;  // CTest's random_scenes_20
  for (int seed = 1; seed <= 500; ++seed) {
    const GeneratedScene s = generate_scene(seed, coarse);
    if (s.kind == GeneratedScene::Kind::Dovetail) {
      EXPECT_GE(s.h_interface, 0.0125) << s.describe();
    }
  }
}

}  // namespace
}  // namespace thinlayer
