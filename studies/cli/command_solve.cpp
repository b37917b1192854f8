#include "studies/cli/command_solve.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/io/output_target.h"
#include "core/io/reference_tables.h"
#include "core/io/vtu_writer.h"
#include "studies/cli/args.h"
#include "cases/bar/bar_scenes.h"
#include "studies/cli/command_scene.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "studies/tools/format.h"
#include "studies/cli/options.h"
#include "studies/cli/results_file.h"

namespace thinlayer {

const char* const solve_help = R"(usage: thinlayer solve --case bar|dovetail [--mode limit|layer] [options] [--out FILE.h5] [--vtu FILE.vtu]
       thinlayer solve --scene FILE.json [--mode limit|layer] [--eps E] [--out FILE.h5] [--vtu FILE.vtu] [--json]

Solves one scene and prints its gap/slide/stick counts, iterations, residual and times.

  --case NAME          bar (paper 4.3, Table 3) | dovetail (paper 3.2, Table 2)
  --mode NAME          limit: the limit interface law on S (default)
                       layer: the meshed layer of thickness --eps, Signorini-Coulomb on both faces
  --eps E              layer thickness (layer mode), mm for the bar, L = 1 units for the dovetail;
                       a thin layer: at most a tenth of the joint's size (bar 4 mm, dovetail 0.1)
  --layer-elements N   Q1 elements through the layer's thickness, >= 2 (default 2)
  --solver NAME        fast (default) | relaxation (the paper's algorithm)
  --out FILE.h5        write the scene as a results file (SPEC section 4: layout, /environment,
                       /checks, /scenes/ID); nothing is written on error; a symbolic link is
                       followed, a directory, FIFO or device refused
  --vtu FILE.vtu       write the scene for ParaView (mesh, displacement, interface fields on
                       the nodes of S; body and stress per cell); nothing is written on error
  --json               print one line of JSON on stdout instead of the text: counts,
                       residual, stop cause, iterations, times (for scripts)
  --verbose            the solver's progress lines on stderr

Bar:
  --row N              Table 3 row 1..6: (lambda_bar, mu_bar) from reference/table3_paper.csv
  --lambda-bar X       lambda_bar in daN/mm^3, 0 <= X <= inf (instead of --row)
  --mu-bar X           mu_bar in daN/mm^3, 0 <= X <= inf (instead of --row)
  --friction F         Coulomb coefficient f >= 0 (default 1; limit mode only)
  --scale S            multiplies lambda_bar and mu_bar (sensitivity study), default 1; the
                       products must stay finite
    In layer mode the layer has lambda_eps = eps lambda_bar, mu_eps = eps mu_bar.
)" MESH_AND_SOLVER_HELP R"(
Dovetail:
  --law-case C         Table 2 case a..i: (gamma, delta) from reference/table2.csv
  --gamma G --delta D  the exponents of lambda_eps = eps^G lambda_g, mu_eps = eps^D mu_g
                       (G >= 0, 0 <= D < 2) instead of --law-case
  --h-interface H      element size along S (default 0.025: 93 nodes on S)
  --h-far H            element size far from S (default 0.1)
  --friction F         Coulomb coefficient f >= 0 on S, or on both faces of the layer
                       (default 0.5, SPEC 2.2; for sensitivity studies)

Both cases:
  --friction-path F1,F2,...
                       fast solver: solve first with these Coulomb coefficients, in order, each
                       solve warm started from the one before, then with the scene's own f, which
                       alone decides convergence (a continuation for hard layer scenes; README,
                       known limitations). Each Fi finite and >= 0; the scene's f must be > 0.

Scene files (your own joint):
  --scene FILE.json    a JSON scene naming the physical groups of a gmsh .geo or .msh (README,
                       "Your own joint"; cases/lap_joint/lap_joint.json); with it only --mode,
                       --eps (mm), --out, --vtu, --json, --solver, --tolerance, --max-iterations,
                       --omega and --verbose apply

Numbers are decimal (1e-3, 0.5, inf where a value may be infinite); no hex, no blanks.
Exit status: 0 converged, 1 not converged (the result is still written), 2 bad input,
including an output that cannot be written.
)";

namespace {

const std::set<std::string> bar_only = {"row", "lambda-bar", "mu-bar", "scale", "nx", "ny", "element",
                                        "diagonal", "plane", "distortion", "load-scale"};
const std::set<std::string> dovetail_only = {"law-case", "gamma", "delta", "h-interface", "h-far"};

// The largest layer that is still thin: a tenth of the joint's size (bar: its side L = 40 mm;
// dovetail: its characteristic length 1, where the layer meshes stop at 0.1 too). Beyond it
// the layer is no thin layer, and its band would cross the adherents' elements.
double thickest_layer(const std::string& case_name) { return case_name == "bar" ? bar::side / 10 : 0.1; }

struct SolveInput {
  std::string case_name, mode, law_case, out, vtu;
  bool json = false;
  SolverKind solver = SolverKind::Fast;
  SolverOptions options;
  double eps = 0;
  int layer_elements = 2;
  // bar
  bar::MeshOptions bar_mesh;
  InterfaceLaw law;
  // dovetail
  dovetail::MeshOptions dovetail_mesh;
  dovetail::Exponents exponents;
  double friction = dovetail::friction;
};

void parse_bar(const Args& args, SolveInput& in) {
  in.bar_mesh = parse_bar_mesh(args);
  double lambda_bar = 0, mu_bar = 0;
  if (args.has("row")) {
    if (args.has("lambda-bar") || args.has("mu-bar")) throw std::invalid_argument("give either --row or --lambda-bar/--mu-bar");
    const int row = args.integer("row", 0);
    const auto table = load_table3_paper();
    if (row < 1 || row > static_cast<int>(table.size()))
      throw std::invalid_argument("unknown Table 3 row " + std::to_string(row) + " (expected 1.." + std::to_string(table.size()) + ")");
    lambda_bar = table[row - 1].lambda_bar;
    mu_bar = table[row - 1].mu_bar;
    in.law_case = "table3-row-" + std::to_string(row);
  } else {
    if (!args.has("lambda-bar") || !args.has("mu-bar")) throw std::invalid_argument("give --row N, or both --lambda-bar and --mu-bar");
    lambda_bar = args.number("lambda-bar", 0);
    mu_bar = args.number("mu-bar", 0);
  }
  const double scale = args.number("scale", 1.0);
  if (!(scale > 0) || std::isinf(scale)) throw std::invalid_argument("--scale must be finite and > 0");
  if (std::isfinite(lambda_bar) && !std::isfinite(lambda_bar * scale))
    throw std::invalid_argument("--scale: lambda_bar x scale overflows (" + plain(lambda_bar) + " x " + args.text("scale", "") + ")");
  if (std::isfinite(mu_bar) && !std::isfinite(mu_bar * scale))
    throw std::invalid_argument("--scale: mu_bar x scale overflows (" + plain(mu_bar) + " x " + args.text("scale", "") + ")");
  if (in.mode == "layer" && args.has("friction")) throw std::invalid_argument("--friction applies to the bar's limit mode only (its layer has f = 1 on both faces)");
  in.law = InterfaceLaw::make(lambda_bar * scale, mu_bar * scale, args.number("friction", bar::friction));
  if (in.law_case.empty()) in.law_case = std::string(1, in.law.table1_case());
}

void parse_dovetail(const Args& args, SolveInput& in) {
  in.dovetail_mesh.h_interface = args.number("h-interface", in.dovetail_mesh.h_interface);
  in.dovetail_mesh.h_far = args.number("h-far", in.dovetail_mesh.h_far);
  in.dovetail_mesh.layer_elements = in.layer_elements;
  in.friction = args.number("friction", dovetail::friction);
  if (args.has("law-case")) {
    if (args.has("gamma") || args.has("delta")) throw std::invalid_argument("give either --law-case or --gamma/--delta");
    const std::string c = args.text("law-case", "");
    if (c.size() != 1) throw std::invalid_argument("unknown law case '" + c + "' (expected a..i)");
    in.exponents = dovetail::exponents_of(c[0]);
    in.law_case = c;
  } else {
    if (!args.has("gamma") || !args.has("delta")) throw std::invalid_argument("give --law-case C, or both --gamma and --delta");
    in.exponents = dovetail::validated({args.number("gamma", 0), args.number("delta", 0)});
  }
}

SolveInput parse_solve(const std::vector<std::string>& argv) {
  std::set<std::string> valued = {"case", "mode", "solver", "out", "vtu", "eps", "layer-elements", "friction",
                                  "friction-path"};
  valued.insert(mesh_and_solver_options.begin(), mesh_and_solver_options.end());
  valued.insert(bar_only.begin(), bar_only.end());
  valued.insert(dovetail_only.begin(), dovetail_only.end());
  const Args args(argv, valued, {"verbose", "json"});

  SolveInput in;
  in.case_name = args.text("case", "");
  if (in.case_name.empty()) throw std::invalid_argument("--case is required (bar or dovetail)");
  if (in.case_name != "bar" && in.case_name != "dovetail")
    throw std::invalid_argument("unknown case '" + in.case_name + "' (expected bar or dovetail)");
  for (const auto& name : in.case_name == "bar" ? dovetail_only : bar_only)
    if (args.has(name)) throw std::invalid_argument("--" + name + " does not apply to the " + in.case_name);
  in.mode = args.text("mode", "limit");
  if (in.mode != "limit" && in.mode != "layer") throw std::invalid_argument("unknown mode '" + in.mode + "' (expected limit or layer)");
  if (in.mode == "layer") {
    if (!args.has("eps")) throw std::invalid_argument("layer mode needs --eps");
    in.eps = args.number("eps", 0);
    if (!(in.eps > 0) || std::isinf(in.eps)) throw std::invalid_argument("--eps must be finite and > 0");
    if (in.eps > thickest_layer(in.case_name))
      throw std::invalid_argument("--eps " + args.text("eps", "") + " is no thin layer for the " + in.case_name +
                                  ": at most " + plain(thickest_layer(in.case_name)) +
                                  (in.case_name == "bar" ? " mm" : "") + " (a tenth of its size)");
  } else if (args.has("eps") || args.has("layer-elements")) {
    throw std::invalid_argument("--eps and --layer-elements apply to the layer mode only");
  }
  in.layer_elements = args.integer("layer-elements", 2);
  if (in.layer_elements < 2) throw std::invalid_argument("--layer-elements must be >= 2");
  in.solver = parse_solver(args.text("solver", "fast"));
  in.options = parse_solver_options(args);
  in.options.verbose = args.has("verbose");
  in.json = args.has("json");
  in.out = args.text("out", "");
  in.vtu = args.text("vtu", "");
  // absolute() first: weakly_canonical leaves a relative path with no existing prefix as it is.
  auto target = [](const std::string& p) { return std::filesystem::weakly_canonical(std::filesystem::absolute(p)); };
  if (!in.out.empty() && !in.vtu.empty() && target(in.out) == target(in.vtu))
    throw std::invalid_argument("--out and --vtu name the same file");
  if (in.case_name == "bar") parse_bar(args, in);
  else parse_dovetail(args, in);
  if (args.has("friction-path")) {
    if (in.solver != SolverKind::Fast) throw std::invalid_argument("--friction-path applies to the fast solver only");
    in.options.friction_path = friction_path_multipliers(args.text("friction-path", ""),
                                                         in.case_name == "bar" ? in.law.friction : in.friction);
  }
  return in;
}

// The human-readable lines go to stdout, or nowhere with --json (stdout is then the JSON
// line alone). Flushed at once: a layer solve takes a while, and its first line says what.
FILE* text_out = stdout;

void say(const char* format, ...) {
  if (!text_out) return;
  va_list args;
  va_start(args, format);
  std::vfprintf(text_out, format, args);
  va_end(args);
  std::fflush(text_out);
}

void print_counts(const char* what, const StatusCount& c) {
  say("  %-9s gap %3d  slide %3d  stick %3d\n", what, c.gap, c.slide, c.stick);
}

// One iteration count per solve: SolveReport::iterations, the one written to the file (the
// solver's own message may count the steps of one attempt only, so it is not printed here).
void print_report(const SolveReport& report, const SceneRecord& record) {
  say("  status tolerance %g (relative)\n", record.numbers.at("status_tolerance"));
  if (auto path = record.text.find("friction_path"); path != record.text.end())
    say("  friction path: f = %s (the last is the scene's own)\n", path->second.c_str());
  const std::string outcome = report.converged ? "converged" : std::string("NOT converged (") + to_string(report.stop_cause) + ")";
  say("  %s after %d iterations; residual %.3e (interface %.3e, bulk %.3e), tolerance %.0e\n", outcome.c_str(),
      report.iterations,
      report.residual.value(), report.residual.interface, report.residual.bulk, report.tolerance);
  say("  time: solve %.4f s, setup %.4f s\n", report.wall_time_s, record.numbers.at("setup_time_s"));
  // SPEC §1.5: the residual body by body and interface by interface.
  say("  residual per body:");
  for (size_t b = 0; b < record.residual_per_body.size(); ++b)
    say(" %s %.3e", record.body_names[b].c_str(), record.residual_per_body[b]);
  say("; per interface:");
  for (size_t i = 0; i < record.residual_per_interface.size(); ++i)
    say(" %s %.3e", record.interface_names[i].c_str(), record.residual_per_interface[i]);
  say("\n");
  // What double precision can resolve of each body's residual for this answer.
  say("  round-off floor per body:");
  for (size_t b = 0; b < record.residual_floor_per_body.size(); ++b)
    say(" %s %.1e", record.body_names[b].c_str(), record.residual_floor_per_body[b]);
  // A layer band is evaluated in its column basis, where its digits are; the nodal u written
  // out resolves its balance only to the nodal floor, shown where that is the larger.
  for (size_t b = 0; b < record.residual_nodal_floor_per_body.size(); ++b)
    if (record.residual_nodal_floor_per_body[b] > 10 * record.residual_floor_per_body[b])
      say("; %s evaluated in its column basis (from the nodal u: %.1e)", record.body_names[b].c_str(),
          record.residual_nodal_floor_per_body[b]);
  say("\n");
}

void print_layer(const MeshQuality& q, double eps, const LayerCounts& c) {
  say("  layer mesh: %d Q1 cells, angles %.1f..%.1f deg, aspect ratio up to %.3g (eps %g), "
      "scaled Jacobian >= %.3f\n", q.cells, q.min_angle_deg, q.max_angle_deg, q.max_aspect_ratio, eps,
      q.min_scaled_jacobian);
  print_counts("S+", c.plus_face);
  print_counts("S-", c.minus_face);
  print_counts("combined", c.combined);
}

// Solves the scene; returns its record (for --out and --vtu) and report.
std::pair<SceneRecord, SolveReport> solve_scene(const SolveInput& in) {
  if (in.case_name == "bar") {
    say("bar %s (lambda_bar %g, mu_bar %g; Table 1 case %c), %s %dx%d, plane %s, %s mode, solver %s\n",
        in.law_case.c_str(), in.law.lambda_bar, in.law.mu_bar, in.law.table1_case(), to_string(in.bar_mesh.element),
        in.bar_mesh.nx, in.bar_mesh.ny, to_string(in.bar_mesh.plane), in.mode.c_str(), to_string(in.solver));
    if (in.mode == "limit") {
      BarBulk bulk(in.bar_mesh);
      BarScene s = solve_bar(bulk, in.law, in.law_case, in.solver, in.options);
      print_counts("S", s.counts);
      print_report(s.report, s.record);
      return {std::move(s.record), std::move(s.report)};
    }
    BarLayerScene s = solve_bar_layer(in.bar_mesh, in.law.lambda_bar, in.law.mu_bar, in.eps, in.law_case, in.solver,
                                      in.options, default_status_tolerance, in.layer_elements);
    print_layer(s.layer_quality, in.eps, s.counts);
    print_report(s.report, s.record);
    return {std::move(s.record), std::move(s.report)};
  }
  DovetailLimitBulk bulk(in.dovetail_mesh, in.friction);
  const InterfaceLaw law = dovetail::limit_law(in.exponents, bulk.friction());
  say("dovetail case %s (gamma %g, delta %g; limit law: case %c, lambda_bar %g, mu_bar %g, f %g), %s mode, "
      "solver %s\n", in.law_case.empty() ? "custom" : in.law_case.c_str(), in.exponents.gamma,
      in.exponents.delta, law.table1_case(), law.lambda_bar, law.mu_bar, law.friction, in.mode.c_str(),
      to_string(in.solver));
  const auto& m = bulk.meshes();
  say("  meshes: base %d + tenon %d nodes, %d nodes on S, meshed in %.3f s\n", m.base.num_nodes(),
      m.tenon.num_nodes(), static_cast<int>(m.base.node_set("S").size()), bulk.meshing_time_s());
  if (in.mode == "limit") {
    DovetailScene s = solve_dovetail_limit(bulk, in.exponents, in.law_case, in.solver, in.options);
    print_counts("S", s.limit);
    print_report(s.report, s.record);
    return {std::move(s.record), std::move(s.report)};
  }
  DovetailScene s = solve_dovetail_layer(bulk, in.exponents, in.eps, in.law_case, in.solver, in.options);
  print_layer(s.layer_quality, in.eps, s.counts);
  print_report(s.report, s.record);
  return {std::move(s.record), std::move(s.report)};
}

nlohmann::json counts_json(const StatusCount& c) { return {{"gap", c.gap}, {"slide", c.slide}, {"stick", c.stick}}; }

// `solve --json`: the scene in one line, for scripts. Non-finite numbers become null.
std::string summary_line(const SolveInput& in, const SceneRecord& record, const SolveReport& report) {
  nlohmann::json counts;
  for (const InterfaceFields& f : record.interfaces) counts[f.name] = counts_json(f.counts());
  if (!record.combined_status.empty()) {
    std::vector<NodeStatus> combined;
    for (int v : record.combined_status) combined.push_back(static_cast<NodeStatus>(v));
    counts["combined"] = counts_json(count_statuses(combined));
  }
  const double setup = record.numbers.at("setup_time_s");
  const nlohmann::json j = {
      {"scene", record.id},
      {"case", in.case_name},
      {"mode", in.mode},
      {"law_case", in.law_case},
      {"solver", report.solver},
      {"converged", report.converged},
      {"stop_cause", to_string(report.stop_cause)},
      {"iterations", report.iterations},
      {"residual", {{"value", report.residual.value()}, {"interface", report.residual.interface},
                    {"bulk", report.residual.bulk}, {"tolerance", report.tolerance},
                    {"roundoff_floor", report.residual.floor()}}},
      {"counts", counts},
      {"times_s", {{"solve", report.wall_time_s}, {"setup", setup}}},
      {"out", in.out.empty() ? nullptr : nlohmann::json(in.out)},
      {"vtu", in.vtu.empty() ? nullptr : nlohmann::json(in.vtu)},
  };
  return j.dump();
}

// The scene as a results file (SPEC §4): layout, environment, the scene, /checks (empty).
void write_results(const std::string& path, const SceneRecord& record) {
  auto out = open_results_file(path);
  write_scene(*out, record);
  write_checks(*out, {});
  out->commit();
}

}  // namespace

int command_solve(const std::vector<std::string>& argv) {
  if (names_scene(argv)) return command_solve_scene(argv);  // the user's own joint (SPEC §5)
  SolveInput in;
  try {
    in = parse_solve(argv);
  } catch (const std::exception& e) {
    std::cerr << "thinlayer solve: " << e.what() << "\n";
    return 2;
  }
  text_out = in.json ? nullptr : stdout;
  try {
    // Check the outputs first: an unwritable path is bad input, found before any work.
    if (!in.out.empty()) H5Writer probe(in.out);  // abandoned at once: nothing is left behind
    if (!in.vtu.empty()) check_vtu_target(in.vtu);
    const auto [record, report] = solve_scene(in);
    if (!in.out.empty()) {
      write_results(in.out, record);
      say("  wrote %s\n", in.out.c_str());
    }
    if (!in.vtu.empty()) {
      write_vtu(in.vtu, record);
      say("  wrote %s\n", in.vtu.c_str());
    }
    if (in.json) std::printf("%s\n", summary_line(in, record, report).c_str());
    if (!report.converged) {
      std::cerr << "thinlayer solve: " << report.message << "\n";
      return 1;
    }
    return 0;
  } catch (const std::invalid_argument& e) {
    std::cerr << "thinlayer solve: " << e.what() << "\n";
    return 2;
  } catch (const OutputError& e) {
    std::cerr << "thinlayer solve: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "thinlayer solve: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace thinlayer
