#include "core/mesh/meshing_child.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <initializer_list>
#include <limits>
#include <mutex>
#include <new>

#include <fcntl.h>
#include <linux/sched.h>
#include <malloc.h>
#include <poll.h>
#include <seccomp.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/io/output_target.h"
#include "core/mesh/gmsh_session.h"
#include "core/mesh/private_root.h"
#include "core/mesh/read_box.h"

namespace thinlayer {

namespace {

// The answer travels in frames: a type byte ('P' a phase, 'R' the result, 'E' an error: 'I' an
// input error or 'G' anything else, then the message), its payload's length (8 bytes), the payload.
constexpr std::size_t frame_header = 1 + sizeof(std::uint64_t);
// The most the parent accepts from a child: a 2·10⁶-node mesh is about 150 MB of answer.
constexpr std::uint64_t max_answer_bytes = 2ULL << 30;

// The child's side (set in run_child; -1 in any other process).
int answer_fd = -1;
long long memory_limit = 0;        // the child's address-space limit, bytes
bool memory_inherited = false;     // the limit is the lower one this process inherited
std::string phase_now;             // for the child's own messages
long long base_address_space = 0;  // at the fork (/proc/self/statm), bytes
std::size_t base_heap = 0;         // malloc's heap at the fork (mallinfo2), bytes
std::string bounded_why;           // the message of the bounded step under way ("" if none)
char alarm_frame[4096];            // that message as a frame, for the SIGALRM handler
std::size_t alarm_frame_size = 0;

void write_all(int fd, const char* data, std::size_t size) {
  for (std::size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent is gone: nobody to tell
    done += static_cast<std::size_t>(n);
  }
}

std::string frame(char type, const std::string& payload) {
  const std::uint64_t size = payload.size();
  std::string f;
  f.reserve(frame_header + payload.size());
  f.push_back(type);
  f.append(reinterpret_cast<const char*>(&size), sizeof size);
  f.append(payload);
  return f;
}

// An error's payload: 'I' (about the input) or 'G' (anything else), then the message.
std::string error_payload(bool input, const std::string& message) {
  std::string p;
  p.reserve(1 + message.size());
  p.push_back(input ? 'I' : 'G');
  p.append(message);
  return p;
}

void send(char type, const std::string& payload) {
  const std::string f = frame(type, payload);
  write_all(answer_fd, f.data(), f.size());
}

std::string gib(long long bytes) {
  char text[32];
  const double g = static_cast<double>(bytes) / (1LL << 30);
  std::snprintf(text, sizeof text, g == std::floor(g) ? "%.0f GiB" : "%.2g GiB", g);
  return text;
}

std::string while_phase(const std::string& phase) { return phase.empty() ? "" : " while " + phase; }

std::string memory_limit_text() {
  return gib(memory_limit) + (memory_inherited ? ", the limit this process inherited (ulimit -v)" : "");
}

[[noreturn]] void answer_error(bool input, const std::string& message) {
  send('E', error_payload(input, message));
  ::_exit(70);
}

// The message of the exception being handled, whatever was thrown (gmsh 4.8 throws bare
// std::string).
[[noreturn]] void answer_current_exception() {
  try {
    throw;
  } catch (const std::bad_alloc&) {
    if (!bounded_why.empty()) answer_error(true, bounded_why);
    answer_error(false, "gmsh ran out of its memory limit (" + memory_limit_text() + ")" + while_phase(phase_now));
  } catch (const std::invalid_argument& e) {  // InputError is one too
    answer_error(true, e.what());
  } catch (const std::exception& e) {
    answer_error(false, e.what());
  } catch (const std::string& message) {
    answer_error(false, "gmsh: " + message);
  } catch (...) {
    answer_error(false, "gmsh failed (an exception of unknown type)" + while_phase(phase_now));
  }
}

// An exception thrown inside one of gmsh's OpenMP regions cannot be caught by the code that
// called gmsh: the runtime calls std::terminate with it still current.
[[noreturn]] void answer_from_terminate() {
  if (std::current_exception()) answer_current_exception();
  answer_error(false, "gmsh stopped (std::terminate)" + while_phase(phase_now));
}

extern "C" void answer_bounded_alarm(int) {
  write_all(answer_fd, alarm_frame, alarm_frame_size);
  ::_exit(70);
}

// The seccomp filter: an allow-list. What gmsh makes of the staged files needs these system calls
// and no other (measured: strace -f of `thinlayer solve --scene` on every shipped scene, both
// modes, and the tests of tests/test_meshing_child.cpp; docs/security.md). Every other call fails
// with EPERM: no exec, no process, no socket, no file written, made, removed, renamed or linked, no
// stat, readlink or access of a path (Landlock decides opens, not lookups), no ioctl, no signal to
// another process, no ptrace, no mount, no new seccomp or Landlock rule, no io_uring.
bool confine() {
  scmp_filter_ctx filter = seccomp_init(SCMP_ACT_ERRNO(EPERM));
  if (!filter) return false;
  bool ok = true;
  auto allow = [&](int call, std::initializer_list<scmp_arg_cmp> args = {}) {
    // A call this architecture lacks (SCMP_SYS gives a negative number) needs no rule.
    if (call >= 0)
      ok = ok && seccomp_rule_add_array(filter, SCMP_ACT_ALLOW, call, static_cast<unsigned>(args.size()),
                                        args.size() ? args.begin() : nullptr) == 0;
  };
  // Memory, threads and their synchronisation, time, the process's own limits and signals.
  for (int call : {SCMP_SYS(brk), SCMP_SYS(munmap), SCMP_SYS(mremap), SCMP_SYS(madvise), SCMP_SYS(futex),
                   SCMP_SYS(set_robust_list), SCMP_SYS(get_robust_list), SCMP_SYS(rseq), SCMP_SYS(set_tid_address),
                   SCMP_SYS(sched_yield), SCMP_SYS(sched_getaffinity), SCMP_SYS(getpid), SCMP_SYS(gettid),
                   SCMP_SYS(getppid), SCMP_SYS(getuid), SCMP_SYS(geteuid), SCMP_SYS(getgid), SCMP_SYS(getegid),
                   SCMP_SYS(clock_gettime), SCMP_SYS(clock_getres), SCMP_SYS(gettimeofday), SCMP_SYS(time),
                   SCMP_SYS(nanosleep), SCMP_SYS(clock_nanosleep), SCMP_SYS(getrusage), SCMP_SYS(times),
                   SCMP_SYS(sysinfo), SCMP_SYS(getrlimit), SCMP_SYS(setrlimit), SCMP_SYS(alarm), SCMP_SYS(setitimer),
                   SCMP_SYS(getitimer), SCMP_SYS(rt_sigaction), SCMP_SYS(rt_sigprocmask), SCMP_SYS(rt_sigreturn),
                   SCMP_SYS(sigaltstack), SCMP_SYS(restart_syscall), SCMP_SYS(exit), SCMP_SYS(exit_group),
                   SCMP_SYS(getrandom), SCMP_SYS(uname), SCMP_SYS(getcwd), SCMP_SYS(membarrier)})
    allow(call);
  // Memory never made executable (no code but what was loaded before the fork).
  allow(SCMP_SYS(mmap), {SCMP_A2(SCMP_CMP_MASKED_EQ, PROT_EXEC, 0)});
  allow(SCMP_SYS(mprotect), {SCMP_A2(SCMP_CMP_MASKED_EQ, PROT_EXEC, 0)});
  // Threads (CLONE_THREAD), no process. glibc tries clone3 first and falls back to clone when
  // the kernel lacks it, where the flags can be read.
  allow(SCMP_SYS(clone), {SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, CLONE_THREAD)});
  ok = ok && seccomp_rule_add(filter, SCMP_ACT_ERRNO(ENOSYS), SCMP_SYS(clone3), 0) == 0;
  // Limits and signals of this process only (a crash raises its own signal: tgkill to itself).
  const scmp_datum_t self = static_cast<scmp_datum_t>(::getpid());
  allow(SCMP_SYS(prlimit64), {SCMP_A0(SCMP_CMP_EQ, 0)});
  allow(SCMP_SYS(tgkill), {SCMP_A0(SCMP_CMP_EQ, self)});
  // Files: read what is open, open for reading only (no write access, creation, truncation or
  // O_PATH handle; Landlock and the private root decide which paths), and fstat an open file
  // (newfstatat and statx on a descriptor: AT_EMPTY_PATH; stat() of a path is refused, which
  // also keeps gmsh from finding a `.opt` side file: it looks with stat()).
  for (int call : {SCMP_SYS(read), SCMP_SYS(pread64), SCMP_SYS(readv), SCMP_SYS(lseek), SCMP_SYS(close),
                   SCMP_SYS(fstat), SCMP_SYS(fcntl), SCMP_SYS(write), SCMP_SYS(writev)})
    allow(call);  // writes: stdout/stderr (/dev/null) and the pipe to the parent are the only files open for writing
  constexpr scmp_datum_t not_read_only = O_ACCMODE | O_CREAT | O_TRUNC | O_PATH | (O_TMPFILE & ~O_DIRECTORY);
  allow(SCMP_SYS(open), {SCMP_A1(SCMP_CMP_MASKED_EQ, not_read_only, O_RDONLY)});
  allow(SCMP_SYS(openat), {SCMP_A2(SCMP_CMP_MASKED_EQ, not_read_only, O_RDONLY)});
  allow(SCMP_SYS(newfstatat), {SCMP_A3(SCMP_CMP_MASKED_EQ, AT_EMPTY_PATH, AT_EMPTY_PATH)});
  allow(SCMP_SYS(statx), {SCMP_A2(SCMP_CMP_MASKED_EQ, AT_EMPTY_PATH, AT_EMPTY_PATH)});
  ok = ok && seccomp_load(filter) == 0;
  seccomp_release(filter);
  return ok;
}

void set_limit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit limit{soft, hard};
  ::setrlimit(resource, &limit);
}

// The address-space limit: the one asked for, or the lower hard limit this process inherited.
void limit_memory(long long asked) {
  rlimit inherited{};
  ::getrlimit(RLIMIT_AS, &inherited);
  memory_limit = asked;
  memory_inherited = inherited.rlim_max != RLIM_INFINITY && static_cast<long long>(inherited.rlim_max) < asked;
  if (memory_inherited) memory_limit = static_cast<long long>(inherited.rlim_max);
  set_limit(RLIMIT_AS, static_cast<rlim_t>(memory_limit), static_cast<rlim_t>(memory_limit));
}

// The address space the child holds (what RLIMIT_AS counts), from /proc before the box and
// malloc's growth after (the box may deny /proc).
long long address_space_now() {
  const struct mallinfo2 m = ::mallinfo2();
  return base_address_space + static_cast<long long>(m.arena + m.hblkhd) - static_cast<long long>(base_heap);
}

void measure_base_address_space() {
  long long pages = 0;
  if (std::FILE* statm = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(statm, "%lld", &pages) != 1) pages = 0;
    std::fclose(statm);
  }
  base_address_space = pages * ::sysconf(_SC_PAGESIZE);
  const struct mallinfo2 m = ::mallinfo2();
  base_heap = m.arena + m.hblkhd;
}

// The child's environment: none of the user's (a scene could print a secret of it, or carry it
// into a coordinate). gmsh reads its environment when it starts (HOME, TMP: its home folder;
// OpenMP and OpenCASCADE theirs when loaded), which happened in this process before the fork;
// after it, only PWD (where a new model's default file name lies: the staging folder), TERM and
// EMACS (colours on a terminal: its output goes to /dev/null), GMSHPLUGINSHOME (plugins are
// refused by the scan) and whatever a script's GetEnv names (refused by the scan). So the child
// keeps PWD alone, set to the staging folder.
void start_with_empty_environment(const std::string& folder) {
  ::clearenv();
  if (!folder.empty()) ::setenv("PWD", folder.c_str(), 1);
}

// In the child: stdio on /dev/null, the pipe as fd 3 and nothing else, the limits, the boxes.
[[noreturn]] void run_child(int pipe_write, const std::function<std::string()>& work, const MeshingChildLimits& limits,
                            pid_t parent) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  ::prctl(PR_SET_DUMPABLE, 0);  // no core dump, not even to a core_pattern pipe
  if (::getppid() != parent) ::_exit(71);  // the parent died before the line above
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) ::signal(s, SIG_DFL);  // not the parent's cleanup handler
  const int null = ::open("/dev/null", O_RDWR);
  for (int fd : {0, 1, 2}) ::dup2(null, fd);
  ::dup2(pipe_write, 3);
  ::close_range(4, ~0U, 0);
  answer_fd = 3;
  std::set_terminate(answer_from_terminate);
  measure_base_address_space();
  limit_memory(limits.memory_limit_bytes);
  set_limit(RLIMIT_CPU, limits.cpu_limit_s, limits.cpu_limit_s + 5);  // SIGXCPU, then SIGKILL
  set_limit(RLIMIT_CORE, 0, 0);
  set_limit(RLIMIT_FSIZE, 0, 0);
  start_with_empty_environment(limits.read_folder);
  if (!limits.read_folder.empty()) {
    try {
      if (!enter_private_root(limits.read_folder) && ::chdir(limits.read_folder.c_str()) != 0)
        answer_error(false, "cannot enter the staging folder " + limits.read_folder + ": gmsh was not run");
      confine_reads_to(limits.read_folder);
    } catch (const std::exception& e) {
      answer_error(false, std::string(e.what()) + ": gmsh was not run");
    }
  }
  if (!confine()) answer_error(false, "cannot confine the meshing process (seccomp): gmsh was not run");
  try {
    const std::string answer = work();
    meshing_phase("handing the meshes back");
    send('R', answer);
  } catch (...) {
    answer_current_exception();
  }
  ::_exit(0);
}

int wait_for(pid_t child) {
  int status = 0;
  while (::waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return status;
}

// What the parent has read of the child's frames.
struct Answer {
  std::string phase;   // the last phase the child named
  char kind = 0;       // 'R' or 'E' once the answer is in
  std::string payload;
  std::string pending;  // bytes of a frame not yet complete
  std::uint64_t total = 0;
  bool too_long = false;

  void take(const char* data, std::size_t size) {
    total += size;
    if (total > max_answer_bytes) {
      too_long = true;
      return;
    }
    pending.append(data, size);
    std::size_t at = 0;
    while (pending.size() - at >= frame_header) {
      std::uint64_t length = 0;
      std::memcpy(&length, pending.data() + at + 1, sizeof length);
      if (length > pending.size() - at - frame_header) break;
      const char type = pending[at];
      std::string body = pending.substr(at + frame_header, length);
      at += frame_header + length;
      if (type == 'P') phase = std::move(body);
      if ((type == 'R' || type == 'E') && kind == 0) kind = type, payload = std::move(body);
    }
    pending.erase(0, at);
  }
};

enum class Ending { Closed, Clock, TooLong };

// Reads the child's frames until it closes the pipe, the clock runs out, or it says too much.
Ending read_answer(int fd, double wall_limit_s, Answer& answer) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(wall_limit_s);
  char buffer[1 << 16];
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return Ending::Clock;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000 * 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) continue;  // the loop checks the clock
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return Ending::Closed;
    answer.take(buffer, static_cast<std::size_t>(n));
    if (answer.too_long) return Ending::TooLong;
  }
}

std::string seconds_text(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

}  // namespace

void meshing_phase(const std::string& phase) {
  if (answer_fd < 0) return;
  phase_now = phase;
  send('P', phase);
}

void run_bounded(const std::string& phase, long long memory_bytes, unsigned seconds, const std::string& why,
                 const std::function<void()>& step) {
  if (answer_fd < 0) return step();
  meshing_phase(phase);
  const std::string alarm_answer = frame('E', error_payload(true, why.substr(0, sizeof alarm_frame - frame_header - 1)));
  std::memcpy(alarm_frame, alarm_answer.data(), alarm_answer.size());
  alarm_frame_size = alarm_answer.size();
  bounded_why = why;
  const long long soft = std::min(memory_limit, address_space_now() + memory_bytes);
  set_limit(RLIMIT_AS, static_cast<rlim_t>(soft), static_cast<rlim_t>(memory_limit));
  ::signal(SIGALRM, answer_bounded_alarm);
  ::alarm(std::max(seconds, 1u));
  try {
    step();
  } catch (const std::bad_alloc&) {
    answer_error(true, why);
  }
  ::alarm(0);
  ::signal(SIGALRM, SIG_DFL);
  set_limit(RLIMIT_AS, static_cast<rlim_t>(memory_limit), static_cast<rlim_t>(memory_limit));
  bounded_why.clear();
}

namespace {

// The command's clock (set_meshing_wall_clock): its length and what the children took of it.
std::mutex clock_mutex;
double clock_s = default_mesh_timeout_s;
double clock_spent_s = 0;

struct Clock {
  double length_s, spent_s;
};
Clock clock_now() {
  const std::lock_guard<std::mutex> lock(clock_mutex);
  return {clock_s, clock_spent_s};
}

// What the children of this process took: the clock's spent part, returned as it was before.
double spend_clock(double seconds) {
  const std::lock_guard<std::mutex> lock(clock_mutex);
  const double before = clock_spent_s;
  clock_spent_s += seconds;
  return before;
}

// "(--mesh-timeout)", and when earlier meshes took part of it, how much.
std::string clock_text(double spent_before) {
  char text[160];
  if (spent_before > 0)
    std::snprintf(text, sizeof text, " (--mesh-timeout, for all the meshing of the command: %.1f s of it went to earlier meshes)",
                  spent_before);
  else
    std::snprintf(text, sizeof text, " (--mesh-timeout)");
  return text;
}

}  // namespace

void set_meshing_wall_clock(double seconds) {
  const std::lock_guard<std::mutex> lock(clock_mutex);
  clock_s = seconds;
  clock_spent_s = 0;
}

std::string run_in_meshing_child(const std::function<std::string()>& work, const MeshingChildLimits& limits) {
  const Clock clock = clock_now();
  const double left = clock.length_s - clock.spent_s;
  if (!(left > 0))
    throw MeshingChildError("the wall-clock limit of " + seconds_text(clock.length_s) + " s" + clock_text(clock.spent_s) +
                                " is spent: gmsh was not run",
                            false);
  const bool clock_binds = left < limits.wall_limit_s;
  const double wall_limit_s = clock_binds ? left : limits.wall_limit_s;
  const auto start = std::chrono::steady_clock::now();
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw MeshingChildError(std::string("cannot start gmsh's process: ") + std::strerror(errno), false);
  const pid_t parent = ::getpid();
  // gmsh starts here, outside the box: the child shares it as it was (its start reads no file).
  ensure_gmsh_initialized();
  const pid_t child = fork_with_gmsh_lock();
  if (child < 0) {
    const int error = errno;
    ::close(fds[0]), ::close(fds[1]);
    throw MeshingChildError(std::string("cannot start gmsh's process: ") + std::strerror(error), false);
  }
  if (child == 0) run_child(fds[1], work, limits, parent);
  ::close(fds[1]);
  set_signal_child(child);  // SIGINT/SIGTERM of this process reach the child too
  Answer answer;
  const Ending ending = read_answer(fds[0], wall_limit_s, answer);
  if (ending != Ending::Closed) ::kill(child, SIGKILL);
  ::close(fds[0]);
  const int status = wait_for(child);
  set_signal_child(0);
  const double spent_before = spend_clock(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  const std::string when = while_phase(answer.phase);
  if (ending == Ending::Clock)
    throw MeshingChildError("gmsh did not finish within the wall-clock limit of " +
                                (clock_binds ? seconds_text(clock.length_s) + " s" + clock_text(spent_before)
                                             : seconds_text(limits.wall_limit_s) + " s (--mesh-timeout)") +
                                when + "; a loop in the geometry?",
                            false);
  if (ending == Ending::TooLong) throw MeshingChildError("gmsh's process answered more than 2 GiB" + when, false);
  if (answer.kind == 'R' && WIFEXITED(status) && WEXITSTATUS(status) == 0) return answer.payload;
  if (answer.kind == 'E' && !answer.payload.empty())
    throw MeshingChildError(answer.payload.substr(1), answer.payload[0] == 'I');
  if (WIFSIGNALED(status) && (WTERMSIG(status) == SIGXCPU || WTERMSIG(status) == SIGKILL))
    throw MeshingChildError("gmsh ran out of its CPU time limit (" + std::to_string(limits.cpu_limit_s) +
                                " s; a loop in the geometry?) or was killed" + when,
                            false);
  if (WIFSIGNALED(status))
    throw MeshingChildError(std::string("gmsh crashed (") + strsignal(WTERMSIG(status)) + ")" + when, false);
  throw MeshingChildError("gmsh ended without a mesh (exit status " + std::to_string(WEXITSTATUS(status)) + ")" + when,
                          false);
}

}  // namespace thinlayer
