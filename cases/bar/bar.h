#pragma once
// The bar benchmark (paper §4.3, Fig. 12, Table 3; SPEC §2.1), limit mode.
//
// Square cross-section ADEG of a long bar, side L = 40 mm, plane strain:
// A = (0,0), D = (L,0), E = (L,L), G = (0,L). u₁ = 0 on DE; u₁ = u₂ = 0 at D. Tractions
// F1 = 10 daN/mm² on AG (+x) and F2 = -5 daN/mm² on GE (y). Contact zone AD against a rigid
// flat foundation, friction f = 1; the contact nodes are the nodes of AD except D.
#include "core/fem/model.h"
#include "core/interface/interface.h"
#include "core/mesh/structured_rectangle.h"

namespace thinlayer::bar {

constexpr double side = 40.0;        // L, mm
// The thickest layer the bar's layer mode accepts (mm): a fortieth of its side, not the tenth that
// makes a layer thin. Table 3's rows give the layer λ̄ up to 4.5e8 against μ̄ down to 0.054
// (daN/mm²), so a thick layer is nearly incompressible (λ_ε/μ_ε up to 1e10): measured with 2 and 4
// elements through it, every row converges at 1 mm (residual <= 1.4e-11), while at 3-4 mm row 2 is
// singular and row 4 stops at its round-off floor (1.8e-10) or adrift (issue 26, item 7).
constexpr double thickest_layer = 1.0;
constexpr double lambda_m = 4500.0;  // daN/mm² (45 GPa)
constexpr double mu_m = 5400.0;      // daN/mm² (54 GPa)
constexpr double F1 = 10.0;          // daN/mm², on AG, along +x
constexpr double F2 = -5.0;          // daN/mm², on GE, along y
constexpr double friction = 1.0;

struct MeshOptions {
  int nx = 32, ny = 32;  // elements along AD and along DE
  ElementType element = ElementType::Q1;
  TriangleDiagonal diagonal = TriangleDiagonal::Right;  // P1 only
  PlaneHypothesis plane = PlaneHypothesis::Strain;
  // Stress tests (S5). Interior nodes moved by up to this fraction of the element size
  // (core/mesh/distortion.h), in [0, 0.5); the boundary stays put. A distortion that inverts
  // a cell is refused (std::invalid_argument).
  double distortion = 0;
  // Multiplies both tractions F1 and F2; -1 pulls AG outwards and GE upwards, which lifts
  // the bar off AD (an interface that opens everywhere).
  double load_scale = 1;
};

// Body 0 is the bar; Dirichlet conditions "DE" (u₁ on DE) and "D" (u₂ at D); tractions
// "AG" and "GE".
Model make_model(const MeshOptions& options = {});

// The limit-mode interface "S" on AD (without D), carrying the given law.
Interface make_interface(const Model& model, const InterfaceLaw& law);

// Thin-layer mode (SPEC §2.1): body 1 is a floating layer of thickness eps (mm) under AD,
// [0, L] × [-eps, 0], `layer_elements` Q1 elements through its thickness, with Lamé
// coefficients λ_ε = eps·λ̄, μ_ε = eps·μ̄ (daN/mm²), on the rigid foundation moved down by eps.
struct LayerOptions {
  double eps = 1e-4;        // mm
  double lambda_eps = 0;    // daN/mm²
  double mu_eps = 0;        // daN/mm²
  int layer_elements = 2;
};
Model make_layer_model(const MeshOptions& mesh, const LayerOptions& layer);

// The two interfaces of the layer, both Signorini-Coulomb with f = 1: "S+" between the bar
// (plus) and the layer's top face, without the node under D (32 nodes: node k is node k of
// the limit mode's S); "S-" between the layer (plus) and the foundation, all 33 nodes (the
// last one under D).
std::vector<Interface> make_layer_interfaces(const Model& model);

}  // namespace thinlayer::bar
