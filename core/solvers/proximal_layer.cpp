#include "core/solvers/proximal_layer.h"

#include <algorithm>
#include <limits>

#include "core/solvers/stagnation.h"

namespace thinlayer {

FloatingLayerRun solve_layer_proximal(const Condensed& c, const ContactProblem& problem,
                                      const CondensedInterface& condensed, const SolverOptions& options,
                                      Eigen::VectorXd r, Eigen::VectorXd w, int max_steps) {
  // The proximal term makes every step well posed and leaves the answer unchanged: at
  // convergence w equals the previous w and the pull vanishes. α shrinks tenfold while the
  // steps settle quickly and grows back tenfold when they do not.
  FloatingLayerRun run;
  Condensed proximal = c;
  const Eigen::VectorXd P = c.S.diagonal().cwiseAbs().cwiseMax(1e-300);
  double alpha = options.proximal_weight;
  auto true_residual = [&](const Eigen::VectorXd& rr, const Eigen::VectorXd& ww) {
    return contact_residual(problem, condensed.displacement(problem, rr, ww), rr).value();
  };
  std::vector<Active> statuses = guess_statuses(c, r, jump_part(c, r, w));
  run.residual = std::numeric_limits<double>::infinity();  // of the best iterate, kept in run
  // A window of 100 steps: this path may crawl and still get there (the dovetail's (e) at
  // ε = 5e-4 gains 1 % a step for 250 steps, then converges).
  Stagnation stagnation(100);
  while (run.newton_steps < max_steps) {
    ++run.outer_steps;
    proximal.S = c.S;
    proximal.S.diagonal() += alpha * P;
    proximal.f_L = c.f_L + alpha * P.cwiseProduct(w);
    const ActiveSetRun step = active_set(proximal, problem, statuses, r, w, max_steps - run.newton_steps);
    run.newton_steps += step.iterations;
    double residual = true_residual(r, w);
    if (residual < run.residual) {
      run.r = r;
      run.w = w;
      run.statuses = statuses;
      run.residual = residual;
    }
    if (residual <= options.tolerance) break;
    if (step.settled) {
      const Step polish = solve_statuses(c, statuses);
      ++run.newton_steps;
      const double polished = true_residual(polish.r, polish.w);
      if (polished < run.residual) {
        run.r = polish.r;
        run.w = polish.w;
        run.statuses = statuses;
        run.residual = polished;
      }
      if (polished <= options.tolerance) break;
    }
    if (stagnation.after_step(run.residual)) {
      run.stagnated = true;
      break;
    }
    const bool quick = step.settled && step.iterations <= 3;
    alpha = quick ? std::max(alpha * 0.1, options.proximal_weight * 1e-6) : std::min(alpha * 10, options.proximal_weight);
  }
  const Step last = solve_statuses(c, run.statuses);  // the conditioning of the final statuses
  run.singular = last.singular;
  run.rcond = last.rcond;
  return run;
}

}  // namespace thinlayer
