#pragma once
// The fields along each bondline of a scene-file scene, in either mode (SPEC §5, "the answer
// drawn"): arc length, the stresses on the plus adherent's face (peel σ_N, shear σ_T; SPEC §1.2
// signs: σ_N > 0 is tension, which only a bonded face carries) and the jumps across the whole
// bondline — in layer mode across the layer, from the two adherents' nodes at each point, so that
// both modes give the same quantity the limit law's [u] stands for — and the status of each node
// (layer mode: the combined one). Node k of a bondline is the same point in both modes; the arc
// length s is measured along the limit mode's bondline from its first node (mm).
#include <string>
#include <vector>

#include "cases/scene/scene_file_scenes.h"

namespace thinlayer {

struct BondlineField {
  std::string bondline;   // its group
  std::vector<double> s, x, y;            // mm (x, y: the limit mode's position)
  std::vector<double> sigma_N, sigma_T;   // stress unit
  std::vector<double> jump_N, jump_T;     // mm
  std::vector<int> status;                // 0 gap, 1 slide, 2 stick
  std::vector<double> length;             // tributary length, mm
};

// One field per bondline, in the scene's order.
std::vector<BondlineField> bondline_fields(const SceneFileBulk& bulk, const SceneRecord& record);

// The peaks of one bondline: the largest tension (peel) and the largest |shear|, and where
// (arc length, mm). A bondline without tension has peel 0 at its first node.
struct BondlinePeaks {
  double peel = 0, s_peel = 0;    // max σ_N⁺
  double shear = 0, s_shear = 0;  // max |σ_T|
  double compression = 0;         // max (−σ_N)⁺
};
BondlinePeaks bondline_peaks(const BondlineField& field);

// The adherents' nodal displacements of a record, in the order of the scene's bodies (both
// modes have the same adherent nodes first), 2 per node (mm).
Eigen::VectorXd adherent_displacements(const SceneFileBulk& bulk, const SceneRecord& record);

}  // namespace thinlayer
