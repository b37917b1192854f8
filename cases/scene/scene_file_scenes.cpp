#include "cases/scene/scene_file_scenes.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "cases/scene/scene_checks.h"
#include "core/io/scene_id_number.h"

namespace thinlayer {

namespace {

// Wall time since `start`, s (the studies' stopwatch lives above the cases).
double elapsed_s(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void add_attributes(SceneRecord& r, const SceneSpec& spec, const std::string& mode, double eps, double meshing_time_s) {
  const InterfaceLaw law = spec.limit_law();
  r.text["case"] = spec.name;
  r.text["mode"] = mode;
  r.text["law_case"] = std::string(1, law.table1_case());
  r.text["table1_case"] = std::string(1, law.table1_case());
  r.text["plane"] = to_string(spec.plane);
  r.text["element"] = to_string(spec.element);
  r.text["scene_file"] = spec.file;
  r.numbers["eps"] = eps;
  r.numbers["gamma"] = spec.has_layer() ? spec.interface.layer->gamma : 0.0;
  r.numbers["delta"] = spec.has_layer() ? spec.interface.layer->delta : 0.0;
  r.numbers["lambda_bar"] = law.lambda_bar;  // the limit law's, in both modes
  r.numbers["mu_bar"] = law.mu_bar;
  r.numbers["friction"] = spec.interface.friction;
  r.numbers["meshing_time_s"] = meshing_time_s;
}

std::string scene_id(const SceneSpec& spec, const std::string& mode, double eps, SolverKind solver) {
  std::ostringstream id;
  id << spec.name << "-" << mode;
  if (mode == "layer") id << "-eps" << scene_id_number(eps);
  id << "-" << to_string(solver);
  return id.str();
}

}  // namespace

SceneFileBulk::SceneFileBulk(SceneSpec spec) : spec_(std::move(spec)) {
  meshes_ = load_scene_meshes(spec_);
  S_ = check_scene_meshes(spec_, meshes_);
  check_scene_mesh_data(spec_, meshes_);  // shared cells, supports on S or in conflict, inverted cells (scene_checks.h)
  if (spec_.has_layer() && spec_.element == ElementType::Q1) thickest_ = scene_thickest_layer(spec_, meshes_, S_);
  model_ = make_scene_limit_model(spec_, meshes_);
  system_ = std::make_unique<LinearSystem>(model_);
}

void check_layer_mode(const SceneFileBulk& bulk, double eps) {
  const SceneSpec& spec = bulk.spec();
  if (!spec.has_layer())
    throw std::invalid_argument("scene '" + spec.name + "' gives a limit law only ('law'): it has no layer mode");
  if (spec.element != ElementType::Q1)
    throw std::invalid_argument("scene '" + spec.name + "' is P1: the layer mode needs \"element\": \"Q1\" (its band is Q1)");
  if (!(eps > 0) || !std::isfinite(eps)) throw std::invalid_argument("eps must be finite and > 0");
  if (eps > bulk.thickest_layer()) {
    std::ostringstream s;
    s << "eps " << eps << " mm is too thick for the elements of body '" << spec.interface.plus
      << "' along the interface: at most " << bulk.thickest_layer() << " mm (half their depth there)";
    throw std::invalid_argument(s.str());
  }
}

const CondensedInterface& SceneFileBulk::condensed() {
  if (!condensed_) {
    const ContactProblem geometry(*system_, {make_scene_limit_interface(spec_, model_, S_, InterfaceLaw{})});
    condensed_ = std::make_unique<CondensedInterface>(geometry);
  }
  return *condensed_;
}

SceneFileScene solve_scene_file_limit(SceneFileBulk& bulk, SolverKind solver, const SolverOptions& options,
                                      double status_tolerance) {
  const SceneSpec& spec = bulk.spec();
  const ContactProblem problem(bulk.system(),
                               {make_scene_limit_interface(spec, bulk.model(), bulk.interface_nodes(), spec.limit_law())});
  const CondensedInterface* condensed = solver == SolverKind::Fast ? &bulk.condensed() : nullptr;
  SceneFileScene scene;
  scene.report = run_solver(problem, condensed, solver, options);
  SceneRecord& r = scene.record;
  r = record_scene(scene_id(spec, "limit", 0, solver), bulk.model(), problem, scene.report, status_tolerance);
  add_attributes(r, spec, "limit", 0.0, bulk.meshes().meshing_time_s);
  r.numbers["setup_time_s"] = condensed ? condensed->setup_time_s() : 0.0;
  scene.limit = r.interfaces.at(0).counts();
  return scene;
}

SceneFileScene solve_scene_file_layer(const SceneFileBulk& bulk, double eps, SolverKind solver,
                                      const SolverOptions& options, double status_tolerance) {
  const SceneSpec& spec = bulk.spec();
  const auto start = std::chrono::steady_clock::now();
  const SceneLayerModel layer = make_scene_layer_model(spec, bulk.meshes(), bulk.interface_nodes(), eps);
  const double meshing = elapsed_s(start);
  const LinearSystem system(layer.model);
  const ContactProblem problem(system, layer.interfaces);
  std::unique_ptr<CondensedInterface> condensed;
  if (solver == SolverKind::Fast) condensed = std::make_unique<CondensedInterface>(problem);
  SceneFileScene scene;
  scene.report = run_solver(problem, condensed.get(), solver, options);
  scene.layer_quality = layer.layer_quality;
  SceneRecord& r = scene.record;
  r = record_scene(scene_id(spec, "layer", eps, solver), layer.model, problem, scene.report, status_tolerance);
  add_attributes(r, spec, "layer", eps, meshing);
  r.numbers["setup_time_s"] = condensed ? condensed->setup_time_s() : 0.0;
  const Body& band = layer.model.bodies[layer.layer_body];
  scene.counts = finish_layer_record(r, band.material, spec.layer_elements, band.selective_integration,
                                     layer.layer_quality);
  return scene;
}

}  // namespace thinlayer
