#pragma once
// Study S2, a control: is a Cauchy difference a step along ε, or a jump between two answers of one
// discrete problem? Where the layer is not pinched its position is not unique, and the solver
// selects one (SPEC §1.5: a spring on the layer's minus or plus face, SolverOptions::layer_selection).
// What S2 measures must not depend on that choice. For the cases with a nearly incompressible
// layer, (e) and (f), each thickness of `pairs` is solved with both selections; the spread between
// them on R_top, u, u_away, sigma_N_away and sigma_T_away is set beside the Cauchy difference from
// that thickness to the next one of the pair. One check per case: every spread ≤ 1e-8 (SPEC
// §1.5), both selections converged.
//
// Case (e) at 5e-4 is also solved with selective integration, both selections: there the two
// selections found two answers (docs/solvers.md, "A second solution, and its cause"), 1.2e-4 apart in the reaction; shown, not
// checked (cases/layer_quadrature.h: the free zigzag makes the problem nearly singular).
#include <string>
#include <utility>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/drivers/table3_study.h"
#include "studies/tools/cauchy_rate.h"
#include "studies/tools/scene_cache.h"

namespace thinlayer {

struct SelectionControlOptions {
  std::string cases = "ef";
  // (ε, the next thinner ε of a study's grid): 5e-4 of the distance grid (the thickness with two
  // answers under selective integration) and 1e-5 of the rate grid's tail, whose neighbour is
  // taken from geometric_eps_grid so that it is the rate study's scene, bit for bit. L units.
  std::vector<std::pair<double, double>> pairs = {{5e-4, 1e-4}, {1e-5, geometric_eps_grid(11, 11, 2).front()}};
  double tolerance = 1e-10;
  double agreement = 1e-8;  // SPEC §1.5: the selections agree on what the problem determines
  std::vector<std::string> quantities = {"R_top", "u", "u_away", "sigma_N_away", "sigma_T_away"};
};

struct SelectionRow {
  char law_case = 'e';
  std::string quadrature;  // "rule" or "selective"
  double eps = 0;
  bool converged = false;  // both selections
  std::vector<double> spread, cauchy;  // per quantity: between the selections; to the next ε
  std::string minus_id, plus_id;
};

std::vector<SelectionRow> run_selection_control(const SelectionControlOptions& options, DovetailSceneCache& cache,
                                                H5Writer* out, std::vector<Check>& checks);

}  // namespace thinlayer
