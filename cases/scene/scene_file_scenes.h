#pragma once
// Scenes of a user's scene file (SPEC §5), both modes: the limit mode's bulk is built and
// factored once and shared by every limit solve; each layer scene builds its own model (the
// layer's moduli and the plus body's nodes depend on ε).
#include <memory>
#include <string>

#include "cases/scene/scene_model.h"
#include "core/fem/linear_system.h"
#include "core/io/scene_record.h"
#include "core/solvers/condensed_interface.h"
#include "core/solvers/solver_choice.h"
#include "cases/layer_scene.h"

namespace thinlayer {

class SceneFileBulk {
 public:
  // Reads nothing: `spec` is already checked; meshes the geometry and checks the meshes
  // (InputError at the scene file's line and column).
  explicit SceneFileBulk(SceneSpec spec);
  const SceneSpec& spec() const { return spec_; }
  const SceneMeshes& meshes() const { return meshes_; }
  const SceneInterfaceNodes& interface_nodes() const { return S_; }
  const Model& model() const { return model_; }
  const LinearSystem& system() const { return *system_; }
  const CondensedInterface& condensed();
  double thickest_layer() const { return thickest_; }  // mm; 0 for a scene without a layer

 private:
  SceneSpec spec_;
  SceneMeshes meshes_;
  SceneInterfaceNodes S_;
  Model model_;
  double thickest_ = 0;
  std::unique_ptr<LinearSystem> system_;
  std::unique_ptr<CondensedInterface> condensed_;
};

// Throws std::invalid_argument unless the scene has a layer mode at thickness `eps` (mm): a
// "layer" (not a bare "law"), Q1 elements (the band is Q1), and eps ≤ thickest_layer().
void check_layer_mode(const SceneFileBulk& bulk, double eps);

struct SceneFileScene {
  SceneRecord record;
  SolveReport report;
  StatusCount limit;          // limit mode: counts on S
  LayerCounts counts;         // layer mode: per face and combined
  MeshQuality layer_quality;  // layer mode only
};

SceneFileScene solve_scene_file_limit(SceneFileBulk& bulk, SolverKind solver, const SolverOptions& options,
                                      double status_tolerance = default_status_tolerance);
// Throws std::invalid_argument for an ε the plus body's elements do not allow.
SceneFileScene solve_scene_file_layer(const SceneFileBulk& bulk, double eps, SolverKind solver,
                                      const SolverOptions& options, double status_tolerance = default_status_tolerance);

}  // namespace thinlayer
