#pragma once
// Solves a scene of S5's generator (studies/tools/scene_generator.h) in layer mode with the fast
// solver, from rest, with the given setup: what the random-scene driver and its test report.
#include <string>

#include "core/io/scene_record.h"
#include "core/solvers/solve_report.h"
#include "studies/tools/scene_generator.h"

namespace thinlayer {

struct GeneratedOutcome {
  GeneratedScene scene;
  double eps = 0;              // the thickness solved (a scene file's: fraction × its thickest, mm)
  SolveReport report;
  SceneRecord record;
  double setup_s = 0;          // factorisations and condensation
  double meshing_s = 0;        // meshing and assembly, not part of the solve
  int interface_nodes = 0;     // nodes on S (a face of the layer)
};

// `cases_dir`: the folder of the shipped scene files (THINLAYER_CASES_DIR).
GeneratedOutcome solve_generated(const GeneratedScene& scene, const SolverOptions& options, const std::string& cases_dir);

}  // namespace thinlayer
