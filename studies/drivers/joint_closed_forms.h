#pragma once
// The classical closed forms drawn beside a scene's computed bondline curves (issue 35): for a
// single lap, Volkersen's shear lag and Goland–Reissner's shear and peel with bending; for a double
// lap, Volkersen's shear lag on each bondline (studies/tools/closed_forms.h). The joint is recognised
// from the scene, not named by it: straight bondlines; one bondline between two adherents (a single
// lap), or two parallel bondlines sharing one adherent (a double lap); an engineer's glue (E, ν, t).
// The closed forms assume balanced adherents (the same membrane stiffness E' t on both sides of a
// bondline: two equal sheets; outer strips as stiff as half the inner one), the case they are
// written for here; otherwise they are not drawn and the reason is said. The adherents' thicknesses
// are their extents across the bondline; the force P through each bondline is the shear the limit
// law carries there (Σ σ_T ℓ), so the closed forms need no knowledge of how the joint is loaded.
#include <string>
#include <vector>

#include "cases/scene/scene_file_scenes.h"
#include "core/io/h5_writer.h"

namespace thinlayer {

struct ClosedFormCurves {
  std::string bondline;    // its name: its group in the list form, "" in the one-bondline form
  std::vector<double> s;   // arc length along the bondline, mm (as bondline_fields)
  std::vector<double> volkersen_shear, gr_shear, gr_peel;  // stress unit, σ_T's sign; empty: not drawn
  double P = 0, length = 0, omega = 0, k = 0, beta = 0, lambda = 0;  // N/mm (force unit per mm), mm, 1/mm, 1, 1, 1
  // Goland–Reissner's bending factors: k (drawn: the mean of both ends') and k' from linear statics
  // of the joint's own supports (studies/tools/lap_beam.h), each end's k, and GR's own geometrically
  // nonlinear k at this P (not the model's: shown second).
  double k_ends[2] = {0, 0}, k_prime = 0, k_nonlinear = 0;
  std::string start, end;   // what lies beyond each end of the bondline (s = 0, s = its length)
  std::string gr_why_not;   // where Goland-Reissner is not drawn
  double t_1 = 0, t_2 = 0;  // mm, the two adherents' thicknesses carrying the bondline's force
};

struct JointClosedForms {
  std::string joint;    // "single lap", "double lap", or "" (none recognised)
  std::string why_not;  // where none is drawn
  std::string assumptions;
  std::vector<ClosedFormCurves> bondlines;
};

// `limit`: a limit-mode record of the scene at the glue's own thickness.
JointClosedForms joint_closed_forms(const SceneFileBulk& bulk, const SceneRecord& limit);

// /studies/scene/<name>/closed_forms: attributes joint, why_not, assumptions; per bondline a group
// (its name, or "S") with s, volkersen_shear, goland_reissner_shear, goland_reissner_peel and the
// parameters as attributes.
void write_joint_closed_forms(H5Writer& out, const std::string& group, const JointClosedForms& forms,
                              const std::string& stress_unit, const std::string& force_unit);

}  // namespace thinlayer
