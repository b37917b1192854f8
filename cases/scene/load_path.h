#pragma once
// Does every load of a scene have a path to a support? (SPEC §1.3, "a scene whose loads have no
// path"; issue 35.) A body with no support of its own is held by its bondlines alone (the inner
// strip of a double lap pulled by a force, the layer itself); where those cannot carry its load
// the solver meets a singular system and ends, after minutes, with a residual and a "floating
// body" message that names nothing the engineer wrote. Two questions are asked before the solve,
// on the model of the mode being solved (limit or layer), for every group of floating bodies held
// together by bilateral (bonded) interfaces — a "held group":
//
//  1. Can anything the group's other interfaces carry balance its loads at all? The forces an
//     interface node can put on the group: a push along its normal (a contact face only pushes; a
//     bilateral law pushes and pulls), a shear along its tangent where the law has a shear
//     stiffness (K_T > 0) and, for a contact face, friction (f > 0) — friction's bound is the
//     second question. The loads' resultant and moment must lie in the cone of those forces (a
//     small non-negative least-squares problem, core/linalg/box_qp.h); where they do not, the
//     load has no path: "body 'inner' is loaded with (1000, 0) N/mm and nothing its bondlines can
//     carry balances it: ...". That is bad input, found before any work (exit 2).
//  2. Held by friction alone, can friction hold it? The group's load along its bondlines (the
//     shear its interfaces must carry) against f × the normal force pressing them. The normal
//     force is not known before the solve in general (it depends on how the other bodies press):
//     it is estimated by one linear solve of the scene with every interface held stuck (each law
//     made bilateral with its own stiffnesses: a sparse LU, core/solvers/bonded_solve.h), the net
//     compression of each interface of the group. Where the load exceeds Σ f_i N_i the joint
//     would slide away: "body 'inner' is held by friction alone: its load along the bondlines,
//     1000 N/mm, exceeds f x its normal force, 0.5 x 1590 = 795 N/mm" (exit 1: the joint fails,
//     no solve is spent on it). Where no interface of a group held by contact alone is pressed in
//     the stuck joint (each in net tension), its contacts open and nothing holds its load either. Within capacity the solve runs; if it then fails, the same line
//     with its numbers says what held the body (studies/cli/command_scene.cpp).
// The check runs before or after the solve, never inside the solver's iteration.
#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "core/fem/model.h"
#include "core/interface/interface.h"

namespace thinlayer {

// One held group that contact and friction alone must hold, with its numbers.
struct FrictionHold {
  std::string bodies;     // the group's bodies other than layers ("inner"), or its layers
  double load = 0;        // the shear its interfaces must carry, force unit per mm (|Σ r_T t| of the stuck solve)
  double normal = 0;      // Σ over its interfaces of the net compression N_i > 0 (stuck solve), force per mm
  double capacity = 0;    // Σ f_i N_i, force per mm
  double scale = 0;       // its loads' resultant |F|, force per mm (what "exceeds" is judged against)
  std::string friction;   // "0.5", or "0.3 / 0.5" where the interfaces differ
  // No interface of the group is pressed in the stuck joint (every N_i ≤ 0): its contacts open.
  bool opens = false;
  // Beyond what contact and friction can hold: open, or a shear above f N (by more than round-off
  // of its loads, 1e-9 |F|).
  bool exceeded() const { return opens || load > capacity + 1e-9 * std::max(scale, load); }
};

struct LoadPath {
  // Question 1: "" where every held group's loads can be balanced, else one line naming the body.
  std::string no_path;
  // Question 2: every group held by friction alone (with a load), and whether its capacity was
  // estimated (the stuck solve converged).
  std::vector<FrictionHold> friction;
  bool capacity_estimated = false;
  std::string capacity_note;  // why not estimated, where it was not
  // The first friction hold whose load exceeds its capacity, or nullptr.
  const FrictionHold* exceeded() const;
};

// `force_unit`: "N" or "daN" (for the messages).
LoadPath check_load_path(const Model& model, const std::vector<Interface>& interfaces, const std::string& force_unit);

// One line: "body 'inner' is held by friction alone: its load along the bondlines, X N/mm, exceeds
// f x its normal force, f x N = C N/mm (...)" (or "is within" when not exceeded).
std::string friction_line(const FrictionHold& hold, const std::string& force_unit);

}  // namespace thinlayer
