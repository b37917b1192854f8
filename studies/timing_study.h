#pragma once
// Study S5, quick version (SPEC §3): wall time against error for each solver on the bar (Table 3
// row 1, limit mode) at several mesh levels, against a tightly converged reference, and the
// ratio of each solve to one linear solve (factorisation + solve) of the same mesh.
// The full S5 (Siconos peers, the dovetail's levels, layer mode, stress tests) is not here.
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/table3_study.h"

namespace thinlayer {

struct TimingStudyOptions {
  std::vector<int> fast_levels = {32, 64, 128};        // contact nodes = elements along AD
  std::vector<int> relaxation_levels = {32, 64};
  std::vector<double> relaxation_tolerances = {1e-4, 1e-6, 1e-8, 1e-10};
  int relaxation_cap = 50000;                           // sweeps
  int repeats = 3;                                      // medians of this many runs
  double reference_tolerance = 1e-12;                   // the fast solver's, for the reference
};

std::vector<Check> run_timing_study(const TimingStudyOptions& options, H5Writer* out);

}  // namespace thinlayer
