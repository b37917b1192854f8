#pragma once
// Study S2, a control (SPEC §3 S2: a measured rate that differs from the prediction is explained
// by a control, not a refit): why the layer of cases (e) and (f) takes full integration
// (cases/layer_quadrature.h). Case (e) is solved again along the rate grid with the selective
// integration that the other cases keep, beside the rule's scenes of the rate study:
//  - σ_N on S+ along the right flank: the rms of its node-to-node zigzag (alternating part, away
//    from the flank's corners) for both quadratures, and the reach ℓ_z (nodes) of the zigzag that selective integration adds,
//    from the difference of the two, against the derived ℓ_z ∝ ε^(−1/4);
//  - the Cauchy differences of sigma_N_away for both, with a slope fitted over every pair: one
//    thickness per decade leaves too few pairs of converged scenes for the rate study's tail rule
//    (several stop at their round-off floor, 1e-10 … 1e-9), so this slope is shown, not checked.
// Nothing here is checked: it is the evidence behind the choice of quadrature, shown in the
// report (section 5c) and in studies/convergence_rates.md.
#include <optional>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/tools/cauchy_rate.h"
#include "studies/tools/rate_fit.h"
#include "studies/tools/scene_cache.h"

namespace thinlayer {

struct QuadratureControlOptions {
  char law_case = 'e';
  // One thickness per decade of the rate grid, 1e-4 … 1e-8 (L units): the rate study's scenes for
  // the rule, and five selective ones (the half decades between would double the control's cost).
  std::vector<double> eps = geometric_eps_grid(4, 8, 1);
  double tolerance = 1e-10;
  double predicted_reach_exponent = -0.25;  // cases/layer_quadrature.h (shown beside the fit)
};

// One quadrature's scenes along the grid.
struct QuadratureSide {
  std::vector<bool> converged;
  std::vector<std::string> ids;
  std::vector<double> zigzag_rms;     // rms of the alternating part of σ_N on the right flank, daN/mm²
  std::vector<double> d_sigma_N_away; // Cauchy differences, one fewer than the grid (mode_distance.h)
  std::optional<PowerLawFit> slope;   // of every difference, converged or not (display only)
};

struct QuadratureControl {
  std::vector<double> eps;
  QuadratureSide selective, rule;
  std::vector<double> reach;            // nodes; NaN where it could not be measured
  std::optional<PowerLawFit> reach_fit; // ℓ_z ≈ C ε^q over every ε where it was measured
};

QuadratureControl run_quadrature_control(const QuadratureControlOptions& options, DovetailSceneCache& cache,
                                         H5Writer* out);

}  // namespace thinlayer
