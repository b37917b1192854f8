#pragma once
// Study S2, the floor (SPEC §3 S2, item 2): the distance between the layer model's ε → 0 limit
// and the limit law, at the interface spacings h, h/2, h/4 along S. On one mesh that distance
// does not shrink with ε (the slot corners: the limit law's averaged corner normal against the
// layer's real corner, SPEC §2.2); it must shrink with h, at a rate fitted here.
//
// The layer's ε → 0 limit is read at a thickness where its own ε-part is negligible against the
// floor: case (d), whose ε-part falls like ε (p = 1, the fastest of the nine), at ε = 1e-5; the
// ε-part left there is bounded by the Cauchy difference to ε·ρ (ρ = 10^(−1/2)) times
// ρ/(1 − ρ), printed beside the floor, which must stay below a tenth of it.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/drivers/table3_study.h"
#include "studies/tools/rate_fit.h"

namespace thinlayer {

struct FloorStudyOptions {
  char law_case = 'd';
  double eps = 1e-5;                            // L units
  std::vector<double> h = {0.05, 0.025, 0.0125};  // spacing along S, L units
  double tolerance = 1e-10;
  int threads = 2;
  bool verbose = true;
  // The quantities whose floor must shrink with h (one check each).
  std::vector<std::string> checked = {"R_top", "u", "sigma_N", "sigma_T"};
};

struct FloorLevel {
  double h = 0;
  int S_nodes = 0;
  std::map<std::string, double> floor;      // quantity → distance(layer at ε·ρ, limit)
  std::map<std::string, double> eps_part;   // quantity → bound on the ε-part left in it
  bool converged = false;                   // the limit and both layer scenes
  double solve_time_s = 0;
};

struct FloorResult {
  std::vector<FloorLevel> levels;
  std::map<std::string, std::optional<PowerLawFit>> rate;  // floor ≈ C h^q, per quantity
};

FloorResult run_floor_study(const FloorStudyOptions& options, H5Writer* out, std::vector<Check>& checks);

}  // namespace thinlayer
