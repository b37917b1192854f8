#include "studies/bar_scenes.h"

#include <sstream>
#include <stdexcept>

#include "core/solvers/fast_solver.h"
#include "core/solvers/relaxation_solver.h"

namespace thinlayer {

BarBulk::BarBulk(const bar::MeshOptions& mesh)
    : mesh_(mesh), model_(bar::make_model(mesh)), system_(std::make_unique<LinearSystem>(model_)) {}

const CondensedInterface& BarBulk::condensed() {
  if (!condensed_) {
    // The condensation depends on where the interface is, not on its law.
    const ContactProblem geometry(*system_, {bar::make_interface(model_, InterfaceLaw{})});
    condensed_ = std::make_unique<CondensedInterface>(geometry);
  }
  return *condensed_;
}

SolverKind parse_solver(const std::string& name) {
  if (name == "fast") return SolverKind::Fast;
  if (name == "relaxation") return SolverKind::Relaxation;
  throw std::invalid_argument("unknown solver '" + name + "' (expected fast or relaxation)");
}

const char* to_string(SolverKind s) { return s == SolverKind::Fast ? "fast" : "relaxation"; }

std::string bar_scene_id(const bar::MeshOptions& mesh, const std::string& law_case, double scale, SolverKind solver) {
  std::ostringstream id;
  id << "bar-" << law_case << "-" << to_string(mesh.element);
  if (mesh.element == ElementType::P1) id << (mesh.diagonal == TriangleDiagonal::Right ? "R" : "L");
  id << "-" << mesh.nx << "x" << mesh.ny << "-plane_" << to_string(mesh.plane);
  if (scale != 1) id << "-s" << scale;
  id << "-" << to_string(solver);
  return id.str();
}

BarScene solve_bar(BarBulk& bulk, const InterfaceLaw& law, const std::string& law_case, SolverKind solver,
                   const SolverOptions& options, double status_tolerance) {
  const ContactProblem problem(bulk.system(), {bar::make_interface(bulk.model(), law)});
  BarScene scene;
  double setup_time = 0;
  if (solver == SolverKind::Fast) {
    const CondensedInterface& condensed = bulk.condensed();
    setup_time = condensed.setup_time_s();
    scene.report = solve_fast(problem, condensed, options);
  } else {
    scene.report = solve_relaxation(problem, options);
  }
  const bar::MeshOptions& mesh = bulk.mesh_options();
  SceneRecord& r = scene.record;
  r = record_scene(bar_scene_id(mesh, law_case, 1.0, solver), bulk.model(), problem, scene.report, status_tolerance);
  r.text["case"] = "bar";
  r.text["mode"] = "limit";
  r.text["law_case"] = law_case;
  r.text["table1_case"] = std::string(1, law.table1_case());
  r.text["plane"] = to_string(mesh.plane);
  r.text["element"] = to_string(mesh.element);
  if (mesh.element == ElementType::P1)
    r.text["diagonal"] = mesh.diagonal == TriangleDiagonal::Right ? "right" : "left";
  r.numbers["eps"] = 0.0;  // limit mode: the layer has shrunk to S
  // The bar's layer has λ_ε = ε λ̄, μ_ε = ε μ̄ (SPEC §2.1): exponents γ = δ = 1.
  r.numbers["gamma"] = 1.0;
  r.numbers["delta"] = 1.0;
  r.numbers["lambda_bar"] = law.lambda_bar;
  r.numbers["mu_bar"] = law.mu_bar;
  r.numbers["friction"] = law.friction;
  r.numbers["setup_time_s"] = setup_time;
  r.integers["nx"] = mesh.nx;
  r.integers["ny"] = mesh.ny;
  scene.counts = r.interfaces.at(0).counts();
  return scene;
}

}  // namespace thinlayer
