#include "core/solvers/condensed_interface.h"

#include <chrono>

namespace thinlayer {

CondensedInterface::CondensedInterface(const ContactProblem& problem) {
  const auto start = std::chrono::steady_clock::now();
  const LinearSystem& system = problem.system();
  factor_ = std::make_shared<SparseCholesky>(system.K());
  const Eigen::MatrixXd Bt = Eigen::MatrixXd(problem.B().transpose());
  const Eigen::MatrixXd X = factor_->solve(Bt);  // K⁻¹ Bᵀ, one column per interface row
  W_ = problem.B() * X;
  W_ = 0.5 * (W_ + W_.transpose()).eval();      // symmetric up to round-off; make it exact
  g0_ = problem.B() * factor_->solve(system.F()) + problem.jump_offset();
  setup_time_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Eigen::VectorXd CondensedInterface::displacement(const ContactProblem& problem, const Eigen::VectorXd& r) const {
  const Eigen::VectorXd rhs = problem.system().F() + problem.B().transpose() * r;
  return factor_->solve(rhs);
}

}  // namespace thinlayer
