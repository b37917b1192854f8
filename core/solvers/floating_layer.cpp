#include "core/solvers/floating_layer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/linalg/anderson.h"
#include "core/solvers/layer_dual.h"
#include "core/solvers/tresca.h"

namespace thinlayer {

namespace {

// The spring stages, as exponents k of ρ = κ 10⁻ᵏ: eliminated (1) while W̃'s conditioning,
// about κ/ρ, leaves its solves accurate, mixed (2) below. The last spring is the proximal steps'
// (3), which converge like 1 − k_film/ρ on a film mode of stiffness k_film: at ε = 1e-8 a film's
// membrane is about 1e-10 daN/mm a column (the dovetail's (f): E'ε/h = 2e-4 · 1e-8 / 0.025),
// 1e-14 κ. Ending at 1e-12 κ, seven dovetail scenes at ε ≤ 1e-6 stopped "layer adrift" at
// 1.3e-10 … 2.4e-9; ending at 1e-14 κ for every scene, they converge but (e) at 1e-7 and a
// validity scene of (a) no longer do; so 1e-14 κ is a second round for an adrift layer only
// (issue 14, measured; a stage at 1e-16 κ more did not finish the scene set in 10 minutes).
constexpr int dual_stages[] = {0, 2, 4, 6, 8};
constexpr int mixed_stages[] = {10, 12};
constexpr int adrift_stage = 14;
constexpr double spring_floor = 1e-13;  // × the layer's largest stiffness on the spring's rows: see `spring`
constexpr int active_set_cap = 60;   // active-set steps per stage before the Tresca fixed point
constexpr int settle_cap = 30;       // mixed Newton steps per stage or proximal step
constexpr int proximal_cap = 30;
// Past the tolerance the proximal steps go on towards the round-off floor while they still improve
// the answer (at most `polish_cap` of them, ending after `polish_patience` in a row that do not): at tolerance 1e-10 the dovetail's case (d) at
// ε = 1e-6 stops at residual 3.9e-11 with its tenon reaction 2.9e-8 from the answer at 3.3e-13
// (measured); a few more steps of the same linear map make the digits the residual suggests true.
constexpr double polish_factor = 1e-2;  // aim at tolerance × this; stop earlier where steps stall
constexpr int polish_cap = 10;
constexpr int polish_patience = 3;
constexpr int max_refinements = 6;  // intermediate springs inserted between the mixed stages
constexpr int anderson_memory = 5;
constexpr int unlimited_solves = std::numeric_limits<int>::max();

// Keeps the best iterate met, judged on the true SPEC residual.
class BestIterate {
 public:
  BestIterate(const ContactProblem& problem, const CondensedInterface& condensed)
      : problem_(problem), condensed_(condensed) {}
  // The candidate (r, x) of the last mixed solve, whose conditioning is in `last`.
  double consider(const Eigen::VectorXd& r, const Eigen::VectorXd& x, const std::vector<Active>& statuses,
                  const Step& last, FloatingLayerRun& run) const {
    const double residual = contact_residual(problem_, condensed_.displacement(problem_, r, x), r,
                                             condensed_.band_coordinates(x)).value();
    if (residual < run.residual) {
      run.r = r;
      run.x = x;
      run.statuses = statuses;
      run.residual = residual;
      run.singular = last.singular;
      run.rcond = last.rcond;
    }
    return residual;
  }

 private:
  const ContactProblem& problem_;
  const CondensedInterface& condensed_;
};

// The linear solves left under SolverOptions::max_iterations (unlimited when it is 0). One solve
// is kept back for the answer: the mixed solve of the statuses found so far (settle_mixed), so
// that a capped solve still returns an iterate and never exceeds its cap.
struct Budget {
  int cap = 0;
  int left(const FloatingLayerRun& run, int wanted) const {
    return cap > 0 ? std::max(0, std::min(wanted, cap - 1 - run.newton_steps)) : wanted;
  }
  bool spent(const FloatingLayerRun& run) const { return cap > 0 && run.newton_steps >= cap - 1; }
};

// Stage 1: the statuses on the eliminated problem, from the previous stage's forces r.
void settle_eliminated(const Condensed& reduced, const ContactProblem& problem, const Budget& budget,
                       std::vector<Active>& statuses, Eigen::VectorXd& r, FloatingLayerRun& run) {
  Eigen::VectorXd none;
  statuses = guess_statuses(reduced, r, jump_part(reduced, r, none));
  const ActiveSetRun first = active_set(reduced, problem, statuses, r, none, budget.left(run, active_set_cap));
  run.newton_steps += first.iterations;
  if (first.settled || budget.spent(run)) return;
  // The active set cycles (a non-associated law): the Tresca fixed point cannot; its statuses
  // then start a last active-set run.
  const TrescaRun tresca = solve_tresca_fixed_point(reduced, r, 100, 1e-10, budget.left(run, unlimited_solves));
  run.newton_steps += tresca.qp_iterations;
  statuses = guess_statuses(reduced, r, jump_part(reduced, r, none));
  run.newton_steps += active_set(reduced, problem, statuses, r, none, budget.left(run, settle_cap)).iterations;
}

// Newton steps on the mixed (r, x) system until the statuses reproduce themselves; `last` is the
// last step's system (for its conditioning).
bool settle_mixed(const Condensed& c, const Budget& budget, std::vector<Active>& statuses, Eigen::VectorXd& r,
                  Eigen::VectorXd& x, Step& last, FloatingLayerRun& run) {
  const int steps = std::max(1, budget.left(run, settle_cap));  // one solve at least: the answer's,
                                                                 // which the budget keeps back
  for (int step = 0; step < steps; ++step) {
    last = solve_statuses(c, statuses);
    ++run.newton_steps;
    r = last.r;
    x = last.w;
    std::vector<Active> next = guess_statuses(c, r, jump_part(c, r, x));
    if (next == statuses) return true;
    statuses = std::move(next);
  }
  return false;
}

// c with the spring K_s anchored at `anchor`, its statuses guessed on the eliminated problem's
// scale κ_row = 1 / W̃_ii (which the anchor does not change).
Condensed mixed_problem(const Condensed& c, const Eigen::MatrixXd& K_s, const Eigen::VectorXd& anchor,
                        const Eigen::VectorXd& kappa) {
  Condensed mixed = with_spring(c, K_s, anchor);
  mixed.kappa = kappa;
  return mixed;
}

}  // namespace

FloatingLayerRun solve_floating_layer(const Condensed& c, const ContactProblem& problem,
                                      const CondensedInterface& condensed, const SolverOptions& options,
                                      Eigen::VectorXd r, Eigen::VectorXd x) {
  FloatingLayerRun run;
  run.residual = std::numeric_limits<double>::infinity();
  const BestIterate best(problem, condensed);
  const Eigen::MatrixXd P = condensed.floating_selection(options.layer_selection);
  const double kappa = adherent_stiffness(problem);
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(x.size());
  const Budget budget{options.max_iterations};
  // A spring weaker than double precision can hold against the layer's own stiffness is no spring:
  // the Jacobi-scaled layer's floating modes sit at spring / S_ii on the rows it holds, and far
  // below 1e-13 its Cholesky fails (a layer much stiffer than its adherents: the bar's rows 1, 2, 4
  // at eps >= 1 mm). The spring is floored at spring_floor × the layer's largest stiffness on those
  // rows (daN/mm). On the 119 scenes of the scene set it never binds (the same steps and residuals).
  double held = 0;  // the layer's largest stiffness on the rows the spring holds
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    if (P(i, i) > 0) held = std::max(held, std::abs(c.S(i, i)));
  const double floor = spring_floor * held;
  auto spring = [&](double k) { return Eigen::MatrixXd(std::max(kappa * std::pow(10.0, -k), floor) * P); };
  auto report = [&](const char* what, double k, double residual) {
    if (!options.verbose) return;
    std::fprintf(stderr, "  layer: %s spring kappa*1e-%g, %d linear solves so far", what, k, run.newton_steps);
    if (std::isfinite(residual)) std::fprintf(stderr, ", residual %.3e", residual);
    std::fprintf(stderr, "\n");
  };

  // 1. The statuses on the eliminated layer, as the spring weakens.
  std::vector<Active> statuses;
  double last = 0;
  for (int k : dual_stages) {
    if (budget.spent(run)) break;
    ++run.outer_steps;
    last = k;
    settle_eliminated(eliminate_layer(c, spring(k), rest), problem, budget, statuses, r, run);
    report("eliminated,", k, std::numeric_limits<double>::quiet_NaN());
  }
  // 2. Weaker springs, on the mixed system (the first of them also when the budget ran out, so
  //    that the statuses found so far give an answer). A spring whose statuses do not settle is
  //    approached in smaller steps from the last one that did (at most `refinements` halvings).
  Eigen::VectorXd kappa_last;
  Step last_step;
  std::vector<double> targets(std::begin(mixed_stages), std::end(mixed_stages));
  std::vector<Active> settled_statuses = statuses;
  Eigen::VectorXd settled_r = r, settled_x = x;
  int settled_in_a_row = 0;
  // Not converged, not capped, and the last proximal steps each re-settled the same statuses: the
  // layer is being followed along a push, not searched for.
  auto left_adrift = [&] {
    return !(run.residual <= options.tolerance) && settled_in_a_row >= 5 && !budget.spent(run);
  };
  // Stages 2 and 3 run once with the springs of mixed_stages and, where the layer is left adrift
  // after them (a film softer than the last spring, which the proximal steps follow at a rate
  // 1 − k_film/ρ), once more from the same settled state with one weaker spring, adrift_stage.
  for (int round = 0; round < 2; ++round) {
    for (int refinements = 0; !targets.empty();) {
      if (budget.spent(run) && std::isfinite(run.residual)) break;
      ++run.outer_steps;
      const double k = targets.front();
      const Eigen::MatrixXd K_s = spring(k);
      const Condensed reduced = eliminate_layer(c, K_s, rest);
      statuses = settled_statuses;
      r = settled_r;
      bool settled = settle_mixed(mixed_problem(c, K_s, rest, reduced.kappa), budget, statuses, r, x, last_step, run);
      if (!settled && !budget.spent(run)) {
        // The weaker spring frees the layer more than full Newton steps can follow: find the
        // statuses on the eliminated layer (coarse but robust at this spring), then settle them.
        statuses = settled_statuses;
        r = settled_r;
        settle_eliminated(reduced, problem, budget, statuses, r, run);
        settled = settle_mixed(mixed_problem(c, K_s, rest, reduced.kappa), budget, statuses, r, x, last_step, run);
      }
      report(settled ? "mixed," : "mixed (not settled),", k, best.consider(r, x, statuses, last_step, run));
      if (!settled && refinements < max_refinements && k - last > 0.25) {
        ++refinements;
        targets.insert(targets.begin(), 0.5 * (last + k));
        continue;
      }
      last = k;
      kappa_last = reduced.kappa;
      settled_statuses = statuses;
      settled_r = r;
      settled_x = x;
      targets.erase(targets.begin());
    }
    const std::vector<Active> staged_statuses = settled_statuses;
    const Eigen::VectorXd staged_r = settled_r, staged_x = settled_x;
    const double staged_last = last;
    settled_in_a_row = 0;
    // 3. Proximal steps: the spring's anchor follows the layer until its pull is gone. The map
    //    anchor → settled x is linear while the statuses hold: Anderson-accelerated. A step whose
    //    statuses do not settle is retried shorter, from the last settled point.
    AndersonAcceleration anderson(anderson_memory);
    Eigen::VectorXd anchor = rest, proposal = settled_x;
    double fraction = 1;
    const Eigen::MatrixXd K_last = spring(last);  // the proximal steps' spring, fixed; only its anchor moves
    auto polished = [&] { return run.residual <= options.tolerance * polish_factor; };
    int polish_steps = 0, stale = 0;
    for (int step = 0; step < proximal_cap && !polished() && !budget.spent(run); ++step) {
      const bool polishing = run.residual <= options.tolerance;
      if (polishing && ++polish_steps > polish_cap) break;
      const double before = run.residual;
      ++run.outer_steps;
      const Eigen::VectorXd trial = anchor + fraction * (proposal - anchor);
      r = settled_r;
      x = settled_x;
      statuses = settled_statuses;
      const bool settled =
          settle_mixed(mixed_problem(c, K_last, trial, kappa_last), budget, statuses, r, x, last_step, run);
      report(polishing ? "proximal (polish)," : "proximal,", last, best.consider(r, x, statuses, last_step, run));
      // At the floor of what these steps reach once three in a row improve nothing.
      stale = polishing && !(run.residual < before) ? stale + 1 : 0;
      if (stale >= polish_patience) break;
      if (settled) {
        ++settled_in_a_row;
        anchor = trial;
        settled_r = r;
        settled_x = x;
        settled_statuses = statuses;
        proposal = anderson.next(anchor, x);
        fraction = std::min(1.0, 2 * fraction);
      } else {
        settled_in_a_row = 0;
        anderson.reset();
        fraction *= 0.25;
        if (fraction < 1e-3) break;
      }
    }
    if (!left_adrift() || round == 1) break;
    settled_statuses = staged_statuses;
    settled_r = staged_r;
    settled_x = staged_x;
    last = staged_last;
    targets = {adrift_stage};
  }
  run.capped = budget.spent(run);
  run.adrift = left_adrift();
  if (!(run.residual <= options.tolerance) || floating_bodies_free(c, run.statuses)) {
    // Not converged, or the layer touches nothing: report the conditioning of the true
    // (spring-free) problem with these statuses, which says whether the layer was left free.
    const Step spring_free = solve_statuses(c, run.statuses);
    run.singular = spring_free.singular;
    run.rcond = spring_free.rcond;
  }
  return run;
}

}  // namespace thinlayer
