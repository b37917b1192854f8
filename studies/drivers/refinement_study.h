#pragma once
// Study S2 under mesh refinement (SPEC §3 S2, items 2 and 3; `study convergence --refine 1,2,4`):
// for each dovetail case, the rate of the layer model from its Cauchy differences on the rate grid
// (1e-4 … 1e-8) at h, h/2 and h/4 along S, and whether it is established there
// (studies/tools/refined_rate.h states the rule); and the floor — the layer at the thinnest answered
// ε against the limit law — at each mesh, with its rate in h. The scenes are solved and kept by
// refinement_scenes.h; this file reads them back, measures, and judges.
//
// Every scene counts only with an answer (converged, or at its proven round-off floor, marked); a
// scene without one is listed with its residual, floor, stop cause, time and film slip, and the
// Cauchy differences it removes — never fitted, never replaced by its best iterate.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/drivers/floor_study.h"
#include "studies/drivers/refinement_scenes.h"
#include "studies/drivers/table3_study.h"
#include "studies/tools/refined_rate.h"

namespace thinlayer {

struct RefinementStudyOptions {
  RefinementSceneOptions scenes;
  RefinedRateRule rule;
  // The quantities judged, as in the one-mesh rate study (cauchy_rates.h): the tenon-top reaction,
  // the adherents' displacements, and the stresses on S away from the slot corners.
  std::vector<std::string> checked = {"R_top", "u", "u_away", "sigma_N_away", "sigma_T_away"};
  // The floor's quantities (floor_study.h's checks).
  std::vector<std::string> floor_checked = {"R_top", "u", "sigma_N", "sigma_T"};
};

// One case on one mesh.
struct RefinedLevel {
  int level = 0;
  std::string mesh;                           // "h", "h/2", "h/4"
  double h = 0;
  int S_nodes = 0;
  std::vector<SceneOutcome> minus, plus;      // per ε of the grid: the two selections
  SceneOutcome limit;
  std::vector<int> status_changes;            // per difference; −1 unknown
  std::map<std::string, std::vector<double>> difference;  // per quantity, per difference (NaN unknown)
  std::map<std::string, std::vector<double>> spread;      // per quantity, per ε: plus against minus (NaN unknown)
  std::map<std::string, RefinedRate> rate;    // per checked quantity
  // The floor: the layer at floor_eps (the thinnest answered ε whose thicker neighbour is answered too)
  // against the limit law; empty without such a pair or a limit answer.
  std::optional<FloorPoint> floor;
  double floor_eps = 0;
};

struct RefinedCase {
  char law_case = 'd';
  double p_predicted = 0;
  std::vector<RefinedLevel> levels;
  std::map<std::string, RefinedVerdict> verdict;                        // per checked quantity
  std::map<std::string, std::optional<PowerLawFit>> floor_rate;         // per quantity: floor ≈ C h^q
};

struct RefinementResult {
  std::vector<double> eps;
  std::vector<std::string> meshes;  // the meshes run
  std::vector<RefinedCase> cases;
  int solved_now = 0;               // scenes solved by this run (the rest came from the store)
  std::vector<Check> checks;
};

RefinementResult run_refinement_study(const RefinementStudyOptions& options, H5Writer* out);

}  // namespace thinlayer
