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

// Which reaction components statics fixes (SPEC §3 S2 item 4: a verdict judges only what can
// differ). The whole joint is one free body: its support reactions R (each held nodal DOF's) and
// its loads F balance, A R + F = 0 (force x, y and moment: 3 rows). A support group's resultant
// component φ·R is the same in every equilibrium — whatever the joint's stiffness, in any model —
// exactly where φ lies in the row space of A (least squares, residual below 1e-9 ‖φ‖): a
// force-loaded joint's reaction along its pull. Those are "not judged: statically determinate"; the
// others (a bending or sideways reaction, any reaction of a displacement-loaded joint) are judged.
struct ReactionComponent {
  std::string group;
  int component = 0;        // 0: x, 1: y
  bool determinate = false;
};
std::vector<ReactionComponent> reaction_components(const Model& model);
// "clamp x, grip x" — the statically determinate ones, in words ("" if none).
std::string determinate_reactions(const std::vector<ReactionComponent>& components);

// Each verdict quantity's relative distance of `layer` to `limit`:
//  - reactions: the worst of the components that can differ (reaction_components), each
//    |R_layer − R_limit| / max(|R_limit|, 1e-3 × the limit's largest reaction component) — its own
//    size, a component under a thousandth of the joint's reactions judged against that thousandth;
//    NaN where every component is fixed by statics (not judged);
//  - u as scene_distance's;
//  - a peak at d, on the quantity's scale on the bondlines, never pointwise (a pointwise ratio
//    explodes where peel crosses zero: 4950 % at d = 1 mm on a single lap):
//    |P_layer − P_limit| / (the limit's largest |σ_N| on every bondline) for peel_at_d, and
//    / (its largest |σ_T|) for shear_at_d — the L∞ norm of that stress on S.
std::map<std::string, double> verdict_distance(const SceneFileBulk& bulk, const SceneRecord& layer,
                                               const SceneRecord& limit, double d);

// Throws std::invalid_argument (bad input, exit 2) where d is beyond half the shortest bondline: a
// "peak at d from each end" there reads past the bondline's middle (main labelled the corner values
// of a 25 mm bondline "at 30 mm").
void check_peak_distance(const SceneFileBulk& bulk, double d);

}  // namespace thinlayer
