#include "core/mesh/meshing_child.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>
#include <initializer_list>
#include <new>

#include <fcntl.h>
#include <linux/sched.h>
#include <seccomp.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/io/output_target.h"
#include "core/mesh/gmsh_session.h"

namespace thinlayer {

namespace {

// The child's end of the pipe, for its terminate handler.
int answer_fd = -1;
long long memory_limit = 0;

void write_all(int fd, const std::string& bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent is gone: nobody to tell
    done += static_cast<std::size_t>(n);
  }
}

std::string gib(long long bytes) { return std::to_string(bytes >> 30) + " GiB"; }

// 'E', then 'I' (an error about the input) or 'G' (anything else), then the message.
[[noreturn]] void answer_error(bool input, const std::string& message) {
  write_all(answer_fd, std::string("E") + (input ? 'I' : 'G') + message);
  ::_exit(70);
}

// The message of the exception being handled, whatever was thrown (gmsh 4.8 throws bare
// std::string).
[[noreturn]] void answer_current_exception() {
  try {
    throw;
  } catch (const std::bad_alloc&) {
    answer_error(false, "gmsh ran out of its memory limit (" + gib(memory_limit) + ")");
  } catch (const std::invalid_argument& e) {  // InputError is one too
    answer_error(true, e.what());
  } catch (const std::exception& e) {
    answer_error(false, e.what());
  } catch (const std::string& message) {
    answer_error(false, "gmsh: " + message);
  } catch (...) {
    answer_error(false, "gmsh failed (an exception of unknown type)");
  }
}

// An exception thrown inside one of gmsh's OpenMP regions cannot be caught by the code that
// called gmsh: the runtime calls std::terminate with it still current.
[[noreturn]] void answer_from_terminate() {
  if (std::current_exception()) answer_current_exception();
  answer_error(false, "gmsh stopped (std::terminate)");
}

// The system calls that run, start, write, remove or signal anything fail with EPERM.
bool confine() {
  scmp_filter_ctx filter = seccomp_init(SCMP_ACT_ALLOW);
  if (!filter) return false;
  const uint32_t refuse = SCMP_ACT_ERRNO(EPERM);
  bool ok = true;
  auto deny = [&](int call, uint32_t action, unsigned count, const scmp_arg_cmp* args) {
    // A call this architecture lacks (SCMP_SYS gives a negative number) needs no rule.
    if (call >= 0) ok = ok && seccomp_rule_add_array(filter, action, call, count, args) == 0;
  };
  for (int call : {SCMP_SYS(execve), SCMP_SYS(execveat), SCMP_SYS(fork), SCMP_SYS(vfork), SCMP_SYS(creat),
                   SCMP_SYS(mkdir), SCMP_SYS(mkdirat), SCMP_SYS(rmdir), SCMP_SYS(unlink), SCMP_SYS(unlinkat),
                   SCMP_SYS(rename), SCMP_SYS(renameat), SCMP_SYS(renameat2), SCMP_SYS(link), SCMP_SYS(linkat),
                   SCMP_SYS(symlink), SCMP_SYS(symlinkat), SCMP_SYS(truncate), SCMP_SYS(chmod), SCMP_SYS(fchmod),
                   SCMP_SYS(fchmodat), SCMP_SYS(chown), SCMP_SYS(fchown), SCMP_SYS(lchown), SCMP_SYS(fchownat),
                   SCMP_SYS(mknod), SCMP_SYS(mknodat), SCMP_SYS(utime), SCMP_SYS(utimes), SCMP_SYS(utimensat),
                   SCMP_SYS(futimesat), SCMP_SYS(socket), SCMP_SYS(socketpair), SCMP_SYS(kill), SCMP_SYS(ptrace),
                   SCMP_SYS(process_vm_writev), SCMP_SYS(mount), SCMP_SYS(umount2), SCMP_SYS(chroot),
                   SCMP_SYS(pivot_root), SCMP_SYS(setxattr), SCMP_SYS(lsetxattr), SCMP_SYS(fsetxattr),
                   SCMP_SYS(removexattr), SCMP_SYS(lremovexattr), SCMP_SYS(fremovexattr),
                   SCMP_SYS(open_by_handle_at), SCMP_SYS(io_uring_setup)})
    deny(call, refuse, 0, nullptr);
  // Threads (CLONE_THREAD) may start, processes may not. glibc tries clone3 first and falls
  // back to clone when the kernel lacks it, where the flags can be read.
  const scmp_arg_cmp no_thread[] = {SCMP_A0(SCMP_CMP_MASKED_EQ, CLONE_THREAD, 0)};
  deny(SCMP_SYS(clone), refuse, 1, no_thread);
  deny(SCMP_SYS(clone3), SCMP_ACT_ERRNO(ENOSYS), 0, nullptr);
  deny(SCMP_SYS(openat2), SCMP_ACT_ERRNO(ENOSYS), 0, nullptr);
  // Files open for reading only: no write access, no creation, no truncation.
  for (auto [call, flags] : {std::pair{SCMP_SYS(open), 1u}, std::pair{SCMP_SYS(openat), 2u}}) {
    const scmp_arg_cmp write_only[] = {{flags, SCMP_CMP_MASKED_EQ, O_ACCMODE, O_WRONLY}};
    const scmp_arg_cmp read_write[] = {{flags, SCMP_CMP_MASKED_EQ, O_ACCMODE, O_RDWR}};
    const scmp_arg_cmp create[] = {{flags, SCMP_CMP_MASKED_EQ, O_CREAT, O_CREAT}};
    const scmp_arg_cmp truncate[] = {{flags, SCMP_CMP_MASKED_EQ, O_TRUNC, O_TRUNC}};
    for (const scmp_arg_cmp* rule : {write_only, read_write, create, truncate}) deny(call, refuse, 1, rule);
  }
  ok = ok && seccomp_load(filter) == 0;
  seccomp_release(filter);
  return ok;
}

void set_limit(int resource, rlim_t soft, rlim_t hard) {
  const rlimit limit{soft, hard};
  ::setrlimit(resource, &limit);
}

// In the child: stdio on /dev/null, the pipe as fd 3 and nothing else, the limits, the filter.
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
  memory_limit = limits.memory_limit_bytes;
  std::set_terminate(answer_from_terminate);
  set_limit(RLIMIT_AS, limits.memory_limit_bytes, limits.memory_limit_bytes);
  set_limit(RLIMIT_CPU, limits.cpu_limit_s, limits.cpu_limit_s + 5);  // SIGXCPU, then SIGKILL
  set_limit(RLIMIT_CORE, 0, 0);
  set_limit(RLIMIT_FSIZE, 0, 0);
  if (!confine()) answer_error(false, "cannot confine the meshing process (seccomp): gmsh was not run");
  try {
    const std::string answer = work();
    write_all(answer_fd, "R" + answer);
  } catch (...) {
    answer_current_exception();
  }
  ::_exit(0);
}

std::string read_all(int fd) {
  std::string bytes;
  char buffer[1 << 16];
  while (true) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return bytes;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
}

int wait_for(pid_t child) {
  int status = 0;
  while (::waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return status;
}

}  // namespace

std::string run_in_meshing_child(const std::function<std::string()>& work, const MeshingChildLimits& limits) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw MeshingChildError(std::string("cannot start gmsh's process: ") + std::strerror(errno), false);
  const pid_t parent = ::getpid();
  const pid_t child = fork_with_gmsh_lock();
  if (child < 0) {
    const int error = errno;
    ::close(fds[0]), ::close(fds[1]);
    throw MeshingChildError(std::string("cannot start gmsh's process: ") + std::strerror(error), false);
  }
  if (child == 0) run_child(fds[1], work, limits, parent);
  ::close(fds[1]);
  set_signal_child(child);  // SIGINT/SIGTERM of this process reach the child too
  const std::string answer = read_all(fds[0]);
  ::close(fds[0]);
  const int status = wait_for(child);
  set_signal_child(0);
  if (answer.size() >= 1 && answer[0] == 'R' && WIFEXITED(status) && WEXITSTATUS(status) == 0) return answer.substr(1);
  if (answer.size() >= 2 && answer[0] == 'E') throw MeshingChildError(answer.substr(2), answer[1] == 'I');
  if (WIFSIGNALED(status) && (WTERMSIG(status) == SIGXCPU || WTERMSIG(status) == SIGKILL))
    throw MeshingChildError("gmsh ran out of its CPU time limit (" + std::to_string(limits.cpu_limit_s) +
                                " s; a loop in the geometry?) or was killed",
                            false);
  if (WIFSIGNALED(status))
    throw MeshingChildError(std::string("gmsh crashed (") + strsignal(WTERMSIG(status)) + ")", false);
  throw MeshingChildError("gmsh ended without a mesh (exit status " + std::to_string(WEXITSTATUS(status)) + ")", false);
}

}  // namespace thinlayer
