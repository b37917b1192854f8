#pragma once
// The paper's algorithm (§4.1), the baseline every other solver is measured against:
// projected Gauss-Seidel over all unknowns with over-relaxation ω, the interface terms
// entering through the γ (normal spring on/off), η (tangential spring on/off) and θ (slider
// force ±ρ) switches, nested in the fixed point ρ ← f |σ_N(u(ρ))| on the friction threshold.
//
// Interface unknowns are taken in the local frame (I_N, I_T of the paper): the tangential and
// normal components of the plus node, relative to the minus node for a two-body interface,
// so that each interface term depends on exactly one unknown.
//
// The tangential potential printed in §4, ½K_T v² + ρ(|v| - ρ/K_T)⁺, matches neither the
// switches printed below it nor the law of eq. 43. We implement the law: a spring in series
// with a slider, ψ(v) = ½K_T v² for |v| ≤ ρ/K_T and ρ|v| - ρ²/(2K_T) beyond, whose
// coordinate minimisation is exactly the η/θ switches.
#include "core/solvers/solve_report.h"

namespace thinlayer {

SolveReport solve_relaxation(const ContactProblem& problem, const SolverOptions& options = {});

}  // namespace thinlayer
