#pragma once
// The film's scale of a layer-mode contact problem (issue 33): the unpinched part of a layer band,
// with everything else frozen.
//
// Where both faces of a layer column carry forces far below the load's (the film), the column's
// statuses decide only where the film sits; its forces are the film's own (of order its in-plane
// stiffness). Given an answer of the whole problem, the film's columns F are solved alone: the
// adherents and the pinched columns frozen at that answer, the film's band stiffness K_FF (its
// neighbours held, so K_FF is definite unless the whole band is film) eliminated,
//   d_f = g_f + W_f r_f,   W_f = G_f K_FF⁻¹ G_fᵀ,   g_f = g_frozen + G_f K_FF⁻¹ f_F,
// and Signorini–Coulomb on its rows (both faces of every film column) solved by the active-set
// method, with the Tresca fixed point (core/solvers/tresca.h, which cannot cycle) where it cycles.
// W_f is dense but of the film's rows only; its entries are the film's compliance.
#include <vector>

#include <Eigen/Core>

#include "core/solvers/active_set.h"
#include "core/solvers/mixed_system.h"

namespace thinlayer {

struct FilmRun {
  std::vector<int> nodes;          // the film's interface nodes (indices into the problem's nodes)
  std::vector<Active> statuses;    // their statuses, in the order of `nodes`
  int linear_solves = 0;           // dense solves of the film's active sets and QPs
  bool settled = false;
};

// The film of `answer` (columns whose faces both carry less than `film_scale` × the largest nodal
// force) solved alone, from the statuses `current`.
FilmRun solve_film(const ContactProblem& problem, const MixedSystem& mixed, const MixedSystem::Answer& answer,
                   const std::vector<Active>& current, double film_scale);

// The whole band with the adherents frozen: on the pinched nodes (force ≥ film_scale × the largest)
// d_N = 0 with the normal force free and |r_T| ≤ f p of the answer (Tresca: which face of a sliding
// column slides is the film's decision); on the film's nodes Signorini and Coulomb (Tresca fixed
// point). A proximal spring ρ (daN/mm) on the band's translations, anchored at the answer, holds
// its rigid modes. Solved in the dual, a bound-constrained QP (core/linalg/box_qp.h).
FilmRun solve_band(const ContactProblem& problem, const MixedSystem& mixed, const MixedSystem::Answer& answer,
                   double film_scale, double rho);

}  // namespace thinlayer
