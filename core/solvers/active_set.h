#pragma once
// The limit-mode machinery of the fast solver (SPEC §1.5): a primal-dual active-set /
// semismooth Newton method on the condensed interface problem
//   d = g₀ + (W + C) r + B_L w,    S w = f_L + B_Lᵀ r   (B_L, S, w: floating bodies only),
// with Signorini-Coulomb on (r, d) at every node. Once the statuses are right, one linear
// solve (solve_statuses) gives the exact answer. The floating-layer solver
// (floating_layer.h) drives the same pieces on the layer's dual operator.
#include <vector>

#include <Eigen/Core>

#include "core/solvers/condensed_interface.h"

namespace thinlayer {

// The status a node's rows are solved for in one active-set step. Bonded: a bilateral law's
// node (SPEC §1.6), d = 0 on each row that carries a force, for either sign of r; it never changes.
enum class Active : int { Gap, Stick, SlidePositive, SlideNegative, Frictionless, Bonded };

struct Condensed {
  Eigen::MatrixXd W;        // W + C
  Eigen::VectorXd g0;
  Eigen::MatrixXd B_L, S;   // floating bodies: d also has B_L w, and S w = f_L + B_Lᵀ r
  Eigen::VectorXd f_L;
  Eigen::VectorXd kappa;    // the local stiffness of each row, as in the SPEC residual
  std::vector<bool> normal, tangential;  // does the row carry a force at all
  std::vector<double> friction;
  std::vector<bool> bilateral;            // a bonded node: no stop, no skidding block
};

// The law's flags of every row (W and the floating part empty) with the complementarity
// parameters κ: all that guess_statuses reads.
Condensed law_rules(const ContactProblem& problem, const Eigen::VectorXd& kappa, bool skip_frictionless_rows = true);

// The condensed problem of a scene, with the complementarity parameter κ of each row scaled
// by complementarity_scale (SolverOptions), and the rows that carry no force marked.
Condensed condense(const ContactProblem& problem, const CondensedInterface& ci, double complementarity_scale,
                   bool skip_frictionless_rows);

// The active-set guess from the current iterate: the sign pattern of the natural map.
std::vector<Active> guess_statuses(const Condensed& c, const Eigen::VectorXd& r, const Eigen::VectorXd& d);

int floating_unknowns(const Condensed& c);

// Does every contact of the floating bodies stand open? Then nothing holds them and their
// rigid position is undetermined: the system is singular, whatever the residual says.
bool floating_bodies_free(const Condensed& c, const std::vector<Active>& statuses);

// d = g₀ + (W + C) r + B_L w.
Eigen::VectorXd jump_part(const Condensed& c, const Eigen::VectorXd& r, const Eigen::VectorXd& w);

// One Newton step: the linear system that the guessed statuses make of the law, for the
// interface forces r and, after them, the floating bodies' interface DOFs w.
struct Step {
  Eigen::VectorXd r, w;
  bool singular = false;  // rank deficient (a floating body left undetermined): minimum-norm solution taken
  double rcond = 1;       // reciprocal condition estimate of the equilibrated system
};

Step solve_statuses(const Condensed& c, const std::vector<Active>& s);

// Relative norm of the natural map on the condensed problem (the map of contact_residual).
double condensed_residual(const Condensed& c, const ContactProblem& problem, const Eigen::VectorXd& r,
                          const Eigen::VectorXd& d);

// Projected (nonsmooth) Gauss-Seidel sweeps over the nodes, each node's law solved exactly
// with the others frozen (supported bodies only: w is not updated).
void nsgs_sweeps(const Condensed& c, Eigen::VectorXd& r, int sweeps);

struct ActiveSetRun {
  int iterations = 0, nsgs_sweeps = 0;
  bool settled = false;   // the statuses reproduced themselves
  bool singular = false;  // the last step's system was rank deficient (a floating body left free)
  double rcond = 1;       // of the last step's system
};

// Semismooth Newton / primal-dual active set from the given statuses and iterate.
ActiveSetRun active_set(const Condensed& c, const ContactProblem& problem, std::vector<Active>& statuses,
                        Eigen::VectorXd& r, Eigen::VectorXd& w, int max_iterations);

}  // namespace thinlayer
