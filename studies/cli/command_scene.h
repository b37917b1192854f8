#pragma once
// The user's own joint on the command line (SPEC §5):
//   thinlayer solve --scene FILE.json [--mode limit|layer] [--eps E] [--out F.h5] [--vtu F.vtu] [--json]
//   thinlayer study convergence|validity --scene FILE.json [--out DIR] ...
// Exit status as every command: 0 success, 1 a solve did not converge or a check failed,
// 2 bad input (the scene file, its geometry, an option) or an output that cannot be written —
// found before anything is written.
#include <string>
#include <vector>

namespace thinlayer {

// Whether the arguments name a scene file (--scene X or --scene=X).
bool names_scene(const std::vector<std::string>& argv);

int command_solve_scene(const std::vector<std::string>& argv);
// study: "convergence" or "validity"; argv: the arguments after the study's name.
int command_study_scene(const std::string& study, const std::vector<std::string>& argv);

}  // namespace thinlayer
