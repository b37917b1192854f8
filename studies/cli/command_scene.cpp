#include "studies/cli/command_scene.h"

#include "cases/answer_admissibility.h"
#include "cases/film_admissibility.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <new>
#include <optional>

#include "cases/scene/scene_mesh_child.h"
#include "core/io/output_ownership.h"
#include "core/mesh/meshing_child.h"
#include "core/io/output_target.h"
#include "core/io/vtu_writer.h"
#include "studies/cli/options.h"
#include "studies/cli/results_file.h"
#include "studies/tools/run_phase.h"
#include "studies/cli/report_runner.h"
#include "studies/cli/scene_report.h"
#include "studies/drivers/classification_cost.h"
#include "studies/drivers/scene_file_study.h"
#include "studies/drivers/scene_solve_output.h"
#include "studies/parallel/process_group.h"
#include "studies/tools/format.h"
#include "studies/tools/scene_distance.h"

namespace thinlayer {

namespace {

struct SceneSolveInput : SolveRun {
  std::string scene, mode = "limit";
  std::size_t max_nodes = SceneSpec{}.max_nodes;
  double eps = 0;  // 0: an engineer's glue at its own thickness (checked with the scene)
};

// What applies to a scene file's solve; the bar's and the dovetail's options do not.
const std::set<std::string> scene_solve_options = {"scene", "mode", "eps", "out", "vtu", "json", "verbose",
                                                   "solver", "tolerance", "max-iterations", "omega", "max-nodes", "mesh-timeout",
                                                   "force"};

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
  start_mesh_clock(c, a.mesh_timeout);
  in.mode = given(c, "mode") ? a.mode : "limit";
  if (given(c, "eps")) {  // without it, an engineer's glue's own thickness (checked with the scene)
    in.eps = a.eps;
    if (!(in.eps > 0) || std::isinf(in.eps)) throw std::invalid_argument("--eps must be finite and > 0");
  }
  parse_solve_run(c, a, in);
  return in;
}

void write_results(const std::string& path, const SceneFileScene& scene, const SceneFileBulk& bulk,
                   const OutputRules& rules, const LimitErrorEstimate* estimate) {
  auto out = open_results_file(path, rules);
  write_scene_file_scene(*out, scene, bulk);
  if (estimate) write_limit_error_estimate(*out, scene.record.id, *estimate);
  write_checks(*out, {});
  out->commit();
}

// One line on stderr, the exit status of its kind (out of memory: 2, naming the phase).
int fail(const std::string& command, const std::exception& e, int status) {
  print_message(command, failure_text(e));
  return dynamic_cast<const std::bad_alloc*>(&e) ? 2 : status;
}

}  // namespace

void start_mesh_clock(const CLI::App& c, double given_value) {
  if (given(c, "mesh-timeout") && !(given_value > 0 && given_value <= 1e6))
    throw std::invalid_argument("--mesh-timeout must be in (0, 1e6] seconds");
  set_meshing_wall_clock(given(c, "mesh-timeout") ? given_value : default_mesh_timeout_s);
}

int command_solve_scene(const CLI::App& command, const SolveArgs& args) {
  SceneSolveInput in;
  std::vector<InputFile> inputs;
  std::unique_ptr<SceneFileBulk> bulk;
  try {
    in = parse_solve(command, args);
    RunPhase reading("reading the scene file " + in.scene);
    SceneSpec spec = read_scene_spec(in.scene);
    spec.max_nodes = in.max_nodes;
    // The outputs first: never one of the run's inputs nor each other, never a file thinlayer did
    // not write (unless --force), and writable; all before any work.
    inputs = scene_inputs(spec);
    check_distinct_outputs({{"--out", in.out}, {"--vtu", in.vtu}}, inputs);
    if (!in.out.empty()) check_replaceable(in.out, OutputKind::Results, inputs, in.force);
    if (!in.vtu.empty()) check_replaceable(in.vtu, OutputKind::Vtu, inputs, in.force);
    if (!in.out.empty()) H5Writer probe(in.out);  // abandoned at once: nothing is left behind
    if (!in.vtu.empty()) check_vtu_target(in.vtu);
    RunPhase meshing("meshing and checking the scene " + in.scene);
    bulk = std::make_unique<SceneFileBulk>(std::move(spec));
    check_scene_eps(*bulk, in.mode, in.eps);
    // SPEC 1.3: a load with no path is bad input; a joint that statics proves friction cannot hold
    // fails (exit 1); both proven before any solve, nothing else refused.
    const LoadPath load_path = scene_load_path(*bulk, in.mode, in.eps);
    if (!load_path.no_path.empty()) throw std::invalid_argument(load_path.no_path);
    if (!load_path.friction_overload.empty()) {
      print_message("solve", load_path.friction_overload + "; nothing solved");
      return 1;
    }
  } catch (const std::invalid_argument& e) {
    return fail("solve", e, 2);
  } catch (const OutputError& e) {
    return fail("solve", e, 2);
  } catch (const std::exception& e) {  // gmsh could not mesh the geometry: the input's fault
    return fail("solve", e, 2);
  }
  try {
    std::optional<RunPhase> phase(std::in_place, "solving the " + in.mode + " mode of " + in.scene);
    // Limit mode: SPEC §3 S6's distance to the layer it stands for, from its first-order answer.
    LimitSolveExtras extras;
    extras.first_order = in.mode == "limit";
    const SceneFileScene s = in.mode == "limit" ? solve_scene_file_limit(*bulk, in.solver, in.options, in.eps,
                                                                         default_status_tolerance, false, extras)
                                                : solve_scene_file_layer(*bulk, in.eps, in.solver, in.options);
    std::optional<LimitErrorEstimate> estimate;
    if (in.mode == "limit") estimate = limit_error_estimate(*bulk, s);
    // SPEC 1.3: what the paper's 3 % / 30x rule would have cost, solved beside (limit mode).
    ClassificationCost cost;
    if (in.mode == "limit") cost = classification_cost(*bulk, s, in.eps, in.options);
    if (!in.json) print_scene_solve(*bulk, in.mode, in.eps, s);
    if (!in.json && cost.differs) std::printf("  %s\n", classification_cost_line(*bulk, s, cost).c_str());
    if (!in.json && estimate) {
      const std::vector<ReactionComponent> reactions = reaction_components(bulk->model());
      const bool fixed = std::all_of(reactions.begin(), reactions.end(), [](const ReactionComponent& c) { return c.determinate; });
      print_limit_error_estimate(*estimate, fixed ? determinate_reactions(reactions) : "");
    }
    phase.emplace("writing " + in.out);
    if (!in.out.empty()) write_results(in.out, s, *bulk, {inputs, in.force}, estimate ? &*estimate : nullptr);
    phase.emplace("writing " + in.vtu);
    if (!in.vtu.empty()) write_vtu(in.vtu, s.record, {inputs, in.force});
    if (!in.json && !in.out.empty()) std::printf("  wrote %s\n", in.out.c_str());
    if (!in.json && !in.vtu.empty()) std::printf("  wrote %s\n", in.vtu.c_str());
    if (in.json) {
      nlohmann::json j = nlohmann::json::parse(scene_solve_json(*bulk, in.scene, in.mode, s, in.out, in.vtu, &cost));
      if (estimate) j["limit_error_estimate"] = limit_error_estimate_json(*estimate);
      std::printf("%s\n", j.dump().c_str());
    }
    if (const std::string w = no_load_warning(s); !w.empty()) print_message("solve", w);
    if (const std::string w = film_warning(s.record); !w.empty()) print_message("solve", w);
    if (const std::string w = displacement_warning_line(s.record); !w.empty()) print_message("solve", w);
    if (const std::string w = strain_warning_line(s.record); !w.empty()) print_message("solve", w);
    if (const std::string w = limit_slip_warning_line(s.record); !w.empty()) print_message("solve", w);
    if (!s.report.converged) {
      print_message("solve", s.report.message);
      // What friction alone had to hold, where it did: an estimate that explains the failure.
      for (const FrictionHold& h : scene_friction_estimate(*bulk, in.mode, in.eps))
        print_message("solve", friction_line(h, bulk->spec().units.force));
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
    std::set<std::string> allowed = {"scene", "out", "eps", "tolerance", "threads", "quiet", "max-nodes", "mesh-timeout",
                                     "force", "peak-distance"};
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
    if (given(c, "peak-distance")) {
      options.peak_distance = a.peak_distance;
      if (!(options.peak_distance > 0) || std::isinf(options.peak_distance))
        throw std::invalid_argument("--peak-distance must be finite and > 0 (mm)");
    }
    options.bisection_steps = given(c, "bisection-steps") ? a.bisection_steps : 2;
    if (options.bisection_steps < 0 || options.bisection_steps > 20)
      throw std::invalid_argument("--bisection-steps must be in 0..20");
    RunPhase reading("reading the scene file " + scene);
    SceneSpec spec = read_scene_spec(scene);
    spec.max_nodes = max_nodes(c, a.max_nodes);
    start_mesh_clock(c, a.mesh_timeout);
    rules = {scene_inputs(spec), a.force};
    if (!out_dir.empty()) {  // the study's files in DIR, before the study (its report checks its own folder)
      check_distinct_outputs({{"results.h5", out_dir + "/results.h5"}, {"bondline_fields.csv", out_dir + "/bondline_fields.csv"}},
                             rules.inputs);
      check_replaceable(out_dir + "/results.h5", OutputKind::Results, rules.inputs, rules.force);
      check_replaceable(out_dir + "/bondline_fields.csv", OutputKind::Csv, rules.inputs, rules.force);
      check_report_folder(out_dir + "/report");
    }
    if (given(c, "eps")) {
      spec.eps = a.eps.values;
      for (double e : spec.eps)
        if (!(e > 0) || std::isinf(e)) throw std::invalid_argument("--eps: thicknesses must be finite and > 0");
      if (spec.eps.size() < 3) throw std::invalid_argument("--eps: the convergence study needs at least 3 thicknesses");
    }
    if (!spec.has_layer())
      throw std::invalid_argument("scene '" + spec.name + "' gives a limit law only ('law'): it has no layer mode to study");
    RunPhase meshing("meshing and checking the scene " + scene);
    bulk = std::make_unique<SceneFileBulk>(std::move(spec));
    for (double e : scene_study_grid(*bulk, options)) check_layer_mode(*bulk, e);
    if (options.peak_distance > 0) check_peak_distance(*bulk, options.peak_distance);  // within half a bondline
    // SPEC 1.3: a load with no path is bad input; a joint statics proves friction cannot hold fails
    // (exit 1); judged on the limit mode (the glue's own thickness), before any of the study's solves.
    const LoadPath path = scene_load_path(*bulk, "limit", 0.0);
    if (!path.no_path.empty()) throw std::invalid_argument(path.no_path);
    if (!path.friction_overload.empty()) {
      print_message("study", path.friction_overload + "; nothing solved");
      return 1;
    }
  } catch (const std::exception& e) {
    return fail("study", e, 2);
  }
  try {
    RunPhase studying("running study " + study + " on " + a.scene);
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
      report_scene_study(out_dir, options.verbose);  // DIR/report/index.html: the joint drawn
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
