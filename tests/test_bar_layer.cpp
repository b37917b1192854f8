// The bar's thin-layer mode (SPEC §2.1): a floating layer under AD held only by
// Signorini-Coulomb contact on both faces. Work in progress for the thin-layer issue: these
// tests pin down what already works.
#include <gtest/gtest.h>

#include "core/io/reference_tables.h"
#include "cases/bar/bar_scenes.h"

namespace thinlayer {
namespace {

// At ε = 1e-4 the layer with λ_ε = ε λ̄, μ_ε = ε μ̄ must behave like the limit law: same
// combined gap/slide/stick counts as the limit mode's baseline, on every row.
TEST(BarLayer, ThinLayerReproducesTheLimitCounts) {
  const auto paper = load_table3_paper();
  const auto baseline = load_table3_baseline();
  for (int row : {1, 2, 3, 4, 5, 6}) {
    SCOPED_TRACE("row " + std::to_string(row));
    const BarLayerScene s = solve_bar_layer(bar::MeshOptions{}, paper[row - 1].lambda_bar, paper[row - 1].mu_bar, 1e-4,
                                            "table3-row-" + std::to_string(row), SolverKind::Fast, SolverOptions{});
    ASSERT_TRUE(s.report.converged) << s.report.message;
    EXPECT_EQ((StatusCount{s.counts.combined.gap, s.counts.combined.slide, s.counts.combined.stick}), baseline[row - 1]);
    // The record has both faces and the combined statuses.
    ASSERT_EQ(s.record.interfaces.size(), 2u);
    EXPECT_EQ(s.record.interfaces[0].name, "S+");
    EXPECT_EQ(s.record.interfaces[1].name, "S-");
    EXPECT_EQ(s.record.combined_status.size(), 32u);
  }
}

// Issue 26, item 7: the documented thickest layer (bar::thickest_layer, 1 mm) works on every row,
// with 2 and 4 elements through it. Before the selection spring was floored against the layer's
// own stiffness, rows 1, 2 and 4 ended "not positive definite" from 1 mm up.
TEST(BarLayer, EveryRowConvergesAtTheThickestDocumentedLayer) {
  const auto paper = load_table3_paper();
  for (int row : {1, 2, 3, 4, 5, 6})
    for (int across : {2, 4}) {
      SCOPED_TRACE("row " + std::to_string(row) + ", " + std::to_string(across) + " across");
      const BarLayerScene s =
          solve_bar_layer(bar::MeshOptions{}, paper[row - 1].lambda_bar, paper[row - 1].mu_bar, bar::thickest_layer,
                          "table3-row-" + std::to_string(row), SolverKind::Fast, SolverOptions{},
                          default_status_tolerance, across);
      EXPECT_TRUE(s.report.converged) << s.report.message << ", residual " << s.report.residual.value();
    }
}

TEST(BarLayer, LayerModeRejectsBadThickness) {
  for (double eps : {0.0, -1e-3, std::nan("")})
    EXPECT_THROW(solve_bar_layer(bar::MeshOptions{}, 450, 540, eps, "x", SolverKind::Fast, SolverOptions{}),
                 std::invalid_argument);
}

}  // namespace
}  // namespace thinlayer
