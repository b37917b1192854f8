// SPEC §1.5, film admissibility: every layer scene says how far its film slid (in elements along
// S) and how much it strained, and the answer that strays outside the model's assumptions is
// flagged (cases/film_admissibility.h).
#include <gtest/gtest.h>

#include "cases/bar/bar_scenes.h"
#include "cases/film_admissibility.h"
#include "core/io/reference_tables.h"

namespace thinlayer {
namespace {

BarLayerScene bar_row(int row, double eps) {
  const Table3Row r = load_table3_paper().at(row - 1);
  return solve_bar_layer({}, r.lambda_bar, r.mu_bar, eps, "table3-row-" + std::to_string(row), SolverKind::Fast, {});
}

TEST(FilmAdmissibility, TheBarsRow5FilmSlidesAlongTheBar) {
  // SPEC §1.5: "on the bar (row 5, ε = 1e-4) a film end slides 70 mm along a 40 mm bar"; the
  // bar's elements along AD are 40/32 = 1.25 mm.
  const BarLayerScene s = bar_row(5, 1e-4);
  ASSERT_TRUE(s.report.converged) << s.report.message;
  const FilmAdmissibility film = film_admissibility(s.record);
  EXPECT_NEAR(film.slip_over_h * 1.25, 70.0, 2.0);
  EXPECT_FALSE(film.admissible());
  EXPECT_DOUBLE_EQ(s.record.numbers.at("film_slip_over_h"), film.slip_over_h);
  EXPECT_DOUBLE_EQ(s.record.numbers.at("film_strain_max"), film.strain_max);
  EXPECT_NE(film_warning(s.record).find("slid"), std::string::npos);
}

TEST(FilmAdmissibility, APinchedLayerStaysWithinOneElement) {
  // Row 1's layer is a million times stiffer than the bar and pinched under it: the bar slides on
  // it by a hundredth of an element (0.011 measured), the film stays put.
  const BarLayerScene s = bar_row(1, 1e-3);
  ASSERT_TRUE(s.report.converged) << s.report.message;
  const FilmAdmissibility film = film_admissibility(s.record);
  EXPECT_LT(film.slip_over_h, film_slip_warning);
  EXPECT_LT(film.strain_max, 1e-2);
  EXPECT_TRUE(film.admissible());
  EXPECT_EQ(film_warning(s.record), "");
}

TEST(FilmAdmissibility, TheLargestSlipIsTheLargestTangentialJumpOverItsElement) {
  const BarLayerScene s = bar_row(3, 1e-4);
  double largest = 0;
  for (const InterfaceFields& f : s.record.interfaces)
    for (Eigen::Index k = 1; k + 1 < f.jump_T.size(); ++k)  // interior nodes: uniform elements of 1.25 mm
      largest = std::max(largest, std::abs(f.jump_T[k]) / 1.25);
  EXPECT_GE(film_admissibility(s.record).slip_over_h, largest * (1 - 1e-12));
}

TEST(FilmAdmissibility, TheWarningNamesOnlyTheAssumptionBroken) {
  FilmAdmissibility strained;  // a glue line strained 2.4 % that did not slide (a scarf joint under 100 MPa)
  strained.slip_over_h = 5e-17;
  strained.strain_max = 0.024;
  EXPECT_NE(film_warning(strained).find("largest strain is 0.024"), std::string::npos) << film_warning(strained);
  EXPECT_EQ(film_warning(strained).find("slid"), std::string::npos) << film_warning(strained);
  FilmAdmissibility slid;  // a film that slid three elements, barely strained
  slid.slip_over_h = 3;
  slid.slip_where = "S+ node 4";
  slid.strain_max = 1e-4;
  EXPECT_NE(film_warning(slid).find("slid 3 elements along S (S+ node 4"), std::string::npos) << film_warning(slid);
  EXPECT_EQ(film_warning(slid).find("strain"), std::string::npos) << film_warning(slid);
  FilmAdmissibility both = slid;
  both.strain_max = 0.5;
  EXPECT_NE(film_warning(both).find("slid 3 elements"), std::string::npos);
  EXPECT_NE(film_warning(both).find("and its largest strain is 0.5"), std::string::npos);
}

}  // namespace
}  // namespace thinlayer
