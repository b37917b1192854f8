// environment_info / write_environment: every key is there and looks right, and the
// attributes read back from /environment of an HDF5 file.
#include <cctype>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "core/io/h5_reader.h"
#include "core/io/h5_writer.h"
#include "studies/cli/environment.h"

namespace thinlayer {
namespace {

namespace fs = std::filesystem;

const char* const keys[] = {"compiler", "eigen",      "cholmod", "suitesparse",  "gmsh",
                            "hdf5",     "build_type", "commit",  "gmsh_read_box"};

// "3.4.0": digits separated by single dots, at least major.minor.
bool looks_like_version(const std::string& v) {
  int dots = 0;
  bool digit_before = false;
  for (char c : v) {
    if (std::isdigit(static_cast<unsigned char>(c))) {
      digit_before = true;
    } else if (c == '.' && digit_before) {
      ++dots;
      digit_before = false;
    } else {
      return false;
    }
  }
  return digit_before && dots >= 1;
}

TEST(Environment, EveryKeyIsPresentAndNonEmpty) {
  const auto info = environment_info();
  for (const char* key : keys) {
    ASSERT_TRUE(info.count(key)) << key;
    EXPECT_FALSE(info.at(key).empty()) << key;
  }
  EXPECT_EQ(info.size(), std::size(keys));
}

TEST(Environment, VersionsLookLikeVersions) {
  const auto info = environment_info();
  for (const char* key : {"eigen", "cholmod", "suitesparse", "gmsh", "hdf5"})
    EXPECT_TRUE(looks_like_version(info.at(key))) << key << " = '" << info.at(key) << "'";
  EXPECT_TRUE(info.at("eigen").rfind("3.", 0) == 0) << info.at("eigen");  // CMake asks for Eigen 3.4
  EXPECT_NE(info.at("compiler").find_first_of("0123456789"), std::string::npos) << info.at("compiler");
  EXPECT_NE(info.at("build_type").find("optimized"), std::string::npos) << info.at("build_type");
}

// A 40-hex-digit SHA-1, optionally " (modified)"; or "unknown" where the sources are not a
// git clone (e.g. an exported tarball).
TEST(Environment, CommitIsAGitHashOrUnknown) {
  const std::string commit = environment_info().at("commit");
  if (commit == "unknown") GTEST_SKIP() << "the source tree is not a git clone here";
  ASSERT_GE(commit.size(), 40u) << commit;
  for (std::size_t i = 0; i < 40; ++i) EXPECT_TRUE(std::isxdigit(static_cast<unsigned char>(commit[i]))) << commit;
  const std::string rest = commit.substr(40);
  EXPECT_TRUE(rest.empty() || rest == " (modified)") << commit;
}

TEST(Environment, WrittenAsStringAttributesOfTheEnvironmentGroup) {
  const fs::path file = fs::temp_directory_path() / ("thinlayer_environment_" + std::to_string(::getpid()) + ".h5");
  {
    H5Writer out(file.string());
    write_environment(out);
    out.commit();
  }
  const auto info = environment_info();
  {
    const H5Reader in(file.string());
    EXPECT_TRUE(in.exists("/environment"));
    for (const auto& [name, value] : info) EXPECT_EQ(in.attr_string("/environment", name), value) << name;
  }
  fs::remove(file);
}

}  // namespace
}  // namespace thinlayer
