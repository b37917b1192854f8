#pragma once
// SPEC §3 S6, "How far is my joint from its limit law?": from the limit-mode solution alone, the
// relative distance to the layer model of thickness t that the limit law stands for, in S2's norms
// (studies/tools/scene_distance.h) — the adherents' displacements u, the plus face's σ_N and σ_T —
// and the reactions (‖R_layer − R_limit‖ / ‖R_limit‖ over every support group together). The layer
// model is not meshed: its first-order answer (cases/scene/scene_first_order.h, derived in
// studies/limit_error_estimate.md) stands for it, so each distance is that of the first-order
// answer to the limit answer.
#include <string>

#include "cases/scene/scene_file_scenes.h"

namespace thinlayer {

struct LimitErrorEstimate {
  bool computed = false;
  std::string note;        // why not, when not computed
  double eps = 0;          // the layers' thickness t (mm; the largest where bondlines differ)
  double u = 0, reactions = 0, sigma_N = 0, sigma_T = 0;  // relative (1 = 100 %)
  double time_s = 0;       // the first-order load and its one extra solve
  bool extra_factorisation = false;
};

// From a limit-mode scene solved with LimitSolveExtras::first_order.
LimitErrorEstimate limit_error_estimate(const SceneFileBulk& bulk, const SceneFileScene& limit);

}  // namespace thinlayer
