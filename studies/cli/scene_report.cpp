#include "studies/cli/scene_report.h"

#include <iostream>
#include <stdexcept>

#include "studies/cli/report_runner.h"

namespace thinlayer {

void report_scene_study(const std::string& dir, bool verbose) {
  if (verbose) std::cerr << "[scene] report\n";
  try {
    run_report(dir + "/results.h5", dir + "/report");  // which says "wrote DIR/report/index.html"
  } catch (const std::runtime_error& e) {
    std::cerr << "thinlayer study: the report was not written: " << e.what() << "\n";
  }
}

}  // namespace thinlayer
