#pragma once
// The assembled linear elastic system of a model with its Dirichlet DOFs eliminated:
//   K u = F  on the free DOFs,  with F = F_ext - K_fd u_d.
#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/fem/column_basis.h"
#include "core/fem/model.h"

namespace thinlayer {

using SparseMatrix = Eigen::SparseMatrix<double>;

// A floating body whose mesh is a layer band: its stiffness and loads in the column basis
// (core/fem/column_basis.h), which the solvers condense instead of the nodal stiffness.
struct FloatingBand {
  int body = 0;
  BandLayout layout;
  SparseMatrix K;              // column basis, daN/mm
  Eigen::VectorXd F;           // column basis, daN
  std::vector<int> free_dof;   // the free index of the body's nodal DOF 2·node + c
};

class LinearSystem {
 public:
  explicit LinearSystem(const Model& model);

  const SparseMatrix& K() const { return K_ff_; }  // free × free, daN/mm
  const Eigen::VectorXd& F() const { return F_f_; }  // daN

  int num_dofs() const { return static_cast<int>(free_index_.size()); }
  int num_free() const { return static_cast<int>(K_ff_.rows()); }
  // Free index of a global DOF, or -1 when the DOF is prescribed.
  int free_index(int global_dof) const { return free_index_[global_dof]; }
  double prescribed_value(int global_dof) const { return prescribed_[global_dof]; }
  // Whether a free DOF belongs to a floating body (Body::floating).
  bool floating(int free_dof) const { return floating_free_[free_dof]; }
  // The body (index into Model::bodies) that owns a free DOF, and the bodies' names: the
  // residual is judged body by body (SPEC §1.5).
  int body_of(int free_dof) const { return body_free_[free_dof]; }
  int num_bodies() const { return static_cast<int>(body_names_.size()); }
  const std::string& body_name(int body) const { return body_names_[body]; }

  // Full nodal displacement vector from the free unknowns (prescribed values filled in).
  Eigen::VectorXd expand(const Eigen::VectorXd& u_free) const;
  // A free-DOF vector (e.g. forces) in the full numbering, zero at the prescribed DOFs.
  Eigen::VectorXd scatter(const Eigen::VectorXd& free_values) const;
  // Resultant force [R_x, R_y] (daN per unit thickness) that each Dirichlet condition exerts
  // on the body, given the full displacement and the external nodal forces the interfaces add.
  std::map<std::string, Eigen::Vector2d> reactions(const Eigen::VectorXd& u_full,
                                                   const Eigen::VectorXd& interface_force_full) const;
  const Eigen::VectorXd& external_force() const { return F_ext_; }  // full, daN
  // The floating bodies that are layer bands (every other floating body is condensed nodally).
  const std::vector<FloatingBand>& floating_bands() const { return floating_bands_; }

 private:
  SparseMatrix K_full_;
  Eigen::VectorXd F_ext_;
  std::vector<int> free_index_;
  std::vector<double> prescribed_;
  std::vector<std::string> owner_;  // name of the condition prescribing each DOF ("" if free)
  std::vector<bool> floating_free_;
  std::vector<int> body_free_;
  std::vector<std::string> body_names_;
  SparseMatrix K_ff_;
  Eigen::VectorXd F_f_;
  std::vector<FloatingBand> floating_bands_;
};

// Building blocks, exposed for the tests.
SparseMatrix assemble_stiffness(const Model& model);
Eigen::VectorXd assemble_tractions(const Model& model);  // the tractions and the nodal forces

}  // namespace thinlayer
