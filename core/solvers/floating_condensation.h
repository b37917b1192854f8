#pragma once
// A floating body (the thin layer, or a body held by its contacts alone) condensed onto the
// unknowns x through which its interfaces touch it: its stiffness is never factored whole
// (singular while its contacts are open), only its interior with x held:
//   S x = f + Tᵀ (Bᵀ r)_faces,   S = K_xx − K_xi K_ii⁻¹ K_ix,   f = F_x − K_xi K_ii⁻¹ F_i.
// The face DOFs w (the interface's nodes on this body) follow x as w = T x.
//  - A layer band (LinearSystem::floating_bands) is kept whole in its column basis
//    (core/fem/column_basis.h): x = z, per column the translation t of its minus-face node and
//    each node's displacement v relative to it, so w_minus = t and w_plus = t + v_top. Its
//    stiffness is banded and nothing is condensed (S = K_zz, sparse in all but storage); the
//    film's in-plane stiffness, on t, is accurate to round-off of its own size instead of 1e-16
//    of the through-thickness one.
//  - Any other floating body is condensed nodally: x = w, T = I.
// The translations are where the layer's position is not unique; the solvers' selection spring
// acts on them (core/solvers/floating_layer.h): on the minus face t, or on the plus face t + v,
// of a band; on every face DOF of a nodal body.
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/fem/linear_system.h"
#include "core/linalg/sparse_cholesky.h"

namespace thinlayer {

// Which face of a layer the selection spring holds (SPEC §1.5: two selections must agree on
// what the problem determines).
enum class LayerSelection { MinusFace, PlusFace };

class FloatingCondensation {
 public:
  // A layer band; on_interface flags the free DOFs that some interface touches.
  static FloatingCondensation band(const FloatingBand& band, const std::vector<bool>& on_interface);
  // Any floating body, given its free DOFs (ascending).
  static FloatingCondensation nodal(const LinearSystem& system, const std::vector<int>& body_dofs,
                                    const std::vector<bool>& on_interface);

  int size() const { return static_cast<int>(S_.rows()); }
  const Eigen::MatrixXd& S() const { return S_; }                  // daN/mm
  const Eigen::VectorXd& f() const { return f_; }                  // daN
  const std::vector<int>& face_dofs() const { return face_dofs_; }  // free indices, ascending
  const Eigen::SparseMatrix<double>& T() const { return T_; }      // |face| × |x|
  // The selection spring's pattern P (|x| × |x|, symmetric positive semi-definite, entries 0 or 1):
  // a spring ρ holds the chosen face's translation through ρ P.
  Eigen::MatrixXd selection(LayerSelection face) const;
  // The body's free DOFs from x, written into u (free numbering).
  void displacement(const Eigen::VectorXd& x, Eigen::VectorXd& u) const;
  // A layer band's x is its whole column basis z (core/fem/column_basis.h).
  bool is_band() const { return is_band_; }
  // The interior factor's CHOLMOD reciprocal condition estimate (1 without interior).
  double rcond() const;

 private:
  FloatingCondensation() = default;
  // Condenses K (in the body's own basis z) onto the z indices `kept`, the rest interior.
  void condense(const Eigen::SparseMatrix<double>& K, const Eigen::VectorXd& F, const std::vector<int>& kept);

  Eigen::MatrixXd S_;
  Eigen::VectorXd f_;
  std::vector<int> face_dofs_;
  Eigen::SparseMatrix<double> T_;
  // Interior reconstruction: z_interior = K_ii⁻¹ (F_i − K_ix x).
  std::vector<int> kept_, interior_;
  std::shared_ptr<SparseCholesky> interior_factor_;
  Eigen::SparseMatrix<double> K_ix_;
  Eigen::VectorXd F_i_;
  // From z to the body's free DOFs: a band's layout and nodal free DOFs, or (nodal) z is the
  // body's free DOFs body_dofs_ themselves.
  bool is_band_ = false;
  BandLayout layout_;
  std::vector<int> body_dofs_;
};

}  // namespace thinlayer
