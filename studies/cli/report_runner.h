#pragma once
// Runs the HTML report (report/make_report.py) on a results file: DIR/report/index.html.
// The interpreter is the one CMake found (/usr/bin/python3, which sees Debian's
// python3-matplotlib and python3-h5py), or $THINLAYER_PYTHON; the script is the source tree's,
// or $THINLAYER_REPORT_SCRIPT. No shell is involved: the paths are passed as arguments.
#include <string>

namespace thinlayer {

// Throws std::runtime_error when the interpreter is missing or the report fails (its own
// one-line message is on stderr; it leaves no half-written report).
void run_report(const std::string& results_h5, const std::string& out_dir);

}  // namespace thinlayer
