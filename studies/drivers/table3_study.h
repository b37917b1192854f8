#pragma once
// Study S1 (SPEC §3, §2.1.1): Table 3 of the paper on the bar, limit mode.
//   1. all six rows with both solvers on the default model: the project's regression
//      baseline, reproduced exactly by both, beside the paper's counts;
//   2. the sensitivity study: plane strain/stress × ny ∈ {8,16,32,64} × Q1/P1 (both
//      diagonals) × nx ∈ {31,32} × scale s ∈ {1,10,100,1e3,1e4}: which variants reproduce
//      which paper rows;
//   3. where along AD the gap-contact and stick-slip transitions lie (mm), under refinement;
//   4. the thin-layer mode at ε = 1e-2, 1e-3, 1e-4, whose combined counts must reach the
//      limit mode's.
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "core/io/reference_tables.h"

namespace thinlayer {

struct Check {
  std::string id;
  bool pass = false;
  std::string expected, got;
  std::string tolerance;
};

struct Table3StudyOptions {
  int repeats = 3;              // timing repetitions per solve; the median is reported
  bool sensitivity = true;
  bool refinement = true;
  double relaxation_tolerance = 1e-10;  // the SPEC §1.5 tolerance, as for the fast solver
  bool verbose = true;          // progress on stderr
};

// Runs the study, prints its tables on stdout, writes scenes and tables into `out` (may be
// null) and returns its checks.
std::vector<Check> run_table3_study(const Table3StudyOptions& options, H5Writer* out);

}  // namespace thinlayer
