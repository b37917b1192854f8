#pragma once
// One cell of the engineer's validity map (SPEC §3 S3; studies/drivers/validity_map.h): the user's
// joint with every layer bondline's glue replaced by an engineer's glue of Young's modulus
// E_g = (E_g/E_a) E_a, Poisson's ratio ν_g and thickness t = (t/L) L — E_a the adherents' Young's
// modulus (bondline 0's reference, SPEC §1.3's λ_m, μ_m), L SPEC §1.3's characteristic length —, and
// at that thickness:
//   - the meshed layer of that glue (layer mode);
//   - the finite spring law of that glue at its own t, stated here (not taken from a classification):
//     λ̄ = λ_g/t, μ̄ = μ_g/t, i.e. K_N = (λ_g+2μ_g)/t, K_T = μ_g/t, bilateral where both faces are
//     bonded, Table 1's with the bondline's f otherwise (core/interface/glue.h, layer_limit_law);
//   - its first-order answer u₁, SPEC §3 S6's estimate (studies/tools/limit_error_estimate.h), and how
//     far the layer is from u₁ itself (order 1) beside how far it is from the law's answer u₀ (order 0);
// on the scene's mesh and on the mesh of half its element size (the mesh floor kept apart), and
// at the finer one the law the paper's 3 % / 30x rule would choose (SPEC §1.3, classified_law), solved
// where it differs from the finite law, against the same layer.
// Each distance is a verdict quantity of the scene studies (studies/tools/scene_distance.h:
// reactions, u, peel_at_d, shear_at_d at the distance d from each bondline end) or one of S2's
// stress norms (sigma_N, sigma_T over the whole bondline).
#include <map>
#include <string>
#include <vector>

#include "cases/scene/scene_file_scenes.h"

namespace thinlayer {

struct MapCellSpec {
  double t_over_L = 0;   // the glue's thickness over L
  double E_ratio = 0;    // E_g / E_a
  double nu = 0.3;       // ν_g
};

// The quantities of a cell, in output order.
const std::vector<std::string>& map_quantities();

struct MapCellLevel {
  double h = 0;                 // mm, the element size along the bondlines
  bool converged = false;       // the layer and the limit scene reached the tolerance
  // Why a scene of this level did not converge or could not be solved (refused, threw), each with
  // its verdict's words (core/solvers/stop_verdict.h); "" where both converged. Distances are
  // measured only between usable answers (converged, or a proven round-off floor).
  std::string failure;
  double layer_residual = 0, limit_residual = 0;
  std::map<std::string, double> measured;   // the layer against the finite law
  std::map<std::string, double> estimate;   // the first-order answer against the finite law (S6)
  std::map<std::string, double> interior;   // the same without its end cells (SceneFirstOrder::interior)
  // Order one: the layer against the first-order answer u₁ (the same distances, u₁ the reference), and
  // against u₁ without its end cells.
  std::map<std::string, double> order1, order1_interior;
  double layer_time_s = 0, limit_time_s = 0, estimate_time_s = 0;
};

struct MapCell {
  MapCellSpec spec;
  double thickness = 0, E = 0;  // mm, stress unit: the glue of this cell
  // The joint's shear-lag length √(E*_a L t / μ_g) (Volkersen: an adherent of thickness L on the glue,
  // E*_a its plane modulus): the length over which the bondline's stresses vary (mm).
  double shear_lag = 0;
  std::string law_case;         // the finite law's Table 1 class, one letter per bondline ("d,d")
  std::string rule_case;        // the paper's 3 % / 30x rule's choice
  MapCellLevel coarse, fine;    // at h and h/2 (fine: empty, h = 0, without a mesh_size)
  // The rule's law at the finer level, where it differs from the finite law (rule_solved).
  bool rule_solved = false, rule_converged = false;
  std::string rule_failure;     // why the rule's scene did not converge ("" if it did): no rule distance then
  std::map<std::string, double> rule_measured;  // the layer against the rule's law
};

// The adherents' Young's modulus the ratio refers to: E = μ(3λ+2μ)/(λ+μ) of bondline 0's reference.
double map_adherent_modulus(const SceneFileBulk& bulk);

// The cell's scene: `meshed`'s with every layer bondline's glue replaced (faces and friction kept).
SceneSpec map_cell_spec(const SceneFileBulk& meshed, const MapCellSpec& cell);

// Solves the cell on `coarse` (the scene's mesh) and, if non-null, `fine` (half its element size),
// with the peaks at d (mm). A scene that cannot be solved is recorded in its level's `failure`.
MapCell solve_map_cell(const SceneFileBulk& coarse, const SceneFileBulk* fine, const MapCellSpec& cell, double d,
                       double tolerance);

}  // namespace thinlayer
