#pragma once
// One rule for "converged", everywhere (SPEC §1.5): `solve`, every study, the validity map and
// `verify` take a solve's verdict from this one function, a function of the problem, the answer,
// its SPEC residual and the condition of the linear system the answer solves — never of a solver's
// iteration — so that any solver (the layer solver being replaced included) calls it the same way.
//
//   - converged: the residual (evaluated in extended precision, contact_residual) meets the
//     tolerance, and the system is not singular;
//   - singular: a linear system whose condition is beyond 1/(1e3 u_eps') ≈ 4.5e12 (u_eps' = 2⁻⁵²,
//     machine epsilon: at that condition a solve keeps fewer than three of double's sixteen digits
//     with certainty), whose residual after refinement stays above 1e-6 (no answer of it exists to
//     a millionth), or whose factorisation failed — named with the body that its near-null motion
//     moves and the laws that leave that body free; never a round-off floor, and its numbers are
//     never reported as distances or costs;
//   - round-off floor: only with its proof — the answer is its linear system's exact solution
//     rounded to double (refined in extended precision until a correction changed no digit,
//     SparseLU::solve) and its residual, evaluated in extended precision, is above the tolerance and
//     within what rounding the answer to double moves it by (Residual::floor()): no answer stored in
//     double does better. Its numbers may be used, flagged; the solve is not converged (exit 1);
//   - otherwise the solver's own cause (an iteration cap, a drifting layer), or loss of accuracy
//     where the linear solve stopped short of its floor.
#include <cfloat>
#include <string>

#include <Eigen/Core>

#include "core/solvers/contact_problem.h"
#include "core/solvers/solve_report.h"

namespace thinlayer {

// Beyond this condition number a linear system is called near-singular: 1 / (1e3 · machine ε).
constexpr double singular_condition = 1.0 / (1e3 * DBL_EPSILON);
// A linear system whose refined answer leaves a residual above this has no answer to speak of.
constexpr double singular_residual = 1e-6;

// What the solver knows of the linear system its answer solves, where it solves one.
struct LinearEvidence {
  // The answer is the solution of one linear system: every face bonded, or the statuses settled.
  bool linear = false;
  bool factor_failed = false;   // that system's factorisation found it singular to working precision
  bool at_round_off = false;    // refined in extended precision until a correction changed no digit
  // A lower bound of that system's condition number where `linear` (SparseLU::near_null), else the
  // solver's estimate; 0 where not known.
  double condition = 0;
  // The motion that system nearly leaves free, as displacements of the free DOFs (empty: not known).
  Eigen::VectorXd free_motion;
};

struct StopVerdict {
  StopCause cause = StopCause::LossOfAccuracy;
  bool converged = false;
  bool usable = false;   // its numbers may be reported as distances and costs: converged, or a proven floor
  std::string why;       // the cause in words, with its proof (floor) or its name (singular); "" if converged
};

// `iteration_cause`: what the solver's own iteration says where its answer is not one linear system
// (IterationCap, LayerAdrift, ...); ignored where it is.
StopVerdict stop_verdict(const ContactProblem& problem, const Eigen::VectorXd& u, const Eigen::VectorXd& r,
                         const Residual& residual, double tolerance, const LinearEvidence& evidence,
                         StopCause iteration_cause = StopCause::LossOfAccuracy);

// May a study report this solve's numbers (distances, costs)? Converged, or stopped at a proven
// round-off floor; never a singular system, a stall or a cap.
bool usable(const SolveReport& report);

// What leaves a problem's system free, in words: the body a near-null motion moves (its share of the
// motion) and the laws of its interfaces with no stiffness in a direction; from the problem alone
// (the laws with a zero stiffness, the bodies with no support) where no motion is known.
std::string free_part(const ContactProblem& problem, const Eigen::VectorXd& free_motion);

}  // namespace thinlayer
