#pragma once
// The dovetail in both modes (SPEC §2.2): the nine cases of Table 2, the limit law and the
// meshed layer at every ε, with the statuses on each face and combined, and the relaxation
// solver on the same scenes under an iteration cap.
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/drivers/table3_study.h"

namespace thinlayer {

struct DovetailStudyOptions {
  std::vector<double> eps = {1e-2, 5e-3, 1e-3, 5e-4, 1e-4};
  std::string cases = "abcdefghi";
  int relaxation_cap = 0;  // sweeps; 0: the relaxation solver is not run
  // Layer scenes, fast solver: a continuation in f first (SolverOptions::friction_path,
  // multiples of f = 0.5). Empty (the default): each scene solved from rest.
  std::vector<double> friction_path;
  bool verbose = true;
};

std::vector<Check> run_dovetail_study(const DovetailStudyOptions& options, H5Writer* out);

}  // namespace thinlayer
