#include "core/solvers/layer_interior_point.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <functional>
#include <memory>
#include <set>

#include "core/linalg/factor_memory.h"
#include "core/linalg/sparse_lu.h"
#include "core/solvers/active_set.h"
#include "core/solvers/descent_blocks.h"
#include "core/solvers/layer_smoother.h"
#include "core/solvers/mixed_system.h"

namespace thinlayer {

namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// The rows of the program: each obstacle row (one pair w, z), each friction row (τ and two pairs),
// each equality row (a free multiplier ν); free rows are not in it.
struct Rows {
  std::vector<int> obstacle, friction, equality;
  std::vector<int> normal_of_friction;  // the obstacle index of the friction row's node (−1: none)
};

Rows program_rows(const ContactProblem& problem, const Eigen::VectorXd* tresca) {
  Rows rows;
  std::vector<int> obstacle_of_node(problem.num_nodes(), -1);
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceLaw& law = problem.law(k);
    if (law.bilateral) {
      if (law.normal_active()) rows.equality.push_back(2 * k);
      if (law.K_T() > 0) rows.equality.push_back(2 * k + 1);
      continue;
    }
    if (!law.normal_active()) continue;
    obstacle_of_node[k] = static_cast<int>(rows.obstacle.size());
    rows.obstacle.push_back(2 * k);
    const bool friction = law.tangential_active() && (!tresca || (*tresca)[k] > 0);
    if (friction) {
      rows.friction.push_back(2 * k + 1);
      rows.normal_of_friction.push_back(obstacle_of_node[k]);
    }
  }
  return rows;
}

// The reduced matrix [K_y + B_Iᵀ Θ B_I, B_Eᵀ; B_E, 0] on a fixed pattern: K_y's values, and for each
// inequality row the positions of its outer product b bᵀ, filled with Θ each iteration.
class ReducedMatrix {
 public:
  ReducedMatrix(const MixedSystem& mixed, const Rows& rows) : ny_(mixed.num_unknowns()) {
    const RowMatrix& B = mixed.B_y();
    std::vector<Eigen::Triplet<double>> t;
    const Eigen::SparseMatrix<double>& K = mixed.K_y();
    for (int c = 0; c < K.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it) t.emplace_back(it.row(), it.col(), 0.0);
    auto outer = [&](int row) {
      for (RowMatrix::InnerIterator a(B, row); a; ++a)
        for (RowMatrix::InnerIterator b(B, row); b; ++b) t.emplace_back(a.col(), b.col(), 0.0);
    };
    auto cross = [&](int row_a, int row_b) {
      for (RowMatrix::InnerIterator a(B, row_a); a; ++a)
        for (RowMatrix::InnerIterator b(B, row_b); b; ++b) t.emplace_back(a.col(), b.col(), 0.0);
    };
    for (int row : rows.obstacle) outer(row);
    for (int row : rows.friction) outer(row);
    for (size_t j = 0; j < rows.friction.size(); ++j)
      if (rows.normal_of_friction[j] >= 0) cross(rows.friction[j], rows.obstacle[rows.normal_of_friction[j]]);
    const int ne = static_cast<int>(rows.equality.size());
    for (int e = 0; e < ne; ++e)
      for (RowMatrix::InnerIterator a(B, rows.equality[e]); a; ++a) {
        t.emplace_back(ny_ + e, a.col(), 0.0);
        t.emplace_back(a.col(), ny_ + e, 0.0);
      }
    for (int e = 0; e < ne; ++e) t.emplace_back(ny_ + e, ny_ + e, 0.0);  // a structural zero: UMFPACK pivots
    M_.resize(ny_ + ne, ny_ + ne);
    M_.setFromTriplets(t.begin(), t.end());
    M_.makeCompressed();
    auto position = [&](int r, int c) {
      const int* begin = M_.innerIndexPtr() + M_.outerIndexPtr()[c];
      const int* end = M_.innerIndexPtr() + M_.outerIndexPtr()[c + 1];
      return static_cast<int>(std::lower_bound(begin, end, r) - M_.innerIndexPtr());
    };
    base_ = Eigen::VectorXd::Zero(M_.nonZeros());
    for (int c = 0; c < K.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it) base_[position(it.row(), it.col())] += it.value();
    for (int e = 0; e < ne; ++e)
      for (RowMatrix::InnerIterator a(B, rows.equality[e]); a; ++a) {
        base_[position(ny_ + e, a.col())] = a.value();
        base_[position(a.col(), ny_ + e)] = a.value();
      }
    auto products = [&](int row) {
      std::vector<std::pair<int, double>> p;
      for (RowMatrix::InnerIterator a(B, row); a; ++a)
        for (RowMatrix::InnerIterator b(B, row); b; ++b) p.emplace_back(position(a.col(), b.col()), a.value() * b.value());
      return p;
    };
    for (int row : rows.obstacle) products_.push_back(products(row));
    for (int row : rows.friction) products_.push_back(products(row));
    // Coulomb: a friction row's force follows its node's normal multiplier (b_T b_Nᵀ).
    for (size_t j = 0; j < rows.friction.size(); ++j) {
      std::vector<std::pair<int, double>> p;
      if (rows.normal_of_friction[j] >= 0)
        for (RowMatrix::InnerIterator a(B, rows.friction[j]); a; ++a)
          for (RowMatrix::InnerIterator b(B, rows.obstacle[rows.normal_of_friction[j]]); b; ++b)
            p.emplace_back(position(a.col(), b.col()), a.value() * b.value());
      products_.push_back(p);
    }
  }

  // Θ: one per obstacle row, one per friction row, then one per friction row's Coulomb coupling to
  // its normal row. False where the LU finds it singular.
  bool factor(const Eigen::VectorXd& theta) {
    Eigen::Map<Eigen::VectorXd>(M_.valuePtr(), M_.nonZeros()) = base_;
    for (size_t i = 0; i < products_.size(); ++i)
      for (const auto& [pos, value] : products_[i]) M_.valuePtr()[pos] += theta[i] * value;
    return lu_.factor_allowing_small_pivots(M_);
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const { return lu_.solve_once_refined(rhs); }
  double rcond() const { return lu_.rcond(); }

 private:
  int ny_;
  Eigen::SparseMatrix<double> M_;
  Eigen::VectorXd base_;
  std::vector<std::vector<std::pair<int, double>>> products_;
  SparseLU lu_;
};

// The primal-dual iterate.
struct Iterate {
  Eigen::VectorXd y, tau, nu;
  Eigen::VectorXd wO, zO, wP, zP, wM, zM;  // obstacle; friction's d − τ ≤ 0 (P) and −d − τ ≤ 0 (M)
};

struct Direction {
  Eigen::VectorXd y, tau, nu, wO, zO, wP, zP, wM, zM;
};

double largest_step(const Eigen::VectorXd& v, const Eigen::VectorXd& dv) {
  double alpha = 1;
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (dv[i] < 0) alpha = std::min(alpha, -v[i] / dv[i]);
  return alpha;
}

}  // namespace

bool layer_interior_point_applies(const ContactProblem& problem) {
  return !problem.system().floating_bands().empty() && layer_descent_applies(problem);
}

InteriorPointRun solve_layer_interior_point(const ContactProblem& problem, const SolverOptions& options,
                                            const InteriorPointOptions& opt) {
  const auto start = std::chrono::steady_clock::now();
  InteriorPointRun run;
  SolveReport& best = run.report;
  best.solver = "fast";
  best.method = "layer interior point";
  best.tolerance = options.tolerance;
  best.residual.interface = best.residual.bulk = std::numeric_limits<double>::infinity();
  if (!layer_interior_point_applies(problem)) {
    run.applies = false;
    run.why_not = "no layer band, or an interface law with a finite spring";
    return run;
  }
  const FactorsFromTheHeap reuse_factor_pages;
  MixedSystem mixed(problem);
  const bool tresca = opt.tresca_thresholds.size() > 0;
  const Rows rows = program_rows(problem, tresca ? &opt.tresca_thresholds : nullptr);
  const RowMatrix& B = mixed.B_y();
  const Eigen::SparseMatrix<double> Bt = Eigen::SparseMatrix<double>(B).transpose();
  const Eigen::SparseMatrix<double>& K = mixed.K_y();
  const Eigen::VectorXd& F = mixed.F_y();
  const Eigen::VectorXd& g = problem.jump_offset();
  const int nO = static_cast<int>(rows.obstacle.size()), nF = static_cast<int>(rows.friction.size()),
            nE = static_cast<int>(rows.equality.size()), ny = mixed.num_unknowns();
  const int n_pairs = nO + 2 * nF;
  ReducedMatrix M(mixed, rows);
  // The statuses an iterate stands on, read by the SPEC residual's own natural map (κ: each row's
  // local stiffness, ContactProblem::kappa). Not the film's own row stiffness
  // (MixedSystem::row_stiffness, 1e-4 … 1e-16 of the adherents' on a film's rows): with it an open film
  // row whose gap is a thousand times its force would read as pressed.
  const Condensed rules = law_rules(problem, problem.kappa());

  auto judge = [&](const MixedSystem::Answer& a) {
    if (a.singular || !a.u.allFinite() || !a.r.allFinite()) return std::numeric_limits<double>::infinity();
    const Residual residual = contact_residual(problem, a.u, a.r, a.band_z);
    if (residual.value() < best.residual.value()) {
      best.u = a.u;
      best.r = a.r;
      best.residual = residual;
      best.condition_estimate = 1.0 / std::max(a.rcond, 1e-300);
    }
    return residual.value();
  };

  // The start.
  Eigen::VectorXd y0, r0;
  if (opt.start_y.size()) {
    y0 = opt.start_y;
    r0 = opt.start_r.size() ? opt.start_r : Eigen::VectorXd::Zero(2 * problem.num_nodes());
  } else {
    std::vector<RowCondition> glued(2 * problem.num_nodes());
    for (int row : rows.obstacle) glued[row].jump = true;
    for (int row : rows.equality) glued[row].jump = true;
    for (int k = 0; k < problem.num_nodes(); ++k)
      if (problem.law(k).tangential_active() && !problem.law(k).bilateral) glued[2 * k + 1].jump = true;
    const MixedSystem::Answer a = mixed.solve(glued);
    ++run.factorisations;
    y0 = a.singular ? Eigen::VectorXd::Zero(ny) : a.y;
    r0 = a.singular ? Eigen::VectorXd::Zero(2 * problem.num_nodes()) : a.r;
  }
  // The interior start: each slack its gap plus a hundredth of the start's displacement scale, each
  // multiplier its pressure plus a hundredth of the start's force scale (a path-following method
  // converges from any interior point; the shifts only keep the first steps long and the products
  // w z of the same order, active row or not).
  Iterate x;
  x.y = y0;
  const Eigen::VectorXd d0 = B * y0 + g;
  const double u_scale = std::max(mixed.displacement(y0).cwiseAbs().maxCoeff(), 1e-300);
  const double r_scale = std::max(r0.cwiseAbs().maxCoeff(), 1e-300);
  const double w_min = 1e-2 * u_scale, z_min = 1e-2 * r_scale;
  x.wO.resize(nO), x.zO.resize(nO);
  for (int i = 0; i < nO; ++i) {
    x.wO[i] = std::max(-d0[rows.obstacle[i]], 0.0) + w_min;
    x.zO[i] = std::max(-r0[rows.obstacle[i]], 0.0) + z_min;
  }
  Eigen::VectorXd s(nF);
  auto update_thresholds = [&]() {
    for (int j = 0; j < nF; ++j) {
      const int k = rows.friction[j] / 2;
      s[j] = tresca ? opt.tresca_thresholds[k] : problem.law(k).friction * x.zO[rows.normal_of_friction[j]];
    }
  };
  update_thresholds();
  x.tau.resize(nF), x.wP.resize(nF), x.zP.resize(nF), x.wM.resize(nF), x.zM.resize(nF);
  for (int j = 0; j < nF; ++j) {
    const double dT = d0[rows.friction[j]], rT = r0[rows.friction[j]];
    x.tau[j] = std::abs(dT) + w_min;
    x.wP[j] = x.tau[j] - dT;
    x.wM[j] = x.tau[j] + dT;
    // z⁺ − z⁻ = −r_T, z⁺ + z⁻ = s, each at least a twentieth of s.
    const double share = std::clamp(0.5 * (1 - rT / s[j]), 0.05, 0.95);
    x.zP[j] = share * s[j];
    x.zM[j] = (1 - share) * s[j];
  }
  // Centred: no pair's product below the mean, μ₀ (a pair far below the others cuts the first steps
  // short — measured: steps of 1e-3 … 5e-2 for the first four iterations from the limit answer); the
  // multiplier of an obstacle pair is raised, a friction pair's τ (both its slacks) where its
  // multipliers are held to their sum s.
  if (opt.centred_start && n_pairs > 0) {
    const double mu0 = (x.wO.dot(x.zO) + x.wP.dot(x.zP) + x.wM.dot(x.zM)) / n_pairs;
    for (int i = 0; i < nO; ++i) x.zO[i] = std::max(x.zO[i], mu0 / x.wO[i]);
    for (int j = 0; j < nF; ++j) {
      const double need = std::max(mu0 / x.zP[j] - x.wP[j], mu0 / x.zM[j] - x.wM[j]);
      if (need > 0) x.tau[j] += need, x.wP[j] += need, x.wM[j] += need;
    }
    if (!tresca) update_thresholds();
  }
  x.nu = Eigen::VectorXd::Zero(nE);
  for (int e = 0; e < nE; ++e) x.nu[e] = -r0[rows.equality[e]];

  // The multipliers as interface forces, r = −λ (defined below); an iterate as an answer.
  std::function<Eigen::VectorXd(const Iterate&)> forces;
  auto judge_iterate = [&](const Iterate& it) {
    MixedSystem::Answer a;
    a.y = it.y;
    a.u = mixed.displacement(it.y);
    a.r = forces(it);
    a.band_z = mixed.band_coordinates(it.y);
    a.rcond = M.rcond();
    return judge(a);
  };
  // The multipliers as interface forces, r = −λ.
  forces = [&](const Iterate& it) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * problem.num_nodes());
    for (int i = 0; i < nO; ++i) r[rows.obstacle[i]] = -it.zO[i];
    for (int j = 0; j < nF; ++j) r[rows.friction[j]] = it.zM[j] - it.zP[j];
    for (int e = 0; e < nE; ++e) r[rows.equality[e]] = -it.nu[e];
    return r;
  };
  // The crossover's rows from statuses: Coulomb's (MixedSystem::solve(statuses)), or Tresca's.
  auto crossover = [&](const std::vector<Active>& statuses) {
    ++run.factorisations;
    ++run.crossovers;
    if (!tresca) return mixed.solve(statuses);
    std::vector<RowCondition> c(2 * problem.num_nodes());
    for (int k = 0; k < problem.num_nodes(); ++k) {
      const Active a = statuses[k];
      c[2 * k].jump = a != Active::Gap;
      c[2 * k + 1].jump = a == Active::Stick || a == Active::Bonded;
      if (a == Active::SlidePositive) c[2 * k + 1].force = opt.tresca_thresholds[k];
      if (a == Active::SlideNegative) c[2 * k + 1].force = -opt.tresca_thresholds[k];
    }
    return mixed.solve(c);
  };

  // The crossover's statuses: the smoother's branches at the iterate (each block minimised exactly
  // with the rest held, on the Tresca energy of the iterate's thresholds f z_N), which settle a film's
  // rows at its own scale where the path's ratios cannot (a row both of whose multiplier and slack are
  // 1e-12 reads either way).
  std::unique_ptr<LayerSmoother> smoother;
  std::unique_ptr<DescentBlocks> blocks;
  auto smoothed_statuses = [&](Eigen::VectorXd y) {
    if (!smoother) {
      blocks = std::make_unique<DescentBlocks>(descent_blocks(mixed));
      smoother = std::make_unique<LayerSmoother>(mixed, problem, *blocks);
      ++run.factorisations;  // its interior Cholesky factor
    }
    Eigen::VectorXd node_s = Eigen::VectorXd::Zero(problem.num_nodes());
    for (int j = 0; j < nF; ++j) node_s[rows.friction[j] / 2] = s[j];
    const std::vector<RowKind> kind = tresca_rows(problem, node_s);
    Eigen::VectorXd row_s = Eigen::VectorXd::Zero(2 * problem.num_nodes());
    for (int k = 0; k < problem.num_nodes(); ++k) row_s[2 * k + 1] = node_s[k];
    smoother->sweep(kind, row_s, y);
    const std::vector<RowState>& st = smoother->state();
    std::vector<Active> out(problem.num_nodes(), Active::Gap);
    for (int k = 0; k < problem.num_nodes(); ++k) {
      const InterfaceLaw& law = problem.law(k);
      if (law.bilateral) {
        out[k] = law.normal_active() || law.K_T() > 0 ? Active::Bonded : Active::Gap;
        continue;
      }
      if (kind[2 * k] != RowKind::Obstacle || st[2 * k] != RowState::Kink) continue;  // open
      if (kind[2 * k + 1] != RowKind::Friction) out[k] = law.tangential_active() ? Active::Stick : Active::Frictionless;
      else if (st[2 * k + 1] == RowState::Kink) out[k] = Active::Stick;
      else out[k] = st[2 * k + 1] == RowState::Plus ? Active::SlideNegative : Active::SlidePositive;  // λ = +s: r_T = −s
    }
    return out;
  };
  // The hybrid crossover's rows: a row whose pair the iterate classifies with a margin Q (its
  // multiplier above Q times its slack's force κ w, or below 1/Q of it, κ the SPEC residual's
  // stiffness of the row) takes its exact condition; a row it cannot classify keeps the barrier's
  // linearisation about the iterate — for an obstacle pair the tangent of w z = μ at (d, r) = (−w, −z),
  // r + Θ d = −2z, Θ = z/w, i.e. d + r/Θ = −2w; for a friction row the reduced relation Δr_T = −θ Δd_T.
  // An unclassified row is one whose multiplier and slack are both small (a film touching with no
  // force, a stick at its slip threshold): its share of the natural map, min(z, κ w), is small
  // whichever way, and committing it exactly (the plain crossover) moved a film's isolated contacts
  // elsewhere.
  auto hybrid_rows = [&](const Iterate& it) {
    const double Q = opt.hybrid_margin;
    const Eigen::VectorXd& kappa = problem.kappa();
    const Eigen::VectorXd d = B * it.y + g;
    std::vector<RowCondition> c(2 * problem.num_nodes());
    std::vector<int> normal_class(problem.num_nodes(), 0);  // 1 contact, 0 open, 2 unclassified
    for (int e = 0; e < nE; ++e) c[rows.equality[e]].jump = true;
    for (int i = 0; i < nO; ++i) {
      const int row = rows.obstacle[i];
      const double q = it.zO[i] / (kappa[row] * it.wO[i]);
      if (q >= Q) c[row].jump = true, normal_class[row / 2] = 1;
      else if (q > 1 / Q) {
        c[row].jump = true;
        c[row].compliance = it.wO[i] / it.zO[i];
        c[row].force = -2 * it.wO[i];
        normal_class[row / 2] = 2;
      }
    }
    for (int j = 0; j < nF; ++j) {
      const int row = rows.friction[j], k = row / 2;
      if (normal_class[k] == 0) continue;  // open: no friction force
      const double f = problem.law(k).friction;
      const double qP = it.zP[j] / (kappa[row] * it.wP[j]), qM = it.zM[j] / (kappa[row] * it.wM[j]);
      if (qP >= Q && qM >= Q) c[row].jump = true;                                          // stick
      else if (qP >= Q && qM <= 1 / Q) c[row].coupling = tresca ? 0.0 : -f,                 // r_T = f r_N
                                       c[row].force = tresca ? -s[j] : 0.0;
      else if (qM >= Q && qP <= 1 / Q) c[row].coupling = tresca ? 0.0 : f,                  // r_T = −f r_N
                                       c[row].force = tresca ? s[j] : 0.0;
      else {
        const double Dp = it.zP[j] / it.wP[j], Dm = it.zM[j] / it.wM[j], theta = 4 * Dp * Dm / (Dp + Dm);
        const double rT = it.zM[j] - it.zP[j];
        if (theta > 0) {
          c[row].jump = true;
          c[row].compliance = 1 / theta;
          c[row].force = d[row] + rT / theta;
        } else {
          c[row].force = rT;
        }
      }
    }
    return c;
  };
  std::set<std::vector<Active>> tried;
  std::vector<Active> previous;
  int stalled = 0;  // consecutive iterations whose step was cut below a tenth
  bool frozen = false, previous_readable = false, moving = false;
  double last_attempt = std::numeric_limits<double>::infinity();
  double factor_s = 0, judge_s = 0;
  bool converged = false;
  while (run.factorisations < opt.max_factorisations && !converged) {
    const auto t0 = std::chrono::steady_clock::now();
    if (!tresca && !frozen) update_thresholds();
    // Residuals.
    const Eigen::VectorXd d = B * x.y + g;
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(B.rows());
    for (int i = 0; i < nO; ++i) lambda[rows.obstacle[i]] = x.zO[i];
    for (int j = 0; j < nF; ++j) lambda[rows.friction[j]] = x.zP[j] - x.zM[j];
    for (int e = 0; e < nE; ++e) lambda[rows.equality[e]] = x.nu[e];
    const Eigen::VectorXd r_y = K * x.y - F + Bt * lambda;
    Eigen::VectorXd r_O(nO), r_P(nF), r_M(nF), r_tau(nF), r_E(nE);
    for (int i = 0; i < nO; ++i) r_O[i] = d[rows.obstacle[i]] + x.wO[i];
    for (int j = 0; j < nF; ++j) {
      const double dj = d[rows.friction[j]];
      r_P[j] = dj - x.tau[j] + x.wP[j];
      r_M[j] = -dj - x.tau[j] + x.wM[j];
      r_tau[j] = s[j] - x.zP[j] - x.zM[j];
    }
    for (int e = 0; e < nE; ++e) r_E[e] = d[rows.equality[e]];
    const double mu = (x.wO.dot(x.zO) + x.wP.dot(x.zP) + x.wM.dot(x.zM)) / std::max(n_pairs, 1);

    // The barrier's curvature and the factorisation.
    // Coulomb: s_j = f z_N, so a friction row's τ-equation reads f Δz_N − Δz⁺ − Δz⁻ = −r_τ, and its
    // force (Δz⁺ − Δz⁻) gains κ_j f Δz_N, κ_j = (D⁺ − D⁻)/(D⁺ + D⁻), with Δz_N = p_N + Θ_N b_Nᵀ Δy.
    Eigen::VectorXd coupling = Eigen::VectorXd::Zero(nF);  // f κ_j (0 for Tresca)
    Eigen::VectorXd theta(nO + 2 * nF);
    for (int i = 0; i < nO; ++i) theta[i] = x.zO[i] / x.wO[i];
    for (int j = 0; j < nF; ++j) {
      const double Dp = x.zP[j] / x.wP[j], Dm = x.zM[j] / x.wM[j];
      theta[nO + j] = 4 * Dp * Dm / (Dp + Dm);
      if (!tresca && !frozen) coupling[j] = problem.law(rows.friction[j] / 2).friction * (Dp - Dm) / (Dp + Dm);
      theta[nO + nF + j] = rows.normal_of_friction[j] >= 0 ? coupling[j] * theta[rows.normal_of_friction[j]] : 0.0;
    }
    const auto tf = std::chrono::steady_clock::now();
    const bool factored = M.factor(theta);
    factor_s += seconds_since(tf);
    ++run.factorisations;
    ++run.iterations;
    if (!factored) {
      if (opt.verbose) std::fprintf(stderr, "  ipm: the reduced matrix is singular\n");
      break;
    }
    // One direction: the Newton step of the residuals (times `residuals`: 1, or 0 for a pure
    // corrector) with the complementarity rows asking Z Δw + W Δz = comp (per pair).
    auto direction = [&](const Eigen::VectorXd& compO, const Eigen::VectorXd& compP, const Eigen::VectorXd& compM,
                         double residuals) {
      Direction D;
      Eigen::VectorXd pO(nO), qP(nF), qM(nF), rho(nF);
      for (int i = 0; i < nO; ++i) pO[i] = (compO[i] + residuals * x.zO[i] * r_O[i]) / x.wO[i];
      Eigen::VectorXd rowforce = Eigen::VectorXd::Zero(B.rows());
      for (int i = 0; i < nO; ++i) rowforce[rows.obstacle[i]] = pO[i];
      for (int j = 0; j < nF; ++j) {
        const double Dp = x.zP[j] / x.wP[j], Dm = x.zM[j] / x.wM[j];
        qP[j] = (compP[j] + residuals * x.zP[j] * r_P[j]) / x.wP[j];
        qM[j] = (compM[j] + residuals * x.zM[j] * r_M[j]) / x.wM[j];
        rho[j] = qP[j] - qM[j] - (Dp - Dm) * (qP[j] + qM[j] - residuals * r_tau[j]) / (Dp + Dm);
        if (rows.normal_of_friction[j] >= 0) rho[j] += coupling[j] * pO[rows.normal_of_friction[j]];
        rowforce[rows.friction[j]] = rho[j];
      }
      Eigen::VectorXd rhs(ny + nE);
      rhs.head(ny) = -residuals * r_y - Bt * rowforce;
      rhs.tail(nE) = -residuals * r_E;
      const Eigen::VectorXd sol = M.solve(rhs);
      D.y = sol.head(ny);
      D.nu = sol.tail(nE);
      const Eigen::VectorXd beta = B * D.y;
      D.wO.resize(nO), D.zO.resize(nO);
      for (int i = 0; i < nO; ++i) {
        D.wO[i] = -residuals * r_O[i] - beta[rows.obstacle[i]];
        D.zO[i] = pO[i] + theta[i] * beta[rows.obstacle[i]];
      }
      D.tau.resize(nF), D.wP.resize(nF), D.zP.resize(nF), D.wM.resize(nF), D.zM.resize(nF);
      for (int j = 0; j < nF; ++j) {
        const double Dp = x.zP[j] / x.wP[j], Dm = x.zM[j] / x.wM[j], b = beta[rows.friction[j]];
        const double f_dzN = rows.normal_of_friction[j] >= 0 && !tresca && !frozen
                                 ? problem.law(rows.friction[j] / 2).friction * D.zO[rows.normal_of_friction[j]]
                                 : 0.0;
        D.tau[j] = (qP[j] + qM[j] + (Dp - Dm) * b - residuals * r_tau[j] - f_dzN) / (Dp + Dm);
        D.wP[j] = -residuals * r_P[j] - (b - D.tau[j]);
        D.zP[j] = qP[j] + Dp * (b - D.tau[j]);
        D.wM[j] = -residuals * r_M[j] - (-b - D.tau[j]);
        D.zM[j] = qM[j] + Dm * (-b - D.tau[j]);
      }
      return D;
    };
    auto step_to_boundary = [&](const Direction& D) {
      return std::min({largest_step(x.wO, D.wO), largest_step(x.zO, D.zO), largest_step(x.wP, D.wP),
                       largest_step(x.zP, D.zP), largest_step(x.wM, D.wM), largest_step(x.zM, D.zM)});
    };
    auto add = [](Direction a, const Direction& b) {
      a.y += b.y, a.tau += b.tau, a.nu += b.nu, a.wO += b.wO, a.zO += b.zO;
      a.wP += b.wP, a.zP += b.zP, a.wM += b.wM, a.zM += b.zM;
      return a;
    };
    // Mehrotra: the affine direction, the centring it asks for, the corrected direction.
    const Direction affine = direction(-x.wO.cwiseProduct(x.zO), -x.wP.cwiseProduct(x.zP), -x.wM.cwiseProduct(x.zM), 1);
    const double a_aff = step_to_boundary(affine);
    const double mu_aff = ((x.wO + a_aff * affine.wO).dot(x.zO + a_aff * affine.zO) +
                           (x.wP + a_aff * affine.wP).dot(x.zP + a_aff * affine.zP) +
                           (x.wM + a_aff * affine.wM).dot(x.zM + a_aff * affine.zM)) / std::max(n_pairs, 1);
    const double sigma = std::pow(std::clamp(mu_aff / mu, 0.0, 1.0), 3);
    auto mehrotra = [&](const Eigen::VectorXd& w, const Eigen::VectorXd& z, const Eigen::VectorXd& dw,
                        const Eigen::VectorXd& dz) {
      return Eigen::VectorXd(Eigen::VectorXd::Constant(w.size(), sigma * mu) - w.cwiseProduct(z) - dw.cwiseProduct(dz));
    };
    Direction D = direction(mehrotra(x.wO, x.zO, affine.wO, affine.zO), mehrotra(x.wP, x.zP, affine.wP, affine.zP),
                            mehrotra(x.wM, x.zM, affine.wM, affine.zM), 1);
    double alpha = std::min(1.0, 0.99 * step_to_boundary(D));
    // Gondzio's centrality correctors, on the same factor: the pairs whose products at a longer trial
    // step fall out of [μ/10, 10 μ] (μ the target σμ) are pulled back into it, the others left; a
    // corrector is kept where it lengthens the step. A pair far below the others (a row at the
    // threshold of two branches: a stick at its limit, a contact that carries nothing) otherwise cuts
    // every step short — measured: a Coulomb slide at its threshold held the step below 1e-3 for 25 iterations.
    for (int corrector = 0; corrector < opt.centrality_correctors && alpha < 1; ++corrector) {
      const double trial = std::min(1.0, 2 * alpha + 0.1);
      const double target = std::max(sigma * mu, 1e-300);
      auto pull = [&](const Eigen::VectorXd& w, const Eigen::VectorXd& z, const Eigen::VectorXd& dw, const Eigen::VectorXd& dz) {
        Eigen::VectorXd c(w.size());
        for (Eigen::Index i = 0; i < w.size(); ++i) {
          const double v = (w[i] + trial * dw[i]) * (z[i] + trial * dz[i]);
          c[i] = v < 0.1 * target ? 0.1 * target - v : v > 10 * target ? std::max(10 * target - v, -10 * target) : 0.0;
        }
        return c;
      };
      const Direction C = direction(pull(x.wO, x.zO, D.wO, D.zO), pull(x.wP, x.zP, D.wP, D.zP), pull(x.wM, x.zM, D.wM, D.zM), 0);
      const Direction E = add(D, C);
      const double a_new = std::min(1.0, 0.99 * step_to_boundary(E));
      if (!(a_new > 1.01 * alpha)) break;
      D = E;
      alpha = a_new;
    }
    if (opt.verbose && alpha < 0.1) {
      const char* names[6] = {"wO", "zO", "wP", "zP", "wM", "zM"};
      const Eigen::VectorXd* v[6] = {&x.wO, &x.zO, &x.wP, &x.zP, &x.wM, &x.zM};
      const Eigen::VectorXd* dv[6] = {&D.wO, &D.zO, &D.wP, &D.zP, &D.wM, &D.zM};
      for (int q = 0; q < 6; ++q)
        for (Eigen::Index i = 0; i < v[q]->size(); ++i)
          if ((*dv[q])[i] < 0 && -(*v[q])[i] / (*dv[q])[i] < 0.1) {
            const bool fr = q >= 2;
            const int node = fr ? rows.friction[i] / 2 : rows.obstacle[i] / 2;
            std::fprintf(stderr, "    blocks: %s[%ld] node %d value %.2e step %.2e | zN %.2e wN %.2e", names[q], long(i), node,
                         (*v[q])[i], (*dv[q])[i], fr ? x.zO[rows.normal_of_friction[i]] : x.zO[i],
                         fr ? x.wO[rows.normal_of_friction[i]] : x.wO[i]);
            if (fr) std::fprintf(stderr, " tau %.2e wP %.2e zP %.2e wM %.2e zM %.2e s %.2e", x.tau[i], x.wP[i], x.zP[i], x.wM[i], x.zM[i], s[i]);
            std::fprintf(stderr, "\n");
          }
    }
    const Iterate before = x;
    x.y += alpha * D.y;
    x.tau += alpha * D.tau;
    x.nu += alpha * D.nu;
    x.wO += alpha * D.wO, x.zO += alpha * D.zO;
    x.wP += alpha * D.wP, x.zP += alpha * D.zP;
    x.wM += alpha * D.wM, x.zM += alpha * D.zM;

    // The statuses the path is heading for, by Tapia's indicators (El-Bakry, Tapia, Tsuchiya & Zhang
    // 1996): a pair is active where its multiplier keeps more of itself over the step than its slack,
    // z⁺/z > w⁺/w — on the path an active pair's z tends to its limit and its w to 0, an inactive
    // pair's the other way round. The ratios carry no unit, so a film row whose force and gap are both
    // 1e-8 of the adherents' is read as well as an adherent's (a natural map's κ is one scale for both).
    auto active = [](double w0, double w1, double z0, double z1) { return z1 / z0 > w1 / w0; };
    std::vector<Active> statuses(problem.num_nodes(), Active::Gap);
    for (int k = 0; k < problem.num_nodes(); ++k)
      if (problem.law(k).bilateral) statuses[k] = problem.law(k).normal_active() || problem.law(k).K_T() > 0 ? Active::Bonded : Active::Gap;
    for (int i = 0; i < nO; ++i)
      if (active(before.wO[i], x.wO[i], before.zO[i], x.zO[i])) statuses[rows.obstacle[i] / 2] = Active::Frictionless;
    for (int j = 0; j < nF; ++j) {
      const int k = rows.friction[j] / 2;
      if (statuses[k] != Active::Frictionless) continue;  // open: no friction force
      const bool P = active(before.wP[j], x.wP[j], before.zP[j], x.zP[j]);
      const bool Mi = active(before.wM[j], x.wM[j], before.zM[j], x.zM[j]);
      // P active: d_T = τ > 0, r_T = z⁻ − z⁺ = −s (SlideNegative: r_T = f r_N); M active: r_T = +s.
      statuses[k] = P == Mi ? Active::Stick : P ? Active::SlideNegative : Active::SlidePositive;
    }
    const std::vector<Active> statuses_read = statuses;
    // The iterate itself, judged as an answer: near the end of the path its natural map is of the
    // order of μ / (its pairs' scales), its equilibrium residual that of the last solve.
    const auto tj = std::chrono::steady_clock::now();
    const double iterate_residual = judge_iterate(x);
    judge_s += seconds_since(tj);
    if (iterate_residual <= options.tolerance) converged = true;
    run.last_y = x.y;
    run.last_r = forces(x);
    run.last_residual = iterate_residual;
    if (opt.stop_at_iterate_residual > 0 && iterate_residual <= opt.stop_at_iterate_residual) break;
    int xsteps = 0;
    double xres = std::numeric_limits<double>::infinity();
    // Crossover where the statuses the iterate reads repeat, or where the path stalls (a step cut
    // below a tenth by a pair that cannot keep up: a degenerate row, a stick at its threshold, that
    // the exact solve of the statuses settles and the path does not).
    stalled = alpha < 0.1 ? stalled + 1 : 0;
    // A path that stalls under Coulomb (measured: a node at both its contact and its slip threshold
    // whose two friction pairs take turns cutting the step below 1e-3) goes on as the Tresca problem
    // of the thresholds it reached, which is convex and does not: the crossover below restores
    // Coulomb's slide rows.
    if (alpha >= 0.5) moving = true;  // the path got going (the first steps from the start are short)
    if (!tresca && moving && stalled >= 2) frozen = true;
    // Tapia's ratios say something only over a step that moved the iterate (α ≥ ½).
    const bool readable = alpha >= 0.5;
    // Crossover where the path has read the statuses from a step that moved it, and the iterate has
    // gained a decade since the last attempt (each attempt costs a factorisation; a read whose
    // degenerate rows — a row at two branches' threshold, exactly solved by either — differ from the
    // last is still an attempt worth making, so the reads are not asked to repeat).
    const bool worth = iterate_residual <= 0.1 * std::min(last_attempt, 0.1);
    const bool repeats = previous_readable && statuses == previous;
    const bool attempt = !converged && readable && (repeats || worth);
    if (attempt) last_attempt = iterate_residual;
    if (attempt && !converged) {
      if (opt.smoothed_crossover) statuses = smoothed_statuses(x.y);
      if (opt.hybrid_margin > 0 && run.factorisations < opt.max_factorisations) {
        const MixedSystem::Answer h = mixed.solve(hybrid_rows(x));
        ++run.factorisations;
        ++run.crossovers;
        ++xsteps;
        const double res = judge(h);
        if (opt.verbose) std::fprintf(stderr, "      hybrid crossover: %.3e\n", res);
        xres = std::min(xres, res);
        if (res <= options.tolerance) converged = true;
      }
      // Damped Newton steps from the iterate: the exact answer of the statuses, then the point along
      // the way from the current point to it with the smallest SPEC residual (halving from 1 to 1/64:
      // evaluations, no factorisation), the statuses re-read there — a film whose isolated contacts a
      // full step moves elsewhere is not thrown off its path.
      MixedSystem::Answer point;
      point.y = x.y;
      point.u = mixed.displacement(x.y);
      point.r = forces(x);
      point.band_z = mixed.band_coordinates(x.y);
      double point_residual = iterate_residual;
      for (int newton = 0; !converged && opt.newton_crossover && run.factorisations < opt.max_factorisations &&
                           tried.insert(statuses).second;
           ++newton) {
        const MixedSystem::Answer a = crossover(statuses);
        ++xsteps;
        if (a.singular || !a.u.allFinite() || !a.r.allFinite()) break;
        MixedSystem::Answer step_best;
        double step_residual = std::numeric_limits<double>::infinity();
        for (double t = 1; t >= 1.0 / 64; t /= 2) {
          MixedSystem::Answer c;
          c.y = point.y + t * (a.y - point.y);
          c.u = mixed.displacement(c.y);
          c.r = point.r + t * (a.r - point.r);
          c.band_z = mixed.band_coordinates(c.y);
          c.rcond = a.rcond;
          const double res = judge(c);
          if (res < step_residual) step_residual = res, step_best = c;
          if (res <= options.tolerance) break;
        }
        if (opt.verbose) std::fprintf(stderr, "      crossover: exact %.3e, damped %.3e (from %.3e)\n", judge(a), step_residual, point_residual);
        xres = std::min(xres, step_residual);
        if (xres <= options.tolerance) {
          converged = true;
          break;
        }
        if (!(step_residual < point_residual)) break;  // no point along the step improves
        point = step_best;
        point_residual = step_residual;
        statuses = guess_statuses(rules, point.r, problem.stop_jumps(point.u, point.r));
      }
    }
    previous = statuses_read;
    previous_readable = readable;
    if (opt.verbose)
      std::fprintf(stderr, "  ipm %2d: %2d LUs, mu %.2e, sigma %.2e, alpha %.3f, |r_y| %.2e, iterate %.2e, crossover %d (%.2e), %.3f s\n",
                   run.iterations, run.factorisations, mu, sigma, alpha, r_y.norm(), iterate_residual, xsteps, xres, seconds_since(t0));
  }
  if (opt.verbose) std::fprintf(stderr, "  ipm: factorisations %.3f s, judging iterates %.3f s, total %.3f s\n", factor_s, judge_s, seconds_since(start));
  best.iterations = run.factorisations;
  best.converged = best.residual.value() <= options.tolerance;
  best.stop_cause = best.converged ? StopCause::Converged
                    : best.residual.value() <= best.residual.floor() ? StopCause::RoundOffFloor
                                                                     : StopCause::IterationCap;
  best.wall_time_s = seconds_since(start);
  best.message = std::string(best.converged ? "converged" : "NOT converged") + " after " +
                 std::to_string(run.factorisations) + " factorisations (" + std::to_string(run.iterations) +
                 " interior-point iterations, " + std::to_string(run.crossovers) + " crossover solves), residual " +
                 std::to_string(best.residual.value());
  return run;
}

}  // namespace thinlayer
