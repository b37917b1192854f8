#pragma once
#include <string>
#include <vector>

namespace thinlayer {
// `thinlayer study NAME ...` and `thinlayer verify ...`. Return the process exit status.
int command_study(const std::vector<std::string>& args);
int command_verify(const std::vector<std::string>& args);
extern const char* const study_help;
extern const char* const verify_help;
}  // namespace thinlayer
