#pragma once
// The dovetail assembly (paper §3.2, Table 2; SPEC §2.2), both modes. Length unit L = 1,
// stresses in daN/mm².
//
// Base clamped on y = -1; the tenon's top edge y = 0.5 pulled out at 45° by the imposed
// displacement (U_x, U_y) = (1e-3, 1e-3). Friction f = 0.5 on every contact face (the default;
// a sensitivity study may change it). The glue's reference moduli are the adherents':
// λ_g = λ_m, μ_g = μ_m; the layer of thickness ε has λ_ε = ε^γ λ_g and μ_ε = ε^δ μ_g
// (γ ≥ 0, 0 ≤ δ < 2).
#include <vector>

#include "cases/dovetail/dovetail_mesh.h"
#include "cases/layer_quadrature.h"
#include "core/fem/model.h"
#include "core/interface/interface.h"

namespace thinlayer::dovetail {

constexpr double lambda_m = 4500.0;  // daN/mm², adherents
constexpr double mu_m = 5400.0;      // daN/mm²
constexpr double lambda_g = lambda_m;
constexpr double mu_g = mu_m;
constexpr double friction = 0.5;
constexpr double pull_x = 1e-3, pull_y = 1e-3;  // imposed on the tenon's top edge

// The exponents of one case; validated (γ ≥ 0, 0 ≤ δ < 2, finite).
struct Exponents {
  double gamma = 1, delta = 1;
};
Exponents validated(Exponents e);
// γ, δ of a Table 2 case letter (read from reference/table2.csv); throws on an unknown letter.
Exponents exponents_of(char law_case);

// The limit law: λ̄ = lim ε^(γ-1) λ_g (∞ if γ < 1, λ_g if γ = 1, 0 if γ > 1), likewise μ̄.
// f: the Coulomb coefficient (validated by InterfaceLaw::make: finite, >= 0).
InterfaceLaw limit_law(const Exponents& e, double f = friction);

// Limit mode: body 0 base, body 1 tenon; Dirichlet "base_bottom" and "tenon_top".
Model make_limit_model(const LimitMeshes& meshes);
// The interface "S": plus = tenon, minus = base, normals pointing into the slot.
Interface make_limit_interface(const Model& model, const InterfaceLaw& law);

// Thin-layer mode: body 0 base, body 1 the floating layer (λ_ε, μ_ε), body 2 tenon. The
// layer's quadrature follows cases/layer_quadrature.h unless `quadrature` says otherwise.
Model make_layer_model(const LayerMeshes& meshes, const Exponents& e,
                       LayerQuadrature quadrature = LayerQuadrature::ByExponents);
// "S+" (plus = tenon, minus = layer) and "S-" (plus = layer, minus = base), Signorini-Coulomb
// with coefficient f on both; node k of either is node k of the limit mode's S.
std::vector<Interface> make_layer_interfaces(const Model& model, double f = friction);

}  // namespace thinlayer::dovetail
