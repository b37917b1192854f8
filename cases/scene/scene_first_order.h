#pragma once
// The first-order answer of a layer behind a scene file's limit solve (SPEC §3 S6): the limit
// answer u₀, r₀ corrected by the layer's first-order terms (core/solvers/first_order_layer.h),
// solved once on the limit mode's own statuses and factorisation (MixedSystem::solve_again) —
// the answer of a layer of thickness t that the limit law leaves out, to first order in t, without
// meshing the layer. What it is worth: studies/limit_error_estimate.md.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/io/scene_record.h"
#include "core/solvers/contact_problem.h"
#include "core/solvers/mixed_system.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

class SceneFileBulk;

struct SceneFirstOrder {
  std::optional<SceneRecord> record;  // as a limit record: u₁ = u₀ + δu, the plus face's traction
  // When asked: the same without the end cells' deficits (its id ends in "-interior"): what a layer
  // meshed with elements longer than its end zone (a few t) can show — the validity map judges the
  // estimate against such layers with it (studies/limit_error_estimate.md, "The ends").
  std::optional<SceneRecord> interior;
  std::vector<double> thickness;      // per bondline: the layer's t (mm; 0: a law only)
  std::string note;                   // why there is no record, or ""
  double time_s = 0;                  // the load and the one extra solve
  bool extra_factorisation = false;   // the limit solve left none to reuse (a contact scene)
};

// eps: the layers' thickness (0: each glue's own; the paper's family needs one). `factored`: the
// limit solve's mixed system, factored at its statuses (a bonded scene), or null (one is factored
// here at the answer's statuses). No record, with a note, where a bondline's thickness is not known
// or the limit answer did not converge.
SceneFirstOrder scene_first_order(const SceneFileBulk& bulk, const ContactProblem& problem, const SolveReport& limit,
                                  const std::string& limit_id, MixedSystem* factored, double eps,
                                  double status_tolerance, bool interior_too = false);

}  // namespace thinlayer
