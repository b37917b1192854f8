#include "core/mesh/read_box.h"

#include "core/mesh/private_root.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <fcntl.h>
#include <linux/landlock.h>
#include <sys/prctl.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace thinlayer {

namespace {

// Debian 12's kernel headers describe Landlock ABI 1 and 2; the rights added later have
// these bits (include/uapi/linux/landlock.h of Linux 6.2, 6.7, 6.10, 6.12).
constexpr std::uint64_t access_fs_truncate = 1ULL << 14;   // ABI 3
constexpr std::uint64_t access_fs_ioctl_dev = 1ULL << 15;  // ABI 5
constexpr std::uint64_t access_net_bind_tcp = 1ULL << 0;   // ABI 4
constexpr std::uint64_t access_net_connect_tcp = 1ULL << 1;
constexpr std::uint64_t scope_abstract_unix_socket = 1ULL << 0;  // ABI 6
constexpr std::uint64_t scope_signal = 1ULL << 1;

// struct landlock_ruleset_attr as of ABI 6; older kernels read its first 8 or 16 bytes.
struct RulesetAttr {
  std::uint64_t handled_access_fs = 0;
  std::uint64_t handled_access_net = 0;
  std::uint64_t scoped = 0;
};

// Every file-system right this ABI knows: handled (so denied) unless a rule grants it.
std::uint64_t fs_rights(int abi) {
  std::uint64_t rights = (LANDLOCK_ACCESS_FS_MAKE_SYM << 1) - 1;  // ABI 1: execute .. make_sym
  if (abi >= 2) rights |= LANDLOCK_ACCESS_FS_REFER;
  if (abi >= 3) rights |= access_fs_truncate;
  if (abi >= 5) rights |= access_fs_ioctl_dev;
  return rights;
}

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("cannot confine the meshing process (Landlock " + what + ": " + std::strerror(errno) + ")");
}

}  // namespace

int landlock_abi() {
  const long abi = ::syscall(SYS_landlock_create_ruleset, nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
  return abi > 0 ? static_cast<int>(abi) : 0;
}

ReadBox confine_reads_to(const std::string& folder) {
  const int abi = landlock_abi();
  if (abi == 0) return ReadBox::StagingOnly;
  RulesetAttr attr;
  attr.handled_access_fs = fs_rights(abi);
  std::size_t size = sizeof(std::uint64_t);
  if (abi >= 4) {
    attr.handled_access_net = access_net_bind_tcp | access_net_connect_tcp;
    size += sizeof(std::uint64_t);
  }
  if (abi >= 6) {
    attr.scoped = scope_abstract_unix_socket | scope_signal;
    size += sizeof(std::uint64_t);
  }
  const Fd ruleset(static_cast<int>(::syscall(SYS_landlock_create_ruleset, &attr, size, 0)));
  if (ruleset.get() < 0) fail("ruleset");
  const Fd beneath(::open(folder.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC));
  if (beneath.get() < 0) fail("staging folder " + folder);
  landlock_path_beneath_attr rule{};
  rule.allowed_access = LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;
  rule.parent_fd = beneath.get();
  if (::syscall(SYS_landlock_add_rule, ruleset.get(), LANDLOCK_RULE_PATH_BENEATH, &rule, 0) != 0) fail("rule");
  // Required of an unprivileged process, and what the seccomp filter sets anyway.
  if (::prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0) fail("no_new_privs");
  if (::syscall(SYS_landlock_restrict_self, ruleset.get(), 0) != 0) fail("restrict_self");
  return ReadBox::Landlock;
}

std::string read_box_description() {
  const int abi = landlock_abi();
  return (abi > 0 ? "Landlock ABI " + std::to_string(abi) : std::string("no Landlock")) +
         (private_root_available() ? "; user, mount and network namespaces (a root holding the staging folder alone)"
                                   : "; no namespaces (the whole file system, for lookups)") +
         "; seccomp allow-list";
}

}  // namespace thinlayer
