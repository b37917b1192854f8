#include "studies/cli/command_validity_map.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <set>

#include "cases/scene/scene_mesh_child.h"
#include "core/io/output_ownership.h"
#include "studies/cli/command_scene.h"
#include "studies/cli/options.h"
#include "studies/cli/report_runner.h"
#include "studies/cli/results_file.h"
#include "studies/drivers/validity_map.h"
#include "studies/tools/scene_distance.h"
#include "studies/parallel/process_group.h"
#include "studies/parallel/spread_command.h"
#include "studies/tools/run_phase.h"
#include "studies/tools/format.h"

namespace thinlayer {

namespace {

// A positive, finite, strictly increasing list (a grid axis), or the default.
std::vector<double> axis(const CLI::App& c, const std::string& option, const NumberList& given_values,
                         std::vector<double> fallback, double upper) {
  if (!given(c, option)) return fallback;
  std::vector<double> v = given_values.values;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (!(v[k] > 0) || !(v[k] < upper) || (k > 0 && !(v[k] > v[k - 1])))
      throw std::invalid_argument("--" + option + ": values in (0, " + plain(upper) + "), increasing");
  return v;
}

}  // namespace

int command_study_validity_map(const CLI::App& c, const StudyArgs& a) {
  ValidityMapOptions options;
  OutputRules rules;
  std::string out_dir, name;
  std::unique_ptr<SceneFileBulk> bulk;
  try {
    require_only(c, {"scene", "out", "quiet", "force", "threads", "tolerance", "max-nodes", "mesh-timeout",
                     "peak-distance", "thickness-ratios", "modulus-ratios", "poisson"},
                 "study validity-map");
    start_mesh_clock(c, a.mesh_timeout);
    if (!given(c, "scene")) throw std::invalid_argument("study validity-map needs --scene FILE.json (the joint to map)");
    options.verbose = !a.quiet;
    if (given(c, "tolerance")) options.tolerance = a.tolerance;
    if (!(options.tolerance > 0) || !(options.tolerance < 1)) throw std::invalid_argument("--tolerance must be in (0, 1)");
    options.threads = given(c, "threads") ? a.threads : 1;
    if (options.threads < 1 || options.threads > 64) throw std::invalid_argument("--threads must be in 1..64");
    if (given(c, "peak-distance")) {
      options.peak_distance = a.peak_distance;
      if (!(options.peak_distance > 0) || std::isinf(options.peak_distance))
        throw std::invalid_argument("--peak-distance must be finite and > 0 (mm)");
    }
    options.t_over_L = axis(c, "thickness-ratios", a.thickness_ratios, options.t_over_L, 1);
    options.E_ratio = axis(c, "modulus-ratios", a.modulus_ratios, options.E_ratio, 1e6);
    if (given(c, "poisson")) {
      options.nu = a.poisson.values;
      for (std::size_t k = 0; k < options.nu.size(); ++k)
        if (!(options.nu[k] > -1 && options.nu[k] < 0.5) || (k > 0 && !(options.nu[k] > options.nu[k - 1])))
          throw std::invalid_argument("--poisson: values in (-1, 0.5), increasing");
    }
    SceneSpec spec = read_scene_spec(a.scene);
    if (given(c, "max-nodes")) {
      if (a.max_nodes < 1) throw std::invalid_argument("--max-nodes must be >= 1");
      spec.max_nodes = static_cast<std::size_t>(a.max_nodes);
    }
    name = spec.name;
    rules = {scene_inputs(spec), a.force};
    out_dir = a.out;
    if (!out_dir.empty() && is_root()) {  // the map's files in DIR, before the map
      check_replaceable(out_dir + "/results.h5", OutputKind::Results, rules.inputs, rules.force);
      check_replaceable(out_dir + "/validity_map_" + name + ".csv", OutputKind::Csv, rules.inputs, rules.force);
      check_report_folder(out_dir + "/report");
    }
    bulk = std::make_unique<SceneFileBulk>(std::move(spec));
    if (options.peak_distance > 0) check_peak_distance(*bulk, options.peak_distance);  // within half a bondline
  } catch (const std::exception& e) {
    if (is_root()) print_message("study", e.what());
    return 2;
  }
  try {
    auto out = open_results_on_root(out_dir, rules);
    if (out_dir.empty()) std::printf("(no --out DIR: the results are printed, not saved)\n");
    const ValidityMapResult r = run_validity_map(*bulk, options, out.get());
    int failed = 0;
    for (const Check& check : r.checks)
      if (!check.pass) {
        ++failed;
        std::printf("FAIL %s: expected %s, got %s\n", check.id.c_str(), check.expected.c_str(), check.got.c_str());
      }
    std::printf("\n%zu checks: %zu passed, %d failed\n", r.checks.size(), r.checks.size() - failed, failed);
    on_root([&] {
      if (!out) return;
      write_checks(*out, r.checks);
      out->commit();
      std::printf("wrote %s and %s/validity_map_%s.csv\n", out->path().c_str(), out_dir.c_str(), name.c_str());
      run_report_keeping(out->path(), out_dir + "/report", {out->path(), out_dir + "/validity_map_" + name + ".csv"});
    });
    return command_status(failed == 0 ? 0 : 1);
  } catch (const std::exception& e) {
    return command_failed("study", e);
  }
}

}  // namespace thinlayer
