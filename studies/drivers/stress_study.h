#pragma once
// Study S5, stress tests of numerical stability (SPEC §3; issue 5): scenes pushed to the edges
// the solvers must survive — ε down to 1e-8, a layer 1e-12 times softer than the adherents,
// f from 0 to 10, distorted meshes, a floating layer whose contacts all open, loads that open
// the whole interface, and deliberately capped solves. Each scene must either converge to the
// SPEC residual or stop with a named cause (core/solvers/solve_report.h: iteration cap,
// singular system, loss of accuracy with a condition estimate, round-off floor, layer adrift); none may write NaN or Inf.
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/drivers/table3_study.h"

namespace thinlayer {

struct StressStudyOptions {
  int layer_cap = 300;       // active-set steps per attempt for the layer scenes at ε <= 1e-6
  int relaxation_cap = 20000;  // sweeps
  bool quick = false;          // skip the slow scenes: ε <= 1e-6, and the stiffest-contrast layer
  bool verbose = true;
};

std::vector<Check> run_stress_study(const StressStudyOptions& options, H5Writer* out);

}  // namespace thinlayer
