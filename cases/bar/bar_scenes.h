#pragma once
// Limit-mode scenes of the bar (SPEC §2.1): one shared bulk per mesh, one scene per law.
#include <memory>
#include <optional>
#include <string>

#include "cases/bar/bar.h"
#include "core/fem/linear_system.h"
#include "core/io/reference_tables.h"
#include "core/io/scene_record.h"
#include "core/mesh/layer_band.h"
#include "cases/layer_scene.h"
#include "core/solvers/condensed_interface.h"
#include "core/solvers/solve_report.h"
#include "core/solvers/solver_choice.h"

namespace thinlayer {

// The bar's bulk for one mesh: model, assembled system, and (built on first use) the
// factorisation condensed onto AD, shared by every law solved on this mesh.
class BarBulk {
 public:
  explicit BarBulk(const bar::MeshOptions& mesh);
  const bar::MeshOptions& mesh_options() const { return mesh_; }
  const Model& model() const { return model_; }
  const LinearSystem& system() const { return *system_; }
  const CondensedInterface& condensed();

 private:
  bar::MeshOptions mesh_;
  Model model_;
  std::unique_ptr<LinearSystem> system_;
  std::unique_ptr<CondensedInterface> condensed_;
};

// The interface law of a Table 3 row: its (λ̄, μ̄) with friction f (the bar's f = 1 by default).
InterfaceLaw table3_law(const Table3Row& row, double friction = bar::friction);

struct BarScene {
  SceneRecord record;
  SolveReport report;
  StatusCount counts;
};

// Solves the bar in limit mode with `law` on AD; law_case is "table3-row-N" or the Table 1
// letter. The record carries every attribute of SPEC §4.
BarScene solve_bar(BarBulk& bulk, const InterfaceLaw& law, const std::string& law_case, SolverKind solver,
                   const SolverOptions& options, double status_tolerance = default_status_tolerance);

std::string bar_scene_id(const bar::MeshOptions& mesh, const std::string& law_case, SolverKind solver);

// Thin-layer mode (SPEC §2.1): the layer under AD with λ_ε = eps λ̄, μ_ε = eps μ̄ and
// Signorini-Coulomb on both faces. Counts per face and combined (gap if either face is open,
// else slide if either slides, else stick).
struct BarLayerScene {
  SceneRecord record;
  SolveReport report;
  LayerCounts counts;
  MeshQuality layer_quality;
};
BarLayerScene solve_bar_layer(const bar::MeshOptions& mesh, double lambda_bar, double mu_bar, double eps,
                              const std::string& law_case, SolverKind solver, const SolverOptions& options,
                              double status_tolerance = default_status_tolerance, int layer_elements = 2);


}  // namespace thinlayer
