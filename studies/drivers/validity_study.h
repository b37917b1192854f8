#pragma once
// Study S3 (SPEC §3): for each dovetail case and tolerance τ, the largest ε at which the limit
// law stays within τ of the layer model — the distance between the adherents' displacements
// (`u` of mode_distance.h) at most τ — by bisection on log ε between the convergence study's
// samples. The paper's claim to compare with: "valid up to 1e-3".
#include <string>
#include <vector>

#include "studies/drivers/convergence_study.h"

namespace thinlayer {

struct ValidityStudyOptions {
  std::vector<double> taus = {0.01, 0.05};
  int bisection_steps = 2;   // each halves log ε of the bracket; one layer solve per bracket
  std::string quantity = "u";
  double paper_claim = 1e-3;  // L units
};

struct ValidityRow {
  char law_case = 'd';
  double tau = 0;
  // "found": error(eps_max) ≤ τ < error(eps_beyond), eps_max within one bracket of the crossing;
  // "at_least": within τ at every sampled ε (eps_max is the largest, a lower bound);
  // "below_range": beyond τ at every sampled ε (eps_max is the smallest sample, not valid).
  std::string status;
  double eps_max = 0, error_at_eps_max = 0, eps_beyond = 0;
  int bisection_steps = 0;
  bool converged = true;  // every scene it used
};

std::vector<ValidityRow> run_validity_study(const ValidityStudyOptions& options, const ConvergenceResult& samples,
                                            const ConvergenceStudyOptions& convergence, DovetailSceneCache& cache,
                                            H5Writer* out, std::vector<Check>& checks);

}  // namespace thinlayer
