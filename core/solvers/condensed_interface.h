#pragma once
// The bulk condensed onto the interface. The supported bodies are factored once (CHOLMOD):
//   W = B_A K_AA⁻¹ B_Aᵀ   (the Delassus operator, mm/daN),   g₀ = B_A K_AA⁻¹ F_A + g_D  (mm).
// The supported bodies share no stiffness, so K_AA is block-diagonal and each connected
// body b is factored on its own, its interface DOFs Γ_b ordered last:
//   W = Σ_b B_b S_b⁻¹ B_bᵀ,   S_b = K_b's Schur complement onto Γ_b,
// with S_b⁻¹ from the trailing block of body b's factor (SparseCholesky::trailing_factor).
// Each S_b⁻¹ costs (2/3)|Γ_b|³ (LAPACK dpotri), where one factor of all the bodies left one
// |Γ| × |Γ| trailing block to solve against all 2m columns of B_Γᵀ and a product Zᵀ Z: for the
// dovetail's two bodies at h = 0.0125 (|Γ_b| = 370, 2m = 370) 2·3.4e7 flops against 3e8.
// The factorisations with Γ_b last remain the bulk of the cost: 1.3–1.45 × a plain
// factorisation of the same body (CAMD with Γ_b last: 1.6–1.9 × its fill, 3.6–5.7 × its
// flops at h = 0.0125; METIS on the interior saves flops but costs more to order).
// A floating body (the thin layer, Body::floating) is never factored whole — its stiffness is
// singular when its contacts open. Each is condensed onto the unknowns x through which its
// interfaces touch it (core/solvers/floating_condensation.h: a layer band in its column basis):
//   S x = f_L + B_Lᵀ r,
// and the solver keeps x as unknowns. The jumps are then g = g₀ + W r + B_L x.
// Nothing here depends on the interface law: every scene that shares the mesh, materials,
// supports and loads (all Table 3 rows, all limit-mode law cases) shares one of these.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/linalg/sparse_cholesky.h"
#include "core/solvers/contact_problem.h"
#include "core/solvers/floating_condensation.h"

namespace thinlayer {

class CondensedInterface {
 public:
  explicit CondensedInterface(const ContactProblem& problem);

  const Eigen::MatrixXd& W() const { return W_; }
  const Eigen::VectorXd& g0() const { return g0_; }
  // Floating bodies (empty when there are none): their unknowns x, one block per body.
  int num_floating_unknowns() const { return static_cast<int>(S_.rows()); }
  const Eigen::MatrixXd& B_L() const { return B_L_; }  // 2m × |x|
  const Eigen::MatrixXd& S() const { return S_; }      // |x| × |x|, daN/mm, singular if it floats
  const Eigen::VectorXd& f_L() const { return f_L_; }
  // The selection spring's pattern on x (FloatingCondensation::selection), block by block.
  Eigen::MatrixXd floating_selection(LayerSelection face) const;

  // Bulk displacement (free DOFs) for interface forces r and floating-body unknowns x.
  Eigen::VectorXd displacement(const ContactProblem& problem, const Eigen::VectorXd& r,
                               const Eigen::VectorXd& x) const;
  double setup_time_s() const { return setup_time_s_; }  // factorisations + condensation
  // The smallest of the factors' SparseCholesky::rcond() (1 if none): a crude, optimistic
  // estimate, for reporting a loss of accuracy.
  double rcond() const;

 private:
  // A connected supported body: its free DOFs (ascending) and its factor, Γ_b last.
  struct SupportedBody {
    std::vector<int> dofs;
    std::shared_ptr<SparseCholesky> factor;
  };
  // Factors one body, adds its part to W_ and g0_, and keeps its factor.
  void condense_body(const ContactProblem& problem, std::vector<int> dofs, const std::vector<bool>& on_interface);

  // Condenses the floating bodies and assembles B_L_, S_, f_L_ from their blocks.
  void condense_floating(const ContactProblem& problem, const std::vector<bool>& on_interface);

  std::vector<SupportedBody> supported_;
  std::vector<FloatingCondensation> floating_;
  Eigen::MatrixXd W_, B_L_, S_;
  Eigen::VectorXd g0_, f_L_;
  double setup_time_s_ = 0;
};

}  // namespace thinlayer
