// Reference data: the small CSV reader (core/io/csv_table.h) and the loaders of the paper's
// tables and the project's baseline (core/io/reference_tables.h).
//
// Expected contents come from SPEC §2.1 (Table 3 as printed there, typed into this file), not
// from the code under test; reader behaviour is checked on small files written by the tests.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/io/csv_table.h"
#include "core/io/reference_tables.h"

namespace thinlayer {
namespace {

namespace fs = std::filesystem;

// A fresh directory for one test, removed afterwards.
class TempDir {
 public:
  TempDir() {
    static int counter = 0;
    path_ = fs::temp_directory_path() /
            ("thinlayer_test_reference_tables_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::string write(const std::string& name, const std::string& content) const {
    const fs::path file = path_ / name;
    std::ofstream(file) << content;
    return file.string();
  }
  std::string str() const { return path_.string(); }

 private:
  fs::path path_;
};

// Sets (or unsets, with nullopt) an environment variable for the scope, then restores it.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value)
      ::setenv(name, value->c_str(), 1);
    else
      ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// The message of the std::runtime_error that f throws ("" and a test failure if none).
template <class F>
std::string runtime_error_message(F&& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected std::runtime_error, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected std::runtime_error, nothing thrown";
  return "";
}

// ---------------------------------------------------------------------------------------------
// CsvTable.

TEST(CsvTable, SkipsCommentsAndBlankLines) {
  const TempDir dir;
  const std::string path = dir.write("t.csv",
                                     "# a comment before the header\n"
                                     "\n"
                                     "name,value\n"
                                     "# a comment between rows\n"
                                     "alpha,1.5\n"
                                     "   \t\n"
                                     "\n"
                                     "beta,-2e3\n"
                                     "# trailing comment\n");
  const CsvTable t = CsvTable::read(path);
  ASSERT_EQ(t.rows(), 2);
  EXPECT_EQ(t.text(0, "name"), "alpha");
  EXPECT_EQ(t.number(0, "value"), 1.5);
  EXPECT_EQ(t.text(1, "name"), "beta");
  EXPECT_EQ(t.number(1, "value"), -2000.0);
  EXPECT_EQ(t.path(), path);
}

TEST(CsvTable, TrimsSpacesAndCarriageReturns) {
  const TempDir dir;
  const CsvTable t = CsvTable::read(dir.write("t.csv", "a , b\r\n  x ,  2.5 \r\n"));
  ASSERT_EQ(t.rows(), 1);
  EXPECT_EQ(t.text(0, "a"), "x");
  EXPECT_EQ(t.number(0, "b"), 2.5);
}

TEST(CsvTable, WrongFieldCountThrowsWithFileAndLine) {
  const TempDir dir;
  // The bad row is physical line 5 (comment and blank lines count).
  const std::string path = dir.write("bad.csv",
                                     "# comment\n"
                                     "a,b,c\n"
                                     "1,2,3\n"
                                     "\n"
                                     "4,5\n"
                                     "6,7,8\n");
  const std::string message = runtime_error_message([&] { CsvTable::read(path); });
  EXPECT_NE(message.find(path + ":5"), std::string::npos) << message;
}

TEST(CsvTable, TooManyFieldsThrowsWithFileAndLine) {
  const TempDir dir;
  const std::string path = dir.write("bad.csv", "a,b\n1,2\n3,4,5\n");
  const std::string message = runtime_error_message([&] { CsvTable::read(path); });
  EXPECT_NE(message.find(path + ":3"), std::string::npos) << message;
}

TEST(CsvTable, NonNumberThrowsNamingTheColumn) {
  const TempDir dir;
  const CsvTable t = CsvTable::read(dir.write("t.csv", "x,y,z,w\n1.5x,abc,,7\n"));
  const std::string message = runtime_error_message([&] { t.number(0, "x"); });
  EXPECT_NE(message.find("'x'"), std::string::npos) << message;
  EXPECT_NE(message.find(t.path()), std::string::npos) << message;
  EXPECT_THROW(t.number(0, "y"), std::runtime_error);
  EXPECT_THROW(t.number(0, "z"), std::runtime_error);  // empty field
  EXPECT_EQ(t.number(0, "w"), 7.0);
}

// "a,b," has three fields, the last one empty (RFC 4180; the header says fields are separated
// by commas): a row ending in a comma must match a three-column header, and its last field
// reads as "".
TEST(CsvTable, EmptyLastFieldIsAField) {
  const TempDir dir;
  const std::string path = dir.write("t.csv", "x,y,z\n1,2,\n");
  try {
    const CsvTable t = CsvTable::read(path);
    ASSERT_EQ(t.rows(), 1);
    EXPECT_EQ(t.text(0, "z"), "");
    EXPECT_THROW(t.number(0, "z"), std::runtime_error);
  } catch (const std::exception& e) {
    FAIL() << "row '1,2,' rejected: " << e.what();
  }
}

TEST(CsvTable, NonIntegerThrows) {
  const TempDir dir;
  const CsvTable t = CsvTable::read(dir.write("t.csv", "n,m\n2.5,32\n"));
  EXPECT_THROW(t.integer(0, "n"), std::runtime_error);
  EXPECT_EQ(t.integer(0, "m"), 32);
}

TEST(CsvTable, MissingFileThrowsNamingIt) {
  const TempDir dir;
  const std::string path = dir.str() + "/does_not_exist.csv";
  const std::string message = runtime_error_message([&] { CsvTable::read(path); });
  EXPECT_NE(message.find(path), std::string::npos) << message;
}

TEST(CsvTable, FileWithoutHeaderThrows) {
  const TempDir dir;
  const std::string path = dir.write("empty.csv", "# only a comment\n\n");
  EXPECT_THROW(CsvTable::read(path), std::runtime_error);
}

TEST(CsvTable, MissingColumnAndRowThrow) {
  const TempDir dir;
  const CsvTable t = CsvTable::read(dir.write("t.csv", "a\n1\n"));
  EXPECT_THROW(t.text(0, "b"), std::runtime_error);
  EXPECT_THROW(t.text(1, "a"), std::out_of_range);
  EXPECT_THROW(t.text(-1, "a"), std::out_of_range);
}

// ---------------------------------------------------------------------------------------------
// The paper's Table 3 and the project's baseline.

TEST(Table3PaperFile, SixRowsOf32Nodes) {
  const auto rows = load_table3_paper();
  ASSERT_EQ(rows.size(), 6u);
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].row, static_cast<int>(i) + 1);
    EXPECT_EQ(rows[i].paper.gap + rows[i].paper.slide + rows[i].paper.stick, 32) << "row " << rows[i].row;
  }
}

// SPEC §2.1's table, typed here: row, μ̄, λ̄, gap, slide, stick.
TEST(Table3PaperFile, MatchesTheSpecTable) {
  struct Expected { int row; double mu_bar, lambda_bar; StatusCount counts; };
  const std::vector<Expected> spec = {
      {1, 5.4e8, 4.5e8, {3, 16, 13}},  {2, 5.4e2, 4.5e8, {3, 14, 15}},
      {3, 5.4e2, 4.5e2, {3, 13, 16}},  {4, 5.4e-2, 4.5e8, {0, 0, 32}},
      {5, 5.4e-2, 4.5e2, {0, 0, 32}},  {6, 5.4e-2, 4.5e-2, {0, 0, 32}}};
  const auto rows = load_table3_paper();
  ASSERT_EQ(rows.size(), spec.size());
  for (size_t i = 0; i < spec.size(); ++i) {
    SCOPED_TRACE("row " + std::to_string(spec[i].row));
    EXPECT_EQ(rows[i].row, spec[i].row);
    EXPECT_DOUBLE_EQ(rows[i].mu_bar, spec[i].mu_bar);
    EXPECT_DOUBLE_EQ(rows[i].lambda_bar, spec[i].lambda_bar);
    EXPECT_EQ(rows[i].paper, spec[i].counts);
  }
}

TEST(Table3BaselineFile, SixRowsOf32Nodes) {
  const auto rows = load_table3_baseline();
  ASSERT_EQ(rows.size(), 6u);
  for (size_t i = 0; i < rows.size(); ++i)
    EXPECT_EQ(rows[i].gap + rows[i].slide + rows[i].stick, 32) << "row " << i + 1;
}

TEST(Table3BaselineFile, RowsOutOfOrderThrow) {
  const TempDir dir;
  dir.write("table3_baseline.csv", "row,gap,slide,stick\n1,0,0,32\n3,0,0,32\n");
  EXPECT_THROW(load_table3_baseline(dir.str()), std::runtime_error);
}

TEST(Table1File, BadCaseLetterThrows) {
  const TempDir dir;
  dir.write("table1.csv", "case,lambda_limit,mu_limit\nz,0,0\n");
  EXPECT_THROW(load_table1(dir.str()), std::runtime_error);
  dir.write("table1.csv", "case,lambda_limit,mu_limit\nab,0,0\n");
  EXPECT_THROW(load_table1(dir.str()), std::runtime_error);
}

// ---------------------------------------------------------------------------------------------
// The reference directory.

TEST(ReferenceDir, EnvironmentVariableOverridesTheDirectory) {
  const TempDir dir;
  dir.write("table3_paper.csv",
            "# a stand-in table\n"
            "row,mu_bar,lambda_bar,gap,slide,stick\n"
            "7,1.25,2.5,1,2,3\n");
  const ScopedEnv env("THINLAYER_REFERENCE_DIR", dir.str());
  EXPECT_EQ(reference_dir(), dir.str());
  const auto rows = load_table3_paper();  // default argument: reference_dir()
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].row, 7);
  EXPECT_EQ(rows[0].mu_bar, 1.25);
  EXPECT_EQ(rows[0].lambda_bar, 2.5);
  EXPECT_EQ(rows[0].paper, (StatusCount{1, 2, 3}));
}

TEST(ReferenceDir, OverrideToAnEmptyDirectoryMakesLoadersThrow) {
  const TempDir dir;
  const ScopedEnv env("THINLAYER_REFERENCE_DIR", dir.str());
  EXPECT_THROW(load_table1(), std::runtime_error);
  EXPECT_THROW(load_table3_paper(), std::runtime_error);
}

TEST(ReferenceDir, UnsetOrEmptyVariableFallsBackToTheSourceTree) {
  {
    const ScopedEnv env("THINLAYER_REFERENCE_DIR", std::nullopt);
    EXPECT_EQ(reference_dir(), std::string(THINLAYER_REFERENCE_DIR));
    EXPECT_EQ(load_table3_paper().size(), 6u);
  }
  {
    const ScopedEnv env("THINLAYER_REFERENCE_DIR", std::string());
    EXPECT_EQ(reference_dir(), std::string(THINLAYER_REFERENCE_DIR));
  }
}

TEST(ReferenceDir, VariableIsRestoredAfterOverride) {
  const char* before = std::getenv("THINLAYER_REFERENCE_DIR");
  const std::optional<std::string> saved = before ? std::optional<std::string>(before) : std::nullopt;
  {
    const ScopedEnv env("THINLAYER_REFERENCE_DIR", std::string("/nonexistent"));
    EXPECT_EQ(reference_dir(), "/nonexistent");
  }
  const char* after = std::getenv("THINLAYER_REFERENCE_DIR");
  EXPECT_EQ(after != nullptr, saved.has_value());
  if (after && saved) {
    EXPECT_EQ(std::string(after), *saved);
  }
}

}  // namespace
}  // namespace thinlayer
