#include "core/mesh/staging_folder.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/io/output_target.h"

namespace thinlayer {

namespace {

// $TMPDIR (or /tmp), absolute and lexically normal: the meshing child works in the folder and
// names it in its box (a relative TMPDIR, read from there, named nothing).
std::string temporary_directory() {
  const char* tmp = std::getenv("TMPDIR");
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(tmp && *tmp ? tmp : "/tmp", ec).lexically_normal();
  if (ec) throw std::runtime_error("cannot stage the scene's files for gmsh ($TMPDIR " + std::string(tmp) + ": " + ec.message() + ")");
  std::string folder = absolute.string();
  while (folder.size() > 1 && folder.back() == '/') folder.pop_back();
  return folder;
}

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("cannot stage the scene's files for gmsh (" + what + ": " + std::strerror(errno) + ")");
}

void write_file(const std::string& path, const std::string& bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0400);
  if (fd < 0) fail(path);
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = errno;
      ::close(fd);
      errno = error;
      fail(path);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) fail(path);
}

}  // namespace

StagingFolder::StagingFolder(const std::vector<std::string>& folders, const std::vector<StagedFile>& files) {
  std::string name = temporary_directory() + "/thinlayer-scene-XXXXXX";
  if (!::mkdtemp(name.data())) fail("mkdtemp in " + temporary_directory());
  root_ = name;
  // Everything that will be made, registered before it is: a signal half-way removes what there is.
  std::vector<Removal> removals;
  for (const StagedFile& f : files) removals.push_back({Removal::File, root_ + "/" + f.name});
  for (auto it = folders.rbegin(); it != folders.rend(); ++it) removals.push_back({Removal::Folder, root_ + "/" + *it});
  removals.push_back({Removal::Folder, root_});
  for (const Removal& r : removals) made_.push_back(r.path);
  try {
    removal_ = register_removals(removals);
    for (const std::string& folder : folders)
      if (::mkdir((root_ + "/" + folder).c_str(), 0700) != 0 && errno != EEXIST) fail(root_ + "/" + folder);
    for (const StagedFile& f : files) write_file(root_ + "/" + f.name, *f.bytes);
  } catch (...) {
    remove();
    throw;
  }
}

StagingFolder::~StagingFolder() { remove(); }

void StagingFolder::remove() noexcept {
  for (const std::string& path : made_)
    if (::unlink(path.c_str()) != 0) ::rmdir(path.c_str());
  unregister_removals(removal_);
  removal_ = -1;
}

}  // namespace thinlayer
