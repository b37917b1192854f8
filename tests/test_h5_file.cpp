// H5Writer / H5Reader: round trips, all-or-nothing output, error messages, and what h5py sees.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <hdf5.h>

#include "core/io/column_table.h"
#include "core/io/h5_reader.h"
#include "core/io/h5_writer.h"

namespace thinlayer {
namespace {

namespace fs = std::filesystem;

// Each test gets its own empty directory, so "no file left behind" can be checked by listing it.
class H5File : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("thinlayer_h5_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename());
    return names;
  }

  fs::path dir_;
};

// Runs `call`, expecting a std::runtime_error, and returns its message.
template <typename Call>
std::string error_of(Call call) {
  try {
    call();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no std::runtime_error thrown";
  return "";
}

TEST_F(H5File, AttributesRoundTrip) {
  const std::string path = file("attrs.h5");
  {
    H5Writer w(path);
    w.attr("/", "pi", 3.141592653589793);
    w.attr("/", "nan", std::numeric_limits<double>::quiet_NaN());
    w.attr("/", "count", 42);
    w.attr("/", "big", 1LL << 40);
    w.attr("/", "size", std::size_t{7});
    w.attr("/", "negative", -3L);
    w.attr("/", "label", std::string("σ_xx in µm"));
    w.attr("/", "literal", "plain");
    w.attr("/", "empty", std::string());
    w.attr("/a/b/c", "depth", 3);  // the groups are created
    w.dataset("/data", std::vector<double>{1.0});
    w.attr("/data", "unit", "mm");  // on an existing dataset
    w.commit();
  }
  H5Reader r(path);
  EXPECT_EQ(r.attr_double("/", "pi"), 3.141592653589793);
  EXPECT_TRUE(std::isnan(r.attr_double("/", "nan")));
  EXPECT_EQ(r.attr_int("/", "count"), 42);
  EXPECT_EQ(r.attr_double("/", "count"), 42.0);  // integers may be read as doubles
  EXPECT_EQ(r.attr_int("/", "big"), 1LL << 40);
  EXPECT_EQ(r.attr_int("/", "size"), 7);
  EXPECT_EQ(r.attr_int("/", "negative"), -3);
  EXPECT_EQ(r.attr_string("/", "label"), "σ_xx in µm");
  EXPECT_EQ(r.attr_string("/", "literal"), "plain");
  EXPECT_EQ(r.attr_string("/", "empty"), "");
  EXPECT_EQ(r.attr_int("/a/b/c", "depth"), 3);
  EXPECT_EQ(r.attr_int("a/b/c", "depth"), 3);  // relative paths start at the root
  EXPECT_EQ(r.attr_string("/data", "unit"), "mm");
}

TEST_F(H5File, DatasetsRoundTripWithShape) {
  const std::string path = file("data.h5");
  H5Writer::RowMatrixXd nodes(3, 2);
  nodes << 0.0, 0.5, 1.0, 1.5, 2.0, std::numeric_limits<double>::infinity();
  H5Writer::RowMatrixXi cells(2, 3);
  cells << 0, 1, 2, 2, 1, -7;
  Eigen::MatrixXd col_major(2, 3);  // converted to row-major by the Ref
  col_major << 1, 2, 3, 4, 5, 6;
  H5Writer::RowMatrixXd wide = H5Writer::RowMatrixXd::Zero(4, 5);
  wide.block(1, 1, 2, 2) << 11, 12, 21, 22;
  const double raw[] = {1, 2, 3, 4, 5, 6};
  const int raw_ints[] = {1, 2, 3, 4, 5, 6};
  {
    H5Writer w(path);
    w.dataset("/mesh/nodes", nodes);
    w.dataset("/mesh/cells", cells);
    w.dataset("/col_major", col_major);
    w.dataset("/block", wide.block(1, 1, 2, 2));  // rows not adjacent in memory
    w.dataset("/raw", raw, 3, 2);
    w.dataset("/raw_ints", raw_ints, 2, 3);
    w.dataset("/deep/er/vector", std::vector<double>{0.25, -1.0});
    w.dataset("/ints", std::vector<int>{3, -1, 4});
    w.dataset("/names", std::vector<std::string>{"top", "σ", ""});
    w.dataset("/none", std::vector<double>{});
    w.dataset("/no_rows", H5Writer::RowMatrixXd(0, 2));
    w.commit();
  }
  H5Reader r(path);
  std::vector<std::size_t> shape;
  EXPECT_EQ(r.read_doubles("/mesh/nodes", &shape),
            (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0, std::numeric_limits<double>::infinity()}));
  EXPECT_EQ(shape, (std::vector<std::size_t>{3, 2}));
  EXPECT_EQ(r.read_ints("/mesh/cells", &shape), (std::vector<long long>{0, 1, 2, 2, 1, -7}));
  EXPECT_EQ(shape, (std::vector<std::size_t>{2, 3}));
  EXPECT_EQ(r.read_doubles("/col_major", &shape), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(shape, (std::vector<std::size_t>{2, 3}));
  EXPECT_EQ(r.read_doubles("/block", &shape), (std::vector<double>{11, 12, 21, 22}));
  EXPECT_EQ(shape, (std::vector<std::size_t>{2, 2}));
  EXPECT_EQ(r.read_doubles("/raw", &shape), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(shape, (std::vector<std::size_t>{3, 2}));
  EXPECT_EQ(r.read_ints("/raw_ints", &shape), (std::vector<long long>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(shape, (std::vector<std::size_t>{2, 3}));
  EXPECT_EQ(r.read_doubles("/deep/er/vector", &shape), (std::vector<double>{0.25, -1.0}));
  EXPECT_EQ(shape, (std::vector<std::size_t>{2}));
  EXPECT_EQ(r.read_ints("/ints", &shape), (std::vector<long long>{3, -1, 4}));
  EXPECT_EQ(shape, (std::vector<std::size_t>{3}));
  EXPECT_EQ(r.read_doubles("/ints"), (std::vector<double>{3, -1, 4}));
  EXPECT_EQ(r.read_strings("/names", &shape), (std::vector<std::string>{"top", "σ", ""}));
  EXPECT_EQ(shape, (std::vector<std::size_t>{3}));
  EXPECT_TRUE(r.read_doubles("/none", &shape).empty());
  EXPECT_EQ(shape, (std::vector<std::size_t>{0}));
  EXPECT_TRUE(r.read_doubles("/no_rows", &shape).empty());
  EXPECT_EQ(shape, (std::vector<std::size_t>{0, 2}));
}

TEST_F(H5File, NestedGroupsAndChildren) {
  const std::string path = file("groups.h5");
  {
    H5Writer w(path);
    w.group("/study/case_b/level_2");
    w.group("/study/case_b/level_2");  // creating an existing group is fine
    w.group("study/case_a");
    w.dataset("/study/values", std::vector<int>{1});
    w.commit();
  }
  H5Reader r(path);
  EXPECT_TRUE(r.exists("/"));
  EXPECT_TRUE(r.exists("/study/case_b/level_2"));
  EXPECT_TRUE(r.exists("/study/values"));
  EXPECT_FALSE(r.exists("/study/case_c"));
  EXPECT_FALSE(r.exists("/missing/deeper/still"));
  EXPECT_FALSE(r.exists("/study/values/inside_a_dataset"));
  EXPECT_EQ(r.children("/"), (std::vector<std::string>{"study"}));
  EXPECT_EQ(r.children("/study"), (std::vector<std::string>{"case_a", "case_b", "values"}));
  EXPECT_TRUE(r.children("/study/case_a").empty());
}

TEST_F(H5File, DuplicatesAndWrongKindsThrowNamingTheObject) {
  H5Writer w(file("dup.h5"));
  w.dataset("/x", std::vector<double>{1.0});
  w.attr("/", "a", 1.0);
  EXPECT_NE(error_of([&] { w.dataset("/x", std::vector<double>{2.0}); }).find("'/x'"),
            std::string::npos);
  EXPECT_NE(error_of([&] { w.attr("/", "a", 2.0); }).find("'a'"), std::string::npos);
  EXPECT_NE(error_of([&] { w.group("/x"); }).find("not a group"), std::string::npos);
  EXPECT_NE(error_of([&] { w.dataset("/x/y", std::vector<int>{}); }).find("'/x'"),
            std::string::npos);
  EXPECT_NE(error_of([&] { w.attr("/", "nul", std::string("a\0b", 3)); }).find("NUL"),
            std::string::npos);
}

// HDF5 prints its error stack to stderr unless told not to; each class must tell it.
TEST_F(H5File, NothingIsPrintedToStderrOnFailure) {
  const auto print_errors_again = [] {  // earlier tests have already turned printing off
    H5Eset_auto2(H5E_DEFAULT, reinterpret_cast<H5E_auto2_t>(H5Eprint2), stderr);
  };
  print_errors_again();
  H5Writer w(file("quiet.h5"));
  ::testing::internal::CaptureStderr();
  error_of([&] { w.attr("/", "", 1); });  // rejected by HDF5 itself
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  w.commit();

  print_errors_again();
  H5Reader r(file("quiet.h5"));
  ::testing::internal::CaptureStderr();
  error_of([&] { r.read_doubles("/missing"); });
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
}

TEST_F(H5File, TargetAppearsOnlyOnCommit) {
  const std::string path = file("result.h5");
  H5Writer w(path);
  w.dataset("/x", std::vector<double>{1.0, 2.0});
  EXPECT_FALSE(fs::exists(path));
  ASSERT_EQ(listing().size(), 1u);  // just the temporary file
  EXPECT_NE(listing()[0].find("result.h5.tmp."), std::string::npos);
  w.commit();
  EXPECT_EQ(listing(), (std::vector<std::string>{"result.h5"}));
  EXPECT_EQ(H5Reader(path).read_doubles("/x"), (std::vector<double>{1.0, 2.0}));
  EXPECT_NE(error_of([&] { w.attr("/", "late", 1); }).find("committed"), std::string::npos);
}

TEST_F(H5File, CommitReplacesAnOldTargetOnlyAtTheEnd) {
  const std::string path = file("result.h5");
  {
    H5Writer w(path);
    w.attr("/", "version", 1);
    w.commit();
  }
  H5Writer w(path);
  w.attr("/", "version", 2);
  EXPECT_EQ(H5Reader(path).attr_int("/", "version"), 1);
  w.commit();
  EXPECT_EQ(H5Reader(path).attr_int("/", "version"), 2);
  EXPECT_EQ(listing(), (std::vector<std::string>{"result.h5"}));
}

TEST_F(H5File, WriterDestroyedWithoutCommitLeavesNoFile) {
  {
    H5Writer w(file("abandoned.h5"));
    w.dataset("/x", std::vector<double>{1.0});
  }
  EXPECT_TRUE(listing().empty());
  try {
    H5Writer w(file("unwound.h5"));
    w.dataset("/x", std::vector<double>{1.0});
    throw std::logic_error("solver failed");
  } catch (const std::logic_error&) {
  }
  EXPECT_TRUE(listing().empty());
}

TEST_F(H5File, UnwritableTargetThrowsNamingThePathAndCreatesNothing) {
  const std::string message = error_of([] { H5Writer w("/nonexistent-dir/x.h5"); });
  EXPECT_NE(message.find("'/nonexistent-dir/x.h5'"), std::string::npos) << message;
  EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists("/nonexistent-dir"));

  const std::string nested = file("missing/x.h5");
  EXPECT_NE(error_of([&] { H5Writer w(nested); }).find(nested), std::string::npos);
  EXPECT_NE(error_of([&] { H5Writer w(dir_.string()); }).find("Is a directory"),
            std::string::npos);
  EXPECT_TRUE(listing().empty());
}

TEST_F(H5File, ReadOnlyDirectoryThrows) {
  if (::geteuid() == 0) GTEST_SKIP() << "root can write into read-only directories";
  fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string message = error_of([&] { H5Writer w(file("x.h5")); });
  fs::permissions(dir_, fs::perms::owner_all);
  EXPECT_NE(message.find("Permission denied"), std::string::npos) << message;
  EXPECT_TRUE(listing().empty());
}

TEST_F(H5File, ReaderRejectsMissingAndNonHdf5Files) {
  const std::string missing = file("missing.h5");
  std::string message = error_of([&] { H5Reader r(missing); });
  EXPECT_NE(message.find("'" + missing + "'"), std::string::npos) << message;
  EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;

  const std::string text = file("notes.h5");
  std::ofstream(text) << "not an HDF5 file, just text\n";
  message = error_of([&] { H5Reader r(text); });
  EXPECT_NE(message.find("'" + text + "'"), std::string::npos) << message;
  EXPECT_NE(message.find("not an HDF5 file"), std::string::npos) << message;
}

TEST_F(H5File, ReaderErrorsNameTheObject) {
  const std::string path = file("r.h5");
  {
    H5Writer w(path);
    w.attr("/g", "x", 1.5);
    w.dataset("/g/d", std::vector<double>{1.0});
    w.commit();
  }
  H5Reader r(path);
  EXPECT_NE(error_of([&] { r.read_doubles("/g/missing"); }).find("'/g/missing'"),
            std::string::npos);
  EXPECT_NE(error_of([&] { r.attr_double("/g", "nope"); }).find("'nope'"), std::string::npos);
  EXPECT_NE(error_of([&] { r.attr_int("/g", "x"); }).find("not an integer"), std::string::npos);
  EXPECT_NE(error_of([&] { r.attr_string("/g", "x"); }).find("not a string"), std::string::npos);
  EXPECT_NE(error_of([&] { r.read_ints("/g/d"); }).find("'/g/d'"), std::string::npos);
  EXPECT_NE(error_of([&] { r.children("/g/d"); }).find("'/g/d'"), std::string::npos);
}

// h5py is what the report reads the results with; check what it actually sees.
TEST_F(H5File, H5pyReadsStringsAsStrAndMatricesWithTheirShape) {
  if (std::system("/usr/bin/python3 -c 'import h5py' >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "/usr/bin/python3 cannot import h5py";
  const std::string path = file("py.h5");
  {
    H5Writer w(path);
    H5Writer::RowMatrixXd nodes(4, 2);
    nodes << 0, 1, 2, 3, 4, 5, 6, 7;
    w.attr("/", "case", "dovetail σ");
    w.attr("/mesh", "count", 4);
    w.dataset("/mesh/nodes", nodes);
    w.dataset("/mesh/cells", H5Writer::RowMatrixXi::Constant(3, 4, 1));
    w.dataset("/names", std::vector<std::string>{"a", "β"});
    w.commit();
  }
  const std::string script = file("check.py");
  std::ofstream(script) << R"(import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    case = f["/"].attrs["case"]
    assert isinstance(case, str), type(case)
    assert case == "dovetail σ", repr(case)
    assert f["/mesh"].attrs["count"] == 4 and f["/mesh"].attrs["count"].dtype == "int64"
    nodes = f["/mesh/nodes"]
    assert nodes.shape == (4, 2) and nodes.dtype == "float64", (nodes.shape, nodes.dtype)
    assert nodes[1, 0] == 2.0 and nodes[3, 1] == 7.0
    cells = f["/mesh/cells"]
    assert cells.shape == (3, 4) and cells.dtype == "int32", (cells.shape, cells.dtype)
    assert list(f["/names"].asstr()[()]) == ["a", "β"]
)";
  const int status = std::system(("/usr/bin/python3 " + script + " " + path).c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "h5py check failed";
}

TEST_F(H5File, ColumnTableWritesOneDatasetPerColumn) {
  ColumnTable t;
  for (int i = 0; i < 3; ++i) {
    t.add("name", std::string(1, static_cast<char>('a' + i)));
    t.add("value", 0.5 * i);
    t.add("count", i);
  }
  {
    H5Writer w(file("t.h5"));
    t.write(w, "/studies/x");
    w.commit();
  }
  const H5Reader r(file("t.h5"));
  EXPECT_EQ(r.read_strings("/studies/x/name"), (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(r.read_doubles("/studies/x/value"), (std::vector<double>{0.0, 0.5, 1.0}));
  EXPECT_EQ(r.read_ints("/studies/x/count"), (std::vector<long long>{0, 1, 2}));
}

TEST_F(H5File, ColumnTableRefusesAnIncompleteRow) {
  ColumnTable t;
  t.add("a", 1.0);
  t.add("a", 2.0);
  t.add("b", 1);
  H5Writer w(file("t.h5"));
  EXPECT_THROW(t.write(w, "/x"), std::logic_error);
}

}  // namespace
}  // namespace thinlayer
