#pragma once
// The whole contact problem as one sparse linear system for given statuses (SPEC §1.4-1.5): the
// bodies' equilibrium and one row per interface unknown,
//   [ K    −Bᵀ ] [y]   [F]
//   [ S_B  S_r ] [r] = [s],
// where a status row is d = B y + g_D + C r = 0 on a row in contact (stick, bonded, the normal row
// of a slide), r_T = ∓f r_N on a slide's tangential row, r = 0 where the node is open or its law
// carries no force. y are the free DOFs, each layer band in its column basis z
// (core/fem/column_basis.h), so that a film's in-plane stiffness keeps its own digits.
// Nothing is condensed and no spring holds a floating layer: the answer of known statuses is exact
// to the solve's round-off, whatever the layer does (SparseLU: equilibrated, refined in extended
// precision). The pattern is built once; each solve fills the status rows' values and factors.
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/linalg/sparse_lu.h"
#include "core/solvers/active_set.h"
#include "core/solvers/contact_problem.h"

namespace thinlayer {

class MixedSystem {
 public:
  explicit MixedSystem(const ContactProblem& problem);
  const ContactProblem& problem() const { return problem_; }

  struct Answer {
    Eigen::VectorXd u;                  // free DOFs, mm
    Eigen::VectorXd r;                  // interface forces (r_N, r_T) per node, daN
    std::vector<Eigen::VectorXd> band_z;  // each layer band in its column basis
    bool singular = false;              // the statuses leave a body free (factorisation failed)
    double rcond = 0;                   // the LU's reciprocal condition estimate
  };
  // One sparse LU with these statuses (one per node of the problem, as the active-set methods
  // name them).
  Answer solve(const std::vector<Active>& statuses);

  // The same statuses' system with another right-hand side, on the factorisation of the last
  // solve() (one forward and back substitution, refined): body_forces (free DOFs, daN) on the
  // equilibrium rows, row_values on each interface row that solve() made a jump equation (d = ...,
  // mm; the force rows stay r = 0 and r_T = ∓f r_N). Nothing of the scene's own loads or imposed
  // jumps: the answer is the response to this load alone (core/solvers/first_order_layer.h's
  // correction, SPEC §3 S6). Throws std::logic_error before any solve().
  Answer solve_again(const Eigen::VectorXd& body_forces, const Eigen::VectorXd& row_values) const;

 private:
  // One entry of a status row: where its value lives in A, and what it is.
  enum class Role { JumpCoefficient, Diagonal, SlideCoupling };
  struct StatusEntry {
    int position;   // index into A's values
    int row;        // interface row 2k or 2k+1
    Role role;
    double b = 0;   // B's coefficient (JumpCoefficient)
  };
  void fill(const std::vector<Active>& statuses, Eigen::VectorXd& rhs);

  const ContactProblem& problem_;
  Eigen::SparseMatrix<double> P_;  // u_free = P y
  std::vector<std::pair<int, int>> bands_;  // each band's offset and size in y
  int ny_ = 0;
  Eigen::VectorXd F_y_;
  Eigen::SparseMatrix<double> A_;
  std::vector<StatusEntry> status_entries_;
  SparseLU lu_;
  std::vector<std::pair<bool, bool>> jump_rows_;  // of the last solve(): which rows are equations d = ...
  bool factored_ = false;
  bool singular_ = false;
};

}  // namespace thinlayer
