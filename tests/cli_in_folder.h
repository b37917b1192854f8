#pragma once
// Test helper: runs the command line (THINLAYER_CLI) with `args`, its stdout discarded and its stderr
// kept in the test's folder; returns its exit status (-1 if it did not exit) and its stderr in `err`.
#include <cstdlib>
#include <string>
#include <sys/wait.h>

#include "tests/scene_folder.h"
#include "tests/text_file.h"

inline int run_cli(const std::string& args, const SceneFolder& f, std::string& err) {
  const std::string path = (f.path / "err.txt").string();
  const int raw = std::system((std::string(THINLAYER_CLI) + " " + args + " >/dev/null 2>" + path).c_str());
  err = read_text_file(path);
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}
