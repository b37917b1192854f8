#pragma once
// The user's own joint on the command line (SPEC §5):
//   thinlayer solve --scene FILE.json [--mode limit|layer] [--eps E] [--out F.h5] [--vtu F.vtu] [--json]
//   thinlayer study convergence|validity --scene FILE.json [--out DIR] ...
// Exit status as every command: 0 success, 1 a solve did not converge or a check failed,
// 2 bad input (the scene file, its geometry, an option) or an output that cannot be written —
// found before anything is written.
#include <string>

#include "studies/cli/command_solve.h"
#include "studies/cli/command_study.h"

namespace thinlayer {

// `solve` given --scene.
int command_solve_scene(const CLI::App& command, const SolveArgs& args);
// `study` given --scene; study: "convergence" or "validity" (any other is refused).
int command_study_scene(const std::string& study, const CLI::App& command, const StudyArgs& args);

// --mesh-timeout S (0 < S <= 1e6 s, default 600) as the command's one meshing clock
// (core/mesh/meshing_child.h: it bounds all the meshing of the command). Throws
// std::invalid_argument for a value out of range.
void start_mesh_clock(const CLI::App& command, double given_value);

}  // namespace thinlayer
