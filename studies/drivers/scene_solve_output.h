#pragma once
// What `thinlayer solve --scene` prints (studies/cli/command_scene.cpp calls these): the text
// summary of one scene (every bondline's law and statuses, the reactions with the applied loads
// beside them), its one-line JSON (--json: counts, residual, reactions, loads, whether the joint
// carries a load) and the warning of a joint that carries none (every bondline node open).
#include <string>

#include <nlohmann/json.hpp>

#include "cases/scene/scene_file_scenes.h"
#include "core/io/h5_writer.h"
#include "studies/drivers/classification_cost.h"
#include "studies/tools/limit_error_estimate.h"

namespace thinlayer {

// mode: "limit" or "layer"; eps: the asked thickness (0: each glue's own).
void print_scene_solve(const SceneFileBulk& bulk, const std::string& mode, double eps, const SceneFileScene& scene);

// `cost`: what the paper's rule would cost (limit mode; nullptr: not asked), as "classification_cost".
std::string scene_solve_json(const SceneFileBulk& bulk, const std::string& scene_file, const std::string& mode,
                             const SceneFileScene& scene, const std::string& out, const std::string& vtu,
                             const ClassificationCost* cost = nullptr);

// The thickness a `solve --scene` asks for (0: none given), checked against the scene: the layer
// mode needs one (--eps, or an engineer's glue's own) the joint can hold; in limit mode --eps
// chooses an engineer's glue's law (SPEC §1.3 at that thickness) and, for any layer, the thickness
// of the layer SPEC §3 S6's estimate measures the law against (a joint of laws only refuses it).
// Throws std::invalid_argument.
void check_scene_eps(const SceneFileBulk& bulk, const std::string& mode, double eps);

// --json's account of a solve: solver, solver_method, converged, stop_cause, iterations and the
// residual (value, its interface and bulk parts, the tolerance, the round-off floor); both forms
// of `solve` write it.
nlohmann::json solve_report_json(const SolveReport& report);

// --json's "counts": {gap, slide, stick} of each face of each bondline, and of the layer's combined
// statuses where the record has them; both forms of `solve` write it.
nlohmann::json status_counts_json(const SceneRecord& record);

// --json's "film" object of a layer scene's record (SPEC §1.5: slip_over_h, strain_max), null for
// any other record; both forms of `solve` write it.
nlohmann::json film_json(const SceneRecord& record);

// SPEC §3 S6 in limit mode: "the limit law is within X % of a layer of thickness t" for the
// reactions, the adherents' displacements, σ_N and σ_T (or why it was not computed).
// `reactions_fixed`: where every reaction component is fixed by statics, which ("clamp x"): the
// reactions' line then says "not judged" (studies/tools/scene_distance.h, reaction_components).
void print_limit_error_estimate(const LimitErrorEstimate& estimate, const std::string& reactions_fixed = "");
// --json's "limit_error_estimate": {eps, u, reactions, sigma_N, sigma_T} (relative, 1 = 100 %), or
// {"computed": false, "note": ...}.
nlohmann::json limit_error_estimate_json(const LimitErrorEstimate& estimate);
// The same as attributes of the scene's group in a results file (limit_error_estimate_<field>).
void write_limit_error_estimate(H5Writer& file, const std::string& scene_id, const LimitErrorEstimate& estimate);

// "" when the joint carries a load; else one line saying that every bondline node is open.
std::string no_load_warning(const SceneFileScene& scene);

}  // namespace thinlayer
