#include "core/solvers/sparse_newton.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <array>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include "core/linalg/factor_memory.h"
#include "core/solvers/bonded_solve.h"
#include "core/solvers/mixed_system.h"
#include "core/solvers/stop_verdict.h"

namespace thinlayer {

bool takes_sparse_newton(const ContactProblem& problem) {
  const LinearSystem& system = problem.system();
  if (every_interface_bonded(problem) || !system.floating_bands().empty()) return false;
  for (int i = 0; i < system.num_free(); ++i)
    if (system.floating(i)) return true;
  return false;
}

std::vector<Active> stuck_statuses(const ContactProblem& problem) {
  std::vector<Active> statuses(problem.num_nodes());
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceLaw& law = problem.law(k);
    if (law.bilateral) statuses[k] = law.normal_active() || law.K_T() > 0 ? Active::Bonded : Active::Gap;
    else if (!law.normal_active()) statuses[k] = Active::Gap;
    else statuses[k] = law.tangential_active() ? Active::Stick : Active::Frictionless;
  }
  return statuses;
}

namespace {

// The floating body each node's sides belong to (-1: none, or a supported body).
std::vector<std::array<int, 2>> floating_sides(const ContactProblem& problem) {
  const LinearSystem& system = problem.system();
  auto floating_body = [&](int global_dof) {
    if (global_dof < 0) return -1;
    const int i = system.free_index(global_dof);
    return i >= 0 && system.floating(i) ? system.body_of(i) : -1;
  };
  std::vector<std::array<int, 2>> sides(problem.num_nodes());
  for (int k = 0; k < problem.num_nodes(); ++k)
    sides[k] = {floating_body(problem.node(k).plus_dof_x), floating_body(problem.node(k).minus_dof_x)};
  return sides;
}

bool holds(Active a) { return a == Active::Stick || a == Active::Bonded; }
bool slides(Active a) { return a == Active::SlidePositive || a == Active::SlideNegative; }

// A body held by friction alone, below what friction can hold (a load statics proves above it is
// refused before the solve, cases/scene/load_path.h), keeps at least one stuck node at its solution: were every
// node of its faces sliding, its friction forces f|r_N| would balance its load exactly — the
// capacity. A guess that lets every node of such a body slide is therefore wrong, and it leaves the
// body's translation along its faces free (a singular step: the Newton iterates of a double lap with
// unequal clamping pressures fell there and cycled). Such a guess keeps stuck, on that body, the
// sliding node whose natural map is least sure of the slide: the smallest |t_T| / (f |t_N|), t = r − κ d.
// The argument takes the faces along the load (a lap); a body wedged between inclined faces may slide
// on all of them below that capacity, and then the rule keeps the Newton from its answer: it stops
// short and the condensed path, which has no such rule, takes over.
void keep_a_hold(const ContactProblem& problem, const Condensed& rules, const std::vector<std::array<int, 2>>& sides,
                 const Eigen::VectorXd& r, const Eigen::VectorXd& d, std::vector<Active>& next) {
  std::map<int, bool> held;
  for (int k = 0; k < problem.num_nodes(); ++k)
    for (int b : sides[k])
      if (b >= 0) held[b] = held[b] || holds(next[k]);
  for (const auto& [body, is_held] : held) {
    if (is_held) continue;
    int keep = -1;
    double least = std::numeric_limits<double>::infinity();
    for (int k = 0; k < problem.num_nodes(); ++k) {
      if ((sides[k][0] != body && sides[k][1] != body) || !slides(next[k])) continue;
      const double t_N = r[2 * k] - rules.kappa[2 * k] * d[2 * k];
      const double t_T = r[2 * k + 1] - rules.kappa[2 * k + 1] * d[2 * k + 1];
      const double excess = std::abs(t_T) / (problem.law(k).friction * std::abs(t_N));
      if (excess < least) least = excess, keep = k;
    }
    if (keep >= 0) next[keep] = Active::Stick;
  }
}

// The one rule (core/solvers/stop_verdict.h): where the statuses settled, the best answer is one
// linear system's (that of the last factorisation) and the verdict reads its evidence; otherwise the
// iteration's own cause, and no round-off floor.
StopVerdict stop_cause(const ContactProblem& problem, const SparseNewtonRun& run, bool capped, bool at_round_off,
                       bool best_is_last, const MixedSystem& mixed) {
  const SolveReport& r = run.report;
  if (!std::isfinite(r.residual.value())) {
    StopVerdict v;
    v.cause = run.singular ? StopCause::Singular : StopCause::NonFinite;
    v.why = to_string(v.cause);
    return v;
  }
  LinearEvidence evidence;
  evidence.condition = r.condition_estimate;
  if (run.settled && best_is_last && !(r.residual.value() <= r.tolerance)) {
    evidence.linear = true;
    evidence.at_round_off = at_round_off;
    const MixedSystem::NearNull near = mixed.near_null();
    evidence.condition = near.condition;
    evidence.free_motion = near.u;
  }
  const StopCause iteration = run.singular ? StopCause::Singular
                              : capped || run.cycled ? StopCause::IterationCap : StopCause::LossOfAccuracy;
  return stop_verdict(problem, r.u, r.r, r.residual, r.tolerance, evidence, iteration);
}

}  // namespace

SparseNewtonRun solve_sparse_newton(const ContactProblem& problem, const SolverOptions& options,
                                    std::vector<Active> seed, int max_steps) {
  const auto start = std::chrono::steady_clock::now();
  SparseNewtonRun run;
  SolveReport& best = run.report;
  best.solver = "fast";
  best.method = "sparse Newton";
  best.tolerance = options.tolerance;
  best.residual.interface = best.residual.bulk = std::numeric_limits<double>::infinity();
  const FactorsFromTheHeap reuse_factor_pages;  // one factorisation a step, on one pattern
  MixedSystem mixed(problem);
  // κ_i: the row's stiffness with everything else held (MixedSystem::row_stiffness). Its size
  // decides only where a row both carries a force and opens or slips the wrong way; the statuses
  // of an exact Newton step have r = 0 or d = 0 on each row.
  const Condensed rules = law_rules(problem, mixed.row_stiffness());
  const std::vector<std::array<int, 2>> sides = floating_sides(problem);
  // The statuses the natural map reads at (u, r), a friction-held body keeping a hold.
  auto guess_at = [&](const Eigen::VectorXd& u, const Eigen::VectorXd& r) {
    const Eigen::VectorXd d = problem.stop_jumps(u, r);
    std::vector<Active> next = guess_statuses(rules, r, d);
    keep_a_hold(problem, rules, sides, r, d, next);
    return next;
  };
  std::vector<Active> statuses = seed.empty() ? stuck_statuses(problem) : std::move(seed);
  std::set<std::vector<Active>> seen{statuses};
  // The iterate the statuses are guessed from: each step's answer, or — where that answer's residual
  // is larger than the iterate's — the first point towards it, x + α (answer − x), α = 1/2, 1/4, …,
  // whose residual is smaller (a backtracking on the SPEC residual, Armijo's sufficient decrease with
  // the customary 1e-4). Both ends are equilibria of the bodies (K u = F + Bᵀ r is linear), so every
  // point between is one too: the backtracking moves only the interface's natural map. Plain Newton
  // on the statuses cycles where a whole face slides and the body's hold moves to the other face
  // (pressures unequal on its two faces); GetFEM's generalized Newton fails on the same scenes.
  Eigen::VectorXd x_u, x_r;
  double x_residual = std::numeric_limits<double>::infinity();
  bool best_at_round_off = false, best_is_last = false;
  int steps = 0;
  for (; steps < max_steps; ++steps) {
    best_is_last = false;
    const MixedSystem::Answer a = mixed.solve(statuses);
    if (a.singular || !a.u.allFinite() || !a.r.allFinite()) {
      run.singular = true;
      break;
    }
    const Residual residual = contact_residual(problem, a.u, a.r, a.band_z);
    if (options.verbose)
      std::fprintf(stderr, "  sparse Newton: step %d, residual %.3e\n", steps + 1, residual.value());
    if (residual.value() < best.residual.value()) {
      best.u = a.u;
      best.r = a.r;
      best.residual = residual;
      best.condition_estimate = 1.0 / std::max(a.rcond, 1e-300);
      best_at_round_off = a.at_round_off;
      best_is_last = true;
    }
    if (residual.value() <= options.tolerance) {
      ++steps;
      break;
    }
    bool full_step = true;
    if (residual.value() < x_residual || x_u.size() == 0) {
      x_u = a.u, x_r = a.r, x_residual = residual.value();
    } else {
      full_step = false;
      double alpha = 0.5;
      for (; alpha >= 1.0 / 64; alpha /= 2) {
        const Eigen::VectorXd u = x_u + alpha * (a.u - x_u), r = x_r + alpha * (a.r - x_r);
        const double value = contact_residual(problem, u, r, {}).value();
        if (value <= (1 - 1e-4 * alpha) * x_residual) {
          x_u = u, x_r = r, x_residual = value;
          break;
        }
      }
      if (alpha < 1.0 / 64) x_u = a.u, x_r = a.r, x_residual = residual.value();  // no decrease: take the step
      if (options.verbose) std::fprintf(stderr, "  sparse Newton: damped to %.3e\n", x_residual);
    }
    std::vector<Active> next = guess_at(x_u, x_r);
    if (!full_step && next == statuses) {
      // The damped point asks for the statuses just solved: their answer is a, so the next guess is a's.
      x_u = a.u, x_r = a.r, x_residual = residual.value();
      next = guess_at(x_u, x_r);
      full_step = true;
    }
    if (next == statuses && full_step) {  // the statuses' own answer, and still above the tolerance
      run.settled = true;
      ++steps;
      break;
    }
    if (!seen.insert(next).second && full_step) {
      run.cycled = true;
      ++steps;
      break;
    }
    if (options.verbose) {
      int changed = 0, gap = 0, stick = 0, slide = 0;
      for (std::size_t k = 0; k < next.size(); ++k) {
        changed += next[k] != statuses[k];
        gap += next[k] == Active::Gap, stick += holds(next[k]), slide += slides(next[k]);
      }
      std::fprintf(stderr, "  sparse Newton: %d statuses change (next: gap %d, stick %d, slide %d)\n", changed, gap, stick, slide);
    }
    statuses = std::move(next);
  }
  best.iterations = steps;
  // The settled statuses' answer is the last factorisation's; the verdict reads it only if it is the best.
  const StopVerdict verdict = stop_cause(problem, run, steps >= max_steps, best_is_last && best_at_round_off,
                                         best_is_last, mixed);
  best.stop_cause = verdict.cause;
  best.converged = verdict.converged;
  best.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream msg;
  msg << (best.converged ? "converged" : "NOT converged") << " after " << steps
      << " semismooth Newton steps on the whole sparse system from the bonded solve, residual " << best.residual.value()
      << " (tolerance " << options.tolerance << ")";
  if (!best.converged) msg << ": " << verdict.why << (run.cycled ? " (a status set came back)" : "");
  best.message = msg.str();
  return run;
}

}  // namespace thinlayer
