#include "studies/cli/scene_report.h"

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "studies/cli/report_runner.h"

namespace thinlayer {

void report_scene_study(const std::string& dir, bool verbose) {
  if (verbose) std::cerr << "[scene] report\n";
  try {
    run_report(dir + "/results.h5", dir + "/report");
    std::printf("wrote %s/report/index.html\n", dir.c_str());
  } catch (const std::runtime_error& e) {
    std::cerr << "thinlayer study: the report was not written: " << e.what() << "\n";
  }
}

}  // namespace thinlayer
