#pragma once
// The classical closed forms of adhesive joints, the check an engineer does by hand (issue 35):
//  - Volkersen's shear lag (1938): the glue a shear spring G/η between two bars in tension, no
//    bending; along an overlap of length l carrying a force P per unit width, from adherent 1
//    (membrane stiffness E1 t1, loaded at x = 0) into adherent 2 (E2 t2, loaded at x = l):
//      τ'' = ω² τ,  ω² = (G/η) (1/(E1 t1) + 1/(E2 t2)),  τ'(0) = −(G/η) P/(E1 t1),  τ'(l) = (G/η) P/(E2 t2),
//      τ(x) = A cosh ωx + B sinh ωx,  B = −(G/η) P/(E1 t1 ω),  A = (G/η) P (1/(E2 t2) + cosh ωl/(E1 t1)) / (ω sinh ωl),
//    whose integral over the overlap is P;
//  - Goland and Reissner (1944): the single lap of two identical adherents (thickness t, plane
//    strain modulus E' = E/(1−ν²)) with the bending its eccentric load causes, x from the overlap's
//    centre, c its half length (as in da Silva, das Neves, Adams & Spelt, Int. J. Adhes. Adhes. 29
//    (2009) 319, eqs. of Goland–Reissner):
//      u₂ = (1/t) √(3P/(2E't)),  k = cosh(u₂c) / (cosh(u₂c) + 2√2 sinh(u₂c))   (the bending moment factor),
//      β = √(8 G t/(E' η)),  τ(x) = P/(8c) [ (βc/t)(1+3k) cosh(βx/t)/sinh(βc/t) + 3(1−k) ],
//      k' = k (c/t) √(3P/(E't)),  λ = (c/t) (6 E_a t/(E' η))^¼,
//      σ(x) = P t/(Δ c²) [ (R₂ λ² k/2 + λ k' cosh λ cos λ) cosh(λx/c) cos(λx/c)
//                         + (R₁ λ² k/2 + λ k' sinh λ sin λ) sinh(λx/c) sin(λx/c) ],
//      R₁ = cosh λ sin λ + sinh λ cos λ,  R₂ = sinh λ cos λ − cosh λ sin λ,  Δ = ½ (sin 2λ + sinh 2λ);
//    its shear integrates to P as Volkersen's, and at a vanishing load (k = 1) it is Volkersen's for
//    an adherent whose surface strain is four times its mean (membrane plus the bending of the
//    eccentric shear: the 1 + 3k).
// Units: lengths mm, P force per mm of width, moduli in the stress unit; stresses in it.
#include <limits>

namespace thinlayer {

struct Volkersen {
  double l = 0, P = 0, E1t1 = 0, E2t2 = 0, G = 0, eta = 0;
  double omega() const;        // 1/mm
  double shear(double x) const;  // τ at x ∈ [0, l]
};

struct GolandReissner {
  double c = 0, P = 0, E = 0, t = 0, G = 0, Ea = 0, eta = 0;  // E: the adherents' E' (plane strain)
  // The bending factors to use: k (M₀ = k P t/2) and k' (V₀ = k' P t/c). Beside a linear model they
  // are the linear statics' of the joint's own supports (studies/tools/lap_beam.h), given here; NaN:
  // GR's own, geometrically nonlinear in P, for symmetric pinned ends.
  double k_given = std::numeric_limits<double>::quiet_NaN(), k_prime_given = std::numeric_limits<double>::quiet_NaN();
  double k_nonlinear() const;  // GR's: cosh(u₂c) / (cosh(u₂c) + 2√2 sinh(u₂c)), falls as P grows
  double k() const;            // the bending moment factor used (1: no bending)
  double k_prime() const;      // the transverse shear factor used
  double beta() const;
  double lambda() const;
  double shear(double x) const;  // τ at x ∈ [−c, c]
  double peel(double x) const;   // σ at x ∈ [−c, c]; NaN where cosh λ overflows (λ > 300)
};

}  // namespace thinlayer
