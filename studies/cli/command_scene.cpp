#include "studies/cli/command_scene.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "cases/scene/scene_mesh_child.h"
#include "core/io/output_ownership.h"
#include "core/io/output_target.h"
#include "core/io/vtu_writer.h"
#include "studies/tools/format.h"
#include "studies/cli/options.h"
#include "studies/parallel/process_group.h"
#include "studies/cli/results_file.h"
#include "studies/drivers/scene_file_study.h"

namespace thinlayer {

namespace {

struct SceneSolveInput : SolveRun {
  std::string scene, mode = "limit";
  std::size_t max_nodes = SceneSpec{}.max_nodes;
  double eps = 0;
};

// What applies to a scene file's solve; the bar's and the dovetail's options do not.
const std::set<std::string> scene_solve_options = {"scene", "mode", "eps", "out", "vtu", "json", "verbose",
                                                   "solver", "tolerance", "max-iterations", "omega", "max-nodes", "force"};

// --max-nodes N (N >= 1), or the default.
std::size_t max_nodes(const CLI::App& c, long long given_value) {
  if (!given(c, "max-nodes")) return SceneSpec{}.max_nodes;
  if (given_value < 1) throw std::invalid_argument("--max-nodes must be >= 1");
  return static_cast<std::size_t>(given_value);
}

SceneSolveInput parse_solve(const CLI::App& c, const SolveArgs& a) {
  require_only(c, scene_solve_options, "a scene file (--scene)");
  SceneSolveInput in;
  in.scene = a.scene;
  if (in.scene.empty()) throw std::invalid_argument("--scene needs a file");
  in.max_nodes = max_nodes(c, a.max_nodes);
  in.mode = given(c, "mode") ? a.mode : "limit";
  if (in.mode == "layer") {
    if (!given(c, "eps")) throw std::invalid_argument("layer mode needs --eps");
    in.eps = a.eps;
    if (!(in.eps > 0) || std::isinf(in.eps)) throw std::invalid_argument("--eps must be finite and > 0");
  } else if (given(c, "eps")) {
    throw std::invalid_argument("--eps applies to the layer mode only");
  }
  parse_solve_run(c, a, in);
  return in;
}

nlohmann::json counts_json(const StatusCount& c) { return {{"gap", c.gap}, {"slide", c.slide}, {"stick", c.stick}}; }

std::string summary_line(const SceneSolveInput& in, const SceneRecord& record, const SolveReport& report) {
  nlohmann::json counts;
  for (const InterfaceFields& f : record.interfaces) counts[f.name] = counts_json(f.counts());
  if (!record.combined_status.empty()) {
    std::vector<NodeStatus> combined;
    for (int v : record.combined_status) combined.push_back(static_cast<NodeStatus>(v));
    counts["combined"] = counts_json(count_statuses(combined));
  }
  const nlohmann::json j = {
      {"scene", record.id},
      {"case", record.text.at("case")},
      {"scene_file", in.scene},
      {"mode", in.mode},
      {"law_case", record.text.at("law_case")},
      {"solver", report.solver},
      {"converged", report.converged},
      {"stop_cause", to_string(report.stop_cause)},
      {"iterations", report.iterations},
      {"residual", {{"value", report.residual.value()}, {"interface", report.residual.interface},
                    {"bulk", report.residual.bulk}, {"tolerance", report.tolerance}}},
      {"counts", counts},
      {"times_s", {{"solve", report.wall_time_s}, {"setup", record.numbers.at("setup_time_s")},
                   {"meshing", record.numbers.at("meshing_time_s")}}},
      {"out", in.out.empty() ? nullptr : nlohmann::json(in.out)},
      {"vtu", in.vtu.empty() ? nullptr : nlohmann::json(in.vtu)},
  };
  return j.dump();
}

void print_counts(const char* what, const StatusCount& c) {
  std::printf("  %-9s gap %3d  slide %3d  stick %3d\n", what, c.gap, c.slide, c.stick);
}

void print_scene(const SceneFileBulk& bulk, const SceneSolveInput& in, const SceneFileScene& s) {
  const SceneSpec& spec = bulk.spec();
  const InterfaceLaw law = spec.limit_law();
  std::printf("scene %s (%s), %s mode%s; limit law: Table 1 case %c (lambda_bar %g, mu_bar %g daN/mm^3, f %g)\n",
              spec.name.c_str(), spec.file.c_str(), in.mode.c_str(), in.mode == "layer" ? (" at eps " + plain(in.eps) + " mm").c_str() : "",
              law.table1_case(), law.lambda_bar, law.mu_bar, law.friction);
  std::printf("  meshes:");
  for (std::size_t b = 0; b < spec.bodies.size(); ++b)
    std::printf(" %s %d nodes%s", spec.bodies[b].name.c_str(), bulk.meshes().bodies[b].num_nodes(),
                bulk.model().bodies[b].floating ? " (held by contact alone)" : "");
  std::printf("; %zu nodes on S; meshed in %.3f s\n", bulk.interface_nodes().plus.size(), bulk.meshes().meshing_time_s);
  if (in.mode == "limit") {
    print_counts("S", s.limit);
  } else {
    const MeshQuality& q = s.layer_quality;
    std::printf("  layer: %d Q1 cells, angles %.1f..%.1f deg, aspect ratio up to %.3g\n", q.cells, q.min_angle_deg,
                q.max_angle_deg, q.max_aspect_ratio);
    print_counts("S+", s.counts.plus_face);
    print_counts("S-", s.counts.minus_face);
    print_counts("combined", s.counts.combined);
  }
  const SolveReport& r = s.report;
  const std::string outcome = r.converged ? "converged" : std::string("NOT converged (") + to_string(r.stop_cause) + ")";
  std::printf("  %s after %d iterations; residual %.3e (interface %.3e, bulk %.3e), tolerance %.0e\n", outcome.c_str(),
              r.iterations, r.residual.value(), r.residual.interface, r.residual.bulk, r.tolerance);
  std::printf("  time: solve %.4f s, setup %.4f s\n  reactions (daN/mm):", r.wall_time_s, s.record.numbers.at("setup_time_s"));
  for (const auto& [name, R] : s.record.reactions) std::printf(" %s (%.6g, %.6g)", name.c_str(), R.x(), R.y());
  std::printf("\n");
}


// One line on stderr, the exit status of its kind.
int fail(const std::string& command, const std::exception& e, int status) {
  std::cerr << "thinlayer " << command << ": " << e.what() << "\n";
  return status;
}

}  // namespace

int command_solve_scene(const CLI::App& command, const SolveArgs& args) {
  SceneSolveInput in;
  std::vector<InputFile> inputs;
  std::unique_ptr<SceneFileBulk> bulk;
  try {
    in = parse_solve(command, args);
    SceneSpec spec = read_scene_spec(in.scene);
    spec.max_nodes = in.max_nodes;
    // The outputs first: never one of the run's inputs, never a file thinlayer did not write
    // (unless --force), and writable; all before any work.
    inputs = scene_inputs(spec);
    if (!in.out.empty()) check_replaceable(in.out, OutputKind::Results, inputs, in.force);
    if (!in.vtu.empty()) check_replaceable(in.vtu, OutputKind::Vtu, inputs, in.force);
    if (!in.out.empty()) H5Writer probe(in.out);  // abandoned at once: nothing is left behind
    if (!in.vtu.empty()) check_vtu_target(in.vtu);
    bulk = std::make_unique<SceneFileBulk>(std::move(spec));
    if (in.mode == "layer") check_layer_mode(*bulk, in.eps);
  } catch (const std::invalid_argument& e) {
    return fail("solve", e, 2);
  } catch (const OutputError& e) {
    return fail("solve", e, 2);
  } catch (const std::exception& e) {  // gmsh could not mesh the geometry: the input's fault
    return fail("solve", e, 2);
  }
  try {
    const SceneFileScene s = in.mode == "limit" ? solve_scene_file_limit(*bulk, in.solver, in.options)
                                                : solve_scene_file_layer(*bulk, in.eps, in.solver, in.options);
    if (!in.json) print_scene(*bulk, in, s);
    if (!in.out.empty()) write_scene_file(in.out, s.record, {inputs, in.force});
    if (!in.vtu.empty()) write_vtu(in.vtu, s.record);
    if (!in.json && !in.out.empty()) std::printf("  wrote %s\n", in.out.c_str());
    if (!in.json && !in.vtu.empty()) std::printf("  wrote %s\n", in.vtu.c_str());
    if (in.json) std::printf("%s\n", summary_line(in, s.record, s.report).c_str());
    if (!s.report.converged) {
      std::cerr << "thinlayer solve: " << s.report.message << "\n";
      return 1;
    }
    return 0;
  } catch (const std::invalid_argument& e) {
    return fail("solve", e, 2);
  } catch (const OutputError& e) {
    return fail("solve", e, 2);
  } catch (const std::exception& e) {
    return fail("solve", e, 1);
  }
}

int command_study_scene(const std::string& study, const CLI::App& c, const StudyArgs& a) {
  SceneStudyOptions options;
  OutputRules rules;
  std::string out_dir;
  std::unique_ptr<SceneFileBulk> bulk;
  try {
    if (study != "convergence" && study != "validity")
      throw std::invalid_argument("--scene applies to study convergence and study validity only");
    if (!refuse_unless_one_process("study " + study + " --scene")) return 2;
    std::set<std::string> allowed = {"scene", "out", "eps", "tolerance", "threads", "quiet", "max-nodes", "force"};
    if (study == "validity") allowed.insert("bisection-steps");
    require_only(c, allowed, "study " + study + " --scene");
    const std::string scene = a.scene;
    if (scene.empty()) throw std::invalid_argument("--scene needs a file");
    out_dir = a.out;
    options.validity = study == "validity";
    options.verbose = !a.quiet;
    if (given(c, "tolerance")) options.tolerance = a.tolerance;
    if (!(options.tolerance > 0) || !(options.tolerance < 1)) throw std::invalid_argument("--tolerance must be in (0, 1)");
    options.threads = given(c, "threads") ? a.threads : 2;
    if (options.threads < 1 || options.threads > 64) throw std::invalid_argument("--threads must be in 1..64");
    options.bisection_steps = given(c, "bisection-steps") ? a.bisection_steps : 2;
    if (options.bisection_steps < 0 || options.bisection_steps > 20)
      throw std::invalid_argument("--bisection-steps must be in 0..20");
    SceneSpec spec = read_scene_spec(scene);
    spec.max_nodes = max_nodes(c, a.max_nodes);
    rules = {scene_inputs(spec), a.force};
    if (!out_dir.empty()) check_replaceable(out_dir + "/results.h5", OutputKind::Results, rules.inputs, rules.force);
    if (given(c, "eps")) {
      spec.eps = a.eps.values;
      for (double e : spec.eps)
        if (!(e > 0) || std::isinf(e)) throw std::invalid_argument("--eps: thicknesses must be finite and > 0");
      if (spec.eps.size() < 3) throw std::invalid_argument("--eps: the convergence study needs at least 3 thicknesses");
    }
    if (!spec.has_layer())
      throw std::invalid_argument("scene '" + spec.name + "' gives a limit law only ('law'): it has no layer mode to study");
    bulk = std::make_unique<SceneFileBulk>(std::move(spec));
    for (double e : bulk->spec().eps.empty() ? options.eps : bulk->spec().eps) check_layer_mode(*bulk, e);
  } catch (const std::exception& e) {
    return fail("study", e, 2);
  }
  try {
    auto out = open_results(out_dir, rules);
    if (out_dir.empty()) std::printf("(no --out DIR: the results are printed, not saved)\n");
    const SceneStudyResult r = run_scene_study(*bulk, options, out.get());
    int failed = 0;
    for (const Check& c : r.checks)
      if (!c.pass) {
        ++failed;
        std::printf("FAIL %s: expected %s, got %s\n", c.id.c_str(), c.expected.c_str(), c.got.c_str());
      }
    std::printf("\n%zu checks: %zu passed, %d failed\n", r.checks.size(), r.checks.size() - failed, failed);
    if (out) {
      write_checks(*out, r.checks);
      out->commit();
      std::printf("wrote %s\n", out->path().c_str());
    }
    return failed == 0 ? 0 : 1;
  } catch (const std::invalid_argument& e) {
    return fail("study", e, 2);
  } catch (const OutputError& e) {
    return fail("study", e, 2);
  } catch (const std::exception& e) {
    return fail("study", e, 1);
  }
}

}  // namespace thinlayer
