#pragma once
// S2 and S3 (SPEC §3) on a user's scene file (SPEC §5): the distance between the layer mode at
// every ε of the scene's grid and the limit mode, its fitted rates, the rate from the Cauchy
// differences of the layer model (where the mesh floor cancels), the mesh floor itself (the
// distance at a thickness far below the grid, at h, h/2 and h/4 along the bondlines), the peak
// stresses of every bondline, and the largest ε at which the limit law stays within τ of the
// layer model (bisection on log ε between the samples) — judged per quantity (issue 35): the
// reactions, the adherents' displacements, and the peak peel and peak shear at a stated distance d
// from each bondline end (studies/tools/scene_distance.h); the corners themselves, singular in the
// layer model, are shown under mesh refinement and not judged.
//
// Two kinds of glue (core/interface/glue.h). The paper's family ("layer": λ_ε = ε^γ λ_g): one
// limit law for every ε; the predicted rate of its (γ, δ) (studies/convergence_rates.md) is
// checked. An engineer's glue ("glue": fixed E, ν): the same glue at each thickness t of the
// grid, and the limit law SPEC §1.3 chooses at that t, so one limit scene per thickness; its
// default grid is its own thickness times 5, 2, 1, 1/2, 1/5, ... 1/100 (those the joint can hold).
// The distances: studies/tools/scene_distance.h.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cases/scene/scene_file_scenes.h"
#include "core/io/h5_writer.h"
#include "studies/drivers/joint_closed_forms.h"
#include "studies/drivers/table3_study.h"
#include "studies/tools/bondline_fields.h"
#include "studies/tools/cauchy_fit.h"
#include "studies/tools/rate_fit.h"
#include "studies/tools/scene_distance.h"

namespace thinlayer {

struct SceneStudyOptions {
  std::vector<double> eps = {1e-2, 5e-3, 1e-3, 5e-4, 1e-4};  // the paper family's; the scene's "eps" replaces it
  double tolerance = 1e-10;   // the SPEC residual every scene is solved to
  int threads = 2;            // layer scenes solved at once
  bool verbose = true;
  std::vector<double> taus = {0.01, 0.05};
  int bisection_steps = 2;
  bool validity = false;      // also S3
  double rate_tolerance = 0.15;  // |p_fit − p_predicted| allowed, as the dovetail's S2 check
  // The mesh floor: the modes' distance at the thinnest ε of the grid times floor_eps_factor
  // (its ε part far below the floor; an engineer's glue: at its own thickness, the joint as
  // glued), at h, h/2, h/4 ... along the bondlines (floor_levels of them; a scene given as
  // "geometry" with "mesh_size" only; fewer than 2: none).
  int floor_levels = 3;
  double floor_eps_factor = 1e-2;
  // The stated distance d (mm) from each bondline end at which the peak peel and shear are judged
  // (the corner itself is singular in the layer model). 0: the larger of the glue's own thickness
  // (the paper's family: the thickest ε of the grid) and two elements of the study's mesh.
  double peak_distance = 0;
};

struct SceneSample {
  double eps = 0;
  std::map<std::string, double> e;  // quantity → distance to the limit mode
  std::map<std::string, double> verdict;  // verdict quantity (scene_distance.h) → distance to the limit mode
  EndStresses layer_ends, limit_ends;     // the peaks at d and at the corners, both modes
  int status_diff = 0;              // S nodes whose combined status differs from the limit's
  bool converged = false;           // the layer scene (and its limit scene)
  std::string not_used;             // why its distances are not used (NaN): a scene neither converged nor at a proven floor
  double residual = 0, time_s = 0;
  int iterations = 0;
  std::string id, limit_id;
};

struct SceneValidityRow {
  std::string quantity = "u";  // a verdict quantity (studies/tools/scene_distance.h)
  double tau = 0;
  std::string status;  // found | at_least | below_range (as studies/drivers/validity_study.h) | not_judged (no usable sample)
  double eps_max = 0, error_at_eps_max = 0, eps_beyond = 0;
  int bisection_steps = 0;
  bool converged = true;
  std::string why_not_judged;  // status not_judged: why (statically determinate, or no usable sample)
};

// The mesh floor at one element size along the bondlines.
struct SceneFloorRow {
  double h = 0;       // mm, mesh_size.interface
  int S_nodes = 0;    // nodes on every bondline together
  double eps = 0;     // mm
  std::map<std::string, double> e;
  std::map<std::string, double> verdict;  // the verdict quantities' distances at h
  EndStresses layer_ends, limit_ends;     // the peaks at d and at the corners at h, both modes
  bool converged = false;
  std::string not_used;  // why its distances are not used (NaN), as SceneSample's
  std::string layer_id, limit_id;
};

// The peak stresses of one bondline in one scene.
struct ScenePeak {
  std::string scene, mode, bondline;
  double eps = 0, h = 0;  // mm (eps 0: limit mode)
  BondlinePeaks peaks;
};

struct SceneStudyResult {
  std::string family;  // "scaled" (the paper's) or "engineer" (some bondline's glue has fixed moduli)
  std::string limit_id;
  bool limit_converged = false;
  double limit_residual = 0;
  std::vector<SceneSample> samples;  // by decreasing ε
  std::map<std::string, std::optional<PowerLawFit>> fit;
  std::map<std::string, std::optional<FlooredPowerLawFit>> floor_fit;
  // The layer model's Cauchy differences between neighbouring samples, and the rate they give.
  std::map<std::string, std::vector<double>> cauchy;
  std::map<std::string, std::optional<PowerLawFit>> cauchy_fit;
  // The rate where the grid ends: the last three differences, and whether the local slopes have
  // settled (studies/tools/cauchy_fit.h). The rate check reads this one.
  std::map<std::string, CauchyTail> cauchy_tail;
  std::vector<SceneFloorRow> floor;                                 // by decreasing h
  std::map<std::string, std::optional<PowerLawFit>> floor_rate;     // the floor's rate in h
  std::vector<ScenePeak> peaks;
  std::optional<double> p_predicted;  // the Table 2 case with the scene's (γ, δ), if any
  JointClosedForms closed_forms;      // Volkersen, Goland-Reissner at the glue's own thickness (a lap, a double lap)
  std::size_t nominal = 0;            // the sample of the glue's own thickness (an engineer's glue), else 0
  double peak_distance = 0;           // mm, d of the peaks judged at a distance from the ends
  std::string peak_distance_reason;   // how d was chosen
  std::vector<SceneValidityRow> validity;
  std::vector<Check> checks;
};

// Runs S2 (and S3 if options.validity), prints its tables, writes /studies/scene/<name>/ and
// every scene it solved under /scenes when `out` is given, and beside it the bondline fields of
// every scene as CSV (bondline_fields.csv). Checks (ids "scene.<name>.*"): the limit and every
// layer scene converged; for the paper's family, the distance u decreases as ε decreases and,
// where the asymptotics predict a rate for the scene's (γ, δ), the rate of u from the last three
// Cauchy differences within rate_tolerance of it, its local slopes settled (the last two within 0.1).
SceneStudyResult run_scene_study(SceneFileBulk& bulk, const SceneStudyOptions& options, H5Writer* out);

// The thicknesses the study samples (mm, decreasing): the scene's "eps", or for the paper's
// family options.eps, for an engineer's glue its own thickness times 5, 2, 1, 1/2, 1/5, ..., 1/100
// (those the joint can hold).
std::vector<double> scene_study_grid(const SceneFileBulk& bulk, const SceneStudyOptions& options);

}  // namespace thinlayer
