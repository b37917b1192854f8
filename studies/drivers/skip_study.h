#pragma once
// Study S5, "skip what a scene doesn't need" (issue 5): each shortcut of the fast solver timed
// with and without it, on the scenes it is meant for, and the answers compared (a shortcut
// may change the cost, never the answer):
//   - one factorisation and condensation shared by every scene on the same bulk (the six
//     Table 3 rows; the dovetail's nine limit laws);
//   - no tangential rows for laws without friction (the dovetail's cases a, c, e);
//   - a single linear solve when the statuses are known (a Table 3 row re-solved from its own
//     answer, as a parameter continuation does);
//   - warm starts along an ε sweep (the bar's layer mode, ε = 1e-2 → 1e-3 → 1e-4).
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/drivers/table3_study.h"

namespace thinlayer {

struct SkipStudyOptions {
  int repeats = 3;  // medians of this many runs
};

std::vector<Check> run_skip_study(const SkipStudyOptions& options, H5Writer* out);

}  // namespace thinlayer
