#pragma once
// Where an output file really goes, and the temporary files on the way there (SPEC §4,
// "Nothing lost").
//
// Every writer of thinlayer (HDF5, VTU, summary.json) writes a temporary file beside the
// target and renames it onto the target once complete. Two rules make that safe:
//   - a symbolic link is followed to its final target, which is replaced (the link stays a
//     link: a user who pointed results.h5 at an archive keeps that arrangement);
//   - a target that exists and is not a regular file (a directory, a FIFO, a device) is
//     refused: renaming onto it would destroy it (as root, even /dev/full).
// Temporary files are registered while they exist; on SIGINT or SIGTERM the handler that
// install_signal_cleanup() sets removes them before the process dies, so an interrupted run
// leaves the previous result as it was and no `*.tmp.*` beside it.
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace thinlayer {

// An output that cannot be written: bad input in the sense of SPEC §4 (exit status 2).
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The path a write to `path` must replace: `path` itself, or the end of its chain of
// symbolic links (relative links resolved against their own directory). Throws OutputError
// naming `path` if that target exists and is not a regular file, or the chain is a loop.
std::string resolve_output_target(const std::string& path);

// A fresh name beside `target` ("<target>.tmp.<pid>.<n>"), unique per call and per process; for a
// name too long to take the suffix (NAME_MAX, 255 bytes, in all), the name's first bytes and the suffix.
std::string temporary_name_beside(const std::string& target);

// The signal handler removes every registered path (at most 64 at a time; paths up to 4095
// bytes). Registering more throws std::runtime_error.
void register_temporary(const std::string& path);
void unregister_temporary(const std::string& path);

// Paths the handler removes besides the temporary files: the private staging folder of a scene's
// geometry (cases/scene/scene_sources.h), the output folders a run made (SPEC §4: no empty output
// folder is left behind, a signal included). A File is unlinked; a Folder is removed only if it
// is empty, so a user's file in it is never touched. Given in removal order (files first, the
// deepest folders first). At most 16 lists at a time, 256 KiB of paths each; more throws
// std::runtime_error. The owner removes its paths itself when done, then unregisters them.
struct Removal {
  enum Kind : char { File = 'f', Folder = 'd' } kind = File;
  std::string path;
};
int register_removals(const std::vector<Removal>& paths);
void unregister_removals(int handle);  // -1: none

// SIGINT, SIGTERM, SIGHUP and SIGPIPE: remove the registered temporary files and removals, then
// die of the same signal (so a shell sees the usual status 130 / 143). Also forwards the signal to a child set by
// set_signal_child (the report's interpreter), which cleans up its own files.
void install_signal_cleanup();
void set_signal_child(int pid);  // 0: none

// Writes `text` to `path` atomically (through a symbolic link, never onto a non-regular
// file), flushed to disk. Throws OutputError naming `path`; the target is then untouched.
// `check_before_rename` (if given) runs once the temporary file is complete, just before it
// replaces the target: what may be replaced is judged at the moment of writing (it throws to refuse).
void write_text_atomically(const std::string& path, const std::string& text,
                           const std::function<void()>& check_before_rename = {});

}  // namespace thinlayer
