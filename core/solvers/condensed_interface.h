#pragma once
// The bulk condensed onto the interface: factor K once (CHOLMOD), then
//   W = B K⁻¹ Bᵀ   (the Delassus operator, mm/daN)   and   g₀ = B K⁻¹ F + g_D  (mm),
// so that the jumps are g = g₀ + W r for any interface forces r. Everything here depends on
// the mesh, the materials, the supports and the loads, never on the interface law: every
// scene that shares them (all Table 3 rows, all limit-mode law cases) shares one of these.
#include <memory>

#include <Eigen/Core>

#include "core/linalg/sparse_cholesky.h"
#include "core/solvers/contact_problem.h"

namespace thinlayer {

class CondensedInterface {
 public:
  explicit CondensedInterface(const ContactProblem& problem);

  const Eigen::MatrixXd& W() const { return W_; }
  const Eigen::VectorXd& g0() const { return g0_; }
  // Bulk displacement for given interface forces: u = K⁻¹ (F + Bᵀ r).
  Eigen::VectorXd displacement(const ContactProblem& problem, const Eigen::VectorXd& r) const;
  double setup_time_s() const { return setup_time_s_; }  // factorisation + condensation

 private:
  std::shared_ptr<SparseCholesky> factor_;
  Eigen::MatrixXd W_;
  Eigen::VectorXd g0_;
  double setup_time_s_ = 0;
};

}  // namespace thinlayer
