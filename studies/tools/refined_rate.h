#pragma once
// The rate of one quantity on one mesh from the layer model's Cauchy differences, and whether it is
// established under mesh refinement (SPEC §3 S2, item 3): a rate measured on one mesh may only
// re-measure the ε-scaling put into the layer's moduli, so it is established only when it holds at
// h, h/2 and h/4 along S — within ± 0.1 of the prediction at each — and its local slopes have
// settled there (the last two within 0.1 of each other). Otherwise "not established", with the cause.
//
// Which differences count (d_k between the neighbours ε_k > ε_{k+1} of a geometric grid):
//   1. both scenes have an answer: converged to the SPEC tolerance, or stopped at their proven
//      round-off floor (counted, and marked where shown). A scene that did not converge is never
//      fitted, nor replaced by its best iterate: it removes the differences on either side of it;
//   2. the two selections of the layer (SPEC §1.5) agree on both scenes far below the difference:
//      a difference within `spread_factor` (10) times the larger of the two scenes' spreads could be
//      a jump between two answers of one discrete problem rather than a step along ε; a spread not
//      measured (the other selection did not converge) does not show it, so that difference is out too;
//   3. ε_k ≤ eps_max (1e-4) and below the last change of a combined status of S between answered
//      neighbours (studies/tools/cauchy_rate.h's tail rule, unchanged).
// The rate is read where the grid ends: the Cauchy fit of the last `count` (3) differences of the
// thinnest run of consecutive counted differences that holds at least `count` (studies/tools/cauchy_fit.h,
// fit_cauchy_tail), with the local slopes along that run.
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "studies/tools/rate_fit.h"

namespace thinlayer {

struct RefinedRateRule {
  double eps_max = 1e-4;      // L units
  double spread_factor = 10;  // item 2
  int count = 3;              // differences fitted where the grid ends
  double settle = 0.1;        // the last two local slopes within this of each other
  double tolerance = 0.1;     // |p − p_predicted| at every mesh
};

// One quantity on one mesh. Per scene of the grid (n of them): `answered` (item 1). Per difference
// (n − 1): the difference (NaN if unknown), the larger of its two scenes' selection spreads (NaN if
// unknown), the S nodes whose combined status differs between its scenes (−1 if unknown).
struct RefinedRateInput {
  std::vector<double> eps;
  std::vector<bool> answered;
  std::vector<double> difference, spread;
  std::vector<int> status_changes;
};

struct RefinedRate {
  std::vector<std::string> left_out;  // per difference: "" (counted) or why not, in a few words
  int run_first = -1, run_last = -1;  // the run read (difference indices, inclusive); −1: none of `count`
  double run_end_eps = 0;             // the thinnest ε of the run (its last difference's thinner scene)
  bool run_reaches_end = false;       // the run ends with the grid's last difference
  std::optional<PowerLawFit> fit;     // the Cauchy fit of the run's last `count` differences
  std::vector<double> local_slopes;   // along the run, thickest pair first
  bool settled = false;               // the last two local slopes within `settle`
  int counted() const;                // differences counted (item 1–3), in any run
};

// Throws std::invalid_argument on mismatched sizes.
RefinedRate refined_rate(const RefinedRateInput& input, const RefinedRateRule& rule = {});

// One mesh's rate in a verdict: its name ("h", "h/2", "h/4"), and whether the mesh was run at all.
struct MeshRate {
  std::string mesh;
  bool run = false;
  RefinedRate rate;
};

struct RefinedVerdict {
  bool established = false;
  std::string cause;  // empty when established; else the causes, mesh by mesh, "; "-separated
  std::string rates;  // "h 0.50 (0.49 0.50), h/2 0.49 (…), h/4 —": the rate and last local slopes at each mesh
  std::string line() const;  // "<rates>: established" | "<rates>: not established: <cause>"
};

// The verdict over `meshes` (h, h/2, h/4, in that order; a required mesh not run is a cause).
RefinedVerdict refined_verdict(const std::vector<MeshRate>& meshes, double p_predicted, const RefinedRateRule& rule = {});

}  // namespace thinlayer
