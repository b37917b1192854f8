#include "core/solvers/fast_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "core/solvers/active_set.h"
#include "core/solvers/bonded_solve.h"
#include "core/solvers/floating_layer.h"
#include "core/solvers/friction_path.h"
#include "core/solvers/mixed_system.h"
#include "core/solvers/sparse_newton.h"
#include "core/solvers/stop_verdict.h"

namespace thinlayer {

namespace {

// The semismooth Newton steps on the whole system that follow the condensed solve (at most): from
// statuses settled with the selection spring they converge in one to three where they converge at
// all (measured on the scene set and the generator's seeds: docs/solvers.md).
constexpr int exact_steps_cap = 5;

StopCause stop_cause(const ContactProblem& problem, const Condensed& c, const std::vector<Active>& statuses,
                     const ActiveSetRun& run, const SolveReport& report, bool cap_reached, bool adrift) {
  if (!report.u.allFinite() || !report.r.allFinite() || !std::isfinite(report.residual.value()))
    return StopCause::NonFinite;
  if (floating_bodies_free(c, statuses)) return StopCause::Singular;
  if (report.converged) return StopCause::Converged;
  const StopCause iteration = adrift ? StopCause::LayerAdrift : cap_reached ? StopCause::IterationCap
                              : run.singular ? StopCause::Singular : StopCause::LossOfAccuracy;
  // The one rule (core/solvers/stop_verdict.h): this answer is not shown to be one linear system's
  // exact solution rounded to double, so it claims no round-off floor.
  LinearEvidence evidence;
  evidence.condition = report.condition_estimate;
  return stop_verdict(problem, report.u, report.r, report.residual, report.tolerance, evidence, iteration).cause;
}

std::string explain(const SolveReport& report, int max_iterations) {
  std::ostringstream why;
  switch (report.stop_cause) {
    case StopCause::IterationCap:
      why << "the cap of " << max_iterations << " active-set steps was reached";
      break;
    case StopCause::Singular:
      why << "a floating body is held by none of its contacts, so its rigid position is undetermined; "
          << "the minimum-norm position is reported";
      break;
    case StopCause::LossOfAccuracy:
      why << "the statuses settled but the linear solve of them stops short of the tolerance";
      break;
    case StopCause::NonFinite:
      why << "NaN or Inf in the iterate";
      break;
    case StopCause::RoundOffFloor:  // not claimed here without its proof (stop_verdict)
      break;
    case StopCause::LayerAdrift:
      why << "the floating layer is pushed by a force that only its selection spring resists; the proximal steps "
             "that follow it did not reach its exact position, which lies as far as the film's in-plane stiffness "
             "puts it; the best iterate is reported";
      break;
    case StopCause::Converged:
      break;
  }
  why << "; condition estimate " << report.condition_estimate;
  return why.str();
}

SolveReport attempt(const ContactProblem& problem, const CondensedInterface& condensed, const SolverOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SolveReport report;
  report.solver = "fast";
  report.tolerance = options.tolerance;
  const Condensed c = condense(problem, condensed, options.complementarity_scale, options.skip_frictionless_rows);
  const int nw = floating_unknowns(c);
  int max_iterations = options.max_iterations > 0 ? options.max_iterations : 200;

  Eigen::VectorXd r = Eigen::VectorXd::Zero(c.g0.size());
  Eigen::VectorXd w = Eigen::VectorXd::Zero(nw);
  if (options.initial_r.size()) r = options.initial_r;
  if (options.initial_w.size()) w = options.initial_w;
  std::vector<Active> statuses = guess_statuses(c, r, jump_part(c, r, w));
  ActiveSetRun run;
  int outer_steps = 0;   // floating layer: spring stages and proximal steps
  bool adrift = false;   // floating layer: the proximal steps kept following a pushed layer
  bool capped = false;
  report.method = nw == 0 ? "condensed active set" : "floating-layer ladder";
  if (nw == 0) {
    run = active_set(c, problem, statuses, r, w, max_iterations);
    report.iterations = run.iterations;
  } else {
    // A floating body (the thin layer): core/solvers/floating_layer.h.
    const FloatingLayerRun layer = solve_floating_layer(c, problem, condensed, options, r, w);
    r = layer.r;
    w = layer.x;
    statuses = layer.statuses;
    report.iterations = layer.newton_steps;
    outer_steps = layer.outer_steps;
    run.singular = layer.singular;
    run.rcond = layer.rcond;
    adrift = layer.adrift;
    capped = layer.capped;  // its work is bounded by its stages; a cap is only the caller's
  }

  report.r = r;
  report.w = w;
  report.u = condensed.displacement(problem, r, w);
  report.residual = contact_residual(problem, report.u, report.r, condensed.band_coordinates(w));
  // The statuses' own answer, solved exactly (core/solvers/mixed_system.h): one sparse LU of the
  // whole problem, without the condensation's round-off and without a floating layer's selection
  // spring (whose pull is part of the iterate's error). Taken where its residual is the smaller.
  // A supported problem that converged does not need it; a solve whose cap ran out does not get it
  // (a cap bounds the linear solves).
  // Where that answer's own statuses differ (a film released by the spring moves on), the
  // semismooth Newton steps go on from it on the whole system, each one sparse LU, until the
  // tolerance, a status set met before (a cycle), or exact_steps_cap.
  int exact = 0;
  const bool cap_spent = nw == 0 ? report.iterations >= max_iterations : capped;
  if (!cap_spent && (nw > 0 || !(report.residual.value() <= options.tolerance))) {
    MixedSystem mixed(problem);
    std::set<std::vector<Active>> tried;
    std::vector<Active> s = statuses;
    for (int step = 0; step < exact_steps_cap && tried.insert(s).second; ++step) {
      const MixedSystem::Answer answer = mixed.solve(s);
      ++report.iterations;
      if (answer.singular || !answer.u.allFinite() || !answer.r.allFinite()) break;
      const Residual residual = contact_residual(problem, answer.u, answer.r, answer.band_z);
      if (residual.value() < report.residual.value()) {
        report.u = answer.u;
        report.r = r = answer.r;
        report.w = w = condensed.floating_unknowns(answer.u, answer.band_z);
        report.residual = residual;
        statuses = s;
        exact = step + 1;
      }
      if (report.residual.value() <= options.tolerance) break;
      s = guess_statuses(c, answer.r, problem.stop_jumps(answer.u, answer.r));
    }
  }
  report.converged = report.residual.value() <= options.tolerance;
  // Capped at 1e300 so that it stays a number (an exactly singular system has rcond 0).
  // The worse of the two systems solved: the final active-set matrix and the bulk's CHOLMOD
  // factors (whose estimate is crude and optimistic, so it rarely decides).
  report.condition_estimate = 1.0 / std::max(std::min(run.rcond, condensed.rcond()), 1e-300);
  report.stop_cause =
      stop_cause(problem, c, statuses, run, report, nw == 0 ? report.iterations >= max_iterations : capped, adrift);
  report.converged = report.stop_cause == StopCause::Converged;
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream msg;
  msg << (report.converged ? "converged" : "NOT converged") << " after " << report.iterations << " active-set steps"
      << (outer_steps ? " in " + std::to_string(outer_steps) + " outer steps (spring stages and proximal steps)" : "")
      << (run.nsgs_sweeps ? " and " + std::to_string(run.nsgs_sweeps) + " NSGS sweeps" : "")
      << (exact ? "; the answer solved exactly without spring after " + std::to_string(exact) + " step(s)" : "")
      << ", residual " << report.residual.value()
      << " (tolerance " << options.tolerance << ")";
  if (!report.converged) msg << ": " << to_string(report.stop_cause) << " (" << explain(report, max_iterations) << ")";
  else if (report.condition_estimate > 1e12)
    msg << "; ill-conditioned: condition estimate " << report.condition_estimate;
  report.message = msg.str();
  return report;
}

// A body held by contact and friction alone, and no layer band: the sparse Newton first
// (core/solvers/sparse_newton.h); where it stops short, the condensed path from rest, its steps
// added and its message saying so. A Newton answer at its round-off floor (its residual, evaluated in
// extended precision, within what its digits can resolve) is final: the condensed path ends there too.
bool sparse_newton_first(const ContactProblem& problem, const SolverOptions& options) {
  return options.sparse_newton && takes_sparse_newton(problem) && options.friction_path.empty() && options.initial_r.size() == 0 &&
         options.initial_w.size() == 0;
}

SolveReport after_sparse_newton(const SparseNewtonRun& newton, SolveReport fallback) {
  fallback.iterations += newton.report.iterations;
  fallback.wall_time_s += newton.report.wall_time_s;
  fallback.method = fallback.method + " after sparse Newton";
  fallback.message += "; taken over from the sparse Newton, which stopped: " + newton.report.message;
  return fallback;
}

}  // namespace

SolveReport solve_fast(const ContactProblem& problem, const CondensedInterface& condensed,
                       const SolverOptions& options) {
  // A warm start of another scene's size is a caller's mistake, not something to ignore.
  if (options.initial_r.size() && options.initial_r.size() != 2 * problem.num_nodes())
    throw std::invalid_argument("solve_fast: the warm start's forces have " + std::to_string(options.initial_r.size()) +
                                " entries, the problem " + std::to_string(2 * problem.num_nodes()));
  if (options.initial_w.size() && options.initial_w.size() != condensed.num_floating_unknowns())
    throw std::invalid_argument("solve_fast: the warm start's layer DOFs have " +
                                std::to_string(options.initial_w.size()) + " entries, the problem " +
                                std::to_string(condensed.num_floating_unknowns()));
  if (every_interface_bonded(problem)) return solve_bonded(problem, options);  // linear: no status to search
  if (sparse_newton_first(problem, options)) {
    const SparseNewtonRun newton = solve_sparse_newton(problem, options);
    if (newton.report.converged || newton.report.stop_cause == StopCause::RoundOffFloor) return newton.report;
    return after_sparse_newton(newton, attempt(problem, condensed, options));
  }
  if (!options.friction_path.empty()) return solve_fast_along_friction_path(problem, condensed, options);
  return attempt(problem, condensed, options);
}

SolveReport solve_fast(const ContactProblem& problem, const SolverOptions& options) {
  if (every_interface_bonded(problem)) return solve_bonded(problem, options);  // nothing to condense
  if (sparse_newton_first(problem, options)) {  // condensed only if it has to take over
    const SparseNewtonRun newton = solve_sparse_newton(problem, options);
    if (newton.report.converged || newton.report.stop_cause == StopCause::RoundOffFloor) return newton.report;
    const CondensedInterface condensed(problem);
    return after_sparse_newton(newton, attempt(problem, condensed, options));
  }
  const CondensedInterface condensed(problem);
  return solve_fast(problem, condensed, options);
}

}  // namespace thinlayer
