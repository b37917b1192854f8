#include "studies/cli/report_runner.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "core/io/output_target.h"

extern char** environ;

namespace thinlayer {

namespace {

std::string setting(const char* variable, const char* built_in) {
  if (const char* v = std::getenv(variable); v && *v) return v;
  return built_in;
}

}  // namespace

void run_report(const std::string& results_h5, const std::string& out_dir) {
  const std::string python = setting("THINLAYER_PYTHON", THINLAYER_PYTHON);
  const std::string script = setting("THINLAYER_REPORT_SCRIPT", THINLAYER_REPORT_SCRIPT);
  if (python.empty() || python.find("NOTFOUND") != std::string::npos)
    throw std::runtime_error("no python3 for the report (install python3-matplotlib and python3-h5py, or set THINLAYER_PYTHON)");
  std::vector<std::string> args = {python, script, results_h5, out_dir};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error("cannot run the report's interpreter '" + python + "'");
  // SIGINT/SIGTERM reach the report too, which then removes its half-built files.
  set_signal_child(pid);
  int status = 0;
  const bool lost = waitpid(pid, &status, 0) < 0;
  set_signal_child(0);
  if (lost) throw std::runtime_error("lost the report process");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("the report failed (" + script + " on " + results_h5 + "), see its message above");
}

}  // namespace thinlayer
