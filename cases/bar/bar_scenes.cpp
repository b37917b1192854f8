#include "cases/bar/bar_scenes.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/io/scene_id_number.h"
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

InterfaceLaw table3_law(const Table3Row& row, double friction) {
  return InterfaceLaw::make(row.lambda_bar, row.mu_bar, friction);
}

std::string bar_scene_id(const bar::MeshOptions& mesh, const std::string& law_case, SolverKind solver) {
  std::ostringstream id;
  id << "bar-" << law_case << "-" << to_string(mesh.element);
  if (mesh.element == ElementType::P1) id << (mesh.diagonal == TriangleDiagonal::Right ? "R" : "L");
  id << "-" << mesh.nx << "x" << mesh.ny << "-plane_" << to_string(mesh.plane);
  if (mesh.distortion != 0) id << "-distorted" << mesh.distortion;
  if (mesh.load_scale != 1) id << "-load" << mesh.load_scale;
  id << "-" << to_string(solver);
  return id.str();
}

namespace {

void add_bar_attributes(SceneRecord& r, const bar::MeshOptions& mesh, const std::string& mode,
                        const std::string& law_case, double lambda_bar, double mu_bar, double eps) {
  r.text["case"] = "bar";
  r.text["mode"] = mode;
  r.text["law_case"] = law_case;
  r.text["table1_case"] = std::string(1, InterfaceLaw::make(lambda_bar, mu_bar, bar::friction).table1_case());
  r.text["plane"] = to_string(mesh.plane);
  r.text["element"] = to_string(mesh.element);
  if (mesh.element == ElementType::P1)
    r.text["diagonal"] = mesh.diagonal == TriangleDiagonal::Right ? "right" : "left";
  r.numbers["eps"] = eps;  // 0 in limit mode: the layer has shrunk to S
  // The bar's layer has λ_ε = ε λ̄, μ_ε = ε μ̄ (SPEC §2.1): exponents γ = δ = 1.
  r.numbers["gamma"] = 1.0;
  r.numbers["delta"] = 1.0;
  r.numbers["lambda_bar"] = lambda_bar;
  r.numbers["mu_bar"] = mu_bar;
  r.numbers["friction"] = bar::friction;
  r.integers["nx"] = mesh.nx;
  r.integers["ny"] = mesh.ny;
  r.numbers["mesh_distortion"] = mesh.distortion;
  r.numbers["load_scale"] = mesh.load_scale;
}

}  // namespace

BarScene solve_bar(BarBulk& bulk, const InterfaceLaw& law, const std::string& law_case, SolverKind solver,
                   const SolverOptions& options, double status_tolerance) {
  const ContactProblem problem(bulk.system(), {bar::make_interface(bulk.model(), law)});
  BarScene scene;
  const CondensedInterface* condensed = solver == SolverKind::Fast ? &bulk.condensed() : nullptr;
  scene.report = run_solver(problem, condensed, solver, options);
  const bar::MeshOptions& mesh = bulk.mesh_options();
  SceneRecord& r = scene.record;
  r = record_scene(bar_scene_id(mesh, law_case, solver), bulk.model(), problem, scene.report, status_tolerance);
  add_bar_attributes(r, mesh, "limit", law_case, law.lambda_bar, law.mu_bar, 0.0);
  r.numbers["friction"] = law.friction;
  record_friction_path(r, options.friction_path, law.friction);
  r.numbers["setup_time_s"] = condensed ? condensed->setup_time_s() : 0.0;
  scene.counts = r.interfaces.at(0).counts();
  return scene;
}

BarLayerScene solve_bar_layer(const bar::MeshOptions& mesh, double lambda_bar, double mu_bar, double eps,
                              const std::string& law_case, SolverKind solver, const SolverOptions& options,
                              double status_tolerance, int layer_elements) {
  if (!(eps > 0) || !std::isfinite(eps)) throw std::invalid_argument("eps must be finite and > 0");
  const InterfaceLaw law = InterfaceLaw::make(lambda_bar, mu_bar, bar::friction);  // validates
  if (!std::isfinite(lambda_bar) || !std::isfinite(mu_bar) || !(mu_bar > 0))
    throw std::invalid_argument("layer mode needs finite lambda_bar >= 0 and mu_bar > 0 (the layer's Lamé "
                                "coefficients are eps times them)");
  bar::LayerOptions layer;
  layer.eps = eps;
  layer.lambda_eps = eps * law.lambda_bar;
  layer.mu_eps = eps * law.mu_bar;
  layer.layer_elements = layer_elements;
  const Model model = bar::make_layer_model(mesh, layer);
  const LinearSystem system(model);
  const ContactProblem problem(system, bar::make_layer_interfaces(model));
  std::unique_ptr<CondensedInterface> condensed;
  if (solver == SolverKind::Fast && needs_condensation(problem, options)) condensed = std::make_unique<CondensedInterface>(problem);
  BarLayerScene scene;
  scene.layer_quality = mesh_quality(model.bodies[1].mesh);
  scene.report = run_solver(problem, condensed.get(), solver, options);
  std::ostringstream id;
  id << bar_scene_id(mesh, law_case, solver) << "-layer-eps" << scene_id_number(eps);
  SceneRecord& r = scene.record;
  r = record_scene(id.str(), model, problem, scene.report, status_tolerance);
  add_bar_attributes(r, mesh, "layer", law_case, lambda_bar, mu_bar, eps);
  record_friction_path(r, options.friction_path, bar::friction);
  r.numbers["setup_time_s"] = condensed ? condensed->setup_time_s() : 0.0;
  scene.counts = finish_layer_record(r, model.bodies[1].material, layer.layer_elements,
                                     model.bodies[1].selective_integration, scene.layer_quality);
  return scene;
}

}  // namespace thinlayer
