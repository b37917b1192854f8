#pragma once
// Scenes of the dovetail (SPEC §2.2): the limit mode's nine laws share one bulk; each layer
// scene builds its own (the layer's moduli depend on the case and on ε).
#include <memory>
#include <string>

#include "cases/dovetail/dovetail.h"
#include "core/fem/linear_system.h"
#include "core/io/scene_record.h"
#include "core/mesh/layer_band.h"
#include "core/solvers/condensed_interface.h"
#include "core/solvers/solver_choice.h"
#include "cases/layer_scene.h"

namespace thinlayer {

// The limit-mode meshes, model and (on first use) the condensation shared by the nine laws,
// and the Coulomb coefficient of every scene built on them (both modes; SPEC §2.2: 0.5).
class DovetailLimitBulk {
 public:
  explicit DovetailLimitBulk(const dovetail::MeshOptions& options = {}, double friction = dovetail::friction);
  const dovetail::MeshOptions& options() const { return options_; }
  double friction() const { return friction_; }
  const dovetail::LimitMeshes& meshes() const { return meshes_; }
  const Model& model() const { return model_; }
  const LinearSystem& system() const { return *system_; }
  const CondensedInterface& condensed();
  double meshing_time_s() const { return meshing_time_s_; }

 private:
  dovetail::MeshOptions options_;
  double friction_;
  dovetail::LimitMeshes meshes_;
  double meshing_time_s_ = 0;
  Model model_;
  std::unique_ptr<LinearSystem> system_;
  std::unique_ptr<CondensedInterface> condensed_;
};

struct DovetailScene {
  SceneRecord record;
  SolveReport report;
  StatusCount limit;   // limit mode: counts on S
  LayerCounts counts;  // layer mode: per face, and combined (SPEC §2.2)
  MeshQuality layer_quality;  // layer mode only
  double meshing_time_s = 0;  // layer mode: building the layer-mode meshes from the limit ones
};

// law_case: a Table 2 letter, or "" for custom exponents (the record then says "custom").
DovetailScene solve_dovetail_limit(DovetailLimitBulk& bulk, const dovetail::Exponents& e,
                                   const std::string& law_case, SolverKind solver, const SolverOptions& options,
                                   double status_tolerance = default_status_tolerance);
// The layer's quadrature follows cases/layer_quadrature.h; a control overrides it, and a scene
// solved with another quadrature than the rule's says so in its id ("-selective", "-full") and
// in its attribute layer_quadrature.
DovetailScene solve_dovetail_layer(const DovetailLimitBulk& bulk, const dovetail::Exponents& e, double eps,
                                   const std::string& law_case, SolverKind solver, const SolverOptions& options,
                                   double status_tolerance = default_status_tolerance,
                                   LayerQuadrature quadrature = LayerQuadrature::ByExponents);

}  // namespace thinlayer
