#pragma once
// Solved scenes kept on disk between runs, so that a long study can be stopped (SIGTERM, Ctrl-C,
// a reboot) and started again without solving a scene twice: a folder with one file per scene,
// written by the process that solved it the moment it is solved (atomically: a temporary file
// renamed, core/io/output_target.h), so a stop loses at most the scenes under way.
//
// A file holds what a study needs to decide whether to reuse the scene and to use it:
//   the scene's full definition (every field that changes its result, canonical text: the key),
//   the solver's identity (core/solvers/solver_revision.h), how its run ended (a scene that ran
//   past its wall-time cap or crashed is stored too, so that a restart does not run it again
//   unless asked), a one-line message, the solve's stop cause, the run's wall time, and the scene itself as bytes
//   (core/io/bytes.h: read back bit for bit).
// Layout: the marker line "thinlayer-scene-store 2\n", those fields as bytes, and an FNV-1a
// checksum of everything before it. An existing file is parsed with bounds-checked reads only
// (it is an existing output: SPEC §4, never parsed where a crash would take the run down).
#include <optional>
#include <stdexcept>
#include <string>

namespace thinlayer {

struct StoredScene {
  std::string definition;  // the key: the scene's definition, as the study writes it
  std::string solver;      // e.g. "fast r1"
  std::string ending;      // "answered" | "capped" | "threw" | "crashed" (studies/parallel/capped_child.h)
  std::string message;     // why it did not answer; empty if it did
  std::string stop;        // "answered": the solve's stop cause ("converged", "round-off floor", "iteration cap", ...)
  double seconds = 0;      // wall time of its run
  double cpu_seconds = 0;  // CPU time of its run
  std::string scene;       // "answered": the scene's bytes; else empty
};

// A file in the store that is not one thinlayer wrote (its first line is not the marker): never
// replaced (SPEC §4: nothing lost). Bad input, exit status 2.
struct ForeignStoreFile : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class SceneStore {
 public:
  explicit SceneStore(std::string folder) : folder_(std::move(folder)) {}
  const std::string& folder() const { return folder_; }

  // The file of a scene: `name` (letters, digits, '.', '-', '_' only) + ".scene" in the folder.
  std::string path_of(const std::string& name) const;

  // The stored scene, or nothing when there is no such file or it is damaged (a thinlayer file
  // cut short or altered: its checksum fails; or written in another layout of the store) —
  // `damaged` then says so, and the scene is solved again and the file replaced. Throws ForeignStoreFile for a file that is not a store file
  // (or not a regular file).
  std::optional<StoredScene> read(const std::string& name, std::string* damaged = nullptr) const;

  // Writes the scene's file atomically, creating the folder if needed. Throws OutputError.
  void write(const std::string& name, const StoredScene& scene) const;

 private:
  std::string folder_;
};

}  // namespace thinlayer
