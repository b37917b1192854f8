#include "studies/cli/results_file.h"

#include <filesystem>
#include <stdexcept>

#include <unistd.h>

#include "core/io/output_target.h"
#include "studies/cli/environment.h"

namespace thinlayer {

std::unique_ptr<H5Writer> open_results_file(const std::string& file, const OutputRules& rules) {
  check_replaceable(file, OutputKind::Results, rules.inputs, rules.force);
  auto out = std::make_unique<H5Writer>(file);
  out->replace_only_under(rules);
  out->attr("/", "layout", std::string(results_layout));
  out->attr("/", "layout_version", results_layout_version);
  write_environment(*out);
  return out;
}

std::unique_ptr<H5Writer> open_results(const std::string& dir, const OutputRules& rules) {
  if (dir.empty()) return nullptr;
  std::vector<std::string> made;  // deepest first
  for (std::filesystem::path p = std::filesystem::absolute(dir); !p.empty() && !std::filesystem::exists(p);
       p = p.parent_path())
    made.push_back(p.string());
  // Known to the signal handler before they exist: a SIGTERM in the first second of a study
  // left the folder behind (SPEC §4). Only empty folders are removed.
  std::vector<Removal> removals;
  for (const std::string& folder : made) removals.push_back({Removal::Folder, folder});
  const int removal = register_removals(removals);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  try {
    if (ec) throw OutputError("cannot create output directory '" + dir + "': " + ec.message());
    auto out = open_results_file(dir + "/results.h5", rules);
    out->remove_if_abandoned(made);
    unregister_removals(removal);
    return out;
  } catch (...) {
    for (const std::string& folder : made) ::rmdir(folder.c_str());
    unregister_removals(removal);
    throw;
  }
}

void write_scene_file(const std::string& file, const SceneRecord& record, const OutputRules& rules) {
  auto out = open_results_file(file, rules);
  write_scene(*out, record);
  write_checks(*out, {});
  out->commit();
}

void write_checks(H5Writer& out, const std::vector<Check>& checks) {
  std::vector<std::string> id, expected, got, tolerance;
  std::vector<int> pass;
  for (const Check& c : checks) {
    id.push_back(c.id);
    pass.push_back(c.pass ? 1 : 0);
    expected.push_back(c.expected);
    got.push_back(c.got);
    tolerance.push_back(c.tolerance);
  }
  out.dataset("/checks/id", id);
  out.dataset("/checks/pass", pass);
  out.dataset("/checks/expected", expected);
  out.dataset("/checks/got", got);
  out.dataset("/checks/tolerance", tolerance);
}

}  // namespace thinlayer
