#include "core/solvers/block_minimiser.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

namespace thinlayer {

namespace {

// The branches a row of each kind can take.
std::vector<RowState> branches(RowKind kind) {
  switch (kind) {
    case RowKind::Free: return {RowState::Open};
    case RowKind::Equality: return {RowState::Kink};
    case RowKind::Obstacle: return {RowState::Kink, RowState::Open};
    case RowKind::Friction: return {RowState::Kink, RowState::Plus, RowState::Minus};
  }
  return {RowState::Open};
}

// One branch: the equality-constrained minimiser and its multipliers, or false where the branch's
// KKT matrix is singular (its kink rows dependent).
bool solve_branch(const BlockProblem& p, const std::vector<RowState>& state, const Eigen::VectorXd& jacobi,
                  Eigen::VectorXd& x, Eigen::VectorXd& lambda) {
  const int n = static_cast<int>(p.A.rows()), rows = static_cast<int>(p.G.rows());
  std::vector<int> kink;
  Eigen::VectorXd rhs = p.c;
  lambda = Eigen::VectorXd::Zero(rows);
  for (int i = 0; i < rows; ++i) {
    if (state[i] == RowState::Kink) kink.push_back(i);
    else if (state[i] == RowState::Plus) lambda[i] = p.s[i];
    else if (state[i] == RowState::Minus) lambda[i] = -p.s[i];
    if (lambda[i] != 0) rhs -= p.G.row(i).transpose() * lambda[i];
  }
  const int q = static_cast<int>(kink.size());
  // x = D x̂ with D = diag(jacobi): the scaled stiffness has a unit diagonal.
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + q, n + q);
  Eigen::VectorXd b(n + q);
  K.topLeftCorner(n, n) = jacobi.asDiagonal() * p.A * jacobi.asDiagonal();
  b.head(n) = jacobi.cwiseProduct(rhs);
  for (int a = 0; a < q; ++a) {
    const Eigen::RowVectorXd Gd = p.G.row(kink[a]).cwiseProduct(jacobi.transpose());
    K.block(n + a, 0, 1, n) = Gd;
    K.block(0, n + a, n, 1) = Gd.transpose();
    b[n + a] = -p.g[kink[a]];
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
  if (!lu.isInvertible()) return false;
  const Eigen::VectorXd z = lu.solve(b);
  x = jacobi.cwiseProduct(z.head(n));
  for (int a = 0; a < q; ++a) lambda[kink[a]] = z[n + a];
  return x.allFinite() && lambda.allFinite();
}

// How far a branch's answer is from satisfying its inequalities: the largest excess, each relative
// to the size of the terms that make the quantity (|G||x| + |g| for a jump; the forces at the
// unknowns the row touches for a multiplier).
double inconsistency(const BlockProblem& p, const std::vector<RowState>& state, const Eigen::VectorXd& x,
                     const Eigen::VectorXd& lambda) {
  const int rows = static_cast<int>(p.G.rows());
  const Eigen::VectorXd force_size =
      p.A.cwiseAbs() * x.cwiseAbs() + p.c.cwiseAbs() + p.G.cwiseAbs().transpose() * lambda.cwiseAbs();
  double worst = 0;
  for (int i = 0; i < rows; ++i) {
    const double d = p.G.row(i).dot(x) + p.g[i];
    const double d_size = p.G.row(i).cwiseAbs().dot(x.cwiseAbs()) + std::abs(p.g[i]);
    double f_size = 0;
    for (int j = 0; j < p.G.cols(); ++j)
      if (p.G(i, j) != 0) f_size = std::max(f_size, force_size[j] / std::abs(p.G(i, j)));
    auto relative = [](double excess, double size) { return excess <= 0 ? 0.0 : size > 0 ? excess / size : HUGE_VAL; };
    double e = 0;
    switch (state[i]) {
      case RowState::Open:
        if (p.kind[i] == RowKind::Obstacle) e = relative(d, d_size);
        break;
      case RowState::Kink:
        if (p.kind[i] == RowKind::Obstacle) e = relative(-lambda[i], f_size);
        if (p.kind[i] == RowKind::Friction) e = relative(std::abs(lambda[i]) - p.s[i], f_size);
        break;
      case RowState::Plus: e = relative(-d, d_size); break;
      case RowState::Minus: e = relative(d, d_size); break;
    }
    worst = std::max(worst, e);
  }
  return worst;
}

}  // namespace

BlockMinimum minimise_block(const BlockProblem& p, const std::vector<RowState>& guess) {
  const int n = static_cast<int>(p.A.rows()), rows = static_cast<int>(p.G.rows());
  Eigen::VectorXd jacobi(n);
  for (int j = 0; j < n; ++j) {
    if (!(p.A(j, j) > 0)) throw std::invalid_argument("minimise_block: the block's stiffness is not positive definite");
    jacobi[j] = 1.0 / std::sqrt(p.A(j, j));
  }
  BlockMinimum best;
  best.inconsistency = HUGE_VAL;
  int kinks_of_best = -1;
  auto consider = [&](const std::vector<RowState>& state) {
    Eigen::VectorXd x, lambda;
    ++best.branches_solved;
    if (!solve_branch(p, state, jacobi, x, lambda)) return;
    const double e = inconsistency(p, state, x, lambda);
    const int kinks = static_cast<int>(std::count(state.begin(), state.end(), RowState::Kink));
    // Ties (a row exactly at its kink with a zero force satisfies two branches) go to the branch
    // with more rows at their kink: the truncated correction then holds them there.
    if (e < best.inconsistency || (e == best.inconsistency && kinks > kinks_of_best)) {
      best.x = x;
      best.lambda = lambda;
      best.state = state;
      best.inconsistency = e;
      kinks_of_best = kinks;
    }
  };
  // The guess, each row's state made one of its kind's branches (a row's kind changes with its
  // threshold: a Friction row whose s fell to 0 is Free).
  std::vector<RowState> first = guess;
  if (static_cast<int>(first.size()) == rows) {
    for (int i = 0; i < rows; ++i) {
      const std::vector<RowState> allowed = branches(p.kind[i]);
      if (std::find(allowed.begin(), allowed.end(), first[i]) == allowed.end()) first[i] = allowed.front();
    }
    consider(first);
    if (best.inconsistency == 0) return best;
  }
  std::vector<std::vector<RowState>> options(rows);
  double combinations = 1;
  for (int i = 0; i < rows; ++i) {
    options[i] = branches(p.kind[i]);
    combinations *= static_cast<double>(options[i].size());
  }
  if (combinations > 4096)
    throw std::invalid_argument("minimise_block: " + std::to_string(rows) + " rows in one block are too many to enumerate");
  std::vector<int> pick(rows, 0);
  std::vector<RowState> state(rows);
  while (true) {
    for (int i = 0; i < rows; ++i) state[i] = options[i][pick[i]];
    if (state != first) consider(state);
    int i = 0;
    while (i < rows && ++pick[i] == static_cast<int>(options[i].size())) pick[i++] = 0;
    if (i == rows) break;
  }
  if (best.x.size() == 0) throw std::runtime_error("minimise_block: every branch's KKT system is singular");
  return best;
}

Eigen::VectorXd project_to_domain(const Eigen::MatrixXd& A, const Eigen::MatrixXd& G, const Eigen::VectorXd& g,
                                  const std::vector<RowKind>& kind, const Eigen::VectorXd& x_hat) {
  const int rows = static_cast<int>(G.rows());
  bool feasible = true;
  BlockProblem p;
  p.A = A;
  p.c = A * x_hat;  // min ½ xᵀA x − (A x̂)ᵀx: the energy-norm distance to x̂
  p.G = G;
  p.g = g;
  p.kind.assign(rows, RowKind::Free);
  p.s = Eigen::VectorXd::Zero(rows);
  for (int i = 0; i < rows; ++i) {
    const double d = G.row(i).dot(x_hat) + g[i];
    if (kind[i] == RowKind::Equality) p.kind[i] = RowKind::Equality, feasible = feasible && d == 0;
    if (kind[i] == RowKind::Obstacle) p.kind[i] = RowKind::Obstacle, feasible = feasible && d <= 0;
  }
  if (feasible) return x_hat;
  return minimise_block(p).x;
}

}  // namespace thinlayer
