// The quadrature of a thin layer's Q1 elements (cases/layer_quadrature.h): the zigzag that
// selective integration leaves to μ alone, the rule that picks full integration where that zigzag
// is free (cases e, f), and what the dovetail's layer scenes record.
#include <gtest/gtest.h>

#include "cases/dovetail/dovetail.h"
#include "cases/layer_quadrature.h"
#include "core/fem/element_q1.h"
#include "core/fem/material.h"
#include "studies/drivers/convergence_study.h"
#include "studies/tools/scene_cache.h"

namespace thinlayer {
namespace {

// A thin cell h × t (t = h/1000) on a fixed base; its top nodes (2, 3) pushed down by a, together
// (a uniform compression) or in opposition (the zigzag of the columns). Energy ½ uᵀ K u.
double energy(const Matrix8d& K, double top_right, double top_left) {
  Eigen::Matrix<double, 8, 1> u = Eigen::Matrix<double, 8, 1>::Zero();
  u[5] = top_right;  // node 2 (h, t), u2
  u[7] = top_left;   // node 3 (0, t), u2
  return 0.5 * u.dot(K * u);
}

TEST(LayerQuadrature, SelectiveIntegrationLeavesTheZigzagToMuAlone) {
  const double h = 0.025, t = h / 1000;
  Coords4 xy;
  xy << 0, 0, h, 0, h, t, 0, t;
  const Material glue{4500 * 1e3, 5400 * 1e-3, PlaneHypothesis::Strain};  // λ/μ = 8.3e5: case (e)'s kind
  const Eigen::Matrix3d D = glue.D();
  Eigen::Matrix3d D_volumetric = Eigen::Matrix3d::Zero();
  D_volumetric.topLeftCorner<2, 2>().setConstant(glue.lambda);
  const Matrix8d full = q1_stiffness(xy, D), selective = q1_stiffness_selective(xy, D_volumetric, D - D_volumetric);
  const double a = 1e-6;
  // Uniform compression: both rules integrate it exactly, (λ + 2μ)/t × h a² / 2.
  const double uniform = (glue.lambda + 2 * glue.mu) / t * h * a * a / 2;
  EXPECT_NEAR(energy(full, -a, -a), uniform, 1e-9 * uniform);
  EXPECT_NEAR(energy(selective, -a, -a), uniform, 1e-9 * uniform);
  // The zigzag: a third of it with full integration (a linear Δ(x) integrated exactly), only
  // μ's part with the one-point λ rule (2μ/(λ + 2μ)/3 of it, up to the O(t/h) shear terms).
  EXPECT_NEAR(energy(full, -a, a) / uniform, 1.0 / 3, 1e-3);
  const double mu_share = 2 * glue.mu / (glue.lambda + 2 * glue.mu) / 3;
  EXPECT_NEAR(energy(selective, -a, a) / uniform, mu_share, 0.01 * mu_share);
  EXPECT_LT(energy(selective, -a, a) / uniform, 1e-5);
}

TEST(LayerQuadrature, FullIntegrationExactlyWhereTheZigzagIsFree) {
  // Table 2: (γ, δ) of cases a … i. Free (γ < 1 and γ < δ): e, f.
  const struct {
    char law_case;
    bool selective;
  } expected[] = {{'a', true}, {'b', true}, {'c', true}, {'d', true}, {'e', false},
                  {'f', false}, {'g', true}, {'h', true}, {'i', true}};
  for (const auto& c : expected) {
    const dovetail::Exponents e = dovetail::exponents_of(c.law_case);
    EXPECT_EQ(selective_layer_quadrature(e.gamma, e.delta), c.selective) << c.law_case;
    EXPECT_TRUE(uses_selective_quadrature(LayerQuadrature::Selective, e.gamma, e.delta));
    EXPECT_FALSE(uses_selective_quadrature(LayerQuadrature::Full, e.gamma, e.delta));
    EXPECT_EQ(uses_selective_quadrature(LayerQuadrature::ByExponents, e.gamma, e.delta), c.selective);
  }
}

TEST(LayerQuadrature, ALayerSceneRecordsItsQuadratureAndAControlSaysSoInItsId) {
  static DovetailLimitBulk bulk(dovetail::MeshOptions{0.05, 0.2, 2});
  DovetailSceneCache cache(bulk, 2, false, "test");
  DovetailSceneDef control = layer_scene('e', 1e-2, 1e-8);
  control.quadrature = LayerQuadrature::Selective;
  cache.solve({layer_scene('e', 1e-2, 1e-8), control, layer_scene('d', 1e-2, 1e-8)});
  const SceneRecord& rule = cache.get(layer_scene('e', 1e-2, 1e-8)).record;
  const SceneRecord& selective = cache.get(control).record;
  EXPECT_EQ(rule.text.at("layer_quadrature"), "full");
  EXPECT_EQ(selective.text.at("layer_quadrature"), "selective");
  EXPECT_EQ(cache.get(layer_scene('d', 1e-2, 1e-8)).record.text.at("layer_quadrature"), "selective");
  EXPECT_NE(selective.id.find("-selective"), std::string::npos) << selective.id;  // two scenes, two ids
  EXPECT_EQ(rule.id.find("-selective"), std::string::npos) << rule.id;
  EXPECT_EQ(rule.id.find("-full"), std::string::npos) << rule.id;  // the rule's choice needs no mark
}

}  // namespace
}  // namespace thinlayer
