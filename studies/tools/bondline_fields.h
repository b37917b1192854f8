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
  std::vector<double> sigma_N, sigma_T;   // stress unit, on the plus adherent's face
  // On the minus adherent's face (layer mode: S-, the layer's other face; limit mode or a law only:
  // the same as the plus face's). A layer's two faces differ near its ends: the worse one breaks.
  std::vector<double> sigma_N_minus, sigma_T_minus;
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

// The stresses at distance d (mm, arc length) from each end of a bondline, on the worse of its two
// faces: the largest σ_N (peel; may be negative, a compression) and the largest |σ_T| of the two
// ends, linearly interpolated between nodes. At the end itself (d = 0) a layer's corner is
// singular: its value grows as the mesh is refined; at a fixed distance it converges (issue 35).
struct EndStresses {
  double d = 0;          // mm
  double peel = 0;       // stress unit, max over the ends and faces of σ_N(d)
  double shear = 0;      // stress unit, max over the ends and faces of |σ_T(d)|
  double peel_end = 0, shear_end = 0;  // the same at the ends' nodes themselves (the corners)
};
EndStresses end_stresses(const BondlineField& field, double d);

// The adherents' nodal displacements of a record, in the order of the scene's bodies (both
// modes have the same adherent nodes first), 2 per node (mm).
Eigen::VectorXd adherent_displacements(const SceneFileBulk& bulk, const SceneRecord& record);

}  // namespace thinlayer
