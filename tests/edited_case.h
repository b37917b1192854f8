#pragma once
// Test helper: a shipped scene of cases/<name>/ (<name>.json and its <name>.geo) copied into a test's
// folder with each (from, to) replaced once in its JSON — the scene a test states by its edits.
#include <string>
#include <utility>
#include <vector>

#include "tests/scene_folder.h"
#include "tests/text_file.h"

inline std::string edited_case(const SceneFolder& f, const std::string& name,
                               const std::vector<std::pair<std::string, std::string>>& edits) {
  const std::string dir = std::string(THINLAYER_CASES_DIR) + "/" + name + "/";
  std::string json = read_text_file(dir + name + ".json");
  for (const auto& [from, to] : edits) {
    EXPECT_NE(json.find(from), std::string::npos) << from;
    if (json.find(from) != std::string::npos) json.replace(json.find(from), from.size(), to);
  }
  f.write(name + ".geo", read_text_file(dir + name + ".geo"));
  return f.write("scene.json", json);
}
