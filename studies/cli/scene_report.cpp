#include "studies/cli/scene_report.h"

#include <iostream>
#include <stdexcept>

#include "studies/cli/report_runner.h"

namespace thinlayer {

void report_scene_study(const std::string& dir, bool verbose) {
  if (verbose) std::cerr << "[scene] report\n";
  // It says "wrote DIR/report/index.html"; refused, it throws OutputError naming what is kept.
  run_report_keeping(dir + "/results.h5", dir + "/report", {dir + "/results.h5", dir + "/bondline_fields.csv"});
}

}  // namespace thinlayer
