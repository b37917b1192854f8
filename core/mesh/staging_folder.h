#pragma once
// A private folder holding exactly the bytes thinlayer read and checked of a scene's files, for
// the meshing child to read and nothing else (SPEC §4; cases/scene/scene_sources.h says which
// files and core/mesh/read_box.h boxes the child into it).
//
// Made with mkdtemp under $TMPDIR (or /tmp; a relative one taken from the working directory), mode 0700, its files 0400, written with O_EXCL and
// O_NOFOLLOW: no other user can read it, and nothing there but what was given. Removed when the
// object goes, and by the signal handler of core/io/output_target.h on SIGINT, SIGTERM, SIGHUP
// or SIGPIPE (not on SIGKILL: then a `thinlayer-scene-*` folder stays in $TMPDIR).
#include <string>
#include <vector>

namespace thinlayer {

struct StagedFile {
  std::string name;          // relative to the folder, lexically normal, inside it
  const std::string* bytes;  // what the file holds
};

class StagingFolder {
 public:
  // `folders`: relative names of the folders to make (each one's parent before it); `files` go
  // into them. Throws std::runtime_error, leaving nothing behind, if the folder cannot be made.
  StagingFolder(const std::vector<std::string>& folders, const std::vector<StagedFile>& files);
  ~StagingFolder();
  StagingFolder(const StagingFolder&) = delete;
  StagingFolder& operator=(const StagingFolder&) = delete;

  const std::string& root() const { return root_; }

 private:
  void remove() noexcept;

  std::string root_;
  std::vector<std::string> made_;  // absolute paths, in removal order (files, then folders deepest first)
  int removal_ = -1;               // its entry in the signal handler's table
};

}  // namespace thinlayer
