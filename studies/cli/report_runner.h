#pragma once
// Runs the HTML report (report/make_report.py) on a results file: DIR/report/index.html.
// The interpreter is the one CMake found (/usr/bin/python3, which sees Debian's
// python3-matplotlib and python3-h5py), or $THINLAYER_PYTHON; the script is the source tree's,
// or $THINLAYER_REPORT_SCRIPT. No shell is involved: the paths are passed as arguments.
#include <string>
#include <vector>

namespace thinlayer {

// Throws std::runtime_error when the interpreter is missing or the report fails (its own
// one-line message is on stderr; it leaves no half-written report).
void run_report(const std::string& results_h5, const std::string& out_dir);

// Before a study's work: throws OutputError (exit 2) with the report's own reason when it would
// refuse to write into `out_dir` (a file in the way that no report wrote, an index.html of the
// user's, a folder it cannot write: report/report_folder.py). Writes nothing.
void check_report_folder(const std::string& out_dir);

// The report of a run whose files are written (`kept`): a report that fails or is refused throws
// OutputError (exit 2), one line with the report's reason and the files kept.
void run_report_keeping(const std::string& results_h5, const std::string& out_dir, const std::vector<std::string>& kept);

}  // namespace thinlayer
