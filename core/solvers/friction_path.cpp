#include "core/solvers/friction_path.h"

#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "core/solvers/fast_solver.h"

namespace thinlayer {

ContactProblem with_friction_scaled(const ContactProblem& problem, double t) {
  if (!(t >= 0) || std::isinf(t))
    throw std::invalid_argument("a friction path multiplier must be a finite number >= 0, got " + std::to_string(t));
  std::vector<Interface> interfaces = problem.interfaces();
  for (Interface& i : interfaces) i.law.friction *= t;
  return ContactProblem(problem.system(), std::move(interfaces));
}

SolveReport solve_fast_along_friction_path(const ContactProblem& problem, const CondensedInterface& condensed,
                                           const SolverOptions& options) {
  SolverOptions stage = options;
  stage.friction_path.clear();
  int iterations = 0;
  double wall_time_s = 0;
  std::ostringstream path;
  for (double t : options.friction_path) {
    const SolveReport s = solve_fast(with_friction_scaled(problem, t), condensed, stage);
    iterations += s.iterations;
    wall_time_s += s.wall_time_s;
    path << "f x " << t << (s.converged ? " converged" : " NOT converged") << ", ";
    if (options.verbose) std::cerr << "[fast] friction path, f x " << t << ": " << s.message << "\n";
    // A stage that misses its tolerance still hands on its best iterate: only the last
    // solve is judged, and its message says which stages failed.
    stage.initial_r = s.r;
    stage.initial_w = s.w;
  }
  SolveReport report = solve_fast(problem, condensed, stage);
  report.iterations += iterations;
  report.wall_time_s += wall_time_s;
  if (!options.friction_path.empty()) report.message += " [friction path: " + path.str() + "then f x 1]";
  return report;
}

}  // namespace thinlayer
