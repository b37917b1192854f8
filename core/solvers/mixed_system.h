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
    Eigen::VectorXd y;                  // the system's own unknowns (y above)
    bool singular = false;              // the statuses leave a body free (factorisation failed)
    double rcond = 0;                   // the LU's reciprocal condition estimate
    // With prove_round_off(true): refined in extended precision until a correction was below
    // double's rounding (SparseLU::solve) — the premise of a round-off floor. False otherwise.
    bool at_round_off = false;
  };
  // One sparse LU with these statuses (one per node of the problem, as the active-set methods
  // name them).
  Answer solve(const std::vector<Active>& statuses);

  // Refine every solve on until its answer is the exact one to double's rounding, and say so
  // (Answer::at_round_off): the proof a linear solve's round-off floor needs (core/solvers/
  // stop_verdict.h), a few more substitutions where the condition is high. Off by default.
  void prove_round_off(bool on) { prove_round_off_ = on; }

  // What the last solve()'s system nearly leaves free (SparseLU::near_null): a lower bound of its
  // condition number and that motion, as displacements of the free DOFs and interface forces.
  struct NearNull {
    double condition = 0;
    Eigen::VectorXd u, r;
  };
  NearNull near_null() const;

  // The unknowns y of the system: each free DOF outside a layer band nodally, then each band in
  // its column basis. The index in y of band b's column-i translation, component c (0: x, 1: y).
  int band_translation(int band, int column, int component) const;
  int num_bands() const { return static_cast<int>(bands_.size()); }
  int band_offset(int band) const { return bands_.at(band).first; }
  // The jumps' rows in y (2m × ny): jumps = B_y y + g_D.
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& B_y() const { return B_y_; }
  // A proximal spring on chosen unknowns of y: ρ_j (daN/mm) added to K's diagonal at y_j, pulling it
  // towards anchor_j (mm). It selects one answer where the problem leaves a film's position free
  // (SPEC §1.5, "Non-unique layers"); clear_springs() returns to the true problem.
  void set_springs(const std::vector<int>& y_index, const Eigen::VectorXd& rho, const Eigen::VectorXd& anchor);
  void clear_springs();
  // Each interface row's stiffness as its unknowns see it with everything else held (daN/mm):
  // 1 / (Σ_j b_ij² / A_jj + C_i) over the row's coefficients b_i in y, springs included — the
  // Jacobi estimate of 1 / W̃_ii, the row's diagonal of the layer's dual operator, without forming
  // it. A film's translation held only by its membrane and a spring ρ gives κ_i ≈ ρ: its statuses
  // follow its forces, not its jumps.
  Eigen::VectorXd row_stiffness() const;
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
  Eigen::SparseMatrix<double, Eigen::RowMajor> B_y_;  // the jump rows in y: 2m × ny
  std::vector<StatusEntry> status_entries_;
  struct Spring {
    int position;   // index into A's values (a diagonal entry of the K block)
    int y;
    double base;    // K's own value there
    double rho, anchor;
  };
  std::vector<Spring> springs_;
  std::vector<BandLayout> layouts_;
  SparseLU lu_;
  std::vector<std::pair<bool, bool>> jump_rows_;  // of the last solve(): which rows are equations d = ...
  bool factored_ = false;
  bool prove_round_off_ = false;
  bool singular_ = false;
};

}  // namespace thinlayer
