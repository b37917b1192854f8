#pragma once
// The bending factor of a single lap from linear statics of its actual supports (SPEC §3 S2 item 4):
// Goland–Reissner's k is the moment at an overlap end over that of the eccentric load, M₀ = k P t/2.
// Their k (studies/tools/closed_forms.h) is geometrically nonlinear — the load line straightens as
// the joint bends, so k falls with P (0.75 / 0.50 / 0.30 at 20 / 200 / 2000 N/mm on one lap) —
// and written for two symmetric pinned ends. A linear model is compared with the linear theory: the
// same joint as a frame of Euler–Bernoulli beams, small displacements, with the scene's own supports.
//
//   lower arm ─── overlap (both adherents as one beam, 2t thick) ─── upper arm
//
// Each arm is a beam on its adherent's mid-plane; the overlap a beam on the mid-plane of the two
// (perfectly bonded: GR's own overlap), joined to the arms by rigid links across half a thickness;
// each support acts at its own point (its nodes' centroid, by a rigid link to the arm's end),
// holding the components it holds and the rotation where it holds a component at two points apart
// across it (a clamped edge: yes; a pin: no). Pinned at both mid-planes this is statically
// determinate, k = L/(L + c) (L the arm's length, c the overlap's half length: the load line's offset
// at the overlap end over t/2); clamped it is not, and the frame's compatibility decides. The factor
// of each end is returned: unequal supports give unequal ends, which GR's symmetric formula cannot.
// Linear: k does not depend on the load.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace thinlayer {

// Along the bondline (s) and across it (n), in mm.
struct LapArm {
  double outer = 0;      // s of the arm's free end
  double axis = 0;       // n of its mid-plane
  double thickness = 0;  // mm
  double E = 0;          // its plane modulus E' (stress unit)
};

// A support or a load acting at one point of an arm's end.
struct LapEnd {
  int arm = 0;                    // 0 or 1
  Eigen::Vector2d at = Eigen::Vector2d::Zero();  // (s, n) of the point
  bool holds_s = false, holds_n = false, holds_rotation = false;
  Eigen::Vector2d value = Eigen::Vector2d::Zero();  // imposed displacement (s, n), mm
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  // applied force (s, n), force per mm
};

struct LapBeam {
  double overlap_start = 0, overlap_end = 0;  // s of the overlap's ends; arm 0 meets it at the start
  LapArm arms[2];
  std::vector<LapEnd> ends;
};

struct LapBending {
  bool solved = false;
  std::string why_not;
  double k[2] = {0, 0};        // M₀ / (N (n_overlap − n_arm)) at the overlap end of each arm
  double k_prime[2] = {0, 0};  // V₀ c / (N t): GR's transverse shear factor, each end
  double N = 0;                // the axial force through the joint, force per mm
};

LapBending lap_bending(const LapBeam& beam);

}  // namespace thinlayer
