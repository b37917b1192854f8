#include "studies/cli/command_solve.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "cases/film_admissibility.h"

#include "core/io/output_ownership.h"
#include "core/io/output_target.h"
#include "core/io/reference_tables.h"
#include "core/io/vtu_writer.h"
#include "cases/bar/bar_scenes.h"
#include "studies/cli/command_scene.h"
#include "studies/drivers/scene_solve_output.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "studies/tools/format.h"
#include "studies/cli/options.h"
#include "studies/cli/results_file.h"
#include "studies/tools/run_phase.h"

namespace thinlayer {

namespace {

const char* const solve_usage =
    "usage: thinlayer solve --case bar|dovetail [--mode limit|layer] [options] [--out FILE.h5] [--vtu FILE.vtu]\n"
    "       thinlayer solve --scene FILE.json [--mode limit|layer] [--eps E] [--out FILE.h5] [--vtu FILE.vtu] [--json]";

const std::set<std::string> bar_only = {"row", "lambda-bar", "mu-bar", "scale", "nx", "ny", "element",
                                        "diagonal", "plane", "distortion", "load-scale"};
const std::set<std::string> dovetail_only = {"law-case", "gamma", "delta", "h-interface", "h-far"};

// The largest layer accepted: the dovetail's is a tenth of its characteristic length 1 (a thicker
// layer is no thin layer, and the layer meshes stop there); the bar's is 1 mm, where every row's
// nearly incompressible layer still converges (bar::thickest_layer says why).
double thickest_layer(const std::string& case_name) {
  return case_name == "bar" ? bar::thickest_layer : dovetail::thickest_layer;
}
std::string thickest_reason(const std::string& case_name) {
  return case_name == "bar" ? "a fortieth of its side: Table 3's layers are nearly incompressible above"
                            : "a tenth of its size";
}

struct SolveInput : SolveRun {
  std::string case_name, mode, law_case;
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

void parse_bar(const CLI::App& c, const SolveArgs& a, SolveInput& in) {
  in.bar_mesh = parse_bar_mesh(c, a);
  double lambda_bar = 0, mu_bar = 0;
  if (given(c, "row")) {
    if (given(c, "lambda-bar") || given(c, "mu-bar")) throw std::invalid_argument("give either --row or --lambda-bar/--mu-bar");
    const auto table = load_table3_paper();
    if (a.row < 1 || a.row > static_cast<int>(table.size()))
      throw std::invalid_argument("unknown Table 3 row " + std::to_string(a.row) + " (expected 1.." + std::to_string(table.size()) + ")");
    lambda_bar = table[a.row - 1].lambda_bar;
    mu_bar = table[a.row - 1].mu_bar;
    in.law_case = "table3-row-" + std::to_string(a.row);
  } else {
    if (!given(c, "lambda-bar") || !given(c, "mu-bar")) throw std::invalid_argument("give --row N, or both --lambda-bar and --mu-bar");
    lambda_bar = a.lambda_bar;
    mu_bar = a.mu_bar;
  }
  const double scale = given(c, "scale") ? a.scale : 1.0;
  if (!(scale > 0) || std::isinf(scale)) throw std::invalid_argument("--scale must be finite and > 0");
  if (std::isfinite(lambda_bar) && !std::isfinite(lambda_bar * scale))
    throw std::invalid_argument("--scale: lambda_bar x scale overflows (" + plain(lambda_bar) + " x " + plain(scale) + ")");
  if (std::isfinite(mu_bar) && !std::isfinite(mu_bar * scale))
    throw std::invalid_argument("--scale: mu_bar x scale overflows (" + plain(mu_bar) + " x " + plain(scale) + ")");
  if (in.mode == "layer" && given(c, "friction")) throw std::invalid_argument("--friction applies to the bar's limit mode only (its layer has f = 1 on both faces)");
  in.law = InterfaceLaw::make(lambda_bar * scale, mu_bar * scale, given(c, "friction") ? a.friction : bar::friction);
  if (in.law_case.empty()) in.law_case = std::string(1, in.law.table1_case());
}

void parse_dovetail(const CLI::App& c, const SolveArgs& a, SolveInput& in) {
  if (given(c, "h-interface")) in.dovetail_mesh.h_interface = a.h_interface;
  if (given(c, "h-far")) in.dovetail_mesh.h_far = a.h_far;
  in.dovetail_mesh.layer_elements = in.layer_elements;
  if (given(c, "friction")) in.friction = a.friction;
  if (given(c, "law-case")) {
    if (given(c, "gamma") || given(c, "delta")) throw std::invalid_argument("give either --law-case or --gamma/--delta");
    if (a.law_case.size() != 1) throw std::invalid_argument("unknown law case '" + a.law_case + "' (expected a..i)");
    in.exponents = dovetail::exponents_of(a.law_case[0]);
    in.law_case = a.law_case;
  } else {
    if (!given(c, "gamma") || !given(c, "delta")) throw std::invalid_argument("give --law-case C, or both --gamma and --delta");
    in.exponents = dovetail::validated({a.gamma, a.delta});
  }
}

SolveInput parse_solve(const CLI::App& c, const SolveArgs& a) {
  SolveInput in;
  in.case_name = a.case_name;
  if (!given(c, "case")) throw std::invalid_argument("--case is required (bar or dovetail)");
  if (given(c, "max-nodes")) throw std::invalid_argument("--max-nodes applies to a scene file (--scene) only");
  if (given(c, "mesh-timeout")) throw std::invalid_argument("--mesh-timeout applies to a scene file (--scene) only");
  for (const auto& name : in.case_name == "bar" ? dovetail_only : bar_only)
    if (given(c, name)) throw std::invalid_argument("--" + name + " does not apply to the " + in.case_name);
  in.mode = given(c, "mode") ? a.mode : "limit";
  if (in.mode == "layer") {
    if (!given(c, "eps")) throw std::invalid_argument("layer mode needs --eps");
    in.eps = a.eps;
    if (!(in.eps > 0) || std::isinf(in.eps)) throw std::invalid_argument("--eps must be finite and > 0");
    if (in.eps > thickest_layer(in.case_name))
      throw std::invalid_argument("--eps " + plain(in.eps) + " is no thin layer for the " + in.case_name +
                                  ": at most " + plain(thickest_layer(in.case_name)) +
                                  (in.case_name == "bar" ? " mm" : "") + " (" + thickest_reason(in.case_name) + ")");
  } else if (given(c, "eps") || given(c, "layer-elements")) {
    throw std::invalid_argument("--eps and --layer-elements apply to the layer mode only");
  }
  if (given(c, "layer-elements")) in.layer_elements = a.layer_elements;
  if (in.layer_elements < 2) throw std::invalid_argument("--layer-elements must be >= 2");
  parse_solve_run(c, a, in);
  if (in.case_name == "bar") parse_bar(c, a, in);
  else parse_dovetail(c, a, in);
  if (given(c, "friction-path")) {
    if (in.solver != SolverKind::Fast) throw std::invalid_argument("--friction-path applies to the fast solver only");
    in.options.friction_path = friction_path_multipliers(a.friction_path.values,
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

// SPEC §1.5, film admissibility: how far the layer slid and how much it strained.
void print_film(const SceneRecord& record) { say("  %s\n", film_line(record).c_str()); }

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
    print_film(s.record);
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
  print_film(s.record);
  print_report(s.report, s.record);
  return {std::move(s.record), std::move(s.report)};
}

// `solve --json`: the scene in one line, for scripts. Non-finite numbers become null.
std::string summary_line(const SolveInput& in, const SceneRecord& record, const SolveReport& report) {
  const nlohmann::json counts = status_counts_json(record);
  const double setup = record.numbers.at("setup_time_s");
  nlohmann::json j = {
      {"scene", record.id},
      {"case", in.case_name},
      {"mode", in.mode},
      {"law_case", in.law_case},
      {"counts", counts},
      {"times_s", {{"solve", report.wall_time_s}, {"setup", setup}}},
      {"out", in.out.empty() ? nullptr : nlohmann::json(in.out)},
      {"vtu", in.vtu.empty() ? nullptr : nlohmann::json(in.vtu)},
  };
  j.update(solve_report_json(report));
  if (nlohmann::json film = film_json(record); !film.is_null()) j["film"] = std::move(film);
  return j.dump();
}


}  // namespace

CLI::App* declare_solve(CLI::App& thinlayer, SolveArgs& a) {
  CLI::App* c = thinlayer.add_subcommand(
      "solve", "solve one scene (bar or dovetail, limit or layer mode, or your own joint)\n\n"
               "Solves one scene and prints its gap/slide/stick counts, iterations, residual and times.");
  c->formatter(help_formatter(solve_usage));
  c->set_help_flag("-h,--help", "this help");
  c->allow_extras();  // refused by parse_command, with the project's message
  c->add_option("--case", a.case_name, "bar (paper 4.3, Table 3) | dovetail (paper 3.2, Table 2)")
      ->type_name("NAME")->check(one_of("case", {"bar", "dovetail"}));
  c->add_option("--mode", a.mode,
                "limit: the limit interface law on S (default)\n"
                "layer: the meshed layer of thickness --eps, Signorini-Coulomb on both faces")
      ->type_name("NAME")->check(one_of("mode", {"limit", "layer"}));
  c->add_option("--eps", a.eps,
                "layer thickness (layer mode), mm for the bar, L = 1 units for the dovetail;\n"
                "at most 1 mm on the bar (its rows' layers are nearly incompressible above), 0.1 on the dovetail")
      ->type_name("E")->check(decimal("eps"));
  c->add_option("--layer-elements", a.layer_elements, "Q1 elements through the layer's thickness, >= 2 (default 2)")
      ->type_name("N")->transform(integer("layer-elements"));
  c->add_option("--solver", a.solver, "fast (default) | relaxation (the paper's algorithm)")
      ->type_name("NAME")->check(one_of("solver", {"fast", "relaxation"}));
  c->add_option("--out", a.out,
                "write the scene as a results file (SPEC section 4: layout, /environment,\n"
                "/checks, /scenes/ID); nothing is written on error; a symbolic link is\n"
                "followed, a directory, FIFO or device refused")
      ->type_name("FILE.h5");
  c->add_option("--vtu", a.vtu,
                "write the scene for ParaView (mesh, displacement, interface fields on\n"
                "the nodes of S; body and stress per cell); nothing is written on error")
      ->type_name("FILE.vtu");
  c->add_flag("--json", a.json,
              "print one line of JSON on stdout instead of the text: counts,\n"
              "residual, stop cause, iterations, times (for scripts)");
  c->add_flag("--verbose", a.verbose, "the solver's progress lines on stderr");
  c->add_flag("--force", a.force,
              "replace an existing --out or --vtu file that thinlayer did not write (never\n"
              "an input of the run: the scene file, its geometry or mesh)");

  const std::string bar = "Bar";
  c->add_option("--row", a.row, "Table 3 row 1..6: (lambda_bar, mu_bar) from reference/table3_paper.csv")
      ->type_name("N")->transform(integer("row"))->group(bar);
  c->add_option("--lambda-bar", a.lambda_bar, "lambda_bar in daN/mm^3, 0 <= X <= inf (instead of --row)")
      ->type_name("X")->check(decimal("lambda-bar"))->group(bar);
  c->add_option("--mu-bar", a.mu_bar,
                "mu_bar in daN/mm^3, 0 <= X <= inf (instead of --row)\n"
                "In layer mode the layer has lambda_eps = eps lambda_bar, mu_eps = eps mu_bar.")
      ->type_name("X")->check(decimal("mu-bar"))->group(bar);
  c->add_option("--scale", a.scale,
                "multiplies lambda_bar and mu_bar (sensitivity study), default 1; the\n"
                "products must stay finite")
      ->type_name("S")->check(decimal("scale"))->group(bar);
  declare_bar_mesh_options(*c, a);

  const std::string dovetail = "Dovetail";
  c->add_option("--law-case", a.law_case, "Table 2 case a..i: (gamma, delta) from reference/table2.csv")
      ->type_name("C")->group(dovetail);
  c->add_option("--gamma", a.gamma, "the exponent of lambda_eps = eps^G lambda_g, G >= 0 (with --delta,\ninstead of --law-case)")
      ->type_name("G")->check(decimal("gamma"))->group(dovetail);
  c->add_option("--delta", a.delta, "the exponent of mu_eps = eps^D mu_g, 0 <= D < 2 (with --gamma)")
      ->type_name("D")->check(decimal("delta"))->group(dovetail);
  c->add_option("--h-interface", a.h_interface, "element size along S (default 0.025: 93 nodes on S)")
      ->type_name("H")->check(decimal("h-interface"))->group(dovetail);
  c->add_option("--h-far", a.h_far, "element size far from S (default 0.1)")
      ->type_name("H")->check(decimal("h-far"))->group(dovetail);

  const std::string both = "Both cases";
  c->add_option("--friction", a.friction,
                "Coulomb coefficient f >= 0: the bar's on S (default 1; limit mode only);\n"
                "the dovetail's on S, or on both faces of the layer (default 0.5, SPEC 2.2;\n"
                "for sensitivity studies)")
      ->type_name("F")->check(decimal("friction"))->group(both);
  c->add_option("--friction-path", a.friction_path,
                "fast solver: solve first with these Coulomb coefficients, in order, each\n"
                "solve warm started from the one before, then with the scene's own f, which\n"
                "alone decides convergence (a continuation for hard layer scenes; the\n"
                "dovetail's example in docs/commands.md). Each Fi finite and >= 0; the scene's f must be > 0.")
      ->type_name("F1,F2,...")->check(number_list("friction-path"))->group(both);
  declare_solver_options(*c, a);

  c->add_option("--scene", a.scene,
                "a JSON scene naming the physical groups of a gmsh .geo or .msh\n"
                "(docs/joints.md; cases/lap_joint/lap_joint.json); with it only --mode,\n"
                "--eps (mm), --out, --vtu, --json, --solver, --tolerance, --max-iterations,\n"
                "--omega, --verbose, --force, --max-nodes and --mesh-timeout apply")
      ->type_name("FILE.json")->group("Scene files (your own joint)");
  c->add_option("--max-nodes", a.max_nodes,
                "refuse a scene whose mesh would have more nodes than N, before meshing\n"
                "(estimated from the geometry and mesh_size; default 2000000)")
      ->type_name("N")->transform(integer("max-nodes"))->group("Scene files (your own joint)");
  c->add_option("--mesh-timeout", a.mesh_timeout,
                "stop gmsh after S seconds of wall clock, reading and meshing the scene's\n"
                "geometry: all the meshing of the command together (default 600; a loop\n"
                "in a .geo ends there)")
      ->type_name("S")->check(decimal("mesh-timeout"))->group("Scene files (your own joint)");
  c->footer(
      "Numbers are decimal (1e-3, 0.5, inf where a value may be infinite); no hex, no blanks.\n"
      "Exit status: 0 converged, 1 not converged (the result is still written), 2 bad input,\n"
      "including an output that cannot be written.");
  return c;
}

int command_solve(const CLI::App& command, const SolveArgs& args) {
  if (given(command, "scene")) return command_solve_scene(command, args);  // the user's own joint (SPEC §5)
  SolveInput in;
  try {
    in = parse_solve(command, args);
  } catch (const std::exception& e) {
    print_message("solve", e.what());
    return 2;
  }
  text_out = in.json ? nullptr : stdout;
  try {
    // Check the outputs first: an unwritable path is bad input, found before any work.
    if (!in.out.empty()) check_replaceable(in.out, OutputKind::Results, {}, in.force);
    if (!in.vtu.empty()) check_replaceable(in.vtu, OutputKind::Vtu, {}, in.force);
    if (!in.out.empty()) H5Writer probe(in.out);  // abandoned at once: nothing is left behind
    if (!in.vtu.empty()) check_vtu_target(in.vtu);
    std::optional<RunPhase> phase(std::in_place, "solving the " + in.case_name);
    const auto [record, report] = solve_scene(in);
    phase.emplace("writing the results");
    if (!in.out.empty()) {
      write_scene_file(in.out, record, {{}, in.force});
      say("  wrote %s\n", in.out.c_str());
    }
    if (!in.vtu.empty()) {
      write_vtu(in.vtu, record, {{}, in.force});
      say("  wrote %s\n", in.vtu.c_str());
    }
    if (in.json) std::printf("%s\n", summary_line(in, record, report).c_str());
    if (const std::string w = film_warning(record); !w.empty()) print_message("solve", w);
    if (!report.converged) {
      print_message("solve", report.message);
      return 1;
    }
    return 0;
  } catch (const std::invalid_argument& e) {
    print_message("solve", e.what());
    return 2;
  } catch (const OutputError& e) {
    print_message("solve", e.what());
    return 2;
  } catch (const std::bad_alloc& e) {
    print_message("solve", failure_text(e));
    return 2;
  } catch (const std::exception& e) {
    print_message("solve", e.what());
    return 1;
  }
}

}  // namespace thinlayer
