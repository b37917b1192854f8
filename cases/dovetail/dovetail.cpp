#include "cases/dovetail/dovetail.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/io/reference_tables.h"

namespace thinlayer::dovetail {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// lim_{ε→0} ε^(p-1) g for the exponent p.
double limit_ratio(double p, double g) {
  if (p < 1) return inf;
  if (p > 1) return 0.0;
  return g;
}

// The supports and the pull-out, the same in both modes.
void add_supports(Model& model, int base, int tenon) {
  const std::vector<int>& bottom = model.bodies[base].mesh.node_set("bottom");
  const std::vector<int>& top = model.bodies[tenon].mesh.node_set("top");
  model.dirichlet.push_back({"base_bottom", base, bottom, 0, 0.0});
  model.dirichlet.push_back({"base_bottom", base, bottom, 1, 0.0});
  model.dirichlet.push_back({"tenon_top", tenon, top, 0, pull_x});
  model.dirichlet.push_back({"tenon_top", tenon, top, 1, pull_y});
}

// Matching nodes lie at the same position up to round-off of coordinates of order 1.
constexpr double match_tolerance = 1e-12;

}  // namespace

Exponents validated(Exponents e) {
  if (!std::isfinite(e.gamma) || e.gamma < 0)
    throw std::invalid_argument("gamma must be finite and >= 0, got " + std::to_string(e.gamma));
  if (!std::isfinite(e.delta) || e.delta < 0 || e.delta >= 2)
    throw std::invalid_argument("delta must be in [0, 2), got " + std::to_string(e.delta));
  return e;
}

Exponents exponents_of(char law_case) {
  for (const Table2Row& row : load_table2())
    if (row.law_case == law_case) return validated({row.gamma, row.delta});
  throw std::invalid_argument(std::string("unknown law case '") + law_case + "' (expected a..i)");
}

InterfaceLaw limit_law(const Exponents& e, double f) {
  return InterfaceLaw::make(limit_ratio(e.gamma, lambda_g), limit_ratio(e.delta, mu_g), f);
}

Model make_limit_model(const LimitMeshes& meshes) {
  Model model;
  model.bodies.push_back({"base", meshes.base, Material{lambda_m, mu_m, PlaneHypothesis::Strain}});
  model.bodies.push_back({"tenon", meshes.tenon, Material{lambda_m, mu_m, PlaneHypothesis::Strain}});
  add_supports(model, 0, 1);
  return model;
}

Interface make_limit_interface(const Model& model, const InterfaceLaw& law) {
  const Mesh& tenon = model.bodies.at(1).mesh;
  return paired_interface("S", law, model, 1, tenon.node_set("S"), tenon.edge_set("S"), 0,
                          model.bodies.at(0).mesh.node_set("S"), match_tolerance);
}

Model make_layer_model(const LayerMeshes& meshes, const Exponents& e, LayerQuadrature quadrature) {
  const Exponents x = validated(e);
  const double lambda_eps = std::pow(meshes.eps, x.gamma) * lambda_g;
  const double mu_eps = std::pow(meshes.eps, x.delta) * mu_g;
  Model model;
  model.bodies.push_back({"base", meshes.base, Material{lambda_m, mu_m, PlaneHypothesis::Strain}});
  // The layer can be nearly incompressible (λ_ε/μ_ε = ε^(γ−δ) λ_g/μ_g): selective integration
  // keeps it from locking, except where its zigzag mode is free (cases (e), (f): γ < 1, γ < δ),
  // which take full integration (cases/layer_quadrature.h). (The bar's layer, γ = δ = 1, keeps
  // full integration: there all 18 scenes converge with it, one fewer without.)
  const bool selective = uses_selective_quadrature(quadrature, x.gamma, x.delta);
  model.bodies.push_back({"layer", meshes.layer, Material{lambda_eps, mu_eps, PlaneHypothesis::Strain}, true, selective});
  model.bodies.push_back({"tenon", meshes.tenon, Material{lambda_m, mu_m, PlaneHypothesis::Strain}});
  add_supports(model, 0, 2);
  return model;
}

std::vector<Interface> make_layer_interfaces(const Model& model, double f) {
  const InterfaceLaw signorini_coulomb = InterfaceLaw::make(inf, inf, f);
  const Mesh& base = model.bodies.at(0).mesh;
  const Mesh& layer = model.bodies.at(1).mesh;
  const Mesh& tenon = model.bodies.at(2).mesh;
  // Coordinates are of order 1 and the faces ε apart: match within round-off only.
  Interface upper = paired_interface("S+", signorini_coulomb, model, 2, tenon.node_set("S"), tenon.edge_set("S"), 1,
                                     layer.node_set("S+"), match_tolerance);
  Interface lower = paired_interface("S-", signorini_coulomb, model, 1, layer.node_set("S-"), layer.edge_set("S-"), 0,
                                     base.node_set("S"), match_tolerance);
  return {upper, lower};
}

}  // namespace thinlayer::dovetail
