#include "studies/cli/environment.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

#include <Eigen/Core>
#include <cholmod.h>
#include <gmsh.h>
#include <hdf5.h>

#include <sys/wait.h>

#include "core/mesh/read_box.h"

namespace thinlayer {
namespace {

std::string dotted(int major, int minor, int patch) {
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

std::string compiler() {
#if defined(__clang__)
  return "clang++ " __clang_version__;
#elif defined(__GNUC__)
  return "g++ " __VERSION__;
#else
  return "unknown";
#endif
}

std::string build_type() {
#ifdef __OPTIMIZE__
  std::string type = "optimized";
#else
  std::string type = "unoptimized";
#endif
#ifdef NDEBUG
  return type + ", assertions off";
#else
  return type + ", assertions on";
#endif
}

// The text between single quotes reaches the program unchanged; a quote in it is closed,
// escaped and reopened. Keeps a source path with spaces or quotes from being run as shell.
std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// Runs `git -C <source dir> <arguments>` and returns its standard output; false if git is
// missing, fails, or the directory is not a clone. Its error messages are discarded.
bool run_git(const std::string& arguments, std::string& output) {
  const std::string source = std::filesystem::path(THINLAYER_REFERENCE_DIR).parent_path().string();
  const std::string command = "git -C " + shell_quoted(source) + " " + arguments + " 2>/dev/null";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return false;
  output.clear();
  std::array<char, 256> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = ::pclose(pipe);
  return status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::string commit() {
  std::string head, changes;
  if (!run_git("rev-parse HEAD", head)) return "unknown";
  while (!head.empty() && (head.back() == '\n' || head.back() == '\r')) head.pop_back();
  if (head.empty()) return "unknown";
  // Without optional locks: a status query must never hold index.lock against a concurrent commit.
  if (!run_git("--no-optional-locks status --porcelain", changes)) return head + " (status unknown)";
  return changes.empty() ? head : head + " (modified)";
}

}  // namespace

std::map<std::string, std::string> environment_info() {
  std::map<std::string, std::string> info;
  info["compiler"] = compiler();
  info["eigen"] = dotted(EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
  info["cholmod"] = dotted(CHOLMOD_MAIN_VERSION, CHOLMOD_SUB_VERSION, CHOLMOD_SUBSUB_VERSION);
#ifdef SUITESPARSE_MAIN_VERSION
  info["suitesparse"] = dotted(SUITESPARSE_MAIN_VERSION, SUITESPARSE_SUB_VERSION, SUITESPARSE_SUBSUB_VERSION);
#endif
  info["gmsh"] = GMSH_API_VERSION;
  info["hdf5"] = dotted(H5_VERS_MAJOR, H5_VERS_MINOR, H5_VERS_RELEASE);
  info["build_type"] = build_type();
  info["commit"] = commit();
  // The meshing child's file-system box on this kernel (core/mesh/read_box.h).
  info["gmsh_read_box"] = read_box_description();
  return info;
}

void write_environment(H5Writer& out) {
  for (const auto& [name, value] : environment_info()) out.attr("/environment", name, value);
}

}  // namespace thinlayer
