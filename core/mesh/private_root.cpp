#include "core/mesh/private_root.h"

#include <sched.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

namespace thinlayer {

namespace {

constexpr int namespaces = CLONE_NEWUSER | CLONE_NEWNS | CLONE_NEWNET;

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("cannot confine the meshing process (private root: " + what + ": " + std::strerror(errno) + ")");
}

void write_proc(const std::string& file, const std::string& text) {
  const int fd = ::open(file.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) fail(file);
  const bool ok = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
  const int error = errno;
  ::close(fd);
  errno = error;
  if (!ok) fail(file);
}

// Every folder of `path` (absolute) made beneath `base`, as plain folders.
void make_path_beneath(const std::string& base, const std::string& path) {
  std::string made = base;
  for (std::size_t at = 1; at < path.size();) {
    const std::size_t slash = std::min(path.find('/', at), path.size());
    made.push_back('/');
    made.append(path, at, slash - at);
    if (::mkdir(made.c_str(), 0755) != 0 && errno != EEXIST) fail("mkdir " + made);
    at = slash + 1;
  }
}

}  // namespace

bool private_root_available() {
  static const bool available = [] {
    const pid_t probe = ::fork();
    if (probe < 0) return false;
    if (probe == 0) ::_exit(::unshare(namespaces) == 0 ? 0 : 1);
    int status = 0;
    while (::waitpid(probe, &status, 0) < 0)
      if (errno != EINTR) return false;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
  }();
  return available;
}

bool enter_private_root(const std::string& folder) {
  const uid_t uid = ::geteuid();
  const gid_t gid = ::getegid();
  if (::unshare(namespaces) != 0) return false;
  // Our own ids mapped to themselves: the files we create in the new root need a mapped owner.
  write_proc("/proc/self/setgroups", "deny");
  write_proc("/proc/self/uid_map", std::to_string(uid) + " " + std::to_string(uid) + " 1");
  write_proc("/proc/self/gid_map", std::to_string(gid) + " " + std::to_string(gid) + " 1");
  // Nothing mounted here reaches the parent's namespace.
  if (::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0) fail("private mounts");
  // The staging folder, held (in this namespace's copy of the mounts) before the tmpfs covers its path.
  const int staged = ::open(folder.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
  if (staged < 0) fail("staging folder " + folder);
  // The new root: an empty tmpfs (mounted over the staging folder's own path, a folder that
  // exists), the staging folder bound into it at its own path.
  if (::mount("thinlayer-root", folder.c_str(), "tmpfs", MS_NOSUID | MS_NODEV | MS_NOEXEC, "size=64k,mode=0755") != 0)
    fail("tmpfs on " + folder);
  make_path_beneath(folder, folder);
  const std::string inner = folder + folder;
  const std::string source = "/proc/self/fd/" + std::to_string(staged);
  // Not MS_REC: that would copy the tmpfs now mounted on the folder too, not what lies beneath it.
  if (::mount(source.c_str(), inner.c_str(), nullptr, MS_BIND, nullptr) != 0) fail("bind " + folder);
  ::close(staged);
  // Read-only; the flags the kernel locks in a user namespace (the original mount's atime rule,
  // nosuid, ...) kept as they are (statvfs's ST_* are the MS_* bits).
  struct statvfs bound {};
  if (::statvfs(inner.c_str(), &bound) != 0) fail("statvfs " + folder);
  if (::mount(nullptr, inner.c_str(), nullptr,
              bound.f_flag | MS_BIND | MS_REMOUNT | MS_RDONLY | MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr) != 0)
    fail("read-only " + folder);
  // pivot_root(".", "."): the tmpfs becomes "/", the old root is stacked on it and detached.
  if (::chdir(folder.c_str()) != 0) fail("chdir " + folder);
  if (::syscall(SYS_pivot_root, ".", ".") != 0) fail("pivot_root");
  if (::umount2(".", MNT_DETACH) != 0) fail("detach the old root");
  if (::chdir(folder.c_str()) != 0) fail("chdir " + folder + " in the new root");
  return true;
}

}  // namespace thinlayer
