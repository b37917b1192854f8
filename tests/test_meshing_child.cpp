// The confined meshing child (core/mesh/meshing_child.h): what gmsh's failures become, and
// what the child cannot do whatever a script asks of it.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/mesh/meshing_child.h"

namespace {

using thinlayer::MeshingChildError;
using thinlayer::MeshingChildLimits;
using thinlayer::run_in_meshing_child;

namespace fs = std::filesystem;

// The message of the MeshingChildError that running `work` throws ("" if none).
std::string failure(const std::function<std::string()>& work, const MeshingChildLimits& limits = {}) {
  try {
    run_in_meshing_child(work, limits);
  } catch (const MeshingChildError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshingChild, HandsBackWhatTheWorkReturns) {
  std::string big(1 << 20, 'x');  // more than a pipe holds at once
  big[12345] = '\0';
  EXPECT_EQ(run_in_meshing_child([&] { return big; }), big);
}

TEST(MeshingChild, AnExceptionComesBackAsItsMessage) {
  EXPECT_EQ(failure([]() -> std::string { throw std::runtime_error("no surface"); }), "no surface");
  EXPECT_EQ(failure([]() -> std::string { throw std::string("Unknown entity"); }), "gmsh: Unknown entity");
  try {
    run_in_meshing_child([]() -> std::string { throw std::invalid_argument("bad group"); });
    FAIL();
  } catch (const MeshingChildError& e) {
    EXPECT_TRUE(e.input);
  }
}

// gmsh's errors inside its OpenMP regions reach std::terminate (the caller never sees them).
TEST(MeshingChild, AnExceptionThatTerminatesComesBackAsItsMessage) {
  EXPECT_EQ(failure([]() -> std::string {
              [] () noexcept { throw std::string("Mesh size too small"); }();
              return "";
            }),
            "gmsh: Mesh size too small");
}

TEST(MeshingChild, ACrashIsAMessage) {
  EXPECT_EQ(failure([]() -> std::string {
              std::raise(SIGSEGV);
              return "";
            }),
            "gmsh crashed (Segmentation fault)");
  EXPECT_NE(failure([]() -> std::string { std::_Exit(0); }).find("ended without a mesh"), std::string::npos);
}

TEST(MeshingChild, LimitsAreMessages) {
  MeshingChildLimits limits;
  limits.cpu_limit_s = 1;
  EXPECT_NE(failure([]() -> std::string {
              for (volatile unsigned long i = 0;; ++i) {
              }
            }, limits).find("CPU time limit (1 s"), std::string::npos);
  limits = {};
  limits.memory_limit_bytes = 1LL << 30;
  EXPECT_NE(failure([]() -> std::string {
              std::vector<char> v(2LL << 30, 1);
              return std::string(v.data(), 1);
            }, limits).find("memory limit (1 GiB)"), std::string::npos);
}

// What a script could ask of gmsh: each attempt fails inside the child, nothing appears outside.
TEST(MeshingChild, CannotRunAProgramOrWriteAFile) {
  const fs::path dir = fs::temp_directory_path() / ("thinlayer-child-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "existing.txt") << "the user's file\n";
  const std::string answer = run_in_meshing_child([&] {
    std::string what;
    what += std::system(("touch " + (dir / "by_system").string()).c_str()) == 0 ? "system ran;" : "";
    what += ::fork() >= 0 ? "forked;" : "";
    what += ::open((dir / "new.txt").c_str(), O_WRONLY | O_CREAT, 0666) >= 0 ? "created;" : "";
    what += ::open((dir / "existing.txt").c_str(), O_WRONLY | O_TRUNC) >= 0 ? "truncated;" : "";
    what += ::open((dir / "existing.txt").c_str(), O_RDWR) >= 0 ? "opened for writing;" : "";
    what += ::unlink((dir / "existing.txt").c_str()) == 0 ? "removed;" : "";
    what += ::rename((dir / "existing.txt").c_str(), (dir / "moved.txt").c_str()) == 0 ? "renamed;" : "";
    what += ::mkdir((dir / "sub").c_str(), 0777) == 0 ? "made a folder;" : "";
    what += ::kill(::getppid(), 0) == 0 ? "signalled its parent;" : "";
    what += ::open((dir / "existing.txt").c_str(), O_RDONLY) >= 0 ? "" : "cannot even read;";
    return what;
  });
  EXPECT_EQ(answer, "");
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"existing.txt"});
  std::ifstream in(dir / "existing.txt");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "the user's file");
  fs::remove_all(dir);
}

}  // namespace
