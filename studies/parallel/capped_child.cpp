#include "studies/parallel/capped_child.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/io/output_target.h"

extern char** environ;

namespace thinlayer {

namespace {

using Clock = std::chrono::steady_clock;

// The answer: one byte ('R' the result, 'E' the message of what the work threw), its length (8
// bytes), the payload. Anything else, or less, is no answer.
constexpr std::size_t header_bytes = 1 + sizeof(std::uint64_t);
constexpr std::uint64_t max_answer_bytes = 1ULL << 30;  // a scene of the finest mesh is about 5 MB

bool write_all(int fd, const char* data, std::size_t size) {
  for (std::size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

void answer(int fd, char kind, const std::string& payload) {
  const std::uint64_t size = payload.size();
  char header[header_bytes];
  header[0] = kind;
  std::memcpy(header + 1, &size, sizeof size);
  write_all(fd, header, sizeof header) && write_all(fd, payload.data(), payload.size());
}

// The caller's environment without MPI's and the launcher's variables.
std::vector<std::string> worker_environment() {
  std::vector<std::string> env;
  for (char** e = environ; e && *e; ++e) {
    const std::string v = *e;
    bool launcher = false;
    for (const char* prefix : {"OMPI_", "PMIX_", "PMI_", "SLURM_"}) launcher = launcher || v.rfind(prefix, 0) == 0;
    if (!launcher) env.push_back(v);
  }
  return env;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> p;
  for (std::string& s : strings) p.push_back(s.data());
  p.push_back(nullptr);
  return p;
}

enum class Reading { Closed, Clock, TooLong };

// Reads the worker's answer until it closes its standard output or the clock runs out.
Reading read_answer(int fd, Clock::time_point deadline, std::string& bytes) {
  char buffer[1 << 16];
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) return Reading::Clock;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 60 * 1000)));
    if (ready <= 0) continue;  // EINTR or nothing yet: the loop checks the clock
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return Reading::Closed;
    bytes.append(buffer, static_cast<std::size_t>(n));
    if (bytes.size() > header_bytes + max_answer_bytes) return Reading::TooLong;
  }
}

int wait_for(pid_t child, double& cpu_seconds) {
  int status = 0;
  rusage usage{};
  while (::wait4(child, &status, 0, &usage) < 0)
    if (errno != EINTR) return -1;
  cpu_seconds = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
                1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  return status;
}

std::string how_it_ended(int status) {
  if (status == -1) return "the worker process could not be waited for";
  if (WIFSIGNALED(status)) return std::string("the worker process died of ") + strsignal(WTERMSIG(status));
  return "the worker process ended without an answer (exit status " + std::to_string(WEXITSTATUS(status)) + ")";
}

bool interrupted(int status) {
  return status != -1 && WIFSIGNALED(status) &&
         (WTERMSIG(status) == SIGINT || WTERMSIG(status) == SIGTERM || WTERMSIG(status) == SIGHUP);
}

}  // namespace

const char* to_string(CappedRun::Ending ending) {
  switch (ending) {
    case CappedRun::Ending::Answered: return "answered";
    case CappedRun::Ending::Capped: return "capped";
    case CappedRun::Ending::Threw: return "threw";
    case CappedRun::Ending::Crashed: return "crashed";
    case CappedRun::Ending::Interrupted: return "interrupted";
  }
  return "?";
}

std::string this_program() { return std::filesystem::read_symlink("/proc/self/exe").string(); }

CappedRun run_capped(const std::vector<std::string>& command, const std::string& input, double wall_limit_s) {
  if (command.empty()) throw std::invalid_argument("run_capped: no program");
  int in[2], out[2];
  if (::pipe2(in, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot start a worker: ") + std::strerror(errno));
  if (::pipe2(out, O_CLOEXEC) != 0) {
    const int error = errno;
    ::close(in[0]), ::close(in[1]);
    throw std::runtime_error(std::string("cannot start a worker: ") + std::strerror(error));
  }
  // The input goes into the pipe before the worker starts (a pipe holds 64 KiB), so that a worker
  // that dies before reading it cannot raise SIGPIPE here.
  if (input.size() > 60 * 1024 || !write_all(in[1], input.data(), input.size())) {
    for (int fd : {in[0], in[1], out[0], out[1]}) ::close(fd);
    throw std::runtime_error("cannot start a worker: its input does not fit its pipe");
  }
  ::close(in[1]);
  // Everything the child needs is made before the fork: between fork and exec only
  // async-signal-safe calls.
  std::vector<std::string> args(command), env = worker_environment();
  std::vector<char*> argv = pointers(args), envp = pointers(env);
  const pid_t parent = ::getpid();
  const auto start = Clock::now();
  const pid_t child = ::fork();
  if (child < 0) {
    const int error = errno;
    for (int fd : {in[0], out[0], out[1]}) ::close(fd);
    throw std::runtime_error(std::string("cannot start a worker: ") + std::strerror(error));
  }
  if (child == 0) {
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(71);  // the parent died before the line above
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) ::signal(s, SIG_DFL);  // not the parent's cleanup handler
    ::dup2(in[0], 0), ::dup2(out[1], 1);  // dup2 clears close-on-exec on 0 and 1
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(127);
  }
  ::close(in[0]), ::close(out[1]);
  set_signal_child(child);  // SIGINT/SIGTERM of this process reach the worker too
  std::string bytes;
  const Reading reading =
      read_answer(out[0], start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(wall_limit_s)), bytes);
  if (reading != Reading::Closed) ::kill(child, SIGKILL);
  ::close(out[0]);
  CappedRun run;
  const int status = wait_for(child, run.cpu_seconds);
  set_signal_child(0);
  run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::uint64_t size = 0;
  if (bytes.size() >= header_bytes) std::memcpy(&size, bytes.data() + 1, sizeof size);
  const bool whole = bytes.size() >= header_bytes && size == bytes.size() - header_bytes;
  if (reading == Reading::Clock) {
    run.ending = CappedRun::Ending::Capped;
    char text[96];
    std::snprintf(text, sizeof text, "stopped at its wall-time cap of %g s", wall_limit_s);
    run.message = text;
  } else if (reading == Reading::TooLong) {
    run.message = "the worker process answered more than 1 GiB";
  } else if (whole && bytes[0] == 'R' && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
    run.ending = CappedRun::Ending::Answered;
    run.answer = bytes.substr(header_bytes);
  } else if (whole && bytes[0] == 'E') {
    run.ending = CappedRun::Ending::Threw;
    run.message = bytes.substr(header_bytes);
  } else {
    run.ending = interrupted(status) ? CappedRun::Ending::Interrupted : CappedRun::Ending::Crashed;
    run.message = how_it_ended(status);
  }
  return run;
}

int serve_capped(const std::function<std::string(const std::string&)>& work) {
  std::string input;
  char buffer[1 << 16];
  for (ssize_t n; (n = ::read(0, buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return 2;
    input.append(buffer, static_cast<std::size_t>(n));
  }
  // The answer goes to the real standard output; anything the work prints there goes to stderr.
  std::fflush(stdout);
  const int answer_fd = ::fcntl(1, F_DUPFD_CLOEXEC, 3);
  ::dup2(2, 1);
  try {
    answer(answer_fd, 'R', work(input));
  } catch (const std::exception& e) {
    answer(answer_fd, 'E', e.what());
  } catch (...) {
    answer(answer_fd, 'E', "an exception that is not a std::exception");
  }
  ::close(answer_fd);
  return 0;
}

}  // namespace thinlayer
