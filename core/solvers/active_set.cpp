#include "core/solvers/active_set.h"

#include <cmath>
#include <set>

#include <Eigen/Dense>

#include "core/linalg/equilibrated_solve.h"

namespace thinlayer {

Condensed law_rules(const ContactProblem& problem, const Eigen::VectorXd& kappa, bool skip_frictionless_rows) {
  Condensed c;
  c.kappa = kappa;
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceLaw& law = problem.law(k);
    c.normal.push_back(law.normal_active());
    c.bilateral.push_back(law.bilateral);
    if (law.bilateral) {  // each row carries a force wherever its stiffness is not zero
      c.tangential.push_back(law.K_T() > 0);
      c.friction.push_back(0.0);
    } else {
      // Without the skip, a frictionless node keeps its tangential row as a slide with r_T = 0.
      c.tangential.push_back(law.normal_active() && (law.tangential_active() || !skip_frictionless_rows));
      c.friction.push_back(law.tangential_active() ? law.friction : 0.0);
    }
  }
  return c;
}

Condensed condense(const ContactProblem& problem, const CondensedInterface& ci, double complementarity_scale,
                   bool skip_frictionless_rows) {
  // The complementarity parameter of the Newton method: the nodal stiffness of both sides (not
  // 1/diag(W + C), which is zero on a face of a floating body), scaled down so that the statuses
  // follow the forces more than the jumps (see SolverOptions).
  Condensed c = law_rules(problem, complementarity_scale * problem.kappa(), skip_frictionless_rows);
  c.W = ci.W();
  c.g0 = ci.g0();
  c.B_L = ci.B_L();
  c.S = ci.S();
  c.f_L = ci.f_L();
  for (int i = 0; i < c.W.rows(); ++i) {
    const double C = problem.compliance()[i];
    if (std::isfinite(C)) c.W(i, i) += C;
  }
  return c;
}

// The active-set guess from the current iterate: the sign pattern of the natural map.
std::vector<Active> guess_statuses(const Condensed& c, const Eigen::VectorXd& r, const Eigen::VectorXd& d) {
  const int m = static_cast<int>(c.normal.size());
  std::vector<Active> s(m);
  for (int k = 0; k < m; ++k) {
    if (c.bilateral[k]) {  // whatever the iterate: bonded, unless the law carries nothing
      s[k] = c.normal[k] || c.tangential[k] ? Active::Bonded : Active::Gap;
      continue;
    }
    const double predicted_pressure = -r[2 * k] + c.kappa[2 * k] * d[2 * k];
    if (!c.normal[k] || predicted_pressure <= 0) {
      s[k] = Active::Gap;
    } else if (!c.tangential[k]) {
      s[k] = Active::Frictionless;
    } else {
      const double z = r[2 * k + 1] - c.kappa[2 * k + 1] * d[2 * k + 1];
      const double threshold = c.friction[k] * predicted_pressure;
      s[k] = std::abs(z) < threshold ? Active::Stick : (z > 0 ? Active::SlidePositive : Active::SlideNegative);
    }
  }
  return s;
}

int floating_unknowns(const Condensed& c) { return static_cast<int>(c.S.rows()); }

bool floating_bodies_free(const Condensed& c, const std::vector<Active>& statuses) {
  if (floating_unknowns(c) == 0) return false;
  for (int k = 0; k < static_cast<int>(statuses.size()); ++k) {
    const bool touches_floating = c.B_L.middleRows<2>(2 * k).cwiseAbs().maxCoeff() > 0;
    if (touches_floating && statuses[k] != Active::Gap) return false;
  }
  return true;
}

// d = g₀ + (W + C) r + B_L w.
Eigen::VectorXd jump_part(const Condensed& c, const Eigen::VectorXd& r, const Eigen::VectorXd& w) {
  Eigen::VectorXd d = c.g0 + c.W * r;
  if (floating_unknowns(c)) d += c.B_L * w;
  return d;
}


Step solve_statuses(const Condensed& c, const std::vector<Active>& s) {
  // The statuses fix part of r outright: r = 0 at a gap, r_T = ±f|r_N| on a slide, r_T = 0
  // without friction. The remaining unknowns are r_N at every contact, r_T at every stick,
  // and w: r = Q x_r, where column j of Q is unit at its row, plus the slide coupling.
  const int m2 = static_cast<int>(c.g0.size()), nw = floating_unknowns(c);
  std::vector<int> rows;  // the equation (d_N = 0 or d_T = 0) that goes with each unknown
  std::vector<std::pair<int, double>> coupling;  // for an r_N column: the T row it drives, and how
  for (int k = 0; k < static_cast<int>(s.size()); ++k) {
    if (s[k] == Active::Gap) continue;
    if (s[k] == Active::Bonded) {  // d = 0 on each row with a force, r free in sign
      for (int row = 0; row < 2; ++row)
        if (row == 0 ? c.normal[k] : c.tangential[k]) {
          rows.push_back(2 * k + row);
          coupling.push_back({-1, 0.0});
        }
      continue;
    }
    rows.push_back(2 * k);
    const bool slide = s[k] == Active::SlidePositive || s[k] == Active::SlideNegative;
    // SlidePositive: r_T = +f p = -f r_N; SlideNegative: r_T = -f p = +f r_N.
    coupling.push_back({slide ? 2 * k + 1 : -1,
                        s[k] == Active::SlidePositive ? -c.friction[k] : c.friction[k]});
    if (s[k] == Active::Stick) {
      rows.push_back(2 * k + 1);
      coupling.push_back({-1, 0.0});
    }
  }
  const int nr = static_cast<int>(rows.size()), n = nr + nw;
  // Column j of M Q is column rows[j] of M, plus the slide coupling times its T column.
  auto times_Q = [&](const auto& M, int j) {
    Eigen::VectorXd col = M.col(rows[j]);
    if (coupling[j].first >= 0) col += coupling[j].second * M.col(coupling[j].first);
    return col;
  };
  // Assembled as triplets: with a floating layer the system is a dense block of contact rows,
  // the layer's banded stiffness and a sparse coupling, which a sparse LU factors 5× faster.
  std::vector<Eigen::Triplet<double>> triplets;
  auto add = [&](int i, int j, double v) {
    if (v != 0) triplets.emplace_back(i, j, v);
  };
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < nr; ++j) {  // d = 0 on the active rows: W Q x_r + B_L w = -g0
    const Eigen::VectorXd WQ_j = times_Q(c.W, j);
    for (int i = 0; i < nr; ++i) add(i, j, WQ_j[rows[i]]);
  }
  for (int i = 0; i < nr; ++i) {
    for (int k = 0; k < nw; ++k) add(i, nr + k, c.B_L(rows[i], k));
    b[i] = -c.g0[rows[i]];
  }
  if (nw) {  // S w - B_Lᵀ Q x_r = f_L
    for (int j = 0; j < nr; ++j) {
      const Eigen::VectorXd column = times_Q(c.B_L.transpose(), j);
      for (int k = 0; k < nw; ++k) add(nr + k, j, -column[k]);
    }
    for (int q = 0; q < nw; ++q)
      for (int p = 0; p < nw; ++p) add(nr + p, nr + q, c.S(p, q));
    b.tail(nw) = c.f_L;
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(triplets.begin(), triplets.end());
  Step step;
  Eigen::VectorXd x = n == 0 ? Eigen::VectorXd()
                      : nw ? solve_equilibrated(A, b, &step.rcond)
                           : solve_equilibrated(Eigen::MatrixXd(A), b, &step.rcond);
  // A floating body whose contacts are all open (or only slide) has rigid motions the step
  // cannot fix: the system is singular. Then take the minimum-norm solution and say so.
  const double scale = std::max(b.norm(), 1e-300);
  if (n && (!x.allFinite() || (A * x - b).norm() > 1e-8 * scale)) {
    x = Eigen::MatrixXd(A).completeOrthogonalDecomposition().solve(b);
    step.singular = true;
  }
  step.r = Eigen::VectorXd::Zero(m2);
  for (int j = 0; j < nr; ++j) {
    step.r[rows[j]] += x[j];
    if (coupling[j].first >= 0) step.r[coupling[j].first] += coupling[j].second * x[j];
  }
  step.w = x.tail(nw);
  return step;
}

// Relative norm of the natural map on the condensed problem (same map as contact_residual).
double condensed_residual(const Condensed& c, const ContactProblem& problem, const Eigen::VectorXd& r,
                          const Eigen::VectorXd& d) {
  double norm2 = 0;
  for (int k = 0; k < problem.num_nodes(); ++k)
    norm2 += natural_map(problem.law(k), r.segment<2>(2 * k), d.segment<2>(2 * k), c.kappa.segment<2>(2 * k))
                 .squaredNorm();
  const double scale = r.norm() > 0 ? r.norm() : 1.0;
  return std::sqrt(norm2) / scale;
}

namespace {

// Local law at one node with the others frozen: d = q + A r (A the node's 2×2 block).
Eigen::Vector2d local_solve(const Condensed& c, int k, const Eigen::Vector2d& q, const Eigen::Matrix2d& A) {
  if (c.bilateral[k]) {  // d = 0 on the rows that carry a force, whatever the sign of r
    if (c.normal[k] && c.tangential[k]) return A.ldlt().solve(-q);
    if (c.normal[k]) return {-q[0] / A(0, 0), 0.0};
    if (c.tangential[k]) return {0.0, -q[1] / A(1, 1)};
    return Eigen::Vector2d::Zero();
  }
  if (!c.normal[k] || q[0] <= 0) return Eigen::Vector2d::Zero();  // gap
  if (!c.tangential[k]) return {std::min(0.0, -q[0] / A(0, 0)), 0.0};
  const double f = c.friction[k];
  const Eigen::Vector2d stick = A.ldlt().solve(-q);
  if (stick[0] <= 0 && std::abs(stick[1]) <= -f * stick[0]) return stick;
  for (double s : {+1.0, -1.0}) {  // slide: r_T = s f p, d_N = 0, slip against r_T
    const double denominator = A(0, 0) - s * f * A(0, 1);
    if (!(denominator > 0)) continue;
    const double rN = -q[0] / denominator;
    const Eigen::Vector2d slide(rN, -s * f * rN);
    const double dT = q[1] + A(1, 0) * slide[0] + A(1, 1) * slide[1];
    if (rN <= 0 && s * dT <= 0) return slide;
  }
  return stick;  // no consistent branch (a non-associated corner case): keep the elastic one
}

}  // namespace

void nsgs_sweeps(const Condensed& c, Eigen::VectorXd& r, int sweeps) {
  const int m = static_cast<int>(c.normal.size());
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (int k = 0; k < m; ++k) {
      const Eigen::Matrix2d A = c.W.block<2, 2>(2 * k, 2 * k);
      const Eigen::Vector2d q = c.g0.segment<2>(2 * k) + c.W.middleRows<2>(2 * k) * r - A * r.segment<2>(2 * k);
      r.segment<2>(2 * k) = local_solve(c, k, q, A);
    }
}


// Semismooth Newton / primal-dual active set from the given statuses and iterate.
ActiveSetRun active_set(const Condensed& c, const ContactProblem& problem, std::vector<Active>& statuses,
                        Eigen::VectorXd& r, Eigen::VectorXd& w, int max_iterations) {
  ActiveSetRun run;
  std::set<std::vector<Active>> visited;
  const bool damped = floating_unknowns(c) > 0;
  for (run.iterations = 1; run.iterations <= max_iterations; ++run.iterations) {
    const Step step = solve_statuses(c, statuses);
    run.singular = step.singular;
    run.rcond = step.rcond;
    if (damped && run.iterations > 1) {
      // Globalise the Newton step with a backtracking line search on the natural map.
      const double merit0 = condensed_residual(c, problem, r, jump_part(c, r, w));
      double t = 1;
      for (; t > 1e-4; t *= 0.5) {
        const Eigen::VectorXd rt = r + t * (step.r - r), wt = w + t * (step.w - w);
        if (condensed_residual(c, problem, rt, jump_part(c, rt, wt)) < (1 - 1e-4 * t) * merit0) break;
      }
      r += t * (step.r - r);
      w += t * (step.w - w);
    } else {
      r = step.r;
      w = step.w;
    }
    std::vector<Active> next = guess_statuses(c, r, jump_part(c, r, w));
    if (next == statuses) {  // a fixed point: re-solving the same statuses changes nothing
      run.settled = true;
      break;
    }
    // The active set cycles: let NSGS move the iterate (bodies with supports only).
    if (!visited.insert(next).second && floating_unknowns(c) == 0) {
      nsgs_sweeps(c, r, 20);
      run.nsgs_sweeps += 20;
      next = guess_statuses(c, r, jump_part(c, r, w));
      visited.clear();
    }
    statuses = std::move(next);
  }
  run.iterations = std::min(run.iterations, max_iterations);
  return run;
}


}  // namespace thinlayer
