#include "core/solvers/fast_solver.h"

#include <chrono>
#include <cmath>
#include <set>
#include <sstream>

#include <Eigen/Dense>

namespace thinlayer {

namespace {

// The status a node's rows are solved for in one active-set step.
enum class Active : int { Gap, Stick, SlidePositive, SlideNegative, Frictionless };

struct Condensed {
  Eigen::MatrixXd W;        // W + C on the rows that carry a force; identity elsewhere
  Eigen::VectorXd g0;
  Eigen::VectorXd kappa;    // 1 / diag(W + C): the local stiffness of each row
  std::vector<bool> normal, tangential;  // does the row carry a force at all
  std::vector<double> friction;
};

Condensed condense(const ContactProblem& problem, const CondensedInterface& ci) {
  const int m = problem.num_nodes();
  Condensed c{ci.W(), ci.g0(), Eigen::VectorXd::Zero(2 * m), {}, {}, {}};
  for (int k = 0; k < m; ++k) {
    const InterfaceLaw& law = problem.law(k);
    c.normal.push_back(law.normal_active());
    c.tangential.push_back(law.normal_active() && law.tangential_active());
    c.friction.push_back(law.friction);
    for (int row = 0; row < 2; ++row) {
      const double C = problem.compliance()[2 * k + row];
      if (std::isfinite(C)) c.W(2 * k + row, 2 * k + row) += C;
      c.kappa[2 * k + row] = 1.0 / c.W(2 * k + row, 2 * k + row);
    }
  }
  return c;
}

// The active-set guess from the current iterate: the sign pattern of the natural map.
std::vector<Active> guess_statuses(const Condensed& c, const Eigen::VectorXd& r, const Eigen::VectorXd& d) {
  const int m = static_cast<int>(c.normal.size());
  std::vector<Active> s(m);
  for (int k = 0; k < m; ++k) {
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

// One Newton step: the linear system that the guessed statuses make of the law.
Eigen::VectorXd solve_statuses(const Condensed& c, const std::vector<Active>& s) {
  const int n = static_cast<int>(c.g0.size());
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < static_cast<int>(s.size()); ++k) {
    const int N = 2 * k, T = 2 * k + 1;
    if (s[k] == Active::Gap) {  // r = 0
      A(N, N) = 1;
      A(T, T) = 1;
      continue;
    }
    A.row(N) = c.W.row(N);  // d_N = 0
    b[N] = -c.g0[N];
    switch (s[k]) {
      case Active::Stick:  // d_T = 0
        A.row(T) = c.W.row(T);
        b[T] = -c.g0[T];
        break;
      case Active::SlidePositive:  // r_T = +f p = -f r_N
      case Active::SlideNegative:  // r_T = -f p = +f r_N
        A(T, T) = 1;
        A(T, N) = s[k] == Active::SlidePositive ? c.friction[k] : -c.friction[k];
        break;
      default:  // frictionless: r_T = 0
        A(T, T) = 1;
        break;
    }
  }
  return A.partialPivLu().solve(b);
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

// Local law at one node with the others frozen: d = q + A r (A the node's 2×2 block).
Eigen::Vector2d local_solve(const Condensed& c, int k, const Eigen::Vector2d& q, const Eigen::Matrix2d& A) {
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

void nsgs_sweeps(const Condensed& c, Eigen::VectorXd& r, int sweeps) {
  const int m = static_cast<int>(c.normal.size());
  for (int sweep = 0; sweep < sweeps; ++sweep)
    for (int k = 0; k < m; ++k) {
      const Eigen::Matrix2d A = c.W.block<2, 2>(2 * k, 2 * k);
      const Eigen::Vector2d q = c.g0.segment<2>(2 * k) + c.W.middleRows<2>(2 * k) * r - A * r.segment<2>(2 * k);
      r.segment<2>(2 * k) = local_solve(c, k, q, A);
    }
}

}  // namespace

SolveReport solve_fast(const ContactProblem& problem, const CondensedInterface& condensed,
                       const SolverOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SolveReport report;
  report.solver = "fast";
  report.tolerance = options.tolerance;
  const int max_iterations = options.max_iterations > 0 ? options.max_iterations : 200;
  const Condensed c = condense(problem, condensed);

  Eigen::VectorXd r = Eigen::VectorXd::Zero(c.g0.size());
  Eigen::VectorXd d = c.g0;
  std::set<std::vector<Active>> visited;
  int nsgs_total = 0;
  std::vector<Active> statuses = guess_statuses(c, r, d);
  for (report.iterations = 1; report.iterations <= max_iterations; ++report.iterations) {
    r = solve_statuses(c, statuses);
    d = c.g0 + c.W * r;
    std::vector<Active> next = guess_statuses(c, r, d);
    // A fixed point of the active-set map is the exact solution of the law; the residual
    // check guards against accepting one that is not (it never happened in our cases).
    if (next == statuses && condensed_residual(c, problem, r, d) <= 0.1 * options.tolerance) break;
    if (!visited.insert(next).second) {  // the active set cycles: let NSGS move the iterate
      nsgs_sweeps(c, r, 20);
      nsgs_total += 20;
      d = c.g0 + c.W * r;
      next = guess_statuses(c, r, d);
      visited.clear();
    }
    statuses = std::move(next);
  }
  report.iterations = std::min(report.iterations, max_iterations);

  report.r = r;
  report.u = condensed.displacement(problem, r);
  report.residual = contact_residual(problem, report.u, report.r);
  report.converged = report.residual.value() <= options.tolerance;
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream msg;
  msg << (report.converged ? "converged" : "NOT converged") << " after " << report.iterations
      << " active-set steps" << (nsgs_total ? " and " + std::to_string(nsgs_total) + " NSGS sweeps" : "")
      << ", residual " << report.residual.value() << " (tolerance " << options.tolerance << ")";
  report.message = msg.str();
  return report;
}

SolveReport solve_fast(const ContactProblem& problem, const SolverOptions& options) {
  const CondensedInterface condensed(problem);
  return solve_fast(problem, condensed, options);
}

}  // namespace thinlayer
