#pragma once
// The limit interface laws of Table 1 (paper §3.1.8, eq. 32-56), as one small value type.
//
// A law is (λ̄, μ̄, f). λ̄ and μ̄ are stiffnesses per unit area in daN/mm³ (stress per length,
// like λ_ε/ε) and may be exactly 0 or exactly +∞ (IEEE infinity, never a large stand-in).
// With K_N = λ̄ + 2μ̄ and K_T = μ̄ every one of the nine cases reads the same way:
//   normal:      a spring K_N in series with a stop      (K_N = ∞: Signorini; K_N = 0: σ_N = 0)
//   tangential:  a spring K_T in series with a Coulomb skidding block of threshold f|σ_N|
//                (K_T = ∞: Coulomb; K_T = 0: σ_T = 0)
// Case (b) has K_N = 2μ̄ because λ̄ = 0 there, as eq. 43 says.
//
// A bilateral law (SPEC §1.6, bonded faces; beyond the paper) has no stop and no skidding block:
//   σ_N = −K_N [u]_N and σ_T = −K_T [u]_T for either sign of [u]_N (tension carried), no friction.
// An infinite component allows no jump (K = ∞ ties the two sides: a bonded face of the meshed
// layer), a zero one carries no stress. Both faces of a layer bonded give this law in the limit
// (the bilateral spring interface of Klarbring 1991 and Geymonat–Krasucki–Lenci 1999).
//
// Sign convention (SPEC §1.2): [u]_N > 0 is interpenetration, σ_N ≤ 0 is compression.
#include <string>

namespace thinlayer {

enum class Limit { Zero, Finite, Infinite };

Limit limit_of(double value);
const char* to_string(Limit l);

struct InterfaceLaw {
  double lambda_bar = 0;  // daN/mm³, in [0, +∞]
  double mu_bar = 0;      // daN/mm³, in [0, +∞]
  double friction = 0;    // f ≥ 0 (0 for a bilateral law)
  // No unilateral condition and no friction: d = g + C r = 0 on both rows, for either sign of r.
  bool bilateral = false;

  // Validates (no NaN, no negative value, f finite) and throws std::invalid_argument with a
  // one-line message otherwise.
  static InterfaceLaw make(double lambda_bar, double mu_bar, double friction);
  // The bilateral spring law σ = −K [u] (K_N = λ̄ + 2μ̄, K_T = μ̄), validated as make().
  static InterfaceLaw make_bilateral(double lambda_bar, double mu_bar);
  // Both sides tied (K_N = K_T = ∞, bilateral): a bonded face.
  static InterfaceLaw tie();

  double K_N() const { return lambda_bar + 2 * mu_bar; }
  double K_T() const { return mu_bar; }
  // Compliances 1/K: exactly 0 for a rigid law, +∞ for a free one.
  double compliance_N() const { return 1.0 / K_N(); }
  double compliance_T() const { return 1.0 / K_T(); }
  bool normal_active() const { return K_N() > 0; }      // there is a normal interaction
  bool tangential_active() const { return K_T() > 0 && friction > 0; }  // Coulomb (never bilateral)

  // Table 1 case letter 'a'..'i' from the limits of λ̄ and μ̄ (of a bilateral law too: the
  // class of its stiffnesses).
  char table1_case() const;
  // For messages: "Table 1 case (d)", or "bilateral spring, Table 1 class (d)".
  std::string describe() const;
};

// Local response of a law with finite K_N, K_T to a prescribed jump (eq. 43-45; a bilateral law:
// σ = −K [u]): the unique (σ_N, σ_T) when the law is a function of the jump. For K = ∞ the stress is set-valued; use
// the natural-map residual (core/solvers/contact_problem.h) to test such states instead.
struct LocalStress {
  double sigma_N = 0;  // daN/mm²
  double sigma_T = 0;  // daN/mm²
};
LocalStress local_stress(const InterfaceLaw& law, double jump_N, double jump_T);

}  // namespace thinlayer
