#pragma once
#include <string>
#include <vector>

namespace thinlayer {
// `thinlayer solve ...`: one scene. Returns the process exit status.
int command_solve(const std::vector<std::string>& args);
extern const char* const solve_help;
}  // namespace thinlayer
