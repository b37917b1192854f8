#include "studies/cli/options.h"

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "core/io/output_ownership.h"

namespace thinlayer {

namespace {

// daN/mm²: the largest traction a solve takes; its squares, summed over a mesh, stay far from
// the largest double (1.8e308). Measured on the bar: 1e150 solves, 1e155 ends in NaN.
constexpr double largest_traction = 1e100;

}  // namespace

void declare_bar_mesh_options(CLI::App& command, SolveArgs& a) {
  const std::string group = "Bar";
  command.add_option("--nx", a.nx, "elements along AD (default 32)")->type_name("N")->transform(integer("nx"))->group(group);
  command.add_option("--ny", a.ny, "elements along DE (default 32)")->type_name("N")->transform(integer("ny"))->group(group);
  command.add_option("--element", a.element, "Q1 (default) | P1")->type_name("E")->check(one_of("element", {"Q1", "P1"}))->group(group);
  command.add_option("--diagonal", a.diagonal, "P1 only: right (default, '/') | left ('\\')")
      ->type_name("D")->check(one_of("diagonal", {"right", "left"}))->group(group);
  command.add_option("--plane", a.plane, "strain (default) | stress")
      ->type_name("P")->check(one_of("plane hypothesis", {"strain", "stress"}))->group(group);
  command.add_option("--distortion", a.distortion,
                     "move interior nodes by up to D x the element size, 0 <= D < 0.5\n"
                     "(a reproducible pseudo-random pattern; stress tests)")
      ->type_name("D")->check(decimal("distortion"))->group(group);
  command.add_option("--load-scale", a.load_scale, "multiply the tractions F1, F2 by S (-1 lifts the bar off AD)")
      ->type_name("S")->check(decimal("load-scale"))->group(group);
}

void declare_solver_options(CLI::App& command, SolveArgs& a) {
  const std::string group = "Solvers";
  command.add_option("--tolerance", a.tolerance, "SPEC residual to reach (default 1e-10)")
      ->type_name("T")->check(decimal("tolerance"))->group(group);
  command.add_option("--max-iterations", a.max_iterations,
                     "solver iteration cap, N >= 1 (default: fast 200; with a floating layer\n"
                     "none, its spring stages bound the work; relaxation 100000 sweeps)")
      ->type_name("N")->transform(integer("max-iterations"))->group(group);
  command.add_option("--omega", a.omega, "relaxation's over-relaxation coefficient in (0, 2) (default 1.8)")
      ->type_name("W")->check(decimal("omega"))->group(group);
}

void parse_solve_run(const CLI::App& command, const SolveArgs& a, SolveRun& run) {
  run.solver = parse_solver(given(command, "solver") ? a.solver : "fast");
  run.options = parse_solver_options(command, a);
  run.options.verbose = a.verbose;
  run.json = a.json;
  run.out = a.out;
  run.vtu = a.vtu;
  run.force = a.force;
  // After every link, a dangling one too (core/io/output_ownership.h).
  check_distinct_outputs({{"--out", run.out}, {"--vtu", run.vtu}}, {});
}

bar::MeshOptions parse_bar_mesh(const CLI::App& command, const SolveArgs& a) {
  bar::MeshOptions m;
  if (given(command, "nx")) m.nx = a.nx;
  if (given(command, "ny")) m.ny = a.ny;
  if (m.nx < 1 || m.ny < 1) throw std::invalid_argument("--nx and --ny must be >= 1");
  if (given(command, "element")) m.element = a.element == "Q1" ? ElementType::Q1 : ElementType::P1;
  if (given(command, "diagonal") && m.element != ElementType::P1)
    throw std::invalid_argument("--diagonal applies to P1 elements only (add --element P1)");
  if (given(command, "diagonal")) m.diagonal = a.diagonal == "right" ? TriangleDiagonal::Right : TriangleDiagonal::Left;
  if (given(command, "distortion")) m.distortion = a.distortion;
  if (!(m.distortion >= 0 && m.distortion < 0.5)) throw std::invalid_argument("--distortion must be in [0, 0.5)");
  if (given(command, "load-scale")) m.load_scale = a.load_scale;
  if (!std::isfinite(m.load_scale)) throw std::invalid_argument("--load-scale must be finite");
  // The solver squares forces (norms, the round-off floor): a traction of 1e155 daN/mm^2 on
  // the bar overflowed them to NaN after the whole solve. Said up front, with room to spare.
  const double largest_F = std::max(std::abs(bar::F1), std::abs(bar::F2));
  if (std::abs(m.load_scale) * largest_F > largest_traction) {
    std::ostringstream why;
    why << "--load-scale " << m.load_scale << ": the tractions, " << m.load_scale << " x " << largest_F
        << " daN/mm^2, overflow the solve (it squares forces): at most " << largest_traction << " daN/mm^2";
    throw std::invalid_argument(why.str());
  }
  if (given(command, "plane")) m.plane = a.plane == "strain" ? PlaneHypothesis::Strain : PlaneHypothesis::Stress;
  return m;
}

SolverOptions parse_solver_options(const CLI::App& command, const SolveArgs& a) {
  SolverOptions o;
  if (given(command, "tolerance")) o.tolerance = a.tolerance;
  if (!(o.tolerance > 0) || std::isinf(o.tolerance)) throw std::invalid_argument("--tolerance must be finite and > 0");
  // 0 is the solver's "use the default"; from the command line the default is had by leaving
  // the option out, so an explicit 0 is a mistake.
  if (given(command, "max-iterations")) {
    o.max_iterations = a.max_iterations;
    if (o.max_iterations < 1) throw std::invalid_argument("--max-iterations must be >= 1 (leave it out for the default)");
  }
  if (given(command, "omega")) o.omega = a.omega;
  if (!(o.omega > 0 && o.omega < 2)) throw std::invalid_argument("--omega must be in (0, 2)");
  return o;
}

std::vector<double> friction_path_multipliers(const std::vector<double>& given_path, double friction) {
  if (!(friction > 0)) throw std::invalid_argument("--friction-path needs a scene with friction (f > 0)");
  std::vector<double> path = given_path;
  for (double& f : path) {
    if (!(f >= 0) || std::isinf(f)) {
      std::ostringstream why;
      why << "--friction-path: each coefficient must be a finite number >= 0, got " << f;
      throw std::invalid_argument(why.str());
    }
    f /= friction;
  }
  return path;
}

}  // namespace thinlayer
