// A thin-layer problem with a closed-form answer: a stack (block / layer / block) under a
// uniform stress σ = [[-ν' p, τ], [τ, -p]], ν' = λ/(λ+2μ), with τ < f p so that both faces of
// the layer stick. If the layer has the blocks' Poisson ratio (λ_ε/μ_ε = λ/μ), every body is
// in the same uniform stress with ε_xx = 0 — compatible across the interfaces — and
//   ε_yy = -p/(λ+2μ),  γ_xy = τ/μ  in each body,
// so the layer compresses by ε p/(λ_ε+2μ_ε) = p/K_N and shears by ε τ/μ_ε = τ/K_T with
// K_N = (λ_ε+2μ_ε)/ε, K_T = μ_ε/ε: exactly the limit law (d), whose solve must agree. Q1
// reproduces these piecewise-linear fields exactly, so everything holds to round-off.
#include <gtest/gtest.h>

#include <limits>

#include "core/mesh/layer_band.h"
#include "core/mesh/structured_rectangle.h"
#include "core/solvers/fast_solver.h"
#include "core/solvers/relaxation_solver.h"

namespace thinlayer {
namespace {

constexpr double lambda = 4500, mu = 5400;  // daN/mm²
constexpr double p = 10, tau = 2, f = 0.5;  // daN/mm², τ < f p
constexpr double nu = lambda / (lambda + 2 * mu);
constexpr int n = 4;                        // elements per side of each block

// Tractions of the uniform stress on a body's left and right sides.
void add_side_tractions(Model& model, int body, const std::vector<std::array<int, 2>>& left,
                        const std::vector<std::array<int, 2>>& right) {
  model.tractions.push_back({"left", body, left, {nu * p, -tau}});
  model.tractions.push_back({"right", body, right, {-nu * p, tau}});
}

std::vector<std::array<int, 2>> edges_of(const std::vector<int>& nodes) {
  std::vector<std::array<int, 2>> edges;
  for (size_t i = 0; i + 1 < nodes.size(); ++i) edges.push_back({nodes[i], nodes[i + 1]});
  return edges;
}

// Bottom block [0,1]×[-1,0] clamped at its bottom, top block [0,1]×[gap, 1+gap] loaded on top.
Model blocks(double gap) {
  Model model;
  model.bodies.reserve(3);
  model.bodies.push_back({"bottom", structured_rectangle({0, -1, 1, 1, n, n}), Material{lambda, mu}});
  // Only the stack holds the top block up: it floats, like the layer.
  model.bodies.push_back({"top", structured_rectangle({0, gap, 1, 1, n, n}), Material{lambda, mu}, true});
  const Mesh& lo = model.bodies[0].mesh;
  const Mesh& up = model.bodies[1].mesh;
  for (int c : {0, 1}) model.dirichlet.push_back({"clamp", 0, lo.node_set("bottom"), c, 0.0});
  model.tractions.push_back({"top", 1, up.edge_set("top"), {tau, -p}});
  add_side_tractions(model, 0, lo.edge_set("left"), lo.edge_set("right"));
  add_side_tractions(model, 1, up.edge_set("left"), up.edge_set("right"));
  return model;
}

struct Jumps {
  Eigen::VectorXd N, T, sigma_N, sigma_T;
};

// Jumps and stresses across the whole layer (limit: across S), node by node along x.
Jumps total_jumps(const Model& model, const LinearSystem& system, const SolveReport& s, int top, int bottom) {
  const Eigen::VectorXd u = system.expand(s.u);
  const auto& upper = model.bodies[top].mesh.node_set("bottom");
  const auto& lower = model.bodies[bottom].mesh.node_set("top");
  Jumps j{Eigen::VectorXd(n + 1), Eigen::VectorXd(n + 1), {}, {}};
  for (int i = 0; i <= n; ++i) {
    const int a = model.dof_offset(top) + 2 * upper[i], b = model.dof_offset(bottom) + 2 * lower[i];
    j.N[i] = u[b + 1] - u[a + 1];  // n = (0, 1): [u]_N = n·(u⁻ - u⁺)
    j.T[i] = u[a] - u[b];          // t = (1, 0): [u]_T = t·(u⁺ - u⁻)
  }
  return j;
}

TEST(ThinLayerClosedForm, BondedStackMatchesTheLimitLawExactly) {
  const double eps = 1e-3;
  const double lambda_eps = eps * lambda, mu_eps = eps * mu;  // same Poisson ratio as the blocks
  const double K_N = (lambda_eps + 2 * mu_eps) / eps, K_T = mu_eps / eps;

  // Layer mode.
  Model layer_model = blocks(eps);
  {
    const Mesh& lo = layer_model.bodies[0].mesh;
    const Mesh& up = layer_model.bodies[1].mesh;
    FacePolyline minus_face(n + 1, 2), plus_face(n + 1, 2);
    for (int i = 0; i <= n; ++i) {
      minus_face.row(i) = lo.nodes.row(lo.node_set("top")[i]);
      plus_face.row(i) = up.nodes.row(up.node_set("bottom")[i]);
    }
    layer_model.bodies.push_back({"layer", layer_band(minus_face, plus_face, 2), Material{lambda_eps, mu_eps}, true});
    const Mesh& layer = layer_model.bodies[2].mesh;
    add_side_tractions(layer_model, 2, edges_of(layer.node_set("end_first")), edges_of(layer.node_set("end_last")));
  }
  const LinearSystem layer_system(layer_model);
  const InterfaceLaw contact = InterfaceLaw::make(std::numeric_limits<double>::infinity(),
                                                  std::numeric_limits<double>::infinity(), f);
  const Mesh& lo = layer_model.bodies[0].mesh;
  const Mesh& up = layer_model.bodies[1].mesh;
  const Mesh& layer = layer_model.bodies[2].mesh;
  const ContactProblem layer_problem(
      layer_system,
      {paired_interface("S+", contact, layer_model, 1, up.node_set("bottom"), up.edge_set("bottom"), 2, layer.node_set("S+"), 1e-12),
       paired_interface("S-", contact, layer_model, 2, layer.node_set("S-"), layer.edge_set("S-"), 0, lo.node_set("top"), 1e-12)});
  const SolveReport layered = solve_fast(layer_problem);
  ASSERT_TRUE(layered.converged) << layered.message;

  // Limit mode: the blocks touch along S with the law (d) of K_N, K_T.
  const Model limit_model = blocks(0.0);
  const LinearSystem limit_system(limit_model);
  const Mesh& lo0 = limit_model.bodies[0].mesh;
  const Mesh& up0 = limit_model.bodies[1].mesh;
  const InterfaceLaw law_d = InterfaceLaw::make(lambda_eps / eps, mu_eps / eps, f);
  const ContactProblem limit_problem(
      limit_system, {paired_interface("S", law_d, limit_model, 1, up0.node_set("bottom"), up0.edge_set("bottom"), 0,
                                      lo0.node_set("top"), 1e-12)});
  const SolveReport limit = solve_fast(limit_problem);
  ASSERT_TRUE(limit.converged) << limit.message;

  const Jumps a = total_jumps(layer_model, layer_system, layered, 1, 0);
  const Jumps b = total_jumps(limit_model, limit_system, limit, 1, 0);
  for (int i = 0; i <= n; ++i) {
    EXPECT_NEAR(a.N[i], p / K_N, 1e-9 * p / K_N) << i;  // the layer's compression, closed form
    EXPECT_NEAR(a.T[i], tau / K_T, 1e-9 * tau / K_T) << i;
    EXPECT_NEAR(b.N[i], p / K_N, 1e-9 * p / K_N) << i;  // the limit law's jump
    EXPECT_NEAR(b.T[i], tau / K_T, 1e-9 * tau / K_T) << i;
  }
  // Stresses on both faces of the layer: σ_N = -p and σ_T = -τ (both faces stick, τ < f p).
  const Eigen::VectorXd g = layer_problem.jumps(layered.u);
  for (int k = 0; k < layer_problem.num_nodes(); ++k) {
    const double l = layer_problem.node(k).length;
    EXPECT_NEAR(layered.r[2 * k] / l, -p, 1e-9 * p) << k;
    EXPECT_NEAR(layered.r[2 * k + 1] / l, -tau, 1e-9 * p) << k;
    EXPECT_NEAR(g[2 * k], 0.0, 1e-12) << k;      // in contact, no interpenetration of the faces
    EXPECT_NEAR(g[2 * k + 1], 0.0, 1e-12) << k;  // and no slip
  }
}

TEST(ThinLayerClosedForm, RelaxationSolvesTheLimitStackToo) {
  // The paper's algorithm on the limit-mode stack: the same closed-form jumps.
  const double K_N = (lambda + 2 * mu), K_T = mu;  // ε λ_g / ε with ε = 1
  const Model model = blocks(0.0);
  const LinearSystem system(model);
  const Mesh& lo = model.bodies[0].mesh;
  const Mesh& up = model.bodies[1].mesh;
  const ContactProblem problem(system, {paired_interface("S", InterfaceLaw::make(lambda, mu, f), model, 1,
                                                         up.node_set("bottom"), up.edge_set("bottom"), 0,
                                                         lo.node_set("top"), 1e-12)});
  SolverOptions options;
  options.tolerance = 1e-11;
  const SolveReport s = solve_relaxation(problem, options);
  ASSERT_TRUE(s.converged) << s.message;
  const Jumps j = total_jumps(model, system, s, 1, 0);
  for (int i = 0; i <= n; ++i) {
    EXPECT_NEAR(j.N[i], p / K_N, 1e-7 * p / K_N) << i;
    EXPECT_NEAR(j.T[i], tau / K_T, 1e-7 * tau / K_T) << i;
  }
}

}  // namespace
}  // namespace thinlayer
