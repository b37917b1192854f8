// `thinlayer verify`: a failing check shows as failing in all three outputs (summary.json,
// results.h5, the HTML report) and makes the exit status non-zero; an unwritable DIR is an
// error before any work. A reduced run (--quick, case d at three thicknesses) keeps it short.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/io/h5_reader.h"
#include "tests/text_file.h"

namespace {

namespace fs = std::filesystem;

struct Verify : ::testing::Test {
  fs::path dir = fs::temp_directory_path() / ("thinlayer-verify-" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }

  // Runs verify with the given reference directory; returns the exit status.
  int run(const fs::path& reference, const fs::path& out) {
    const std::string command = "THINLAYER_REFERENCE_DIR=" + reference.string() + " " + THINLAYER_CLI +
                                " verify --quick --quiet --repeats 1 --cases d --eps 1e-2,5e-3,1e-3 --rate-eps 1e-3,3e-4,1e-4 --out " +
                                out.string() + " >" + (dir / "stdout").string() + " 2>" + (dir / "stderr").string();
    const int raw = std::system(command.c_str());
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  }
};

TEST_F(Verify, AWrongReferenceValueFailsInAllThreeOutputs) {
  // A copy of reference/ whose Table 3 baseline claims a wrong count for row 1.
  const fs::path reference = dir / "reference";
  fs::copy(THINLAYER_REFERENCE_DIR, reference);
  {
    std::string csv = read_text_file(reference / "table3_baseline.csv");
    const size_t at = csv.find("\n1,3,14,15");
    ASSERT_NE(at, std::string::npos);
    csv.replace(at, 10, "\n1,4,13,15");
    std::ofstream(reference / "table3_baseline.csv") << csv;
  }
  const fs::path out = dir / "out";
  const int status = run(reference, out);
  EXPECT_EQ(status, 1) << read_text_file(dir / "stderr");

  const std::string id = "table3.row1.fast.baseline";
  const std::string json = read_text_file(out / "summary.json");
  const size_t entry = json.find("\"" + id + "\"");
  ASSERT_NE(entry, std::string::npos) << json.substr(0, 400);
  const size_t pass = json.find("\"pass\"", entry);
  ASSERT_NE(pass, std::string::npos);
  EXPECT_EQ(json.substr(pass, 13), "\"pass\": false") << json.substr(entry, 200);

  const thinlayer::H5Reader h5((out / "results.h5").string());
  const auto ids = h5.read_strings("/checks/id");
  const auto passed = h5.read_ints("/checks/pass");
  ASSERT_EQ(ids.size(), passed.size());
  bool found = false;
  for (size_t i = 0; i < ids.size(); ++i)
    if (ids[i] == id) {
      found = true;
      EXPECT_EQ(passed[i], 0);
    }
  EXPECT_TRUE(found);

  // Every study of the run is in the file: S2's distances and rates, S3's table, S4's crossings, S5.
  EXPECT_EQ(h5.read_doubles("/studies/convergence/d/e_u_away").size(), 3u);
  EXPECT_EQ(h5.read_doubles("/studies/convergence/d/cauchy/d_R_top").size(), 2u);  // 3 thicknesses of --rate-eps
  const auto validity = h5.read_strings("/studies/validity/status");
  const auto tau = h5.read_doubles("/studies/validity/tau");
  const auto eps_max = h5.read_doubles("/studies/validity/eps_max");
  const auto eps_beyond = h5.read_doubles("/studies/validity/eps_beyond");
  const auto error = h5.read_doubles("/studies/validity/error_at_eps_max");
  ASSERT_EQ(validity.size(), 8u);  // case d × {u, R_top, sigma_N, sigma_T} × τ ∈ {1 %, 5 %}
  for (size_t i = 0; i < validity.size(); ++i) {
    EXPECT_TRUE(validity[i] == "found" || validity[i] == "at_least" || validity[i] == "below_range") << validity[i];
    if (validity[i] != "below_range") {
      EXPECT_LE(error[i], tau[i]);
    }
    if (validity[i] == "found") {
      EXPECT_LT(eps_max[i], eps_beyond[i]);
    }
  }
  EXPECT_TRUE(h5.exists("/studies/thresholds/crossings/ratio"));
  EXPECT_TRUE(h5.exists("/studies/timing/time_s"));
  EXPECT_TRUE(h5.exists("/environment"));

  const std::string html = read_text_file(out / "report" / "index.html");
  // Every check: the same verdict in summary.json, in /checks and in every report row that
  // shows it (a row is `<td class="l">ID</td><td><span class="pass|fail">`).
  for (size_t i = 0; i < ids.size(); ++i) {
    SCOPED_TRACE(ids[i]);
    const size_t in_json = json.find("\"id\": \"" + ids[i] + "\"");
    ASSERT_NE(in_json, std::string::npos);
    EXPECT_EQ(json.substr(json.find("\"pass\": ", in_json), 13) == "\"pass\": true,", passed[i] == 1);
    const std::string cell = "<td class=\"l\">" + ids[i] + "</td><td><span class=\"";
    int rows = 0;
    for (size_t at = html.find(cell); at != std::string::npos; at = html.find(cell, at + 1)) {
      ++rows;
      EXPECT_EQ(html.substr(at + cell.size(), 4), passed[i] ? "pass" : "fail");
    }
    EXPECT_GE(rows, 1);
  }
  const size_t row = html.find(id);
  ASSERT_NE(row, std::string::npos);
  EXPECT_NE(html.find("FAIL", row), std::string::npos);
  EXPECT_NE(read_text_file(dir / "stdout").find("FAIL " + id), std::string::npos);
}

TEST_F(Verify, UnwritableDirIsAnErrorAndWritesNothing) {
  const int status = run(THINLAYER_REFERENCE_DIR, "/proc/thinlayer-cannot-write-here");
  EXPECT_EQ(status, 2);
  const std::string err = read_text_file(dir / "stderr");
  EXPECT_NE(err.find("thinlayer verify: "), std::string::npos) << err;
  EXPECT_FALSE(fs::exists("/proc/thinlayer-cannot-write-here"));
}

}  // namespace
