#pragma once
// The distance between a scene file's two modes (SPEC §3 S2 on SPEC §5's joints): a layer-mode
// record against the limit-mode record of the same scene, on the same mesh (the adherents come
// first in both, in scene order, with the same nodes; the layers are the last bodies). With
// several bondlines, S is all of them, one after the other.
//
// Quantities (relative discrete L² distances, error_norms.h), globally only (a user's geometry
// has no corners known in advance):
//   u        the adherents' nodal displacements, scale U = the largest nodal |u| of the limit;
//   jump_N,  [u]_N and [u]_T across the whole layer: from the adherents' pair of nodes at each
//   jump_T   node of S, with the limit's normal; scale U;
//   sigma_N, σ_N, σ_T on the plus body's face (S in limit mode, S+ in layer mode); scale the
//   sigma_T  largest |σ| of the limit mode on S.
// The scales matter where the limit field vanishes (a law that opens everywhere): there the
// distance is relative to the problem's magnitude, not to zero. Interface norms weigh node k by
// its tributary length (mm), bulk norms weigh nodes equally.
#include <map>
#include <string>
#include <vector>

#include "cases/scene/scene_file_scenes.h"
#include "studies/tools/bondline_fields.h"

namespace thinlayer {

// The quantities, in output order.
const std::vector<std::string>& scene_distance_quantities();

// The distances of one record (layer mode; a limit record gives zeros) to the limit record;
// `status_diff`, if given, receives the number of S nodes whose (combined) status differs.
std::map<std::string, double> scene_distance(const SceneFileBulk& bulk, const SceneRecord& layer,
                                             const SceneRecord& limit, int* status_diff = nullptr);

// ‖R_a − R_b‖ / ‖R_b‖ over every support group together (the reactions as one vector), or the
// absolute ‖R_a − R_b‖ where R_b vanishes.
double reaction_distance(const SceneRecord& a, const SceneRecord& b);

// The verdict's quantities (SPEC §3 S3, issue 35), what breaks joints: the reactions, the
// adherents' displacements, and the peak peel and peak shear at a stated distance d (mm) from each
// bondline end — the corner itself is singular in the layer model. In output order:
// "reactions", "u", "peel_at_d", "shear_at_d".
const std::vector<std::string>& verdict_quantities();

// The peaks at d of every bondline of a record: the largest peel and the largest |shear| over the
// bondlines (studies/tools/bondline_fields.h, end_stresses).
EndStresses peaks_at_distance(const SceneFileBulk& bulk, const SceneRecord& record, double d);

// Each verdict quantity's relative distance of `layer` to `limit`: the reactions and u as above;
// a peak as |P_layer − P_limit| / max(|P_limit|, 1e-6 × the limit's largest |σ| on S).
std::map<std::string, double> verdict_distance(const SceneFileBulk& bulk, const SceneRecord& layer,
                                               const SceneRecord& limit, double d);

}  // namespace thinlayer
