#pragma once
// The layer mode by descent: a truncated nonsmooth Newton method over the film's columns
// (after Gräser & Kornhuber's TNNMG, Gräser & Sander, IMA J. Numer. Anal. 2019), with the
// Coulomb thresholds as an outer fixed point.
//
// With the thresholds s frozen, the answer minimises the convex Tresca energy J_s of
// core/solvers/descent_blocks.h. One step:
//   1. smooth: the adherents off S solved exactly (one Cholesky factor, kept), then each block —
//      a film column and the adherent nodes facing it — minimised exactly with the rest held
//      (core/solvers/block_minimiser.h), forward then backward. Each row ends on one branch: open,
//      at its kink (d = 0), or sliding one way;
//   2. truncate: the whole mixed system (core/solvers/mixed_system.h: one sparse LU) solved with
//      the rows the smoother left at their kink held there (d = 0), the sliding rows' forces given
//      (r_T = ∓s), the open rows' forces zero: the minimiser of J_s on that face, y*. No selection
//      spring: where the face leaves a film part free (every row of its columns open or sliding), a
//      proximal shift on those columns' translations makes the correction solvable — a direction only;
//   3. search: the exact minimiser of J_s along y* − y (core/solvers/kink_line_search.h), feasible
//      for the open rows.
// J_s decreases at every step (the smoother exactly, the search exactly), so the iterates converge
// to a minimiser whether or not it is unique; a film whose position the problem leaves free ends
// wherever the descent leaves it (any point of the solution set is an answer, SPEC §1.5).
// Coulomb: s ← f·max(0, −r_N) from each correction's forces (Anderson-accelerated); where a
// correction repeats the previous step's branches and is taken whole, its statuses are solved once
// more with Coulomb's slide rows (r_T = ∓f r_N): the exact answer where they are right. Every answer
// is judged on the SPEC residual of the true problem (core/solvers/contact_problem.h); the best one
// met is returned.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/solvers/contact_problem.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

struct TnnmgOptions {
  int max_factorisations = 40;   // sparse LUs of the mixed system (the bonded start included)
  int smoothing_sweeps = 1;      // forward + backward sweeps per step
  // Tresca only (empty: Coulomb): the thresholds s, one per node (force unit), held fixed.
  Eigen::VectorXd tresca_thresholds;
  // The start in y (MixedSystem's unknowns) and its thresholds; empty: the bonded start (every row
  // at its kink: the joint glued, one sparse LU).
  Eigen::VectorXd start_y, start_thresholds;
  bool anderson = true;          // accelerate the threshold fixed point
  int closing_rounds = 0;        // corrections re-solved with the open rows they crossed held closed
  bool releasing = false;        // ... and with the held rows whose force left its set let go
  bool verbose = false;          // one line per step on stderr
  // Diagnostics: per-node statuses of a reference answer, printed beside the iterate's each step.
  std::vector<int> reference_rows;  // per row: 0 open/free, 1 kink, 2 plus, 3 minus
};

struct TnnmgStep {
  int factorisations = 0;        // so far
  double alpha = 0;              // the search's step
  bool clipped = false, shifted = false, coulomb = false;
  int changed_rows = 0;          // rows whose branch differs from the previous step's
  double residual = 0;           // SPEC residual of the step's best answer (Coulomb)
  double threshold_change = 0;   // ‖s_new − s‖ / ‖s_new‖
  double smoothing_s = 0, correction_s = 0;
};

struct TnnmgRun {
  SolveReport report;            // the best answer met
  std::vector<TnnmgStep> steps;
  int factorisations = 0;
  bool applies = true;           // false: the problem is not the method's (descent_blocks.h)
  std::string why_not;
  Eigen::VectorXd y;             // the best answer in MixedSystem's unknowns
};

TnnmgRun solve_tnnmg(const ContactProblem& problem, const SolverOptions& options, const TnnmgOptions& tnnmg = {});

}  // namespace thinlayer
