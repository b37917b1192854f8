// Regression of Table 3 (SPEC §2.1.1): both solvers reproduce the project's baseline counts
// (reference/table3_baseline.csv) exactly on the default bar model. The baseline is backed by
// the agreement of two independent solvers, and is not the paper's table (see the study).
#include <gtest/gtest.h>

#include "core/io/reference_tables.h"
#include "cases/bar/bar_scenes.h"

namespace thinlayer {
namespace {

TEST(Table3Baseline, BothSolversReproduceTheBaselineOnEveryRow) {
  const auto paper = load_table3_paper();
  const auto baseline = load_table3_baseline();
  ASSERT_EQ(paper.size(), 6u);
  ASSERT_EQ(baseline.size(), 6u);
  BarBulk bulk(bar::MeshOptions{});
  for (size_t i = 0; i < paper.size(); ++i) {
    SCOPED_TRACE("row " + std::to_string(paper[i].row));
    const InterfaceLaw law = InterfaceLaw::make(paper[i].lambda_bar, paper[i].mu_bar, bar::friction);
    for (SolverKind solver : {SolverKind::Fast, SolverKind::Relaxation}) {
      const BarScene s = solve_bar(bulk, law, "table3-row-" + std::to_string(paper[i].row), solver, SolverOptions{});
      ASSERT_TRUE(s.report.converged) << s.report.message;
      EXPECT_EQ(s.counts.gap + s.counts.slide + s.counts.stick, 32);
      EXPECT_EQ(s.counts.gap, baseline[i].gap) << to_string(solver);
      EXPECT_EQ(s.counts.slide, baseline[i].slide) << to_string(solver);
      EXPECT_EQ(s.counts.stick, baseline[i].stick) << to_string(solver);
    }
  }
}

TEST(Table3Baseline, StatusesAreNotOnAKnifeEdge) {
  // The baseline counts must not hinge on the classification tolerance: the same counts come
  // out with a tolerance 100 times looser and 100 times tighter.
  const auto paper = load_table3_paper();
  const auto baseline = load_table3_baseline();
  BarBulk bulk(bar::MeshOptions{});
  for (size_t i = 0; i < paper.size(); ++i) {
    const InterfaceLaw law = InterfaceLaw::make(paper[i].lambda_bar, paper[i].mu_bar, bar::friction);
    for (double tol : {1e-4, 1e-8}) {
      const BarScene s = solve_bar(bulk, law, "row", SolverKind::Fast, SolverOptions{}, tol);
      EXPECT_EQ((StatusCount{s.counts.gap, s.counts.slide, s.counts.stick}), baseline[i])
          << "row " << paper[i].row << ", tolerance " << tol;
    }
  }
}

}  // namespace
}  // namespace thinlayer
