#pragma once
// Study S3 (SPEC §3): for each dovetail case, tolerance τ and determined quantity, the largest
// ε at which the limit law stays within τ of the layer model — the distance (mode_distance.h) of
// the adherents' displacements `u`, the tenon-top reaction `R_top`, or the stresses on S
// `sigma_N`, `sigma_T` at most τ — by bisection on log ε between the convergence study's samples
// (its distance grid and the rate grid below it, so down to 1e-8 where a case needs it). The
// paper's claim to compare with: "valid up to 1e-3".
#include <string>
#include <vector>

#include "studies/drivers/convergence_study.h"

namespace thinlayer {

struct ValidityStudyOptions {
  std::vector<double> taus = {0.01, 0.05};
  int bisection_steps = 2;   // each halves log ε of the bracket; one layer solve per bracket
  std::vector<std::string> quantities = {"u", "R_top", "sigma_N", "sigma_T"};
  std::vector<double> extra_eps;  // samples beyond the convergence study's (the rate grid's ε)
  double paper_claim = 1e-3;  // L units
};

struct ValidityRow {
  char law_case = 'd';
  double tau = 0;
  std::string quantity;
  // "found": error(eps_max) ≤ τ < error(eps_beyond), eps_max within one bracket of the crossing;
  // "at_least": within τ at every sampled ε (eps_max is the largest, a lower bound);
  // "below_range": beyond τ at every sampled ε (eps_max is the smallest sample, not valid).
  std::string status;
  double eps_max = 0, error_at_eps_max = 0, eps_beyond = 0;
  int bisection_steps = 0;
  bool converged = true;  // the scenes the answer rests on: the bracket's two and its bisection's
};

std::vector<ValidityRow> run_validity_study(const ValidityStudyOptions& options, const ConvergenceResult& samples,
                                            const ConvergenceStudyOptions& convergence, DovetailSceneCache& cache,
                                            H5Writer* out, std::vector<Check>& checks);

}  // namespace thinlayer
