#include "studies/command_solve.h"

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include "core/io/reference_tables.h"
#include "studies/args.h"
#include "studies/bar_scenes.h"
#include "studies/options.h"

namespace thinlayer {

const char* const solve_help = R"(usage: thinlayer solve --case bar [options] [--out FILE.h5]

Solves one scene and prints its gap/slide/stick counts, iterations, residual and time.

  --case NAME          bar (the dovetail and the layer mode come with the thin-layer work)
  --mode limit         the limit interface law on S (default)
  --row N              Table 3 row 1..6: (lambda_bar, mu_bar) from reference/table3_paper.csv
  --lambda-bar X       lambda_bar in daN/mm^3, 0 <= X <= inf (instead of --row)
  --mu-bar X           mu_bar in daN/mm^3, 0 <= X <= inf (instead of --row)
  --friction F         Coulomb coefficient f >= 0 (default: the case's, 1 for the bar)
  --scale S            multiplies lambda_bar and mu_bar (sensitivity study), default 1
  --solver NAME        fast (default) | relaxation (the paper's algorithm)
)" MESH_AND_SOLVER_HELP R"(  --out FILE.h5        write the scene (SPEC section 4 schema); nothing is written on error

Exit status: 0 converged, 1 not converged (the result is still written), 2 bad input.
)";

namespace {

struct SolveInput {
  bar::MeshOptions mesh;
  InterfaceLaw law;
  std::string law_case;
  SolverKind solver = SolverKind::Fast;
  SolverOptions options;
  std::string out;
};

SolveInput parse_solve(const std::vector<std::string>& argv) {
  std::set<std::string> valued = {"case", "mode", "row", "lambda-bar", "mu-bar", "friction", "scale", "solver", "out"};
  valued.insert(mesh_and_solver_options.begin(), mesh_and_solver_options.end());
  const Args args(argv, valued, {"verbose"});
  if (!args.positional().empty()) throw std::invalid_argument("unexpected argument '" + args.positional()[0] + "'");
  const std::string case_name = args.text("case", "");
  if (case_name.empty()) throw std::invalid_argument("--case is required (bar)");
  if (case_name == "dovetail") throw std::invalid_argument("case 'dovetail' is not implemented yet (thin-layer issue)");
  if (case_name != "bar") throw std::invalid_argument("unknown case '" + case_name + "' (expected bar)");
  const std::string mode = args.text("mode", "limit");
  if (mode == "layer") throw std::invalid_argument("mode 'layer' is not implemented yet (thin-layer issue)");
  if (mode != "limit") throw std::invalid_argument("unknown mode '" + mode + "' (expected limit)");

  SolveInput in;
  in.mesh = parse_bar_mesh(args);
  in.solver = parse_solver(args.text("solver", "fast"));
  in.options = parse_solver_options(args);
  in.out = args.text("out", "");

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
    in.law_case = "";
  }
  const double scale = args.number("scale", 1.0);
  if (!(scale > 0) || std::isinf(scale)) throw std::invalid_argument("--scale must be finite and > 0");
  in.law = InterfaceLaw::make(lambda_bar * scale, mu_bar * scale, args.number("friction", bar::friction));
  if (in.law_case.empty()) in.law_case = std::string(1, in.law.table1_case());
  if (args.has("verbose")) in.options.verbose = true;
  return in;
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
    BarBulk bulk(in.mesh);
    const BarScene scene = solve_bar(bulk, in.law, in.law_case, in.solver, in.options);
    const auto& c = scene.counts;
    std::printf("bar %s (lambda_bar %g, mu_bar %g, f %g; Table 1 case %c), %s %dx%d, plane %s, solver %s\n",
                in.law_case.c_str(), in.law.lambda_bar, in.law.mu_bar, in.law.friction, in.law.table1_case(),
                to_string(in.mesh.element), in.mesh.nx, in.mesh.ny, to_string(in.mesh.plane), to_string(in.solver));
    std::printf("  gap %d  slide %d  stick %d   (status tolerance %g)\n", c.gap, c.slide, c.stick, default_status_tolerance);
    std::printf("  %s\n  residual: interface %.3e, bulk %.3e; iterations %d; solve %.4f s (+ setup %.4f s)\n",
                scene.report.message.c_str(), scene.report.residual.interface, scene.report.residual.bulk,
                scene.report.iterations, scene.report.wall_time_s, scene.record.numbers.at("setup_time_s"));
    if (out) {
      write_scene(*out, scene.record);
      out->commit();
      std::printf("  wrote %s\n", in.out.c_str());
    }
    if (!scene.report.converged) {
      std::cerr << "thinlayer solve: " << scene.report.message << "\n";
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
