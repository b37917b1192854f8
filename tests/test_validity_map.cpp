// The engineer's validity map (SPEC §3 S3, studies/drivers/validity_map.h) on a 2 × 2 grid of the
// shipped double lap, and SPEC §3 S6's estimate on one of its cells.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "cases/scene/scene_spec.h"
#include "core/interface/classifier.h"
#include "studies/drivers/validity_map.h"
#include "studies/drivers/validity_map_output.h"

namespace thinlayer {
namespace {

SceneFileBulk& double_lap() {
  static SceneFileBulk bulk(read_scene_spec(std::string(THINLAYER_CASES_DIR) + "/double_lap/double_lap.json"));
  return bulk;
}

ValidityMapOptions two_by_two() {
  ValidityMapOptions o;
  o.t_over_L = {1e-2, 1e-1};
  o.E_ratio = {1e-3, 1e-1};
  o.nu = {0.45};
  o.verbose = false;
  return o;
}

const ValidityMapResult& map() {
  static const ValidityMapResult r = run_validity_map(double_lap(), two_by_two(), nullptr);
  return r;
}

const MapCell& cell(double t, double E) {
  for (const MapCell& c : map().cells)
    if (c.spec.t_over_L == t && c.spec.E_ratio == E) return c;
  throw std::logic_error("no such cell");
}

// One test: CTest runs each TEST in its own process, and the map takes ~10 s on this machine.
void each_cell_solved_at_both_meshes() {
  const ValidityMapResult& r = map();
  ASSERT_EQ(r.cells.size(), 4u);
  EXPECT_DOUBLE_EQ(r.h_fine, r.h / 2);  // the floor level: half the scene's element size
  for (const MapCell& c : r.cells) {
    EXPECT_TRUE(c.coarse.converged && c.fine.converged) << c.coarse.failure << c.fine.failure;
    EXPECT_NEAR(c.thickness, c.spec.t_over_L * r.L, 1e-15);
    for (const std::string& q : map_quantities()) {
      EXPECT_TRUE(c.fine.measured.count(q) && c.fine.estimate.count(q)) << q;
      EXPECT_TRUE(std::isfinite(c.fine.measured.at(q))) << q;
    }
  }
}

void a_thicker_glue_is_farther_from_its_law() {
  // The finite law's distance to the layer is the first-order terms of the layer's thickness: ten
  // times thicker, about ten times farther, at either stiffness (measured 0.013 % -> 0.13 % and
  // 0.015 % -> 0.14 % on u, 2026-11-27).
  for (double E : {1e-3, 1e-1}) {
    const double thin = cell(1e-2, E).fine.measured.at("u"), thick = cell(1e-1, E).fine.measured.at("u");
    EXPECT_GT(thick / thin, 5.0) << E;
    EXPECT_LT(thick / thin, 20.0) << E;
  }
}

void the_papers_rule_is_the_classification_of_the_glue() {
  // SPEC §1.3's rule on λ_g/t and μ_g/t against λ_m/L and μ_m/L, computed here by hand: the finite law
  // is (d) at every cell; the rule gives 0 or ∞ where a ratio leaves [0.03, 30].
  const ValidityMapResult& r = map();
  const double lambda_m = 70000 * 0.33 / (1.33 * 0.34), mu_m = 70000 / 2.66;  // the aluminium, MPa
  for (const MapCell& c : r.cells) {
    const double E = c.E, nu = c.spec.nu, t = c.thickness;
    const double lambda_g = E * nu / ((1 + nu) * (1 - 2 * nu)), mu_g = E / (2 * (1 + nu));
    auto limit = [](double ratio) { return ratio < 0.03 ? '0' : ratio > 30 ? 'i' : 'f'; };
    const char l = limit((lambda_g / t) / (lambda_m / r.L)), m = limit((mu_g / t) / (mu_m / r.L));
    // Table 1: λ̄ 0 / finite / ∞ × μ̄ 0 / finite / ∞.
    const char expected = m == '0' ? (l == '0' ? 'a' : l == 'f' ? 'c' : 'e')
                        : m == 'f' ? (l == '0' ? 'b' : l == 'f' ? 'd' : 'f')
                                   : (l == '0' ? 'g' : l == 'f' ? 'h' : 'i');
    EXPECT_EQ(c.rule_case, std::string(1, expected) + "," + expected) << c.spec.t_over_L << " " << c.spec.E_ratio;
    EXPECT_EQ(c.law_case, "d,d");
    EXPECT_EQ(c.rule_solved, expected != 'd');
  }
}

void the_estimate_on_one_cell() {
  // SPEC §3 S6 on the cell t/L = 0.1, E_g/E_a = 0.1, ν_g = 0.45 (a 0.14 mm glue of 7000 MPa, the mesh
  // at h/2 = 0.125 resolving its end zone): the estimate from the limit mode alone within a factor 2
  // of the meshed layer on the reactions and the adherents (measured 2026-11-27: 5.7e-4 against
  // 4.8e-4, 1.43e-3 against 1.41e-3).
  const MapCell& c = cell(1e-1, 1e-1);
  for (const std::string q : {"reactions", "u"}) {
    const MapJudgement j = judge(c, q, 2);
    EXPECT_TRUE(j.converged && j.resolved && j.ends_resolved) << q;
    EXPECT_TRUE(j.within) << q << ": estimate " << j.estimate << ", measured " << j.measured;
  }
}

void the_csv_has_a_row_per_cell() {
  std::istringstream csv(validity_map_csv(map(), two_by_two()));
  int rows = 0;
  for (std::string line; std::getline(csv, line);)
    if (!line.empty() && line[0] != '#') ++rows;
  EXPECT_EQ(rows, 1 + 4);  // the header and the cells
}

TEST(ValidityMap, TwoByTwoOnTheDoubleLap) {
  each_cell_solved_at_both_meshes();
  a_thicker_glue_is_farther_from_its_law();
  the_papers_rule_is_the_classification_of_the_glue();
  the_estimate_on_one_cell();
  the_csv_has_a_row_per_cell();
}

}  // namespace
}  // namespace thinlayer
