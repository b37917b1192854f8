#include "benchmarks/two_scale_lab/outer_newton.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <sstream>

#include "benchmarks/two_scale_lab/film_solver.h"
#include "core/solvers/mixed_system.h"

namespace thinlayer {

namespace {

double largest_nodal_force(const Eigen::VectorXd& r) {
  double m = 0;
  for (int k = 0; 2 * k < r.size(); ++k) m = std::max(m, r.segment<2>(2 * k).norm());
  return m;
}

}  // namespace

OuterNewtonRun solve_outer_newton(const ContactProblem& problem, const std::vector<Active>& seed,
                                  const std::vector<std::vector<int>>& spring_columns, const SolverOptions& solver,
                                  const OuterNewtonOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  OuterNewtonRun run;
  SolveReport& best = run.report;
  best.solver = "fast";
  best.tolerance = solver.tolerance;
  best.residual.interface = best.residual.bulk = std::numeric_limits<double>::infinity();
  MixedSystem mixed(problem);

  // The film's spring on the chosen columns' translations, anchored at rest.
  const double kappa_adherent = adherent_stiffness(problem);
  std::vector<int> y;
  for (int b = 0; b < mixed.num_bands() && b < static_cast<int>(spring_columns.size()); ++b)
    for (int column : spring_columns[b])
      for (int c = 0; c < 2; ++c) y.push_back(mixed.band_translation(b, column, c));
  Eigen::VectorXd anchor = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(y.size()));
  const LinearSystem& system = problem.system();
  auto value = [&](const Eigen::VectorXd& u, int dof) {
    const int free = system.free_index(dof);
    return free >= 0 ? u[free] : system.prescribed_value(dof);
  };
  // The anchors at the mean of the facing adherent nodes of answer a.
  auto follow = [&](const MixedSystem::Answer& a) {
    if (options.anchor_faces.size() * 2 != y.size()) return;
    for (size_t j = 0; j < options.anchor_faces.size(); ++j)
      for (int c = 0; c < 2; ++c)
        anchor[2 * j + c] = 0.5 * (value(a.u, options.anchor_faces[j][0] + c) + value(a.u, options.anchor_faces[j][1] + c));
  };

  auto consider = [&](const MixedSystem::Answer& a, const std::vector<Active>& s, bool spring) {
    const auto t0 = std::chrono::steady_clock::now();
    const Residual residual = contact_residual(problem, a.u, a.r, a.band_z);
    if (options.verbose)
      std::fprintf(stderr, "  outer: residual evaluated in %.3f s\n",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    run.steps.push_back({s, a.r, residual.value(), spring});
    if (options.verbose)
      std::fprintf(stderr, "  outer: step %zu (%s), residual %.3e\n", run.steps.size(), spring ? "spring" : "exact",
                   residual.value());
    if (!a.singular && a.u.allFinite() && a.r.allFinite() && residual.value() < best.residual.value()) {
      best.u = a.u;
      best.r = a.r;
      best.residual = residual;
      best.condition_estimate = 1.0 / std::max(a.rcond, 1e-300);
    }
  };

  // 1. The load's scale: Newton steps with the spring until the statuses reproduce themselves.
  std::vector<Active> statuses = seed;
  const std::vector<double> stages = options.spring_stages.empty() ? std::vector<double>{options.film_spring}
                                                                   : options.spring_stages;
  for (double stage : stages) {
  std::set<std::vector<Active>> seen{statuses};
  const Eigen::VectorXd rho_y = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(y.size()), stage * kappa_adherent);
  if (!y.empty()) mixed.set_springs(y, rho_y, anchor);
  run.settled = run.cycled = false;
  const Condensed rules = law_rules(problem, mixed.row_stiffness());
  const Eigen::VectorXd freeze_kappa = options.freeze_measure == 0   ? Eigen::VectorXd::Zero(rules.kappa.size())
                                       : options.freeze_measure == 1 ? problem.kappa()
                                                                     : rules.kappa;
  for (int step = 1; step <= options.max_steps; ++step) {
    const auto t_solve = std::chrono::steady_clock::now();
    const MixedSystem::Answer a = mixed.solve(statuses);
    if (options.verbose)
      std::fprintf(stderr, "  outer: mixed solve %.3f s\n",
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - t_solve).count());
    ++run.spring_steps;
    consider(a, statuses, true);
    follow(a);
    if (!y.empty()) mixed.set_springs(y, rho_y, anchor);
    std::vector<Active> next = guess_statuses(rules, a.r, problem.stop_jumps(a.u, a.r));
    int frozen = 0;
    for (size_t k = 0; k < options.held.size(); ++k)
      if (options.held[k]) next[k] = statuses[k];
    if (step >= options.freeze_from_step) {
      // A row's force: the one it carries, or the one its jump would make at the residual's κ
      // (a gap row that penetrates is not film-scale however small its r).
      const Eigen::VectorXd d = problem.stop_jumps(a.u, a.r);
      const double floor = options.freeze_below * largest_nodal_force(a.r);
      for (int k = 0; k < problem.num_nodes(); ++k)
        if (a.r.segment<2>(2 * k).norm() + freeze_kappa.segment<2>(2 * k).cwiseProduct(d.segment<2>(2 * k)).norm() <
                floor &&
            next[k] != statuses[k]) {
          next[k] = statuses[k];
          ++frozen;
        }
    }
    if (options.verbose) {
      int changed = 0, counts[6] = {0, 0, 0, 0, 0, 0};
      const double peak = largest_nodal_force(a.r);
      double tension = 0, penetration = 0;
      const Eigen::VectorXd d = problem.stop_jumps(a.u, a.r);
      for (int k = 0; k < problem.num_nodes(); ++k) {
        changed += next[k] != statuses[k];
        ++counts[static_cast<int>(statuses[k])];
        tension = std::max(tension, a.r[2 * k]);
        penetration = std::max(penetration, d[2 * k]);
      }
      std::fprintf(stderr, "    solved gap %d stick %d slide+ %d slide- %d; next changes %d (frozen %d); "
                   "peak force %.3e, largest tension %.3e, penetration %.3e\n",
                   counts[0], counts[1], counts[2], counts[3], changed, frozen, peak, tension, penetration);
    }
    if (next == statuses) {
      run.settled = true;
      break;
    }
    if (!seen.insert(next).second) {
      run.cycled = true;
      statuses = std::move(next);
      break;
    }
    statuses = std::move(next);
  }
  if (options.verbose) std::fprintf(stderr, "  outer: stage %.1e done after %d spring steps\n", stage, run.spring_steps);
  }

  // 2. The spring off: the statuses solved exactly, then Newton steps on the true problem; with
  //    film_inner, the film's statuses before each of them from the film alone (film_solver.h).
  MixedSystem::Answer last = mixed.solve(statuses);  // with the spring: the film's frozen surroundings
  mixed.clear_springs();
  const Condensed exact_rules = law_rules(problem, mixed.row_stiffness());
  std::set<std::vector<Active>> tried;
  for (int step = 0; step <= options.polish_steps; ++step) {
    if (options.film_inner) {
      const FilmRun film = options.band_inner
                               ? solve_band(problem, mixed, last, options.film_scale, options.band_spring * kappa_adherent)
                               : solve_film(problem, mixed, last, statuses, options.film_scale);
      run.film_solves += film.linear_solves;
      for (size_t q = 0; q < film.nodes.size(); ++q) statuses[film.nodes[q]] = film.statuses[q];
      if (options.verbose)
        std::fprintf(stderr, "  film: %zu nodes, %d dense solves, %s\n", film.nodes.size(), film.linear_solves,
                     film.settled ? "settled" : "NOT settled");
    }
    if (!tried.insert(statuses).second) break;
    const MixedSystem::Answer a = mixed.solve(statuses);
    consider(a, statuses, false);
    if (options.verbose) {  // where the spring-free answer breaks its law
      const Eigen::VectorXd d = problem.stop_jumps(a.u, a.r);
      const double peak = largest_nodal_force(a.r);
      double film_map = 0, load_map = 0;
      int worst = -1;
      double worst_map = 0;
      for (int k = 0; k < problem.num_nodes(); ++k) {
        const double map =
            natural_map(problem.law(k), a.r.segment<2>(2 * k), d.segment<2>(2 * k), problem.kappa().segment<2>(2 * k))
                .norm();
        const bool film = a.r.segment<2>(2 * k).norm() < options.film_scale * peak;
        (film ? film_map : load_map) = std::max(film ? film_map : load_map, map);
        if (map > worst_map) worst_map = map, worst = k;
      }
      const Residual res = contact_residual(problem, a.u, a.r, a.band_z);
      std::fprintf(stderr, "    natural map: film rows %.3e, load rows %.3e (peak force %.3e); worst node %d "
                   "status %d r (%.3e, %.3e) d (%.3e, %.3e); bodies",
                   film_map, load_map, peak, worst, worst >= 0 ? static_cast<int>(statuses[worst]) : -1,
                   worst >= 0 ? a.r[2 * worst] : 0.0, worst >= 0 ? a.r[2 * worst + 1] : 0.0,
                   worst >= 0 ? d[2 * worst] : 0.0, worst >= 0 ? d[2 * worst + 1] : 0.0);
      for (double b : res.per_body) std::fprintf(stderr, " %.2e", b);
      std::fprintf(stderr, "; interfaces");
      for (double b : res.per_interface) std::fprintf(stderr, " %.2e", b);
      std::fprintf(stderr, "\n");
    }
    if (best.residual.value() <= solver.tolerance) break;
    statuses = guess_statuses(exact_rules, a.r, problem.stop_jumps(a.u, a.r));
    last = a;
  }

  best.iterations = static_cast<int>(run.steps.size());
  best.converged = best.residual.value() <= solver.tolerance;
  best.stop_cause = best.converged ? StopCause::Converged
                    : best.residual.value() <= best.residual.floor() ? StopCause::RoundOffFloor
                                                                      : StopCause::IterationCap;
  best.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream msg;
  msg << (best.converged ? "converged" : "NOT converged") << " after " << best.iterations
      << " sparse factorisations (" << run.spring_steps << " with the film's spring), residual "
      << best.residual.value();
  best.message = msg.str();
  return run;
}

}  // namespace thinlayer
