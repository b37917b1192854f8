#pragma once
// Which existing file an output may replace (SPEC §4, "Nothing lost").
//
// An output never replaces an input of the same run (the scene file, its geometry or mesh,
// a file the geometry includes): `solve --scene j.json --out j.json` would turn the user's
// scene into HDF5. Nor does it replace an existing file thinlayer did not write, unless the
// user says so with --force: a results file is recognised by its root attribute `layout`
// ("thinlayer-results"), a VTU or CSV by the marker its writer puts at its top, summary.json
// by its "layout" key (or, written before that key, its "checks" and "timings"). Anything
// else there (the user's notes, another tool's HDF5, a text file named results.h5) is
// refused. The comparison is of the files themselves (device and inode, after the target's
// symbolic links): a link to the scene, or a second name of it, is the scene.
#include <string>
#include <vector>

namespace thinlayer {

enum class OutputKind { Results, Vtu, Summary, Csv };

// Markers of thinlayer's own files.
constexpr const char* results_layout_name = "thinlayer-results";  // root attribute `layout`
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

}  // namespace thinlayer
