#include "cases/dovetail/dovetail_scenes.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "core/io/scene_id_number.h"
#include "core/solvers/fast_solver.h"

namespace thinlayer {

namespace {

// Wall time since `start`, s (the studies' stopwatch lives above the cases).
double elapsed_s(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void add_dovetail_attributes(SceneRecord& r, const std::string& mode, const std::string& law_case,
                             const dovetail::Exponents& e, double eps, const DovetailLimitBulk& bulk) {
  const dovetail::MeshOptions& mesh = bulk.options();
  const InterfaceLaw law = dovetail::limit_law(e, bulk.friction());
  r.text["case"] = "dovetail";
  r.text["mode"] = mode;
  r.text["law_case"] = law_case.empty() ? "custom" : law_case;
  r.text["table1_case"] = std::string(1, law.table1_case());
  r.text["plane"] = "strain";
  r.text["element"] = "Q1";
  r.numbers["eps"] = eps;
  r.numbers["gamma"] = e.gamma;
  r.numbers["delta"] = e.delta;
  r.numbers["lambda_bar"] = law.lambda_bar;  // the limit law's, in both modes
  r.numbers["mu_bar"] = law.mu_bar;
  r.numbers["friction"] = bulk.friction();
  r.numbers["h_interface"] = mesh.h_interface;
  r.numbers["h_far"] = mesh.h_far;
}

std::string scene_id(const std::string& mode, const std::string& law_case, const dovetail::Exponents& e, double eps,
                     SolverKind solver, const DovetailLimitBulk& bulk) {
  const dovetail::MeshOptions& mesh = bulk.options();
  std::ostringstream id;
  id << "dovetail-" << mode << "-";
  if (law_case.empty()) id << "g" << e.gamma << "-d" << e.delta;
  else id << law_case;
  if (mode == "layer") id << "-eps" << scene_id_number(eps);
  id << "-h" << mesh.h_interface;
  if (bulk.friction() != dovetail::friction) id << "-f" << bulk.friction();
  id << "-" << to_string(solver);
  return id.str();
}


}  // namespace

DovetailLimitBulk::DovetailLimitBulk(const dovetail::MeshOptions& options, double friction)
    : options_(options), friction_(friction) {
  dovetail::limit_law({}, friction_);  // throws on a friction that no law accepts, before any meshing
  const auto start = std::chrono::steady_clock::now();
  meshes_ = dovetail::make_limit_meshes(options);
  meshing_time_s_ = elapsed_s(start);
  model_ = dovetail::make_limit_model(meshes_);
  system_ = std::make_unique<LinearSystem>(model_);
}

const CondensedInterface& DovetailLimitBulk::condensed() {
  if (!condensed_) {
    const ContactProblem geometry(*system_, {dovetail::make_limit_interface(model_, InterfaceLaw{})});
    condensed_ = std::make_unique<CondensedInterface>(geometry);
  }
  return *condensed_;
}

DovetailScene solve_dovetail_limit(DovetailLimitBulk& bulk, const dovetail::Exponents& e,
                                   const std::string& law_case, SolverKind solver, const SolverOptions& options,
                                   double status_tolerance) {
  const InterfaceLaw law = dovetail::limit_law(dovetail::validated(e), bulk.friction());
  const ContactProblem problem(bulk.system(), {dovetail::make_limit_interface(bulk.model(), law)});
  const CondensedInterface* condensed = solver == SolverKind::Fast ? &bulk.condensed() : nullptr;
  DovetailScene scene;
  scene.report = run_solver(problem, condensed, solver, options);
  SceneRecord& r = scene.record;
  r = record_scene(scene_id("limit", law_case, e, 0, solver, bulk), bulk.model(), problem, scene.report,
                   status_tolerance);
  add_dovetail_attributes(r, "limit", law_case, e, 0.0, bulk);
  record_friction_path(r, options.friction_path, bulk.friction());
  r.numbers["setup_time_s"] = condensed ? condensed->setup_time_s() : 0.0;
  r.numbers["meshing_time_s"] = bulk.meshing_time_s();
  scene.limit = r.interfaces.at(0).counts();
  return scene;
}

DovetailScene solve_dovetail_layer(const DovetailLimitBulk& bulk, const dovetail::Exponents& e, double eps,
                                   const std::string& law_case, SolverKind solver, const SolverOptions& options,
                                   double status_tolerance, LayerQuadrature quadrature) {
  const dovetail::Exponents x = dovetail::validated(e);
  if (!(eps > 0) || !std::isfinite(eps)) throw std::invalid_argument("eps must be finite and > 0");
  DovetailScene scene;
  auto start = std::chrono::steady_clock::now();
  const dovetail::LayerMeshes meshes = dovetail::make_layer_meshes(bulk.meshes(), eps, bulk.options().layer_elements);
  scene.meshing_time_s = elapsed_s(start);
  scene.layer_quality = mesh_quality(meshes.layer);
  const Model model = dovetail::make_layer_model(meshes, x, quadrature);
  const LinearSystem system(model);
  const ContactProblem problem(system, dovetail::make_layer_interfaces(model, bulk.friction()));
  std::unique_ptr<CondensedInterface> condensed;
  if (solver == SolverKind::Fast && needs_condensation(problem, options)) condensed = std::make_unique<CondensedInterface>(problem);
  scene.report = run_solver(problem, condensed.get(), solver, options);

  SceneRecord& r = scene.record;
  const bool selective = model.bodies[1].selective_integration;
  std::string id = scene_id("layer", law_case, x, eps, solver, bulk);
  if (selective != selective_layer_quadrature(x.gamma, x.delta)) id += std::string("-") + quadrature_name(selective);
  r = record_scene(id, model, problem, scene.report, status_tolerance);
  add_dovetail_attributes(r, "layer", law_case, x, eps, bulk);
  record_friction_path(r, options.friction_path, bulk.friction());
  r.numbers["setup_time_s"] = condensed ? condensed->setup_time_s() : 0.0;
  r.numbers["meshing_time_s"] = scene.meshing_time_s;
  scene.counts = finish_layer_record(r, model.bodies[1].material, bulk.options().layer_elements, selective,
                                     scene.layer_quality);
  return scene;
}

}  // namespace thinlayer
