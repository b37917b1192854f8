#include "studies/cli/command_scene.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "core/io/output_target.h"
#include "core/io/vtu_writer.h"
#include "studies/cli/args.h"
#include "studies/tools/format.h"
#include "studies/cli/options.h"
#include "studies/parallel/process_group.h"
#include "studies/cli/results_file.h"
#include "studies/drivers/scene_file_study.h"
#include "studies/drivers/scene_solve_output.h"
#include "studies/cli/scene_report.h"

namespace thinlayer {

namespace {

struct SceneSolveInput {
  std::string scene, mode = "limit", out, vtu;
  double eps = 0;
  bool json = false;
  SolverKind solver = SolverKind::Fast;
  SolverOptions options;
};

SceneSolveInput parse_solve(const std::vector<std::string>& argv) {
  const Args args(argv, {"scene", "mode", "eps", "out", "vtu", "solver", "tolerance", "max-iterations", "omega"},
                  {"json", "verbose"});
  SceneSolveInput in;
  in.scene = args.text("scene", "");
  if (in.scene.empty()) throw std::invalid_argument("--scene needs a file");
  in.mode = args.text("mode", "limit");
  if (in.mode != "limit" && in.mode != "layer") throw std::invalid_argument("unknown mode '" + in.mode + "' (expected limit or layer)");
  if (args.has("eps")) {  // without it, an engineer's glue's own thickness (checked with the scene)
    in.eps = args.number("eps", 0);
    if (!(in.eps > 0) || std::isinf(in.eps)) throw std::invalid_argument("--eps must be finite and > 0");
  }
  in.solver = parse_solver(args.text("solver", "fast"));
  in.options = parse_solver_options(args);
  in.options.verbose = args.has("verbose");
  in.json = args.has("json");
  in.out = args.text("out", "");
  in.vtu = args.text("vtu", "");
  auto target = [](const std::string& p) { return std::filesystem::weakly_canonical(std::filesystem::absolute(p)); };
  if (!in.out.empty() && !in.vtu.empty() && target(in.out) == target(in.vtu))
    throw std::invalid_argument("--out and --vtu name the same file");
  return in;
}

void write_results(const std::string& path, const SceneFileScene& scene, const SceneFileBulk& bulk) {
  auto out = open_results_file(path);
  write_scene_file_scene(*out, scene, bulk);
  write_checks(*out, {});
  out->commit();
}

// One line on stderr, the exit status of its kind.
int fail(const std::string& command, const std::exception& e, int status) {
  std::cerr << "thinlayer " << command << ": " << e.what() << "\n";
  return status;
}

}  // namespace

bool names_scene(const std::vector<std::string>& argv) {
  for (const std::string& a : argv)
    if (a == "--scene" || a.rfind("--scene=", 0) == 0) return true;
  return false;
}

int command_solve_scene(const std::vector<std::string>& argv) {
  SceneSolveInput in;
  std::unique_ptr<SceneFileBulk> bulk;
  try {
    in = parse_solve(argv);
    if (!in.out.empty()) H5Writer probe(in.out);  // abandoned at once: nothing is left behind
    if (!in.vtu.empty()) check_vtu_target(in.vtu);
    bulk = std::make_unique<SceneFileBulk>(read_scene_spec(in.scene));
    check_scene_eps(*bulk, in.mode, in.eps);
  } catch (const std::invalid_argument& e) {
    return fail("solve", e, 2);
  } catch (const OutputError& e) {
    return fail("solve", e, 2);
  } catch (const std::exception& e) {  // gmsh could not mesh the geometry: the input's fault
    return fail("solve", e, 2);
  }
  try {
    const SceneFileScene s = in.mode == "limit" ? solve_scene_file_limit(*bulk, in.solver, in.options, in.eps)
                                                : solve_scene_file_layer(*bulk, in.eps, in.solver, in.options);
    if (!in.json) print_scene_solve(*bulk, in.mode, in.eps, s);
    if (!in.out.empty()) write_results(in.out, s, *bulk);
    if (!in.vtu.empty()) write_vtu(in.vtu, s.record);
    if (!in.json && !in.out.empty()) std::printf("  wrote %s\n", in.out.c_str());
    if (!in.json && !in.vtu.empty()) std::printf("  wrote %s\n", in.vtu.c_str());
    if (in.json) std::printf("%s\n", scene_solve_json(*bulk, in.scene, in.mode, s, in.out, in.vtu).c_str());
    if (const std::string w = no_load_warning(s); !w.empty()) std::cerr << "thinlayer solve: " << w << "\n";
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

int command_study_scene(const std::string& study, const std::vector<std::string>& argv) {
  SceneStudyOptions options;
  std::string out_dir;
  std::unique_ptr<SceneFileBulk> bulk;
  try {
    if (study != "convergence" && study != "validity")
      throw std::invalid_argument("--scene applies to study convergence and study validity only");
    if (!refuse_unless_one_process("study " + study + " --scene")) return 2;
    std::set<std::string> valued = {"scene", "out", "eps", "tolerance", "threads"};
    if (study == "validity") valued.insert("bisection-steps");
    const Args args(argv, valued, {"quiet"});
    const std::string scene = args.text("scene", "");
    if (scene.empty()) throw std::invalid_argument("--scene needs a file");
    out_dir = args.text("out", "");
    options.validity = study == "validity";
    options.verbose = !args.has("quiet");
    options.tolerance = args.number("tolerance", options.tolerance);
    if (!(options.tolerance > 0) || !(options.tolerance < 1)) throw std::invalid_argument("--tolerance must be in (0, 1)");
    options.threads = args.integer("threads", 2);
    if (options.threads < 1 || options.threads > 64) throw std::invalid_argument("--threads must be in 1..64");
    options.bisection_steps = args.integer("bisection-steps", 2);
    if (options.bisection_steps < 0 || options.bisection_steps > 20)
      throw std::invalid_argument("--bisection-steps must be in 0..20");
    SceneSpec spec = read_scene_spec(scene);
    if (args.has("eps")) {
      spec.eps = parse_number_list("eps", args.text("eps", ""));
      for (double e : spec.eps)
        if (!(e > 0) || std::isinf(e)) throw std::invalid_argument("--eps: thicknesses must be finite and > 0");
      if (spec.eps.size() < 3) throw std::invalid_argument("--eps: the convergence study needs at least 3 thicknesses");
    }
    if (!spec.has_layer())
      throw std::invalid_argument("scene '" + spec.name + "' gives a limit law only ('law'): it has no layer mode to study");
    bulk = std::make_unique<SceneFileBulk>(std::move(spec));
    for (double e : scene_study_grid(*bulk, options)) check_layer_mode(*bulk, e);
  } catch (const std::exception& e) {
    return fail("study", e, 2);
  }
  try {
    auto out = open_results(out_dir);
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
