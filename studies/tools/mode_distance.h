#pragma once
// The distance between the dovetail's two modes (SPEC §3 S2): a layer-mode scene against the
// limit-mode scene of the same case, on the same limit mesh (the layer-mode adherents are the
// limit ones with their nodes moved, same numbering).
//
// Quantities, each a relative discrete L² distance (error_norms.h), globally and "away" from
// the slot's four corners (farther than `corner_radius` from each; SPEC §2.2 expects a floor
// at the corners that shrinks with the element size, not with ε):
//   u        the adherents' nodal displacements (base and tenon), scale U = |(U_x, U_y)| mm;
//   jump_N   [u]_N on S, across the whole layer in layer mode: n·(u_base − u_tenon) at the
//            pair of adherent nodes that S node k joins (the limit's normal n), scale U;
//   jump_T   [u]_T = t·(u_tenon − u_base), scale U;
//   sigma_N  σ_N on S; in layer mode the stress the layer exerts on the tenon (face S+),
//            scale σ_ref = μ_m U / L daN/mm² (the stress of an adherent strained by U/L);
//   sigma_T  σ_T likewise;
//   R_top    the reaction of the tenon's top edge (the pull's force), |ΔR| / max(|R|, R_ref) with R
//            the second record's and R_ref = σ_ref × the top edge's width (0.8 L) — global only.
// Interface norms weigh node k by its tributary length on S; bulk norms weigh nodes equally.
// The fixed scales matter where the limit field vanishes (σ in case (a), the jumps where the
// law is rigid): there the distance is relative to the problem's load, not to zero.
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/interface/interface.h"
#include "core/io/scene_record.h"

namespace thinlayer {

struct DovetailNodes {
  int base_nodes = 0, tenon_nodes = 0;  // the adherents' node counts (same in both modes)
  Eigen::MatrixX2d base_x, tenon_x;     // limit-mode positions, L = 1 units
  std::vector<InterfaceNode> S;         // the limit interface: tenon (plus) and base (minus) node of each S node
};

struct ModeDistance {
  std::map<std::string, double> e;  // quantity (u, u_away, jump_N, jump_N_away, ...) → distance
  int status_diff = 0;              // S nodes whose combined layer status differs from the limit's
};

// The quantities, in output order.
const std::vector<std::string>& distance_quantities();

constexpr double default_corner_radius = 0.1;  // L units: 4 element sizes along S by default

// `layer` may also be a limit-mode record (the distance of a scene to itself is zero, a check),
// and `limit` a layer-mode record: the Cauchy differences of the layer model along ε (SPEC §3
// S2) are this distance between two layer scenes. Statuses compare the combined ones.
ModeDistance mode_distance(const SceneRecord& layer, const SceneRecord& limit, const DovetailNodes& nodes,
                           double corner_radius = default_corner_radius);

// Distance from a point to the nearest of the slot's four corners (L units).
double distance_to_slot_corner(const Eigen::Vector2d& x);

}  // namespace thinlayer
