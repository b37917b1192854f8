#include "studies/cli/options.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace thinlayer {

bar::MeshOptions parse_bar_mesh(const Args& args) {
  bar::MeshOptions m;
  m.nx = args.integer("nx", m.nx);
  m.ny = args.integer("ny", m.ny);
  if (m.nx < 1 || m.ny < 1) throw std::invalid_argument("--nx and --ny must be >= 1");
  const std::string element = args.text("element", "Q1");
  if (element == "Q1") m.element = ElementType::Q1;
  else if (element == "P1") m.element = ElementType::P1;
  else throw std::invalid_argument("unknown element '" + element + "' (expected Q1 or P1)");
  if (args.has("diagonal") && m.element != ElementType::P1)
    throw std::invalid_argument("--diagonal applies to P1 elements only (add --element P1)");
  const std::string diagonal = args.text("diagonal", "right");
  if (diagonal == "right") m.diagonal = TriangleDiagonal::Right;
  else if (diagonal == "left") m.diagonal = TriangleDiagonal::Left;
  else throw std::invalid_argument("unknown diagonal '" + diagonal + "' (expected right or left)");
  const std::string plane = args.text("plane", "strain");
  m.distortion = args.number("distortion", 0.0);
  if (!(m.distortion >= 0 && m.distortion < 0.5)) throw std::invalid_argument("--distortion must be in [0, 0.5)");
  m.load_scale = args.number("load-scale", 1.0);
  if (!std::isfinite(m.load_scale)) throw std::invalid_argument("--load-scale must be finite");
  if (plane == "strain") m.plane = PlaneHypothesis::Strain;
  else if (plane == "stress") m.plane = PlaneHypothesis::Stress;
  else throw std::invalid_argument("unknown plane hypothesis '" + plane + "' (expected strain or stress)");
  return m;
}

SolverOptions parse_solver_options(const Args& args) {
  SolverOptions o;
  o.tolerance = args.number("tolerance", o.tolerance);
  if (!(o.tolerance > 0) || std::isinf(o.tolerance)) throw std::invalid_argument("--tolerance must be finite and > 0");
  // 0 is the solver's "use the default"; from the command line the default is had by leaving
  // the option out, so an explicit 0 is a mistake.
  o.max_iterations = args.integer("max-iterations", 0);
  if (args.has("max-iterations") && o.max_iterations < 1)
    throw std::invalid_argument("--max-iterations must be >= 1 (leave it out for the default)");
  o.omega = args.number("omega", o.omega);
  if (!(o.omega > 0 && o.omega < 2)) throw std::invalid_argument("--omega must be in (0, 2)");
  return o;
}

std::vector<double> friction_path_multipliers(const std::string& text, double friction) {
  if (!(friction > 0)) throw std::invalid_argument("--friction-path needs a scene with friction (f > 0)");
  std::vector<double> path = parse_number_list("friction-path", text);
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
