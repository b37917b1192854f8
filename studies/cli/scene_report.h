#pragma once
// The report of a scene-file study (`study convergence|validity --scene FILE --out DIR`):
// DIR/report/index.html, about that joint (report/make_report.py draws a results file whose only
// study is a scene study as the joint's report).
#include <string>

namespace thinlayer {

// Runs the report on DIR/results.h5 into DIR/report; says so on stderr unless quiet. A report
// that fails is one line on stderr and leaves the results as they are (they are written).
void report_scene_study(const std::string& dir, bool verbose);

}  // namespace thinlayer
