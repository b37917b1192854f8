#include "benchmarks/two_scale_lab/film_solver.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "core/linalg/sparse_block.h"
#include "core/linalg/sparse_cholesky.h"
#include "core/solvers/tresca.h"
#include "core/linalg/anderson.h"
#include "core/linalg/box_qp.h"

namespace thinlayer {

namespace {

// For each interface node, the (band, column) of the layer node on either side, or (-1, -1).
struct ColumnOf {
  std::vector<std::pair<int, int>> plus, minus;
};

ColumnOf columns_of_nodes(const ContactProblem& problem) {
  const LinearSystem& system = problem.system();
  std::vector<std::pair<int, int>> column_of_free(system.num_free(), {-1, -1});
  const std::vector<FloatingBand>& bands = system.floating_bands();
  for (size_t b = 0; b < bands.size(); ++b)
    for (size_t q = 0; q < bands[b].free_dof.size(); q += 2)
      if (bands[b].free_dof[q] >= 0)
        column_of_free[bands[b].free_dof[q]] = {static_cast<int>(b), bands[b].layout.column_of(static_cast<int>(q / 2))};
  ColumnOf out;
  auto at = [&](int dof) {
    const int free = dof >= 0 ? system.free_index(dof) : -1;
    return free >= 0 ? column_of_free[free] : std::pair<int, int>{-1, -1};
  };
  for (int k = 0; k < problem.num_nodes(); ++k) {
    out.plus.push_back(at(problem.node(k).plus_dof_x));
    out.minus.push_back(at(problem.node(k).minus_dof_x));
  }
  return out;
}

// The rows of the jump at `nodes` on the unknowns `position` marks (y index → its index there, −1
// elsewhere): G on those unknowns, and the rest of the jump frozen at the answer, g_frozen.
struct JumpRows {
  Eigen::MatrixXd G;
  Eigen::VectorXd g_frozen;
};

JumpRows jump_rows(const ContactProblem& problem, const MixedSystem& mixed, const MixedSystem::Answer& answer,
                   const std::vector<int>& nodes, const std::vector<int>& position, int n) {
  const int rows = 2 * static_cast<int>(nodes.size());
  JumpRows j{Eigen::MatrixXd::Zero(rows, n), Eigen::VectorXd(rows)};
  for (int q = 0; q < static_cast<int>(nodes.size()); ++q)
    for (int c = 0; c < 2; ++c) {
      const int row = 2 * nodes[q] + c;
      double frozen = problem.jump_offset()[row];
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(mixed.B_y(), row); it; ++it) {
        if (position[it.col()] >= 0) j.G(2 * q + c, position[it.col()]) = it.value();
        else frozen += it.value() * answer.y[it.col()];
      }
      j.g_frozen[2 * q + c] = frozen;
    }
  return j;
}

// Those unknowns eliminated: W = G K⁻¹ Gᵀ (symmetrised) and g = g_frozen + G K⁻¹ f, K Jacobi-scaled
// first (a film's stiffness spans its membrane and through-thickness scales).
struct Eliminated {
  Eigen::MatrixXd W;
  Eigen::VectorXd g;
};

Eliminated eliminate(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& f, const JumpRows& j) {
  const Eigen::VectorXd scale = Eigen::VectorXd(K.diagonal()).cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::SparseMatrix<double> M = scale.asDiagonal() * K * scale.asDiagonal();
  const SparseCholesky factor(M);
  const Eigen::MatrixXd GD = j.G * scale.asDiagonal();
  const Eigen::MatrixXd Z = factor.solve(Eigen::MatrixXd(GD.transpose()));
  Eliminated e;
  e.W = GD * Z;
  e.W = 0.5 * (e.W + e.W.transpose()).eval();
  e.g = j.g_frozen + GD * factor.solve(Eigen::VectorXd(scale.asDiagonal() * f));
  return e;
}

}  // namespace

FilmRun solve_film(const ContactProblem& problem, const MixedSystem& mixed, const MixedSystem::Answer& answer,
                   const std::vector<Active>& current, double film_scale) {
  FilmRun run;
  const LinearSystem& system = problem.system();
  const std::vector<FloatingBand>& bands = system.floating_bands();
  if (bands.empty()) return run;
  const int m = problem.num_nodes();
  double peak = 0;
  for (int k = 0; k < m; ++k) peak = std::max(peak, answer.r.segment<2>(2 * k).norm());

  // 1. The film's columns: every interface node touching them carries a film-scale force.
  const ColumnOf column = columns_of_nodes(problem);
  std::map<std::pair<int, int>, bool> film;  // (band, column) → all its nodes small
  for (int k = 0; k < m; ++k)
    for (const auto& c : {column.plus[k], column.minus[k]}) {
      if (c.first < 0) continue;
      const bool small = answer.r.segment<2>(2 * k).norm() < film_scale * peak;
      auto [it, inserted] = film.emplace(c, small);
      if (!inserted) it->second = it->second && small;
    }
  std::vector<int> film_y;  // the film's unknowns in y
  for (const auto& [c, is_film] : film) {
    if (!is_film) continue;
    const BandLayout& L = bands[c.first].layout;
    const int offset = mixed.band_offset(c.first);
    for (int comp = 0; comp < 2; ++comp) film_y.push_back(offset + L.t(c.second) + comp);
    for (int j = 1; j <= L.across; ++j)
      for (int comp = 0; comp < 2; ++comp) film_y.push_back(offset + L.v(c.second, j) + comp);
  }
  for (int k = 0; k < m; ++k) {
    const bool on_film = (column.plus[k].first >= 0 && film[column.plus[k]]) ||
                         (column.minus[k].first >= 0 && film[column.minus[k]]);
    if (on_film) run.nodes.push_back(k);
  }
  if (run.nodes.empty()) {
    run.settled = true;
    return run;
  }
  std::sort(film_y.begin(), film_y.end());
  const int nf = static_cast<int>(film_y.size());
  std::vector<int> position(answer.y.size(), -1);
  for (int i = 0; i < nf; ++i) position[film_y[i]] = i;

  // 2. The film's stiffness with its neighbours held, and its load from them (y's band blocks).
  Eigen::SparseMatrix<double> K_FF(nf, nf);
  Eigen::VectorXd f_F = Eigen::VectorXd::Zero(nf);
  {
    std::vector<Eigen::Triplet<double>> t;
    for (size_t b = 0; b < bands.size(); ++b) {
      const int offset = mixed.band_offset(static_cast<int>(b));
      const Eigen::SparseMatrix<double>& K = bands[b].K;
      for (int col = 0; col < K.outerSize(); ++col)
        for (Eigen::SparseMatrix<double>::InnerIterator it(K, col); it; ++it) {
          const int i = position[offset + it.row()], j = position[offset + col];
          if (i < 0) continue;
          if (j >= 0) t.emplace_back(i, j, it.value());
          else f_F[i] -= it.value() * answer.y[offset + col];
        }
      for (int z = 0; z < bands[b].F.size(); ++z)
        if (position[offset + z] >= 0) f_F[position[offset + z]] += bands[b].F[z];
    }
    K_FF.setFromTriplets(t.begin(), t.end());
  }
  // 3. The film's rows: G_f on the film's unknowns, the rest of the jump frozen.
  const int rows = 2 * static_cast<int>(run.nodes.size());
  // 4. Eliminated: W_f = G K_FF⁻¹ Gᵀ, g_f = g_frozen + G K_FF⁻¹ f_F.
  Eliminated film_eliminated = eliminate(K_FF, f_F, jump_rows(problem, mixed, answer, run.nodes, position, nf));
  Condensed c;
  c.W = std::move(film_eliminated.W);
  c.g0 = std::move(film_eliminated.g);
  for (int q = 0; q < static_cast<int>(run.nodes.size()); ++q) {
    const int k = run.nodes[q];
    const InterfaceLaw& law = problem.law(k);
    for (int row = 0; row < 2; ++row) {
      const double C = problem.compliance()[2 * k + row];
      if (std::isfinite(C)) c.W(2 * q + row, 2 * q + row) += C;
    }
    c.normal.push_back(law.normal_active());
    c.bilateral.push_back(law.bilateral);
    c.tangential.push_back(law.bilateral ? law.K_T() > 0 : law.normal_active() && law.tangential_active());
    c.friction.push_back(law.tangential_active() && !law.bilateral ? law.friction : 0.0);
  }
  c.kappa = c.W.diagonal().cwiseMax(1e-300).cwiseInverse();

  // 5. Its statuses: the active set from the current ones; the Tresca fixed point where it cycles.
  Eigen::VectorXd r(rows), none;
  for (int q = 0; q < static_cast<int>(run.nodes.size()); ++q) r.segment<2>(2 * q) = answer.r.segment<2>(2 * run.nodes[q]);
  std::vector<Active> statuses;
  for (int k : run.nodes) statuses.push_back(current[k]);
  ActiveSetRun first = active_set(c, problem, statuses, r, none, 200);
  run.linear_solves += first.iterations;
  run.settled = first.settled;
  if (!first.settled) {
    const TrescaRun tresca = solve_tresca_fixed_point(c, r, 100, 1e-12);
    run.linear_solves += tresca.qp_iterations;
    statuses = guess_statuses(c, r, jump_part(c, r, none));
    const ActiveSetRun last = active_set(c, problem, statuses, r, none, 60);
    run.linear_solves += last.iterations;
    run.settled = last.settled;
  }
  run.statuses = statuses;
  return run;
}

FilmRun solve_band(const ContactProblem& problem, const MixedSystem& mixed, const MixedSystem::Answer& answer,
                   double film_scale, double rho) {
  FilmRun run;
  const LinearSystem& system = problem.system();
  const std::vector<FloatingBand>& bands = system.floating_bands();
  if (bands.empty()) return run;
  const int m = problem.num_nodes();
  double peak = 0;
  for (int k = 0; k < m; ++k) peak = std::max(peak, answer.r.segment<2>(2 * k).norm());
  // The band's unknowns in y, and the nodes that touch it.
  std::vector<int> band_y;
  for (size_t b = 0; b < bands.size(); ++b)
    for (int z = 0; z < bands[b].layout.size(); ++z) band_y.push_back(mixed.band_offset(static_cast<int>(b)) + z);
  const int nf = static_cast<int>(band_y.size());
  std::vector<int> position(answer.y.size(), -1);
  for (int i = 0; i < nf; ++i) position[band_y[i]] = i;
  for (int k = 0; k < m; ++k) {
    bool touches = false;
    for (int c = 0; c < 2; ++c)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(mixed.B_y(), 2 * k + c); it; ++it)
        touches = touches || position[it.col()] >= 0;
    if (touches) run.nodes.push_back(k);
  }
  const int n_nodes = static_cast<int>(run.nodes.size()), rows = 2 * n_nodes;
  // K_b + ρ P (P on each column's translation t), f_b + ρ P z.
  Eigen::SparseMatrix<double> K(nf, nf);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(nf);
  {
    std::vector<Eigen::Triplet<double>> t;
    int base = 0;
    for (size_t b = 0; b < bands.size(); ++b) {
      const Eigen::SparseMatrix<double>& Kb = bands[b].K;
      for (int col = 0; col < Kb.outerSize(); ++col)
        for (Eigen::SparseMatrix<double>::InnerIterator it(Kb, col); it; ++it) t.emplace_back(base + it.row(), base + col, it.value());
      f.segment(base, Kb.rows()) = bands[b].F;
      const BandLayout& L = bands[b].layout;
      for (int i = 0; i < L.columns; ++i)
        for (int c = 0; c < 2; ++c) {
          const int q = base + L.t(i) + c;
          t.emplace_back(q, q, rho);
          f[q] += rho * answer.y[band_y[q]];
        }
      base += static_cast<int>(Kb.rows());
    }
    K.setFromTriplets(t.begin(), t.end());
  }
  const Eliminated band = eliminate(K, f, jump_rows(problem, mixed, answer, run.nodes, position, nf));
  const Eigen::MatrixXd& W = band.W;
  const Eigen::VectorXd& g = band.g;

  // Bounds: pinched nodes d_N = 0 (r_N free), |r_T| ≤ f p; film nodes r_N ≤ 0, |r_T| ≤ f p (fixed point).
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<bool> pinched(n_nodes);
  Eigen::VectorXd r(rows), lo(rows), hi(rows), s(n_nodes);
  for (int q = 0; q < n_nodes; ++q) {
    const int k = run.nodes[q];
    r.segment<2>(2 * q) = answer.r.segment<2>(2 * k);
    pinched[q] = answer.r.segment<2>(2 * k).norm() >= film_scale * peak;  // its threshold is the answer's
    s[q] = problem.law(k).tangential_active() ? problem.law(k).friction * std::max(0.0, -answer.r[2 * k]) : 0.0;
  }
  AndersonAcceleration anderson(5);
  for (int update = 0; update < 100; ++update) {
    for (int q = 0; q < n_nodes; ++q) {
      lo[2 * q] = -infinity;
      hi[2 * q] = 0.0;
      lo[2 * q + 1] = -s[q];
      hi[2 * q + 1] = s[q];
    }
    const BoxQPRun qp = solve_box_qp(W, g, lo, hi, r);
    run.linear_solves += qp.iterations;
    Eigen::VectorXd image = s;
    for (int q = 0; q < n_nodes; ++q)
      if (!pinched[q])
        image[q] = problem.law(run.nodes[q]).tangential_active() ? problem.law(run.nodes[q]).friction * std::max(0.0, -r[2 * q]) : 0.0;
    const double change = (image - s).norm() / std::max(image.norm(), 1e-300);
    run.settled = qp.optimal && change <= 1e-10;
    if (std::getenv("FILM_DETAIL")) std::fprintf(stderr, "    band QP: %d iterations, %s, threshold change %.3e\n", qp.iterations, qp.optimal ? "optimal" : "not optimal", change);
    if (run.settled || change == 0) break;
    s = anderson.next(s, image).cwiseMax(0.0);
  }
  // The statuses: a pinched node is in contact, sticking inside its threshold, sliding at it.
  const Eigen::VectorXd d = g + W * r;
  for (int q = 0; q < n_nodes; ++q) {
    const int k = run.nodes[q];
    const double tol = 1e-9;
    const bool contact = r[2 * q] < 0 || d[2 * q] > tol * std::abs(g[2 * q]);
    if (!contact) {
      run.statuses.push_back(Active::Gap);
    } else if (!problem.law(k).tangential_active()) {
      run.statuses.push_back(Active::Frictionless);
    } else if (std::abs(r[2 * q + 1]) < (1 - 1e-9) * s[q]) {
      run.statuses.push_back(Active::Stick);
    } else {
      run.statuses.push_back(r[2 * q + 1] > 0 ? Active::SlidePositive : Active::SlideNegative);
    }
  }
  return run;
}

}  // namespace thinlayer
