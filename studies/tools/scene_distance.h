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

namespace thinlayer {

// The quantities, in output order.
const std::vector<std::string>& scene_distance_quantities();

// The distances of one record (layer mode; a limit record gives zeros) to the limit record;
// `status_diff`, if given, receives the number of S nodes whose (combined) status differs.
std::map<std::string, double> scene_distance(const SceneFileBulk& bulk, const SceneRecord& layer,
                                             const SceneRecord& limit, int* status_diff = nullptr);

}  // namespace thinlayer
