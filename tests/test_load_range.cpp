// Loads outside the model's range (SPEC 1.5 small strain; cases/answer_admissibility.h), through the
// command line, on the shipped single lap (cases/single_lap) edited here:
//  - in aluminium (E 70000 MPa, 1 mm sheets) pulled by 30 000 N/mm: the membrane strain alone is
//    30000 / (70000 x 1) = 0.43, far beyond small strain (1e-2): warned with its number; the
//    supports are fine (the clamp holds, the grip is held in y): no "a support left free?". At
//    100 N/mm the membrane strain is 1.4e-3: no strain warning;
//  - a 3 mm glue on the 12.5 mm overlap: layer mode refuses it as not thin (at most a tenth of the
//    bondline, 1.25 mm), and limit mode by the same rule, with the same bound: exit 2, one line.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "tests/cli_in_folder.h"
#include "tests/edited_case.h"

namespace {

std::string lap_with(const SceneFolder& f, const std::vector<std::pair<std::string, std::string>>& edits) {
  return edited_case(f, "single_lap", edits);
}

std::string aluminium_pulled(const SceneFolder& f, double force) {
  return lap_with(f, {{"\"E\": 210000, \"nu\": 0.3}", "\"E\": 70000, \"nu\": 0.33}"},
                      {"\"E\": 210000, \"nu\": 0.3}", "\"E\": 70000, \"nu\": 0.33}"},
                      {"\"supports\": [{\"group\": \"clamp\", \"u\": [0, 0]}, {\"group\": \"grip\", \"u\": [0.01, 0]}]",
                       "\"supports\": [{\"group\": \"clamp\", \"u\": [0, 0]}, {\"group\": \"grip\", \"u\": [null, 0]}],\n"
                       "  \"loads\": [{\"group\": \"grip\", \"force\": [" + full_digits(force) + ", 0]}]"}});
}

}  // namespace

TEST(LoadRange, ANonsenseLoadIsWarnedAsBeyondSmallStrainNotAsAFreeSupport) {
  SceneFolder f;
  std::string err;
  EXPECT_EQ(run_cli("solve --scene " + aluminium_pulled(f, 30000), f, err), 0) << err;
  const std::size_t at = err.find("beyond small strain");
  ASSERT_NE(at, std::string::npos) << err;
  // The number: the adherent's largest principal strain, at least the membrane strain 0.43.
  const std::size_t strains = err.rfind("strains ", at);
  ASSERT_NE(strains, std::string::npos) << err;
  EXPECT_GE(std::stod(err.substr(strains + 8)), 0.43) << err;
  EXPECT_EQ(err.find("support left free"), std::string::npos) << err;
}

TEST(LoadRange, AnOrdinaryLoadIsNotWarned) {
  SceneFolder f;
  std::string err;
  EXPECT_EQ(run_cli("solve --scene " + aluminium_pulled(f, 100), f, err), 0) << err;
  EXPECT_EQ(err.find("small strain"), std::string::npos) << err;
  EXPECT_EQ(err.find("support left free"), std::string::npos) << err;
}

TEST(LoadRange, LimitModeRefusesAGlueTooThickByLayerModesRule) {
  SceneFolder f;
  const std::string scene = lap_with(f, {{"\"thickness\": 0.5", "\"thickness\": 3"}});
  for (const std::string mode : {"layer", "limit"}) {
    std::string err;
    EXPECT_EQ(run_cli("solve --scene " + scene + " --mode " + mode, f, err), 2) << mode << ": " << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find("at most 1.25 mm"), std::string::npos) << mode << ": " << err;  // 12.5 mm / 10, by hand
  }
}
