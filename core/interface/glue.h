#pragma once
// The glue of a bondline: the layer's moduli at a thickness ε, how each face of the layer holds
// its adherent, and the limit law that stands for the layer (SPEC §1.1-§1.3, §1.6, §5). One small
// piece used alike by the layer mode (the moduli it meshes), the limit mode (the law) and the
// studies (which vary ε), so that both modes always describe the same glue.
//
// Two families of glue:
//  - the paper's scaled family (paper §3.2): λ_ε = ε^γ λ_g, μ_ε = ε^δ μ_g. With γ = 1, λ_g is a
//    modulus per unit thickness (daN/mm³): the glue softens as it thins. Its limit law is
//    Table 1's, λ̄ = lim λ_ε/ε and μ̄ = lim μ_ε/ε, whatever ε;
//  - an engineer's glue: fixed E_g, ν_g (λ_g, μ_g by the 3D relations), at a nominal thickness t.
//    A thinner line of it is the same glue thinner. Its limit law is the finite spring law of
//    that line at its own thickness (SPEC §1.3): λ̄ = λ_g/ε, μ̄ = μ_g/ε, so K_N = (λ_g + 2μ_g)/ε and
//    K_T = μ_g/ε — Table 1's case (d), never a 0 or ∞ cut-off. Why: the cut-offs belong to the
//    paper's family, whose moduli go to 0 or ∞ with ε; a real glue's do not, and cutting μ̄ to 0
//    (a 0.5 mm epoxy line between 1 mm steel sheets: μ_g/t is 2.8 % of μ_m/L) leaves a lap joint
//    with no shear path at all. The law stiffens as the line thins. What the paper's 3 % / 30×
//    rule would choose instead is classified_law(), printed beside it, never solved for it.
//
// Faces (SPEC §1.6): each face of the layer is in contact with its adherent (Signorini-Coulomb,
// the paper's) or bonded to it (tied). The limit law of each combination (derived in docs/joints.md,
// "Bonded faces"): both faces bonded, the bilateral spring law σ = −K [u]; otherwise Table 1's law,
// the contact living on one face or two (two skidding blocks in series slide as one).
// Units: moduli in the scene's stress unit (daN/mm², or MPa), λ̄, μ̄ in that unit per mm.
#include "core/interface/classifier.h"
#include "core/interface/law.h"

namespace thinlayer {

struct LameModuli {
  double lambda = 0, mu = 0;  // daN/mm² (or MPa)
};

// λ = E ν / ((1 + ν)(1 − 2ν)), μ = E / (2 (1 + ν)): the 3D relations (a plane-strain body keeps
// its 3D moduli; plane stress is applied by Material). Throws std::invalid_argument unless
// E > 0 and −1 < ν < 0.5.
LameModuli lame_from_young(double E, double nu);

enum class FaceHold { Contact, Bonded };
const char* to_string(FaceHold face);

struct LayerFaces {
  FaceHold plus = FaceHold::Contact, minus = FaceHold::Contact;
  bool both_bonded() const { return plus == FaceHold::Bonded && minus == FaceHold::Bonded; }
  bool any_bonded() const { return plus == FaceHold::Bonded || minus == FaceHold::Bonded; }
};

// The law of one face of the meshed layer: bonded, tied (K = ∞, bilateral); in contact,
// Signorini-Coulomb with f.
InterfaceLaw face_law(FaceHold face, double friction);

// The limit law of a layer whose own stiffnesses are (λ̄, μ̄), given how its faces hold:
// bilateral when both are bonded, else Table 1's with f.
InterfaceLaw layer_limit_law(double lambda_bar, double mu_bar, const LayerFaces& faces, double friction);

class Glue {
 public:
  // The paper's family: γ ≥ 0, 0 ≤ δ < 2, λ_g ≥ 0, μ_g > 0.
  static Glue scaled(double gamma, double delta, double lambda_g, double mu_g);
  // An engineer's glue: E > 0, −1 < ν < 0.5, thickness t > 0 (mm).
  static Glue engineer(double E, double nu, double thickness);

  bool is_engineer() const { return engineer_; }
  // The layer's moduli at thickness eps (mm).
  LameModuli at(double eps) const;
  // The limit law standing for the layer of thickness eps: Table 1's for the scaled family
  // (eps unused), the finite law λ̄ = λ_g/eps, μ̄ = μ_g/eps for an engineer's glue (SPEC §1.3;
  // `reference` unused then: it is kept so both families answer the same call).
  InterfaceLaw limit_law(double eps, const AdherentData& reference, const LayerFaces& faces, double friction) const;
  // What the paper's §3.3 rule would choose at thickness eps: λ_g/eps and μ_g/eps against the
  // adherents' λ_m/L and μ_m/L (`reference`), 0 below 3 %, ∞ above 30 times, the ratio in
  // between. For the scaled family it is limit_law itself (its Table 1 class).
  InterfaceLaw classified_law(double eps, const AdherentData& reference, const LayerFaces& faces, double friction) const;
  // An engineer's glue: its nominal thickness t (mm); the scaled family has none (0).
  double nominal_thickness() const { return engineer_ ? thickness_ : 0.0; }
  // The exponents of λ_ε and μ_ε in ε: (γ, δ), or (0, 0) for fixed moduli (they choose the
  // layer's quadrature, cases/layer_quadrature.h, and the predicted rate).
  double gamma() const { return gamma_; }
  double delta() const { return delta_; }
  // The moduli at ε = 1 (scaled family: λ_g, μ_g), or the engineer's fixed ones.
  LameModuli reference_moduli() const { return {lambda_g_, mu_g_}; }
  double young() const { return E_; }   // an engineer's glue only (0 otherwise)
  double poisson() const { return nu_; }

 private:
  bool engineer_ = false;
  double gamma_ = 1, delta_ = 1, lambda_g_ = 0, mu_g_ = 0;
  double E_ = 0, nu_ = 0, thickness_ = 0;
};

}  // namespace thinlayer
