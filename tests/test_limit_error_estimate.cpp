// SPEC §3 S6: the layer's first-order answer behind a limit solve (core/solvers/first_order_layer.h,
// core/solvers/layer_end_cell.h; derived in studies/limit_error_estimate.md), against closed forms.
//
// A bonded bilayer — two blocks, the interface between them the bilateral spring of a glue of
// thickness t (K_N = (λ_g+2μ_g)/t, K_T = μ_g/t) — in three uniform states whose layer answer is known
// by hand (plane strain, every field uniform in each body):
//  - uniform shear (simple shear, the sides held on the exact profile): the layer shears by τ t/μ_g,
//    exactly the spring's jump: nothing to correct;
//  - uniform tension across the layer (uniaxial strain, the sides held on the exact profile): it stretches by
//    σ t/(λ_g+2μ_g), the spring's again: nothing to correct;
//  - uniform tension along the layer (ε_xx = ε imposed on the sides, the faces free): the spring carries
//    nothing and has no jump, but the layer, stretched in its plane with its normal stress free,
//    thins by ν* ε t (ν* = λ_g/(λ_g+2μ_g)): the upper block comes down by exactly that.
// The end cell against its two limits known by hand: ν = 0 (no Poisson coupling: the uniformly
// stretched strip satisfies the free end, no normal deficit) and ν → 1/2 (the squeezed glue's
// Poiseuille length t √((1−ν)/(6(1−2ν)))).
#include <gtest/gtest.h>

#include <cmath>

#include "core/mesh/structured_rectangle.h"
#include "core/solvers/answer_statuses.h"
#include "core/solvers/bonded_solve.h"
#include "core/solvers/first_order_layer.h"
#include "core/solvers/layer_end_cell.h"
#include "core/solvers/mixed_system.h"

namespace thinlayer {
namespace {

constexpr double L = 4, H = 1;              // each block [0, L] × [−H, 0] (minus) and [0, L] × [0, H] (plus), mm
constexpr int nx = 8, ny = 2;
constexpr double lambda_a = 4500, mu_a = 5400;  // adherents, daN/mm²
constexpr double lambda_g = 300, mu_g = 100;    // glue, daN/mm² (ν_g = 0.375)
constexpr double t = 0.05;                      // mm

struct Bilayer {
  Model model;
  const Mesh& lower() const { return model.bodies[0].mesh; }
  const Mesh& upper() const { return model.bodies[1].mesh; }
};

Bilayer bilayer() {
  Bilayer b;
  b.model.bodies.push_back({"lower", structured_rectangle({0, -H, L, H, nx, ny}), Material{lambda_a, mu_a}});
  b.model.bodies.push_back({"upper", structured_rectangle({0, 0, L, H, nx, ny}), Material{lambda_a, mu_a}});
  return b;
}

// u_c = value(y) on the nodes of a node set of body `body`.
template <class F>
void hold(Model& model, int body, const std::string& set, int c, F value) {
  const Mesh& mesh = model.bodies[body].mesh;
  for (int node : mesh.node_set(set))
    model.dirichlet.push_back({set + std::to_string(body) + std::to_string(c) + "_" + std::to_string(node), body, {node}, c,
                               value(mesh.nodes(node, 0), mesh.nodes(node, 1))});
}

// The limit solve (bonded: one sparse solve, its factorisation kept), then the first-order answer's
// δu, as SPEC §3 S6's estimate computes it (cases/scene/scene_first_order.cpp), full numbering.
struct Answer {
  Eigen::VectorXd u, delta;  // full DOF numbering, mm
};
Answer first_order(const Model& model) {
  const LinearSystem system(model);
  const InterfaceLaw law = InterfaceLaw::make_bilateral(lambda_g / t, mu_g / t);
  const Mesh& lower = model.bodies[0].mesh;
  const Mesh& upper = model.bodies[1].mesh;
  // S: the nodes between the sides (a side's nodes are held, and an interface node may not be): the
  // layer goes on into the supports there (LayerAtThickness::free_ends false).
  auto inner = [](std::vector<int> nodes) { return std::vector<int>(nodes.begin() + 1, nodes.end() - 1); };
  const ContactProblem problem(system, {paired_interface("S", law, model, 1, inner(upper.node_set("bottom")),
                                                         upper.edge_set("bottom"), 0, inner(lower.node_set("top")), 1e-12)});
  MixedSystem mixed(problem);
  const SolveReport limit = solve_bonded(problem, {}, &mixed);
  EXPECT_TRUE(limit.converged) << limit.message;
  LayerAtThickness layer{t, lambda_g, mu_g, PlaneHypothesis::Strain};
  layer.free_ends = false;
  const Eigen::VectorXd u = system.expand(limit.u);
  const FirstOrderLoad load =
      first_order_layer_load(problem, {layer}, u, limit.r, answer_statuses(problem, limit.r, 1e-6));
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(system.num_free());
  for (int g = 0; g < system.num_dofs(); ++g)
    if (system.free_index(g) >= 0) forces[system.free_index(g)] = load.body_forces[g];
  const MixedSystem::Answer d = mixed.solve_again(forces, load.row_values);
  return {u, system.scatter(d.u)};
}

TEST(FirstOrderLayer, UniformShearIsTheSpringsExactly) {
  // Simple shear τ: u_x = (τ/μ_a)(y + H) below, the same plus the jump τ/K_T above; u_y = 0.
  const double U = 1e-3;
  const double K_T = mu_g / t, tau = U / (2 * H / mu_a + 1 / K_T);
  Bilayer b = bilayer();
  auto below = [&](double, double y) { return tau / mu_a * (y + H); };
  auto above = [&](double, double y) { return tau / mu_a * (y + H) + tau / K_T; };
  auto zero = [](double, double) { return 0.0; };
  for (const char* side : {"left", "right", "bottom"}) hold(b.model, 0, side, 0, below), hold(b.model, 0, side, 1, zero);
  for (const char* side : {"left", "right", "top"}) hold(b.model, 1, side, 0, above), hold(b.model, 1, side, 1, zero);
  const Answer a = first_order(b.model);
  for (int i = 0; i < b.upper().num_nodes(); ++i)  // the limit answer is the uniform state
    EXPECT_NEAR(a.u[b.model.dof_offset(1) + 2 * i], above(0, b.upper().nodes(i, 1)), 1e-12) << i;
  EXPECT_LT(a.delta.cwiseAbs().maxCoeff(), 1e-12 * U);
}

TEST(FirstOrderLayer, UniformTensionAcrossTheLayerIsTheSpringsExactly) {
  // Uniaxial strain: σ_yy = σ everywhere, u_x = 0; the jump σ/K_N.
  const double V = 1e-3;
  const double K_N = (lambda_g + 2 * mu_g) / t, sigma = V / (2 * H / (lambda_a + 2 * mu_a) + 1 / K_N);
  Bilayer b = bilayer();
  auto zero = [](double, double) { return 0.0; };
  auto below = [&](double, double y) { return sigma / (lambda_a + 2 * mu_a) * (y + H); };
  auto above = [&](double, double y) { return sigma / (lambda_a + 2 * mu_a) * (y + H) + sigma / K_N; };
  for (const char* side : {"left", "right", "bottom"}) hold(b.model, 0, side, 0, zero), hold(b.model, 0, side, 1, below);
  for (const char* side : {"left", "right", "top"}) hold(b.model, 1, side, 0, zero), hold(b.model, 1, side, 1, above);
  const Answer a = first_order(b.model);
  for (int i = 0; i < b.upper().num_nodes(); ++i)
    EXPECT_NEAR(a.u[b.model.dof_offset(1) + 2 * i + 1], sigma / (lambda_a + 2 * mu_a) * (b.upper().nodes(i, 1) + H) + sigma / K_N,
                1e-12) << i;
  EXPECT_LT(a.delta.cwiseAbs().maxCoeff(), 1e-12 * V);
}

TEST(FirstOrderLayer, TensionAlongTheLayerThinsItByItsPoissonRatio) {
  // ε_xx = ε on every side, the top and bottom free, the lower block pinned at one corner: σ_yy = 0
  // in all, the spring carries nothing, u_y(top block) − u_y(bottom block) = 0 across S in the
  // limit; the layer thins by ν* ε t, so the upper block comes down by that much, all of it.
  const double eps = 1e-3;
  Bilayer b = bilayer();
  auto zero = [](double, double) { return 0.0; };
  auto stretched = [&](double x, double) { return eps * x; };
  for (int body : {0, 1}) {
    hold(b.model, body, "left", 0, stretched);
    hold(b.model, body, "right", 0, stretched);
  }
  hold(b.model, 0, "bottom_left", 1, zero);
  const Answer a = first_order(b.model);
  const double nu_star = lambda_g / (lambda_g + 2 * mu_g);
  for (int i = 0; i < b.upper().num_nodes(); ++i) {
    EXPECT_NEAR(a.delta[b.model.dof_offset(1) + 2 * i + 1], -nu_star * eps * t, 1e-9 * nu_star * eps * t) << i;
    EXPECT_NEAR(a.delta[b.model.dof_offset(1) + 2 * i], 0.0, 1e-12 * eps * L) << i;
  }
  for (int i = 0; i < b.lower().num_nodes(); ++i) EXPECT_NEAR(a.delta[2 * i + 1], 0.0, 1e-12 * eps * L) << i;
}

TEST(LayerEndCell, NoPoissonCouplingNoNormalDeficit) {
  // ν = 0: λ = 0, the uniform uniaxial strain of the strip has σ_xx = λ ε_yy = 0 and satisfies the
  // free end as it is: the normal force is the spring's to the end.
  const LayerEndDeficits d = layer_end_deficits(0.0, PlaneHypothesis::Strain);
  EXPECT_NEAR(d.normal, 0.0, 1e-9);
  EXPECT_GT(d.shear, 0.1);  // the shear's σ_xy must vanish on the end face: a deficit of order t
}

TEST(LayerEndCell, NearlyIncompressibleGlueIsSqueezedOverItsPoiseuilleLength) {
  // ν → 1/2: the glue pressed between rigid faces flows out at its end; lubrication theory gives a
  // pressure rising over the length t √((λ+2μ)/(12μ)) = t √((1−ν)/(6(1−2ν))), the normal deficit.
  for (double nu : {0.495, 0.499}) {
    const double poiseuille = std::sqrt((1 - nu) / (6 * (1 - 2 * nu)));
    EXPECT_NEAR(layer_end_deficits(nu, PlaneHypothesis::Strain).normal / poiseuille, 1.0, 0.1) << nu;
  }
}

}  // namespace
}  // namespace thinlayer
