#pragma once
// The bulk condensed onto the interface. The supported bodies are factored once (CHOLMOD):
//   W = B_A K_AA⁻¹ B_Aᵀ   (the Delassus operator, mm/daN),   g₀ = B_A K_AA⁻¹ F_A + g_D  (mm).
// K_AA is factored exactly as a linear solve factors it (CHOLMOD's own fill-reducing order),
// and W comes from the block of K_AA⁻¹ on the interface DOFs Γ (SparseCholesky::
// inverse_congruence): Z = L⁻¹ P E_Γ by a forward solve restricted to the paths from Γ to the
// roots of the elimination tree, then K_ΓΓ⁻¹ = Zᵀ Z. The supported bodies share no stiffness,
// so each is a tree of its own and is condensed on its own: W = Σ_b B_b (K_b⁻¹)_ΓΓ B_bᵀ.
// For the dovetail at h = 0.0125 (two bodies, |Γ_b| = 370) that is 1.7e8 flops in 4.4 ms, a
// fifth of one linear solve (22.6 ms), where ordering each Γ_b last to read S_b from its
// factor's trailing block (the previous design) made the numeric factorisation itself 1.5
// times a plain one (22 ms against 14.5) before S_b⁻¹ (dpotri, 6.8e7 flops, 2 ms).
// The bar is the other way round: its Γ is one straight edge, which costs nothing to order
// last, while the paths from Γ cross its largest separators (at 256 contact nodes the blocks
// cost a tenth of the factorisation, 2.8e9 flops).
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
  // Each layer band's displacement in its column basis (LinearSystem::floating_bands order), cut
  // out of x: what contact_residual evaluates a band's balance on.
  std::vector<Eigen::VectorXd> band_coordinates(const Eigen::VectorXd& x) const;
  // The inverse: x from the free DOFs u and each band's column basis z (an answer solved without
  // condensation, core/solvers/mixed_system.h).
  Eigen::VectorXd floating_unknowns(const Eigen::VectorXd& u, const std::vector<Eigen::VectorXd>& band_z) const;
  double setup_time_s() const { return setup_time_s_; }  // factorisations + condensation
  // The smallest of the factors' SparseCholesky::rcond() (1 if none): a crude, optimistic
  // estimate, for reporting a loss of accuracy.
  double rcond() const;

 private:
  // Factors the supported bodies' stiffness (their free DOFs `dofs`, ascending) and forms W_, g0_.
  void condense_supported(const ContactProblem& problem, std::vector<int> dofs);

  // Condenses the floating bodies and assembles B_L_, S_, f_L_ from their blocks.
  void condense_floating(const ContactProblem& problem, const std::vector<bool>& on_interface);

  std::vector<int> supported_;               // the supported free DOFs, ascending
  std::shared_ptr<SparseCholesky> factor_;   // of their stiffness (null if none)
  std::vector<FloatingCondensation> floating_;
  Eigen::MatrixXd W_, B_L_, S_;
  Eigen::VectorXd g0_, f_L_;
  double setup_time_s_ = 0;
};

}  // namespace thinlayer
