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
// Two more, where the first-order answer carries what the limit law leaves out, against closed forms:
//  - the bilayer pulled along the layer by a force: the layer's membrane carries t E*_g ε of it (Betti);
//  - two glued strips in pure bending against their meshed layer: order 0 off by a = 3t/(4h), the
//    first-order answer by −(2/3) a² (beam theory, derived in the test).
// The end cell against its two limits known by hand: ν = 0 (no Poisson coupling: the uniformly
// stretched strip satisfies the free end, no normal deficit) and ν → 1/2 (the squeezed glue's
// Poiseuille length t √((1−ν)/(6(1−2ν)))).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

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
// δu, as SPEC §3 S6's estimate computes it (cases/scene/scene_first_order.cpp), full numbering. S runs
// between body `plus` (its bottom) and body `minus` (its top) over the nodes [first, size − drop_last).
struct Answer {
  Eigen::VectorXd u, delta;  // full DOF numbering, mm
};
Answer first_order_answer(const Model& model, int plus, int minus, int drop_last, const LayerAtThickness& layer) {
  const LinearSystem system(model);
  const InterfaceLaw law = InterfaceLaw::make_bilateral(layer.lambda / layer.thickness, layer.mu / layer.thickness);
  const Mesh& top = model.bodies[minus].mesh;
  const Mesh& bottom = model.bodies[plus].mesh;
  // The first node (x = 0) is held in these tests, and a node of S may not be.
  auto part = [drop_last](std::vector<int> nodes) { return std::vector<int>(nodes.begin() + 1, nodes.end() - drop_last); };
  const ContactProblem problem(system, {paired_interface("S", law, model, plus, part(bottom.node_set("bottom")),
                                                         bottom.edge_set("bottom"), minus, part(top.node_set("top")), 1e-12)});
  MixedSystem mixed(problem);
  const SolveReport limit = solve_bonded(problem, {}, &mixed);
  EXPECT_TRUE(limit.converged) << limit.message;
  const Eigen::VectorXd u = system.expand(limit.u);
  const FirstOrderLoad load =
      first_order_layer_load(problem, {layer}, u, limit.r, answer_statuses(problem, limit.r, 1e-6));
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(system.num_free());
  for (int g = 0; g < system.num_dofs(); ++g)
    if (system.free_index(g) >= 0) forces[system.free_index(g)] = load.body_forces[g];
  const MixedSystem::Answer d = mixed.solve_again(forces, load.row_values);
  return {u, system.scatter(d.u)};
}

// The bilayer held on its sides: S the nodes between them (a side's nodes are held), the layer going
// on into the supports there (LayerAtThickness::free_ends false).
Answer first_order(const Model& model) {
  LayerAtThickness layer{t, lambda_g, mu_g, PlaneHypothesis::Strain};
  layer.free_ends = false;
  return first_order_answer(model, 1, 0, 1, layer);
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

// The plane modulus of a membrane whose normal stress is free (plane strain): E* = 4μ(λ+μ)/(λ+2μ).
double plane_modulus(double lambda, double mu) { return 4 * mu * (lambda + mu) / (lambda + 2 * mu); }

// The same with free ends, S from the second node (x = 0 is held) to the last: S's last node is free,
// and S's first node is where the layer's held x = 0 end would be, loaded by nothing there in these
// tests (σ = 0 and ∂_s m_s = 0 at it, or the force that is checked).
Answer first_order_free_ends(const Model& model, int plus, int minus, double lambda, double mu, double thickness) {
  return first_order_answer(model, plus, minus, 0, LayerAtThickness{thickness, lambda, mu, PlaneHypothesis::Strain});
}

// A traction on a body's right side, one EdgeTraction per edge, its value at the edge's mid-height y.
void pull_right(Model& model, int body, const std::function<Eigen::Vector2d(double y)>& traction) {
  const Mesh& mesh = model.bodies[body].mesh;
  for (const auto& e : mesh.edge_set("right"))
    model.tractions.push_back({"right" + std::to_string(body), body, {e},
                               traction(0.5 * (mesh.nodes(e[0], 1) + mesh.nodes(e[1], 1)))});
}

TEST(FirstOrderLayer, TensionAlongTheLayerLoadsItsMembraneByTEStarEpsilon) {
  // The bilayer pulled by σ on its right sides, held at x = 0 (u_x = 0, one node u_y = 0): the limit
  // answer is the uniform uniaxial state ε = σ/E*_a, S carries nothing. The layer between S's ends
  // (x₁ = L/nx … L) is stretched by ε in its plane with its normal stress free: it carries the membrane
  // force N = t E*_g ε of the load, which the adherents no longer carry there. By Betti's reciprocity on
  // the (linear, symmetric) limit system, the loaded faces' mean displacement Σ f·δu / Σ f_x changes by
  // exactly the work of the first-order load on u₀ over the load: N (u₀(x₁) − u₀(L)) / (2Hσ) =
  // −(t E*_g / (2H E*_a)) ε (L − x₁) (the membrane's pair of forces at S's ends; S carries no σ, so no
  // other term: the eigen-jump's rows meet r₀ = 0). The meshed layer's, to first order in t.
  const double sigma = 10;  // daN/mm²
  Bilayer b = bilayer();
  auto zero = [](double, double) { return 0.0; };
  for (int body : {0, 1}) {
    hold(b.model, body, "left", 0, zero);
    pull_right(b.model, body, [&](double) { return Eigen::Vector2d(sigma, 0); });
  }
  hold(b.model, 0, "bottom_left", 1, zero);
  const Answer a = first_order_free_ends(b.model, 1, 0, lambda_g, mu_g, t);
  const double eps = sigma / plane_modulus(lambda_a, mu_a), x1 = L / nx;
  for (int i = 0; i < b.upper().num_nodes(); ++i)  // the limit answer is the uniform state
    EXPECT_NEAR(a.u[b.model.dof_offset(1) + 2 * i], eps * b.upper().nodes(i, 0), 1e-12) << i;
  double work = 0, force = 0;  // Σ f·δu and Σ f_x over the right sides' consistent nodal forces
  for (int body : {0, 1}) {
    const Mesh& mesh = b.model.bodies[body].mesh;
    for (const auto& e : mesh.edge_set("right")) {
      const double f = 0.5 * sigma * std::abs(mesh.nodes(e[1], 1) - mesh.nodes(e[0], 1));  // each end of the edge
      for (int n : e) work += f * a.delta[b.model.dof_offset(body) + 2 * n], force += f;
    }
  }
  const double expected = -t * plane_modulus(lambda_g, mu_g) / (2 * H * plane_modulus(lambda_a, mu_a)) * eps * (L - x1);
  EXPECT_NEAR(force, 2 * H * sigma, 1e-12 * H * sigma);
  EXPECT_NEAR(work / force, expected, 1e-9 * std::abs(expected));
}

TEST(FirstOrderLayer, PureBendingOfTwoGluedStripsIsRightToTheSquareOfItsOrderZeroError) {
  // Two strips of thickness h (lower [0, ℓ] × [−h, 0], upper on top) glued by a layer of thickness t, in
  // pure bending: each strip's right end carries the layered beam's pure-bending stress at curvature κ,
  // σ_xx = −E*_a κ (y − t/2) in the meshed layer's geometry (upper strip at y ≥ t); held by symmetry at
  // x = 0 (u_x = 0, one node u_y = 0). Three models of the same strips under the same loads: the meshed
  // layer (a band of glue tied to both strips), the glue's spring law in the limit geometry (upper strip
  // at y ≥ 0), and its first-order answer. Beam theory (exact in 2D for these states) for strips of
  // modulus E with a slip s(x) between their faces: the upper strip's axial force N⁺ = −N⁻, compatibility
  // 2N⁺/(Eh) + κh = s', the moment about S, M = 2E(h³/12)κ − N⁺h, so M = E I₀ κ − (E h²/2) s', I₀ = 2h³/3.
  // A layer carrying no shear slips by s = −tθ (θ = u_y'), s' = −tκ: the meshed layer's M = E I₀ κ (1 + a),
  // a = 3t/(4h); the limit law (s = 0) bends by κ₀ = M/(E I₀) = κ_layer (1 + a): order 0 is off by a.
  // The first-order answer takes the eigen-jump at u₀, s' = −t κ₀: alone it would give κ₀ (1 − a), off by
  // −a². Beside it the squares' m-force t σ_sn ∂_s m_n carries a moment t ∫ σ_sn ds: σ the limit answer's
  // shear where its strips take their axial force from the layer's loads, N⁺ going from the layered
  // beam's −Eκh(h+t)/2 at the loaded end to the limit's −Eκ₀h²/2 within (the glue's shear-lag length
  // ≤ 1.3 of it), ∫ σ_sn = E κ h t/8, a moment (3/16)(t/h)² = a²/3 of M that the symmetry takes: the
  // first-order answer is off by −a² + a²/3 = −(2/3) a², the square of order 0's error (the glue's own
  // bending, E_g t³/12, is 1e-6 of E I₀). The curvature is read as 2 (mean u_y at x = ℓ/2 − mean u_y at
  // x = 0) / (ℓ/2)² of the lower strip, ℓ/2 = 9 shear-lag lengths away from the loaded end. Q1 strips,
  // 16 elements a unit of length along x and 8 through h: their parasitic shear (which stiffens their
  // bending, not their stretch, and so moves a) is then < 1 % of their bending stiffness.
  constexpr double h = 1, ell = 24;
  constexpr int sx = 384, sy = 8, gy = 2;
  const double kappa = 1e-4, E_a = plane_modulus(lambda_a, mu_a);
  const Material adherent{lambda_a, mu_a}, glue{lambda_g, mu_g};
  auto zero = [](double, double) { return 0.0; };
  // A body of the rectangle [0, ℓ] × [y0, y0 + height], held by symmetry at x = 0; a strip (load) also
  // carries the layered beam's stress on its right end, `shift` its offset from the layer's geometry.
  auto add_body = [&](Model& model, double y0, double height, int ny, const Material& material) {
    const int body = static_cast<int>(model.bodies.size());
    model.bodies.push_back({"body" + std::to_string(body), structured_rectangle({0, y0, ell, height, sx, ny}), material});
    hold(model, body, "left", 0, zero);
    return body;
  };
  auto load = [&](Model& model, int body, double shift, double thickness) {
    pull_right(model, body, [=](double y) { return Eigen::Vector2d(-E_a * kappa * (y + shift - thickness / 2), 0); });
  };
  auto curvature = [&](const Model& model, const Eigen::VectorXd& u) {
    const Mesh& m = model.bodies[0].mesh;
    double middle = 0, left = 0;
    for (int n = 0; n < m.num_nodes(); ++n) {
      if (std::abs(m.nodes(n, 0) - ell / 2) < 1e-9) middle += u[2 * n + 1];
      if (std::abs(m.nodes(n, 0)) < 1e-9) left += u[2 * n + 1];
    }
    return 2 * (middle - left) / (sy + 1) / (ell * ell / 4);
  };
  // A tie between body `plus`'s bottom and body `minus`'s top, from the second node on.
  auto tie = [](const std::string& name, const Model& model, int plus, int minus) {
    const Mesh &p = model.bodies[plus].mesh, &m = model.bodies[minus].mesh;
    auto tail = [](std::vector<int> nodes) { return std::vector<int>(nodes.begin() + 1, nodes.end()); };
    return paired_interface(name, InterfaceLaw::tie(), model, plus, tail(p.node_set("bottom")), p.edge_set("bottom"), minus,
                            tail(m.node_set("top")), 1e-12);
  };
  for (const double thickness : {0.05, 0.1}) {
    const double a = 0.75 * thickness / h;
    Model limit;  // the limit geometry: the upper strip on S at y = 0
    load(limit, add_body(limit, -h, h, sy, adherent), 0, thickness);
    load(limit, add_body(limit, 0, h, sy, adherent), thickness, thickness);
    hold(limit, 0, "bottom_left", 1, zero);
    const Answer first = first_order_free_ends(limit, 1, 0, lambda_g, mu_g, thickness);
    Model layered;  // the meshed layer: lower strip, glue band [0, t], upper strip at y = t
    load(layered, add_body(layered, -h, h, sy, adherent), 0, thickness);
    add_body(layered, 0, thickness, gy, glue);
    load(layered, add_body(layered, thickness, h, sy, adherent), 0, thickness);
    hold(layered, 0, "bottom_left", 1, zero);
    const LinearSystem system(layered);
    const ContactProblem problem(system, {tie("S+", layered, 2, 1), tie("S-", layered, 1, 0)});
    const SolveReport layer = solve_bonded(problem);
    ASSERT_TRUE(layer.converged) << layer.message;
    const double kappa_layer = curvature(layered, system.expand(layer.u));
    const double order0 = curvature(limit, first.u) / kappa_layer - 1;
    const double order1 = curvature(limit, first.u + first.delta) / kappa_layer - 1;
    EXPECT_NEAR(order0, a, 0.05 * a) << thickness;
    EXPECT_NEAR(order1, -2 * a * a / 3, 0.1 * 2 * a * a / 3) << thickness << ": order 0 " << order0;
  }
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
