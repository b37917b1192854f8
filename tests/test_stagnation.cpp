// When the floating-layer paths give up for want of progress (core/solvers/stagnation.h).
#include <gtest/gtest.h>

#include <cmath>

#include "core/solvers/stagnation.h"

namespace thinlayer {
namespace {

TEST(Stagnation, ACrawlThatDoesNotHalveInTheWindowStops) {
  Stagnation stagnation(30);
  double best = 1e-8;
  int steps = 0;
  while (!stagnation.after_step(best) && steps < 1000) {
    best *= 0.995;  // 0.5 % a step: 0.86 over 30 steps
    ++steps;
  }
  EXPECT_EQ(steps, 30);
}

TEST(Stagnation, ACrawlThatHalvesInTheWindowGoesOn) {
  Stagnation stagnation(100);
  double best = 1e-7;
  for (int step = 0; step < 1000; ++step) {
    EXPECT_FALSE(stagnation.after_step(best)) << "step " << step;
    best *= 0.99;  // 1 % a step: 0.37 over 100 steps (the dovetail's (e) at 5e-4)
  }
}

TEST(Stagnation, NoVerdictBeforeAWholeWindow) {
  Stagnation stagnation(5);
  for (int step = 0; step < 5; ++step) EXPECT_FALSE(stagnation.after_step(1.0));
  EXPECT_TRUE(stagnation.after_step(1.0));
}

}  // namespace
}  // namespace thinlayer
