#include "core/solvers/solver_choice.h"

#include <stdexcept>

#include "core/solvers/fast_solver.h"
#include "core/solvers/relaxation_solver.h"

namespace thinlayer {

SolverKind parse_solver(const std::string& name) {
  if (name == "fast") return SolverKind::Fast;
  if (name == "relaxation") return SolverKind::Relaxation;
  throw std::invalid_argument("unknown solver '" + name + "' (expected fast or relaxation)");
}

const char* to_string(SolverKind s) { return s == SolverKind::Fast ? "fast" : "relaxation"; }

SolveReport run_solver(const ContactProblem& problem, const CondensedInterface* condensed, SolverKind solver,
                       const SolverOptions& options) {
  if (solver == SolverKind::Relaxation) return solve_relaxation(problem, options);
  if (condensed) return solve_fast(problem, *condensed, options);
  return solve_fast(problem, options);
}

}  // namespace thinlayer
