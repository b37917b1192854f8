#pragma once
// Which quadrature a thin layer's Q1 elements use for the λ part of their stiffness
// (studies/convergence_rates.md, "The layer's quadrature").
//
// Selective integration (the λ part at the cell centre) keeps a nearly incompressible body
// from locking, but in a thin layer the λ part is the layer's through-thickness stiffness
// (λ_ε + 2μ_ε)/ε, and the one-point rule sees only the mean of each cell's two columns: a
// zigzag of the columns' compressions, Δ_i = (−1)^i a, costs nothing of it. What holds that
// zigzag is the μ part, 2μ_ε/(3ε), and the adherents' stiffness against a zigzag of the
// interface, k_a ≈ π E*/(4h) (both bodies in series; E* the adherents' plane-strain modulus).
// A slowly modulated zigzag decays from where it is excited (a corner, a contact edge) over
//     ℓ_z / h = ½ √( (λ_ε/ε) / (k_a + 2μ_ε/(3ε)) )     nodes,
// which stays bounded as ε → 0 unless λ_ε/ε → ∞ faster than μ_ε/ε: γ < 1 and γ < δ (Table 1:
// λ̄ = ∞, μ̄ < ∞, cases (e) and (f)). There ℓ_z/h grows like ε^(−1/4) (e, f: 0.05 ε^(−1/4),
// measured 0.6 … 7.7 nodes over ε = 1e-4 … 1e-8 on the dovetail) and the layer's stresses on S
// do not converge on any ε a double-precision solve reaches; the two selections of a floating
// layer may then even find two answers (case (e) at ε = 5e-4). Full 2×2 integration integrates
// the through-thickness energy exactly (the zigzag costs a third of a uniform compression), and
// it cannot lock a thin layer: its extra in-plane constraint costs λ_ε·ε, which vanishes with ε
// in every case of Table 1 (λ_ε = ε^γ λ_g, γ > 0).
namespace thinlayer {

enum class LayerQuadrature {
  ByExponents,  // the rule below
  Selective,    // the λ part at the cell centre (controls, and the rule's choice where it is stable)
  Full,         // 2×2 Gauss points for every part
};

// The rule: selective integration unless its zigzag's reach grows without bound, γ < 1 and γ < δ.
bool selective_layer_quadrature(double gamma, double delta);

// `quadrature` resolved for a layer of exponents (γ, δ): true for selective integration.
bool uses_selective_quadrature(LayerQuadrature quadrature, double gamma, double delta);

// "selective" or "full": what a layer scene records (attribute layer_quadrature).
const char* quadrature_name(bool selective);

}  // namespace thinlayer
