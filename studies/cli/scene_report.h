#pragma once
// The report of a scene-file study (`study convergence|validity --scene FILE --out DIR`):
// DIR/report/index.html, about that joint (report/make_report.py draws a results file whose only
// study is a scene study as the joint's report).
#include <string>

namespace thinlayer {

// Runs the report on DIR/results.h5 into DIR/report; says so on stderr unless quiet. A report
// that fails or is refused throws OutputError (exit 2: one line naming the files kept, which are
// written). Its folder is checked before the study (check_report_folder, report_runner.h).
void report_scene_study(const std::string& dir, bool verbose);

}  // namespace thinlayer
