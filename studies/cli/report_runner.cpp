#include "studies/cli/report_runner.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
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

std::string python() {
  const std::string p = setting("THINLAYER_PYTHON", THINLAYER_PYTHON);
  if (p.empty() || p.find("NOTFOUND") != std::string::npos)
    throw std::runtime_error("no python3 for the report (install python3-matplotlib and python3-h5py, or set THINLAYER_PYTHON)");
  return p;
}

std::string script() { return setting("THINLAYER_REPORT_SCRIPT", THINLAYER_REPORT_SCRIPT); }

// Runs the report's interpreter on `args` (after the script) and returns its exit status (-1: it
// did not exit). With `said`, its stderr is read into it instead of reaching ours. SIGINT/SIGTERM
// reach it too, and it removes its half-built files.
int run_script(const std::vector<std::string>& args, std::string* said) {
  const std::string interpreter = python();
  std::vector<std::string> all = {interpreter, script()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  int pipe_fds[2] = {-1, -1};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (said) {
    if (::pipe2(pipe_fds, O_CLOEXEC) != 0) throw std::runtime_error("cannot run the report's interpreter (pipe)");
    posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 2);
  }
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, interpreter.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (said) ::close(pipe_fds[1]);
  if (spawned != 0) {
    if (said) ::close(pipe_fds[0]);
    throw std::runtime_error("cannot run the report's interpreter '" + interpreter + "'");
  }
  set_signal_child(pid);
  if (said) {
    char buffer[4096];
    for (ssize_t n; (n = ::read(pipe_fds[0], buffer, sizeof buffer)) != 0;) {
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) break;
      if (said->size() < (64 << 10)) said->append(buffer, static_cast<std::size_t>(n));
    }
    ::close(pipe_fds[0]);
  }
  int status = 0;
  bool lost = false;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      lost = true;
      break;
    }
  set_signal_child(0);
  if (lost) throw std::runtime_error("lost the report process");
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The report's reason in what it said on stderr: its last "make_report: " line, else its last line.
std::string reason(const std::string& said) {
  const std::string prefix = "make_report: ";
  std::string prefixed, any;
  for (std::size_t at = 0; at < said.size();) {
    const std::size_t end = std::min(said.find('\n', at), said.size());
    const std::string line = said.substr(at, end - at);
    if (line.rfind(prefix, 0) == 0) prefixed = line.substr(prefix.size());
    else if (!line.empty()) any = line;
    at = end + 1;
  }
  return prefixed.empty() ? any : prefixed;
}

}  // namespace

void check_report_folder(const std::string& out_dir) {
  std::string said;
  if (run_script({"--check-folder", out_dir}, &said) == 0) return;
  const std::string why = reason(said);
  throw OutputError("the report's folder: " + (why.empty() ? out_dir + " cannot be checked" : why));
}

void run_report_keeping(const std::string& results_h5, const std::string& out_dir, const std::vector<std::string>& kept) {
  std::string said;
  if (run_script({results_h5, out_dir}, &said) == 0) return;
  std::string files;
  for (std::size_t k = 0; k < kept.size(); ++k) files += (k == 0 ? "" : k + 1 == kept.size() ? " and " : ", ") + kept[k];
  const std::string why = reason(said);
  throw OutputError("the report was not written (" + (why.empty() ? "it failed without a word" : why) + "); kept " + files);
}

void run_report(const std::string& results_h5, const std::string& out_dir) {
  if (run_script({results_h5, out_dir}, nullptr) != 0)
    throw std::runtime_error("the report failed (" + script() + " on " + results_h5 + "), see its message above");
}

}  // namespace thinlayer
