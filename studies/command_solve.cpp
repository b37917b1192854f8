#include "studies/command_solve.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "core/io/reference_tables.h"
#include "core/io/vtu_writer.h"
#include "studies/args.h"
#include "studies/bar_scenes.h"
#include "studies/dovetail_scenes.h"
#include "studies/options.h"

namespace thinlayer {

const char* const solve_help = R"(usage: thinlayer solve --case bar|dovetail [--mode limit|layer] [options] [--out FILE.h5] [--vtu FILE.vtu]

Solves one scene and prints its gap/slide/stick counts, iterations, residual and times.

  --case NAME          bar (paper 4.3, Table 3) | dovetail (paper 3.2, Table 2)
  --mode NAME          limit: the limit interface law on S (default)
                       layer: the meshed layer of thickness --eps, Signorini-Coulomb on both faces
  --eps E              layer thickness (layer mode), mm for the bar, L = 1 units for the dovetail
  --layer-elements N   Q1 elements through the layer's thickness, >= 2 (default 2)
  --solver NAME        fast (default) | relaxation (the paper's algorithm)
  --out FILE.h5        write the scene (SPEC section 4 schema); nothing is written on error
  --vtu FILE.vtu       write the scene for ParaView (mesh, displacement, interface fields on
                       the nodes of S); nothing is written on error

Bar:
  --row N              Table 3 row 1..6: (lambda_bar, mu_bar) from reference/table3_paper.csv
  --lambda-bar X       lambda_bar in daN/mm^3, 0 <= X <= inf (instead of --row)
  --mu-bar X           mu_bar in daN/mm^3, 0 <= X <= inf (instead of --row)
  --friction F         Coulomb coefficient f >= 0 (default 1; limit mode only)
  --scale S            multiplies lambda_bar and mu_bar (sensitivity study), default 1
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

Exit status: 0 converged, 1 not converged (the result is still written), 2 bad input.
)";

namespace {

const std::set<std::string> bar_only = {"row", "lambda-bar", "mu-bar", "scale", "nx", "ny", "element",
                                        "diagonal", "plane", "distortion", "load-scale"};
const std::set<std::string> dovetail_only = {"law-case", "gamma", "delta", "h-interface", "h-far"};

struct SolveInput {
  std::string case_name, mode, law_case, out, vtu;
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
  const Args args(argv, valued, {"verbose"});
  if (!args.positional().empty()) throw std::invalid_argument("unexpected argument '" + args.positional()[0] + "'");

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
  } else if (args.has("eps") || args.has("layer-elements")) {
    throw std::invalid_argument("--eps and --layer-elements apply to the layer mode only");
  }
  in.layer_elements = args.integer("layer-elements", 2);
  if (in.layer_elements < 2) throw std::invalid_argument("--layer-elements must be >= 2");
  in.solver = parse_solver(args.text("solver", "fast"));
  in.options = parse_solver_options(args);
  in.options.verbose = args.has("verbose");
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

void print_counts(const char* what, const StatusCount& c) {
  std::printf("  %-9s gap %3d  slide %3d  stick %3d\n", what, c.gap, c.slide, c.stick);
}

void print_report(const SolveReport& report, const SceneRecord& record) {
  std::printf("  status tolerance %g (relative)\n", record.numbers.at("status_tolerance"));
  std::printf("  %s\n  residual: interface %.3e, bulk %.3e; iterations %d; solve %.4f s (+ setup %.4f s)\n",
              report.message.c_str(), report.residual.interface, report.residual.bulk, report.iterations,
              report.wall_time_s, record.numbers.at("setup_time_s"));
  // SPEC §1.5: the residual body by body and interface by interface.
  std::printf("  residual per body:");
  for (size_t b = 0; b < record.residual_per_body.size(); ++b)
    std::printf(" %s %.3e", record.body_names[b].c_str(), record.residual_per_body[b]);
  std::printf("; per interface:");
  for (size_t i = 0; i < record.residual_per_interface.size(); ++i)
    std::printf(" %s %.3e", record.interface_names[i].c_str(), record.residual_per_interface[i]);
  std::printf("\n");
}

void print_layer(const MeshQuality& q, double eps, const LayerCounts& c) {
  std::printf("  layer mesh: %d Q1 cells, angles %.1f..%.1f deg, aspect ratio up to %.3g (eps %g), "
              "scaled Jacobian >= %.3f\n", q.cells, q.min_angle_deg, q.max_angle_deg, q.max_aspect_ratio, eps,
              q.min_scaled_jacobian);
  print_counts("S+", c.plus_face);
  print_counts("S-", c.minus_face);
  print_counts("combined", c.combined);
}

// Solves the scene; returns its record (for --out and --vtu) and report.
std::pair<SceneRecord, SolveReport> solve_scene(const SolveInput& in) {
  if (in.case_name == "bar") {
    std::printf("bar %s (lambda_bar %g, mu_bar %g; Table 1 case %c), %s %dx%d, plane %s, %s mode, solver %s\n",
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
  std::printf("dovetail case %s (gamma %g, delta %g; limit law: case %c, lambda_bar %g, mu_bar %g, f %g), %s mode, "
              "solver %s\n", in.law_case.empty() ? "custom" : in.law_case.c_str(), in.exponents.gamma,
              in.exponents.delta, law.table1_case(), law.lambda_bar, law.mu_bar, law.friction, in.mode.c_str(),
              to_string(in.solver));
  const auto& m = bulk.meshes();
  std::printf("  meshes: base %d + tenon %d nodes, %d nodes on S, meshed in %.3f s\n", m.base.num_nodes(),
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

}  // namespace

int command_solve(const std::vector<std::string>& argv) {
  SolveInput in;
  try {
    in = parse_solve(argv);
  } catch (const std::exception& e) {
    std::cerr << "thinlayer solve: " << e.what() << "\n";
    return 2;
  }
  try {
    // Open the output first: an unwritable path is bad input, found before any work.
    std::unique_ptr<H5Writer> out;
    if (!in.out.empty()) out = std::make_unique<H5Writer>(in.out);
    if (!in.vtu.empty()) check_vtu_target(in.vtu);
    const auto [record, report] = solve_scene(in);
    if (out) {
      write_scene(*out, record);
      out->commit();
      std::printf("  wrote %s\n", in.out.c_str());
    }
    if (!in.vtu.empty()) {
      write_vtu(in.vtu, record);
      std::printf("  wrote %s\n", in.vtu.c_str());
    }
    if (!report.converged) {
      std::cerr << "thinlayer solve: " << report.message << "\n";
      return 1;
    }
    return 0;
  } catch (const std::invalid_argument& e) {
    std::cerr << "thinlayer solve: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "thinlayer solve: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace thinlayer
