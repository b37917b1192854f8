#pragma once
// Study S2, the rate (SPEC §3 S2, item 1): for each dovetail case, the Cauchy differences of the
// layer model along a geometric ε grid, ‖q(ε_k) − q(ε_{k+1})‖ for the tenon-top reaction, the
// adherents' displacements and the stresses on S (globally and away from the slot corners), and
// the rate p fitted on their asymptotic tail (studies/tools/cauchy_rate.h states the tail rule)
// against the rate the asymptotics predict (studies/convergence_rates.md). The mesh floor,
// which does not depend on ε, cancels in the differences; floor_study.h measures it apart.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/drivers/table3_study.h"
#include "studies/tools/cauchy_rate.h"
#include "studies/tools/scene_cache.h"

namespace thinlayer {

struct CauchyStudyOptions {
  std::string cases = "abcdefghi";
  // ε_k = 10^(−k/2), k = 8…16: 1e-4 … 1e-8 (L units), the grid ratio ρ = 10^(−1/2).
  std::vector<double> eps = geometric_eps_grid(8, 16, 2);
  double tolerance = 1e-10;  // SPEC §1.5: every scene of every study
  TailRule tail;
  double rate_tolerance = 0.15;  // |p − p_predicted| the check allows
  // The checked quantities, one check each per case: the reaction, the adherents' displacements
  // and the two stresses on S away from the corners (at a corner the stress is singular and the
  // limit law's averaged normal differs from the layer's: a different question, measured by the
  // global columns and by the floor study).
  std::vector<std::string> checked = {"R_top", "u", "u_away", "sigma_N_away", "sigma_T_away"};
};

struct CaseCauchy {
  char law_case = 'd';
  double p_predicted = 0;
  std::vector<double> eps;                  // the grid
  std::vector<bool> converged;              // each grid scene at the tolerance
  std::vector<int> iterations;              // each grid scene's solver steps
  std::vector<double> residual;             // each grid scene's SPEC residual
  std::vector<std::string> layer_ids;       // each grid scene's id under /scenes
  std::vector<int> status_changes;          // S nodes whose combined status differs, ε_k against ε_{k+1}
  std::map<std::string, CauchyRate> rate;   // per quantity (mode_distance.h)
  std::map<std::string, bool> pass;         // per checked quantity
};

std::vector<CaseCauchy> run_cauchy_rates(const CauchyStudyOptions& options, DovetailSceneCache& cache, H5Writer* out,
                                         std::vector<Check>& checks);

}  // namespace thinlayer
