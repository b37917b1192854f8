#pragma once
// Which existing file an output may replace (SPEC §4, "Nothing lost").
//
// An output never replaces an input of the same run (the scene file, its geometry or mesh,
// a file the geometry includes): `solve --scene j.json --out j.json` would turn the user's
// scene into HDF5. Nor does it replace an existing file thinlayer did not write, unless the
// user says so with --force: a results file is recognised by the marker at its first byte (the
// HDF5 user block H5Writer reserves, read as raw bytes: an existing file is never parsed by
// HDF5 here, where a damaged one took the run down with a signal), a VTU or CSV by the marker
// its writer puts at its top, summary.json by its "layout" key (or, written before that key,
// its "checks" and "timings"; at most 1 MiB is read). Anything else there (the user's notes,
// another tool's HDF5, a text file named results.h5, a results file written before the marker)
// is refused. The comparison is of the files themselves (device and inode, after the target's
// symbolic links): a link to the scene, or a second name of it, is the scene.
//
// Outputs are distinct, whatever --force says: two outputs of one run naming one file (after
// every symbolic link, a dangling one included: `--out O/r.h5 --vtu O/ln` with O/ln -> r.h5)
// would each overwrite the other.
#include <string>
#include <vector>

namespace thinlayer {

enum class OutputKind { Results, Vtu, Summary, Csv };

// Markers of thinlayer's own files.
constexpr const char* results_layout_name = "thinlayer-results";  // root attribute `layout`
// A results file's first bytes (its HDF5 user block, core/io/h5_writer.h).
constexpr const char* results_marker = "thinlayer-results\n";
constexpr const char* vtu_marker = "<!-- written by thinlayer -->";  // the VTU's second line
constexpr const char* csv_marker = "# thinlayer";                   // how a CSV's first line starts
constexpr const char* summary_layout_name = "thinlayer-summary";    // summary.json's "layout"

struct InputFile {
  std::string path;
  std::string what;  // "the scene file", "its geometry", ...
};

// Throws OutputError "cannot write 'PATH': ..." (exit status 2), touching nothing, when the
// file a write to `path` would replace is one of `inputs`, or exists and is not thinlayer's
// own output of `kind` (unless `force`).
void check_replaceable(const std::string& path, OutputKind kind, const std::vector<InputFile>& inputs, bool force);

// What a run's outputs may replace: never one of its inputs; an existing file thinlayer did not
// write only with --force. Judged before the work and again at the moment each output is written
// (a file saved at an output's path while the run works is never replaced: SPEC §4).
struct OutputRules {
  std::vector<InputFile> inputs;
  bool force = false;
};

// Writes `text` to `path` atomically (core/io/output_target.h), refused as check_replaceable
// says at the moment of the write, the target then untouched.
void write_output_text(const std::string& path, OutputKind kind, const OutputRules& rules, const std::string& text);

// The file a write to `path` creates or replaces, as one string for all its names: the end of
// its chain of symbolic links (dangling or not), in its folder's canonical path. Throws
// OutputError as resolve_output_target does.
std::string output_identity(const std::string& path);

// An output, as the user named it: the option ("--out") and the path ("" : not given).
struct OutputFile {
  std::string what;
  std::string path;
};

// Throws OutputError "cannot write 'PATH': ..." when two of `outputs` are one file, or one is an
// input of the run (output_identity against the inputs' canonical paths).
void check_distinct_outputs(const std::vector<OutputFile>& outputs, const std::vector<InputFile>& inputs);

}  // namespace thinlayer
