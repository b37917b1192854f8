#include "core/solvers/tnnmg.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "core/linalg/anderson.h"
#include "core/linalg/factor_memory.h"
#include "core/linalg/sparse_block.h"
#include "core/linalg/sparse_cholesky.h"
#include "core/solvers/block_minimiser.h"
#include "core/solvers/descent_blocks.h"
#include "core/solvers/kink_line_search.h"
#include "core/solvers/layer_smoother.h"
#include "core/solvers/mixed_system.h"

namespace thinlayer {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The truncated correction's rows: a kink held (d = 0), a slide's force given (λ = ±s, r = −λ), an
// open row's zero. With `coulomb`, a slide's force is Coulomb's instead (r_T = ∓f r_N), and a row
// whose normal is open carries no tangential force.
std::vector<RowCondition> correction_rows(const ContactProblem& problem, const std::vector<RowKind>& kind,
                                          const std::vector<RowState>& state, const Eigen::VectorXd& row_threshold,
                                          bool coulomb) {
  std::vector<RowCondition> rows(state.size());
  for (size_t i = 0; i < state.size(); ++i) {
    if (kind[i] == RowKind::Free) continue;  // r = 0
    if (state[i] == RowState::Kink) rows[i].jump = true;
    else if (state[i] == RowState::Plus) rows[i].force = -row_threshold[i];
    else if (state[i] == RowState::Minus) rows[i].force = row_threshold[i];
  }
  if (coulomb)
    for (int k = 0; k < problem.num_nodes(); ++k) {
      RowCondition& T = rows[2 * k + 1];
      if (kind[2 * k + 1] != RowKind::Friction) continue;
      const double f = problem.law(k).friction;
      if (state[2 * k] != RowState::Kink) T = RowCondition{};       // open: no friction force
      else if (state[2 * k + 1] == RowState::Plus) T = {false, 0, -f};  // r_T = f r_N (≤ 0)
      else if (state[2 * k + 1] == RowState::Minus) T = {false, 0, f};  // r_T = −f r_N (≥ 0)
    }
  return rows;
}

// The rows the correction holds at their kink: those the smoother left there, and those it left on
// another branch with a jump that is zero to working precision — within the round-off of evaluating
// d = B y + g (n u (|B||y| + |g|) for a row of n terms, u the unit round-off). Such a row has left
// its kink by less than d's own digits; were it let slide or open, the first point along the
// correction would cross that kink (or close that gap) at α ≈ 0 and stall the search.
std::vector<RowState> truncated(const MixedSystem& mixed, const Eigen::VectorXd& g_D, const std::vector<RowKind>& kind,
                                std::vector<RowState> state, const Eigen::VectorXd& y) {
  constexpr double unit_roundoff = 0.5 * std::numeric_limits<double>::epsilon();
  const auto& B = mixed.B_y();
  for (int row = 0; row < B.rows(); ++row) {
    if (state[row] == RowState::Kink || kind[row] == RowKind::Free || kind[row] == RowKind::Equality) continue;
    double d = g_D[row], size = std::abs(g_D[row]);
    int terms = 1;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(B, row); it; ++it, ++terms) {
      d += it.value() * y[it.col()];
      size += std::abs(it.value() * y[it.col()]);
    }
    if (std::abs(d) <= terms * unit_roundoff * size) state[row] = RowState::Kink;
  }
  return state;
}

// The thresholds a set of forces gives, per node: f·max(0, −r_N) where the law has friction.
Eigen::VectorXd coulomb_thresholds(const ContactProblem& problem, const Eigen::VectorXd& r) {
  Eigen::VectorXd s = Eigen::VectorXd::Zero(problem.num_nodes());
  for (int k = 0; k < problem.num_nodes(); ++k)
    if (problem.law(k).tangential_active() && !problem.law(k).bilateral) s[k] = problem.law(k).friction * std::max(0.0, -r[2 * k]);
  return s;
}

Eigen::VectorXd per_row(const Eigen::VectorXd& node_threshold) {
  Eigen::VectorXd t = Eigen::VectorXd::Zero(2 * node_threshold.size());
  for (Eigen::Index k = 0; k < node_threshold.size(); ++k) t[2 * k + 1] = node_threshold[k];
  return t;
}

// The translations of the film columns whose rows are all off their kinks: held by the membrane
// alone, they are what leaves a correction's face singular.
std::vector<int> loose_translations(const MixedSystem& mixed, const DescentBlocks& blocks,
                                    const std::vector<RowState>& state, bool all) {
  std::vector<int> out;
  for (int b = 0; b < mixed.num_bands(); ++b) {
    const BandLayout& L = mixed.band_layout(b);
    for (int i = 0; i < L.columns; ++i) {
      const int t = mixed.band_offset(b) + L.t(i);
      bool held = false;
      if (!all)
        for (const DescentBlock& block : blocks.blocks)
          if (std::binary_search(block.y.begin(), block.y.end(), t))
            for (int row : block.rows) held = held || state[row] == RowState::Kink;
      if (!held) out.push_back(t), out.push_back(t + 1);
    }
  }
  return out;
}

}  // namespace

TnnmgRun solve_tnnmg(const ContactProblem& problem, const SolverOptions& options, const TnnmgOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  TnnmgRun run;
  SolveReport& best = run.report;
  best.solver = "fast";
  best.method = "layer descent (TNNMG)";
  best.tolerance = options.tolerance;
  best.residual.interface = best.residual.bulk = std::numeric_limits<double>::infinity();
  if (!layer_descent_applies(problem)) {
    run.applies = false;
    run.why_not = "no layer band, or an interface law with a finite spring";
    return run;
  }
  const FactorsFromTheHeap reuse_factor_pages;
  MixedSystem mixed(problem);
  const DescentBlocks blocks = descent_blocks(mixed);
  LayerSmoother smoother(mixed, problem, blocks);
  const bool tresca = opt.tresca_thresholds.size() > 0;
  std::vector<Eigen::VectorXd> thresholds_history;

  auto judge = [&](const MixedSystem::Answer& a, const Eigen::VectorXd& y) {
    if (a.singular || !a.u.allFinite() || !a.r.allFinite()) return std::numeric_limits<double>::infinity();
    const Residual residual = contact_residual(problem, a.u, a.r, a.band_z);
    if (residual.value() < best.residual.value()) {
      best.u = a.u;
      best.r = a.r;
      best.residual = residual;
      best.condition_estimate = 1.0 / std::max(a.rcond, 1e-300);
      run.y = y;
    }
    return residual.value();
  };

  // The start: given, or the joint glued (every row at its kink).
  Eigen::VectorXd y, s;
  if (opt.start_y.size()) {
    y = opt.start_y;
    s = opt.start_thresholds.size() ? opt.start_thresholds : Eigen::VectorXd::Zero(problem.num_nodes());
  } else {
    const std::vector<RowKind> glued = tresca_rows(problem, Eigen::VectorXd::Constant(problem.num_nodes(), 1.0));
    std::vector<RowCondition> rows(glued.size());
    for (size_t i = 0; i < glued.size(); ++i) rows[i].jump = glued[i] != RowKind::Free;
    const MixedSystem::Answer a = mixed.solve(rows);
    ++run.factorisations;
    y = a.singular ? Eigen::VectorXd::Zero(mixed.num_unknowns()) : a.y;
    s = a.singular ? Eigen::VectorXd::Zero(problem.num_nodes()) : coulomb_thresholds(problem, a.r);
  }
  if (tresca) s = opt.tresca_thresholds;
  AndersonAcceleration anderson(5);
  std::vector<RowState> previous;
  bool converged = false;

  while (run.factorisations < opt.max_factorisations && !converged) {
    TnnmgStep step;
    const std::vector<RowKind> kind = tresca_rows(problem, s);
    const Eigen::VectorXd row_s = per_row(s);
    // 1. smooth.
    auto t0 = std::chrono::steady_clock::now();
    smoother.reset_counters();
    for (int sweep = 0; sweep < opt.smoothing_sweeps; ++sweep) smoother.sweep(kind, row_s, y);
    const std::vector<RowState> state = truncated(mixed, problem.jump_offset(), kind, smoother.state(), y);
    step.smoothing_s = seconds_since(t0);
    for (size_t i = 0; i < state.size(); ++i) step.changed_rows += !previous.empty() && state[i] != previous[i];
    // 2. truncate.
    t0 = std::chrono::steady_clock::now();
    auto correct = [&](const std::vector<RowState>& held) {
      const std::vector<RowCondition> rows = correction_rows(problem, kind, held, row_s, false);
      MixedSystem::Answer a = mixed.solve(rows);
      ++run.factorisations;
      if (a.singular) {  // a film part held by nothing on this face: a proximal shift on its translations
        for (bool all : {false, true}) {
          const std::vector<int> loose = loose_translations(mixed, blocks, held, all);
          Eigen::VectorXd rho(loose.size()), anchor(loose.size());
          for (size_t j = 0; j < loose.size(); ++j) {
            rho[j] = mixed.K_y().coeff(loose[j], loose[j]);  // the membrane's own stiffness
            anchor[j] = y[loose[j]];
          }
          mixed.set_springs(loose, rho, anchor);
          a = mixed.solve(rows);
          mixed.clear_springs();
          ++run.factorisations;
          step.shifted = true;
          if (!a.singular) break;
        }
      }
      return a;
    };
    std::vector<RowState> held = state;
    MixedSystem::Answer a = correct(held);
    if (opt.verbose && run.steps.empty()) {
      const Eigen::VectorXd d0 = mixed.B_y() * y + problem.jump_offset();
      const Eigen::VectorXd ds = mixed.B_y() * a.y + problem.jump_offset();
      std::fprintf(stderr, "    first correction, S+ N rows 60..90: node state d(y) d(y*) r*\n");
      for (int k = 60; k <= 90; ++k)
        std::fprintf(stderr, "      %d %d %+.3e %+.3e %+.3e | T %d %+.3e %+.3e\n", k, int(held[2 * k]), d0[2 * k], ds[2 * k], a.r[2 * k], int(held[2*k+1]), d0[2*k+1], ds[2*k+1]);
    }
    // Rows the correction carries across their kink — an open row closed past its obstacle, a slide
    // reversed — are held at it and the face solved again (a primal active set): the smoother, being
    // local, cannot see a film that sags onto a face over many columns, nor a film chain whose slips
    // end at a kink far from where they start; the correction can.
    for (int round = 0; round < opt.closing_rounds && run.factorisations < opt.max_factorisations; ++round) {
      if (a.singular || !a.y.allFinite()) break;
      const Eigen::VectorXd d_star = mixed.B_y() * a.y + problem.jump_offset();
      int closed = 0;
      for (size_t i = 0; i < held.size(); ++i) {
        const bool crosses = (kind[i] == RowKind::Obstacle && held[i] == RowState::Open && d_star[i] > 0) ||
                             (kind[i] == RowKind::Friction && held[i] == RowState::Plus && d_star[i] < 0) ||
                             (kind[i] == RowKind::Friction && held[i] == RowState::Minus && d_star[i] > 0);
        if (crosses) held[i] = RowState::Kink, ++closed;
        if (!opt.releasing || held[i] != RowState::Kink) continue;
        // A held row whose force leaves its admissible set is let go: a contact in tension opens, a
        // stick beyond its threshold slides the way its force pushes (r = −λ; Plus: λ = +s).
        if (kind[i] == RowKind::Obstacle && a.r[i] > 0) held[i] = RowState::Open, ++closed;
        if (kind[i] == RowKind::Friction && a.r[i] < -row_s[i]) held[i] = RowState::Plus, ++closed;
        if (kind[i] == RowKind::Friction && a.r[i] > row_s[i]) held[i] = RowState::Minus, ++closed;
      }
      if (opt.verbose && !opt.reference_rows.empty()) {
        const int m = problem.num_nodes();
        auto code = [](int v) { return "o|+-"[v]; };
        std::string sp, sm;
        for (int k = 0; k < m / 2; ++k) {
          sp += code(int(held[2 * k])), sp += code(int(held[2 * k + 1]));
          sm += code(int(held[m + 2 * k])), sm += code(int(held[m + 2 * k + 1]));
        }
        std::fprintf(stderr, "      round %d: %d changed\n      S+ %s\n      S- %s\n", round, closed, sp.c_str(), sm.c_str());
      }
      if (closed == 0) break;
      a = correct(held);
    }
    step.correction_s = seconds_since(t0);
    if (a.singular || !a.y.allFinite()) break;
    // 3. project, then search.
    const Eigen::VectorXd delta = smoother.project(kind, a.y) - y;
    const KinkLineSearch search = kink_line_search(mixed.K_y(), mixed.F_y(), mixed.B_y(), problem.jump_offset(), kind,
                                                   row_s, y, delta, 1.0);
    step.alpha = search.alpha;
    step.clipped = search.alpha < 1;
    if (opt.verbose) {
      const Eigen::VectorXd d = mixed.B_y() * y + problem.jump_offset();
      const Eigen::VectorXd d_star = mixed.B_y() * a.y + problem.jump_offset();
      double kink_d = 0, kink_d_star = 0, wrong_sign = 0, force_err = 0;
      for (size_t i = 0; i < state.size(); ++i) {
        if (kind[i] == RowKind::Free) continue;
        if (state[i] == RowState::Kink) kink_d = std::max(kink_d, std::abs(d[i])), kink_d_star = std::max(kink_d_star, std::abs(d_star[i]));
        if (state[i] == RowState::Plus) wrong_sign = std::max(wrong_sign, -d[i]), force_err = std::max(force_err, std::abs(a.r[i] + row_s[i]));
        if (state[i] == RowState::Minus) wrong_sign = std::max(wrong_sign, d[i]), force_err = std::max(force_err, std::abs(a.r[i] - row_s[i]));
        if (state[i] == RowState::Open) force_err = std::max(force_err, std::abs(a.r[i]));
      }
      const Eigen::VectorXd eq = mixed.K_y() * a.y - mixed.F_y() - Eigen::SparseMatrix<double>(mixed.B_y()).transpose() * a.r;
      const Eigen::VectorXd dl = a.y - y;
      const double qKq = dl.dot(mixed.K_y() * dl), gy = dl.dot(mixed.K_y() * y - mixed.F_y()),
                   gys = dl.dot(mixed.K_y() * a.y - mixed.F_y());
      double kinkterm = 0, slideterm = 0, freeterm = 0;
      for (size_t i = 0; i < state.size(); ++i) {
        if (kind[i] == RowKind::Free) { freeterm += a.r[i] * (d_star[i] - d[i]); continue; }
        if (state[i] == RowState::Kink) kinkterm += a.r[i] * (d_star[i] - d[i]);
        else slideterm += a.r[i] * (d_star[i] - d[i]);
      }
      for (size_t i = 0; i < state.size(); ++i)
        if (kind[i] == RowKind::Friction && state[i] != RowState::Kink) {
          const double sig = state[i] == RowState::Plus ? 1 : -1;
          const double ddi = d_star[i] - d[i];
          const double sig0 = d[i] > 0 ? 1 : d[i] < 0 ? -1 : (ddi > 0 ? 1 : -1);
          if (sig0 != sig) std::fprintf(stderr, "    row %zu state %d d %.3e dd %.3e s %.3e\n", i, int(state[i]), d[i], ddi, row_s[i]);
        }
      {
        int violated = 0;
        double worst = 0;
        std::string where;
        for (size_t i = 0; i < state.size(); ++i)
          if (kind[i] == RowKind::Obstacle && state[i] != RowState::Kink && d_star[i] > 0) {
            ++violated;
            worst = std::max(worst, d_star[i]);
            if (violated <= 12) where += " " + std::to_string(i) + ":" + std::to_string(d_star[i]).substr(0, 8);
          }
        std::fprintf(stderr, "    y* violates %d open rows (worst %.2e):%s\n", violated, worst, where.c_str());
      }
      std::fprintf(stderr, "    dKd %.3e  grad(y).d %.3e  grad(y*).d %.3e  kink %.3e slide %.3e free %.3e\n", qKq, gy, gys, kinkterm, slideterm, freeterm);
      std::fprintf(stderr, "    face: |d_kink(y)| %.2e |d_kink(y*)| %.2e wrong-sign %.2e force-err %.2e |eq(y*)| %.2e\n", kink_d,
                   kink_d_star, wrong_sign, force_err, eq.norm());
    }
    if (opt.verbose)
      std::fprintf(stderr, "    search: slope0 %.3e, alpha_max %.3e, breakpoints %d, |delta| %.3e, |y| %.3e\n",
                   search.slope_at_zero, search.alpha_max, search.breakpoints, delta.norm(), y.norm());
    y += search.alpha * delta;
    step.residual = step.shifted ? std::numeric_limits<double>::infinity() : judge(a, a.y);
    converged = step.residual <= options.tolerance;
    // Coulomb: where the branches repeat and the step was whole, their Coulomb answer.
    Eigen::VectorXd forces = a.r;
    if (!tresca && !converged && !step.shifted && search.alpha == 1 && state == previous &&
        run.factorisations < opt.max_factorisations) {
      const MixedSystem::Answer c = mixed.solve(correction_rows(problem, kind, state, row_s, true));
      ++run.factorisations;
      step.coulomb = true;
      const double residual = judge(c, c.y);
      step.residual = std::min(step.residual, residual);
      converged = residual <= options.tolerance;
      if (!c.singular && c.y.allFinite()) {
        y = c.y;
        forces = c.r;
      }
    }
    previous = state;
    if (!tresca && !converged) {
      const Eigen::VectorXd image = coulomb_thresholds(problem, forces);
      step.threshold_change = (image - s).norm() / std::max(image.norm(), 1e-300);
      s = opt.anderson ? Eigen::VectorXd(anderson.next(s, image).cwiseMax(0.0)) : image;
    }
    step.factorisations = run.factorisations;
    run.steps.push_back(step);
    if (opt.verbose && !opt.reference_rows.empty()) {
      const int m = problem.num_nodes();
      auto code = [](int v) { return "o|+-"[v]; };
      std::string plus_N, plus_T, minus_N, minus_T, rp, rm;
      for (int k = 0; k < m / 2; ++k) {
        plus_N += code(int(held[2 * k])), plus_T += code(int(held[2 * k + 1]));
        minus_N += code(int(held[m + 2 * k])), minus_T += code(int(held[m + 2 * k + 1]));
        rp += code(opt.reference_rows[2 * k]) , rp += code(opt.reference_rows[2 * k + 1]);
        rm += code(opt.reference_rows[m + 2 * k]), rm += code(opt.reference_rows[m + 2 * k + 1]);
      }
      std::string it_p, it_m;
      for (int k = 0; k < m / 2; ++k) it_p += plus_N[k], it_p += plus_T[k], it_m += minus_N[k], it_m += minus_T[k];
      std::fprintf(stderr, "    S+ ref %s\n    S+ now %s\n    S- ref %s\n    S- now %s\n", rp.c_str(), it_p.c_str(), rm.c_str(), it_m.c_str());
    }
    if (opt.verbose)
      std::fprintf(stderr,
                   "  tnnmg: %2d LUs, alpha %.3g%s%s%s, %d rows changed, residual %.3e, thresholds %.2e, "
                   "branches %d (worst %.1e), smooth %.3f s, correct %.3f s\n",
                   run.factorisations, step.alpha, step.clipped ? " (partial)" : "", step.shifted ? " (shifted)" : "",
                   step.coulomb ? " +Coulomb" : "", step.changed_rows, step.residual, step.threshold_change,
                   smoother.branches_solved(), smoother.worst_inconsistency(), step.smoothing_s, step.correction_s);
  }
  best.iterations = run.factorisations;
  best.converged = best.residual.value() <= options.tolerance;
  best.stop_cause = best.converged ? StopCause::Converged
                    : best.residual.value() <= best.residual.floor() ? StopCause::RoundOffFloor
                                                                     : StopCause::IterationCap;
  best.wall_time_s = seconds_since(start);
  best.w.resize(0);
  best.message = std::string(best.converged ? "converged" : "NOT converged") + " after " +
                 std::to_string(run.factorisations) + " factorisations (layer descent), residual " +
                 std::to_string(best.residual.value());
  return run;
}

}  // namespace thinlayer
