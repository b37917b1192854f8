#pragma once
// What a layer of thickness t adds to its limit law at first order (SPEC §3 S6): the load that,
// applied to the limit-mode solution u₀ and solved once on the limit mode's own factorisation
// (MixedSystem::solve_again), turns it into the first-order answer of the layer model,
// u₁ = u₀ + δu. The derivation, and why it should hold, is studies/limit_error_estimate.md; in short:
//
// Between its faces u⁻ (minus adherent) and u⁺ (plus adherent) a thin layer's displacement is, to
// first order, linear through its thickness. With j = u⁺ − u⁻, m = (u⁺ + u⁻)/2, (s, n) the bondline's
// tangent and normal (minus → plus), its energy per unit length of bondline is then, exactly,
//   W = (K_N/2)(j_n + t ν* ∂_s m_s)² + (K_T/2)(j_s + t ∂_s m_n)² + (t/2) E* (∂_s m_s)²  (+ O(t³))
// with K_N = (λ+2μ)/t, K_T = μ/t, ν* = λ/(λ+2μ), E* = 4μ(λ+μ)/(λ+2μ) (plane strain; plane stress
// with λ* = 2λμ/(λ+2μ)): the spring law acting on the jump less the layer's own Poisson thinning
// and rotation, and the membrane of the layer with its normal stress free. The limit law keeps
// (K/2) j². Expanding the squares, the rest is the coupling λ j_n ∂_s m_s + μ j_s ∂_s m_n (O(1) on
// the jumps, whose stiffness is O(1/t)) and terms O(t); at the first-order answer the square's
// bracket is −σ/K, so the force the squares put on m is −t ∂_sᵀ σ ≈ what the coupling gives at u₀:
// the load is the coupling's gradient at u₀ and the membrane E*, nothing of the squares' t² K part
// (it cancels against the coupling's response — a naive expansion counting (t/2)(λ+2μ)(∂_s m_s)²
// stiffens the membrane by λ²t/(λ+2μ): the bilayer in in-plane tension, tests). Applied:
//   - segment by segment along each bondline (∂_s m constant on a segment, j at its mean), where the
//     limit answer holds both faces (a node's status: the normal coupling where it is not open, the
//     tangential one and the membrane where it sticks or is bonded);
//   - at each free end of a bondline, the end cell's deficits (core/solvers/layer_end_cell.h);
//   - the spring's own misfit where the law's stiffness is not the layer's (the paper's family off
//     γ, δ = 1; a law classified to 0 or ∞): a finite misfit ΔK as a force −ΔK ℓ j, a rigid law
//     (K = ∞, no jump) as the compliance 1/(K_layer ℓ) it leaves out, a law carrying no force
//     (K = 0) as the force K_layer ℓ j₀ the layer would carry.
// Units: mm, the scene's force and stress units (daN, daN/mm², or N, MPa).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/fem/material.h"
#include "core/solvers/active_set.h"
#include "core/solvers/contact_problem.h"

namespace thinlayer {

// The layer that stands behind one interface's law: thickness t (mm; 0: none, the law is a law only)
// and its moduli at t.
struct LayerAtThickness {
  double thickness = 0;            // mm
  double lambda = 0, mu = 0;       // stress unit: the layer's λ_t, μ_t (3D)
  PlaneHypothesis plane = PlaneHypothesis::Strain;
  // The end deficits (core/solvers/layer_end_cell.h): near a free end of the layer its traction falls
  // short of the spring's by the force α_N t σ_N (normal) and α_T t σ_T (shear).
  double end_deficit_N = 0, end_deficit_T = 0;
  // The bondline's end nodes are the layer's free ends (a scene file's always are: its supports never
  // touch a bondline). False: the layer goes on into a support there (the closed-form tests' bilayers,
  // held on their sides): no end deficit, and the support takes the segments' force at the end node.
  bool free_ends = true;
  // λ seen in the plane: λ in plane strain, 2λμ/(λ+2μ) in plane stress (σ33 = 0).
  double plane_lambda() const;
  double K_N() const { return (lambda + 2 * mu) / thickness; }  // the spring of a bonded layer at t
  double K_T() const { return mu / thickness; }
};

// The first-order load on a limit answer.
struct FirstOrderLoad {
  Eigen::VectorXd body_forces;  // full DOF numbering (LinearSystem), force unit: on the adherents
  Eigen::VectorXd row_values;   // per interface row (2 per node): the jump equation's right-hand side
  // Per node of the problem (all interfaces in order): the parts of body_forces acting on its plus and
  // its minus side (force unit, x and y): with the spring's force they make the layer's traction on
  // each face. The two differ by what the layer carries along S (the membrane, the squares' m-force:
  // ∂W/∂m acts half on each face, with the same sign), so the faces' tractions differ at first order,
  // as the meshed layer's S+ and S- do.
  std::vector<Eigen::Vector2d> plus_force, minus_force;
};

// layers: one per interface of `problem`, in order. u_full: the limit answer's full nodal
// displacement (LinearSystem::expand); r: its interface forces; statuses: its statuses
// (answer_statuses). Throws std::invalid_argument on mismatched sizes or a layer with t > 0 and
// μ ≤ 0.
FirstOrderLoad first_order_layer_load(const ContactProblem& problem, const std::vector<LayerAtThickness>& layers,
                                      const Eigen::VectorXd& u_full, const Eigen::VectorXd& r,
                                      const std::vector<Active>& statuses);

}  // namespace thinlayer
