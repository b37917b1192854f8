#pragma once
// Study S2, the floor (SPEC §3 S2, item 2): the distance between the layer model's ε → 0 limit
// and the limit law, at the interface spacings h, h/2, h/4 along S. On one mesh that distance
// does not shrink with ε (the slot corners: the limit law's averaged corner normal against the
// layer's real corner, SPEC §2.2); it must shrink with h, at a rate fitted here.
//
// The layer's ε → 0 limit is read at a thickness where its own ε-part is negligible against the
// floor: case (d), whose ε-part falls like ε (p = 1, the fastest of the nine), at ε = 10^-5.5;
// the ε-part left there is bounded by its Cauchy difference to 1e-5 times ρ^p/(1 − ρ^p)
// (ρ = 10^(−1/2), the geometric tail summed), printed beside the floor, which must stay below a
// tenth of it.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/io/h5_writer.h"
#include "studies/drivers/table3_study.h"
#include "studies/tools/cauchy_rate.h"
#include "studies/tools/mode_distance.h"
#include "studies/tools/rate_fit.h"
#include "studies/tools/scene_cache.h"

namespace thinlayer {

struct FloorStudyOptions {
  char law_case = 'd';
  // The thickness pair (L units): 1e-5 and 10^-5.5, the rate grid's own values (cauchy_rates.h),
  // so that the level on the studies' mesh reuses the rate study's scenes.
  std::vector<double> eps = geometric_eps_grid(10, 11, 2);
  // Spacing along S, L units: h, h/2, h/4 ending at the studies' mesh (0.025). A layer scene at
  // 0.0125 takes 200 s (issue 13: the floating-layer solver at 185 S nodes), too long for verify.
  std::vector<double> h = {0.1, 0.05, 0.025};
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

// The floor on one mesh from three of its scenes: the layer at `thin` against the limit law, and the
// bound on the ε-part left in it, its Cauchy difference to `thick` times ρ^p/(1 − ρ^p) (the geometric
// tail summed; ρ = ε_thin/ε_thick, p the case's predicted rate). Per quantity of mode_distance.h.
struct FloorPoint {
  std::map<std::string, double> floor, eps_part;
};
FloorPoint floor_point(const SceneRecord& thick, const SceneRecord& thin, const SceneRecord& limit,
                       const DovetailNodes& nodes, double p, double rho);

// The floor's check on one quantity over the mesh levels (coarsest first): it shrinks at every
// halving of h, its ε-part stays below a tenth of it, and every level's scenes converged. The
// Check's id is left to the caller.
Check floor_check(const std::string& quantity, const std::vector<double>& floor, const std::vector<double>& eps_part,
                  const std::vector<bool>& converged, const std::optional<PowerLawFit>& rate);

// `shared` is the studies' cache: the level on its mesh is solved there (and written with it).
FloorResult run_floor_study(const FloorStudyOptions& options, DovetailSceneCache& shared, H5Writer* out,
                            std::vector<Check>& checks);

}  // namespace thinlayer
