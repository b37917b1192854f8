#pragma once
// Does every load of a scene have a path to a support? (SPEC §1.3, "a scene whose loads have no
// path" and "a refusal is a proof".) A scene is refused before its solve only on what statics
// proves, on the model of the mode being solved (limit or layer):
//
//   every body b balances, force and moment:   Σ_j G_bj x_j + F_b = 0,
//
// over nodal forces x inside each node's admissible set — a contact node pushes along its normal
// and, where its law has a shear stiffness (K_T > 0) and friction (f > 0), shears within its
// Coulomb cone |r_T| ≤ f r_N, which in 2D is exactly the cone of two rays n ± f t; a bonded node
// carries any force its law has a stiffness for (±n where K_N > 0, ±t where K_T > 0); a node whose
// law carries nothing (K_N = K_T = 0) none; a support any reaction along each component it holds.
// Every body counts, supported or not, each with its own force and moment. The least ℓ1 imbalance
// any such forces leave is a linear program (core/linalg/least_imbalance.h: GLPK, confirmed by its
// exact rational simplex). Two questions:
//
//  1. A load with no path: the imbalance stays with friction unbounded (any shear where the law
//     has one) — nothing the interfaces and supports can carry balances the load at all. That is
//     bad input (exit 2): "body 'inner' is loaded with (-500, 0) N/mm and nothing its supports and
//     interfaces can carry balances that load: ...".
//  2. A friction overload proven: a path exists, but not inside the Coulomb cones — "statics proves
//     no forces inside its contacts' friction cones balance it ... the least imbalance is 200
//     N/mm"; the joint fails (exit 1), nothing solved.
// A body is refused only where the imbalance is above 1e-6 of its loads (‖F‖₁ over every body's
// rows): the answer's own equilibrium is judged to 1e-10, so an imbalance of 1e-6 is no rounding.
// Statics cannot refuse what elasticity decides: where the normal force pressing a friction contact
// is not fixed by statics (the clamped strips of cases/friction_double_lap could press harder), the
// solve runs. If it then fails, an estimate explains it: the normal force of the joint held stuck
// (friction_estimate below, one linear solve) — an explanation of a failure, never a refusal.
#include <algorithm>
#include <string>
#include <vector>

#include "core/fem/model.h"
#include "core/interface/interface.h"

namespace thinlayer {

struct LoadPath {
  // Question 1: "" where the loads have a path, else one line naming the body (exit 2).
  std::string no_path;
  // Question 2: "" where forces inside the Coulomb cones balance the loads, else one line (exit 1).
  std::string friction_overload;
  // The least imbalance of each question (force unit per mm, ℓ1 over every body's rows; moments
  // over the body's size) and the loads' own ℓ1 norm, for the tests and the messages.
  double imbalance_any_shear = 0, imbalance_in_cones = 0, loads = 0;
};

// `force_unit`: "N" or "daN" (for the messages).
LoadPath check_load_path(const Model& model, const std::vector<Interface>& interfaces, const std::string& force_unit);

// One held group that contact and friction alone must hold, with the numbers of the joint held
// stuck (an estimate: one linear solve with every interface law made bilateral with its own
// stiffnesses). Used only to explain a solve that failed.
struct FrictionHold {
  std::string bodies;     // the group's bodies other than layers ("inner"), or its layers
  double load = 0;        // the shear its interfaces must carry, force unit per mm (|Σ r_T t| of the stuck solve)
  double normal = 0;      // Σ over its interfaces of the net compression N_i > 0 (stuck solve), force per mm
  double capacity = 0;    // Σ f_i N_i, force per mm
  double scale = 0;       // its loads' resultant |F|, force per mm (what "exceeds" is judged against)
  std::string friction;   // "0.5", or "0.3 / 0.5" where the interfaces differ
  // No interface of the group is pressed in the stuck joint (every N_i ≤ 0).
  bool opens = false;
  bool exceeded() const { return opens || load > capacity + 1e-9 * std::max(scale, load); }
};

// Every group of floating bodies held by contact alone, with a load; empty where the stuck solve
// did not converge (nothing to explain with).
std::vector<FrictionHold> friction_estimate(const Model& model, const std::vector<Interface>& interfaces);

// One line explaining a failed solve: "body 'inner' is held by friction alone: its load along the
// bondlines, X N/mm, exceeds f x its normal force in the joint held stuck, f x N = C N/mm (an
// estimate, ...)" (or "is within").
std::string friction_line(const FrictionHold& hold, const std::string& force_unit);

}  // namespace thinlayer
