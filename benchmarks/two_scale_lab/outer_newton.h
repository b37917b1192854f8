#pragma once
// The load's scale of a layer-mode contact problem (issue 33): semismooth Newton on the whole
// sparse mixed system (core/solvers/mixed_system.h), one UMFPACK factorisation a step, the
// statuses re-guessed from each answer with a per-row complementarity parameter κ_i.
//
// Where the layer is not pinched its position is not unique (SPEC §1.5): a proximal spring ρ on
// the translations of the film's columns selects one answer (ρ = film_spring × the adherents'
// nodal stiffness). Rows whose force is below freeze_below × the largest are film-scale: from
// step freeze_from_step on their statuses are kept, so that the Newton steps settle what the
// load decides instead of chasing the film. Then the spring comes off: the settled statuses are
// solved exactly and polished by at most polish_steps more Newton steps on the true problem.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "core/solvers/active_set.h"
#include "core/solvers/contact_problem.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

struct OuterNewtonOptions {
  double film_spring = 1e-8;     // × the adherents' median nodal stiffness κ (daN/mm)
  // Continuation: the springs (× κ) of successive stages, each warm started; empty: film_spring alone.
  std::vector<double> spring_stages;
  double freeze_below = 1e-6;    // × the largest nodal force
  int freeze_from_step = 3;
  // A row's size for the freeze: 0 |r|; 1 |r| + κ|d| with the residual's κ; 2 with the row's own κ_i.
  int freeze_measure = 0;
  int max_steps = 60;            // spring steps
  int polish_steps = 5;          // spring-free steps after them
  bool verbose = false;
  // Nodes whose status the spring steps never change (the film's rows, kept as seeded).
  std::vector<bool> held;
  // Per spring column (in the order given), the global x-DOFs of the adherents' two nodes facing it:
  // its spring is anchored at their mean displacement of the previous step (empty: at rest).
  std::vector<std::array<int, 2>> anchor_faces;
  // The film's statuses from the film alone before each spring-free step (core/solvers/film_solver.h):
  // the columns whose faces carry less than film_scale × the largest force.
  bool film_inner = false;
  double film_scale = 1e-6;
  bool band_inner = false;       // the whole band (solve_band) instead of the film's columns
  double band_spring = 1e-12;    // its proximal spring, × κ
};

// One factorisation of the run: its statuses (the ones solved), forces and true residual.
struct OuterStep {
  std::vector<Active> statuses;
  Eigen::VectorXd r;
  double residual = 0;
  bool spring = true;   // solved with the film's spring
};

struct OuterNewtonRun {
  SolveReport report;            // the best answer met (true residual)
  std::vector<OuterStep> steps;  // every factorisation, in order
  int spring_steps = 0;          // factorisations with the spring
  bool settled = false;          // the spring steps reproduced their statuses
  bool cycled = false;           // they met a status set seen before
  int film_solves = 0;           // the film's dense solves (film_solver.h)
};

// `seed`: one status per node of `problem` (e.g. the limit answer mapped to both faces);
// `springs`: for each layer band, the columns whose translations the spring holds.
OuterNewtonRun solve_outer_newton(const ContactProblem& problem, const std::vector<Active>& seed,
                                  const std::vector<std::vector<int>>& spring_columns, const SolverOptions& solver,
                                  const OuterNewtonOptions& options = {});


}  // namespace thinlayer
