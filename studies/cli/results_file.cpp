#include "studies/cli/results_file.h"

#include <filesystem>
#include <stdexcept>

#include "core/io/output_target.h"
#include "studies/cli/environment.h"

namespace thinlayer {

std::unique_ptr<H5Writer> open_results_file(const std::string& file) {
  auto out = std::make_unique<H5Writer>(file);
  out->attr("/", "layout", std::string(results_layout));
  out->attr("/", "layout_version", results_layout_version);
  write_environment(*out);
  return out;
}

std::unique_ptr<H5Writer> open_results(const std::string& dir) {
  if (dir.empty()) return nullptr;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw OutputError("cannot create output directory '" + dir + "': " + ec.message());
  return open_results_file(dir + "/results.h5");
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
